// A model plugin that leaves two symbols to the process it is loaded into, as robot
// plugins do: tf::resolve, from tf's library, which it does not link (AgileX LIMO's drive
// includes tf's headers and links only tf2_ros; gzserver has tf loaded with gazebo_ros's API
// plugin), and a function nothing defines, called only when <callUndefined> is true.
#include <string>
#include <gazebo/gazebo.hh>
#include <gazebo/physics/physics.hh>
#include <tf/tf.h>

extern "C" void sim_bridge_test_defined_nowhere();

namespace
{
  std::string resolved;
}

extern "C" const char *host_scope_plugin_report()
{
  return resolved.c_str();
}

namespace gazebo
{
  class HostScopePlugin : public ModelPlugin
  {
    public: void Load(physics::ModelPtr, sdf::ElementPtr _sdf)
    {
      resolved = tf::resolve(_sdf->Get<std::string>("prefix"), _sdf->Get<std::string>("frame"));
      if (_sdf->HasElement("callUndefined") && _sdf->Get<bool>("callUndefined"))
        sim_bridge_test_defined_nowhere();
    }
  };

  GZ_REGISTER_MODEL_PLUGIN(HostScopePlugin)
}

// A model plugin that gives up in Load, as one that misses its joint does.
#include <gazebo/gazebo.hh>
#include <gazebo/physics/physics.hh>

namespace gazebo
{
  class ThrowingPlugin : public ModelPlugin
  {
    public: void Load(physics::ModelPtr _model, sdf::ElementPtr _sdf)
    {
      gzthrow("couldn't get wheel hinge joint named " << _sdf->Get<std::string>("joint")
              << " in " << _model->GetName());
    }
  };

  GZ_REGISTER_MODEL_PLUGIN(ThrowingPlugin);
}

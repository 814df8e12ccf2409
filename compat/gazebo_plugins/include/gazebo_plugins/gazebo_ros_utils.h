// gazebo_plugins' helper for robot plugins, GazeboRos, under its upstream name and API
// (gazebo_ros_pkgs noetic-devel f9e1a46 gazebo_plugins/include/gazebo_plugins/gazebo_ros_utils.h,
// src/gazebo_ros_utils.cpp), written here for sim_bridge's Gazebo plugin API
// (compat/gazebo_dev). The behaviour is upstream's:
//   - the namespace: a model plugin's <robotNamespace>, or the model's name when the tag is
//     missing or empty, with "/" appended (gazebo_ros's spawn adds <robotNamespace> with the
//     request's namespace, "/" by default, so a spawned robot's plugin is in "//", the root);
//     a sensor plugin's <robotNamespace>, the sensor's model when empty, "" when missing;
//   - node() a ros::NodeHandle in that namespace; info() "<plugin>(ns = <namespace>)";
//   - <rosDebugLevel> (Debug, Info, Warn, Error, Fatal) sets rosconsole's default level;
//     the tf prefix is the tf_prefix parameter searched upwards from the namespace, and
//     resolveTF(name) prefixes a frame with it;
//   - getParameter(value, tag, default): the default, with a warning naming it, when the tag
//     is missing; getParameterBoolean reads true/false/1/0 in any case, warns otherwise;
//     getJoint throws (gzthrow) when the model has no joint of the name the tag gives;
//   - isInitialized() only logs (ROS_FATAL) when roscpp is not initialised.
#ifndef GAZEBO_PLUGINS_GAZEBO_ROS_UTILS_H
#define GAZEBO_PLUGINS_GAZEBO_ROS_UTILS_H
#include <map>
#include <string>

#include <boost/algorithm/string.hpp>
#include <boost/lexical_cast.hpp>
#include <boost/shared_ptr.hpp>
#include <gazebo/common/common.hh>
#include <gazebo/gazebo_config.h>
#include <gazebo/physics/physics.hh>
#include <gazebo/sensors/Sensor.hh>
#include <ros/ros.h>

// plugins written for several Gazebo versions cast sensors with it
#ifndef GAZEBO_SENSORS_USING_DYNAMIC_POINTER_CAST
#define GAZEBO_SENSORS_USING_DYNAMIC_POINTER_CAST using std::dynamic_pointer_cast
#endif

namespace gazebo
{
  // the model a sensor is on: the second field of its scoped name (world::model::...),
  // "" when there is none
  inline std::string GetModelName(const sensors::SensorPtr &_parent)
  {
    std::vector<std::string> fields;
    std::string scoped = _parent->ScopedName();
    boost::replace_all(scoped, "::", ",");
    boost::split(fields, scoped, boost::is_any_of(","));
    return fields.size() < 2 ? std::string() : fields[1];
  }

  // a sensor plugin's <robotNamespace>: the sensor's model when it is empty, "" when there
  // is none; pInfo, when given, heads a log line saying which
  inline std::string GetRobotNamespace(const sensors::SensorPtr &_parent,
                                       const sdf::ElementPtr &_sdf, const char *pInfo = NULL)
  {
    std::string ns;
    std::string why;
    if (!_sdf->HasElement("robotNamespace"))
    {
      why = "The 'robotNamespace' param did not exist";
    }
    else
    {
      ns = _sdf->Get<std::string>("robotNamespace");
      if (ns.empty())
      {
        why = "The 'robotNamespace' param was empty";
        ns = GetModelName(_parent);
      }
      else
      {
        why = "Using the 'robotNamespace' param: '" + ns + "'";
      }
    }
    if (pInfo != NULL)
      ROS_INFO_NAMED("utils", "%s Plugin: %s", pInfo, why.c_str());
    return ns;
  }

  class GazeboRos
  {
    public: GazeboRos(physics::ModelPtr &_parent, sdf::ElementPtr _sdf,
                      const std::string &_plugin);
    public: GazeboRos(sensors::SensorPtr _parent, sdf::ElementPtr _sdf,
                      const std::string &_plugin);
    public: const char *info() const;
    public: boost::shared_ptr<ros::NodeHandle> &node();
    public: const boost::shared_ptr<ros::NodeHandle> &node() const;
    public: std::string resolveTF(const std::string &_name);
    public: void getParameterBoolean(bool &_value, const char *_tag_name, const bool &_default);
    public: void getParameterBoolean(bool &_value, const char *_tag_name);
    public: physics::JointPtr getJoint(physics::ModelPtr &_parent, const char *_tag_name,
                                       const std::string &_joint_default_name);
    public: void isInitialized();

    public: template <class T>
            void getParameter(T &_value, const char *_tag_name, const T &_default)
    {
      _value = _default;
      if (this->sdf_->HasElement(_tag_name))
      {
        this->getParameter<T>(_value, _tag_name);
        return;
      }
      ROS_WARN_NAMED("utils", "%s: missing <%s> default is %s", this->info(), _tag_name,
                     boost::lexical_cast<std::string>(_default).c_str());
    }

    public: template <class T>
            void getParameter(T &_value, const char *_tag_name)
    {
      if (this->sdf_->HasElement(_tag_name))
        _value = this->sdf_->GetElement(_tag_name)->template Get<T>();
      ROS_DEBUG_NAMED("utils", "%s: <%s> = %s", this->info(), _tag_name,
                      boost::lexical_cast<std::string>(_value).c_str());
    }

    // the tag's text looked up in _options
    public: template <class T>
            void getParameter(T &_value, const char *_tag_name,
                              const std::map<std::string, T> &_options, const T &_default)
    {
      _value = _default;
      if (this->sdf_->HasElement(_tag_name))
      {
        this->getParameter<T>(_value, _tag_name, _options);
        return;
      }
      ROS_WARN_NAMED("utils", "%s: missing <%s> default is %s", this->info(), _tag_name,
                     boost::lexical_cast<std::string>(_default).c_str());
    }

    public: template <class T>
            void getParameter(T &_value, const char *_tag_name,
                              const std::map<std::string, T> &_options)
    {
      std::string key = "default";
      if (this->sdf_->HasElement(_tag_name))
      {
        const std::string text = this->sdf_->GetElement(_tag_name)->template Get<std::string>();
        const auto found = _options.find(text);
        if (found == _options.end())
        {
          ROS_WARN_NAMED("utils", "%s: <%s> no matching key to %s", this->info(), _tag_name,
                         text.c_str());
        }
        else
        {
          _value = found->second;
          key = found->first;
        }
      }
      ROS_DEBUG_NAMED("utils", "%s: <%s> = %s := %s", this->info(), _tag_name, key.c_str(),
                      boost::lexical_cast<std::string>(_value).c_str());
    }

    // the log line of a plugin starting, <rosDebugLevel>, the tf prefix
    private: void readCommonParameter();

    private: sdf::ElementPtr sdf_;
    private: std::string plugin_;
    private: std::string namespace_;
    private: boost::shared_ptr<ros::NodeHandle> rosnode_;
    private: std::string tf_prefix_;
    private: std::string info_text;
  };

  typedef boost::shared_ptr<GazeboRos> GazeboRosPtr;
}
#endif

// GazeboRos (see include/gazebo_plugins/gazebo_ros_utils.h): the library robot plugins link
// as libgazebo_ros_utils.so, as they link gazebo_plugins' own.
#include <gazebo_plugins/gazebo_ros_utils.h>

#include <sdf/sdf.hh>
#include <tf/tf.h>
#include <tf/transform_listener.h>

namespace gazebo
{
GazeboRos::GazeboRos(physics::ModelPtr &_parent, sdf::ElementPtr _sdf,
                     const std::string &_plugin)
  : sdf_(_sdf), plugin_(_plugin)
{
  this->namespace_ = _parent->GetName();
  if (this->sdf_->HasElement("robotNamespace"))
  {
    this->namespace_ = this->sdf_->GetElement("robotNamespace")->Get<std::string>();
    if (this->namespace_.empty())
      this->namespace_ = _parent->GetName();
  }
  else
  {
    ROS_INFO_NAMED("utils", "%s missing <robotNamespace>, defaults is %s",
                   this->plugin_.c_str(), this->namespace_.c_str());
  }
  if (!this->namespace_.empty())
    this->namespace_ += "/";
  this->rosnode_.reset(new ros::NodeHandle(this->namespace_));
  this->info_text = this->plugin_ + "(ns = " + this->namespace_ + ")";
  this->readCommonParameter();
}

GazeboRos::GazeboRos(sensors::SensorPtr _parent, sdf::ElementPtr _sdf,
                     const std::string &_plugin)
  : sdf_(_sdf), plugin_(_plugin)
{
  std::string why;
  if (!this->sdf_->HasElement("robotNamespace"))
  {
    why = "the 'robotNamespace' param did not exist";
  }
  else
  {
    this->namespace_ = this->sdf_->Get<std::string>("robotNamespace");
    if (this->namespace_.empty())
    {
      why = "the 'robotNamespace' param was empty";
      this->namespace_ = GetModelName(_parent);
    }
    else
    {
      why = "Using the 'robotNamespace' param: '" + this->namespace_ + "'";
    }
  }
  this->rosnode_.reset(new ros::NodeHandle(this->namespace_));
  this->info_text = this->plugin_ + "(ns = " + this->namespace_ + ")";
  ROS_INFO_NAMED("utils", "%s: %s", this->info_text.c_str(), why.c_str());
  this->readCommonParameter();
}

const char *GazeboRos::info() const { return this->info_text.c_str(); }

boost::shared_ptr<ros::NodeHandle> &GazeboRos::node() { return this->rosnode_; }

const boost::shared_ptr<ros::NodeHandle> &GazeboRos::node() const { return this->rosnode_; }

std::string GazeboRos::resolveTF(const std::string &_name)
{
  return tf::resolve(this->tf_prefix_, _name);
}

void GazeboRos::readCommonParameter()
{
  ROS_INFO_NAMED("utils", "Starting plugin %s", this->info());
  std::string level;
  this->getParameter<std::string>(level, "rosDebugLevel", "na");
  static const std::map<std::string, ros::console::levels::Level> levels = {
      {"debug", ros::console::levels::Debug}, {"info", ros::console::levels::Info},
      {"warn", ros::console::levels::Warn}, {"error", ros::console::levels::Error},
      {"fatal", ros::console::levels::Fatal}};
  const auto found = levels.find(boost::to_lower_copy(level));
  if (found != levels.end() &&
      ros::console::set_logger_level(ROSCONSOLE_DEFAULT_NAME, found->second))
  {
    ros::console::notifyLoggerLevelsChanged();
  }
  if (this->sdf_->HasElement("rosDebugLevel"))
    ROS_INFO_NAMED("utils", "%s: <rosDebugLevel> = %s", this->info(), level.c_str());
  this->tf_prefix_ = tf::getPrefixParam(*this->rosnode_);
  ROS_INFO_NAMED("utils", "%s: <tf_prefix> = %s", this->info(), this->tf_prefix_.c_str());
}

void GazeboRos::getParameterBoolean(bool &_value, const char *_tag_name, const bool &_default)
{
  _value = _default;
  if (this->sdf_->HasElement(_tag_name))
  {
    this->getParameterBoolean(_value, _tag_name);
    return;
  }
  ROS_WARN_NAMED("utils", "%s: missing <%s> default is %s", this->info(), _tag_name,
                 _default ? "true" : "false");
}

void GazeboRos::getParameterBoolean(bool &_value, const char *_tag_name)
{
  if (this->sdf_->HasElement(_tag_name))
  {
    const std::string text = this->sdf_->GetElement(_tag_name)->Get<std::string>();
    if (boost::iequals(text, "true") || text == "1")
      _value = true;
    else if (boost::iequals(text, "false") || text == "0")
      _value = false;
    else
      ROS_WARN_NAMED("utils", "%s: <%s> must be either true or false but is '%s'",
                     this->info(), _tag_name, text.c_str());
  }
  ROS_DEBUG_NAMED("utils", "%s: <%s> = %s", this->info(), _tag_name,
                  _value ? "true" : "false");
}

physics::JointPtr GazeboRos::getJoint(physics::ModelPtr &_parent, const char *_tag_name,
                                      const std::string &_joint_default_name)
{
  std::string name;
  this->getParameter<std::string>(name, _tag_name, _joint_default_name);
  physics::JointPtr joint = _parent->GetJoint(name);
  if (!joint)
  {
    std::ostringstream message;
    message << this->info() << ": couldn't get wheel hinge joint named " << name;
    gzthrow(message.str());
  }
  return joint;
}

void GazeboRos::isInitialized()
{
  if (ros::isInitialized())
    return;
  ROS_FATAL_STREAM(this->info() << "A ROS node for Gazebo has not been initialized, unable to "
                   "load plugin. Load the Gazebo system plugin 'libgazebo_ros_api_plugin.so' "
                   "in the gazebo_ros package)");
}
}  // namespace gazebo

// robot_model_loader::RobotModelLoader: the URDF and SRDF from the parameter server (searched from the private
// namespace as rdf_loader.cpp l. 64-93 searches them, noetic-devel) or from strings, and robot_description_planning's
// joint limits as robot_model_loader.cpp l. 105-160 applies them; the groups' kinematics plugins as
// loadKinematicsSolvers (l. 169-232) loads them.
#include <moveit/robot_model_loader/robot_model_loader.h>

#include <typeinfo>

#include <ros/ros.h>
#include <urdf/model.h>

namespace robot_model_loader
{
namespace
{
const char LOGNAME[] = "robot_model_loader";

// Position limits of a planar or floating joint's orientation and of a continuous joint cannot be set
bool canSpecifyPosition(const moveit::core::JointModel* joint, std::size_t index)
{
  const bool ok = !((joint->getType() == moveit::core::JointModel::PLANAR && index == 2) ||
                    (joint->getType() == moveit::core::JointModel::FLOATING && index > 2) || joint->isContinuous());
  if (!ok)
    ROS_ERROR_NAMED(LOGNAME, "Cannot specify position limits for variable %zu of joint '%s'", index,
                    joint->getName().c_str());
  return ok;
}
}  // namespace

RobotModelLoader::RobotModelLoader(const std::string& robot_description, bool load_kinematics_solvers)
{
  Options opt(robot_description);
  opt.load_kinematics_solvers_ = load_kinematics_solvers;
  configure(opt);
}

RobotModelLoader::RobotModelLoader(const Options& opt)
{
  configure(opt);
}

RobotModelLoader::~RobotModelLoader()
{
  // the model holds the plugins: released before their loader (l. 60-67)
  model_.reset();
  kinematics_loader_.reset();
}

void RobotModelLoader::configure(const Options& opt)
{
  std::string urdf_string = opt.urdf_string_;
  std::string srdf_string = opt.srdf_string_;
  std::string srdf_param;
  if (urdf_string.empty() || srdf_string.empty())
  {
    ros::NodeHandle nh("~");
    if (!nh.searchParam(opt.robot_description_, robot_description_) || !nh.getParam(robot_description_, urdf_string))
    {
      ROS_ERROR_NAMED(LOGNAME, "Robot model parameter not found! Did you remap '%s'?", opt.robot_description_.c_str());
      return;
    }
    srdf_param = robot_description_ + "_semantic";
    if (!nh.getParam(srdf_param, srdf_string))
      ROS_ERROR_NAMED(LOGNAME, "Robot semantic description not found. Did you forget to define or remap '%s'?",
                      srdf_param.c_str());
  }
  auto urdf = std::make_shared<urdf::Model>();
  if (!urdf->initString(urdf_string))
  {
    ROS_ERROR_NAMED(LOGNAME, "Unable to parse URDF from parameter '%s'", robot_description_.c_str());
    return;
  }
  urdf_ = urdf;
  auto srdf = std::make_shared<srdf::Model>();
  if (!srdf_string.empty() && !srdf->initString(*urdf_, srdf_string))
    ROS_ERROR_NAMED(LOGNAME, "Unable to parse SRDF from parameter '%s'", srdf_param.c_str());
  srdf_ = srdf;
  model_ = std::make_shared<moveit::core::RobotModel>(urdf_, srdf_);
  if (!robot_description_.empty())
    applyPlanningJointLimits(robot_description_ + "_planning/joint_limits/");
  if (opt.load_kinematics_solvers_)
    loadKinematicsSolvers();
}

void RobotModelLoader::loadKinematicsSolvers(const kinematics_plugin_loader::KinematicsPluginLoaderPtr& kloader)
{
  if (!model_ || !srdf_)
    return;
  kinematics_loader_ =
      kloader ? kloader : std::make_shared<kinematics_plugin_loader::KinematicsPluginLoader>(robot_description_);
  const moveit::core::SolverAllocatorFn allocator = kinematics_loader_->getLoaderFunction(srdf_);
  const std::vector<std::string>& groups = kinematics_loader_->getKnownGroups();
  if (groups.empty() && !model_->getJointModelGroups().empty())
    ROS_WARN_NAMED(LOGNAME, "No kinematics plugins defined. Fill and load kinematics.yaml!");

  // a group gets its solver when the solver supports it (l. 191-220); a group without one (its reason logged by the
  // loader) is answered by RobotState's KDL solver
  std::map<std::string, moveit::core::SolverAllocatorFn> allocators;
  for (const std::string& group : groups)
  {
    if (!model_->hasJointModelGroup(group))
      continue;
    const moveit::core::JointModelGroup* jmg = model_->getJointModelGroup(group);
    const kinematics::KinematicsBasePtr solver = allocator(jmg);
    if (!solver)
      continue;
    std::string error;
    if (solver->supportsGroup(jmg, &error))
      allocators[group] = allocator;
    else
    {
      const auto& instance = *solver;
      ROS_ERROR_NAMED(LOGNAME, "Kinematics solver %s does not support joint group %s.  Error: %s",
                      typeid(instance).name(), group.c_str(), error.c_str());
    }
  }
  model_->setKinematicsAllocators(allocators);

  // kinematics_solver_timeout: the group's default IK timeout, its solver's too (l. 222-230)
  for (const auto& entry : kinematics_loader_->getIKTimeout())
    if (model_->hasJointModelGroup(entry.first))
      model_->getJointModelGroup(entry.first)->setDefaultIKTimeout(entry.second);
}

void RobotModelLoader::applyPlanningJointLimits(const std::string& prefix_base)
{
  ros::NodeHandle nh("~");
  for (moveit::core::JointModel* joint : model_->getJointModels())
  {
    std::vector<moveit_msgs::JointLimits> limits = joint->getVariableBoundsMsg();
    for (std::size_t i = 0; i < limits.size(); ++i)
    {
      const std::string prefix = prefix_base + limits[i].joint_name + "/";
      double value;
      bool flag;
      if (nh.getParam(prefix + "max_position", value) && canSpecifyPosition(joint, i))
      {
        limits[i].has_position_limits = true;
        limits[i].max_position = value;
      }
      if (nh.getParam(prefix + "min_position", value) && canSpecifyPosition(joint, i))
      {
        limits[i].has_position_limits = true;
        limits[i].min_position = value;
      }
      if (nh.getParam(prefix + "max_velocity", value))
      {
        limits[i].has_velocity_limits = true;
        limits[i].max_velocity = value;
      }
      if (nh.getParam(prefix + "has_velocity_limits", flag))
        limits[i].has_velocity_limits = flag;
      if (nh.getParam(prefix + "max_acceleration", value))
      {
        limits[i].has_acceleration_limits = true;
        limits[i].max_acceleration = value;
      }
      if (nh.getParam(prefix + "has_acceleration_limits", flag))
        limits[i].has_acceleration_limits = flag;
    }
    joint->setVariableBounds(limits);
  }
}
}  // namespace robot_model_loader

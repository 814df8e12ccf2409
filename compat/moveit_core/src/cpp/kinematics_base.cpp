// kinematics::KinematicsBase's non-pure methods; the defaults are upstream's (kinematics_base.cpp, noetic-devel:
// DEFAULT_SEARCH_DISCRETIZATION 0.1 rad, DEFAULT_TIMEOUT 1.0 s, supported_methods_ {NO_DISCRETIZATION}).
#include <moveit/kinematics_base/kinematics_base.h>
#include <moveit/robot_model/joint_model_group.h>
#include <moveit/robot_model/robot_model.h>

#include <algorithm>

namespace kinematics
{
const double KinematicsBase::DEFAULT_SEARCH_DISCRETIZATION = 0.1;
const double KinematicsBase::DEFAULT_TIMEOUT = 1.0;

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
KinematicsBase::KinematicsBase()
  : tip_frame_("DEPRECATED")
  , search_discretization_(DEFAULT_SEARCH_DISCRETIZATION)
  , default_timeout_(DEFAULT_TIMEOUT)
{
  supported_methods_.push_back(DiscretizationMethods::NO_DISCRETIZATION);
}

KinematicsBase::~KinematicsBase() = default;

void KinematicsBase::setValues(const std::string& robot_description, const std::string& group_name,
                               const std::string& base_frame, const std::vector<std::string>& tip_frames,
                               double search_discretization)
{
  robot_description_ = robot_description;
  group_name_ = group_name;
  base_frame_ = removeSlash(base_frame);
  tip_frames_.clear();
  for (const std::string& tip : tip_frames)
    tip_frames_.push_back(removeSlash(tip));
  if (!tip_frames_.empty())
    tip_frame_ = tip_frames_.front();
  search_discretization_ = search_discretization;
  setSearchDiscretization(search_discretization);
}

void KinematicsBase::setValues(const std::string& robot_description, const std::string& group_name,
                               const std::string& base_frame, const std::string& tip_frame,
                               double search_discretization)
{
  setValues(robot_description, group_name, base_frame, std::vector<std::string>({ tip_frame }), search_discretization);
}

void KinematicsBase::storeValues(const moveit::core::RobotModel& robot_model, const std::string& group_name,
                                 const std::string& base_frame, const std::vector<std::string>& tip_frames,
                                 double search_discretization)
{
  // The solver refers to the model that initialised it without owning it
  robot_model_ = moveit::core::RobotModelConstPtr(&robot_model, [](const moveit::core::RobotModel*) {});
  setValues("", group_name, base_frame, tip_frames, search_discretization);
}
#pragma GCC diagnostic pop

bool KinematicsBase::initialize(const std::string& /*robot_description*/, const std::string& /*group_name*/,
                                const std::string& /*base_frame*/, const std::string& /*tip_frame*/,
                                double /*search_discretization*/)
{
  return false;
}

bool KinematicsBase::initialize(const std::string& robot_description, const std::string& group_name,
                                const std::string& base_frame, const std::vector<std::string>& tip_frames,
                                double search_discretization)
{
  if (tip_frames.size() == 1)
  {
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
    return initialize(robot_description, group_name, base_frame, tip_frames[0], search_discretization);
#pragma GCC diagnostic pop
  }
  ROS_ERROR_NAMED("kinematics_base", "This kinematic solver does not support initialization with more than one tip");
  return false;
}

bool KinematicsBase::initialize(const moveit::core::RobotModel& robot_model, const std::string& group_name,
                                const std::string& base_frame, const std::vector<std::string>& tip_frames,
                                double search_discretization)
{
  ROS_WARN_NAMED("kinematics_base", "IK plugin for group '%s' relies on deprecated API: it does not override "
                                    "initialize(const RobotModel&, ...)",
                 group_name.c_str());
  robot_model_ = moveit::core::RobotModelConstPtr(&robot_model, [](const moveit::core::RobotModel*) {});
  return initialize("robot_description", group_name, base_frame, tip_frames, search_discretization);
}

const std::string& KinematicsBase::getTipFrame() const
{
  if (tip_frames_.size() > 1)
    ROS_ERROR_NAMED("kinematics_base", "This kinematic solver has several tip frames; getTipFrame() gives the first");
  return tip_frames_.at(0);
}

bool KinematicsBase::setRedundantJoints(const std::vector<unsigned int>& redundant_joint_indices)
{
  const std::size_t joint_count = getJointNames().size();
  for (unsigned int index : redundant_joint_indices)
    if (index >= joint_count)
      return false;
  redundant_joint_indices_ = redundant_joint_indices;
  setSearchDiscretization(DEFAULT_SEARCH_DISCRETIZATION);
  return true;
}

bool KinematicsBase::setRedundantJoints(const std::vector<std::string>& redundant_joint_names)
{
  const std::vector<std::string>& names = getJointNames();
  std::vector<unsigned int> indices;
  for (const std::string& name : redundant_joint_names)
  {
    auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end())
      return false;
    indices.push_back(it - names.begin());
  }
  return setRedundantJoints(indices);
}

void KinematicsBase::setSearchDiscretization(double sd)
{
  redundant_joint_discretization_.clear();
  for (unsigned int index : redundant_joint_indices_)
    redundant_joint_discretization_[index] = sd;
}

void KinematicsBase::setSearchDiscretization(const std::map<int, double>& discretization)
{
  redundant_joint_discretization_ = discretization;
  redundant_joint_indices_.clear();
  for (const auto& entry : discretization)
    redundant_joint_indices_.push_back(entry.first);
}

double KinematicsBase::getSearchDiscretization(int joint_index) const
{
  auto it = redundant_joint_discretization_.find(joint_index);
  return it == redundant_joint_discretization_.end() ? 0.0 : it->second;
}

std::string KinematicsBase::removeSlash(const std::string& str) const
{
  return !str.empty() && str[0] == '/' ? str.substr(1) : str;
}

bool KinematicsBase::supportsGroup(const moveit::core::JointModelGroup* jmg, std::string* error_text_out) const
{
  // Legacy solvers serve chains only (kinematics_base.cpp l. 165-178, noetic-devel)
  if (!jmg->isChain())
  {
    if (error_text_out)
      *error_text_out = "This plugin only supports joint groups which are chains";
    return false;
  }
  return true;
}

bool KinematicsBase::getPositionIK(const std::vector<geometry_msgs::Pose>& ik_poses,
                                   const std::vector<double>& ik_seed_state,
                                   std::vector<std::vector<double>>& solutions, KinematicsResult& result,
                                   const kinematics::KinematicsQueryOptions& options) const
{
  solutions.clear();
  if (ik_poses.size() != 1)
  {
    ROS_ERROR_NAMED("kinematics_base", "This kinematic solver does not support getPositionIK for multiple poses");
    result.kinematic_error = KinematicErrors::MULTIPLE_TIPS_NOT_SUPPORTED;
    return false;
  }
  if (options.discretization_method != DiscretizationMethods::NO_DISCRETIZATION)
  {
    result.kinematic_error = KinematicErrors::UNSUPORTED_DISCRETIZATION_REQUESTED;
    return false;
  }
  std::vector<double> solution;
  moveit_msgs::MoveItErrorCodes error;
  if (!getPositionIK(ik_poses[0], ik_seed_state, solution, error, options))
  {
    result.kinematic_error = KinematicErrors::NO_SOLUTION;
    result.solution_percentage = 0.0;
    return false;
  }
  solutions.push_back(solution);
  result.kinematic_error = KinematicErrors::OK;
  result.solution_percentage = 1.0;
  return true;
}

bool KinematicsBase::searchPositionIK(const std::vector<geometry_msgs::Pose>& ik_poses,
                                      const std::vector<double>& ik_seed_state, double timeout,
                                      const std::vector<double>& consistency_limits, std::vector<double>& solution,
                                      const IKCallbackFn& solution_callback, moveit_msgs::MoveItErrorCodes& error_code,
                                      const kinematics::KinematicsQueryOptions& options,
                                      const moveit::core::RobotState* /*context_state*/) const
{
  if (ik_poses.size() != 1)
  {
    ROS_ERROR_NAMED("kinematics_base", "This kinematic solver does not support searchPositionIK with multiple poses");
    return false;
  }
  if (solution_callback)
    return searchPositionIK(ik_poses[0], ik_seed_state, timeout, consistency_limits, solution, solution_callback,
                            error_code, options);
  return searchPositionIK(ik_poses[0], ik_seed_state, timeout, consistency_limits, solution, error_code, options);
}
}  // namespace kinematics

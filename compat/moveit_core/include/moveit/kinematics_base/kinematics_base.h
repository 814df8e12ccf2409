// kinematics::KinematicsBase, the base class of MoveIt's kinematics plugins (MoveIt noetic-devel
// moveit_core/kinematics_base/include/moveit/kinematics_base/kinematics_base.h), the workspace's own implementation with
// upstream's enums, structs, virtual methods, members and defaults, so that IKFast-generated and TRAC-IK plugins
// compile against it and pluginlib can load them as "kinematics::KinematicsBase".
//
// Provided: the whole class (pure virtuals getPositionIK, searchPositionIK (4 overloads), getPositionFK, getJointNames,
// getLinkNames; the multi-pose overloads, initialize (3 overloads), setValues, storeValues, supportsGroup,
// redundant joints, search discretization, default timeout, lookupParam), DEFAULT_SEARCH_DISCRETIZATION (0.1) and
// DEFAULT_TIMEOUT (1.0) as upstream's kinematics_base.cpp defines them.
// Not provided here: loading plugins (kinematics_plugin_loader, moveit_ros_planning): JointModelGroup::getSolverInstance()
// is null until something calls JointModelGroup::setSolverAllocators.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <boost/function.hpp>
#include <geometry_msgs/Pose.h>
#include <moveit/macros/class_forward.h>
#include <moveit_msgs/MoveItErrorCodes.h>
#include <ros/console.h>
#include <ros/node_handle.h>

namespace moveit
{
namespace core
{
MOVEIT_CLASS_FORWARD(JointModelGroup);
MOVEIT_CLASS_FORWARD(RobotState);
MOVEIT_CLASS_FORWARD(RobotModel);
}  // namespace core
}  // namespace moveit

namespace kinematics
{
/// How redundant joints are sampled by searchPositionIK
namespace DiscretizationMethods
{
enum DiscretizationMethod
{
  NO_DISCRETIZATION = 1,
  ALL_DISCRETIZED,
  SOME_DISCRETIZED,
  ALL_RANDOM_SAMPLED,
  SOME_RANDOM_SAMPLED
};
}  // namespace DiscretizationMethods
using DiscretizationMethod = DiscretizationMethods::DiscretizationMethod;

namespace KinematicErrors
{
enum KinematicError
{
  OK = 1,
  UNSUPORTED_DISCRETIZATION_REQUESTED,
  DISCRETIZATION_NOT_INITIALIZED,
  MULTIPLE_TIPS_NOT_SUPPORTED,
  EMPTY_TIP_POSES,
  IK_SEED_OUTSIDE_LIMITS,
  SOLVER_NOT_ACTIVE,
  NO_SOLUTION
};
}  // namespace KinematicErrors
using KinematicError = KinematicErrors::KinematicError;

struct KinematicsQueryOptions
{
  KinematicsQueryOptions()
    : lock_redundant_joints(false)
    , return_approximate_solution(false)
    , discretization_method(DiscretizationMethods::NO_DISCRETIZATION)
  {
  }

  bool lock_redundant_joints;
  bool return_approximate_solution;
  DiscretizationMethod discretization_method;
};

struct KinematicsResult
{
  KinematicError kinematic_error;
  double solution_percentage;
};

MOVEIT_CLASS_FORWARD(KinematicsBase);

class KinematicsBase
{
public:
  static const double DEFAULT_SEARCH_DISCRETIZATION;
  static const double DEFAULT_TIMEOUT;

  /// Called with each IK solution found; sets error_code.val to SUCCESS to accept it
  using IKCallbackFn =
      boost::function<void(const geometry_msgs::Pose&, const std::vector<double>&, moveit_msgs::MoveItErrorCodes&)>;

  virtual bool
  getPositionIK(const geometry_msgs::Pose& ik_pose, const std::vector<double>& ik_seed_state,
                std::vector<double>& solution, moveit_msgs::MoveItErrorCodes& error_code,
                const kinematics::KinematicsQueryOptions& options = kinematics::KinematicsQueryOptions()) const = 0;

  /// All solutions for one or more tip poses; this base answers MULTIPLE_TIPS_NOT_SUPPORTED / NO_SOLUTION through
  /// getPositionIK for a single pose
  virtual bool getPositionIK(const std::vector<geometry_msgs::Pose>& ik_poses, const std::vector<double>& ik_seed_state,
                             std::vector<std::vector<double>>& solutions, KinematicsResult& result,
                             const kinematics::KinematicsQueryOptions& options) const;

  virtual bool
  searchPositionIK(const geometry_msgs::Pose& ik_pose, const std::vector<double>& ik_seed_state, double timeout,
                   std::vector<double>& solution, moveit_msgs::MoveItErrorCodes& error_code,
                   const kinematics::KinematicsQueryOptions& options = kinematics::KinematicsQueryOptions()) const = 0;

  virtual bool
  searchPositionIK(const geometry_msgs::Pose& ik_pose, const std::vector<double>& ik_seed_state, double timeout,
                   const std::vector<double>& consistency_limits, std::vector<double>& solution,
                   moveit_msgs::MoveItErrorCodes& error_code,
                   const kinematics::KinematicsQueryOptions& options = kinematics::KinematicsQueryOptions()) const = 0;

  virtual bool
  searchPositionIK(const geometry_msgs::Pose& ik_pose, const std::vector<double>& ik_seed_state, double timeout,
                   std::vector<double>& solution, const IKCallbackFn& solution_callback,
                   moveit_msgs::MoveItErrorCodes& error_code,
                   const kinematics::KinematicsQueryOptions& options = kinematics::KinematicsQueryOptions()) const = 0;

  virtual bool
  searchPositionIK(const geometry_msgs::Pose& ik_pose, const std::vector<double>& ik_seed_state, double timeout,
                   const std::vector<double>& consistency_limits, std::vector<double>& solution,
                   const IKCallbackFn& solution_callback, moveit_msgs::MoveItErrorCodes& error_code,
                   const kinematics::KinematicsQueryOptions& options = kinematics::KinematicsQueryOptions()) const = 0;

  /// Several tips at once: this base hands a single pose to the single-pose overloads and refuses more than one
  /// (kinematics_base.h l. 326-350, noetic-devel)
  virtual bool
  searchPositionIK(const std::vector<geometry_msgs::Pose>& ik_poses, const std::vector<double>& ik_seed_state,
                   double timeout, const std::vector<double>& consistency_limits, std::vector<double>& solution,
                   const IKCallbackFn& solution_callback, moveit_msgs::MoveItErrorCodes& error_code,
                   const kinematics::KinematicsQueryOptions& options = kinematics::KinematicsQueryOptions(),
                   const moveit::core::RobotState* context_state = nullptr) const;

  virtual bool getPositionFK(const std::vector<std::string>& link_names, const std::vector<double>& joint_angles,
                             std::vector<geometry_msgs::Pose>& poses) const = 0;

  [[deprecated]] virtual void setValues(const std::string& robot_description, const std::string& group_name,
                                        const std::string& base_frame, const std::string& tip_frame,
                                        double search_discretization);
  virtual void setValues(const std::string& robot_description, const std::string& group_name,
                         const std::string& base_frame, const std::vector<std::string>& tip_frames,
                         double search_discretization);

  /// The legacy initializers: they fail in this base (a plugin overrides the one it supports)
  [[deprecated]] virtual bool initialize(const std::string& robot_description, const std::string& group_name,
                                         const std::string& base_frame, const std::string& tip_frame,
                                         double search_discretization);
  virtual bool initialize(const std::string& robot_description, const std::string& group_name,
                          const std::string& base_frame, const std::vector<std::string>& tip_frames,
                          double search_discretization);
  /// The initializer MoveIt calls; this base falls back to the string-based one for a single tip, as upstream's
  virtual bool initialize(const moveit::core::RobotModel& robot_model, const std::string& group_name,
                          const std::string& base_frame, const std::vector<std::string>& tip_frames,
                          double search_discretization);

  virtual const std::string& getGroupName() const
  {
    return group_name_;
  }
  virtual const std::string& getBaseFrame() const
  {
    return base_frame_;
  }
  /// The first tip frame (a ROS error when the solver has several)
  virtual const std::string& getTipFrame() const;
  virtual const std::vector<std::string>& getTipFrames() const
  {
    return tip_frames_;
  }

  virtual bool setRedundantJoints(const std::vector<unsigned int>& redundant_joint_indices);
  bool setRedundantJoints(const std::vector<std::string>& redundant_joint_names);
  virtual void getRedundantJoints(std::vector<unsigned int>& redundant_joint_indices) const
  {
    redundant_joint_indices = redundant_joint_indices_;
  }

  virtual const std::vector<std::string>& getJointNames() const = 0;
  virtual const std::vector<std::string>& getLinkNames() const = 0;

  /// Whether this solver can serve the group: by default, when the group is a chain
  virtual bool supportsGroup(const moveit::core::JointModelGroup* jmg, std::string* error_text_out = nullptr) const;

  /// The same step for every redundant joint
  void setSearchDiscretization(double sd);
  /// Per-joint steps; the joints named become the redundant joints
  void setSearchDiscretization(const std::map<int, double>& discretization);
  /// The step of a redundant joint, 0 when it has none
  double getSearchDiscretization(int joint_index = 0) const;
  std::vector<DiscretizationMethod> getSupportedDiscretizationMethods() const
  {
    return supported_methods_;
  }

  void setDefaultTimeout(double timeout)
  {
    default_timeout_ = timeout;
  }
  double getDefaultTimeout() const
  {
    return default_timeout_;
  }

  virtual ~KinematicsBase();
  KinematicsBase();

protected:
  moveit::core::RobotModelConstPtr robot_model_;
  std::string robot_description_;
  std::string group_name_;
  std::string base_frame_;
  std::vector<std::string> tip_frames_;
  [[deprecated]] std::string tip_frame_;
  [[deprecated]] double search_discretization_;
  double default_timeout_;
  std::vector<unsigned int> redundant_joint_indices_;
  std::map<int, double> redundant_joint_discretization_;
  std::vector<DiscretizationMethod> supported_methods_;

  /// A kinematics parameter, searched where MoveIt searches it: the node's private "<group>/<param>", its private
  /// "<param>", then "robot_description_kinematics/<group>/<param>" and "robot_description_kinematics/<param>";
  /// false (and val = default_val) when none is set
  template <typename T>
  inline bool lookupParam(const std::string& param, T& val, const T& default_val) const
  {
    const ros::NodeHandle private_nh("~");
    const ros::NodeHandle nh;
    const std::vector<std::pair<const ros::NodeHandle*, std::string>> places = {
      { &private_nh, group_name_ + "/" + param },
      { &private_nh, param },
      { &nh, "robot_description_kinematics/" + group_name_ + "/" + param },
      { &nh, "robot_description_kinematics/" + param },
    };
    for (const auto& place : places)
      if (place.first->hasParam(place.second))
      {
        val = place.first->param(place.second, default_val);
        return true;
      }
    val = default_val;
    return false;
  }

  /// Keeps what initialize() was given (the model is referred to, not owned)
  void storeValues(const moveit::core::RobotModel& robot_model, const std::string& group_name,
                   const std::string& base_frame, const std::vector<std::string>& tip_frames,
                   double search_discretization);

private:
  std::string removeSlash(const std::string& str) const;
};
}  // namespace kinematics

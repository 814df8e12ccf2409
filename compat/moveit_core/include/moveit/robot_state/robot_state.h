// moveit::core::RobotState (MoveIt noetic-devel moveit_core/robot_state/include/moveit/robot_state/robot_state.h), the
// workspace's own implementation.
//
// Provided: variable positions (whole state, by name, by map, names + values, JointState messages), velocities and
// efforts, joint and joint-group positions (by group or group name; std::vector, double*, Eigen::VectorXd),
// setToDefaultValues (all variables, or a group's SRDF state), setToRandomPositions (within bounds; optionally a group
// or a given generator), setToRandomPositionsNearBy, forward kinematics (update, updateLinkTransforms,
// getGlobalLinkTransform, getJointTransform, getFrameTransform, knowsFrameTransform: link frames and the model
// frame), bounds (satisfiesBounds, enforceBounds, harmonizePositions), distance, interpolate, getJacobian (revolute
// and prismatic joints), setFromIK (a group's loaded kinematics solver when it has one, called as robot_state.cpp's
// setFromIK calls it on noetic-devel: see robot_state.cpp; else, where MoveIt would fail with "No kinematics solver
// instantiated", the workspace's KDL solver: Levenberg-Marquardt, restarted from random seeds until the timeout),
// setToIKSolverFrame, printStatePositions, printStateInfo, printTransforms.
// Not provided: attached bodies (attachBody, getAttachedBodies...: moveit::core::AttachedBody needs geometric_shapes,
// which Debian does not package; attach objects through move_group), collision body transforms, robot markers,
// setFromDiffIK, computeCartesianPath (ask move_group's compute_cartesian_path), accelerations, dynamics.
#pragma once

#include <iostream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>
#include <boost/function.hpp>
#include <eigen_stl_containers/eigen_stl_containers.h>
#include <geometry_msgs/Pose.h>
#include <moveit/robot_model/robot_model.h>
#include <sensor_msgs/JointState.h>

namespace moveit
{
namespace core
{
MOVEIT_CLASS_FORWARD(RobotState);

/// Checks a candidate (e.g. an IK solution for joint_group): true when the state is acceptable
typedef boost::function<bool(RobotState* robot_state, const JointModelGroup* joint_group,
                             const double* joint_group_variable_values)>
    GroupStateValidityCallbackFn;

class RobotState
{
public:
  EIGEN_MAKE_ALIGNED_OPERATOR_NEW

  /// A state of the model; its positions are undefined until set (setToDefaultValues() sets them all)
  RobotState(const RobotModelConstPtr& robot_model);
  ~RobotState();
  RobotState(const RobotState& other);
  RobotState& operator=(const RobotState& other);

  const RobotModelConstPtr& getRobotModel() const
  {
    return robot_model_;
  }
  std::size_t getVariableCount() const
  {
    return robot_model_->getVariableCount();
  }
  const std::vector<std::string>& getVariableNames() const
  {
    return robot_model_->getVariableNames();
  }
  const LinkModel* getLinkModel(const std::string& link) const
  {
    return robot_model_->getLinkModel(link);
  }
  const JointModel* getJointModel(const std::string& joint) const
  {
    return robot_model_->getJointModel(joint);
  }
  const JointModelGroup* getJointModelGroup(const std::string& group) const
  {
    return robot_model_->getJointModelGroup(group);
  }

  double* getVariablePositions()
  {
    return position_.data();
  }
  const double* getVariablePositions() const
  {
    return position_.data();
  }
  void setVariablePositions(const double* position);
  void setVariablePositions(const std::vector<double>& position);
  void setVariablePositions(const std::map<std::string, double>& variable_map);
  void setVariablePositions(const std::map<std::string, double>& variable_map,
                            std::vector<std::string>& missing_variables);
  void setVariablePositions(const std::vector<std::string>& variable_names,
                            const std::vector<double>& variable_position);
  void setVariablePosition(const std::string& variable, double value);
  void setVariablePosition(int index, double value);
  double getVariablePosition(const std::string& variable) const;
  double getVariablePosition(int index) const
  {
    return position_[index];
  }

  bool hasVelocities() const
  {
    return has_velocity_;
  }
  double* getVariableVelocities();
  const double* getVariableVelocities() const
  {
    return velocity_.data();
  }
  void zeroVelocities();
  void setVariableVelocities(const double* velocity);
  void setVariableVelocities(const std::vector<double>& velocity)
  {
    setVariableVelocities(velocity.data());
  }
  void setVariableVelocities(const std::map<std::string, double>& variable_map);
  void setVariableVelocities(const std::vector<std::string>& variable_names,
                             const std::vector<double>& variable_velocity);
  void setVariableVelocity(int index, double value);
  double getVariableVelocity(int index) const
  {
    return velocity_[index];
  }
  void dropVelocities()
  {
    has_velocity_ = false;
  }

  bool hasEffort() const
  {
    return has_effort_;
  }
  double* getVariableEffort();
  const double* getVariableEffort() const
  {
    return effort_.data();
  }
  void zeroEffort();
  void setVariableEffort(const double* effort);
  void setVariableEffort(const std::vector<double>& effort)
  {
    setVariableEffort(effort.data());
  }
  void setVariableEffort(const std::map<std::string, double>& variable_map);
  void setVariableEffort(const std::vector<std::string>& variable_names, const std::vector<double>& variable_effort);
  void dropEffort()
  {
    has_effort_ = false;
  }

  void setJointPositions(const std::string& joint_name, const double* position)
  {
    setJointPositions(robot_model_->getJointModel(joint_name), position);
  }
  void setJointPositions(const std::string& joint_name, const std::vector<double>& position)
  {
    setJointPositions(robot_model_->getJointModel(joint_name), position.data());
  }
  void setJointPositions(const JointModel* joint, const std::vector<double>& position)
  {
    setJointPositions(joint, position.data());
  }
  void setJointPositions(const JointModel* joint, const double* position);
  void setJointPositions(const std::string& joint_name, const Eigen::Isometry3d& transform)
  {
    setJointPositions(robot_model_->getJointModel(joint_name), transform);
  }
  void setJointPositions(const JointModel* joint, const Eigen::Isometry3d& transform);
  const double* getJointPositions(const std::string& joint_name) const
  {
    return getJointPositions(robot_model_->getJointModel(joint_name));
  }
  const double* getJointPositions(const JointModel* joint) const
  {
    return position_.data() + joint->getFirstVariableIndex();
  }

  /// Positions of a group's variables, in JointModelGroup::getVariableNames() order (ROS error: unknown group)
  void setJointGroupPositions(const std::string& joint_group_name, const double* gstate);
  void setJointGroupPositions(const std::string& joint_group_name, const std::vector<double>& gstate);
  void setJointGroupPositions(const JointModelGroup* group, const std::vector<double>& gstate);
  void setJointGroupPositions(const JointModelGroup* group, const double* gstate);
  void setJointGroupPositions(const std::string& joint_group_name, const Eigen::VectorXd& values);
  void setJointGroupPositions(const JointModelGroup* group, const Eigen::VectorXd& values);
  /// Positions of a group's active joints' variables only (mimic joints follow)
  void setJointGroupActivePositions(const JointModelGroup* group, const std::vector<double>& gstate);
  void setJointGroupActivePositions(const std::string& joint_group_name, const std::vector<double>& gstate);
  void setJointGroupActivePositions(const JointModelGroup* group, const Eigen::VectorXd& values);
  void setJointGroupActivePositions(const std::string& joint_group_name, const Eigen::VectorXd& values);
  void copyJointGroupPositions(const std::string& joint_group_name, std::vector<double>& gstate) const;
  void copyJointGroupPositions(const std::string& joint_group_name, double* gstate) const;
  void copyJointGroupPositions(const JointModelGroup* group, std::vector<double>& gstate) const;
  void copyJointGroupPositions(const JointModelGroup* group, double* gstate) const;
  void copyJointGroupPositions(const std::string& joint_group_name, Eigen::VectorXd& values) const;
  void copyJointGroupPositions(const JointModelGroup* group, Eigen::VectorXd& values) const;
  void copyJointGroupVelocities(const JointModelGroup* group, std::vector<double>& gstate) const;
  void copyJointGroupVelocities(const std::string& joint_group_name, std::vector<double>& gstate) const;

  /// Sets the group's variables to an IK solution for @e pose (in the model frame) of the group's end-effector tip
  /// (or @e tip). Solved by the group's kinematics solver when one is loaded, else by KDL (positions to 1e-6 m);
  /// @e timeout 0 takes the group's default IK timeout. A solution is accepted when @e constraint (if given) agrees.
  bool setFromIK(const JointModelGroup* group, const geometry_msgs::Pose& pose, double timeout = 0.0,
                 const GroupStateValidityCallbackFn& constraint = GroupStateValidityCallbackFn(),
                 const kinematics::KinematicsQueryOptions& options = kinematics::KinematicsQueryOptions());
  [[deprecated("The attempts argument is not supported anymore.")]] bool
  setFromIK(const JointModelGroup* group, const geometry_msgs::Pose& pose, unsigned int /* attempts */,
            double timeout = 0.0, const GroupStateValidityCallbackFn& constraint = GroupStateValidityCallbackFn(),
            const kinematics::KinematicsQueryOptions& options = kinematics::KinematicsQueryOptions())
  {
    return setFromIK(group, pose, timeout, constraint, options);
  }
  bool setFromIK(const JointModelGroup* group, const geometry_msgs::Pose& pose, const std::string& tip,
                 double timeout = 0.0, const GroupStateValidityCallbackFn& constraint = GroupStateValidityCallbackFn(),
                 const kinematics::KinematicsQueryOptions& options = kinematics::KinematicsQueryOptions());
  [[deprecated("The attempts argument is not supported anymore.")]] bool
  setFromIK(const JointModelGroup* group, const geometry_msgs::Pose& pose, const std::string& tip,
            unsigned int /* attempts */, double timeout = 0.0,
            const GroupStateValidityCallbackFn& constraint = GroupStateValidityCallbackFn(),
            const kinematics::KinematicsQueryOptions& options = kinematics::KinematicsQueryOptions())
  {
    return setFromIK(group, pose, tip, timeout, constraint, options);
  }
  bool setFromIK(const JointModelGroup* group, const Eigen::Isometry3d& pose, double timeout = 0.0,
                 const GroupStateValidityCallbackFn& constraint = GroupStateValidityCallbackFn(),
                 const kinematics::KinematicsQueryOptions& options = kinematics::KinematicsQueryOptions());
  [[deprecated("The attempts argument is not supported anymore.")]] bool
  setFromIK(const JointModelGroup* group, const Eigen::Isometry3d& pose, unsigned int /* attempts */,
            double timeout = 0.0, const GroupStateValidityCallbackFn& constraint = GroupStateValidityCallbackFn(),
            const kinematics::KinematicsQueryOptions& options = kinematics::KinematicsQueryOptions())
  {
    return setFromIK(group, pose, timeout, constraint, options);
  }
  bool setFromIK(const JointModelGroup* group, const Eigen::Isometry3d& pose, const std::string& tip,
                 double timeout = 0.0, const GroupStateValidityCallbackFn& constraint = GroupStateValidityCallbackFn(),
                 const kinematics::KinematicsQueryOptions& options = kinematics::KinematicsQueryOptions());
  [[deprecated("The attempts argument is not supported anymore.")]] bool
  setFromIK(const JointModelGroup* group, const Eigen::Isometry3d& pose, const std::string& tip,
            unsigned int /* attempts */, double timeout = 0.0,
            const GroupStateValidityCallbackFn& constraint = GroupStateValidityCallbackFn(),
            const kinematics::KinematicsQueryOptions& options = kinematics::KinematicsQueryOptions())
  {
    return setFromIK(group, pose, tip, timeout, constraint, options);
  }
  /// As above, with the solver's consistency limits (how far each of its joints may move from the seed)
  bool setFromIK(const JointModelGroup* group, const Eigen::Isometry3d& pose, const std::string& tip,
                 const std::vector<double>& consistency_limits, double timeout = 0.0,
                 const GroupStateValidityCallbackFn& constraint = GroupStateValidityCallbackFn(),
                 const kinematics::KinematicsQueryOptions& options = kinematics::KinematicsQueryOptions());
  /// @e pose (model frame) into the frame of the IK solver (its base frame); false when that frame is unknown
  bool setToIKSolverFrame(Eigen::Isometry3d& pose, const kinematics::KinematicsBaseConstPtr& solver);
  bool setToIKSolverFrame(Eigen::Isometry3d& pose, const std::string& ik_frame);

  /// The geometric Jacobian (6 x active variables: linear rows first) of @e link's @e reference_point_position, in
  /// the model frame, for the group's chain; quaternion representation is not provided (false and a ROS error)
  bool getJacobian(const JointModelGroup* group, const LinkModel* link, const Eigen::Vector3d& reference_point_position,
                   Eigen::MatrixXd& jacobian, bool use_quaternion_representation = false) const;
  Eigen::MatrixXd getJacobian(const JointModelGroup* group,
                              const Eigen::Vector3d& reference_point_position = Eigen::Vector3d(0.0, 0.0, 0.0)) const;

  void setVariableValues(const sensor_msgs::JointState& msg);

  void setToDefaultValues();
  /// The SRDF's group state @e name; false when the group has none
  bool setToDefaultValues(const JointModelGroup* group, const std::string& name);
  bool setToDefaultValues(const std::string& group_name, const std::string& state_name);
  void setToRandomPositions();
  void setToRandomPositions(random_numbers::RandomNumberGenerator& rng);
  void setToRandomPositions(const JointModelGroup* group);
  void setToRandomPositions(const JointModelGroup* group, random_numbers::RandomNumberGenerator& rng);
  void setToRandomPositionsNearBy(const JointModelGroup* group, const RobotState& seed, double distance);
  void setToRandomPositionsNearBy(const JointModelGroup* group, const RobotState& seed, double distance,
                                  random_numbers::RandomNumberGenerator& rng);

  /// Recomputes the link transforms if any position changed since (always with @e force)
  void update(bool force = false);
  void updateLinkTransforms();
  /// The link's pose in the model frame; the non-const overloads update first, the const ones require an up-to-date
  /// state (a ROS error otherwise, as MoveIt asserts)
  const Eigen::Isometry3d& getGlobalLinkTransform(const std::string& link_name)
  {
    return getGlobalLinkTransform(robot_model_->getLinkModel(link_name));
  }
  const Eigen::Isometry3d& getGlobalLinkTransform(const LinkModel* link)
  {
    updateLinkTransforms();
    return global_link_transforms_[link->getLinkIndex()];
  }
  const Eigen::Isometry3d& getGlobalLinkTransform(const std::string& link_name) const
  {
    return getGlobalLinkTransform(robot_model_->getLinkModel(link_name));
  }
  const Eigen::Isometry3d& getGlobalLinkTransform(const LinkModel* link) const;
  /// The joint's motion transform (its child link relative to the joint frame)
  const Eigen::Isometry3d& getJointTransform(const std::string& joint_name)
  {
    return getJointTransform(robot_model_->getJointModel(joint_name));
  }
  const Eigen::Isometry3d& getJointTransform(const JointModel* joint);
  const Eigen::Isometry3d& getJointTransform(const std::string& joint_name) const
  {
    return getJointTransform(robot_model_->getJointModel(joint_name));
  }
  const Eigen::Isometry3d& getJointTransform(const JointModel* joint) const;
  bool dirtyLinkTransforms() const
  {
    return dirty_;
  }
  bool dirty() const
  {
    return dirty_;
  }

  double distance(const RobotState& other) const
  {
    return robot_model_->distance(position_.data(), other.getVariablePositions());
  }
  double distance(const RobotState& other, const JointModelGroup* joint_group) const;
  void interpolate(const RobotState& to, double t, RobotState& state) const;
  void interpolate(const RobotState& to, double t, RobotState& state, const JointModelGroup* joint_group) const;

  void enforceBounds();
  void enforceBounds(const JointModelGroup* joint_group);
  void enforceBounds(const JointModel* joint);
  void harmonizePositions();
  void harmonizePositions(const JointModelGroup* joint_group);
  bool satisfiesBounds(double margin = 0.0) const;
  bool satisfiesBounds(const JointModelGroup* joint_group, double margin = 0.0) const;
  bool satisfiesBounds(const JointModel* joint, double margin = 0.0) const;

  /// A link's pose in the model frame, the model frame itself (identity), or, with a leading '/', the same names;
  /// an unknown frame gives identity, a ROS error and *frame_found = false
  const Eigen::Isometry3d& getFrameTransform(const std::string& frame_id, bool* frame_found = nullptr);
  const Eigen::Isometry3d& getFrameTransform(const std::string& frame_id, bool* frame_found = nullptr) const;
  bool knowsFrameTransform(const std::string& frame_id) const;
  /// The nearest link that @e frame (a link name) is rigidly attached to; see RobotModel
  const moveit::core::LinkModel*
  getRigidlyConnectedParentLinkModel(const std::string& frame, Eigen::Isometry3d* transform = nullptr,
                                     const moveit::core::JointModelGroup* jmg = nullptr) const;

  void printStatePositions(std::ostream& out = std::cout) const;
  void printStatePositionsWithJointLimits(const moveit::core::JointModelGroup* jmg, std::ostream& out = std::cout) const;
  void printStateInfo(std::ostream& out = std::cout) const;
  void printTransforms(std::ostream& out = std::cout) const;
  void printTransform(const Eigen::Isometry3d& transform, std::ostream& out = std::cout) const;
  /// The state's generator, made when first asked for (public, as upstream's)
  random_numbers::RandomNumberGenerator& getRandomNumberGenerator();

private:
  void updateMimicJoint(const JointModel* joint);
  void markDirty()
  {
    dirty_ = true;
  }
  /// The KDL fallback of setFromIK: pose (model frame) of @e tip, solving the group's variables
  bool setFromIKWithKDL(const JointModelGroup* group, const Eigen::Isometry3d& pose, const LinkModel* tip,
                        double timeout, const GroupStateValidityCallbackFn& constraint);
  bool setFromIKWithSolver(const JointModelGroup* group, const Eigen::Isometry3d& pose, const std::string& tip,
                           const std::vector<double>& consistency_limits, double timeout,
                           const GroupStateValidityCallbackFn& constraint,
                           const kinematics::KinematicsQueryOptions& options);

  RobotModelConstPtr robot_model_;
  std::vector<double> position_;
  std::vector<double> velocity_;
  std::vector<double> effort_;
  bool has_velocity_ = false;
  bool has_effort_ = false;
  bool dirty_ = true;
  EigenSTL::vector_Isometry3d joint_transforms_;
  EigenSTL::vector_Isometry3d global_link_transforms_;
  std::unique_ptr<random_numbers::RandomNumberGenerator> rng_;
};

/// The state's variable positions, one per line
std::ostream& operator<<(std::ostream& out, const RobotState& s);
}  // namespace core
}  // namespace moveit

// moveit::core::JointModelGroup (MoveIt noetic-devel moveit_core/robot_model/include/moveit/robot_model/
// joint_model_group.h), the workspace's own implementation.
//
// Provided: names, joints (all, active, fixed, mimic, continuous), variables and their indices in the robot's
// state, links and updated links, default states from the SRDF (getDefaultStateNames, getVariableDefaultPositions),
// random and default positions, bounds (getActiveJointModelsBounds, satisfies/enforcePositionBounds), distance,
// interpolation, subgroups, chain detection (isChain: the group's active joints lie on one path from a base link to a
// tip), end-effector data (getEndEffectorName, getEndEffectorParentGroup, getAttachedEndEffectorNames,
// getEndEffectorTips, getOnlyOneEndEffectorTip), kinematics solver slots (setSolverAllocators, getSolverInstance,
// canSetStateFromIK, default IK timeout).
// getSolverInstance() is null until a kinematics solver is allocated for the group: robot_model_loader::
// RobotModelLoader (moveit_ros_planning) allocates the kinematics.yaml's C++ plugin; a group without one (MoveIt's
// own KDL/LMA/TRAC-IK names, or a plugin that could not be loaded) is solved by RobotState::setFromIK's KDL solver.
#pragma once

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <boost/function.hpp>
#include <moveit/kinematics_base/kinematics_base.h>
#include <moveit/robot_model/joint_model.h>
#include <moveit/robot_model/link_model.h>
#include <srdfdom/model.h>

namespace moveit
{
namespace core
{
class RobotModel;
class JointModelGroup;

typedef boost::function<kinematics::KinematicsBasePtr(const JointModelGroup*)> SolverAllocatorFn;
using SolverAllocatorMapFn = std::map<const JointModelGroup*, SolverAllocatorFn>;
using JointModelGroupMap = std::map<std::string, JointModelGroup*>;
using JointModelGroupMapConst = std::map<std::string, const JointModelGroup*>;
using JointBoundsVector = std::vector<const JointModel::Bounds*>;

class JointModelGroup
{
public:
  struct KinematicsSolver
  {
    /// True once an allocator made a solver and its joints were matched with the group's
    operator bool() const
    {
      return allocator_ && !bijection_.empty() && solver_instance_;
    }
    void reset()
    {
      solver_instance_.reset();
      bijection_.clear();
    }

    SolverAllocatorFn allocator_;
    /// bijection_[i]: the group variable that is the solver's i-th joint
    std::vector<unsigned int> bijection_;
    kinematics::KinematicsBasePtr solver_instance_;
    /// MoveIt's default (joint_model_group.h KinematicsSolver(), noetic-devel)
    double default_ik_timeout_ = 0.5;
  };
  using KinematicsSolverMap = std::map<const JointModelGroup*, KinematicsSolver>;

  JointModelGroup(const std::string& name, const srdf::Model::Group& config,
                  const std::vector<const JointModel*>& joint_vector, const RobotModel* parent_model);
  ~JointModelGroup();

  const RobotModel& getParentModel() const
  {
    return *parent_model_;
  }
  const std::string& getName() const
  {
    return name_;
  }
  const srdf::Model::Group& getConfig() const
  {
    return config_;
  }

  bool hasJointModel(const std::string& joint) const;
  bool hasLinkModel(const std::string& link) const;
  const JointModel* getJointModel(const std::string& joint) const;
  const LinkModel* getLinkModel(const std::string& link) const;

  const std::vector<const JointModel*>& getJointModels() const
  {
    return joint_model_vector_;
  }
  const std::vector<std::string>& getJointModelNames() const
  {
    return joint_model_name_vector_;
  }
  /// Joints with variables of their own: not fixed, not mimic
  const std::vector<const JointModel*>& getActiveJointModels() const
  {
    return active_joint_model_vector_;
  }
  const std::vector<std::string>& getActiveJointModelNames() const
  {
    return active_joint_model_name_vector_;
  }
  const std::vector<const JointModel*>& getFixedJointModels() const
  {
    return fixed_joints_;
  }
  const std::vector<const JointModel*>& getMimicJointModels() const
  {
    return mimic_joints_;
  }
  const std::vector<const JointModel*>& getContinuousJointModels() const
  {
    return continuous_joint_model_vector_;
  }
  /// The variables of the group's joints (mimic joints' included), in the robot state's order
  const std::vector<std::string>& getVariableNames() const
  {
    return variable_names_;
  }
  /// Joints of the group whose parent joint is not in the group
  const std::vector<const JointModel*>& getJointRoots() const
  {
    return joint_roots_;
  }
  const JointModel* getCommonRoot() const
  {
    return common_root_;
  }
  /// The links whose parent joint is in the group
  const std::vector<const LinkModel*>& getLinkModels() const
  {
    return link_model_vector_;
  }
  const std::vector<std::string>& getLinkModelNames() const
  {
    return link_model_name_vector_;
  }
  /// The links that move when the group's joints move
  const std::vector<const LinkModel*>& getUpdatedLinkModels() const
  {
    return updated_link_model_vector_;
  }
  const std::set<const LinkModel*>& getUpdatedLinkModelsSet() const
  {
    return updated_link_model_set_;
  }
  const std::vector<std::string>& getUpdatedLinkModelNames() const
  {
    return updated_link_model_name_vector_;
  }
  bool isLinkUpdated(const std::string& name) const
  {
    return updated_link_model_name_set_.count(name) > 0;
  }
  /// Index in the robot state of each of getVariableNames()
  const std::vector<int>& getVariableIndexList() const
  {
    return variable_index_list_;
  }
  /// Index of a variable within the group's vector; -1 (and a ROS error) when the group has no such variable
  int getVariableGroupIndex(const std::string& variable) const;

  const std::vector<std::string>& getDefaultStateNames() const
  {
    return default_states_names_;
  }
  void addDefaultState(const std::string& name, const std::map<std::string, double>& default_state);
  /// The SRDF's <group_state> @e name; false when the group has none of that name
  bool getVariableDefaultPositions(const std::string& name, std::map<std::string, double>& values) const;
  void getVariableDefaultPositions(std::map<std::string, double>& values) const;
  void getVariableDefaultPositions(std::vector<double>& values) const
  {
    values.resize(variable_count_);
    getVariableDefaultPositions(values.data());
  }
  void getVariableDefaultPositions(double* values) const;

  void getVariableRandomPositions(random_numbers::RandomNumberGenerator& rng, double* values) const
  {
    getVariableRandomPositions(rng, values, active_joint_models_bounds_);
  }
  void getVariableRandomPositions(random_numbers::RandomNumberGenerator& rng, std::vector<double>& values) const
  {
    values.resize(variable_count_);
    getVariableRandomPositions(rng, values.data(), active_joint_models_bounds_);
  }
  void getVariableRandomPositions(random_numbers::RandomNumberGenerator& rng, double* values,
                                  const JointBoundsVector& active_joint_bounds) const;
  void getVariableRandomPositionsNearBy(random_numbers::RandomNumberGenerator& rng, double* values, const double* seed,
                                        const double distance) const
  {
    getVariableRandomPositionsNearBy(rng, values, active_joint_models_bounds_, seed, distance);
  }
  void getVariableRandomPositionsNearBy(random_numbers::RandomNumberGenerator& rng, std::vector<double>& values,
                                        const std::vector<double>& seed, double distance) const
  {
    values.resize(variable_count_);
    getVariableRandomPositionsNearBy(rng, values.data(), active_joint_models_bounds_, seed.data(), distance);
  }
  void getVariableRandomPositionsNearBy(random_numbers::RandomNumberGenerator& rng, double* values,
                                        const JointBoundsVector& active_joint_bounds, const double* seed,
                                        const double distance) const;

  bool enforcePositionBounds(double* state) const
  {
    return enforcePositionBounds(state, active_joint_models_bounds_);
  }
  bool enforcePositionBounds(double* state, const JointBoundsVector& active_joint_bounds) const;
  bool satisfiesPositionBounds(const double* state, double margin = 0.0) const
  {
    return satisfiesPositionBounds(state, active_joint_models_bounds_, margin);
  }
  bool satisfiesPositionBounds(const double* state, const JointBoundsVector& active_joint_bounds,
                               double margin = 0.0) const;
  double getMaximumExtent() const
  {
    return getMaximumExtent(active_joint_models_bounds_);
  }
  double getMaximumExtent(const JointBoundsVector& active_joint_bounds) const;
  double distance(const double* state1, const double* state2) const;
  void interpolate(const double* from, const double* to, double t, double* state) const;

  unsigned int getVariableCount() const
  {
    return variable_count_;
  }
  unsigned int getActiveVariableCount() const
  {
    return active_variable_count_;
  }

  void setSubgroupNames(const std::vector<std::string>& subgroups);
  const std::vector<std::string>& getSubgroupNames() const
  {
    return subgroup_names_;
  }
  void getSubgroups(std::vector<const JointModelGroup*>& sub_groups) const;
  bool isSubgroup(const std::string& group) const
  {
    return subgroup_names_set_.count(group) > 0;
  }

  bool isChain() const
  {
    return is_chain_;
  }
  bool isSingleDOFJoints() const
  {
    return is_single_dof_;
  }
  /// True when an SRDF <end_effector> names this group as its component group
  bool isEndEffector() const
  {
    return !end_effector_name_.empty();
  }
  bool isContiguousWithinState() const
  {
    return is_contiguous_index_list_;
  }
  const std::string& getEndEffectorName() const
  {
    return end_effector_name_;
  }
  void setEndEffectorName(const std::string& name);
  void setEndEffectorParent(const std::string& group, const std::string& link);
  void attachEndEffector(const std::string& eef_name);
  /// For an end-effector group: the group it is attached to (may be empty) and the link it hangs from
  const std::pair<std::string, std::string>& getEndEffectorParentGroup() const
  {
    return end_effector_parent_;
  }
  /// The end effectors whose parent group is this group
  const std::vector<std::string>& getAttachedEndEffectorNames() const
  {
    return attached_end_effector_names_;
  }
  /// The parent links of the end effectors attached to this group (or to its subgroups)
  bool getEndEffectorTips(std::vector<const LinkModel*>& tips) const;
  bool getEndEffectorTips(std::vector<std::string>& tips) const;
  /// The single end-effector tip; nullptr (and a ROS error) when there is none or more than one
  const moveit::core::LinkModel* getOnlyOneEndEffectorTip() const;

  const JointBoundsVector& getActiveJointModelsBounds() const
  {
    return active_joint_models_bounds_;
  }

  const std::pair<KinematicsSolver, KinematicsSolverMap>& getGroupKinematics() const
  {
    return group_kinematics_;
  }
  void setSolverAllocators(const SolverAllocatorFn& solver,
                           const SolverAllocatorMapFn& solver_map = SolverAllocatorMapFn())
  {
    setSolverAllocators(std::make_pair(solver, solver_map));
  }
  void setSolverAllocators(const std::pair<SolverAllocatorFn, SolverAllocatorMapFn>& solvers);
  const kinematics::KinematicsBaseConstPtr getSolverInstance() const
  {
    return group_kinematics_.first.solver_instance_;
  }
  const kinematics::KinematicsBasePtr& getSolverInstance()
  {
    return group_kinematics_.first.solver_instance_;
  }
  /// Whether a loaded solver serves @e tip
  bool canSetStateFromIK(const std::string& tip) const;
  bool setRedundantJoints(const std::vector<std::string>& joints);
  double getDefaultIKTimeout() const
  {
    return group_kinematics_.first.default_ik_timeout_;
  }
  void setDefaultIKTimeout(double ik_timeout);
  const std::vector<unsigned int>& getKinematicsSolverJointBijection() const
  {
    return group_kinematics_.first.bijection_;
  }

  void printGroupInfo(std::ostream& out = std::cout) const;

  bool isValidVelocityMove(const std::vector<double>& from_joint_pose, const std::vector<double>& to_joint_pose,
                           double dt) const;
  bool isValidVelocityMove(const double* from_joint_pose, const double* to_joint_pose, std::size_t array_size,
                           double dt) const;

protected:
  /// Matches a solver's joint names with the group's variables
  bool computeIKIndexBijection(const std::vector<std::string>& ik_jnames,
                               std::vector<unsigned int>& joint_bijection) const;
  /// Sets the group's mimic joints from the joints they follow (values: the group's vector)
  void updateMimicJoints(double* values) const;

  const RobotModel* parent_model_;
  std::string name_;
  std::vector<const JointModel*> joint_model_vector_;
  std::vector<std::string> joint_model_name_vector_;
  std::vector<const JointModel*> active_joint_model_vector_;
  std::vector<std::string> active_joint_model_name_vector_;
  std::vector<const JointModel*> fixed_joints_;
  std::vector<const JointModel*> mimic_joints_;
  std::vector<const JointModel*> continuous_joint_model_vector_;
  std::vector<std::string> variable_names_;
  std::set<std::string> variable_names_set_;
  std::map<std::string, int> variable_group_index_map_;
  std::map<std::string, const JointModel*> joint_model_map_;
  std::map<std::string, const LinkModel*> link_model_map_;
  std::vector<const JointModel*> joint_roots_;
  const JointModel* common_root_ = nullptr;
  std::vector<int> variable_index_list_;
  /// Start of each active joint's variables within the group's vector
  std::vector<int> active_joint_model_start_index_;
  std::vector<const LinkModel*> link_model_vector_;
  std::vector<std::string> link_model_name_vector_;
  std::vector<const LinkModel*> updated_link_model_vector_;
  std::set<const LinkModel*> updated_link_model_set_;
  std::vector<std::string> updated_link_model_name_vector_;
  std::set<std::string> updated_link_model_name_set_;
  JointBoundsVector active_joint_models_bounds_;
  unsigned int variable_count_ = 0;
  unsigned int active_variable_count_ = 0;
  bool is_contiguous_index_list_ = true;
  std::vector<std::string> subgroup_names_;
  std::set<std::string> subgroup_names_set_;
  std::vector<std::string> attached_end_effector_names_;
  std::pair<std::string, std::string> end_effector_parent_;
  std::string end_effector_name_;
  bool is_chain_ = false;
  bool is_single_dof_ = true;
  struct GroupMimicUpdate
  {
    int src;
    int dest;
    double factor;
    double offset;
  };
  std::vector<GroupMimicUpdate> group_mimic_update_;
  std::pair<KinematicsSolver, KinematicsSolverMap> group_kinematics_;
  srdf::Model::Group config_;
  std::map<std::string, std::map<std::string, double>> default_states_;
  std::vector<std::string> default_states_names_;

  friend class RobotModel;
};
}  // namespace core
}  // namespace moveit

// moveit::core::RobotModel (MoveIt noetic-devel moveit_core/robot_model/include/moveit/robot_model/robot_model.h), the
// workspace's own implementation, built from a urdf::ModelInterface and an srdf::Model (srdfdom/model.h).
//
// Provided: the kinematic tree (links, joints, the SRDF's virtual joint as root joint: fixed, planar or floating;
// passive joints; mimic joints), the model frame (the virtual joint's parent frame, else the root link), variables
// (names, count, indices, bounds, default and random positions), joint model groups from the SRDF (joints, links,
// chains, subgroups; group states), end effectors, rigidly connected links, printModelInfo, the legacy namespaces
// robot_model:: and robot_state:: (aliases of moveit::core::).
// Not provided: collision geometry (geometric_shapes is not packaged by Debian). Kinematics plugins are loaded by
// moveit_ros_planning's RobotModelLoader (through setKinematicsAllocators), as MoveIt's.
#pragma once

#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <moveit/macros/class_forward.h>
#include <moveit/robot_model/joint_model.h>
#include <moveit/robot_model/joint_model_group.h>
#include <moveit/robot_model/link_model.h>
#include <random_numbers/random_numbers.h>
#include <srdfdom/model.h>
#include <urdf_model/model.h>

namespace moveit
{
namespace core
{
MOVEIT_CLASS_FORWARD(RobotModel);

class RobotModel
{
public:
  RobotModel(const urdf::ModelInterfaceSharedPtr& urdf_model, const srdf::ModelConstSharedPtr& srdf_model);
  ~RobotModel();

  const std::string& getName() const
  {
    return model_name_;
  }
  /// The frame the model is expressed in: the virtual joint's parent frame, else the root link
  const std::string& getModelFrame() const
  {
    return model_frame_;
  }
  bool isEmpty() const
  {
    return root_link_ == nullptr;
  }
  const urdf::ModelInterfaceSharedPtr& getURDF() const
  {
    return urdf_;
  }
  const srdf::ModelConstSharedPtr& getSRDF() const
  {
    return srdf_;
  }
  void printModelInfo(std::ostream& out) const;

  const JointModel* getRootJoint() const
  {
    return root_joint_;
  }
  const std::string& getRootJointName() const;
  bool hasJointModel(const std::string& name) const;
  /// nullptr and a ROS error when there is no such joint
  const JointModel* getJointModel(const std::string& joint) const;
  const JointModel* getJointModel(int index) const;
  JointModel* getJointModel(const std::string& joint);
  const std::vector<const JointModel*>& getJointModels() const
  {
    return joint_model_vector_const_;
  }
  const std::vector<JointModel*>& getJointModels()
  {
    return joint_model_vector_;
  }
  const std::vector<std::string>& getJointModelNames() const
  {
    return joint_model_names_vector_;
  }
  const std::vector<const JointModel*>& getActiveJointModels() const
  {
    return active_joint_model_vector_const_;
  }
  const std::vector<std::string>& getActiveJointModelNames() const
  {
    return active_joint_model_names_vector_;
  }
  const std::vector<JointModel*>& getActiveJointModels()
  {
    return active_joint_model_vector_;
  }
  const std::vector<const JointModel*>& getSingleDOFJointModels() const
  {
    return single_dof_joints_;
  }
  const std::vector<const JointModel*>& getMultiDOFJointModels() const
  {
    return multi_dof_joints_;
  }
  const std::vector<const JointModel*>& getContinuousJointModels() const
  {
    return continuous_joint_model_vector_;
  }
  const std::vector<const JointModel*>& getMimicJointModels() const
  {
    return mimic_joints_;
  }
  const JointModel* getJointOfVariable(int variable_index) const
  {
    return joints_of_variable_[variable_index];
  }
  const JointModel* getJointOfVariable(const std::string& variable) const
  {
    return joints_of_variable_[getVariableIndex(variable)];
  }
  std::size_t getJointModelCount() const
  {
    return joint_model_vector_.size();
  }

  const LinkModel* getRootLink() const
  {
    return root_link_;
  }
  const std::string& getRootLinkName() const;
  bool hasLinkModel(const std::string& name) const;
  /// nullptr when there is no such link (a ROS error unless has_link is given, which is set instead)
  const LinkModel* getLinkModel(const std::string& link, bool* has_link = nullptr) const;
  const LinkModel* getLinkModel(int index) const;
  LinkModel* getLinkModel(const std::string& link, bool* has_link = nullptr);
  /// The nearest ancestor (or the link itself) that @e link is rigidly fixed to: climbing stops at a joint that is
  /// not fixed (or, with @e jmg, at a joint of that group); @e transform is @e link's pose relative to it
  static const moveit::core::LinkModel* getRigidlyConnectedParentLinkModel(const LinkModel* link,
                                                                           Eigen::Isometry3d& transform,
                                                                           const JointModelGroup* jmg = nullptr);
  static const moveit::core::LinkModel* getRigidlyConnectedParentLinkModel(const LinkModel* link,
                                                                           const JointModelGroup* jmg = nullptr)
  {
    Eigen::Isometry3d unused;
    return getRigidlyConnectedParentLinkModel(link, unused, jmg);
  }
  const std::vector<const LinkModel*>& getLinkModels() const
  {
    return link_model_vector_const_;
  }
  const std::vector<LinkModel*>& getLinkModels()
  {
    return link_model_vector_;
  }
  const std::vector<std::string>& getLinkModelNames() const
  {
    return link_model_names_vector_;
  }
  std::size_t getLinkModelCount() const
  {
    return link_model_vector_.size();
  }

  void getVariableRandomPositions(random_numbers::RandomNumberGenerator& rng, double* values) const;
  void getVariableDefaultPositions(double* values) const;
  void getVariableRandomPositions(random_numbers::RandomNumberGenerator& rng, std::vector<double>& values) const
  {
    values.resize(variable_count_);
    getVariableRandomPositions(rng, values.data());
  }
  void getVariableDefaultPositions(std::vector<double>& values) const
  {
    values.resize(variable_count_);
    getVariableDefaultPositions(values.data());
  }
  void getVariableRandomPositions(random_numbers::RandomNumberGenerator& rng,
                                  std::map<std::string, double>& values) const;
  void getVariableDefaultPositions(std::map<std::string, double>& values) const;
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

  bool hasJointModelGroup(const std::string& group) const;
  /// nullptr and a ROS error when there is no such group
  const JointModelGroup* getJointModelGroup(const std::string& name) const;
  JointModelGroup* getJointModelGroup(const std::string& name);
  const std::vector<const JointModelGroup*>& getJointModelGroups() const
  {
    return joint_model_groups_const_;
  }
  const std::vector<JointModelGroup*>& getJointModelGroups()
  {
    return joint_model_groups_;
  }
  const std::vector<std::string>& getJointModelGroupNames() const
  {
    return joint_model_group_names_;
  }

  bool hasEndEffector(const std::string& eef) const;
  /// The end effector's component group; nullptr and a ROS error when there is no such end effector
  const JointModelGroup* getEndEffector(const std::string& name) const;
  JointModelGroup* getEndEffector(const std::string& name);
  const std::vector<const JointModelGroup*>& getEndEffectors() const
  {
    return end_effectors_;
  }

  std::size_t getVariableCount() const
  {
    return variable_count_;
  }
  const std::vector<std::string>& getVariableNames() const
  {
    return variable_names_;
  }
  /// Throws std::runtime_error naming the variable when the model has none of that name
  const VariableBounds& getVariableBounds(const std::string& variable) const
  {
    return getJointOfVariable(variable)->getVariableBounds(variable);
  }
  const JointBoundsVector& getActiveJointModelsBounds() const
  {
    return active_joint_models_bounds_;
  }
  void getMissingVariableNames(const std::vector<std::string>& variables,
                               std::vector<std::string>& missing_variables) const;
  /// Throws std::runtime_error naming the variable when the model has none of that name
  int getVariableIndex(const std::string& variable) const;
  /// The deepest joint that is an ancestor of both (or one of them)
  const JointModel* getCommonRoot(const JointModel* a, const JointModel* b) const;

  void setKinematicsAllocators(const std::map<std::string, SolverAllocatorFn>& allocators);

  /// Sets mimic joints' values from the joints they follow
  void updateMimicJoints(double* values) const;

private:
  void buildModel(const urdf::ModelInterface& urdf_model, const srdf::Model& srdf_model);
  void buildTree(const urdf::ModelInterface& urdf_model, const srdf::Model& srdf_model);
  void addLinkAndChildren(const urdf::LinkConstSharedPtr& urdf_link, LinkModel* parent_link,
                          const urdf::JointConstSharedPtr& urdf_joint);
  void buildJointInfo();
  void buildMimic(const urdf::ModelInterface& urdf_model);
  void buildGroups(const srdf::Model& srdf_model);
  bool addJointModelGroup(const srdf::Model::Group& group, const srdf::Model& srdf_model);
  void buildGroupStates(const srdf::Model& srdf_model);
  void buildGroupsInfoEndEffectors(const srdf::Model& srdf_model);

  std::string model_name_;
  std::string model_frame_;
  urdf::ModelInterfaceSharedPtr urdf_;
  srdf::ModelConstSharedPtr srdf_;

  const LinkModel* root_link_ = nullptr;
  std::vector<LinkModel*> link_model_vector_;
  std::vector<const LinkModel*> link_model_vector_const_;
  std::vector<std::string> link_model_names_vector_;
  std::map<std::string, LinkModel*> link_model_map_;

  const JointModel* root_joint_ = nullptr;
  std::vector<JointModel*> joint_model_vector_;
  std::vector<const JointModel*> joint_model_vector_const_;
  std::vector<std::string> joint_model_names_vector_;
  std::map<std::string, JointModel*> joint_model_map_;
  std::vector<JointModel*> active_joint_model_vector_;
  std::vector<std::string> active_joint_model_names_vector_;
  std::vector<const JointModel*> active_joint_model_vector_const_;
  std::vector<const JointModel*> continuous_joint_model_vector_;
  std::vector<const JointModel*> mimic_joints_;
  std::vector<const JointModel*> single_dof_joints_;
  std::vector<const JointModel*> multi_dof_joints_;

  std::vector<std::string> variable_names_;
  std::size_t variable_count_ = 0;
  std::map<std::string, int> variable_index_map_;
  std::vector<const JointModel*> joints_of_variable_;
  JointBoundsVector active_joint_models_bounds_;

  std::vector<JointModelGroup*> joint_model_groups_;
  std::vector<const JointModelGroup*> joint_model_groups_const_;
  std::vector<std::string> joint_model_group_names_;
  std::map<std::string, JointModelGroup*> joint_model_group_map_;
  std::vector<const JointModelGroup*> end_effectors_;
  std::map<std::string, JointModelGroup*> end_effectors_map_;
};
}  // namespace core
}  // namespace moveit

namespace robot_model = moveit::core;
namespace robot_state = moveit::core;

// moveit::core::JointModel and VariableBounds (MoveIt noetic-devel moveit_core/robot_model/include/moveit/robot_model/
// joint_model.h), the workspace's own implementation.
//
// Provided: one concrete JointModel for the five joint types MoveIt models (REVOLUTE, continuous revolute included,
// PRISMATIC, PLANAR, FLOATING, FIXED): names, type, parent/child links, variable names (multi-DOF variables are
// "<joint>/<local name>": x, y, theta for planar; trans_x, trans_y, trans_z, rot_x, rot_y, rot_z, rot_w for floating),
// variable bounds (from the URDF, overridden by robot_description_planning/joint_limits), default and random positions,
// bound checks and enforcement, distance, interpolation, mimic data, the joint transform.
// Not provided: the subclasses RevoluteJointModel, PrismaticJointModel, PlanarJointModel, FloatingJointModel and
// FixedJointModel (their headers stop with #error); a cast to them has no class to cast to.
#pragma once

#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <moveit_msgs/JointLimits.h>
#include <random_numbers/random_numbers.h>

namespace moveit
{
namespace core
{
struct VariableBounds
{
  double min_position_ = 0.0;
  double max_position_ = 0.0;
  bool position_bounded_ = false;
  double min_velocity_ = 0.0;
  double max_velocity_ = 0.0;
  bool velocity_bounded_ = false;
  double min_acceleration_ = 0.0;
  double max_acceleration_ = 0.0;
  bool acceleration_bounded_ = false;
};

class LinkModel;
class JointModel;

typedef std::map<std::string, int> VariableIndexMap;
using VariableBoundsMap = std::map<std::string, VariableBounds>;
using JointModelMap = std::map<std::string, JointModel*>;
using JointModelMapConst = std::map<std::string, const JointModel*>;

class JointModel
{
public:
  enum JointType
  {
    UNKNOWN,
    REVOLUTE,
    PRISMATIC,
    PLANAR,
    FLOATING,
    FIXED
  };

  using Bounds = std::vector<VariableBounds>;

  /// A joint of the given type; its variables are named from @e name and the type. Axis (revolute, prismatic) and
  /// continuity are set afterwards with setAxis() / setContinuous().
  JointModel(const std::string& name, JointType type = FIXED);
  virtual ~JointModel();

  const std::string& getName() const
  {
    return name_;
  }
  JointType getType() const
  {
    return type_;
  }
  /// "Unknown", "Revolute", "Prismatic", "Planar", "Floating" or "Fixed", as MoveIt names them
  std::string getTypeName() const;

  const LinkModel* getParentLinkModel() const
  {
    return parent_link_model_;
  }
  const LinkModel* getChildLinkModel() const
  {
    return child_link_model_;
  }
  void setParentLinkModel(const LinkModel* link)
  {
    parent_link_model_ = link;
  }
  void setChildLinkModel(const LinkModel* link)
  {
    child_link_model_ = link;
  }

  const std::vector<std::string>& getVariableNames() const
  {
    return variable_names_;
  }
  const std::vector<std::string>& getLocalVariableNames() const
  {
    return local_variable_names_;
  }
  bool hasVariable(const std::string& variable) const
  {
    return variable_index_map_.find(variable) != variable_index_map_.end();
  }
  std::size_t getVariableCount() const
  {
    return variable_names_.size();
  }
  int getFirstVariableIndex() const
  {
    return first_variable_index_;
  }
  void setFirstVariableIndex(int index)
  {
    first_variable_index_ = index;
  }
  int getJointIndex() const
  {
    return joint_index_;
  }
  void setJointIndex(int index)
  {
    joint_index_ = index;
  }
  /// Index of a variable (full or local name) within this joint; throws std::runtime_error
  /// when the joint has no such variable
  int getLocalVariableIndex(const std::string& variable) const;

  void getVariableDefaultPositions(double* values) const
  {
    getVariableDefaultPositions(values, variable_bounds_);
  }
  virtual void getVariableDefaultPositions(double* values, const Bounds& other_bounds) const;
  void getVariableRandomPositions(random_numbers::RandomNumberGenerator& rng, double* values) const
  {
    getVariableRandomPositions(rng, values, variable_bounds_);
  }
  virtual void getVariableRandomPositions(random_numbers::RandomNumberGenerator& rng, double* values,
                                          const Bounds& other_bounds) const;
  void getVariableRandomPositionsNearBy(random_numbers::RandomNumberGenerator& rng, double* values, const double* seed,
                                        const double distance) const
  {
    getVariableRandomPositionsNearBy(rng, values, variable_bounds_, seed, distance);
  }
  virtual void getVariableRandomPositionsNearBy(random_numbers::RandomNumberGenerator& rng, double* values,
                                                const Bounds& other_bounds, const double* seed,
                                                const double distance) const;

  bool satisfiesPositionBounds(const double* values, double margin = 0.0) const
  {
    return satisfiesPositionBounds(values, variable_bounds_, margin);
  }
  virtual bool satisfiesPositionBounds(const double* values, const Bounds& other_bounds, double margin) const;
  bool enforcePositionBounds(double* values) const
  {
    return enforcePositionBounds(values, variable_bounds_);
  }
  /// Clamps to the bounds (continuous joints: wraps into [-pi, pi]; floating: normalises the quaternion); true when
  /// a value changed
  virtual bool enforcePositionBounds(double* values, const Bounds& other_bounds) const;
  virtual bool harmonizePosition(double* values, const Bounds& other_bounds) const;
  bool harmonizePosition(double* values) const
  {
    return harmonizePosition(values, variable_bounds_);
  }
  bool satisfiesVelocityBounds(const double* values, double margin = 0.0) const
  {
    return satisfiesVelocityBounds(values, variable_bounds_, margin);
  }
  virtual bool satisfiesVelocityBounds(const double* values, const Bounds& other_bounds, double margin) const;
  bool enforceVelocityBounds(double* values) const
  {
    return enforceVelocityBounds(values, variable_bounds_);
  }
  virtual bool enforceVelocityBounds(double* values, const Bounds& other_bounds) const;
  bool satisfiesAccelerationBounds(const double* values, double margin = 0.0) const
  {
    return satisfiesAccelerationBounds(values, variable_bounds_, margin);
  }
  virtual bool satisfiesAccelerationBounds(const double* values, const Bounds& other_bounds, double margin) const;

  const VariableBounds& getVariableBounds(const std::string& variable) const;
  const Bounds& getVariableBounds() const
  {
    return variable_bounds_;
  }
  void setVariableBounds(const std::string& variable, const VariableBounds& bounds);
  void setVariableBounds(const std::vector<moveit_msgs::JointLimits>& jlim);
  const std::vector<moveit_msgs::JointLimits>& getVariableBoundsMsg() const
  {
    return variable_bounds_msg_;
  }

  virtual double distance(const double* value1, const double* value2) const;
  double getDistanceFactor() const
  {
    return distance_factor_;
  }
  void setDistanceFactor(double factor)
  {
    distance_factor_ = factor;
  }
  virtual unsigned int getStateSpaceDimension() const;

  const JointModel* getMimic() const
  {
    return mimic_;
  }
  double getMimicOffset() const
  {
    return mimic_offset_;
  }
  double getMimicFactor() const
  {
    return mimic_factor_;
  }
  void setMimic(const JointModel* mimic, double factor, double offset);
  const std::vector<const JointModel*>& getMimicRequests() const
  {
    return mimic_requests_;
  }
  void addMimicRequest(const JointModel* joint);

  void addDescendantJointModel(const JointModel* joint);
  void addDescendantLinkModel(const LinkModel* link);
  const std::vector<const LinkModel*>& getDescendantLinkModels() const
  {
    return descendant_link_models_;
  }
  const std::vector<const JointModel*>& getDescendantJointModels() const
  {
    return descendant_joint_models_;
  }
  const std::vector<const JointModel*>& getNonFixedDescendantJointModels() const
  {
    return non_fixed_descendant_joint_models_;
  }

  bool isPassive() const
  {
    return passive_;
  }
  void setPassive(bool flag)
  {
    passive_ = flag;
  }

  virtual void interpolate(const double* from, const double* to, const double t, double* state) const;
  virtual double getMaximumExtent(const Bounds& other_bounds) const;
  double getMaximumExtent() const
  {
    return getMaximumExtent(variable_bounds_);
  }

  /// The joint's motion for the given variable values (the transform from the joint frame to the child link frame;
  /// the fixed origin is the child LinkModel's getJointOriginTransform())
  virtual void computeTransform(const double* joint_values, Eigen::Isometry3d& transf) const;
  virtual void computeVariablePositions(const Eigen::Isometry3d& transform, double* joint_values) const;

  /// Revolute and prismatic joints: the unit axis in the joint frame (RevoluteJointModel/PrismaticJointModel::getAxis)
  const Eigen::Vector3d& getAxis() const
  {
    return axis_;
  }
  void setAxis(const Eigen::Vector3d& axis);
  /// Revolute joints without position limits (URDF "continuous"): RevoluteJointModel::isContinuous
  bool isContinuous() const
  {
    return continuous_;
  }
  void setContinuous(bool flag);

protected:
  void computeVariableBoundsMsg();

  std::string name_;
  JointType type_;
  std::vector<std::string> local_variable_names_;
  std::vector<std::string> variable_names_;
  Bounds variable_bounds_;
  std::vector<moveit_msgs::JointLimits> variable_bounds_msg_;
  VariableIndexMap variable_index_map_;
  const LinkModel* parent_link_model_ = nullptr;
  const LinkModel* child_link_model_ = nullptr;
  const JointModel* mimic_ = nullptr;
  double mimic_factor_ = 1.0;
  double mimic_offset_ = 0.0;
  std::vector<const JointModel*> mimic_requests_;
  std::vector<const LinkModel*> descendant_link_models_;
  std::vector<const JointModel*> descendant_joint_models_;
  std::vector<const JointModel*> non_fixed_descendant_joint_models_;
  bool passive_ = false;
  double distance_factor_ = 1.0;
  int first_variable_index_ = -1;
  int joint_index_ = -1;
  Eigen::Vector3d axis_ = Eigen::Vector3d::UnitX();
  bool continuous_ = false;
};

std::ostream& operator<<(std::ostream& out, const VariableBounds& b);
}  // namespace core
}  // namespace moveit

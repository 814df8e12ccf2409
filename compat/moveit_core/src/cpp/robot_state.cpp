// moveit::core::RobotState: positions, forward kinematics through the model's joint transforms, and setFromIK. The
// behaviour reproduced from MoveIt (noetic-devel moveit_core/robot_state/src/robot_state.cpp): a link's global
// transform is its parent's, times its joint origin, times the joint's motion; setFromIK answers with the group's
// kinematics solver when it has one, as l. 1603-1832 do (pose into the solver's base frame, a rigidly attached frame
// turned into the solver's tip, seed = the state's values, the validity callback as the solver's solution callback,
// one searchPositionIK with the group's default timeout when none is given: noetic-devel's setFromIK makes no
// attempts of its own, the solver restarts within the timeout), else (here, not in MoveIt, which fails without a
// solver) with KDL's Levenberg-Marquardt solver restarted from random seeds within bounds until the timeout.
#include <moveit/robot_state/robot_state.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <stdexcept>

#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainiksolverpos_lma.hpp>
#include <ros/console.h>
#include <ros/time.h>

namespace moveit
{
namespace core
{
namespace
{
const char LOGNAME[] = "robot_state";
// What the KDL fallback calls solved: the tip within these of the pose (metres, radians)
constexpr double IK_POSITION_TOLERANCE = 1e-7;
constexpr double IK_ORIENTATION_TOLERANCE = 1e-7;
// LMA's iteration cap per seed and its convergence thresholds (squared weighted error; joint step)
constexpr int LMA_MAX_ITERATIONS = 500;
constexpr double LMA_EPS = 1e-15;
constexpr double LMA_EPS_JOINTS = 1e-15;
// The default IK timeout when the group has none (MoveIt's KinematicsSolver default, joint_model_group.h)
constexpr double DEFAULT_IK_TIMEOUT = 0.5;

KDL::Frame toKDL(const Eigen::Isometry3d& t)
{
  KDL::Frame f;
  for (int r = 0; r < 3; ++r)
  {
    f.p(r) = t.translation()(r);
    for (int c = 0; c < 3; ++c)
      f.M(r, c) = t.linear()(r, c);
  }
  return f;
}

Eigen::Isometry3d poseToEigen(const geometry_msgs::Pose& pose)
{
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  t.linear() = Eigen::Quaterniond(pose.orientation.w, pose.orientation.x, pose.orientation.y, pose.orientation.z)
                   .normalized()
                   .toRotationMatrix();
  return t;
}

std::string stripSlash(const std::string& frame)
{
  return !frame.empty() && frame[0] == '/' ? frame.substr(1) : frame;
}

geometry_msgs::Pose eigenToPose(const Eigen::Isometry3d& t)
{
  geometry_msgs::Pose pose;
  pose.position.x = t.translation().x();
  pose.position.y = t.translation().y();
  pose.position.z = t.translation().z();
  const Eigen::Quaterniond q(t.linear());
  pose.orientation.x = q.x();
  pose.orientation.y = q.y();
  pose.orientation.z = q.z();
  pose.orientation.w = q.w();
  return pose;
}
}  // namespace

RobotState::RobotState(const RobotModelConstPtr& robot_model) : robot_model_(robot_model)
{
  position_.assign(robot_model_->getVariableCount(), 0.0);
  velocity_.assign(robot_model_->getVariableCount(), 0.0);
  effort_.assign(robot_model_->getVariableCount(), 0.0);
  joint_transforms_.assign(robot_model_->getJointModelCount(), Eigen::Isometry3d::Identity());
  global_link_transforms_.assign(robot_model_->getLinkModelCount(), Eigen::Isometry3d::Identity());
}

RobotState::~RobotState() = default;

RobotState::RobotState(const RobotState& other)
{
  *this = other;
}

RobotState& RobotState::operator=(const RobotState& other)
{
  if (this == &other)
    return *this;
  robot_model_ = other.robot_model_;
  position_ = other.position_;
  velocity_ = other.velocity_;
  effort_ = other.effort_;
  has_velocity_ = other.has_velocity_;
  has_effort_ = other.has_effort_;
  dirty_ = other.dirty_;
  joint_transforms_ = other.joint_transforms_;
  global_link_transforms_ = other.global_link_transforms_;
  return *this;
}

random_numbers::RandomNumberGenerator& RobotState::getRandomNumberGenerator()
{
  if (!rng_)
    rng_.reset(new random_numbers::RandomNumberGenerator());
  return *rng_;
}

void RobotState::setVariablePositions(const double* position)
{
  std::copy(position, position + position_.size(), position_.begin());
  markDirty();
}

void RobotState::setVariablePositions(const std::vector<double>& position)
{
  if (position.size() < position_.size())
    throw std::invalid_argument("setVariablePositions: " + std::to_string(position.size()) + " values for " +
                                std::to_string(position_.size()) + " variables");
  setVariablePositions(position.data());
}

void RobotState::setVariablePositions(const std::map<std::string, double>& variable_map)
{
  for (const auto& kv : variable_map)
    position_[robot_model_->getVariableIndex(kv.first)] = kv.second;
  for (const JointModel* joint : robot_model_->getMimicJointModels())
    updateMimicJoint(joint);
  markDirty();
}

void RobotState::setVariablePositions(const std::map<std::string, double>& variable_map,
                                      std::vector<std::string>& missing_variables)
{
  setVariablePositions(variable_map);
  std::vector<std::string> given;
  for (const auto& kv : variable_map)
    given.push_back(kv.first);
  robot_model_->getMissingVariableNames(given, missing_variables);
}

void RobotState::setVariablePositions(const std::vector<std::string>& names, const std::vector<double>& values)
{
  for (std::size_t i = 0; i < names.size() && i < values.size(); ++i)
    position_[robot_model_->getVariableIndex(names[i])] = values[i];
  for (const JointModel* joint : robot_model_->getMimicJointModels())
    updateMimicJoint(joint);
  markDirty();
}

void RobotState::setVariablePosition(const std::string& variable, double value)
{
  setVariablePosition(robot_model_->getVariableIndex(variable), value);
}

void RobotState::setVariablePosition(int index, double value)
{
  position_[index] = value;
  const JointModel* joint = robot_model_->getJointOfVariable(index);
  for (const JointModel* follower : joint->getMimicRequests())
    updateMimicJoint(follower);
  markDirty();
}

double RobotState::getVariablePosition(const std::string& variable) const
{
  return position_[robot_model_->getVariableIndex(variable)];
}

double* RobotState::getVariableVelocities()
{
  has_velocity_ = true;
  return velocity_.data();
}

void RobotState::zeroVelocities()
{
  std::fill(velocity_.begin(), velocity_.end(), 0.0);
  has_velocity_ = true;
}

void RobotState::setVariableVelocities(const double* velocity)
{
  std::copy(velocity, velocity + velocity_.size(), velocity_.begin());
  has_velocity_ = true;
}

void RobotState::setVariableVelocities(const std::map<std::string, double>& variable_map)
{
  for (const auto& kv : variable_map)
    velocity_[robot_model_->getVariableIndex(kv.first)] = kv.second;
  has_velocity_ = true;
}

void RobotState::setVariableVelocities(const std::vector<std::string>& names, const std::vector<double>& values)
{
  for (std::size_t i = 0; i < names.size() && i < values.size(); ++i)
    velocity_[robot_model_->getVariableIndex(names[i])] = values[i];
  has_velocity_ = true;
}

void RobotState::setVariableVelocity(int index, double value)
{
  velocity_[index] = value;
  has_velocity_ = true;
}

double* RobotState::getVariableEffort()
{
  has_effort_ = true;
  return effort_.data();
}

void RobotState::zeroEffort()
{
  std::fill(effort_.begin(), effort_.end(), 0.0);
  has_effort_ = true;
}

void RobotState::setVariableEffort(const double* effort)
{
  std::copy(effort, effort + effort_.size(), effort_.begin());
  has_effort_ = true;
}

void RobotState::setVariableEffort(const std::map<std::string, double>& variable_map)
{
  for (const auto& kv : variable_map)
    effort_[robot_model_->getVariableIndex(kv.first)] = kv.second;
  has_effort_ = true;
}

void RobotState::setVariableEffort(const std::vector<std::string>& names, const std::vector<double>& values)
{
  for (std::size_t i = 0; i < names.size() && i < values.size(); ++i)
    effort_[robot_model_->getVariableIndex(names[i])] = values[i];
  has_effort_ = true;
}

void RobotState::updateMimicJoint(const JointModel* joint)
{
  const int src = joint->getMimic()->getFirstVariableIndex();
  const int dest = joint->getFirstVariableIndex();
  for (std::size_t k = 0; k < joint->getVariableCount(); ++k)
    position_[dest + k] = position_[src + k] * joint->getMimicFactor() + joint->getMimicOffset();
}

void RobotState::setJointPositions(const JointModel* joint, const double* position)
{
  std::copy(position, position + joint->getVariableCount(), position_.begin() + joint->getFirstVariableIndex());
  for (const JointModel* follower : joint->getMimicRequests())
    updateMimicJoint(follower);
  markDirty();
}

void RobotState::setJointPositions(const JointModel* joint, const Eigen::Isometry3d& transform)
{
  std::vector<double> values(joint->getVariableCount());
  joint->computeVariablePositions(transform, values.data());
  setJointPositions(joint, values.data());
}

void RobotState::setJointGroupPositions(const std::string& group_name, const double* gstate)
{
  const JointModelGroup* jmg = robot_model_->getJointModelGroup(group_name);
  if (jmg)
    setJointGroupPositions(jmg, gstate);
}

void RobotState::setJointGroupPositions(const std::string& group_name, const std::vector<double>& gstate)
{
  const JointModelGroup* jmg = robot_model_->getJointModelGroup(group_name);
  if (jmg)
    setJointGroupPositions(jmg, gstate);
}

void RobotState::setJointGroupPositions(const JointModelGroup* group, const std::vector<double>& gstate)
{
  if (gstate.size() < group->getVariableCount())
  {
    ROS_ERROR_NAMED(LOGNAME, "setJointGroupPositions: %zu values for group '%s' of %u variables", gstate.size(),
                    group->getName().c_str(), group->getVariableCount());
    return;
  }
  setJointGroupPositions(group, gstate.data());
}

void RobotState::setJointGroupPositions(const JointModelGroup* group, const double* gstate)
{
  const std::vector<int>& indices = group->getVariableIndexList();
  for (std::size_t i = 0; i < indices.size(); ++i)
    position_[indices[i]] = gstate[i];
  for (const JointModel* joint : group->getMimicJointModels())
    updateMimicJoint(joint);
  markDirty();
}

void RobotState::setJointGroupPositions(const std::string& group_name, const Eigen::VectorXd& values)
{
  const JointModelGroup* jmg = robot_model_->getJointModelGroup(group_name);
  if (jmg)
    setJointGroupPositions(jmg, values);
}

void RobotState::setJointGroupPositions(const JointModelGroup* group, const Eigen::VectorXd& values)
{
  std::vector<double> v(values.data(), values.data() + values.size());
  setJointGroupPositions(group, v);
}

void RobotState::setJointGroupActivePositions(const JointModelGroup* group, const std::vector<double>& gstate)
{
  std::size_t i = 0;
  for (const JointModel* joint : group->getActiveJointModels())
    for (std::size_t k = 0; k < joint->getVariableCount() && i < gstate.size(); ++k)
      position_[joint->getFirstVariableIndex() + k] = gstate[i++];
  for (const JointModel* joint : robot_model_->getMimicJointModels())
    updateMimicJoint(joint);
  markDirty();
}

void RobotState::setJointGroupActivePositions(const std::string& group_name, const std::vector<double>& gstate)
{
  const JointModelGroup* jmg = robot_model_->getJointModelGroup(group_name);
  if (jmg)
    setJointGroupActivePositions(jmg, gstate);
}

void RobotState::setJointGroupActivePositions(const JointModelGroup* group, const Eigen::VectorXd& values)
{
  setJointGroupActivePositions(group, std::vector<double>(values.data(), values.data() + values.size()));
}

void RobotState::setJointGroupActivePositions(const std::string& group_name, const Eigen::VectorXd& values)
{
  const JointModelGroup* jmg = robot_model_->getJointModelGroup(group_name);
  if (jmg)
    setJointGroupActivePositions(jmg, values);
}

void RobotState::copyJointGroupPositions(const std::string& group_name, std::vector<double>& gstate) const
{
  const JointModelGroup* jmg = robot_model_->getJointModelGroup(group_name);
  if (jmg)
    copyJointGroupPositions(jmg, gstate);
}

void RobotState::copyJointGroupPositions(const std::string& group_name, double* gstate) const
{
  const JointModelGroup* jmg = robot_model_->getJointModelGroup(group_name);
  if (jmg)
    copyJointGroupPositions(jmg, gstate);
}

void RobotState::copyJointGroupPositions(const JointModelGroup* group, std::vector<double>& gstate) const
{
  gstate.resize(group->getVariableCount());
  copyJointGroupPositions(group, gstate.data());
}

void RobotState::copyJointGroupPositions(const JointModelGroup* group, double* gstate) const
{
  const std::vector<int>& indices = group->getVariableIndexList();
  for (std::size_t i = 0; i < indices.size(); ++i)
    gstate[i] = position_[indices[i]];
}

void RobotState::copyJointGroupPositions(const std::string& group_name, Eigen::VectorXd& values) const
{
  const JointModelGroup* jmg = robot_model_->getJointModelGroup(group_name);
  if (jmg)
    copyJointGroupPositions(jmg, values);
}

void RobotState::copyJointGroupPositions(const JointModelGroup* group, Eigen::VectorXd& values) const
{
  values.resize(group->getVariableCount());
  copyJointGroupPositions(group, values.data());
}

void RobotState::copyJointGroupVelocities(const JointModelGroup* group, std::vector<double>& gstate) const
{
  const std::vector<int>& indices = group->getVariableIndexList();
  gstate.resize(indices.size());
  for (std::size_t i = 0; i < indices.size(); ++i)
    gstate[i] = velocity_[indices[i]];
}

void RobotState::copyJointGroupVelocities(const std::string& group_name, std::vector<double>& gstate) const
{
  const JointModelGroup* jmg = robot_model_->getJointModelGroup(group_name);
  if (jmg)
    copyJointGroupVelocities(jmg, gstate);
}

void RobotState::setVariableValues(const sensor_msgs::JointState& msg)
{
  if (!msg.position.empty())
    setVariablePositions(msg.name, msg.position);
  if (!msg.velocity.empty())
    setVariableVelocities(msg.name, msg.velocity);
  if (!msg.effort.empty())
    setVariableEffort(msg.name, msg.effort);
}

void RobotState::setToDefaultValues()
{
  robot_model_->getVariableDefaultPositions(position_.data());
  markDirty();
}

bool RobotState::setToDefaultValues(const JointModelGroup* group, const std::string& name)
{
  std::map<std::string, double> values;
  if (!group || !group->getVariableDefaultPositions(name, values))
    return false;
  setVariablePositions(values);
  return true;
}

bool RobotState::setToDefaultValues(const std::string& group_name, const std::string& state_name)
{
  return setToDefaultValues(robot_model_->getJointModelGroup(group_name), state_name);
}

void RobotState::setToRandomPositions()
{
  setToRandomPositions(getRandomNumberGenerator());
}

void RobotState::setToRandomPositions(random_numbers::RandomNumberGenerator& rng)
{
  robot_model_->getVariableRandomPositions(rng, position_.data());
  markDirty();
}

void RobotState::setToRandomPositions(const JointModelGroup* group)
{
  setToRandomPositions(group, getRandomNumberGenerator());
}

void RobotState::setToRandomPositions(const JointModelGroup* group, random_numbers::RandomNumberGenerator& rng)
{
  std::vector<double> values;
  group->getVariableRandomPositions(rng, values);
  setJointGroupPositions(group, values);
}

void RobotState::setToRandomPositionsNearBy(const JointModelGroup* group, const RobotState& seed, double distance)
{
  setToRandomPositionsNearBy(group, seed, distance, getRandomNumberGenerator());
}

void RobotState::setToRandomPositionsNearBy(const JointModelGroup* group, const RobotState& seed, double distance,
                                            random_numbers::RandomNumberGenerator& rng)
{
  std::vector<double> seed_values, values(group->getVariableCount());
  seed.copyJointGroupPositions(group, seed_values);
  group->getVariableRandomPositionsNearBy(rng, values.data(), seed_values.data(), distance);
  setJointGroupPositions(group, values);
}

void RobotState::update(bool force)
{
  if (force)
    markDirty();
  updateLinkTransforms();
}

void RobotState::updateLinkTransforms()
{
  if (!dirty_)
    return;
  // Links are ordered parents first (RobotModel builds them depth-first)
  for (const LinkModel* link : robot_model_->getLinkModels())
  {
    const JointModel* joint = link->getParentJointModel();
    Eigen::Isometry3d& motion = joint_transforms_[joint->getJointIndex()];
    joint->computeTransform(position_.data() + joint->getFirstVariableIndex(), motion);
    const LinkModel* parent = link->getParentLinkModel();
    const Eigen::Isometry3d origin = link->getJointOriginTransform() * motion;
    global_link_transforms_[link->getLinkIndex()] =
        parent ? Eigen::Isometry3d(global_link_transforms_[parent->getLinkIndex()] * origin) : origin;
  }
  dirty_ = false;
}

const Eigen::Isometry3d& RobotState::getGlobalLinkTransform(const LinkModel* link) const
{
  if (dirty_)
    ROS_ERROR_NAMED(LOGNAME, "getGlobalLinkTransform('%s') on a const RobotState whose positions changed since the "
                             "last update(): the transform is stale",
                    link->getName().c_str());
  return global_link_transforms_[link->getLinkIndex()];
}

const Eigen::Isometry3d& RobotState::getJointTransform(const JointModel* joint)
{
  updateLinkTransforms();
  return joint_transforms_[joint->getJointIndex()];
}

const Eigen::Isometry3d& RobotState::getJointTransform(const JointModel* joint) const
{
  if (dirty_)
    ROS_ERROR_NAMED(LOGNAME, "getJointTransform('%s') on a const RobotState that was not updated",
                    joint->getName().c_str());
  return joint_transforms_[joint->getJointIndex()];
}

double RobotState::distance(const RobotState& other, const JointModelGroup* joint_group) const
{
  std::vector<double> a, b;
  copyJointGroupPositions(joint_group, a);
  other.copyJointGroupPositions(joint_group, b);
  return joint_group->distance(a.data(), b.data());
}

void RobotState::interpolate(const RobotState& to, double t, RobotState& state) const
{
  robot_model_->interpolate(position_.data(), to.getVariablePositions(), t, state.getVariablePositions());
  state.markDirty();
}

void RobotState::interpolate(const RobotState& to, double t, RobotState& state,
                             const JointModelGroup* joint_group) const
{
  std::vector<double> a, b, out(joint_group->getVariableCount());
  copyJointGroupPositions(joint_group, a);
  to.copyJointGroupPositions(joint_group, b);
  joint_group->interpolate(a.data(), b.data(), t, out.data());
  state.setJointGroupPositions(joint_group, out);
}

void RobotState::enforceBounds()
{
  robot_model_->enforcePositionBounds(position_.data());
  markDirty();
}

void RobotState::enforceBounds(const JointModelGroup* joint_group)
{
  for (const JointModel* joint : joint_group->getActiveJointModels())
    enforceBounds(joint);
}

void RobotState::enforceBounds(const JointModel* joint)
{
  if (joint->enforcePositionBounds(position_.data() + joint->getFirstVariableIndex()))
  {
    for (const JointModel* follower : joint->getMimicRequests())
      updateMimicJoint(follower);
    markDirty();
  }
  if (has_velocity_)
    joint->enforceVelocityBounds(velocity_.data() + joint->getFirstVariableIndex());
}

void RobotState::harmonizePositions()
{
  for (const JointModel* joint : robot_model_->getActiveJointModels())
    if (joint->harmonizePosition(position_.data() + joint->getFirstVariableIndex()))
      markDirty();
}

void RobotState::harmonizePositions(const JointModelGroup* joint_group)
{
  for (const JointModel* joint : joint_group->getActiveJointModels())
    if (joint->harmonizePosition(position_.data() + joint->getFirstVariableIndex()))
      markDirty();
}

bool RobotState::satisfiesBounds(double margin) const
{
  for (const JointModel* joint : robot_model_->getActiveJointModels())
    if (!satisfiesBounds(joint, margin))
      return false;
  return true;
}

bool RobotState::satisfiesBounds(const JointModelGroup* joint_group, double margin) const
{
  for (const JointModel* joint : joint_group->getActiveJointModels())
    if (!satisfiesBounds(joint, margin))
      return false;
  return true;
}

bool RobotState::satisfiesBounds(const JointModel* joint, double margin) const
{
  if (!joint->satisfiesPositionBounds(position_.data() + joint->getFirstVariableIndex(), margin))
    return false;
  return !has_velocity_ || joint->satisfiesVelocityBounds(velocity_.data() + joint->getFirstVariableIndex(), margin);
}

const Eigen::Isometry3d& RobotState::getFrameTransform(const std::string& frame_id, bool* frame_found)
{
  updateLinkTransforms();
  return static_cast<const RobotState*>(this)->getFrameTransform(frame_id, frame_found);
}

const Eigen::Isometry3d& RobotState::getFrameTransform(const std::string& frame_id, bool* frame_found) const
{
  static const Eigen::Isometry3d IDENTITY = Eigen::Isometry3d::Identity();
  const std::string id = !frame_id.empty() && frame_id[0] == '/' ? frame_id.substr(1) : frame_id;
  if (frame_found)
    *frame_found = true;
  if (id == robot_model_->getModelFrame())
    return IDENTITY;
  bool has_link = false;
  const LinkModel* link = robot_model_->getLinkModel(id, &has_link);
  if (has_link)
    return getGlobalLinkTransform(link);
  if (frame_found)
    *frame_found = false;
  else
    ROS_ERROR_NAMED(LOGNAME, "Frame '%s' is not known to the robot state (model '%s')", frame_id.c_str(),
                    robot_model_->getName().c_str());
  return IDENTITY;
}

bool RobotState::knowsFrameTransform(const std::string& frame_id) const
{
  const std::string id = !frame_id.empty() && frame_id[0] == '/' ? frame_id.substr(1) : frame_id;
  return id == robot_model_->getModelFrame() || robot_model_->hasLinkModel(id);
}

const LinkModel* RobotState::getRigidlyConnectedParentLinkModel(const std::string& frame,
                                                                Eigen::Isometry3d* transform,
                                                                const JointModelGroup* jmg) const
{
  bool has_link = false;
  const LinkModel* link = robot_model_->getLinkModel(frame, &has_link);
  if (!has_link)
    return nullptr;
  // the model's walk up across rigid joints (robot_state.cpp delegates to it likewise on noetic-devel)
  Eigen::Isometry3d t;
  link = RobotModel::getRigidlyConnectedParentLinkModel(link, t, jmg);
  if (transform)
    *transform = t;
  return link;
}

bool RobotState::getJacobian(const JointModelGroup* group, const LinkModel* link,
                             const Eigen::Vector3d& reference_point_position, Eigen::MatrixXd& jacobian,
                             bool use_quaternion_representation) const
{
  if (use_quaternion_representation)
  {
    ROS_ERROR_NAMED(LOGNAME, "getJacobian: the quaternion representation is not provided here");
    return false;
  }
  const Eigen::Vector3d point = getGlobalLinkTransform(link) * reference_point_position;
  jacobian = Eigen::MatrixXd::Zero(6, group->getActiveVariableCount());
  std::size_t column = 0;
  for (const JointModel* joint : group->getActiveJointModels())
  {
    if (joint->getVariableCount() != 1)
    {
      ROS_ERROR_NAMED(LOGNAME, "getJacobian: multi-DOF joint '%s' is not provided", joint->getName().c_str());
      return false;
    }
    const auto& below = joint->getDescendantLinkModels();
    const bool moves_link = std::find(below.begin(), below.end(), link) != below.end();
    if (moves_link)
    {
      const Eigen::Isometry3d& frame = getGlobalLinkTransform(joint->getChildLinkModel());
      const Eigen::Vector3d axis = frame.linear() * joint->getAxis();
      if (joint->getType() == JointModel::REVOLUTE)
      {
        jacobian.block<3, 1>(0, column) = axis.cross(point - frame.translation());
        jacobian.block<3, 1>(3, column) = axis;
      }
      else
        jacobian.block<3, 1>(0, column) = axis;
    }
    ++column;
  }
  return true;
}

Eigen::MatrixXd RobotState::getJacobian(const JointModelGroup* group,
                                        const Eigen::Vector3d& reference_point_position) const
{
  Eigen::MatrixXd jacobian;
  getJacobian(group, group->getLinkModels().back(), reference_point_position, jacobian);
  return jacobian;
}

bool RobotState::setFromIK(const JointModelGroup* group, const geometry_msgs::Pose& pose, double timeout,
                           const GroupStateValidityCallbackFn& constraint,
                           const kinematics::KinematicsQueryOptions& options)
{
  return setFromIK(group, poseToEigen(pose), timeout, constraint, options);
}

bool RobotState::setFromIK(const JointModelGroup* group, const geometry_msgs::Pose& pose, const std::string& tip,
                           double timeout, const GroupStateValidityCallbackFn& constraint,
                           const kinematics::KinematicsQueryOptions& options)
{
  return setFromIK(group, poseToEigen(pose), tip, timeout, constraint, options);
}

bool RobotState::setFromIK(const JointModelGroup* group, const Eigen::Isometry3d& pose, double timeout,
                           const GroupStateValidityCallbackFn& constraint,
                           const kinematics::KinematicsQueryOptions& options)
{
  if (!group)
    return false;
  const kinematics::KinematicsBaseConstPtr solver = group->getSolverInstance();
  if (solver)
    return setFromIK(group, pose, solver->getTipFrame(), timeout, constraint, options);
  std::vector<std::string> tips;
  group->getEndEffectorTips(tips);
  // Without an end effector, the group's last link is its tip
  const std::string tip = tips.size() == 1 ? tips.front() : group->getLinkModelNames().back();
  return setFromIK(group, pose, tip, timeout, constraint, options);
}

bool RobotState::setFromIK(const JointModelGroup* group, const Eigen::Isometry3d& pose, const std::string& tip,
                           double timeout, const GroupStateValidityCallbackFn& constraint,
                           const kinematics::KinematicsQueryOptions& options)
{
  return setFromIK(group, pose, tip, std::vector<double>(), timeout, constraint, options);
}

bool RobotState::setFromIK(const JointModelGroup* group, const Eigen::Isometry3d& pose, const std::string& tip,
                           const std::vector<double>& consistency_limits, double timeout,
                           const GroupStateValidityCallbackFn& constraint,
                           const kinematics::KinematicsQueryOptions& options)
{
  if (!group)
    return false;
  if (group->getSolverInstance())
    return setFromIKWithSolver(group, pose, tip, consistency_limits, timeout, constraint, options);
  if (timeout <= 0.0)
    timeout = group->getDefaultIKTimeout() > 0.0 ? group->getDefaultIKTimeout() : DEFAULT_IK_TIMEOUT;
  const LinkModel* tip_link = robot_model_->getLinkModel(stripSlash(tip));
  if (!tip_link)
    return false;
  return setFromIKWithKDL(group, pose, tip_link, timeout, constraint);
}

bool RobotState::setToIKSolverFrame(Eigen::Isometry3d& pose, const kinematics::KinematicsBaseConstPtr& solver)
{
  return setToIKSolverFrame(pose, solver->getBaseFrame());
}

bool RobotState::setToIKSolverFrame(Eigen::Isometry3d& pose, const std::string& ik_frame)
{
  // robot_state.cpp l. 1559-1575: a pose in the model frame, expressed in the solver's base link
  const std::string frame = stripSlash(ik_frame);
  if (frame == stripSlash(robot_model_->getModelFrame()))
    return true;
  const LinkModel* link = robot_model_->getLinkModel(frame);
  if (!link)
  {
    ROS_ERROR_STREAM_NAMED(LOGNAME, "IK frame '" << ik_frame << "' does not exist.");
    return false;
  }
  updateLinkTransforms();
  pose = getGlobalLinkTransform(link).inverse() * pose;
  return true;
}

bool RobotState::setFromIKWithSolver(const JointModelGroup* group, const Eigen::Isometry3d& pose_in,
                                     const std::string& tip_in, const std::vector<double>& consistency_limits,
                                     double timeout, const GroupStateValidityCallbackFn& constraint,
                                     const kinematics::KinematicsQueryOptions& options)
{
  // One pose for one tip, as robot_state.cpp's setFromIK (l. 1603-1832 on noetic-devel) handles it
  const kinematics::KinematicsBaseConstPtr solver = group->getSolverInstance();
  updateLinkTransforms();
  const std::vector<std::string>& solver_tips = solver->getTipFrames();
  std::vector<geometry_msgs::Pose> ik_queries(solver_tips.size());
  std::vector<bool> tip_used(solver_tips.size(), false);

  // the pose into the solver's base frame; a tip the solver does not know but that moves rigidly with one of its
  // tips is turned into that tip's pose (l. 1678-1762)
  Eigen::Isometry3d pose = pose_in;
  const std::string pose_frame = stripSlash(tip_in);
  if (!setToIKSolverFrame(pose, solver))
    return false;
  bool found = false;
  std::size_t id = 0;
  for (; id < solver_tips.size() && !found; ++id)
  {
    const std::string solver_tip = stripSlash(solver_tips[id]);
    if (pose_frame == solver_tip)
    {
      found = true;
      break;
    }
    Eigen::Isometry3d pose_parent_to_frame, tip_parent_to_tip;
    const LinkModel* pose_parent = getRigidlyConnectedParentLinkModel(pose_frame, &pose_parent_to_frame, group);
    if (!pose_parent)
    {
      ROS_ERROR_STREAM_NAMED(LOGNAME, "Pose frame '" << pose_frame << "' does not exist.");
      return false;
    }
    const LinkModel* tip_parent = getRigidlyConnectedParentLinkModel(solver_tip, &tip_parent_to_tip, group);
    if (!tip_parent)
    {
      ROS_ERROR_STREAM_NAMED(LOGNAME, "Solver tip frame '" << solver_tip << "' does not exist.");
      return false;
    }
    if (pose_parent == tip_parent)
    {
      pose = pose * pose_parent_to_frame.inverse() * tip_parent_to_tip;
      found = true;
      break;
    }
  }
  if (!found)
  {
    std::string available;
    for (const std::string& frame : solver_tips)
      available += frame + ", ";
    ROS_ERROR_NAMED(LOGNAME, "Cannot compute IK for query 0 pose reference frame '%s'", pose_frame.c_str());
    ROS_ERROR_NAMED(LOGNAME, "Available tip frames: [%s]", available.c_str());
    return false;
  }
  ik_queries[id] = eigenToPose(pose);
  tip_used[id] = true;

  // a solver with several tips gets the others' current poses (l. 1764-1795)
  for (std::size_t other = 0; other < solver_tips.size(); ++other)
  {
    if (tip_used[other])
      continue;
    const LinkModel* link = robot_model_->getLinkModel(stripSlash(solver_tips[other]));
    if (!link)
    {
      ROS_ERROR_STREAM_NAMED(LOGNAME, "Solver tip frame '" << solver_tips[other] << "' does not exist.");
      return false;
    }
    Eigen::Isometry3d current = getGlobalLinkTransform(link);
    if (!setToIKSolverFrame(current, solver))
      return false;
    ik_queries[other] = eigenToPose(current);
  }

  // no timeout given: the group's default, kinematics_solver_timeout (l. 1797-1799)
  if (timeout < std::numeric_limits<double>::epsilon())
    timeout = group->getDefaultIKTimeout();

  // the validity callback sees the candidate in the group's variable order (ikCallbackFnAdapter, l. 1539-1551, 1801-1807)
  const std::vector<unsigned int>& bijection = group->getKinematicsSolverJointBijection();
  kinematics::KinematicsBase::IKCallbackFn callback;
  if (constraint)
    callback = [this, group, &constraint, &bijection](const geometry_msgs::Pose&, const std::vector<double>& candidate,
                                                      moveit_msgs::MoveItErrorCodes& error_code) {
      std::vector<double> values(bijection.size());
      for (std::size_t i = 0; i < bijection.size(); ++i)
        values[bijection[i]] = candidate[i];
      error_code.val = constraint(this, group, values.data()) ? moveit_msgs::MoveItErrorCodes::SUCCESS :
                                                                 moveit_msgs::MoveItErrorCodes::NO_IK_SOLUTION;
    };

  // the seed: the state's own values of the solver's joints (l. 1809-1816)
  std::vector<double> initial_values;
  copyJointGroupPositions(group, initial_values);
  std::vector<double> seed(bijection.size());
  for (std::size_t i = 0; i < bijection.size(); ++i)
    seed[i] = initial_values[bijection[i]];

  // one search; the solver itself restarts within the timeout as it sees fit (l. 1818-1831)
  std::vector<double> ik_solution;
  moveit_msgs::MoveItErrorCodes error;
  if (!solver->searchPositionIK(ik_queries, seed, timeout, consistency_limits, ik_solution, callback, error, options,
                                this))
    return false;
  std::vector<double> solution(bijection.size());
  for (std::size_t i = 0; i < bijection.size(); ++i)
    solution[bijection[i]] = ik_solution[i];
  setJointGroupPositions(group, solution);
  return true;
}

bool RobotState::setFromIKWithKDL(const JointModelGroup* group, const Eigen::Isometry3d& pose, const LinkModel* tip,
                                  double timeout, const GroupStateValidityCallbackFn& constraint)
{
  // The chain from the group's root joint's parent link to the tip; every moving joint on it must be the group's
  const JointModel* root = group->getJointRoots().empty() ? nullptr : group->getJointRoots().front();
  if (!root || group->getJointRoots().size() != 1)
  {
    ROS_ERROR_NAMED(LOGNAME, "setFromIK: group '%s' is not a single chain; no kinematics solver is loaded for it",
                    group->getName().c_str());
    return false;
  }
  const LinkModel* base = root->getParentLinkModel();
  std::vector<const LinkModel*> path;
  for (const LinkModel* link = tip; link && link != base; link = link->getParentLinkModel())
    path.insert(path.begin(), link);
  if (path.empty() || path.front()->getParentLinkModel() != base)
  {
    ROS_ERROR_NAMED(LOGNAME, "setFromIK: tip '%s' is not below group '%s'", tip->getName().c_str(),
                    group->getName().c_str());
    return false;
  }
  KDL::Chain chain;
  std::vector<int> group_index;  // the group variable of each chain joint
  for (const LinkModel* link : path)
  {
    const JointModel* joint = link->getParentJointModel();
    const KDL::Frame origin = toKDL(link->getJointOriginTransform());
    const Eigen::Vector3d& a = joint->getAxis();
    const KDL::Vector axis = origin.M * KDL::Vector(a.x(), a.y(), a.z());
    if (joint->getType() == JointModel::FIXED)
    {
      chain.addSegment(KDL::Segment(link->getName(), KDL::Joint(joint->getName(), KDL::Joint::None), origin));
      continue;
    }
    if (joint->getVariableCount() != 1 || !group->hasJointModel(joint->getName()) || joint->getMimic())
    {
      ROS_ERROR_NAMED(LOGNAME, "setFromIK: joint '%s' on the way to '%s' cannot be solved by KDL for group '%s'",
                      joint->getName().c_str(), tip->getName().c_str(), group->getName().c_str());
      return false;
    }
    const KDL::Joint::JointType type = joint->getType() == JointModel::REVOLUTE ? KDL::Joint::RotAxis :
                                                                                  KDL::Joint::TransAxis;
    chain.addSegment(KDL::Segment(link->getName(), KDL::Joint(joint->getName(), origin.p, axis, type), origin));
    group_index.push_back(group->getVariableGroupIndex(joint->getName()));
  }

  updateLinkTransforms();
  const Eigen::Isometry3d target_in_base = getGlobalLinkTransform(base).inverse() * pose;
  const KDL::Frame target = toKDL(target_in_base);
  // Position and orientation errors weigh the same: the answer must match both
  Eigen::Matrix<double, 6, 1> weights = Eigen::Matrix<double, 6, 1>::Ones();
  KDL::ChainIkSolverPos_LMA lma(chain, weights, LMA_EPS, LMA_MAX_ITERATIONS, LMA_EPS_JOINTS);
  KDL::ChainFkSolverPos_recursive fk(chain);

  std::vector<double> group_values;
  copyJointGroupPositions(group, group_values);
  const std::vector<double> start = group_values;
  KDL::JntArray seed(chain.getNrOfJoints()), result(chain.getNrOfJoints());
  for (std::size_t i = 0; i < group_index.size(); ++i)
    seed(i) = group_values[group_index[i]];

  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout);
  random_numbers::RandomNumberGenerator& rng = getRandomNumberGenerator();
  bool first = true;
  while (first || ros::WallTime::now() < deadline)
  {
    if (!first)
    {
      std::vector<double> random_values;
      group->getVariableRandomPositions(rng, random_values);
      for (std::size_t i = 0; i < group_index.size(); ++i)
        seed(i) = random_values[group_index[i]];
    }
    first = false;
    lma.CartToJnt(seed, target, result);
    KDL::Frame reached;
    fk.JntToCart(result, reached);
    const KDL::Twist error = KDL::diff(reached, target);
    if (error.vel.Norm() > IK_POSITION_TOLERANCE || error.rot.Norm() > IK_ORIENTATION_TOLERANCE)
      continue;
    std::vector<double> candidate = start;
    for (std::size_t i = 0; i < group_index.size(); ++i)
      candidate[group_index[i]] = result(i);
    // Revolute angles found outside [-pi, pi] may be inside the bounds once wrapped
    bool within = true;
    for (std::size_t i = 0; i < group_index.size(); ++i)
    {
      const JointModel* joint = group->getJointModel(group->getVariableNames()[group_index[i]]);
      double& v = candidate[group_index[i]];
      if (joint->getType() == JointModel::REVOLUTE)
      {
        const VariableBounds& b = joint->getVariableBounds()[0];
        v = std::remainder(v, 2.0 * M_PI);
        if (!joint->isContinuous() && v < b.min_position_)
          v += 2.0 * M_PI;
        if (!joint->isContinuous() && v > b.max_position_)
          v -= 2.0 * M_PI;
      }
      within = within && joint->satisfiesPositionBounds(&v);
    }
    if (!within)
      continue;
    RobotState trial(*this);
    trial.setJointGroupPositions(group, candidate);
    if (constraint && !constraint(&trial, group, candidate.data()))
      continue;
    setJointGroupPositions(group, candidate);
    return true;
  }
  return false;
}

void RobotState::printStatePositions(std::ostream& out) const
{
  const std::vector<std::string>& names = robot_model_->getVariableNames();
  for (std::size_t i = 0; i < names.size(); ++i)
    out << names[i] << "=" << position_[i] << std::endl;
}

void RobotState::printStatePositionsWithJointLimits(const JointModelGroup* jmg, std::ostream& out) const
{
  for (const JointModel* joint : jmg->getActiveJointModels())
    for (std::size_t k = 0; k < joint->getVariableCount(); ++k)
    {
      const VariableBounds& b = joint->getVariableBounds()[k];
      const double v = position_[joint->getFirstVariableIndex() + k];
      out << std::setw(30) << joint->getVariableNames()[k] << " " << std::setw(10) << b.min_position_ << " "
          << std::setw(10) << v << " " << std::setw(10) << b.max_position_
          << (joint->satisfiesPositionBounds(&position_[joint->getFirstVariableIndex()]) ? "" : "  OUT OF BOUNDS")
          << std::endl;
    }
}

void RobotState::printStateInfo(std::ostream& out) const
{
  out << "Robot State @" << this << std::endl;
  out << "  * Position: ";
  for (double v : position_)
    out << v << " ";
  out << std::endl;
  if (has_velocity_)
  {
    out << "  * Velocity: ";
    for (double v : velocity_)
      out << v << " ";
    out << std::endl;
  }
  if (has_effort_)
  {
    out << "  * Effort: ";
    for (double v : effort_)
      out << v << " ";
    out << std::endl;
  }
  out << "  * Dirty link transforms: " << (dirty_ ? "yes" : "no") << std::endl;
}

void RobotState::printTransform(const Eigen::Isometry3d& transform, std::ostream& out) const
{
  const Eigen::Quaterniond q(transform.linear());
  out << "T.xyz = [" << transform.translation().x() << ", " << transform.translation().y() << ", "
      << transform.translation().z() << "], Q.xyzw = [" << q.x() << ", " << q.y() << ", " << q.z() << ", " << q.w()
      << "]" << std::endl;
}

void RobotState::printTransforms(std::ostream& out) const
{
  out << "Link poses:" << std::endl;
  for (const LinkModel* link : robot_model_->getLinkModels())
  {
    out << "  " << link->getName() << ": ";
    printTransform(global_link_transforms_[link->getLinkIndex()], out);
  }
}

std::ostream& operator<<(std::ostream& out, const RobotState& s)
{
  s.printStatePositions(out);
  return out;
}
}  // namespace core
}  // namespace moveit

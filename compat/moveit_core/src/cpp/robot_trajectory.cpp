// robot_trajectory::RobotTrajectory: the workspace's implementation of MoveIt noetic-devel's class (interface and
// behaviour of moveit_core/robot_trajectory/src/robot_trajectory.cpp, "rt" below), on this moveit_core's RobotState.
#include <moveit/robot_trajectory/robot_trajectory.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numeric>
#include <utility>

#include <boost/math/constants/constants.hpp>
#include <moveit/robot_state/conversions.h>
#include <ros/console.h>

namespace robot_trajectory
{
namespace
{
constexpr double PI = boost::math::constants::pi<double>();
const double EPSILON = std::numeric_limits<double>::epsilon();

geometry_msgs::Transform toTransform(const Eigen::Isometry3d& pose)
{
  geometry_msgs::Transform out;
  out.translation.x = pose.translation().x();
  out.translation.y = pose.translation().y();
  out.translation.z = pose.translation().z();
  const Eigen::Quaterniond q(pose.linear());
  out.rotation.x = q.x();
  out.rotation.y = q.y();
  out.rotation.z = q.z();
  out.rotation.w = q.w();
  return out;
}

Eigen::Isometry3d fromTransform(const geometry_msgs::Transform& transform)
{
  Eigen::Quaterniond q(transform.rotation.w, transform.rotation.x, transform.rotation.y, transform.rotation.z);
  // an all-zero quaternion is the identity, as MoveIt's message readers take it
  q = q.norm() > 0.0 ? q.normalized() : Eigen::Quaterniond::Identity();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = q.toRotationMatrix();
  pose.translation() = Eigen::Vector3d(transform.translation.x, transform.translation.y, transform.translation.z);
  return pose;
}

// the accelerations of a point by the model's variable index (empty when the point has none)
std::vector<double> accelerationsOf(const moveit::core::RobotModel& model, const std::vector<std::string>& names,
                                    const std::vector<double>& values, const std::vector<double>& base)
{
  if (values.empty())
    return base;
  if (values.size() != names.size())
    throw std::invalid_argument("RobotTrajectory: a point has " + std::to_string(values.size()) +
                                " accelerations for " + std::to_string(names.size()) + " joints");
  std::vector<double> out = base.empty() ? std::vector<double>(model.getVariableCount(), 0.0) : base;
  for (std::size_t i = 0; i < names.size(); ++i)
    out[model.getVariableIndex(names[i])] = values[i];
  return out;
}
}  // namespace

RobotTrajectory::RobotTrajectory(const moveit::core::RobotModelConstPtr& robot_model)
  : robot_model_(robot_model), group_(nullptr)
{
}

RobotTrajectory::RobotTrajectory(const moveit::core::RobotModelConstPtr& robot_model, const std::string& group)
  : robot_model_(robot_model), group_(group.empty() ? nullptr : robot_model->getJointModelGroup(group))
{
}

RobotTrajectory::RobotTrajectory(const moveit::core::RobotModelConstPtr& robot_model,
                                 const moveit::core::JointModelGroup* group)
  : robot_model_(robot_model), group_(group)
{
}

RobotTrajectory::RobotTrajectory(const RobotTrajectory& other, bool deepcopy)
{
  *this = other;
  if (deepcopy)
    for (auto& waypoint : waypoints_)
      waypoint = std::make_shared<moveit::core::RobotState>(*waypoint);
}

const std::string& RobotTrajectory::getGroupName() const
{
  static const std::string EMPTY;
  return group_ ? group_->getName() : EMPTY;
}

RobotTrajectory& RobotTrajectory::setGroupName(const std::string& group_name)
{
  group_ = robot_model_->getJointModelGroup(group_name);
  return *this;
}

double RobotTrajectory::getWaypointDurationFromStart(std::size_t index) const
{
  return getWayPointDurationFromStart(index);
}

double RobotTrajectory::getWayPointDurationFromStart(std::size_t index) const
{
  // an index past the end is the last waypoint's time (rt:473-484)
  if (duration_from_previous_.empty())
    return 0.0;
  index = std::min(index, duration_from_previous_.size() - 1);
  return std::accumulate(duration_from_previous_.begin(), duration_from_previous_.begin() + index + 1, 0.0);
}

RobotTrajectory& RobotTrajectory::setWayPointDurationFromPrevious(std::size_t index, double value)
{
  if (duration_from_previous_.size() <= index)
    duration_from_previous_.resize(index + 1, 0.0);
  duration_from_previous_[index] = value;
  return *this;
}

std::vector<double>& RobotTrajectory::wayPointAccelerations(std::size_t index)
{
  if (accelerations_.size() < waypoints_.size())
    accelerations_.resize(waypoints_.size());
  std::vector<double>& values = accelerations_.at(index);
  if (values.empty())
    values.assign(robot_model_->getVariableCount(), 0.0);
  return values;
}

RobotTrajectory& RobotTrajectory::addWayPoint(std::size_t index, const moveit::core::RobotStatePtr& state, double dt,
                                              std::vector<double> accelerations)
{
  state->update();
  waypoints_.insert(waypoints_.begin() + index, state);
  // durations may have been set past the waypoints (setWayPointDurationFromPrevious): keep them aligned from the front
  duration_from_previous_.insert(duration_from_previous_.begin() + std::min(index, duration_from_previous_.size()), dt);
  accelerations_.resize(waypoints_.size() - 1);
  accelerations_.insert(accelerations_.begin() + index, std::move(accelerations));
  return *this;
}

RobotTrajectory& RobotTrajectory::addSuffixWayPoint(const moveit::core::RobotState& state, double dt)
{
  return addSuffixWayPoint(std::make_shared<moveit::core::RobotState>(state), dt);
}

RobotTrajectory& RobotTrajectory::addSuffixWayPoint(const moveit::core::RobotStatePtr& state, double dt)
{
  return addWayPoint(waypoints_.size(), state, dt, {});
}

RobotTrajectory& RobotTrajectory::addPrefixWayPoint(const moveit::core::RobotState& state, double dt)
{
  return addPrefixWayPoint(std::make_shared<moveit::core::RobotState>(state), dt);
}

RobotTrajectory& RobotTrajectory::addPrefixWayPoint(const moveit::core::RobotStatePtr& state, double dt)
{
  return addWayPoint(0, state, dt, {});
}

RobotTrajectory& RobotTrajectory::insertWayPoint(std::size_t index, const moveit::core::RobotState& state, double dt)
{
  return insertWayPoint(index, std::make_shared<moveit::core::RobotState>(state), dt);
}

RobotTrajectory& RobotTrajectory::insertWayPoint(std::size_t index, const moveit::core::RobotStatePtr& state,
                                                 double dt)
{
  return addWayPoint(index, state, dt, {});
}

RobotTrajectory& RobotTrajectory::append(const RobotTrajectory& source, double dt, size_t start_index,
                                         size_t end_index)
{
  // rt:103-118: the source's waypoints by pointer, dt added to the first appended duration
  end_index = std::min(end_index, source.waypoints_.size());
  if (start_index >= end_index)
    return *this;
  const std::size_t first = duration_from_previous_.size();
  for (std::size_t i = start_index; i < end_index; ++i)
  {
    waypoints_.push_back(source.waypoints_[i]);
    if (i < source.duration_from_previous_.size())
      duration_from_previous_.push_back(source.duration_from_previous_[i]);
    accelerations_.resize(waypoints_.size() - 1);
    accelerations_.push_back(i < source.accelerations_.size() ? source.accelerations_[i] : std::vector<double>());
  }
  if (duration_from_previous_.size() > first)
    duration_from_previous_[first] += dt;
  return *this;
}

void RobotTrajectory::swap(RobotTrajectory& other)
{
  robot_model_.swap(other.robot_model_);
  std::swap(group_, other.group_);
  waypoints_.swap(other.waypoints_);
  duration_from_previous_.swap(other.duration_from_previous_);
  accelerations_.swap(other.accelerations_);
}

RobotTrajectory& RobotTrajectory::clear()
{
  waypoints_.clear();
  duration_from_previous_.clear();
  accelerations_.clear();
  return *this;
}

double RobotTrajectory::getDuration() const
{
  return std::accumulate(duration_from_previous_.begin(), duration_from_previous_.end(), 0.0);
}

double RobotTrajectory::getAverageSegmentDuration() const
{
  return duration_from_previous_.empty() ? 0.0 : getDuration() / static_cast<double>(duration_from_previous_.size());
}

const std::vector<const moveit::core::JointModel*>& RobotTrajectory::activeJoints() const
{
  return group_ ? group_->getActiveJointModels() : robot_model_->getActiveJointModels();
}

void RobotTrajectory::getRobotTrajectoryMsg(moveit_msgs::RobotTrajectory& trajectory,
                                            const std::vector<std::string>& joint_filter) const
{
  // rt:223-355: the group's (or model's) active joints, the filter's only when one is given; one-DOF joints' values
  // by point, multi-DOF joints' transforms; velocities, accelerations and efforts only when every joint has them;
  // time_from_start the running sum of the durations
  trajectory = moveit_msgs::RobotTrajectory();
  if (waypoints_.empty())
    return;
  std::vector<const moveit::core::JointModel*> onedof;
  std::vector<const moveit::core::JointModel*> mdof;
  for (const moveit::core::JointModel* joint : activeJoints())
  {
    if (!joint_filter.empty() && std::find(joint_filter.begin(), joint_filter.end(), joint->getName()) == joint_filter.end())
      continue;
    if (joint->getVariableCount() == 1)
    {
      trajectory.joint_trajectory.joint_names.push_back(joint->getName());
      onedof.push_back(joint);
    }
    else
    {
      trajectory.multi_dof_joint_trajectory.joint_names.push_back(joint->getName());
      mdof.push_back(joint);
    }
  }
  if (!onedof.empty())
  {
    trajectory.joint_trajectory.header.frame_id = robot_model_->getModelFrame();
    trajectory.joint_trajectory.points.resize(waypoints_.size());
  }
  if (!mdof.empty())
  {
    trajectory.multi_dof_joint_trajectory.header.frame_id = robot_model_->getModelFrame();
    trajectory.multi_dof_joint_trajectory.points.resize(waypoints_.size());
  }
  double total_time = 0.0;
  for (std::size_t i = 0; i < waypoints_.size(); ++i)
  {
    if (i < duration_from_previous_.size())
      total_time += duration_from_previous_[i];
    const ros::Duration from_start(i < duration_from_previous_.size() ? total_time : 0.0);
    const moveit::core::RobotState& state = *waypoints_[i];
    const std::vector<double>* accelerations = i < accelerations_.size() && !accelerations_[i].empty() ?
                                                   &accelerations_[i] :
                                                   nullptr;
    if (!onedof.empty())
    {
      trajectory_msgs::JointTrajectoryPoint& point = trajectory.joint_trajectory.points[i];
      for (const moveit::core::JointModel* joint : onedof)
      {
        const int index = joint->getFirstVariableIndex();
        point.positions.push_back(state.getVariablePosition(index));
        if (state.hasVelocities())
          point.velocities.push_back(state.getVariableVelocity(index));
        if (accelerations)
          point.accelerations.push_back((*accelerations)[index]);
        if (state.hasEffort())
          point.effort.push_back(state.getVariableEffort()[index]);
      }
      point.time_from_start = from_start;
    }
    if (!mdof.empty())
    {
      trajectory_msgs::MultiDOFJointTrajectoryPoint& point = trajectory.multi_dof_joint_trajectory.points[i];
      for (const moveit::core::JointModel* joint : mdof)
        point.transforms.push_back(toTransform(state.getJointTransform(joint)));
      point.time_from_start = from_start;
    }
  }
}

RobotTrajectory& RobotTrajectory::setRobotTrajectoryMsg(const moveit::core::RobotState& reference_state,
                                                        const trajectory_msgs::JointTrajectory& trajectory)
{
  moveit_msgs::RobotTrajectory message;
  message.joint_trajectory = trajectory;
  return setRobotTrajectoryMsg(reference_state, message);
}

RobotTrajectory& RobotTrajectory::setRobotTrajectoryMsg(const moveit::core::RobotState& reference_state,
                                                        const moveit_msgs::RobotTrajectory& trajectory)
{
  // rt:385-431: each point over a copy of the reference state; a waypoint's duration is the difference of the
  // points' stamps (header stamp + time_from_start), the first one's from the header stamp
  const moveit::core::RobotState reference(reference_state);  // the reference may be one of our waypoints
  clear();
  const trajectory_msgs::JointTrajectory& joints = trajectory.joint_trajectory;
  const trajectory_msgs::MultiDOFJointTrajectory& multi = trajectory.multi_dof_joint_trajectory;
  const std::size_t count = std::max(joints.points.size(), multi.points.size());
  ros::Time last = joints.points.empty() ? multi.header.stamp : joints.header.stamp;
  for (std::size_t i = 0; i < count; ++i)
  {
    ros::Time stamp = last;
    auto state = std::make_shared<moveit::core::RobotState>(reference);
    std::vector<double> accelerations;
    if (i < joints.points.size())
    {
      const trajectory_msgs::JointTrajectoryPoint& point = joints.points[i];
      state->setVariablePositions(joints.joint_names, point.positions);
      if (!point.velocities.empty())
        state->setVariableVelocities(joints.joint_names, point.velocities);
      accelerations = accelerationsOf(*robot_model_, joints.joint_names, point.accelerations, accelerations);
      if (!point.effort.empty())
        state->setVariableEffort(joints.joint_names, point.effort);
      stamp = joints.header.stamp + point.time_from_start;
    }
    if (i < multi.points.size())
    {
      const trajectory_msgs::MultiDOFJointTrajectoryPoint& point = multi.points[i];
      if (point.transforms.size() != multi.joint_names.size())
        throw std::invalid_argument("RobotTrajectory: a multi-DOF point has " + std::to_string(point.transforms.size()) +
                                    " transforms for " + std::to_string(multi.joint_names.size()) + " joints");
      for (std::size_t j = 0; j < multi.joint_names.size(); ++j)
        state->setJointPositions(multi.joint_names[j], fromTransform(point.transforms[j]));
      stamp = multi.header.stamp + point.time_from_start;
    }
    addWayPoint(waypoints_.size(), state, (stamp - last).toSec(), std::move(accelerations));
    last = stamp;
  }
  return *this;
}

RobotTrajectory& RobotTrajectory::setRobotTrajectoryMsg(const moveit::core::RobotState& reference_state,
                                                        const moveit_msgs::RobotState& state,
                                                        const moveit_msgs::RobotTrajectory& trajectory)
{
  moveit::core::RobotState start(reference_state);
  moveit::core::robotStateMsgToRobotState(state, start);
  return setRobotTrajectoryMsg(start, trajectory);
}

RobotTrajectory& RobotTrajectory::reverse()
{
  // rt:120-136: the waypoints reversed, their velocities negated, the durations shifted so that each still lies
  // between the same two waypoints
  std::reverse(waypoints_.begin(), waypoints_.end());
  accelerations_.resize(waypoints_.size());
  std::reverse(accelerations_.begin(), accelerations_.end());
  for (const moveit::core::RobotStatePtr& waypoint : waypoints_)
    if (waypoint->hasVelocities())
    {
      double* velocities = waypoint->getVariableVelocities();
      for (std::size_t i = 0; i < waypoint->getVariableCount(); ++i)
        velocities[i] = -velocities[i];
    }
  if (!duration_from_previous_.empty())
  {
    duration_from_previous_.push_back(duration_from_previous_.front());
    std::reverse(duration_from_previous_.begin(), duration_from_previous_.end());
    duration_from_previous_.pop_back();
  }
  return *this;
}

namespace
{
// a continuous joint's values along the waypoints made continuous: each jump of more than pi taken as a wrap
void unwindJoint(std::deque<moveit::core::RobotStatePtr>& waypoints, const moveit::core::JointModel* joint,
                 double running_offset)
{
  double last_value = waypoints[0]->getJointPositions(joint)[0];
  if (std::fabs(running_offset) > EPSILON)
  {
    double value = last_value + running_offset;
    waypoints[0]->setJointPositions(joint, &value);
  }
  for (std::size_t j = 1; j < waypoints.size(); ++j)
  {
    double value = waypoints[j]->getJointPositions(joint)[0];
    if (last_value > value + PI)
      running_offset += 2.0 * PI;
    else if (value > last_value + PI)
      running_offset -= 2.0 * PI;
    last_value = value;
    if (std::fabs(running_offset) > EPSILON)
    {
      value += running_offset;
      waypoints[j]->setJointPositions(joint, &value);
    }
  }
}
}  // namespace

RobotTrajectory& RobotTrajectory::unwind()
{
  // rt:138-173
  if (waypoints_.empty())
    return *this;
  const auto& continuous = group_ ? group_->getContinuousJointModels() : robot_model_->getContinuousJointModels();
  for (const moveit::core::JointModel* joint : continuous)
    unwindJoint(waypoints_, joint, 0.0);
  for (const moveit::core::RobotStatePtr& waypoint : waypoints_)
    waypoint->update();
  return *this;
}

RobotTrajectory& RobotTrajectory::unwind(const moveit::core::RobotState& state)
{
  // rt:175-221: as unwind(), starting from the turns the given state's value holds beyond its bounds
  if (waypoints_.empty())
    return *this;
  const auto& continuous = group_ ? group_->getContinuousJointModels() : robot_model_->getContinuousJointModels();
  for (const moveit::core::JointModel* joint : continuous)
  {
    const double reference = state.getJointPositions(joint)[0];
    double bounded = reference;
    joint->enforcePositionBounds(&bounded);
    unwindJoint(waypoints_, joint, reference - bounded);
  }
  for (const moveit::core::RobotStatePtr& waypoint : waypoints_)
    waypoint->update();
  return *this;
}

void RobotTrajectory::findWayPointIndicesForDurationAfterStart(const double duration, int& before, int& after,
                                                               double& blend) const
{
  // rt:442-471
  if (duration < 0.0)
  {
    before = 0;
    after = 0;
    blend = 0;
    return;
  }
  std::size_t index = 0;
  const std::size_t num_points = waypoints_.size();
  double running_duration = 0.0;
  for (; index < num_points; ++index)
  {
    running_duration += getWayPointDurationFromPrevious(index);
    if (running_duration >= duration)
      break;
  }
  before = std::max<int>(static_cast<int>(index) - 1, 0);
  after = std::min<int>(static_cast<int>(index), static_cast<int>(num_points) - 1);
  const double segment = getWayPointDurationFromPrevious(index);
  const double before_time = running_duration - segment;
  blend = after == before ? 1.0 : (duration - before_time) / segment;
}

bool RobotTrajectory::getStateAtDurationFromStart(const double request_duration,
                                                  moveit::core::RobotStatePtr& output_state) const
{
  // rt:491-505
  if (waypoints_.empty())
    return false;
  int before = 0;
  int after = 0;
  double blend = 1.0;
  findWayPointIndicesForDurationAfterStart(request_duration, before, after, blend);
  waypoints_[before]->interpolate(*waypoints_[after], blend, *output_state);
  return true;
}

double path_length(RobotTrajectory const& trajectory)
{
  double length = 0.0;
  for (std::size_t index = 1; index < trajectory.getWayPointCount(); ++index)
    length += trajectory.getWayPoint(index - 1).distance(trajectory.getWayPoint(index));
  return length;
}
}  // namespace robot_trajectory

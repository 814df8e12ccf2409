// robot_trajectory::RobotTrajectory (MoveIt noetic-devel moveit_core/robot_trajectory/include/moveit/robot_trajectory/
// robot_trajectory.h), minimal: the workspace's own implementation.
//
// Provided: construction for a model and group, waypoints with durations (add, insert, get, clear, reverse), conversion
// to and from moveit_msgs::RobotTrajectory (joint trajectory of the group's variables; time from start),
// getDuration, getAverageSegmentDuration.
// Not provided: multi-DOF trajectory points, unwind, findWayPointIndicesForDurationAfterStart, getStateAtDurationFromStart,
// time parameterization (trajectory_processing: move_group's Python side parameterizes).
#pragma once

#include <deque>
#include <string>
#include <vector>

#include <moveit/macros/class_forward.h>
#include <moveit/robot_state/robot_state.h>
#include <moveit_msgs/RobotState.h>
#include <moveit_msgs/RobotTrajectory.h>

namespace robot_trajectory
{
MOVEIT_CLASS_FORWARD(RobotTrajectory);

class RobotTrajectory
{
public:
  RobotTrajectory(const moveit::core::RobotModelConstPtr& robot_model, const std::string& group);
  RobotTrajectory(const moveit::core::RobotModelConstPtr& robot_model,
                  const moveit::core::JointModelGroup* group = nullptr);

  const moveit::core::RobotModelConstPtr& getRobotModel() const
  {
    return robot_model_;
  }
  const moveit::core::JointModelGroup* getGroup() const
  {
    return group_;
  }
  const std::string& getGroupName() const;
  void setGroupName(const std::string& group_name);

  std::size_t getWayPointCount() const
  {
    return waypoints_.size();
  }
  const moveit::core::RobotState& getWayPoint(std::size_t index) const
  {
    return *waypoints_[index];
  }
  const moveit::core::RobotState& getLastWayPoint() const
  {
    return *waypoints_.back();
  }
  const moveit::core::RobotState& getFirstWayPoint() const
  {
    return *waypoints_.front();
  }
  moveit::core::RobotStatePtr& getWayPointPtr(std::size_t index)
  {
    return waypoints_[index];
  }
  const std::deque<double>& getWayPointDurations() const
  {
    return duration_from_previous_;
  }
  double getWayPointDurationFromPrevious(std::size_t index) const;
  double getWayPointDurationFromStart(std::size_t index) const;
  void setWayPointDurationFromPrevious(std::size_t index, double value);
  bool empty() const
  {
    return waypoints_.empty();
  }

  RobotTrajectory& addSuffixWayPoint(const moveit::core::RobotState& state, double dt)
  {
    return addSuffixWayPoint(std::make_shared<moveit::core::RobotState>(state), dt);
  }
  RobotTrajectory& addSuffixWayPoint(const moveit::core::RobotStatePtr& state, double dt);
  RobotTrajectory& addPrefixWayPoint(const moveit::core::RobotState& state, double dt)
  {
    return addPrefixWayPoint(std::make_shared<moveit::core::RobotState>(state), dt);
  }
  RobotTrajectory& addPrefixWayPoint(const moveit::core::RobotStatePtr& state, double dt);
  RobotTrajectory& insertWayPoint(std::size_t index, const moveit::core::RobotState& state, double dt)
  {
    return insertWayPoint(index, std::make_shared<moveit::core::RobotState>(state), dt);
  }
  RobotTrajectory& insertWayPoint(std::size_t index, const moveit::core::RobotStatePtr& state, double dt);
  RobotTrajectory& clear();
  RobotTrajectory& reverse();

  double getDuration() const;
  double getAverageSegmentDuration() const;

  /// The group's variables (all the model's when no group) as a joint trajectory, times from start
  void getRobotTrajectoryMsg(moveit_msgs::RobotTrajectory& trajectory,
                             const std::vector<std::string>& joint_filter = std::vector<std::string>()) const;
  /// Waypoints from the message, each on a copy of @e reference_state
  RobotTrajectory& setRobotTrajectoryMsg(const moveit::core::RobotState& reference_state,
                                         const trajectory_msgs::JointTrajectory& trajectory);
  RobotTrajectory& setRobotTrajectoryMsg(const moveit::core::RobotState& reference_state,
                                         const moveit_msgs::RobotTrajectory& trajectory);
  RobotTrajectory& setRobotTrajectoryMsg(const moveit::core::RobotState& reference_state,
                                         const moveit_msgs::RobotState& state,
                                         const moveit_msgs::RobotTrajectory& trajectory);

private:
  moveit::core::RobotModelConstPtr robot_model_;
  const moveit::core::JointModelGroup* group_;
  std::deque<moveit::core::RobotStatePtr> waypoints_;
  std::deque<double> duration_from_previous_;
};
}  // namespace robot_trajectory

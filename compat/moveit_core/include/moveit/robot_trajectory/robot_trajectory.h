// robot_trajectory::RobotTrajectory (MoveIt noetic-devel moveit_core/robot_trajectory/include/moveit/robot_trajectory/
// robot_trajectory.h), written anew on this workspace's moveit::core::RobotState: a sequence of full robot states
// (waypoints, shared by pointer) and each one's duration from the previous one, for the whole robot or one group.
//
// Provided, with upstream's signatures and semantics: the three constructors and the shallow/deep copy constructor,
// getRobotModel, getGroup, getGroupName, setGroupName, getWayPointCount, getWayPoint(Ptr), getFirstWayPoint(Ptr),
// getLastWayPoint(Ptr), getWayPointDurations, getWayPointDurationFromStart (and the deprecated getWaypoint... spelling),
// getWayPointDurationFromPrevious, setWayPointDurationFromPrevious, empty, addSuffixWayPoint, addPrefixWayPoint,
// insertWayPoint, append, swap, clear, getDuration, getAverageSegmentDuration, getRobotTrajectoryMsg (one-DOF joints
// in joint_trajectory, multi-DOF joints as transforms in multi_dof_joint_trajectory; the joint filter),
// setRobotTrajectoryMsg (the three overloads), reverse (velocities negated, as RobotState::invertVelocity), unwind
// (both overloads), findWayPointIndicesForDurationAfterStart, getStateAtDurationFromStart, and path_length.
//
// One difference, inside: this RobotState keeps no accelerations, so the trajectory keeps each waypoint's
// accelerations beside it (what a message brought, written back by getRobotTrajectoryMsg; a waypoint added as a
// RobotState has none, as upstream's RobotState without accelerations). Multi-DOF velocities are not written (upstream
// writes a planar joint's only). trajectory_processing::IterativeParabolicTimeParameterization times a trajectory
// (moveit/trajectory_processing/iterative_time_parameterization.h), setting those accelerations too.
#pragma once

#include <deque>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <moveit/macros/class_forward.h>
#include <moveit/robot_model/robot_model.h>
#include <moveit/robot_state/robot_state.h>
#include <moveit_msgs/RobotState.h>
#include <moveit_msgs/RobotTrajectory.h>
#include <trajectory_msgs/JointTrajectory.h>

namespace trajectory_processing
{
class IterativeParabolicTimeParameterization;
}

namespace robot_trajectory
{
MOVEIT_CLASS_FORWARD(RobotTrajectory);

class RobotTrajectory
{
public:
  explicit RobotTrajectory(const moveit::core::RobotModelConstPtr& robot_model);
  // an empty group name is the whole robot; an unknown one also (the model reports it), as upstream's lookup returns
  // nullptr
  RobotTrajectory(const moveit::core::RobotModelConstPtr& robot_model, const std::string& group);
  RobotTrajectory(const moveit::core::RobotModelConstPtr& robot_model, const moveit::core::JointModelGroup* group);
  RobotTrajectory& operator=(const RobotTrajectory&) = default;
  // deepcopy: the waypoints are copied, else shared with other
  RobotTrajectory(const RobotTrajectory& other, bool deepcopy = false);

  const moveit::core::RobotModelConstPtr& getRobotModel() const
  {
    return robot_model_;
  }
  const moveit::core::JointModelGroup* getGroup() const
  {
    return group_;
  }
  const std::string& getGroupName() const;
  RobotTrajectory& setGroupName(const std::string& group_name);

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
  moveit::core::RobotStatePtr& getLastWayPointPtr()
  {
    return waypoints_.back();
  }
  moveit::core::RobotStatePtr& getFirstWayPointPtr()
  {
    return waypoints_.front();
  }
  const std::deque<double>& getWayPointDurations() const
  {
    return duration_from_previous_;
  }
  double getWayPointDurationFromStart(std::size_t index) const;
  [[deprecated]] double getWaypointDurationFromStart(std::size_t index) const;
  double getWayPointDurationFromPrevious(std::size_t index) const
  {
    return index < duration_from_previous_.size() ? duration_from_previous_[index] : 0.0;
  }
  RobotTrajectory& setWayPointDurationFromPrevious(std::size_t index, double value);
  bool empty() const
  {
    return waypoints_.empty();
  }

  // each adds the state (by pointer, or a copy) after update(), with dt from its predecessor
  RobotTrajectory& addSuffixWayPoint(const moveit::core::RobotState& state, double dt);
  RobotTrajectory& addSuffixWayPoint(const moveit::core::RobotStatePtr& state, double dt);
  RobotTrajectory& addPrefixWayPoint(const moveit::core::RobotState& state, double dt);
  RobotTrajectory& addPrefixWayPoint(const moveit::core::RobotStatePtr& state, double dt);
  RobotTrajectory& insertWayPoint(std::size_t index, const moveit::core::RobotState& state, double dt);
  RobotTrajectory& insertWayPoint(std::size_t index, const moveit::core::RobotStatePtr& state, double dt);
  // source's waypoints [start_index, end_index) appended; dt is added to the first one's duration
  RobotTrajectory& append(const RobotTrajectory& source, double dt, size_t start_index = 0,
                          size_t end_index = std::numeric_limits<std::size_t>::max());
  void swap(RobotTrajectory& other);
  RobotTrajectory& clear();

  double getDuration() const;
  double getAverageSegmentDuration() const;

  void getRobotTrajectoryMsg(moveit_msgs::RobotTrajectory& trajectory,
                             const std::vector<std::string>& joint_filter = std::vector<std::string>()) const;
  // each waypoint is the reference state with the point's values over it; durations from the time stamps
  RobotTrajectory& setRobotTrajectoryMsg(const moveit::core::RobotState& reference_state,
                                         const trajectory_msgs::JointTrajectory& trajectory);
  RobotTrajectory& setRobotTrajectoryMsg(const moveit::core::RobotState& reference_state,
                                         const moveit_msgs::RobotTrajectory& trajectory);
  RobotTrajectory& setRobotTrajectoryMsg(const moveit::core::RobotState& reference_state,
                                         const moveit_msgs::RobotState& state,
                                         const moveit_msgs::RobotTrajectory& trajectory);

  RobotTrajectory& reverse();
  RobotTrajectory& unwind();
  RobotTrajectory& unwind(const moveit::core::RobotState& state);

  void findWayPointIndicesForDurationAfterStart(const double duration, int& before, int& after, double& blend) const;
  bool getStateAtDurationFromStart(const double request_duration, moveit::core::RobotStatePtr& output_state) const;

private:
  // the time parameterization sets the accelerations this trajectory keeps for its RobotStates
  friend class trajectory_processing::IterativeParabolicTimeParameterization;
  // the waypoint's accelerations by variable index, made (zeros) when it had none
  std::vector<double>& wayPointAccelerations(std::size_t index);
  RobotTrajectory& addWayPoint(std::size_t index, const moveit::core::RobotStatePtr& state, double dt,
                               std::vector<double> accelerations);
  const std::vector<const moveit::core::JointModel*>& activeJoints() const;

  moveit::core::RobotModelConstPtr robot_model_;
  const moveit::core::JointModelGroup* group_;
  std::deque<moveit::core::RobotStatePtr> waypoints_;
  std::deque<double> duration_from_previous_;
  // each waypoint's accelerations by variable index (empty: none), as RobotState keeps none here
  std::deque<std::vector<double>> accelerations_;
};

// the sum of the joint-space distances between consecutive waypoints (RobotState::distance)
[[nodiscard]] double path_length(RobotTrajectory const& trajectory);
}  // namespace robot_trajectory

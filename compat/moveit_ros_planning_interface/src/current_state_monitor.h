// Internal to moveit_ros_planning_interface: the robot's current state from `joint_states`, as MoveIt's
// planning_scene_monitor::CurrentStateMonitor gives it to MoveGroupInterface (current_state_monitor.cpp, noetic-devel
// 7c0343f0): the latest position of every variable any message named, with the message's stamp per joint; a state is
// "current at t" once the oldest stamp among the updated active joints is t or later (l. 79-116, 272-292).
// Unlike MoveIt's, it spins its own callback queue, so the state arrives whether or not the node spins.
#pragma once

#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include <moveit/robot_state/robot_state.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>

namespace moveit
{
namespace planning_interface
{
namespace detail
{
class CurrentStateMonitor
{
public:
  CurrentStateMonitor(const moveit::core::RobotModelConstPtr& model, const ros::NodeHandle& node_handle);
  ~CurrentStateMonitor();

  bool isActive() const;
  /** subscribes to joint_states (relative to the node handle) */
  void startStateMonitor();
  /** waits up to \e wait_seconds (wall time) until the state is current at \e t */
  bool waitForCurrentState(const ros::Time& t, double wait_seconds) const;
  /** waits up to \e wait_seconds until every active joint of \e group has been named once */
  bool waitForCompleteState(const std::string& group, double wait_seconds) const;
  moveit::core::RobotStatePtr getCurrentState() const;

private:
  void jointStateCallback(const sensor_msgs::JointStateConstPtr& message);
  ros::Time oldestUpdate() const;  // called with mutex_ held

  moveit::core::RobotModelConstPtr model_;
  ros::NodeHandle node_handle_;
  ros::CallbackQueue queue_;
  std::unique_ptr<ros::AsyncSpinner> spinner_;
  ros::Subscriber subscriber_;

  mutable std::mutex mutex_;
  mutable std::condition_variable updated_;
  std::map<std::string, double> positions_;
  std::map<std::string, ros::Time> joint_time_;
};
}  // namespace detail
}  // namespace planning_interface
}  // namespace moveit

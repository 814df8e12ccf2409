// MoveIt's common_planning_interface_objects (moveit_ros_planning_interface, noetic-devel 7c0343f0): the TF buffer
// and robot models a process's interfaces share.
//
// Provided: getSharedTF() (one tf2_ros::Buffer with its TransformListener for the process, alive while anyone holds
// it) and getSharedRobotModel(robot_description) (one model per parameter name, loaded by moveit_ros_planning's
// RobotModelLoader). Not provided: getSharedStateMonitor (MoveIt's planning_scene_monitor::CurrentStateMonitor is not
// here; MoveGroupInterface::getCurrentState gives the current state): calling it stops the build saying so.
#pragma once

#include <memory>
#include <string>

#include <moveit/robot_model/robot_model.h>
#include <tf2_ros/buffer.h>

namespace moveit
{
namespace planning_interface
{
std::shared_ptr<tf2_ros::Buffer> getSharedTF();

moveit::core::RobotModelConstPtr getSharedRobotModel(const std::string& robot_description);

namespace detail
{
template <typename... Args>
struct NotProvided
{
  static constexpr bool value = sizeof...(Args) == 0 && sizeof...(Args) != 0;  // false, once the call is seen
};
}  // namespace detail

template <typename... Args>
void getSharedStateMonitor(Args&&... /* robot_model, tf_buffer, nh */)
{
  static_assert(detail::NotProvided<Args...>::value,
                "moveit::planning_interface::getSharedStateMonitor is not provided here (MoveIt's "
                "planning_scene_monitor::CurrentStateMonitor is not in this workspace): use "
                "MoveGroupInterface::getCurrentState() or subscribe to joint_states");
}
}  // namespace planning_interface
}  // namespace moveit

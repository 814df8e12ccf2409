// Conversions between moveit::core::RobotState and messages (MoveIt noetic-devel
// moveit_core/robot_state/include/moveit/robot_state/conversions.h), the workspace's own implementation.
//
// Provided: jointStateToRobotState, robotStateMsgToRobotState (joint_state and multi_dof_joint_state; is_diff keeps the
// variables the message does not name, otherwise they are left as they were too, as MoveIt does), robotStateToRobotStateMsg,
// robotStateToJointStateMsg, jointTrajPointToRobotState, robotStateToStream, streamToRobotState.
// Not provided: attached collision objects (RobotState has no attached bodies here): copy_attached_bodies is
// accepted and nothing is attached; a message carrying attached_collision_objects gets a ROS warning naming them.
// The overload taking moveit::core::Transforms is not provided (moveit/transforms is not here).
#pragma once

#include <iostream>
#include <string>
#include <vector>

#include <moveit/robot_state/robot_state.h>
#include <moveit_msgs/RobotState.h>
#include <moveit_msgs/RobotTrajectory.h>
#include <sensor_msgs/JointState.h>
#include <trajectory_msgs/JointTrajectory.h>

namespace moveit
{
namespace core
{
/// Sets the variables named by @e joint_state's name/position; false when the message is malformed
bool jointStateToRobotState(const sensor_msgs::JointState& joint_state, RobotState& state);
bool robotStateMsgToRobotState(const moveit_msgs::RobotState& robot_state, RobotState& state,
                               bool copy_attached_bodies = true);
void robotStateToRobotStateMsg(const RobotState& state, moveit_msgs::RobotState& robot_state,
                               bool copy_attached_bodies = true);
void robotStateToJointStateMsg(const RobotState& state, sensor_msgs::JointState& joint_state);
bool jointTrajPointToRobotState(const trajectory_msgs::JointTrajectory& trajectory, std::size_t point_id,
                                RobotState& state);
void robotStateToStream(const RobotState& state, std::ostream& out, bool include_header = true,
                        const std::string& separator = ",");
void robotStateToStream(const RobotState& state, std::ostream& out,
                        const std::vector<std::string>& joint_groups_ordering, bool include_header = true,
                        const std::string& separator = ",");
void streamToRobotState(RobotState& state, const std::string& line, const std::string& separator = ",");
}  // namespace core
}  // namespace moveit

// trajectory_processing's trajectory_tools.h (MoveIt noetic-devel): whether a trajectory message has points, and how
// many waypoints it has (the longer of its joint and multi-DOF parts).
#pragma once

#include <cstddef>

#include <moveit_msgs/RobotTrajectory.h>

namespace trajectory_processing
{
bool isTrajectoryEmpty(const moveit_msgs::RobotTrajectory& trajectory);
std::size_t trajectoryWaypointCount(const moveit_msgs::RobotTrajectory& trajectory);
}  // namespace trajectory_processing

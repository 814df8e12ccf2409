// trajectory_processing's trajectory_tools (MoveIt noetic-devel): the workspace's implementation.
#include <moveit/trajectory_processing/trajectory_tools.h>

#include <algorithm>

namespace trajectory_processing
{
bool isTrajectoryEmpty(const moveit_msgs::RobotTrajectory& trajectory)
{
  return trajectory.joint_trajectory.points.empty() && trajectory.multi_dof_joint_trajectory.points.empty();
}

std::size_t trajectoryWaypointCount(const moveit_msgs::RobotTrajectory& trajectory)
{
  return std::max(trajectory.joint_trajectory.points.size(), trajectory.multi_dof_joint_trajectory.points.size());
}
}  // namespace trajectory_processing

// robot_trajectory::RobotTrajectory (MoveIt's moveit_core/robot_trajectory) is not provided yet by compat/moveit_core:
// plans come back from move_group as moveit_msgs::RobotTrajectory (MoveGroupInterface::Plan::trajectory_), which
// carries the same waypoints; time parameterization is done by move_group.
#error "robot_trajectory::RobotTrajectory (moveit/robot_trajectory/robot_trajectory.h) is not provided by compat/moveit_core yet: use moveit_msgs::RobotTrajectory from MoveGroupInterface::Plan"

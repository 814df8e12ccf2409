"""move_group in Python: MoveIt's ROS interfaces over moveit_core's robot model and
moveit_kinematics' solvers (see node, context, kinematics_service)."""

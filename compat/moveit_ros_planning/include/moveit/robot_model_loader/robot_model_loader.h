// MoveIt's C++ RobotModelLoader is not provided by this workspace: MoveIt's C++ libraries are not installable on
// this platform, and compat/ stands in for MoveIt's ROS interfaces in Python.
#error "MoveIt's C++ RobotModelLoader is not provided here (compat/, MoveIt's names in Python): use moveit_commander (Python), or move_group's compute_fk and compute_ik services from C++"

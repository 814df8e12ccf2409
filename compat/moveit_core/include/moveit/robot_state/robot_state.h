// MoveIt's C++ RobotState (moveit_core) is not provided by this workspace: MoveIt's C++ libraries are not installable on
// this platform, and compat/ stands in for MoveIt's ROS interfaces in Python.
#error "MoveIt's C++ RobotState (moveit_core) is not provided here (compat/, MoveIt's names in Python): use moveit_commander (Python), or move_group's services from C++"

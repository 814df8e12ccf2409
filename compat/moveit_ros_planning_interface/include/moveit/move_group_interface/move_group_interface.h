// MoveIt's C++ MoveGroupInterface is not provided by this workspace: MoveIt's C++ libraries are not installable on
// this platform, and compat/ stands in for MoveIt's ROS interfaces in Python.
#error "MoveIt's C++ MoveGroupInterface is not provided here (compat/, MoveIt's names in Python): write the node in Python with moveit_commander, or talk to move_group's actions and services (move_group, execute_trajectory, compute_ik ...) from C++"

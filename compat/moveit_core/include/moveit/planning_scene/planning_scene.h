// MoveIt's C++ PlanningScene (moveit_core) is not provided by this workspace: MoveIt's C++ libraries are not installable on
// this platform, and compat/ stands in for MoveIt's ROS interfaces in Python.
#error "MoveIt's C++ PlanningScene (moveit_core) is not provided here (compat/, MoveIt's names in Python): use the get_planning_scene and apply_planning_scene services from C++"

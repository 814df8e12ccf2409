// MoveIt's C++ PlanningSceneInterface is not provided by this workspace: MoveIt's C++ libraries are not installable on
// this platform, and compat/ stands in for MoveIt's ROS interfaces in Python.
#error "MoveIt's C++ PlanningSceneInterface is not provided here (compat/, MoveIt's names in Python): use moveit_commander's PlanningSceneInterface (Python), or the apply_planning_scene service and the collision_object topic from C++"

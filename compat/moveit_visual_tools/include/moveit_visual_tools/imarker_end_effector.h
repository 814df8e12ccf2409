// moveit_visual_tools::IMarkerEndEffector (noetic-devel 3.6.1) is not provided here.
#error "moveit_visual_tools' IMarkerEndEffector is not provided here (compat/moveit_visual_tools, see compat/README.md): it needs interactive markers on a PlanningSceneMonitor; use rviz's MotionPlanning display (compat/moveit_ros_visualization) to drag an end effector"

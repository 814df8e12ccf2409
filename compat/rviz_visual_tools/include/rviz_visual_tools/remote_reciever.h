// rviz_visual_tools::RemoteReciever (noetic-devel 3.9.1, the rviz panel's publisher) is not provided here.
#error "rviz_visual_tools' RemoteReciever (the RvizVisualToolsGui panel's side) is not provided here (compat/rviz_visual_tools, see compat/README.md): publish sensor_msgs/Joy on /rviz_visual_tools_gui (buttons[1] next, [2] continue, [3] full continue, [4] stop)"

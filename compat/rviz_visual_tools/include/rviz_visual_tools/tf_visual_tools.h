// rviz_visual_tools::TFVisualTools (noetic-devel 3.9.1) is not provided here.
#error "rviz_visual_tools' TFVisualTools is not provided here (compat/rviz_visual_tools, see compat/README.md): publish transforms with tf2_ros::TransformBroadcaster or tf2_ros::StaticTransformBroadcaster"

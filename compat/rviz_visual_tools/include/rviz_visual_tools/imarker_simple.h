// rviz_visual_tools::IMarkerSimple (noetic-devel 3.9.1) is not provided here.
#error "rviz_visual_tools' IMarkerSimple is not provided here (compat/rviz_visual_tools, see compat/README.md): use interactive_markers::InteractiveMarkerServer (Debian's libinteractive-markers-dev) directly"

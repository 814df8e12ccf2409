/* The version sim_bridge's Gazebo plugin API answers for: Gazebo 11.10.2, the release
 * ROS Noetic uses (compat/gazebo_dev). Plugins branch on GAZEBO_MAJOR_VERSION. */
#ifndef GAZEBO_COMPAT_GAZEBO_CONFIG_H
#define GAZEBO_COMPAT_GAZEBO_CONFIG_H
#define GAZEBO_MAJOR_VERSION 11
#define GAZEBO_MINOR_VERSION 10
#define GAZEBO_PATCH_VERSION 2
#define GAZEBO_VERSION "11.10"
#define GAZEBO_VERSION_FULL "11.10.2"
#define GAZEBO_VERSION_NAMED "11.10.2 (sim_bridge)"
#endif

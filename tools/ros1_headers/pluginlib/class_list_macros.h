// <pluginlib/class_list_macros.h> as Noetic's pluginlib 1.13 has it (noetic-devel pluginlib/include/pluginlib/class_list_macros.h):
// <pluginlib/class_list_macros.hpp> under its ROS 1 name, which ROS 1 packages still include. Debian's pluginlib-dev
// (5.2.1) has only the .hpp; tools/setup.sh installs this into /usr/local/include/pluginlib/.
#ifndef PLUGINLIB_ROS1_CLASS_LIST_MACROS_H
#define PLUGINLIB_ROS1_CLASS_LIST_MACROS_H
#include <pluginlib/class_list_macros.hpp>
#endif  // PLUGINLIB_ROS1_CLASS_LIST_MACROS_H

// <pluginlib/class_loader_base.h> as Noetic's pluginlib 1.13 has it (noetic-devel pluginlib/include/pluginlib/class_loader_base.h):
// <pluginlib/class_loader_base.hpp> under its ROS 1 name, which ROS 1 packages still include. Debian's pluginlib-dev
// (5.2.1) has only the .hpp; tools/setup.sh installs this into /usr/local/include/pluginlib/.
#ifndef PLUGINLIB_ROS1_CLASS_LOADER_BASE_H
#define PLUGINLIB_ROS1_CLASS_LOADER_BASE_H
#include <pluginlib/class_loader_base.hpp>
#endif  // PLUGINLIB_ROS1_CLASS_LOADER_BASE_H

// Noetic's pluginlib (1.13, noetic-devel pluginlib/include/pluginlib/class_loader_imp.h) stops a build that
// includes this header directly; so does this one. Installed by tools/setup.sh into /usr/local/include/pluginlib/.
#ifndef PLUGINLIB_ROS1_CLASS_LOADER_IMP_H
#define PLUGINLIB_ROS1_CLASS_LOADER_IMP_H
#error "<pluginlib/class_loader_imp.h> is not meant to be included: include <pluginlib/class_loader.hpp>"
#endif  // PLUGINLIB_ROS1_CLASS_LOADER_IMP_H

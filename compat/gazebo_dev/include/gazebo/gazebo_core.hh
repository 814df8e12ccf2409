// What every plugin includes through gazebo/gazebo.hh.
#ifndef GAZEBO_COMPAT_GAZEBO_CORE_HH
#define GAZEBO_COMPAT_GAZEBO_CORE_HH
#include "gazebo/util/system.hh"
#include "gazebo/common/common.hh"
#include "gazebo/msgs/msgs.hh"
#include "gazebo/transport/transport.hh"
#endif

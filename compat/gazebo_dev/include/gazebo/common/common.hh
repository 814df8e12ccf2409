// What sim_bridge provides of gazebo::common (Gazebo's own common.hh includes every header
// of the library; here the supported ones).
#ifndef GAZEBO_COMPAT_COMMON_COMMON_HH
#define GAZEBO_COMPAT_COMMON_COMMON_HH
#include "gazebo/gazebo_config.h"
#include "gazebo/common/Assert.hh"
#include "gazebo/common/CommonTypes.hh"
#include "gazebo/common/Console.hh"
#include "gazebo/common/Event.hh"
#include "gazebo/common/Events.hh"
#include "gazebo/common/Exception.hh"
#include "gazebo/common/PID.hh"
#include "gazebo/common/Plugin.hh"
#include "gazebo/common/Time.hh"
#include "gazebo/common/UpdateInfo.hh"
#endif

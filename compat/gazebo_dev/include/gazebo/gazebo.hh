// Gazebo 11's plugin API as sim_bridge provides it (compat/gazebo_dev; see sim_bridge's
// README, "Gazebo C++ plugins"). The functions that start a Gazebo server (setupServer,
// runWorld...) are not provided: sim_bridge is the server.
#ifndef GAZEBO_COMPAT_GAZEBO_HH
#define GAZEBO_COMPAT_GAZEBO_HH
#include "gazebo/gazebo_core.hh"
#endif

// gazebo::sensors: the names only so far (see SensorTypes.hh). Code that calls a sensor's
// methods does not compile against sim_bridge yet.
#ifndef GAZEBO_COMPAT_SENSORS_SENSORS_HH
#define GAZEBO_COMPAT_SENSORS_SENSORS_HH
#include "gazebo/sensors/SensorTypes.hh"
#endif

// What sim_bridge provides of gazebo::sensors: the names and pointer types
// (SensorTypes.hh) and the Sensor base class (Sensor.hh); the typed sensors and
// SensorManager are not provided yet, and code calling them does not compile.
#ifndef GAZEBO_COMPAT_SENSORS_SENSORS_HH
#define GAZEBO_COMPAT_SENSORS_SENSORS_HH
#include "gazebo/sensors/SensorTypes.hh"
#include "gazebo/sensors/Sensor.hh"
#endif

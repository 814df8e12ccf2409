// What sim_bridge provides of gazebo::sensors: Sensor, ContactSensor, RaySensor, ImuSensor,
// SensorManager and get_sensor (the other sensor types are named, as plain Sensors).
#ifndef GAZEBO_COMPAT_SENSORS_SENSORS_HH
#define GAZEBO_COMPAT_SENSORS_SENSORS_HH
#include "gazebo/sensors/SensorTypes.hh"
#include "gazebo/sensors/Sensor.hh"
#include "gazebo/sensors/ContactSensor.hh"
#include "gazebo/sensors/ImuSensor.hh"
#include "gazebo/sensors/RaySensor.hh"
#include "gazebo/sensors/SensorManager.hh"
#include "gazebo/sensors/SensorsIface.hh"
#endif

// gazebo::sensors' free functions: get_sensor, SensorManager's lookup by name.
#ifndef GAZEBO_COMPAT_SENSORS_SENSORSIFACE_HH
#define GAZEBO_COMPAT_SENSORS_SENSORSIFACE_HH
#include <string>

#include "gazebo/sensors/SensorTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
  namespace sensors
  {
    GZ_SENSORS_VISIBLE SensorPtr get_sensor(const std::string &_name);
  }
}
#endif

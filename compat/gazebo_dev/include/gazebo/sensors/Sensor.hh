// gazebo::sensors::Sensor: what every sensor answers, by name (gazebo_plugins'
// gazebo_ros_utils.h includes this header and reads a sensor's ScopedName). sim_bridge makes
// no C++ sensor yet (its sensors are emulated in Python): the class is here so that code
// written against it compiles and links; SensorManager and the typed sensors (ContactSensor,
// RaySensor, ImuSensor) are a later landing's.
#ifndef GAZEBO_COMPAT_SENSORS_SENSOR_HH
#define GAZEBO_COMPAT_SENSORS_SENSOR_HH
#include <string>

#include "gazebo/sensors/SensorTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
  namespace sensors
  {
    class GZ_SENSORS_VISIBLE Sensor
    {
      // _parent is the scoped name of the link it is on (model::link)
      public: Sensor(const std::string &_worldName, const std::string &_parent,
                     const std::string &_name, const std::string &_type);
      public: virtual ~Sensor();
      public: std::string Name() const;
      // world::model::link::sensor
      public: std::string ScopedName() const;
      public: std::string ParentName() const;
      public: std::string WorldName() const;
      public: std::string Type() const;
      public: virtual void SetActive(const bool _value);
      public: virtual bool IsActive() const;

      private: std::string worldName;
      private: std::string parentName;
      private: std::string name;
      private: std::string type;
      private: bool active = false;
    };
  }
}
#endif

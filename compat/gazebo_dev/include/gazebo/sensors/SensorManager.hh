// gazebo::sensors::SensorManager: every sensor of the world's models, by name. GetSensor
// takes a scoped name (world::model::link::sensor) or a plain one; a plain name that two
// sensors share is a gzerr and no sensor, as in Gazebo.
#ifndef GAZEBO_COMPAT_SENSORS_SENSORMANAGER_HH
#define GAZEBO_COMPAT_SENSORS_SENSORMANAGER_HH
#include <mutex>
#include <string>

#include "gazebo/sensors/Sensor.hh"
#include "gazebo/sensors/SensorTypes.hh"

namespace gazebo
{
  namespace sensors
  {
    class GZ_SENSORS_VISIBLE SensorManager
    {
      public: static SensorManager *Instance();
      public: SensorPtr GetSensor(const std::string &_name) const;
      public: Sensor_V GetSensors() const;
      public: bool SensorsInitialized();

      // for sim_bridge's host: a model's sensors come and go with it
      public: void AddSensor(SensorPtr _sensor);
      public: void RemoveSensors(const std::string &_model);
      public: void Clear();

      private: SensorManager() = default;
      private: mutable std::mutex mutex;
      private: Sensor_V sensors;
    };
  }
}
#endif

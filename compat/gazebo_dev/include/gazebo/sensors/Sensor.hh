// gazebo::sensors::Sensor: what every sensor answers. sim_bridge makes one for each
// <sensor> of a model (its Python world measures; see gazebo_compat/Backend.hh) when the
// model's plugins are loaded, so that they find them in Load, as in Gazebo; the typed ones
// are ContactSensor, RaySensor and ImuSensor, the others plain Sensors.
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
      // on the link _link of the model _model (Gazebo's names)
      public: Sensor(const std::string &_worldName, const std::string &_model,
                     const std::string &_link, const std::string &_name,
                     const std::string &_type, double _updateRate);
      public: virtual ~Sensor();
      public: std::string Name() const;
      // world::model::link::sensor
      public: std::string ScopedName() const;
      // the link's scoped name, model::link
      public: std::string ParentName() const;
      public: std::string WorldName() const;
      public: std::string Type() const;
      // Hz of simulated time; 0: every step
      public: double UpdateRate() const;
      public: virtual void SetActive(const bool _value);
      public: virtual bool IsActive() const;

      // for sim_bridge's host
      public: std::string ModelName() const;

      protected: std::string worldName;
      protected: std::string modelName;
      protected: std::string linkName;
      protected: std::string name;
      protected: std::string type;
      protected: double updateRate = 0.0;
      private: bool active = false;
    };
  }
}
#endif

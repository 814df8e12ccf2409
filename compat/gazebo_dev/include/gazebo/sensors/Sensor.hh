// gazebo::sensors::Sensor: what every sensor answers. sim_bridge makes one for each
// <sensor> of a model (its Python world measures; see gazebo_compat/Backend.hh) when the
// model's plugins are loaded, so that they find them in Load, as in Gazebo; the typed ones
// are ContactSensor, RaySensor and ImuSensor, the others plain Sensors. A sensor is active
// from the start when its <always_on> says so, else once SetActive(true); an active one
// updates at its <update_rate> (every step for 0), after the step's WorldUpdateEnd, and
// then calls what ConnectUpdated connected (a sensor plugin's OnUpdate).
#ifndef GAZEBO_COMPAT_SENSORS_SENSOR_HH
#define GAZEBO_COMPAT_SENSORS_SENSOR_HH
#include <cstdint>
#include <functional>
#include <string>

#include "gazebo/common/Event.hh"
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
                     const std::string &_type, double _updateRate, bool _alwaysOn = false);
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
      public: event::ConnectionPtr ConnectUpdated(std::function<void()> _subscriber);
      // an update now (when active and due, or _force), its subscribers called
      public: void Update(const bool _force);

      // for sim_bridge's host: its model, and the end of a step at _simTimeNs
      public: std::string ModelName() const;
      public: void StepEnded(int64_t _simTimeNs);

      protected: std::string worldName;
      protected: std::string modelName;
      protected: std::string linkName;
      protected: std::string name;
      protected: std::string type;
      protected: double updateRate = 0.0;
      private: bool active = false;
      private: int64_t nextUpdateNs = 0;
      private: event::EventT<void()> updated;
    };
  }
}
#endif

// gazebo::sensors' names and pointer types (std::shared_ptr, as Gazebo 11's); sensors.hh
// says which classes are provided.
#ifndef GAZEBO_COMPAT_SENSORS_SENSORTYPES_HH
#define GAZEBO_COMPAT_SENSORS_SENSORTYPES_HH
#include <memory>
#include <vector>

namespace gazebo
{
  namespace sensors
  {
    class Sensor;
    class RaySensor;
    class ContactSensor;
    class ImuSensor;
    class CameraSensor;
    class GpsSensor;
    class SensorManager;
    typedef std::shared_ptr<Sensor> SensorPtr;
    typedef std::shared_ptr<RaySensor> RaySensorPtr;
    typedef std::shared_ptr<ContactSensor> ContactSensorPtr;
    typedef std::shared_ptr<ImuSensor> ImuSensorPtr;
    typedef std::shared_ptr<CameraSensor> CameraSensorPtr;
    typedef std::shared_ptr<GpsSensor> GpsSensorPtr;
    typedef std::vector<SensorPtr> Sensor_V;
  }
}
#endif

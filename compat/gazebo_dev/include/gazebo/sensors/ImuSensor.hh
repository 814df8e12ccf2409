// gazebo::sensors::ImuSensor: angular velocity and specific force (reads +g up at rest) in
// the sensor's axes, and its orientation relative to the one it had when it was made (its
// reference, as Gazebo 11's; SetReferencePose takes the present one). No noise is added:
// the _noiseFree flag changes nothing.
#ifndef GAZEBO_COMPAT_SENSORS_IMUSENSOR_HH
#define GAZEBO_COMPAT_SENSORS_IMUSENSOR_HH
#include <string>
#include <vector>

#include <ignition/math/Quaternion.hh>
#include <ignition/math/Vector3.hh>

#include "gazebo/sensors/Sensor.hh"

namespace gazebo
{
  namespace sensors
  {
    class GZ_SENSORS_VISIBLE ImuSensor : public Sensor
    {
      public: ImuSensor(const std::string &_worldName, const std::string &_model,
                        const std::string &_link, const std::string &_name,
                        const std::string &_type, double _updateRate, bool _alwaysOn);
      public: ignition::math::Vector3d AngularVelocity(const bool _noiseFree = false) const;
      public: ignition::math::Vector3d LinearAcceleration(const bool _noiseFree = false) const;
      public: ignition::math::Quaterniond Orientation() const;
      public: void SetReferencePose();
      public: void SetWorldToReferenceOrientation(const ignition::math::Quaterniond &_q);

      private: std::vector<double> Reading() const;
      private: ignition::math::Quaterniond worldToReference;
    };
  }
}
#endif

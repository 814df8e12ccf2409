// gazebo::sensors::ContactSensor: what the collisions named in its <contact><collision>
// touch, as Gazebo's msgs::Contacts (one Contact per pair of touching collisions; positions
// and normals in world axes, the normal pointing at collision1, which is the sensor's;
// depths; each point's wrench on collision1 as body_1_wrench). Read from the last physics
// step whatever the sensor's update rate (Gazebo's refreshes at its update_rate).
#ifndef GAZEBO_COMPAT_SENSORS_CONTACTSENSOR_HH
#define GAZEBO_COMPAT_SENSORS_CONTACTSENSOR_HH
#include <string>

#include "gazebo/msgs/msgs.hh"
#include "gazebo/sensors/Sensor.hh"

namespace gazebo
{
  namespace sensors
  {
    class GZ_SENSORS_VISIBLE ContactSensor : public Sensor
    {
      public: using Sensor::Sensor;
      public: msgs::Contacts Contacts() const;
    };
  }
}
#endif

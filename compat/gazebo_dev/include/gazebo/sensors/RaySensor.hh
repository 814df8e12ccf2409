// gazebo::sensors::RaySensor: a scanning range finder's last scan (sim_bridge casts one
// horizontal plane of <samples> rays from <min_angle> to <max_angle>). A ray that hits
// nothing within range reads +inf, as Gazebo 11's (REP 117).
#ifndef GAZEBO_COMPAT_SENSORS_RAYSENSOR_HH
#define GAZEBO_COMPAT_SENSORS_RAYSENSOR_HH
#include <string>
#include <vector>

#include <ignition/math/Angle.hh>

#include "gazebo/sensors/Sensor.hh"

namespace gazebo
{
  namespace sensors
  {
    class GZ_SENSORS_VISIBLE RaySensor : public Sensor
    {
      public: RaySensor(const std::string &_worldName, const std::string &_model,
                        const std::string &_link, const std::string &_name,
                        const std::string &_type, double _updateRate, bool _alwaysOn,
                        double _angleMin, double _angleMax, int _samples, double _rangeMin,
                        double _rangeMax);
      public: ignition::math::Angle AngleMin() const;
      public: ignition::math::Angle AngleMax() const;
      public: double AngleResolution() const;
      public: double RangeMin() const;
      public: double RangeMax() const;
      public: int RayCount() const;
      public: int RangeCount() const;
      public: int VerticalRayCount() const;
      public: int VerticalRangeCount() const;
      // m; an index out of range is a gzerr and 0, as in Gazebo
      public: double Range(const unsigned int _index) const;
      public: void Ranges(std::vector<double> &_ranges) const;

      private: double angleMin, angleMax;
      private: int samples;
      private: double rangeMin, rangeMax;
    };
  }
}
#endif

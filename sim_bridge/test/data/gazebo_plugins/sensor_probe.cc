// A plugin that reads a robot's sensors through Gazebo's sensor API, as robot plugins do,
// and reports what it read for test_native_plugins.py: sensor_probe_report() (C linkage;
// the test opens this library with ctypes and gets the instance sim_bridge loaded). The
// <sensors> it names (space-separated, plain or scoped) are looked up in Load through
// SensorManager, as Kobuki's plugin looks up its own; a missing one throws. Its first line
// names the model as Kobuki's plugin reads it, from the <plugin> element's parent.
#include <cstdio>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include <gazebo/gazebo.hh>
#include <gazebo/physics/physics.hh>
#include <gazebo/sensors/sensors.hh>

namespace
{
std::mutex reportMutex;
std::string report;
}

extern "C" const char *sensor_probe_report()
{
  std::lock_guard<std::mutex> lock(reportMutex);
  static std::string copy;
  copy = report;
  return copy.c_str();
}

namespace gazebo
{
  class SensorProbe : public ModelPlugin
  {
    public: void Load(physics::ModelPtr, sdf::ElementPtr _sdf)
    {
      this->sdf = _sdf;
      std::istringstream names(_sdf->Get<std::string>("sensors"));
      std::string name;
      while (names >> name)
      {
        sensors::SensorPtr sensor = sensors::SensorManager::Instance()->GetSensor(name);
        if (!sensor)
          gzthrow("SensorProbe: no sensor named " << name);
        sensor->SetActive(true);
        this->found.push_back(sensor);
      }
      this->connection = event::Events::ConnectWorldUpdateEnd(
          std::bind(&SensorProbe::OnUpdate, this));
    }

    // one line per sensor: its scoped and parent names, type, then what it reads
    private: void OnUpdate()
    {
      std::ostringstream out;
      out.precision(6);
      // read at each update: the element's parent outlives Load
      out << "model: " << this->sdf->GetParent()->Get<std::string>("name") << "\n";
      for (const auto &sensor : this->found)
      {
        out << sensor->ScopedName() << " " << sensor->ParentName() << " " << sensor->Type();
        if (auto contact = std::dynamic_pointer_cast<sensors::ContactSensor>(sensor))
        {
          const msgs::Contacts contacts = contact->Contacts();
          double force = 0.0;
          int points = 0;
          for (int i = 0; i < contacts.contact_size(); ++i)
          {
            const msgs::Contact &c = contacts.contact(i);
            out << " pair " << c.collision1() << " " << c.collision2();
            for (int j = 0; j < c.position_size(); ++j, ++points)
              force += c.wrench(j).body_1_wrench().force().z();
            if (c.normal_size() > 0)
              out << " normal_z " << c.normal(0).z();
          }
          out << " points " << points << " force_z " << force;
        }
        else if (auto ray = std::dynamic_pointer_cast<sensors::RaySensor>(sensor))
        {
          out << " count " << ray->RangeCount() << " min " << ray->RangeMin() << " max "
              << ray->RangeMax() << " angle_min " << ray->AngleMin().Radian() << " range0 "
              << ray->Range(0);
        }
        else if (auto imu = std::dynamic_pointer_cast<sensors::ImuSensor>(sensor))
        {
          out << " accel_z " << imu->LinearAcceleration().Z() << " rate_z "
              << imu->AngularVelocity().Z() << " yaw " << imu->Orientation().Yaw();
        }
        out << "\n";
      }
      std::lock_guard<std::mutex> lock(reportMutex);
      report = out.str();
    }

    private: sdf::ElementPtr sdf;
    private: std::vector<sensors::SensorPtr> found;
    private: event::ConnectionPtr connection;
  };

  GZ_REGISTER_MODEL_PLUGIN(SensorProbe)
}

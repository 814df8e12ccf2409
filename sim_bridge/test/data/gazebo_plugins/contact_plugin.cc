// A sensor plugin in the shape of Gazebo's contact sensor tutorial (written here): Load
// takes the sensor, casts it to a ContactSensor, connects to its updates and activates it;
// each update reads its contacts. What it saw is reported to test_native_plugins.py through
// contact_plugin_report() (C linkage; the test opens this library with ctypes).
#include <mutex>
#include <sstream>
#include <string>

#include <gazebo/gazebo.hh>
#include <gazebo/sensors/sensors.hh>

namespace
{
std::mutex reportMutex;
std::string report;
}

extern "C" const char *contact_plugin_report()
{
  std::lock_guard<std::mutex> lock(reportMutex);
  static std::string copy;
  copy = report;
  return copy.c_str();
}

namespace gazebo
{
  class ContactProbe : public SensorPlugin
  {
    public: void Load(sensors::SensorPtr _sensor, sdf::ElementPtr)
    {
      this->sensor = std::dynamic_pointer_cast<sensors::ContactSensor>(_sensor);
      if (!this->sensor)
        gzthrow("ContactProbe needs a contact sensor");
      this->connection = this->sensor->ConnectUpdated(std::bind(&ContactProbe::OnUpdate, this));
      this->sensor->SetActive(true);
    }

    // "updates N contacts M first <collision1> <collision2>"
    private: void OnUpdate()
    {
      const msgs::Contacts contacts = this->sensor->Contacts();
      std::ostringstream out;
      out << "updates " << ++this->updates << " contacts " << contacts.contact_size();
      if (contacts.contact_size() > 0)
        out << " first " << contacts.contact(0).collision1() << " "
            << contacts.contact(0).collision2();
      std::lock_guard<std::mutex> lock(reportMutex);
      report = out.str();
    }

    private: sensors::ContactSensorPtr sensor;
    private: event::ConnectionPtr connection;
    private: int updates = 0;
  };

  GZ_REGISTER_SENSOR_PLUGIN(ContactProbe)
}

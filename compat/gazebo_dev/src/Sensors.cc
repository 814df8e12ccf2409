// gazebo::sensors::Sensor (see include/gazebo/sensors/Sensor.hh).
#include "gazebo/sensors/Sensor.hh"

namespace gazebo
{
namespace sensors
{
Sensor::Sensor(const std::string &_worldName, const std::string &_parent,
               const std::string &_name, const std::string &_type)
  : worldName(_worldName), parentName(_parent), name(_name), type(_type)
{
}

Sensor::~Sensor() {}

std::string Sensor::Name() const { return this->name; }

std::string Sensor::ScopedName() const
{
  return this->worldName + "::" + this->parentName + "::" + this->name;
}

std::string Sensor::ParentName() const { return this->parentName; }
std::string Sensor::WorldName() const { return this->worldName; }
std::string Sensor::Type() const { return this->type; }
void Sensor::SetActive(const bool _value) { this->active = _value; }
bool Sensor::IsActive() const { return this->active; }
}  // namespace sensors
}  // namespace gazebo

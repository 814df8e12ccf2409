// gazebo::sensors (see include/gazebo/sensors/): C++ sensors over sim_bridge's world, which
// measures (gazebo_compat::Backend's Sensor* calls, made each time a reading is asked for;
// the world measures once per step and sensor).
#include <algorithm>
#include <limits>

#include "gazebo/common/Console.hh"
#include "gazebo/sensors/ContactSensor.hh"
#include "gazebo/sensors/ImuSensor.hh"
#include "gazebo/sensors/RaySensor.hh"
#include "gazebo/sensors/Sensor.hh"
#include "gazebo/sensors/SensorManager.hh"
#include "gazebo/sensors/SensorsIface.hh"
#include "gazebo_compat/Host.hh"

namespace gazebo
{
namespace sensors
{
namespace
{
std::shared_ptr<gazebo_compat::Backend> backend()
{
  return gazebo_compat::Host::Instance().GetBackend();
}

// the IMU reading's layout (gazebo_compat::Backend::SensorImu)
const size_t kAngular = 0;
const size_t kLinear = 3;
const size_t kOrientation = 6;
const size_t kImuValues = 10;
}  // namespace

// --- Sensor --------------------------------------------------------------------------------
Sensor::Sensor(const std::string &_worldName, const std::string &_model,
               const std::string &_link, const std::string &_name, const std::string &_type,
               double _updateRate, bool _alwaysOn)
  : worldName(_worldName), modelName(_model), linkName(_link), name(_name), type(_type),
    updateRate(_updateRate), active(_alwaysOn)
{
}

Sensor::~Sensor() {}

std::string Sensor::Name() const { return this->name; }

std::string Sensor::ScopedName() const
{
  return this->worldName + "::" + this->ParentName() + "::" + this->name;
}

std::string Sensor::ParentName() const { return this->modelName + "::" + this->linkName; }
std::string Sensor::WorldName() const { return this->worldName; }
std::string Sensor::Type() const { return this->type; }
double Sensor::UpdateRate() const { return this->updateRate; }
void Sensor::SetActive(const bool _value) { this->active = _value; }
bool Sensor::IsActive() const { return this->active; }
std::string Sensor::ModelName() const { return this->modelName; }

event::ConnectionPtr Sensor::ConnectUpdated(std::function<void()> _subscriber)
{
  return this->updated.Connect(_subscriber);
}

void Sensor::Update(const bool _force)
{
  if (_force || this->active)
    this->updated();
}

void Sensor::StepEnded(int64_t _simTimeNs)
{
  if (!this->active || _simTimeNs < this->nextUpdateNs)
    return;
  // the next update one period on (Gazebo's sensors keep to their rate)
  const int64_t period = this->updateRate > 0 ? static_cast<int64_t>(1e9 / this->updateRate) : 0;
  this->nextUpdateNs = _simTimeNs + period;
  this->updated();
}

// --- ContactSensor -------------------------------------------------------------------------
msgs::Contacts ContactSensor::Contacts() const
{
  msgs::Contacts contacts;
  for (const auto &pair : backend()->SensorContacts(this->modelName, this->name))
  {
    msgs::Contact *contact = contacts.add_contact();
    contact->set_collision1(pair.collision1);
    contact->set_collision2(pair.collision2);
    contact->set_world(this->worldName);
    for (size_t i = 0; i < pair.depths.size(); ++i)
    {
      msgs::Vector3d *position = contact->add_position();
      position->set_x(pair.positions.at(3 * i));
      position->set_y(pair.positions.at(3 * i + 1));
      position->set_z(pair.positions.at(3 * i + 2));
      msgs::Vector3d *normal = contact->add_normal();
      normal->set_x(pair.normals.at(3 * i));
      normal->set_y(pair.normals.at(3 * i + 1));
      normal->set_z(pair.normals.at(3 * i + 2));
      contact->add_depth(pair.depths.at(i));
      msgs::JointWrench *wrench = contact->add_wrench();
      wrench->set_body_1_name(pair.collision1);
      wrench->set_body_2_name(pair.collision2);
      msgs::Wrench *onFirst = wrench->mutable_body_1_wrench();
      onFirst->mutable_force()->set_x(pair.forces.at(3 * i));
      onFirst->mutable_force()->set_y(pair.forces.at(3 * i + 1));
      onFirst->mutable_force()->set_z(pair.forces.at(3 * i + 2));
      onFirst->mutable_torque()->set_x(pair.torques.at(3 * i));
      onFirst->mutable_torque()->set_y(pair.torques.at(3 * i + 1));
      onFirst->mutable_torque()->set_z(pair.torques.at(3 * i + 2));
      // what collision1 pushes collision2 with
      msgs::Wrench *onSecond = wrench->mutable_body_2_wrench();
      onSecond->mutable_force()->set_x(-pair.forces.at(3 * i));
      onSecond->mutable_force()->set_y(-pair.forces.at(3 * i + 1));
      onSecond->mutable_force()->set_z(-pair.forces.at(3 * i + 2));
    }
    const int64_t ns = gazebo_compat::Host::Instance().SimTimeNs();
    contact->mutable_time()->set_sec(static_cast<int32_t>(ns / 1000000000));
    contact->mutable_time()->set_nsec(static_cast<int32_t>(ns % 1000000000));
  }
  const int64_t ns = gazebo_compat::Host::Instance().SimTimeNs();
  contacts.mutable_time()->set_sec(static_cast<int32_t>(ns / 1000000000));
  contacts.mutable_time()->set_nsec(static_cast<int32_t>(ns % 1000000000));
  return contacts;
}

// --- RaySensor -----------------------------------------------------------------------------
RaySensor::RaySensor(const std::string &_worldName, const std::string &_model,
                     const std::string &_link, const std::string &_name,
                     const std::string &_type, double _updateRate, bool _alwaysOn,
                     double _angleMin, double _angleMax, int _samples, double _rangeMin,
                     double _rangeMax)
  : Sensor(_worldName, _model, _link, _name, _type, _updateRate, _alwaysOn),
    angleMin(_angleMin),
    angleMax(_angleMax), samples(_samples), rangeMin(_rangeMin), rangeMax(_rangeMax)
{
}

ignition::math::Angle RaySensor::AngleMin() const { return this->angleMin; }
ignition::math::Angle RaySensor::AngleMax() const { return this->angleMax; }

double RaySensor::AngleResolution() const
{
  return this->samples > 1 ? (this->angleMax - this->angleMin) / (this->samples - 1) : 0.0;
}

double RaySensor::RangeMin() const { return this->rangeMin; }
double RaySensor::RangeMax() const { return this->rangeMax; }
int RaySensor::RayCount() const { return this->samples; }
int RaySensor::RangeCount() const { return this->samples; }
int RaySensor::VerticalRayCount() const { return 1; }
int RaySensor::VerticalRangeCount() const { return 1; }

double RaySensor::Range(const unsigned int _index) const
{
  const std::vector<double> ranges = backend()->SensorRanges(this->modelName, this->name);
  if (_index >= ranges.size())
  {
    gzerr << "Range index[" << _index << "] out of range [0, " << ranges.size() << ")"
          << std::endl;
    return 0.0;
  }
  return ranges[_index];
}

void RaySensor::Ranges(std::vector<double> &_ranges) const
{
  _ranges = backend()->SensorRanges(this->modelName, this->name);
}

// --- ImuSensor -----------------------------------------------------------------------------
ImuSensor::ImuSensor(const std::string &_worldName, const std::string &_model,
                     const std::string &_link, const std::string &_name,
                     const std::string &_type, double _updateRate, bool _alwaysOn)
  : Sensor(_worldName, _model, _link, _name, _type, _updateRate, _alwaysOn)
{
  this->SetReferencePose();
}

std::vector<double> ImuSensor::Reading() const
{
  std::vector<double> reading = backend()->SensorImu(this->modelName, this->name);
  reading.resize(kImuValues, 0.0);
  return reading;
}

ignition::math::Vector3d ImuSensor::AngularVelocity(const bool) const
{
  const std::vector<double> r = this->Reading();
  return {r[kAngular], r[kAngular + 1], r[kAngular + 2]};
}

ignition::math::Vector3d ImuSensor::LinearAcceleration(const bool) const
{
  const std::vector<double> r = this->Reading();
  return {r[kLinear], r[kLinear + 1], r[kLinear + 2]};
}

ignition::math::Quaterniond ImuSensor::Orientation() const
{
  const std::vector<double> r = this->Reading();
  const ignition::math::Quaterniond world(r[kOrientation + 3], r[kOrientation],
                                          r[kOrientation + 1], r[kOrientation + 2]);
  return this->worldToReference.Inverse() * world;
}

void ImuSensor::SetReferencePose()
{
  const std::vector<double> r = this->Reading();
  this->worldToReference = ignition::math::Quaterniond(r[kOrientation + 3], r[kOrientation],
                                                       r[kOrientation + 1],
                                                       r[kOrientation + 2]);
}

void ImuSensor::SetWorldToReferenceOrientation(const ignition::math::Quaterniond &_q)
{
  this->worldToReference = _q;
}

// --- SensorManager -------------------------------------------------------------------------
SensorManager *SensorManager::Instance()
{
  static SensorManager manager;
  return &manager;
}

SensorPtr SensorManager::GetSensor(const std::string &_name) const
{
  std::lock_guard<std::mutex> lock(this->mutex);
  for (const auto &sensor : this->sensors)
    if (sensor->ScopedName() == _name)
      return sensor;
  SensorPtr found;
  for (const auto &sensor : this->sensors)
  {
    if (sensor->Name() != _name)
      continue;
    if (found)
    {
      gzerr << "Unable to get a sensor: several sensors are named[" << _name
            << "]; ask for a scoped name (world::model::link::sensor)" << std::endl;
      return SensorPtr();
    }
    found = sensor;
  }
  return found;
}

Sensor_V SensorManager::GetSensors() const
{
  std::lock_guard<std::mutex> lock(this->mutex);
  return this->sensors;
}

bool SensorManager::SensorsInitialized() { return true; }

void SensorManager::AddSensor(SensorPtr _sensor)
{
  std::lock_guard<std::mutex> lock(this->mutex);
  this->sensors.push_back(_sensor);
}

void SensorManager::RemoveSensors(const std::string &_model)
{
  std::lock_guard<std::mutex> lock(this->mutex);
  this->sensors.erase(std::remove_if(this->sensors.begin(), this->sensors.end(),
                                     [&](const SensorPtr &_s)
                                     { return _s->ModelName() == _model; }),
                      this->sensors.end());
}

void SensorManager::Clear()
{
  std::lock_guard<std::mutex> lock(this->mutex);
  this->sensors.clear();
}

SensorPtr get_sensor(const std::string &_name)
{
  return SensorManager::Instance()->GetSensor(_name);
}
}  // namespace sensors
}  // namespace gazebo

// gazebo_compat::Host: the world, its models, the plugin loader, the step's events.
#include <dlfcn.h>
#include <sys/stat.h>

#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "gazebo/common/Events.hh"
#include "gazebo/physics/physics.hh"
#include "gazebo/sensors/sensors.hh"
#include "gazebo_compat/Host.hh"

namespace gazebo_compat
{
namespace
{
std::vector<std::string> Split(const char *_text)
{
  std::vector<std::string> parts;
  if (!_text)
    return parts;
  std::stringstream stream(_text);
  std::string part;
  while (std::getline(stream, part, ':'))
    if (!part.empty())
      parts.push_back(part);
  return parts;
}

bool IsFile(const std::string &_path)
{
  struct stat info;
  return stat(_path.c_str(), &info) == 0 && S_ISREG(info.st_mode);
}

// "the exception's text" for whatever a plugin threw
std::string Describe(std::exception_ptr _error)
{
  try
  {
    std::rethrow_exception(_error);
  }
  catch (const gazebo::common::Exception &_e)
  {
    std::string text = _e.GetErrorStr();
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
      text.pop_back();
    return text;
  }
  catch (const std::exception &_e)
  {
    return _e.what();
  }
  catch (...)
  {
    return "an exception that is not a std::exception";
  }
}
}  // namespace

void *OpenPluginLibrary(const std::string &_filename, std::string &_fullname,
                        std::string &_error)
{
  _fullname = _filename;
  if (_filename.find('/') == std::string::npos)
  {
    for (const auto &folder : Host::PluginPath())
    {
      if (IsFile(folder + "/" + _filename))
      {
        _fullname = folder + "/" + _filename;
        break;
      }
    }
  }
  // Gazebo opens plugins RTLD_LAZY | RTLD_GLOBAL (Gazebo 11.10.2 gazebo/common/Plugin.hh:152):
  // a symbol nothing defines is found missing only when it is called, and then the process
  // ends with "symbol lookup error". Binding everything first names it before that happens.
  void *handle = dlopen(_fullname.c_str(), RTLD_NOW | RTLD_GLOBAL);
  if (!handle)
  {
    const char *nowError = dlerror();
    const std::string unbound = nowError ? nowError : "";
    handle = dlopen(_fullname.c_str(), RTLD_LAZY | RTLD_GLOBAL);
    if (handle)
      gzwarn << unbound << ": loaded as Gazebo loads it (lazily); the simulator stops when "
             << "the plugin calls it (link the library that defines it)\n";
  }
  if (!handle)
  {
    const char *error = dlerror();
    _error = error ? error : "dlopen failed";
    return nullptr;
  }
  void *symbol = dlsym(handle, "RegisterPlugin");
  if (!symbol)
  {
    const char *error = dlerror();
    _error = std::string("no RegisterPlugin in it (not a Gazebo plugin: GZ_REGISTER_*_PLUGIN "
                         "missing?): ") + (error ? error : "");
    return nullptr;
  }
  return symbol;
}

namespace
{
// The plugin of type T the library _filename registers (its RegisterPlugin, as
// GZ_REGISTER_*_PLUGIN defines it), or none with why not in _error: the library not found
// or not loadable, its constructor threw, it returned none, or it is of another type than
// _type (_wrongType then).
template <typename T>
typename T::TPtr MakePlugin(const std::string &_filename, gazebo::PluginType _type,
                            const std::string &_wrongType, std::string &_error)
{
  std::string fullname, error;
  void *symbol = OpenPluginLibrary(_filename, fullname, error);
  if (!symbol)
  {
    _error = "failed to load plugin " + _filename + ": " + error;
    return typename T::TPtr();
  }
  typename T::TPtr plugin;
  try
  {
    typedef T *(*Register)();
    plugin.reset(reinterpret_cast<Register>(symbol)());
  }
  catch (...)
  {
    _error = "its constructor threw: " + Describe(std::current_exception());
    return typename T::TPtr();
  }
  if (!plugin)
    _error = "RegisterPlugin returned no plugin";
  else if (plugin->GetType() != _type)
    _error = _wrongType;
  else
    return plugin;
  return typename T::TPtr();
}
}  // namespace

std::vector<std::string> Host::PluginPath()
{
  std::vector<std::string> folders = Split(std::getenv("GAZEBO_PLUGIN_PATH"));
  for (const auto &prefix : Split(std::getenv("CMAKE_PREFIX_PATH")))
    folders.push_back(prefix + "/lib");
  return folders;
}

Host &Host::Instance()
{
  static Host host;
  return host;
}

void Host::SetBackend(std::shared_ptr<Backend> _backend)
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  this->backend = _backend;
}

std::shared_ptr<Backend> Host::GetBackend() const
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  if (!this->backend)
    throw std::runtime_error("sim_bridge's Gazebo plugin host has no world (closed)");
  return this->backend;
}

gazebo::physics::WorldPtr Host::World()
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  if (!this->world)
    this->world.reset(new gazebo::physics::World());
  return this->world;
}

gazebo::physics::ModelPtr Host::Model(const std::string &_name)
{
  using namespace gazebo::physics;
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  auto found = this->models.find(_name);
  if (found != this->models.end())
    return found->second;
  const ModelInfo info = this->GetBackend()->Describe(_name);
  ModelPtr model(new gazebo::physics::Model(BasePtr()));
  model->SetWorld(this->World());
  model->SetName(_name);
  Link_V links;
  for (const auto &name : info.links)
  {
    LinkPtr link(new Link(model));
    link->SetName(name);
    links.push_back(link);
  }
  auto linkNamed = [&links](const std::string &_link) {
    for (const auto &link : links)
      if (link->GetName() == _link)
        return link;
    return LinkPtr();
  };
  Joint_V joints;
  for (const auto &joint : info.joints)
  {
    JointPtr made(new Joint(model, joint.type));
    made->SetName(joint.name);
    made->Attach(linkNamed(joint.parent), linkNamed(joint.child), joint.lower, joint.upper,
                 joint.effort, joint.velocity);
    joints.push_back(made);
  }
  model->Build(links, joints);
  this->models[_name] = model;
  // its sensors, before any of its plugins loads (Gazebo's Model::LoadPlugins waits for them)
  const std::string world = this->GetBackend()->WorldName();
  {
    // kept for the per-step UpdateInfo: a call into the backend costs a Python call
    std::lock_guard<std::recursive_mutex> lock(this->mutex);
    this->worldName = world;
  }
  for (const auto &sensor : this->GetBackend()->Sensors(_name))
  {
    gazebo::sensors::SensorPtr made;
    if (sensor.type == "contact")
      made.reset(new gazebo::sensors::ContactSensor(world, _name, sensor.link, sensor.name,
                                                    sensor.type, sensor.updateRate,
                                                    sensor.alwaysOn));
    else if (sensor.type == "ray" || sensor.type == "gpu_ray")
      made.reset(new gazebo::sensors::RaySensor(world, _name, sensor.link, sensor.name,
                                                sensor.type, sensor.updateRate,
                                                sensor.alwaysOn, sensor.angleMin,
                                                sensor.angleMax,
                                                sensor.samples, sensor.rangeMin,
                                                sensor.rangeMax));
    else if (sensor.type == "imu")
      made.reset(new gazebo::sensors::ImuSensor(world, _name, sensor.link, sensor.name,
                                                sensor.type, sensor.updateRate,
                                                sensor.alwaysOn));
    else
      made.reset(new gazebo::sensors::Sensor(world, _name, sensor.link, sensor.name,
                                             sensor.type, sensor.updateRate, sensor.alwaysOn));
    gazebo::sensors::SensorManager::Instance()->AddSensor(made);
  }
  return model;
}

std::vector<gazebo::physics::ModelPtr> Host::KnownModels() const
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  std::vector<gazebo::physics::ModelPtr> known;
  for (const auto &entry : this->models)
    known.push_back(entry.second);
  return known;
}

std::string Host::LoadModelPlugin(const std::string &_model, const std::string &_filename,
                                  const std::string &_name, sdf::ElementPtr _sdf)
{
  std::string error;
  gazebo::ModelPlugin::TPtr plugin = MakePlugin<gazebo::ModelPlugin>(
      _filename, gazebo::MODEL_PLUGIN, "it is not a model plugin (GZ_REGISTER_MODEL_PLUGIN); "
      "a world plugin belongs in the world file, a system plugin on gzserver's command line "
      "(-s)", error);
  if (!plugin)
    return error;
  try
  {
    plugin->Load(this->Model(_model), _sdf);
    plugin->Init();
  }
  catch (...)
  {
    return "exception in the Load function of plugin with name[" + _name + "] and filename[" +
           _filename + "]: " + Describe(std::current_exception()) + "; this plugin will not run";
  }
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  this->modelPlugins.emplace_back(_model, plugin);
  return "";
}

std::string Host::LoadSensorPlugin(const std::string &_model, const std::string &_sensor,
                                   const std::string &_filename, const std::string &_name,
                                   sdf::ElementPtr _sdf)
{
  std::string error;
  gazebo::SensorPlugin::TPtr plugin = MakePlugin<gazebo::SensorPlugin>(
      _filename, gazebo::SENSOR_PLUGIN, "it is not a sensor plugin (GZ_REGISTER_SENSOR_PLUGIN)",
      error);
  if (!plugin)
    return error;
  gazebo::sensors::SensorPtr sensor;
  try
  {
    this->Model(_model);  // its sensors made
    for (const auto &candidate : gazebo::sensors::SensorManager::Instance()->GetSensors())
      if (candidate->ModelName() == _model && candidate->Name() == _sensor)
        sensor = candidate;
  }
  catch (...)
  {
    return "its model '" + _model + "' could not be read: " +
           Describe(std::current_exception());
  }
  if (!sensor)
    return "its sensor '" + _sensor + "' is not one sim_bridge makes";
  try
  {
    plugin->Load(sensor, _sdf);
    plugin->Init();
  }
  catch (...)
  {
    return "exception in the Load function of plugin with name[" + _name + "] and filename[" +
           _filename + "]: " + Describe(std::current_exception()) + "; this plugin will not run";
  }
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  this->sensorPlugins.emplace_back(_model, plugin);
  return "";
}

std::string Host::LoadWorldPlugin(const std::string &_filename, const std::string &_name,
                                  sdf::ElementPtr _sdf)
{
  std::string error;
  gazebo::WorldPlugin::TPtr plugin = MakePlugin<gazebo::WorldPlugin>(
      _filename, gazebo::WORLD_PLUGIN, "it is not a world plugin (GZ_REGISTER_WORLD_PLUGIN)",
      error);
  if (!plugin)
    return error;
  try
  {
    plugin->Load(this->World(), _sdf);
    plugin->Init();
  }
  catch (...)
  {
    return "exception in the Load function of plugin with name[" + _name + "] and filename[" +
           _filename + "]: " + Describe(std::current_exception()) + "; this plugin will not run";
  }
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  this->worldPlugins.push_back(plugin);
  return "";
}

// gzserver's system plugins (gazebo-classic, Debian's gazebo 11.10.2 source: Server.cc
// :282-290 takes each -s; gazebo_shared.cc:33-53 makes it, refusing another plugin type
// with a gzerr; :55-96 calls every plugin's Load(argc, argv) before transport starts and
// every Init() after; physics/World.cc:414 signals worldCreated once the world has loaded)
std::string Host::LoadSystemPlugin(const std::string &_filename,
                                   const std::vector<std::string> &_argv)
{
  std::string error;
  gazebo::SystemPlugin::TPtr plugin = MakePlugin<gazebo::SystemPlugin>(
      _filename, gazebo::SYSTEM_PLUGIN, "System is attempting to load a plugin, but detected "
      "an incorrect plugin type. Plugin filename[" + _filename + "]", error);
  if (!plugin)
    return error;
  {
    std::lock_guard<std::recursive_mutex> lock(this->mutex);
    if (this->systemArgv.empty())
    {
      this->systemArguments = _argv;
      for (auto &argument : this->systemArguments)
        this->systemArgv.push_back(&argument[0]);
      this->systemArgv.push_back(nullptr);
    }
  }
  try
  {
    plugin->Load(static_cast<int>(this->systemArgv.size()) - 1, this->systemArgv.data());
  }
  catch (...)
  {
    return "exception in the Load function of system plugin [" + _filename + "]: " +
           Describe(std::current_exception()) + "; this plugin will not run";
  }
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  this->systemPlugins.emplace_back(_filename, plugin);
  return "";
}

std::vector<std::string> Host::InitSystemPlugins()
{
  std::vector<std::pair<std::string, gazebo::SystemPlugin::TPtr>> plugins, kept;
  {
    std::lock_guard<std::recursive_mutex> lock(this->mutex);
    plugins = this->systemPlugins;
  }
  std::vector<std::string> errors;
  for (const auto &entry : plugins)
  {
    try
    {
      entry.second->Init();
      kept.push_back(entry);
    }
    catch (...)
    {
      errors.push_back("exception in the Init function of system plugin [" + entry.first +
                       "]: " + Describe(std::current_exception()) + "; this plugin will not run");
    }
  }
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  this->systemPlugins.swap(kept);
  return errors;
}

void Host::WorldCreated()
{
  gazebo::event::Events::worldCreated(this->World()->Name());
}

void Host::RemoveModel(const std::string &_name)
{
  std::vector<gazebo::ModelPlugin::TPtr> dropped;
  std::vector<gazebo::SensorPlugin::TPtr> droppedSensorPlugins;
  {
    std::lock_guard<std::recursive_mutex> lock(this->mutex);
    for (auto it = this->sensorPlugins.begin(); it != this->sensorPlugins.end();)
    {
      if (it->first == _name)
      {
        droppedSensorPlugins.push_back(it->second);
        it = this->sensorPlugins.erase(it);
      }
      else
        ++it;
    }
    for (auto it = this->modelPlugins.begin(); it != this->modelPlugins.end();)
    {
      if (it->first == _name)
      {
        dropped.push_back(it->second);
        it = this->modelPlugins.erase(it);
      }
      else
        ++it;
    }
    this->models.erase(_name);
  }
  // destroyed outside the lock: a plugin's destructor may join its own threads
  dropped.clear();
  droppedSensorPlugins.clear();
  gazebo::sensors::SensorManager::Instance()->RemoveSensors(_name);
}

std::vector<std::string> Host::PluginNames(const std::string &_model) const
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  std::vector<std::string> names;
  for (const auto &entry : this->modelPlugins)
    if (entry.first == _model)
      names.push_back(entry.second->GetHandle());
  for (const auto &entry : this->sensorPlugins)
    if (entry.first == _model)
      names.push_back(entry.second->GetHandle());
  return names;
}

void Host::SetSimTime(int64_t _simTimeNs)
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  this->simTimeNs = _simTimeNs;
}

int64_t Host::SimTimeNs() const
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  return this->simTimeNs;
}

uint32_t Host::Iterations() const
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  return this->iterations;
}

void Host::WorldUpdateBegin(int64_t _simTimeNs)
{
  {
    std::lock_guard<std::recursive_mutex> lock(this->mutex);
    this->simTimeNs = _simTimeNs;
    ++this->iterations;
  }
  gazebo::common::UpdateInfo info;
  {
    std::lock_guard<std::recursive_mutex> lock(this->mutex);
    info.worldName = this->worldName;
  }
  info.simTime = this->World()->SimTime();
  info.realTime = gazebo::common::Time::GetWallTime();
  gazebo::event::Events::worldUpdateBegin(info);
  // then the models' joint controllers, as Gazebo's World::Update runs Model::Update
  for (const auto &model : this->KnownModels())
    model->UpdateControllers();
  gazebo::event::Events::beforePhysicsUpdate(info);
}

void Host::WorldUpdateEnd()
{
  // a joint's effort lasts one step (Gazebo clears its forces after each)
  for (const auto &model : this->KnownModels())
    model->ClearForces();
  gazebo::event::Events::worldUpdateEnd();
  // then the sensors that are due measure and tell their subscribers
  const int64_t now = this->SimTimeNs();
  for (const auto &sensor : gazebo::sensors::SensorManager::Instance()->GetSensors())
    sensor->StepEnded(now);
}

void Host::Reset()
{
  for (const auto &model : this->KnownModels())
    model->Reset();
  std::vector<gazebo::WorldPlugin::TPtr> worldPlugins;
  std::vector<gazebo::ModelPlugin::TPtr> modelPlugins;
  std::vector<gazebo::SensorPlugin::TPtr> sensorPlugins;
  {
    std::lock_guard<std::recursive_mutex> lock(this->mutex);
    worldPlugins = this->worldPlugins;
    for (const auto &entry : this->modelPlugins)
      modelPlugins.push_back(entry.second);
    for (const auto &entry : this->sensorPlugins)
      sensorPlugins.push_back(entry.second);
  }
  for (const auto &plugin : worldPlugins)
    plugin->Reset();
  for (const auto &plugin : modelPlugins)
    plugin->Reset();
  for (const auto &plugin : sensorPlugins)
    plugin->Reset();
  gazebo::event::Events::worldReset();
  gazebo::event::Events::timeReset();
}

void Host::Close()
{
  gazebo::event::Events::stop();
  std::vector<gazebo::WorldPlugin::TPtr> worldPlugins;
  std::vector<std::pair<std::string, gazebo::ModelPlugin::TPtr>> modelPlugins;
  std::vector<std::pair<std::string, gazebo::SensorPlugin::TPtr>> sensorPlugins;
  std::vector<std::pair<std::string, gazebo::SystemPlugin::TPtr>> systemPlugins;
  {
    std::lock_guard<std::recursive_mutex> lock(this->mutex);
    worldPlugins.swap(this->worldPlugins);
    modelPlugins.swap(this->modelPlugins);
    sensorPlugins.swap(this->sensorPlugins);
    systemPlugins.swap(this->systemPlugins);
    this->models.clear();
    this->world.reset();
    this->iterations = 0;
  }
  sensorPlugins.clear();
  modelPlugins.clear();
  worldPlugins.clear();
  systemPlugins.clear();
  gazebo::sensors::SensorManager::Instance()->Clear();
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  this->backend.reset();
}
}  // namespace gazebo_compat

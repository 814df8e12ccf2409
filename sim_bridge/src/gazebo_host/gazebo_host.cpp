// sim_bridge._gazebo_host: Gazebo C++ plugins inside sim_bridge's process.
//
// The Python side (sim_bridge.gazebo_plugins) implements gazebo_compat::Backend over its
// pybullet world by subclassing Backend; this module hands that object to the host library
// (compat/gazebo_dev's gazebo_compat), loads plugins with the <plugin> element turned into a
// real sdformat element tree, and signals the step's events. The events are signalled with
// the interpreter lock released, so that a plugin's ROS threads can call the backend (each
// backend call takes the lock) while the physics thread runs the plugins' callbacks. roscpp
// is initialised here, once, under its own node name, with an AsyncSpinner on the global
// queue, as gazebo_ros's API plugin does.
#include <dlfcn.h>

#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <ros/ros.h>

#include "gazebo_compat/Backend.hh"
#include "gazebo_compat/Host.hh"

namespace py = pybind11;
using gazebo_compat::Backend;
using gazebo_compat::ContactInfo;
using gazebo_compat::Host;
using gazebo_compat::JointInfo;
using gazebo_compat::ModelInfo;
using gazebo_compat::SensorInfo;

namespace
{
class PyBackend : public Backend
{
  public: using Backend::Backend;
  std::string WorldName() override
  { PYBIND11_OVERRIDE_PURE(std::string, Backend, world_name, ); }
  double StepSize() override { PYBIND11_OVERRIDE_PURE(double, Backend, step_size, ); }
  std::vector<std::string> ModelNames() override
  { PYBIND11_OVERRIDE_PURE(std::vector<std::string>, Backend, model_names, ); }
  ModelInfo Describe(const std::string &_model) override
  { PYBIND11_OVERRIDE_PURE(ModelInfo, Backend, describe, _model); }
  std::vector<double> ModelState(const std::string &_model) override
  { PYBIND11_OVERRIDE_PURE(std::vector<double>, Backend, model_state, _model); }
  std::vector<double> LinkState(const std::string &_model, const std::string &_link) override
  { PYBIND11_OVERRIDE_PURE(std::vector<double>, Backend, link_state, _model, _link); }
  void SetModelPose(const std::string &_model, const std::vector<double> &_pose) override
  { PYBIND11_OVERRIDE_PURE(void, Backend, set_model_pose, _model, _pose); }
  void SetModelVelocity(const std::string &_model, const std::vector<double> &_twist) override
  { PYBIND11_OVERRIDE_PURE(void, Backend, set_model_velocity, _model, _twist); }
  void SetLinkVelocity(const std::string &_model, const std::string &_link,
                       const std::vector<double> &_twist) override
  { PYBIND11_OVERRIDE_PURE(void, Backend, set_link_velocity, _model, _link, _twist); }
  void AddLinkWrench(const std::string &_model, const std::string &_link,
                     const std::vector<double> &_wrench, bool _inLinkFrame) override
  { PYBIND11_OVERRIDE_PURE(void, Backend, add_link_wrench, _model, _link, _wrench, _inLinkFrame); }
  void SetGravityMode(const std::string &_model, bool _on) override
  { PYBIND11_OVERRIDE_PURE(void, Backend, set_gravity_mode, _model, _on); }
  std::vector<double> JointState(const std::string &_model, const std::string &_joint) override
  { PYBIND11_OVERRIDE_PURE(std::vector<double>, Backend, joint_state, _model, _joint); }
  void SetJointVelocity(const std::string &_model, const std::string &_joint,
                        double _velocity) override
  { PYBIND11_OVERRIDE_PURE(void, Backend, set_joint_velocity, _model, _joint, _velocity); }
  void SetJointMotor(const std::string &_model, const std::string &_joint, double _velocity,
                     double _maxForce) override
  { PYBIND11_OVERRIDE_PURE(void, Backend, set_joint_motor, _model, _joint, _velocity, _maxForce); }
  void SetJointForce(const std::string &_model, const std::string &_joint, double _force) override
  { PYBIND11_OVERRIDE_PURE(void, Backend, set_joint_force, _model, _joint, _force); }
  std::vector<SensorInfo> Sensors(const std::string &_model) override
  { PYBIND11_OVERRIDE_PURE(std::vector<SensorInfo>, Backend, sensors, _model); }
  std::vector<ContactInfo> SensorContacts(const std::string &_model,
                                          const std::string &_sensor) override
  { PYBIND11_OVERRIDE_PURE(std::vector<ContactInfo>, Backend, sensor_contacts, _model, _sensor); }
  std::vector<double> SensorRanges(const std::string &_model, const std::string &_sensor) override
  { PYBIND11_OVERRIDE_PURE(std::vector<double>, Backend, sensor_ranges, _model, _sensor); }
  std::vector<double> SensorImu(const std::string &_model, const std::string &_sensor) override
  { PYBIND11_OVERRIDE_PURE(std::vector<double>, Backend, sensor_imu, _model, _sensor); }
};

// the Python object behind the backend, kept alive while the host uses it
py::object keptBackend;
std::unique_ptr<ros::AsyncSpinner> spinner;
std::unique_ptr<ros::NodeHandle> rosNode;

// (tag, {attribute: value}, text, [children]) → an sdformat element as sdformat's parser
// keeps a <plugin>'s content: every attribute and value a string, parsed by Get<T>()
sdf::ElementPtr Element(const py::handle &_node, sdf::ElementPtr _parent)
{
  auto node = _node.cast<py::tuple>();
  sdf::ElementPtr element(new sdf::Element);
  element->SetName(node[0].cast<std::string>());
  element->SetParent(_parent);
  for (const auto &item : node[1].cast<std::map<std::string, std::string>>())
  {
    element->AddAttribute(item.first, "string", "", false, "");
    element->GetAttribute(item.first)->SetFromString(item.second);
  }
  const auto text = node[2].cast<std::string>();
  auto children = node[3].cast<py::list>();
  if (!text.empty() || children.size() == 0)
    element->AddValue("string", text, false, "");
  for (const auto &child : children)
    element->InsertElement(Element(child, element));
  return element;
}

// the <model> and <world> elements above the plugins' elements, by model ("" the world's):
// an element holds its parent weakly, and plugins read _sdf->GetParent() (Kobuki's its
// model's name) long after they are loaded
std::map<std::string, std::vector<sdf::ElementPtr>> keptParents;

// a <plugin> inside its <model name=...> (plugins read _sdf->GetParent()'s name), or
// inside <world name=...>; the parent kept under _key
sdf::ElementPtr PluginElement(const std::string &_parentTag, const std::string &_parentName,
                              const py::handle &_plugin, const std::string &_key)
{
  sdf::ElementPtr parent(new sdf::Element);
  parent->SetName(_parentTag);
  parent->AddAttribute("name", "string", "", true, "");
  parent->GetAttribute("name")->SetFromString(_parentName);
  sdf::ElementPtr plugin = Element(_plugin, parent);
  parent->InsertElement(plugin);
  keptParents[_key].push_back(parent);
  return plugin;
}

// Gazebo's process has the plugin API, and once gazebo_ros's API plugin is loaded roscpp,
// roslib and tf, in its global symbol scope (it dlopens plugins RTLD_GLOBAL); plugins that
// leave those symbols to the host rely on it (AgileX LIMO's drive uses tf's
// TransformBroadcaster and links only tf2_ros)
void PromoteToGlobal(const char *_library)
{
  dlopen(_library, RTLD_LAZY | RTLD_NOLOAD | RTLD_GLOBAL);
}

// the ':'-separated library files given, opened into the global scope
void OpenGlobally(const std::string &_files)
{
  std::istringstream stream(_files);
  std::string file;
  while (std::getline(stream, file, ':'))
    if (!file.empty() && !dlopen(file.c_str(), RTLD_LAZY | RTLD_GLOBAL))
      gzwarn << "sim_bridge's plugin host: " << dlerror() << "\n";
}

bool InitRos(const std::string &_nodeName)
{
  if (ros::isInitialized())
    return false;
  ros::M_string remappings;
  ros::init(remappings, _nodeName, ros::init_options::NoSigintHandler);
  rosNode.reset(new ros::NodeHandle("~"));
  // one thread per core on the global queue, as gazebo_ros's API plugin runs
  spinner.reset(new ros::AsyncSpinner(0));
  spinner->start();
  return true;
}

void ShutdownRos()
{
  if (spinner)
    spinner->stop();
  spinner.reset();
  rosNode.reset();
  if (ros::isInitialized() && !ros::isShuttingDown())
    ros::shutdown();
}
}  // namespace

PYBIND11_MODULE(_gazebo_host, m)
{
  PromoteToGlobal("libgazebo_compat.so");
  PromoteToGlobal("libroscpp.so");
  OpenGlobally(GAZEBO_ROS_API_PLUGIN_SCOPE);

  py::class_<JointInfo>(m, "JointInfo")
      .def(py::init<>())
      .def_readwrite("name", &JointInfo::name)
      .def_readwrite("type", &JointInfo::type)
      .def_readwrite("parent", &JointInfo::parent)
      .def_readwrite("child", &JointInfo::child)
      .def_readwrite("lower", &JointInfo::lower)
      .def_readwrite("upper", &JointInfo::upper)
      .def_readwrite("effort", &JointInfo::effort)
      .def_readwrite("velocity", &JointInfo::velocity);
  py::class_<ModelInfo>(m, "ModelInfo")
      .def(py::init<>())
      .def_readwrite("links", &ModelInfo::links)
      .def_readwrite("joints", &ModelInfo::joints);
  py::class_<SensorInfo>(m, "SensorInfo")
      .def(py::init<>())
      .def_readwrite("name", &SensorInfo::name)
      .def_readwrite("type", &SensorInfo::type)
      .def_readwrite("link", &SensorInfo::link)
      .def_readwrite("update_rate", &SensorInfo::updateRate)
      .def_readwrite("always_on", &SensorInfo::alwaysOn)
      .def_readwrite("angle_min", &SensorInfo::angleMin)
      .def_readwrite("angle_max", &SensorInfo::angleMax)
      .def_readwrite("samples", &SensorInfo::samples)
      .def_readwrite("range_min", &SensorInfo::rangeMin)
      .def_readwrite("range_max", &SensorInfo::rangeMax);
  py::class_<ContactInfo>(m, "ContactInfo")
      .def(py::init<>())
      .def_readwrite("collision1", &ContactInfo::collision1)
      .def_readwrite("collision2", &ContactInfo::collision2)
      .def_readwrite("positions", &ContactInfo::positions)
      .def_readwrite("normals", &ContactInfo::normals)
      .def_readwrite("depths", &ContactInfo::depths)
      .def_readwrite("forces", &ContactInfo::forces)
      .def_readwrite("torques", &ContactInfo::torques);
  py::class_<Backend, PyBackend, std::shared_ptr<Backend>>(m, "Backend").def(py::init<>());

  m.def("set_backend", [](py::object _backend) {
    keptBackend = _backend;
    Host::Instance().SetBackend(_backend.cast<std::shared_ptr<Backend>>());
  });
  m.def("load_model_plugin", [](const std::string &_model, const std::string &_filename,
                                const std::string &_name, py::handle _plugin) {
    sdf::ElementPtr element = PluginElement("model", _model, _plugin, _model);
    py::gil_scoped_release release;
    return Host::Instance().LoadModelPlugin(_model, _filename, _name, element);
  });
  m.def("load_sensor_plugin", [](const std::string &_model, const std::string &_sensor,
                                 const std::string &_filename, const std::string &_name,
                                 py::handle _plugin) {
    sdf::ElementPtr element = PluginElement("sensor", _sensor, _plugin, _model);
    py::gil_scoped_release release;
    return Host::Instance().LoadSensorPlugin(_model, _sensor, _filename, _name, element);
  });
  m.def("load_world_plugin", [](const std::string &_world, const std::string &_filename,
                                const std::string &_name, py::handle _plugin) {
    sdf::ElementPtr element = PluginElement("world", _world, _plugin, "");
    py::gil_scoped_release release;
    return Host::Instance().LoadWorldPlugin(_filename, _name, element);
  });
  m.def("load_system_plugin", [](const std::string &_filename,
                                 const std::vector<std::string> &_argv) {
    return Host::Instance().LoadSystemPlugin(_filename, _argv);
  }, py::call_guard<py::gil_scoped_release>());
  m.def("init_system_plugins", []() { return Host::Instance().InitSystemPlugins(); },
        py::call_guard<py::gil_scoped_release>());
  m.def("world_created", []() { Host::Instance().WorldCreated(); },
        py::call_guard<py::gil_scoped_release>());
  m.def("plugin_names", [](const std::string &_model) {
    return Host::Instance().PluginNames(_model);
  });
  m.def("remove_model", [](const std::string &_model) {
    {
      py::gil_scoped_release release;
      Host::Instance().RemoveModel(_model);
    }
    keptParents.erase(_model);
  });
  m.def("set_sim_time", [](int64_t _ns) { Host::Instance().SetSimTime(_ns); });
  m.def("world_update_begin", [](int64_t _ns) { Host::Instance().WorldUpdateBegin(_ns); },
        py::call_guard<py::gil_scoped_release>());
  m.def("world_update_end", []() { Host::Instance().WorldUpdateEnd(); },
        py::call_guard<py::gil_scoped_release>());
  m.def("reset", []() { Host::Instance().Reset(); }, py::call_guard<py::gil_scoped_release>());
  m.def("close", []() {
    {
      py::gil_scoped_release release;
      Host::Instance().Close();
    }
    keptParents.clear();
    keptBackend = py::object();
  });
  m.def("plugin_path", []() { return Host::PluginPath(); });
  m.def("init_ros", &InitRos, py::call_guard<py::gil_scoped_release>());
  m.def("shutdown_ros", &ShutdownRos, py::call_guard<py::gil_scoped_release>());
  m.def("ros_initialized", []() { return ros::isInitialized(); });
}

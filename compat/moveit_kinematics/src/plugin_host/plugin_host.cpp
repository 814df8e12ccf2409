// moveit_kinematics._plugin_host: MoveIt's C++ kinematics plugins (kinematics::KinematicsBase, loaded through
// pluginlib) inside the Python move_group's process.
//
// What MoveIt's move_group does with a kinematics.yaml entry (kinematics_plugin_loader.cpp on noetic-devel,
// KinematicsLoaderImpl::allocKinematicsSolver l. 127-209), done here for one group at a time with the C++
// RobotModelLoader's own steps (moveit_ros_planning's library moveit_kinematics_plugin_loader:
// kinematics_plugin_loader::loadKinematicsPlugin, which cites the lines):
// - the process's one pluginlib loader of kinematics::KinematicsBase, createUniqueInstance(lookup name);
// - the robot model built from the URDF and SRDF move_group read (its joint bounds set to the ones move_group plans
//   with: robot_description_planning's joint limits applied, as RobotModelLoader applies them before plugins load);
// - initialize(robot_model, group, base, tips, search_resolution) with base = the parent link of the group's first
//   link (else the model frame) and tips = kinematics_solver_ik_links when given (move_group read them), else the
//   group's last link (chooseTipFrames l. 88-125); when it fails, the string-based initialize;
// - setDefaultTimeout(kinematics_solver_timeout) (l. 189, the group's default IK timeout).
// The plugin reads its own parameters (lookupParam: robot_description_kinematics/<group>/...) through roscpp, which
// this module initialises once per process under its own node name (the rospy node already owns /move_group; a
// second node of that name would make the master shut the first down), in move_group's namespace, without roscpp's
// SIGINT handler (rospy's handles Ctrl-C).
//
// Threads: move_group answers services on several rospy threads. The interpreter lock is released before a solver's
// mutex is taken (a thread holding the lock while it waits for the mutex would block the solution callback of the
// thread that holds the mutex), and taken again only to call the Python solution callback.
#include <moveit/kinematics_base/kinematics_base.h>
#include <moveit/kinematics_plugin_loader/kinematics_plugin_loader.h>
#include <moveit/robot_model/robot_model.h>
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <ros/ros.h>
#include <srdfdom/model.h>
#include <urdf/model.h>

#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace py = pybind11;

namespace
{
std::unique_ptr<ros::NodeHandle> rosNode;
// callbacks a plugin subscribes (tf, topics, timers) run on roscpp's global queue: one thread, as move_group's own
// AsyncSpinner (move_group.cpp l. 206-207 on noetic-devel)
std::unique_ptr<ros::AsyncSpinner> spinner;
const uint32_t SPINNER_THREADS = 1;

// Why a plugin could not be loaded (moveit_kinematics._plugin_host.PluginError in Python). The plugins come from the
// process's one loader (kinematics_plugin_loader::classLoader), never destroyed: Python frees its objects after
// C++'s static destructors ran, and the libraries must stay loaded until then.
using LoadError = kinematics_plugin_loader::PluginLoadError;

bool InitRos(const std::string& node_name, const std::string& ns)
{
  if (ros::isInitialized())
    return false;
  ros::M_string remappings;
  if (!ns.empty())
    remappings["__ns"] = ns;
  ros::init(remappings, node_name, ros::init_options::NoSigintHandler);
  rosNode.reset(new ros::NodeHandle("~"));
  spinner.reset(new ros::AsyncSpinner(SPINNER_THREADS));
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

// geometry_msgs::Pose of (x, y, z, qx, qy, qz, qw)
geometry_msgs::Pose PoseOf(const std::vector<double>& values)
{
  if (values.size() != 7)
    throw std::invalid_argument("a pose is 7 values (x y z qx qy qz qw), not " + std::to_string(values.size()));
  geometry_msgs::Pose pose;
  pose.position.x = values[0];
  pose.position.y = values[1];
  pose.position.z = values[2];
  pose.orientation.x = values[3];
  pose.orientation.y = values[4];
  pose.orientation.z = values[5];
  pose.orientation.w = values[6];
  return pose;
}

std::vector<double> ValuesOf(const geometry_msgs::Pose& pose)
{
  return { pose.position.x,    pose.position.y,    pose.position.z,   pose.orientation.x,
           pose.orientation.y, pose.orientation.z, pose.orientation.w };
}

// A loaded, initialised plugin with the model it was initialised on (the plugin refers to the model, not owning it)
class Solver
{
public:
  Solver(moveit::core::RobotModelPtr model, kinematics::KinematicsBasePtr plugin, std::string lookup_name)
    : model_(std::move(model)), plugin_(std::move(plugin)), lookup_name_(std::move(lookup_name))
  {
  }

  // (solution or None, MoveItErrorCodes value); accept(solution) -> bool is MoveIt's solution callback
  std::pair<std::vector<double>, int> search(const std::vector<double>& pose, const std::vector<double>& seed,
                                             double timeout, const py::object& accept)
  {
    const geometry_msgs::Pose target = PoseOf(pose);
    kinematics::KinematicsBase::IKCallbackFn callback;
    if (!accept.is_none())
      callback = [&accept](const geometry_msgs::Pose&, const std::vector<double>& solution,
                           moveit_msgs::MoveItErrorCodes& code) {
        py::gil_scoped_acquire gil;
        code.val = accept(solution).cast<bool>() ? moveit_msgs::MoveItErrorCodes::SUCCESS :
                                                   moveit_msgs::MoveItErrorCodes::NO_IK_SOLUTION;
      };
    std::vector<double> solution;
    moveit_msgs::MoveItErrorCodes code;
    bool found;
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(mutex_);
      found = callback ? plugin_->searchPositionIK(target, seed, timeout, solution, callback, code) :
                         plugin_->searchPositionIK(target, seed, timeout, solution, code);
    }
    if (!found)
      solution.clear();
    return { solution, code.val };
  }

  // the poses of links (tip frame, links of getLinkNames) in the base frame, or an empty list when FK failed
  std::vector<std::vector<double>> forward(const std::vector<std::string>& links, const std::vector<double>& joints)
  {
    std::vector<geometry_msgs::Pose> poses;
    bool done;
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(mutex_);
      done = plugin_->getPositionFK(links, joints, poses);
    }
    std::vector<std::vector<double>> values;
    if (done)
      for (const auto& pose : poses)
        values.push_back(ValuesOf(pose));
    return values;
  }

  std::vector<std::string> jointNames() const
  {
    return plugin_->getJointNames();
  }
  std::vector<std::string> linkNames() const
  {
    return plugin_->getLinkNames();
  }
  std::string baseFrame() const
  {
    return plugin_->getBaseFrame();
  }
  std::vector<std::string> tipFrames() const
  {
    return plugin_->getTipFrames();
  }
  double defaultTimeout() const
  {
    return plugin_->getDefaultTimeout();
  }
  const std::string& lookupName() const
  {
    return lookup_name_;
  }

private:
  moveit::core::RobotModelPtr model_;
  kinematics::KinematicsBasePtr plugin_;
  std::string lookup_name_;
  std::mutex mutex_;
};

moveit::core::RobotModelPtr BuildModel(const std::string& urdf_text, const std::string& srdf_text,
                                       const std::map<std::string, std::pair<double, double>>& bounds)
{
  auto urdf = std::make_shared<urdf::Model>();
  if (!urdf->initString(urdf_text))
    throw LoadError("the URDF (robot_description) cannot be parsed");
  auto srdf = std::make_shared<srdf::Model>();
  if (!srdf->initString(*urdf, srdf_text))
    throw LoadError("the SRDF (robot_description_semantic) cannot be parsed");
  auto model = std::make_shared<moveit::core::RobotModel>(urdf, srdf);
  for (const auto& entry : bounds)
  {
    moveit::core::JointModel* joint = model->getJointModel(entry.first);
    if (!joint || joint->getVariableCount() != 1)
      continue;
    moveit::core::VariableBounds variable = joint->getVariableBounds()[0];
    variable.position_bounded_ = true;
    variable.min_position_ = entry.second.first;
    variable.max_position_ = entry.second.second;
    joint->setVariableBounds(joint->getVariableNames()[0], variable);
  }
  return model;
}

// The plugin named `lookup_name` for `group`, initialised as MoveIt initialises it; LoadError saying why not
std::shared_ptr<Solver> Load(const std::string& lookup_name, const std::string& urdf_text,
                             const std::string& srdf_text,
                             const std::map<std::string, std::pair<double, double>>& bounds, const std::string& group,
                             const std::vector<std::string>& ik_links, double search_resolution, double timeout,
                             const std::string& robot_description)
{
  py::gil_scoped_release release;
  if (!ros::isInitialized())
    throw LoadError("roscpp is not initialised (call init_ros first): plugins read their parameters through it");
  moveit::core::RobotModelPtr model = BuildModel(urdf_text, srdf_text, bounds);
  const moveit::core::JointModelGroup* jmg = model->getJointModelGroup(group);
  if (!jmg)
    throw LoadError("the robot model has no group '" + group + "'");
  const auto& links = jmg->getLinkModels();
  if (links.empty())
    throw LoadError("group '" + group + "' has no links");
  const std::vector<std::string> tips = ik_links.empty() ? std::vector<std::string>{ links.back()->getName() } :
                                                           ik_links;
  const kinematics::KinematicsBasePtr plugin =
      kinematics_plugin_loader::loadKinematicsPlugin(lookup_name, *jmg, tips, search_resolution, robot_description);
  plugin->setDefaultTimeout(timeout);
  return std::make_shared<Solver>(model, plugin, lookup_name);
}
}  // namespace

PYBIND11_MODULE(_plugin_host, m)
{
  m.doc() = "MoveIt's C++ kinematics plugins (pluginlib, kinematics::KinematicsBase) in move_group's process";
  py::class_<Solver, std::shared_ptr<Solver>>(m, "Solver")
      .def("search", &Solver::search, py::arg("pose"), py::arg("seed"), py::arg("timeout"),
           py::arg("accept") = py::none())
      .def("forward", &Solver::forward)
      .def_property_readonly("joint_names", &Solver::jointNames)
      .def_property_readonly("link_names", &Solver::linkNames)
      .def_property_readonly("base_frame", &Solver::baseFrame)
      .def_property_readonly("tip_frames", &Solver::tipFrames)
      .def_property_readonly("default_timeout", &Solver::defaultTimeout)
      .def_property_readonly("lookup_name", &Solver::lookupName);
  py::register_exception<LoadError>(m, "PluginError");
  m.def("init_ros", &InitRos, py::arg("node_name"), py::arg("namespace") = "");
  m.def("shutdown_ros", &ShutdownRos);
  m.def("load", &Load, py::arg("lookup_name"), py::arg("urdf"), py::arg("srdf"), py::arg("bounds"), py::arg("group"),
        py::arg("ik_links"), py::arg("search_resolution"), py::arg("timeout"),
        py::arg("robot_description") = "robot_description");
}

// kinematics_plugin_loader::KinematicsPluginLoader: the groups' kinematics.yaml entries from the parameter server and
// their plugins through pluginlib, as MoveIt's kinematics_plugin_loader.cpp (noetic-devel) reads and loads them (the
// lines are cited where each step is done).
#include <moveit/kinematics_plugin_loader/kinematics_plugin_loader.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <mutex>
#include <set>
#include <sstream>

#include <ros/ros.h>
#include <urdf/model.h>

namespace kinematics_plugin_loader
{
namespace
{
const char LOGNAME[] = "kinematics_plugin_loader";
// pluginlib's names of the base class and of the package whose plugins export it (kinematics_plugin_loader.cpp l. 74)
const char BASE_PACKAGE[] = "moveit_core";
const char BASE_CLASS[] = "kinematics::KinematicsBase";
// MoveIt's own solvers: no C++ library of theirs is built here (see the header)
const char* const BUILT_IN_SOLVERS[] = { "kdl_kinematics_plugin/KDLKinematicsPlugin",
                                         "lma_kinematics_plugin/LMAKinematicsPlugin",
                                         "cached_ik_kinematics_plugin/CachedKDLKinematicsPlugin",
                                         "srv_kinematics_plugin/SrvKinematicsPlugin",
                                         "trac_ik_kinematics_plugin/TRAC_IKKinematicsPlugin" };

std::string stripSlash(const std::string& frame)
{
  return !frame.empty() && frame[0] == '/' ? frame.substr(1) : frame;
}

// A parameter given as a double or an int (kinematics_plugin_loader.cpp l. 338-346, 375-384)
bool getNumber(const ros::NodeHandle& nh, const std::string& name, double& value)
{
  if (nh.getParam(name, value))
    return true;
  int whole;
  if (!nh.getParam(name, whole))
    return false;
  value = whole;
  return true;
}
}  // namespace

pluginlib::ClassLoader<kinematics::KinematicsBase>& classLoader()
{
  static auto* loader = new pluginlib::ClassLoader<kinematics::KinematicsBase>(BASE_PACKAGE, BASE_CLASS);
  return *loader;
}

bool isBuiltInSolverName(const std::string& lookup_name)
{
  return std::find(std::begin(BUILT_IN_SOLVERS), std::end(BUILT_IN_SOLVERS), lookup_name) != std::end(BUILT_IN_SOLVERS);
}

std::string solverBaseFrame(const moveit::core::JointModelGroup& jmg)
{
  const moveit::core::LinkModel* parent = jmg.getLinkModels().front()->getParentJointModel()->getParentLinkModel();
  return stripSlash(parent ? parent->getName() : jmg.getParentModel().getModelFrame());
}

kinematics::KinematicsBasePtr loadKinematicsPlugin(const std::string& lookup_name,
                                                   const moveit::core::JointModelGroup& jmg,
                                                   const std::vector<std::string>& tips, double search_resolution,
                                                   const std::string& robot_description)
{
  const std::string& group = jmg.getName();
  if (jmg.getLinkModels().empty())
    throw PluginLoadError("group '" + group + "' has no links");
  if (tips.empty())
    throw PluginLoadError("no tip frame chosen for group '" + group + "'");
  const std::string base = solverBaseFrame(jmg);

  // pluginlib's loader is not thread-safe; MoveIt takes a lock around it too (l. 162-163)
  static std::mutex loader_mutex;
  std::lock_guard<std::mutex> lock(loader_mutex);
  pluginlib::ClassLoader<kinematics::KinematicsBase>& loader = classLoader();
  if (!loader.isClassAvailable(lookup_name))
  {
    std::string known;
    for (const auto& name : loader.getDeclaredClasses())
      known += (known.empty() ? "" : ", ") + name;
    throw PluginLoadError("pluginlib knows no plugin '" + lookup_name + "' of base class " + BASE_CLASS +
                          " (declared: " + (known.empty() ? "none" : known) + ")");
  }
  kinematics::KinematicsBasePtr plugin;
  try
  {
    plugin = loader.createUniqueInstance(lookup_name);
  }
  catch (const pluginlib::PluginlibException& e)
  {
    throw PluginLoadError(std::string("pluginlib could not create it: ") + e.what());
  }
  bool initialized = false;
  try
  {
    initialized = plugin->initialize(jmg.getParentModel(), group, base, tips, search_resolution);
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
    if (!initialized)
      initialized = plugin->initialize(robot_description, group, base, tips, search_resolution);
#pragma GCC diagnostic pop
  }
  catch (const std::exception& e)
  {
    throw PluginLoadError(std::string("its initialize() threw: ") + e.what());
  }
  if (!initialized)
    throw PluginLoadError("its initialize() returned false for group '" + group + "' (base '" + base + "', tip '" +
                          tips.front() + "')");
  return plugin;
}

class KinematicsPluginLoader::KinematicsLoaderImpl
{
public:
  KinematicsLoaderImpl(std::string robot_description, std::map<std::string, std::vector<std::string>> solvers,
                       std::map<std::string, std::vector<double>> search_res,
                       std::map<std::string, std::vector<std::string>> tip_links)
    : robot_description_(std::move(robot_description))
    , solvers_(std::move(solvers))
    , search_res_(std::move(search_res))
    , tip_links_(std::move(tip_links))
  {
  }

  // kinematics_solver_ik_links when given, else the group's last link (chooseTipFrames, l. 88-125)
  std::vector<std::string> chooseTipFrames(const moveit::core::JointModelGroup& jmg) const
  {
    const auto it = tip_links_.find(jmg.getName());
    if (it != tip_links_.end())
      return it->second;
    return { jmg.getLinkModels().back()->getName() };
  }

  // The first of the group's solvers that loads (l. 127-209); null when none does (each reason logged once)
  kinematics::KinematicsBasePtr allocKinematicsSolver(const moveit::core::JointModelGroup* jmg)
  {
    kinematics::KinematicsBasePtr result;
    if (!jmg)
    {
      ROS_ERROR_NAMED(LOGNAME, "Specified group is NULL. Cannot allocate kinematics solver.");
      return result;
    }
    const auto it = solvers_.find(jmg->getName());
    if (it == solvers_.end())
      return result;
    const bool first_time = reported_.insert(jmg->getName()).second;
    const std::vector<std::string> tips = chooseTipFrames(*jmg);
    for (std::size_t i = 0; !result && i < it->second.size(); ++i)
    {
      const std::string& name = it->second[i];
      if (isBuiltInSolverName(name))
      {
        if (first_time)
          ROS_INFO_NAMED(LOGNAME,
                         "group '%s': kinematics solver '%s' is answered by RobotState's KDL solver (no C++ "
                         "library of MoveIt's own solvers here)",
                         jmg->getName().c_str(), name.c_str());
        continue;
      }
      const double search_res = search_res_.at(jmg->getName())[i];
      try
      {
        result = loadKinematicsPlugin(name, *jmg, tips, search_res, robot_description_);
      }
      catch (const PluginLoadError& e)
      {
        if (first_time)
          ROS_ERROR_NAMED(LOGNAME, "group '%s': kinematics solver '%s' could not be loaded: %s; solving with KDL "
                                   "instead",
                          jmg->getName().c_str(), name.c_str(), e.what());
        continue;
      }
      // the group's default IK timeout (l. 189); RobotModelLoader then sets kinematics_solver_timeout
      result->setDefaultTimeout(jmg->getDefaultIKTimeout());
      if (first_time)
        ROS_INFO_NAMED(LOGNAME,
                       "group '%s': kinematics solver '%s' loaded (C++ plugin through pluginlib; base '%s', tip "
                       "'%s', search resolution %g)",
                       jmg->getName().c_str(), name.c_str(), result->getBaseFrame().c_str(),
                       result->getTipFrame().c_str(), search_res);
    }
    return result;
  }

  // One instance per group, handed on once: RobotModelLoader allocates one to check it supports the group, and
  // JointModelGroup::setSolverAllocators takes that same one (l. 211-224)
  kinematics::KinematicsBasePtr allocKinematicsSolverWithCache(const moveit::core::JointModelGroup* jmg)
  {
    std::lock_guard<std::mutex> lock(cache_mutex_);
    kinematics::KinematicsBasePtr& cached = instances_[jmg];
    if (cached && cached.use_count() == 1)
      return std::move(cached);
    cached = allocKinematicsSolver(jmg);
    return cached;
  }

  void status() const
  {
    for (const auto& entry : solvers_)
      for (std::size_t i = 0; i < entry.second.size(); ++i)
        ROS_INFO_NAMED(LOGNAME, "Solver for group '%s': '%s' (search resolution = %lf)", entry.first.c_str(),
                       entry.second[i].c_str(), search_res_.at(entry.first)[i]);
  }

private:
  std::string robot_description_;
  std::map<std::string, std::vector<std::string>> solvers_;
  std::map<std::string, std::vector<double>> search_res_;
  std::map<std::string, std::vector<std::string>> tip_links_;
  std::map<const moveit::core::JointModelGroup*, kinematics::KinematicsBasePtr> instances_;
  std::set<std::string> reported_;
  std::mutex cache_mutex_;
};

KinematicsPluginLoader::~KinematicsPluginLoader() = default;

void KinematicsPluginLoader::status() const
{
  if (loader_)
    loader_->status();
  else
    ROS_INFO_NAMED(LOGNAME, "Loader function was never required");
}

moveit::core::SolverAllocatorFn KinematicsPluginLoader::getLoaderFunction()
{
  if (!loader_)
  {
    // the SRDF from <robot_description>_semantic, searched as rdf_loader searches it
    ros::NodeHandle nh("~");
    std::string urdf_param, urdf_string, srdf_string;
    auto srdf = std::make_shared<srdf::Model>();
    urdf::Model urdf;
    if (!nh.searchParam(robot_description_, urdf_param) || !nh.getParam(urdf_param, urdf_string) ||
        !urdf.initString(urdf_string) || !nh.getParam(urdf_param + "_semantic", srdf_string) ||
        !srdf->initString(urdf, srdf_string))
    {
      ROS_ERROR_NAMED(LOGNAME, "Unable to read the URDF and SRDF from '%s' and '%s_semantic'",
                      robot_description_.c_str(), robot_description_.c_str());
      srdf.reset();
    }
    else
      robot_description_ = urdf_param;
    return getLoaderFunction(srdf);
  }
  std::shared_ptr<KinematicsLoaderImpl> loader = loader_;
  return [loader](const moveit::core::JointModelGroup* jmg) { return loader->allocKinematicsSolverWithCache(jmg); };
}

moveit::core::SolverAllocatorFn KinematicsPluginLoader::getLoaderFunction(const srdf::ModelSharedPtr& srdf_model)
{
  if (!loader_)
  {
    groups_.clear();
    std::map<std::string, std::vector<std::string>> solvers;
    std::map<std::string, std::vector<double>> search_res;
    std::map<std::string, std::vector<std::string>> tip_links;
    // the parameters and the plugins' own lookupParam need roscpp; upstream would abort in ros::NodeHandle
    const bool have_ros = ros::isInitialized();
    if (srdf_model && !have_ros)
      ROS_ERROR_NAMED(LOGNAME, "No kinematics plugins loaded: reading robot_description_kinematics needs roscpp "
                               "(call ros::init first)");
    if (srdf_model && have_ros)
    {
      // no resolution given: KinematicsBase's default (l. 287-288)
      if (default_search_resolution_ <= std::numeric_limits<double>::epsilon())
        default_search_resolution_ = kinematics::KinematicsBase::DEFAULT_SEARCH_DISCRETIZATION;
      for (const srdf::Model::Group& group : srdf_model->getGroups())
      {
        if (!default_solver_plugin_.empty())
        {
          // one solver for every group (l. 435-445)
          solvers[group.name_].assign(1, default_solver_plugin_);
          search_res[group.name_].assign(1, default_search_resolution_);
          ik_timeout_[group.name_] = default_solver_timeout_;
          groups_.push_back(group.name_);
          continue;
        }
        readGroupParameters(group.name_, solvers, search_res, tip_links);
      }
    }
    loader_ = std::make_shared<KinematicsLoaderImpl>(robot_description_, solvers, search_res, tip_links);
  }
  std::shared_ptr<KinematicsLoaderImpl> loader = loader_;
  return [loader](const moveit::core::JointModelGroup* jmg) { return loader->allocKinematicsSolverWithCache(jmg); };
}

void KinematicsPluginLoader::readGroupParameters(const std::string& group,
                                                 std::map<std::string, std::vector<std::string>>& solvers,
                                                 std::map<std::string, std::vector<double>>& search_res,
                                                 std::map<std::string, std::vector<std::string>>& tip_links)
{
  // <group>/... found from the private namespace up, else <robot_description>_kinematics/<group>/... (l. 298-310)
  ros::NodeHandle nh("~");
  std::string base = group;
  std::string found_name;
  bool found = nh.searchParam(base + "/kinematics_solver", found_name);
  if (!found || !nh.hasParam(found_name))
  {
    base = robot_description_ + "_kinematics/" + group;
    found = nh.searchParam(base + "/kinematics_solver", found_name);
  }
  std::string names;
  if (found && nh.getParam(found_name, names))
  {
    // several solvers may be named, separated by spaces: the first that loads is used (l. 315-331)
    std::stringstream words(names);
    std::string name;
    while (words >> name)
      solvers[group].push_back(name);
    if (!solvers[group].empty())
      groups_.push_back(group);
  }

  std::string param;
  double number;
  if (nh.searchParam(base + "/kinematics_solver_timeout", param) && getNumber(nh, param, number))
    ik_timeout_[group] = number;

  if (nh.searchParam(base + "/kinematics_solver_attempts", param) && nh.hasParam(param))
    ROS_WARN_ONCE_NAMED(LOGNAME,
                        "Kinematics solver doesn't support #attempts anymore, but only a timeout.\n"
                        "Please remove the parameter '%s' from your configuration.",
                        param.c_str());

  // one resolution per solver, as a string of numbers or a single number (l. 360-386)
  if (nh.searchParam(base + "/kinematics_solver_search_resolution", param))
  {
    std::string text;
    if (nh.getParam(param, text))
    {
      std::stringstream values(text);
      double value;
      while (values >> value)
        search_res[group].push_back(value);
    }
    else if (getNumber(nh, param, number))
      search_res[group].push_back(number);
  }

  // the solver's tips: the deprecated single link, then the list (l. 388-427)
  std::string link;
  if (nh.searchParam(base + "/kinematics_solver_ik_link", param) && nh.getParam(param, link))
  {
    ROS_WARN_STREAM_NAMED(LOGNAME, "Using kinematics_solver_ik_link rosparam is deprecated in favor of "
                                   "kinematics_solver_ik_links rosparam array.");
    tip_links[group].push_back(link);
  }
  XmlRpc::XmlRpcValue links;
  if (nh.searchParam(base + "/kinematics_solver_ik_links", param) && nh.getParam(param, links))
  {
    if (links.getType() != XmlRpc::XmlRpcValue::TypeArray)
      ROS_WARN_STREAM_NAMED(LOGNAME, "rosparam '" << param << "' should be an XmlRpc value type 'Array'");
    else
      for (int i = 0; i < links.size(); ++i)
      {
        if (links[i].getType() != XmlRpc::XmlRpcValue::TypeString)
        {
          ROS_ERROR_STREAM_NAMED(LOGNAME, "rosparam '" << param << "' holds a value that is not a link name");
          continue;
        }
        tip_links[group].push_back(static_cast<std::string>(links[i]));
      }
  }

  // every solver has a resolution (l. 429-432)
  while (search_res[group].size() < solvers[group].size())
    search_res[group].push_back(default_search_resolution_);
}
}  // namespace kinematics_plugin_loader

// kinematics_plugin_loader::KinematicsPluginLoader (MoveIt noetic-devel moveit_ros/planning/kinematics_plugin_loader/
// include/moveit/kinematics_plugin_loader/kinematics_plugin_loader.h), the workspace's own implementation, in the
// library moveit_kinematics_plugin_loader (upstream's name).
//
// Provided: both constructors, getLoaderFunction() and getLoaderFunction(srdf), getKnownGroups(), getIKTimeout(),
// status(): each SRDF group's <robot_description>_kinematics/<group>/{kinematics_solver, kinematics_solver_timeout,
// kinematics_solver_search_resolution, kinematics_solver_ik_link(s)} read from the node's private namespace with
// searchParam (kinematics_plugin_loader.cpp l. 284-433), the solver created through pluginlib and initialised as
// allocKinematicsSolver does (l. 127-209), one instance per group handed on once (allocKinematicsSolverWithCache,
// l. 214-224).
// Differences, because this workspace has no C++ KDL library: MoveIt's own solver names (KDLKinematicsPlugin,
// LMAKinematicsPlugin, CachedKDLKinematicsPlugin, SrvKinematicsPlugin, TRAC_IKKinematicsPlugin: see
// isBuiltInSolverName) allocate no solver: RobotState::setFromIK answers such groups with its own KDL solver
// (Orocos KDL's LMA; TRAC-IK's solve_type is not honoured there). A plugin that cannot be loaded is logged with the
// reason, and its group is answered by that KDL solver too (upstream it would have no solver at all).
//
// Also here, shared with moveit_kinematics' plugin host (the Python move_group's C++ plugins): classLoader(), one
// pluginlib loader for the process, never destroyed; solverBaseFrame(); loadKinematicsPlugin(), which creates and
// initialises one plugin or throws PluginLoadError saying why.
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <moveit/kinematics_base/kinematics_base.h>
#include <moveit/macros/class_forward.h>
#include <moveit/robot_model/robot_model.h>
#include <pluginlib/class_loader.hpp>
#include <srdfdom/model.h>

namespace kinematics_plugin_loader
{
MOVEIT_CLASS_FORWARD(KinematicsPluginLoader);

class KinematicsPluginLoader
{
public:
  /// Solvers named by the parameter server (see the file's comment)
  KinematicsPluginLoader(const std::string& robot_description = "robot_description",
                         double default_search_resolution = 0.0)
    : robot_description_(robot_description), default_search_resolution_(default_search_resolution)
  {
  }

  /// @e solver_plugin for every group, @e solve_timeout its default IK timeout (the attempts are ignored upstream too)
  KinematicsPluginLoader(const std::string& solver_plugin, double solve_timeout, unsigned int /* ik_attempts */,
                         const std::string& robot_description = "robot_description",
                         double default_search_resolution = 0.0)
    : robot_description_(robot_description)
    , default_search_resolution_(default_search_resolution)
    , default_solver_plugin_(solver_plugin)
    , default_solver_timeout_(solve_timeout)
  {
  }
  ~KinematicsPluginLoader();

  /// The allocator; reads the SRDF from <robot_description>_semantic the first time
  moveit::core::SolverAllocatorFn getLoaderFunction();
  /// The allocator; reads the groups' parameters the first time
  moveit::core::SolverAllocatorFn getLoaderFunction(const srdf::ModelSharedPtr& srdf_model);

  /// The groups that name a solver
  const std::vector<std::string>& getKnownGroups() const
  {
    return groups_;
  }
  /// Each group's kinematics_solver_timeout
  const std::map<std::string, double>& getIKTimeout() const
  {
    return ik_timeout_;
  }
  /// Logs each group's solver and search resolution
  void status() const;

private:
  class KinematicsLoaderImpl;
  /// One group's kinematics.yaml entry from the parameter server (kinematics_plugin_loader.cpp l. 298-432)
  void readGroupParameters(const std::string& group, std::map<std::string, std::vector<std::string>>& solvers,
                           std::map<std::string, std::vector<double>>& search_res,
                           std::map<std::string, std::vector<std::string>>& tip_links);
  std::string robot_description_;
  double default_search_resolution_;
  std::shared_ptr<KinematicsLoaderImpl> loader_;
  std::vector<std::string> groups_;
  std::map<std::string, double> ik_timeout_;
  std::string default_solver_plugin_;
  double default_solver_timeout_ = 0.0;
};

/// Why a plugin could not be created or initialised
class PluginLoadError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// pluginlib's loader of kinematics::KinematicsBase plugins (package moveit_core), one for the process. Never
/// destroyed: a plugin's library must stay loaded as long as any solver made from it lives, and solvers outlive the
/// RobotModelLoader that made them whenever a caller keeps the model (upstream works around this in
/// ~RobotModelLoader, robot_model_loader.cpp l. 60-67, only for the model it owns).
pluginlib::ClassLoader<kinematics::KinematicsBase>& classLoader();

/// Names of MoveIt's own solvers, which this workspace answers with its KDL solvers instead of a C++ plugin
bool isBuiltInSolverName(const std::string& lookup_name);

/// The frame a group's solver works in: the parent link of the group's first link, else the model frame, without a
/// leading '/' (kinematics_plugin_loader.cpp l. 158-160, 177-178)
std::string solverBaseFrame(const moveit::core::JointModelGroup& jmg);

/// The plugin @e lookup_name created through classLoader() and initialised for @e jmg as allocKinematicsSolver does
/// (l. 168-189): initialize(model, group, base, tips, search_resolution), else the deprecated string-based initialize
/// with @e robot_description. Throws PluginLoadError saying why not. The default timeout is left to the caller.
kinematics::KinematicsBasePtr loadKinematicsPlugin(const std::string& lookup_name,
                                                   const moveit::core::JointModelGroup& jmg,
                                                   const std::vector<std::string>& tips, double search_resolution,
                                                   const std::string& robot_description);
}  // namespace kinematics_plugin_loader

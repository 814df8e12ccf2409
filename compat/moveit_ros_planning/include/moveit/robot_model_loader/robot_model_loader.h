// robot_model_loader::RobotModelLoader (MoveIt noetic-devel moveit_ros/planning/robot_model_loader/include/moveit/
// robot_model_loader/robot_model_loader.h), the workspace's own implementation.
//
// Provided: the model from the parameter server: the URDF from <robot_description>, the SRDF from
// <robot_description>_semantic (both searched as MoveIt's rdf_loader searches them: ros::NodeHandle::searchParam from
// the node's private namespace), joint limits from <robot_description>_planning/joint_limits/<joint>/
// {has_,}{max_velocity,max_acceleration,min_position,max_position}, as robot_model_loader.cpp (l. 130-198) applies
// them; or from URDF and SRDF strings (Options). getModel(), getRobotDescription(), getURDF(), getSRDF().
// An absent or unparsable URDF gives a ROS error naming its parameter and a null getModel(); an absent or unparsable
// SRDF gives a ROS error naming its parameter and a model without groups, as MoveIt builds it then
// (robot_model_loader.cpp l. 98-103).
// Kinematics solvers (load_kinematics_solvers_, the default): loadKinematicsSolvers() as robot_model_loader.cpp
// l. 169-232 does it: a kinematics_plugin_loader::KinematicsPluginLoader reads each group's
// <robot_description>_kinematics/<group>/kinematics_solver and loads that plugin through pluginlib, the groups whose
// solver supports them get it (JointModelGroup::getSolverInstance), and kinematics_solver_timeout becomes the group's
// default IK timeout. MoveIt's own solver names (KDL, LMA, cached, service, TRAC-IK) load no C++ plugin here: there
// is no C++ library of them in this workspace, and RobotState::setFromIK answers their groups with its KDL solver;
// so it does for a group whose plugin could not be loaded (the reason is logged).
// Not provided: getRDFLoader() (moveit/rdf_loader is not here).
#pragma once

#include <string>

#include <moveit/kinematics_plugin_loader/kinematics_plugin_loader.h>
#include <moveit/macros/class_forward.h>
#include <moveit/robot_model/robot_model.h>
#include <srdfdom/model.h>
#include <urdf_model/model.h>

namespace robot_model_loader
{
MOVEIT_CLASS_FORWARD(RobotModelLoader);

class RobotModelLoader
{
public:
  struct Options
  {
    Options(const std::string& robot_description = "robot_description")
      : robot_description_(robot_description), load_kinematics_solvers_(true)
    {
    }
    Options(const std::string& urdf_string, const std::string& srdf_string)
      : urdf_string_(urdf_string), srdf_string_(srdf_string), load_kinematics_solvers_(true)
    {
    }

    /// The parameter holding the URDF; "<name>_semantic" holds the SRDF, "<name>_planning" the joint limits
    std::string robot_description_;
    /// Documents given directly (used when robot_description_ is empty)
    std::string urdf_string_, srdf_string_;
    bool load_kinematics_solvers_;
  };

  RobotModelLoader(const Options& opt = Options());
  RobotModelLoader(const std::string& robot_description, bool load_kinematics_solvers = true);
  ~RobotModelLoader();

  /// The model; null when it could not be built (the reason was logged)
  const moveit::core::RobotModelPtr& getModel() const
  {
    return model_;
  }
  const std::string& getRobotDescription() const
  {
    return robot_description_;
  }
  const urdf::ModelInterfaceSharedPtr& getURDF() const
  {
    return urdf_;
  }
  const srdf::ModelSharedPtr& getSRDF() const
  {
    return srdf_;
  }
  /// The loader of the model's kinematics plugins (null until loadKinematicsSolvers ran)
  const kinematics_plugin_loader::KinematicsPluginLoaderPtr& getKinematicsPluginLoader() const
  {
    return kinematics_loader_;
  }
  /// Loads the groups' kinematics solvers into the model (done by the constructors unless load_kinematics_solvers_
  /// is false); @e kloader replaces the loader made from the robot description
  void loadKinematicsSolvers(const kinematics_plugin_loader::KinematicsPluginLoaderPtr& kloader =
                                 kinematics_plugin_loader::KinematicsPluginLoaderPtr());

private:
  void configure(const Options& opt);
  /// robot_description_planning's joint limits onto the model's joints
  void applyPlanningJointLimits(const std::string& planning_namespace);

  moveit::core::RobotModelPtr model_;
  std::string robot_description_;
  urdf::ModelInterfaceSharedPtr urdf_;
  srdf::ModelSharedPtr srdf_;
  kinematics_plugin_loader::KinematicsPluginLoaderPtr kinematics_loader_;
};
}  // namespace robot_model_loader

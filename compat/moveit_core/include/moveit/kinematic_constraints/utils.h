// Helpers that build moveit_msgs::Constraints (MoveIt noetic-devel
// moveit_core/kinematic_constraints/include/moveit/kinematic_constraints/utils.h), the workspace's own implementation.
//
// Provided: mergeConstraints, countIndividualConstraints, constructGoalConstraints (joint-state, pose with scalar or
// per-axis tolerances, orientation, position with or without reference point), resolveConstraintFrames (link-name
// frames kept; a frame the robot does not know: false).
// Not provided: constructConstraints from XmlRpc (moveit_core's kinematic_constraints library with its
// KinematicConstraintSet is not here; move_group (Python) evaluates constraints).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include <geometry_msgs/Point.h>
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/QuaternionStamped.h>
#include <moveit/robot_state/robot_state.h>
#include <moveit_msgs/Constraints.h>

namespace kinematic_constraints
{
/// Both sets of constraints; a joint constrained in both keeps the intersection of the two ranges
moveit_msgs::Constraints mergeConstraints(const moveit_msgs::Constraints& first, const moveit_msgs::Constraints& second);
std::size_t countIndividualConstraints(const moveit_msgs::Constraints& constr);

/// One joint constraint per active joint variable of @e jmg at its value in @e state
moveit_msgs::Constraints constructGoalConstraints(const moveit::core::RobotState& state,
                                                  const moveit::core::JointModelGroup* jmg, double tolerance_below,
                                                  double tolerance_above);
moveit_msgs::Constraints constructGoalConstraints(const moveit::core::RobotState& state,
                                                  const moveit::core::JointModelGroup* jmg,
                                                  double tolerance = std::numeric_limits<double>::epsilon());
/// A position constraint (a sphere of radius tolerance_pos) and an orientation constraint (tolerance_angle on each
/// axis) for @e link_name at @e pose
moveit_msgs::Constraints constructGoalConstraints(const std::string& link_name, const geometry_msgs::PoseStamped& pose,
                                                  double tolerance_pos = 1e-3, double tolerance_angle = 1e-2);
/// A box of the three position tolerances, three orientation tolerances; a tolerance vector of the wrong size gives
/// an empty constraint set and a ROS error
moveit_msgs::Constraints constructGoalConstraints(const std::string& link_name, const geometry_msgs::PoseStamped& pose,
                                                  const std::vector<double>& tolerance_pos,
                                                  const std::vector<double>& tolerance_angle);
moveit_msgs::Constraints constructGoalConstraints(const std::string& link_name,
                                                  const geometry_msgs::QuaternionStamped& quat,
                                                  double tolerance = 1e-2);
moveit_msgs::Constraints constructGoalConstraints(const std::string& link_name,
                                                  const geometry_msgs::Point& reference_point,
                                                  const geometry_msgs::PointStamped& goal_point,
                                                  double tolerance = 1e-3);
moveit_msgs::Constraints constructGoalConstraints(const std::string& link_name,
                                                  const geometry_msgs::PointStamped& goal_point,
                                                  double tolerance = 1e-3);
bool resolveConstraintFrames(const moveit::core::RobotState& state, moveit_msgs::Constraints& constraints);
}  // namespace kinematic_constraints

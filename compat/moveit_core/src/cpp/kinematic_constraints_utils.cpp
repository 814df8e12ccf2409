// Constraint-message helpers (MoveIt noetic-devel moveit_core/kinematic_constraints/src/utils.cpp): the same
// messages for the same arguments: joint constraints of weight 1 per active variable; a pose goal as a sphere of
// radius tolerance_pos centred on the pose (or a box of the three tolerances) plus an orientation constraint; weights 1.
#include <moveit/kinematic_constraints/utils.h>

#include <algorithm>

#include <ros/console.h>
#include <shape_msgs/SolidPrimitive.h>

namespace kinematic_constraints
{
namespace
{
const char LOGNAME[] = "kinematic_constraints";

moveit_msgs::PositionConstraint positionConstraint(const std::string& link_name,
                                                   const geometry_msgs::PoseStamped& pose,
                                                   const shape_msgs::SolidPrimitive& region)
{
  moveit_msgs::PositionConstraint pc;
  pc.header = pose.header;
  pc.link_name = link_name;
  pc.constraint_region.primitives.push_back(region);
  geometry_msgs::Pose centre;
  centre.position = pose.pose.position;
  centre.orientation.w = 1.0;
  pc.constraint_region.primitive_poses.push_back(centre);
  pc.weight = 1.0;
  return pc;
}

moveit_msgs::OrientationConstraint orientationConstraint(const std::string& link_name, const std_msgs::Header& header,
                                                         const geometry_msgs::Quaternion& q, double x, double y,
                                                         double z)
{
  moveit_msgs::OrientationConstraint oc;
  oc.header = header;
  oc.link_name = link_name;
  oc.orientation = q;
  oc.absolute_x_axis_tolerance = x;
  oc.absolute_y_axis_tolerance = y;
  oc.absolute_z_axis_tolerance = z;
  oc.weight = 1.0;
  return oc;
}
}  // namespace

moveit_msgs::Constraints mergeConstraints(const moveit_msgs::Constraints& first, const moveit_msgs::Constraints& second)
{
  moveit_msgs::Constraints r;
  // A joint constrained in both keeps the overlap of the two ranges (or the first's when they do not overlap)
  for (const moveit_msgs::JointConstraint& a : first.joint_constraints)
  {
    moveit_msgs::JointConstraint merged = a;
    for (const moveit_msgs::JointConstraint& b : second.joint_constraints)
      if (a.joint_name == b.joint_name)
      {
        const double low = std::max(a.position - a.tolerance_below, b.position - b.tolerance_below);
        const double high = std::min(a.position + a.tolerance_above, b.position + b.tolerance_above);
        if (low <= high)
        {
          merged.position = std::max(low, std::min(a.position, high));
          merged.tolerance_below = merged.position - low;
          merged.tolerance_above = high - merged.position;
        }
        else
          ROS_ERROR_NAMED(LOGNAME, "Joint constraints on '%s' do not overlap; the first is kept", a.joint_name.c_str());
      }
    r.joint_constraints.push_back(merged);
  }
  for (const moveit_msgs::JointConstraint& b : second.joint_constraints)
  {
    bool seen = false;
    for (const moveit_msgs::JointConstraint& a : first.joint_constraints)
      seen = seen || a.joint_name == b.joint_name;
    if (!seen)
      r.joint_constraints.push_back(b);
  }
  r.position_constraints = first.position_constraints;
  r.position_constraints.insert(r.position_constraints.end(), second.position_constraints.begin(),
                                second.position_constraints.end());
  r.orientation_constraints = first.orientation_constraints;
  r.orientation_constraints.insert(r.orientation_constraints.end(), second.orientation_constraints.begin(),
                                   second.orientation_constraints.end());
  r.visibility_constraints = first.visibility_constraints;
  r.visibility_constraints.insert(r.visibility_constraints.end(), second.visibility_constraints.begin(),
                                  second.visibility_constraints.end());
  return r;
}

std::size_t countIndividualConstraints(const moveit_msgs::Constraints& constr)
{
  return constr.position_constraints.size() + constr.orientation_constraints.size() +
         constr.visibility_constraints.size() + constr.joint_constraints.size();
}

moveit_msgs::Constraints constructGoalConstraints(const moveit::core::RobotState& state,
                                                  const moveit::core::JointModelGroup* jmg, double tolerance_below,
                                                  double tolerance_above)
{
  moveit_msgs::Constraints goal;
  std::vector<double> values;
  state.copyJointGroupPositions(jmg, values);
  goal.joint_constraints.resize(values.size());
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    moveit_msgs::JointConstraint& jc = goal.joint_constraints[i];
    jc.joint_name = jmg->getVariableNames()[i];
    jc.position = values[i];
    jc.tolerance_below = tolerance_below;
    jc.tolerance_above = tolerance_above;
    jc.weight = 1.0;
  }
  return goal;
}

moveit_msgs::Constraints constructGoalConstraints(const moveit::core::RobotState& state,
                                                  const moveit::core::JointModelGroup* jmg, double tolerance)
{
  return constructGoalConstraints(state, jmg, tolerance, tolerance);
}

moveit_msgs::Constraints constructGoalConstraints(const std::string& link_name, const geometry_msgs::PoseStamped& pose,
                                                  double tolerance_pos, double tolerance_angle)
{
  moveit_msgs::Constraints goal;
  shape_msgs::SolidPrimitive sphere;
  sphere.type = shape_msgs::SolidPrimitive::SPHERE;
  sphere.dimensions.push_back(tolerance_pos);
  goal.position_constraints.push_back(positionConstraint(link_name, pose, sphere));
  goal.orientation_constraints.push_back(orientationConstraint(link_name, pose.header, pose.pose.orientation,
                                                               tolerance_angle, tolerance_angle, tolerance_angle));
  return goal;
}

moveit_msgs::Constraints constructGoalConstraints(const std::string& link_name, const geometry_msgs::PoseStamped& pose,
                                                  const std::vector<double>& tolerance_pos,
                                                  const std::vector<double>& tolerance_angle)
{
  if (tolerance_pos.size() != 3 || tolerance_angle.size() != 3)
  {
    ROS_ERROR_NAMED(LOGNAME, "constructGoalConstraints: 3 position and 3 angle tolerances are needed (%zu, %zu given)",
                    tolerance_pos.size(), tolerance_angle.size());
    return moveit_msgs::Constraints();
  }
  moveit_msgs::Constraints goal;
  shape_msgs::SolidPrimitive box;
  box.type = shape_msgs::SolidPrimitive::BOX;
  box.dimensions = tolerance_pos;
  goal.position_constraints.push_back(positionConstraint(link_name, pose, box));
  goal.orientation_constraints.push_back(orientationConstraint(link_name, pose.header, pose.pose.orientation,
                                                               tolerance_angle[0], tolerance_angle[1],
                                                               tolerance_angle[2]));
  return goal;
}

moveit_msgs::Constraints constructGoalConstraints(const std::string& link_name,
                                                  const geometry_msgs::QuaternionStamped& quat, double tolerance)
{
  moveit_msgs::Constraints goal;
  goal.orientation_constraints.push_back(
      orientationConstraint(link_name, quat.header, quat.quaternion, tolerance, tolerance, tolerance));
  return goal;
}

moveit_msgs::Constraints constructGoalConstraints(const std::string& link_name,
                                                  const geometry_msgs::Point& reference_point,
                                                  const geometry_msgs::PointStamped& goal_point, double tolerance)
{
  geometry_msgs::PoseStamped pose;
  pose.header = goal_point.header;
  pose.pose.position = goal_point.point;
  shape_msgs::SolidPrimitive sphere;
  sphere.type = shape_msgs::SolidPrimitive::SPHERE;
  sphere.dimensions.push_back(tolerance);
  moveit_msgs::Constraints goal;
  goal.position_constraints.push_back(positionConstraint(link_name, pose, sphere));
  goal.position_constraints.back().target_point_offset.x = reference_point.x;
  goal.position_constraints.back().target_point_offset.y = reference_point.y;
  goal.position_constraints.back().target_point_offset.z = reference_point.z;
  return goal;
}

moveit_msgs::Constraints constructGoalConstraints(const std::string& link_name,
                                                  const geometry_msgs::PointStamped& goal_point, double tolerance)
{
  return constructGoalConstraints(link_name, geometry_msgs::Point(), goal_point, tolerance);
}

bool resolveConstraintFrames(const moveit::core::RobotState& state, moveit_msgs::Constraints& constraints)
{
  for (const moveit_msgs::PositionConstraint& c : constraints.position_constraints)
    if (!state.knowsFrameTransform(c.link_name))
      return false;
  for (const moveit_msgs::OrientationConstraint& c : constraints.orientation_constraints)
    if (!state.knowsFrameTransform(c.link_name))
      return false;
  return true;
}
}  // namespace kinematic_constraints

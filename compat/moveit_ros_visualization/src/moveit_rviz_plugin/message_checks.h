/* Checks on what the displays receive: a non-finite number (NaN, inf) in a pose, a shape's
 * size or a joint position would reach OGRE's scene nodes; the message (or the part of it)
 * is refused with its reason instead, as rviz's own displays refuse them (validateFloats). */
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <geometry_msgs/Pose.h>
#include <moveit_msgs/CollisionObject.h>
#include <sensor_msgs/JointState.h>

namespace moveit_rviz_plugin
{
inline bool finite(const std::vector<double>& values)
{
  for (double value : values)
    if (!std::isfinite(value))
      return false;
  return true;
}

inline bool finite(const geometry_msgs::Pose& pose)
{
  return finite({ pose.position.x, pose.position.y, pose.position.z, pose.orientation.x, pose.orientation.y,
                  pose.orientation.z, pose.orientation.w });
}

/* Empty when every number of the object is finite, else which part is not. */
inline std::string nonFinitePart(const moveit_msgs::CollisionObject& object)
{
  if (!finite(object.pose))
    return "its pose";
  for (const auto& pose : object.primitive_poses)
    if (!finite(pose))
      return "a primitive's pose";
  for (const auto& primitive : object.primitives)
    if (!finite(std::vector<double>(primitive.dimensions.begin(), primitive.dimensions.end())))
      return "a primitive's dimensions";
  for (const auto& pose : object.mesh_poses)
    if (!finite(pose))
      return "a mesh's pose";
  for (const auto& mesh : object.meshes)
    for (const auto& vertex : mesh.vertices)
      if (!finite({ vertex.x, vertex.y, vertex.z }))
        return "a mesh's vertices";
  for (const auto& pose : object.plane_poses)
    if (!finite(pose))
      return "a plane's pose";
  for (const auto& plane : object.planes)
    if (!finite(std::vector<double>(plane.coef.begin(), plane.coef.end())))
      return "a plane's coefficients";
  return std::string();
}

/* The first joint whose position is not finite, or empty. */
inline std::string nonFiniteJoint(const sensor_msgs::JointState& joints)
{
  for (size_t i = 0; i < joints.name.size() && i < joints.position.size(); ++i)
    if (!std::isfinite(joints.position[i]))
      return joints.name[i];
  return std::string();
}
}  // namespace moveit_rviz_plugin

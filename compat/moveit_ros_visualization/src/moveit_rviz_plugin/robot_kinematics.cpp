/* Forward kinematics on KDL's tree (Segment::pose), the URDF's limits and mimic tags. */
#include "robot_kinematics.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

#include <kdl_parser/kdl_parser.hpp>

namespace moveit_rviz_plugin
{
namespace
{
const int MAX_SUBGROUP_DEPTH = 16;  // SRDF subgroups nest; a cycle must not recurse forever
}

bool RobotKinematics::load(const std::string& urdf_xml, std::string& error)
{
  if (urdf_xml.empty())
  {
    error = "the robot description is empty";
    return false;
  }
  urdf::Model model;
  if (!model.initString(urdf_xml))
  {
    error = "the robot description is not a URDF that urdfdom can read";
    return false;
  }
  KDL::Tree tree;
  if (!kdl_parser::treeFromUrdfModel(model, tree))
  {
    error = "kdl_parser could not build a tree from the robot description";
    return false;
  }
  urdf_ = model;
  tree_ = tree;
  root_link_ = tree_.getRootSegment()->first;
  joint_order_.clear();
  std::function<void(KDL::SegmentMap::const_iterator)> walk = [&](KDL::SegmentMap::const_iterator segment) {
    for (const auto& child : GetTreeElementChildren(segment->second))
    {
      joint_order_.push_back(GetTreeElementSegment(child->second).getJoint().getName());
      walk(child);
    }
  };
  walk(tree_.getRootSegment());
  return true;
}

bool RobotKinematics::isMovable(const std::string& joint) const
{
  auto j = urdf_.getJoint(joint);
  if (!j || j->mimic)
    return false;
  return j->type == urdf::Joint::REVOLUTE || j->type == urdf::Joint::CONTINUOUS ||
         j->type == urdf::Joint::PRISMATIC;
}

double RobotKinematics::defaultPosition(const std::string& joint) const
{
  auto j = urdf_.getJoint(joint);
  if (!j || !j->limits || j->type == urdf::Joint::CONTINUOUS)
    return 0.0;
  // moveit_core/robot_model/src/revolute_joint_model.cpp l. 96-103 (noetic-devel): 0 when
  // within the bounds, else the bounds' middle
  if (j->limits->lower <= 0.0 && 0.0 <= j->limits->upper)
    return 0.0;
  return 0.5 * (j->limits->lower + j->limits->upper);
}

namespace
{
// the extents of a link's collision shapes at their origins (an axis-aligned box around them)
KDL::Vector shapeExtents(const urdf::LinkConstSharedPtr& link)
{
  double high[3] = { 0, 0, 0 }, low[3] = { 0, 0, 0 };
  bool any = false;
  for (const auto& collision : link->collision_array)
  {
    if (!collision || !collision->geometry)
      continue;
    double half[3] = { 0, 0, 0 };
    const urdf::Geometry& geometry = *collision->geometry;
    if (geometry.type == urdf::Geometry::BOX)
    {
      const auto& box = static_cast<const urdf::Box&>(geometry);
      half[0] = box.dim.x / 2;
      half[1] = box.dim.y / 2;
      half[2] = box.dim.z / 2;
    }
    else if (geometry.type == urdf::Geometry::CYLINDER)
    {
      const auto& cylinder = static_cast<const urdf::Cylinder&>(geometry);
      half[0] = half[1] = cylinder.radius;
      half[2] = cylinder.length / 2;
    }
    else if (geometry.type == urdf::Geometry::SPHERE)
      half[0] = half[1] = half[2] = static_cast<const urdf::Sphere&>(geometry).radius;
    else
      continue;
    const urdf::Vector3& at = collision->origin.position;
    const double centre[3] = { at.x, at.y, at.z };
    for (int i = 0; i < 3; ++i)
    {
      high[i] = any ? std::max(high[i], centre[i] + half[i]) : centre[i] + half[i];
      low[i] = any ? std::min(low[i], centre[i] - half[i]) : centre[i] - half[i];
    }
    any = true;
  }
  return KDL::Vector(high[0] - low[0], high[1] - low[1], high[2] - low[2]);
}
}  // namespace

double RobotKinematics::markerSize(const std::string& link_name) const
{
  // moveit_ros/robot_interaction/src/robot_interaction.cpp l. 117-145 (noetic-devel)
  for (auto link = urdf_.getLink(link_name); link;)
  {
    KDL::Vector extents = shapeExtents(link);
    int largest = 0;
    for (int i = 1; i < 3; ++i)
      if (extents[i] > extents[largest])
        largest = i;
    extents[largest] = 0.0;
    const double size = 1.01 * extents.Norm();
    if (size > 0)
      return 2.0 * size;
    if (!link->parent_joint || link->parent_joint->type != urdf::Joint::FIXED)
      break;
    link = urdf_.getLink(link->parent_joint->parent_link_name);
  }
  return 0.0;
}

double RobotKinematics::randomPosition(const std::string& joint, std::mt19937& generator) const
{
  auto j = urdf_.getJoint(joint);
  double low = -M_PI, high = M_PI;
  if (j && j->limits && j->type != urdf::Joint::CONTINUOUS)
  {
    low = j->limits->lower;
    high = j->limits->upper;
  }
  return std::uniform_real_distribution<double>(low, high)(generator);
}

double RobotKinematics::position(const std::string& joint, const JointPositions& positions) const
{
  auto j = urdf_.getJoint(joint);
  if (j && j->mimic)
    return j->mimic->multiplier * position(j->mimic->joint_name, positions) + j->mimic->offset;
  auto found = positions.find(joint);
  return found != positions.end() ? found->second : defaultPosition(joint);
}

void RobotKinematics::addPoses(const KDL::SegmentMap::const_iterator& segment, const KDL::Frame& parent,
                               const JointPositions& positions, LinkPoses& poses) const
{
  for (const auto& child : GetTreeElementChildren(segment->second))
  {
    const KDL::Segment& link = GetTreeElementSegment(child->second);
    KDL::Frame pose = parent * link.pose(position(link.getJoint().getName(), positions));
    poses[child->first] = pose;
    addPoses(child, pose, positions, poses);
  }
}

LinkPoses RobotKinematics::linkPoses(const JointPositions& positions) const
{
  LinkPoses poses;
  if (root_link_.empty())
    return poses;
  poses[root_link_] = KDL::Frame::Identity();
  addPoses(tree_.getRootSegment(), KDL::Frame::Identity(), positions, poses);
  return poses;
}

void RobotKinematics::collectGroupJoints(const SrdfModel& srdf, const std::string& name,
                                         std::vector<std::string>& joints, int depth) const
{
  const SrdfGroup* group = srdf.group(name);
  if (!group || depth > MAX_SUBGROUP_DEPTH)
    return;
  joints.insert(joints.end(), group->joints.begin(), group->joints.end());
  for (const auto& link_name : group->links)
  {
    auto link = urdf_.getLink(link_name);
    if (link && link->parent_joint)
      joints.push_back(link->parent_joint->name);
  }
  for (const auto& chain : group->chains)
  {
    KDL::Chain kdl_chain;
    if (tree_.getChain(chain.first, chain.second, kdl_chain))
      for (const auto& segment : kdl_chain.segments)
        joints.push_back(segment.getJoint().getName());
  }
  for (const auto& subgroup : group->subgroups)
    collectGroupJoints(srdf, subgroup, joints, depth + 1);
}

std::vector<std::string> RobotKinematics::groupJoints(const SrdfModel& srdf, const std::string& group) const
{
  std::vector<std::string> named;
  collectGroupJoints(srdf, group, named, 0);
  std::set<std::string> wanted(named.begin(), named.end());
  std::vector<std::string> joints;
  for (const auto& joint : joint_order_)
    if (wanted.count(joint) && isMovable(joint))
      joints.push_back(joint);
  return joints;
}

std::string RobotKinematics::groupTipLink(const SrdfModel& srdf, const std::string& name) const
{
  const SrdfGroup* group = srdf.group(name);
  if (!group)
    return std::string();
  std::vector<std::string> joints;
  collectGroupJoints(srdf, name, joints, 0);
  std::set<std::string> links;
  for (const auto& joint : joints)
    if (auto j = urdf_.getJoint(joint))
      links.insert(j->child_link_name);
  links.insert(group->links.begin(), group->links.end());
  for (const auto& eef : srdf.end_effectors)
    if (eef.parent_group == name || (eef.parent_group.empty() && links.count(eef.parent_link)))
      return eef.parent_link;
  if (!group->chains.empty())
    return group->chains.back().second;
  for (auto joint = joint_order_.rbegin(); joint != joint_order_.rend(); ++joint)
    if (std::find(joints.begin(), joints.end(), *joint) != joints.end())
      return urdf_.getJoint(*joint)->child_link_name;
  return group->links.empty() ? std::string() : group->links.back();
}
}  // namespace moveit_rviz_plugin

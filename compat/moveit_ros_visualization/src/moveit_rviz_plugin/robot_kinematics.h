/* The robot's forward kinematics for drawing it: the URDF (urdf::Model) and its KDL tree
 * (kdl_parser), link poses relative to the root link from named joint positions (mimic
 * joints follow their leader, as MoveIt's RobotState makes them), and which joints a SRDF
 * group moves. */
#pragma once

#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <kdl/frames.hpp>
#include <kdl/tree.hpp>
#include <urdf/model.h>

#include "srdf_model.h"

namespace moveit_rviz_plugin
{
using JointPositions = std::map<std::string, double>;
using LinkPoses = std::map<std::string, KDL::Frame>;

class RobotKinematics
{
public:
  /* Reads the URDF; false with the reason in `error`. */
  bool load(const std::string& urdf_xml, std::string& error);

  const urdf::Model& urdf() const { return urdf_; }
  const std::string& rootLink() const { return root_link_; }

  /* Every link's pose in the root link's frame. A joint missing from `positions` is at its
   * default (0, or the nearer bound when 0 is outside them: MoveIt's default value). */
  LinkPoses linkPoses(const JointPositions& positions) const;

  /* The movable joints (revolute, continuous, prismatic; mimic joints excluded) of a group,
   * in the tree's order, as SRDF declares it (joints, links' parent joints, chains,
   * subgroups). */
  std::vector<std::string> groupJoints(const SrdfModel& srdf, const std::string& group) const;

  /* The link the group's end-effector marker sits on: the parent link of the group's end
   * effector, else the tip of its chain, else its last joint's child link. */
  std::string groupTipLink(const SrdfModel& srdf, const std::string& group) const;

  /* The goal marker's size for a link (MoveIt's RobotInteraction::computeLinkMarkerSize): twice
   * 1.01 times the norm of the two smaller extents of the link's collision shapes, walking up
   * fixed joints past links without shapes; 0 when none is found. Meshes count as no shape
   * (their extents need the mesh loaded). */
  double markerSize(const std::string& link) const;

  /* A position within the joint's limits (continuous joints: -pi..pi). */
  double randomPosition(const std::string& joint, std::mt19937& generator) const;

  double defaultPosition(const std::string& joint) const;
  bool isMovable(const std::string& joint) const;

private:
  void collectGroupJoints(const SrdfModel& srdf, const std::string& group, std::vector<std::string>& joints,
                          int depth) const;
  void addPoses(const KDL::SegmentMap::const_iterator& segment, const KDL::Frame& parent,
                const JointPositions& positions, LinkPoses& poses) const;
  double position(const std::string& joint, const JointPositions& positions) const;

  urdf::Model urdf_;
  KDL::Tree tree_;
  std::string root_link_;
  std::vector<std::string> joint_order_;  // depth-first, as the tree is walked
};
}  // namespace moveit_rviz_plugin

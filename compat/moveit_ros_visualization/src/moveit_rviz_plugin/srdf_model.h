/* The SRDF as MoveIt's displays need it (srdfdom's reading, on tinyxml2): planning groups
 * (joints, links, chains, subgroups), named group states, end effectors and the virtual
 * joint. Which joints a group moves needs the robot's tree: see RobotKinematics. */
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace moveit_rviz_plugin
{
struct SrdfGroup
{
  std::string name;
  std::vector<std::string> joints;
  std::vector<std::string> links;
  std::vector<std::pair<std::string, std::string>> chains;  // base link, tip link
  std::vector<std::string> subgroups;
};

struct SrdfGroupState
{
  std::string name;
  std::string group;
  std::map<std::string, std::vector<double>> values;  // joint name -> its variables
};

struct SrdfEndEffector
{
  std::string name;
  std::string parent_link;
  std::string group;         // the end effector's own group (the gripper)
  std::string parent_group;  // the arm it ends; empty: the group whose links hold parent_link
};

class SrdfModel
{
public:
  /* Reads an SRDF document; false with the reason in `error` when it is not one. Unknown
   * elements are skipped, as srdfdom skips them. */
  bool parse(const std::string& xml, std::string& error);

  std::vector<SrdfGroup> groups;
  std::vector<SrdfGroupState> group_states;
  std::vector<SrdfEndEffector> end_effectors;
  std::string virtual_joint_parent_frame;  // empty without a virtual joint

  const SrdfGroup* group(const std::string& name) const;
  std::vector<const SrdfGroupState*> statesOf(const std::string& group) const;
};
}  // namespace moveit_rviz_plugin

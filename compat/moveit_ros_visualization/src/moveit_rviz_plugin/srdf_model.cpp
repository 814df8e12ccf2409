/* The SRDF reader: the element and attribute names are srdfdom's (srdfdom/src/model.cpp on
 * noetic-devel: loadGroups, loadGroupStates, loadEndEffectors, loadVirtualJoints). */
#include "srdf_model.h"

#include <sstream>

#include <tinyxml2.h>

namespace moveit_rviz_plugin
{
namespace
{
std::string attribute(const tinyxml2::XMLElement* element, const char* name)
{
  const char* value = element->Attribute(name);
  return value ? std::string(value) : std::string();
}

std::vector<double> numbers(const std::string& text)
{
  std::vector<double> values;
  std::istringstream stream(text);
  double value;
  while (stream >> value)
    values.push_back(value);
  return values;
}
}  // namespace

bool SrdfModel::parse(const std::string& xml, std::string& error)
{
  tinyxml2::XMLDocument document;
  if (document.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS)
  {
    error = std::string("the SRDF is not XML: ") + (document.ErrorStr() ? document.ErrorStr() : "");
    return false;
  }
  const tinyxml2::XMLElement* robot = document.FirstChildElement("robot");
  if (!robot)
  {
    error = "the SRDF has no <robot> element";
    return false;
  }
  groups.clear();
  group_states.clear();
  end_effectors.clear();
  virtual_joint_parent_frame.clear();
  for (auto* g = robot->FirstChildElement("group"); g; g = g->NextSiblingElement("group"))
  {
    SrdfGroup group;
    group.name = attribute(g, "name");
    for (auto* e = g->FirstChildElement(); e; e = e->NextSiblingElement())
    {
      const std::string tag = e->Name();
      if (tag == "joint")
        group.joints.push_back(attribute(e, "name"));
      else if (tag == "link")
        group.links.push_back(attribute(e, "name"));
      else if (tag == "chain")
        group.chains.emplace_back(attribute(e, "base_link"), attribute(e, "tip_link"));
      else if (tag == "group")
        group.subgroups.push_back(attribute(e, "name"));
    }
    if (!group.name.empty())
      groups.push_back(group);
  }
  for (auto* s = robot->FirstChildElement("group_state"); s; s = s->NextSiblingElement("group_state"))
  {
    SrdfGroupState state;
    state.name = attribute(s, "name");
    state.group = attribute(s, "group");
    for (auto* j = s->FirstChildElement("joint"); j; j = j->NextSiblingElement("joint"))
      state.values[attribute(j, "name")] = numbers(attribute(j, "value"));
    group_states.push_back(state);
  }
  for (auto* e = robot->FirstChildElement("end_effector"); e; e = e->NextSiblingElement("end_effector"))
    end_effectors.push_back(
        { attribute(e, "name"), attribute(e, "parent_link"), attribute(e, "group"), attribute(e, "parent_group") });
  if (auto* v = robot->FirstChildElement("virtual_joint"))
    virtual_joint_parent_frame = attribute(v, "parent_frame");
  return true;
}

const SrdfGroup* SrdfModel::group(const std::string& name) const
{
  for (const auto& g : groups)
    if (g.name == name)
      return &g;
  return nullptr;
}

std::vector<const SrdfGroupState*> SrdfModel::statesOf(const std::string& group) const
{
  std::vector<const SrdfGroupState*> states;
  for (const auto& s : group_states)
    if (s.group == group)
      states.push_back(&s);
  return states;
}
}  // namespace moveit_rviz_plugin

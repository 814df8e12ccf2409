// The SRDF reader behind srdf::Model (srdfdom/model.h): tinyxml2, as srdfdom's src/model.cpp (noetic-devel) reads it.
#include <srdfdom/model.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include <ros/console.h>

namespace srdf
{
namespace
{
std::string attribute(const tinyxml2::XMLElement* element, const char* name)
{
  const char* value = element->Attribute(name);
  return value ? std::string(value) : std::string();
}

bool hasLink(const urdf::ModelInterface& urdf_model, const std::string& name)
{
  return static_cast<bool>(urdf_model.getLink(name));
}
}  // namespace

const Model::PropertyMap& Model::getJointProperties(const std::string& joint_name) const
{
  static const PropertyMap empty_map;
  auto it = joint_properties_.find(joint_name);
  return it == joint_properties_.end() ? empty_map : it->second;
}

bool Model::isValidJoint(const urdf::ModelInterface& urdf_model, const std::string& name) const
{
  if (urdf_model.getJoint(name))
    return true;
  for (const VirtualJoint& vj : virtual_joints_)
    if (vj.name_ == name)
      return true;
  return false;
}

void Model::loadVirtualJoints(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* robot_xml)
{
  for (tinyxml2::XMLElement* xml = robot_xml->FirstChildElement("virtual_joint"); xml;
       xml = xml->NextSiblingElement("virtual_joint"))
  {
    VirtualJoint vj;
    vj.name_ = attribute(xml, "name");
    vj.child_link_ = attribute(xml, "child_link");
    vj.parent_frame_ = attribute(xml, "parent_frame");
    vj.type_ = attribute(xml, "type");
    if (vj.name_.empty() || vj.child_link_.empty() || vj.parent_frame_.empty() || vj.type_.empty())
    {
      ROS_ERROR_NAMED("srdf", "A virtual_joint needs name, child_link, parent_frame and type");
      continue;
    }
    std::transform(vj.type_.begin(), vj.type_.end(), vj.type_.begin(), ::tolower);
    if (vj.type_ != "planar" && vj.type_ != "floating" && vj.type_ != "fixed")
    {
      ROS_ERROR_NAMED("srdf", "Unknown type of virtual joint '%s': '%s'", vj.name_.c_str(), vj.type_.c_str());
      continue;
    }
    if (!hasLink(urdf_model, vj.child_link_))
    {
      ROS_ERROR_NAMED("srdf", "Virtual joint '%s' names a child link '%s' the URDF does not have", vj.name_.c_str(),
                      vj.child_link_.c_str());
      continue;
    }
    virtual_joints_.push_back(vj);
  }
}

void Model::loadGroups(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* robot_xml)
{
  for (tinyxml2::XMLElement* group_xml = robot_xml->FirstChildElement("group"); group_xml;
       group_xml = group_xml->NextSiblingElement("group"))
  {
    Group group;
    group.name_ = attribute(group_xml, "name");
    if (group.name_.empty())
    {
      ROS_ERROR_NAMED("srdf", "A group has no name");
      continue;
    }
    for (tinyxml2::XMLElement* link = group_xml->FirstChildElement("link"); link;
         link = link->NextSiblingElement("link"))
    {
      const std::string name = attribute(link, "name");
      if (hasLink(urdf_model, name))
        group.links_.push_back(name);
      else
        ROS_ERROR_NAMED("srdf", "Group '%s' names a link '%s' the URDF does not have", group.name_.c_str(),
                        name.c_str());
    }
    for (tinyxml2::XMLElement* joint = group_xml->FirstChildElement("joint"); joint;
         joint = joint->NextSiblingElement("joint"))
    {
      const std::string name = attribute(joint, "name");
      if (isValidJoint(urdf_model, name))
        group.joints_.push_back(name);
      else
        ROS_ERROR_NAMED("srdf", "Group '%s' names a joint '%s' the robot does not have", group.name_.c_str(),
                        name.c_str());
    }
    for (tinyxml2::XMLElement* chain = group_xml->FirstChildElement("chain"); chain;
         chain = chain->NextSiblingElement("chain"))
    {
      const std::string base = attribute(chain, "base_link");
      const std::string tip = attribute(chain, "tip_link");
      if (hasLink(urdf_model, base) && hasLink(urdf_model, tip))
        group.chains_.emplace_back(base, tip);
      else
        ROS_ERROR_NAMED("srdf", "Group '%s' has a chain from '%s' to '%s' whose links the URDF does not both have",
                        group.name_.c_str(), base.c_str(), tip.c_str());
    }
    for (tinyxml2::XMLElement* sub = group_xml->FirstChildElement("group"); sub; sub = sub->NextSiblingElement("group"))
      group.subgroups_.push_back(attribute(sub, "name"));
    groups_.push_back(group);
  }

  // A subgroup must name a group of the SRDF; a group left with nothing in it is dropped (srdfdom does the same)
  bool removed = true;
  while (removed)
  {
    removed = false;
    std::set<std::string> known;
    for (const Group& group : groups_)
      known.insert(group.name_);
    for (auto it = groups_.begin(); it != groups_.end();)
    {
      std::vector<std::string> kept;
      for (const std::string& sub : it->subgroups_)
        if (known.count(sub))
          kept.push_back(sub);
        else
          ROS_ERROR_NAMED("srdf", "Group '%s' names a subgroup '%s' the SRDF does not define", it->name_.c_str(),
                          sub.c_str());
      it->subgroups_ = kept;
      if (it->joints_.empty() && it->links_.empty() && it->chains_.empty() && it->subgroups_.empty())
      {
        ROS_WARN_NAMED("srdf", "Group '%s' is empty and is left out", it->name_.c_str());
        it = groups_.erase(it);
        removed = true;
      }
      else
        ++it;
    }
  }
}

void Model::loadGroupStates(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* robot_xml)
{
  for (tinyxml2::XMLElement* gs_xml = robot_xml->FirstChildElement("group_state"); gs_xml;
       gs_xml = gs_xml->NextSiblingElement("group_state"))
  {
    GroupState gs;
    gs.name_ = attribute(gs_xml, "name");
    gs.group_ = attribute(gs_xml, "group");
    bool found = false;
    for (const Group& group : groups_)
      found = found || group.name_ == gs.group_;
    if (gs.name_.empty() || !found)
    {
      ROS_ERROR_NAMED("srdf", "group_state '%s' names group '%s' the SRDF does not define", gs.name_.c_str(),
                      gs.group_.c_str());
      continue;
    }
    for (tinyxml2::XMLElement* joint = gs_xml->FirstChildElement("joint"); joint;
         joint = joint->NextSiblingElement("joint"))
    {
      const std::string name = attribute(joint, "name");
      if (!isValidJoint(urdf_model, name))
      {
        ROS_ERROR_NAMED("srdf", "group_state '%s' names a joint '%s' the robot does not have", gs.name_.c_str(),
                        name.c_str());
        continue;
      }
      std::istringstream values(attribute(joint, "value"));
      std::vector<double>& out = gs.joint_values_[name];
      double v;
      while (values >> v)
        out.push_back(v);
      if (out.empty())
      {
        ROS_ERROR_NAMED("srdf", "group_state '%s' gives joint '%s' no value", gs.name_.c_str(), name.c_str());
        gs.joint_values_.erase(name);
      }
    }
    group_states_.push_back(gs);
  }
}

void Model::loadEndEffectors(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* robot_xml)
{
  for (tinyxml2::XMLElement* xml = robot_xml->FirstChildElement("end_effector"); xml;
       xml = xml->NextSiblingElement("end_effector"))
  {
    EndEffector eef;
    eef.name_ = attribute(xml, "name");
    eef.component_group_ = attribute(xml, "group");
    eef.parent_link_ = attribute(xml, "parent_link");
    eef.parent_group_ = attribute(xml, "parent_group");
    bool found = false;
    for (const Group& group : groups_)
      found = found || group.name_ == eef.component_group_;
    if (eef.name_.empty() || !found)
    {
      ROS_ERROR_NAMED("srdf", "end_effector '%s' names group '%s' the SRDF does not define", eef.name_.c_str(),
                      eef.component_group_.c_str());
      continue;
    }
    if (!hasLink(urdf_model, eef.parent_link_))
    {
      ROS_ERROR_NAMED("srdf", "end_effector '%s' names a parent link '%s' the URDF does not have", eef.name_.c_str(),
                      eef.parent_link_.c_str());
      continue;
    }
    end_effectors_.push_back(eef);
  }
}

void Model::loadLinkSphereApproximations(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* robot_xml)
{
  for (tinyxml2::XMLElement* xml = robot_xml->FirstChildElement("link_sphere_approximation"); xml;
       xml = xml->NextSiblingElement("link_sphere_approximation"))
  {
    LinkSpheres link_spheres;
    link_spheres.link_ = attribute(xml, "link");
    if (!hasLink(urdf_model, link_spheres.link_))
      continue;
    for (tinyxml2::XMLElement* sphere_xml = xml->FirstChildElement("sphere"); sphere_xml;
         sphere_xml = sphere_xml->NextSiblingElement("sphere"))
    {
      Sphere sphere{};
      std::istringstream center(attribute(sphere_xml, "center"));
      center >> sphere.center_x_ >> sphere.center_y_ >> sphere.center_z_;
      sphere.radius_ = sphere_xml->DoubleAttribute("radius", -1.0);
      if (!center.fail() && sphere.radius_ > 0.0)
        link_spheres.spheres_.push_back(sphere);
    }
    link_sphere_approximations_.push_back(link_spheres);
  }
}

void Model::loadCollisionDefaults(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* robot_xml)
{
  for (tinyxml2::XMLElement* xml = robot_xml->FirstChildElement("disable_default_collisions"); xml;
       xml = xml->NextSiblingElement("disable_default_collisions"))
  {
    const std::string link = attribute(xml, "link");
    if (hasLink(urdf_model, link))
      no_default_collision_links_.push_back(link);
  }
}

void Model::loadCollisionPairs(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* robot_xml,
                               const char* tag_name, std::vector<CollisionPair>& pairs)
{
  for (tinyxml2::XMLElement* xml = robot_xml->FirstChildElement(tag_name); xml; xml = xml->NextSiblingElement(tag_name))
  {
    CollisionPair pair{ attribute(xml, "link1"), attribute(xml, "link2"), attribute(xml, "reason") };
    if (!hasLink(urdf_model, pair.link1_) || !hasLink(urdf_model, pair.link2_))
    {
      ROS_WARN_NAMED("srdf", "%s names links '%s' and '%s' the URDF does not both have", tag_name,
                     pair.link1_.c_str(), pair.link2_.c_str());
      continue;
    }
    pairs.push_back(pair);
  }
}

void Model::loadPassiveJoints(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* robot_xml)
{
  for (tinyxml2::XMLElement* xml = robot_xml->FirstChildElement("passive_joint"); xml;
       xml = xml->NextSiblingElement("passive_joint"))
  {
    PassiveJoint pj{ attribute(xml, "name") };
    if (isValidJoint(urdf_model, pj.name_))
      passive_joints_.push_back(pj);
    else
      ROS_ERROR_NAMED("srdf", "passive_joint '%s' is not a joint of the robot", pj.name_.c_str());
  }
}

void Model::loadJointProperties(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* robot_xml)
{
  for (tinyxml2::XMLElement* xml = robot_xml->FirstChildElement("joint_property"); xml;
       xml = xml->NextSiblingElement("joint_property"))
  {
    const std::string joint = attribute(xml, "joint_name");
    const std::string property = attribute(xml, "property_name");
    if (isValidJoint(urdf_model, joint) && !property.empty())
      joint_properties_[joint][property] = attribute(xml, "value");
  }
}

bool Model::initXml(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* robot_xml)
{
  clear();
  if (!robot_xml || std::string(robot_xml->Value()) != "robot")
  {
    ROS_ERROR_NAMED("srdf", "The SRDF's root element is not <robot>");
    return false;
  }
  name_ = attribute(robot_xml, "name");
  if (name_ != urdf_model.getName())
    ROS_ERROR_NAMED("srdf", "The SRDF names robot '%s', the URDF '%s'", name_.c_str(), urdf_model.getName().c_str());
  loadVirtualJoints(urdf_model, robot_xml);
  loadGroups(urdf_model, robot_xml);
  loadGroupStates(urdf_model, robot_xml);
  loadEndEffectors(urdf_model, robot_xml);
  loadLinkSphereApproximations(urdf_model, robot_xml);
  loadCollisionDefaults(urdf_model, robot_xml);
  loadCollisionPairs(urdf_model, robot_xml, "enable_collisions", enabled_collision_pairs_);
  loadCollisionPairs(urdf_model, robot_xml, "disable_collisions", disabled_collision_pairs_);
  loadPassiveJoints(urdf_model, robot_xml);
  loadJointProperties(urdf_model, robot_xml);
  return true;
}

bool Model::initXml(const urdf::ModelInterface& urdf_model, tinyxml2::XMLDocument* xml)
{
  tinyxml2::XMLElement* robot_xml = xml ? xml->FirstChildElement("robot") : nullptr;
  if (!robot_xml)
  {
    ROS_ERROR_NAMED("srdf", "The SRDF has no <robot> element");
    return false;
  }
  return initXml(urdf_model, robot_xml);
}

bool Model::initFile(const urdf::ModelInterface& urdf_model, const std::string& filename)
{
  std::ifstream in(filename);
  if (!in)
  {
    ROS_ERROR_NAMED("srdf", "Cannot open SRDF file '%s'", filename.c_str());
    return false;
  }
  std::stringstream content;
  content << in.rdbuf();
  return initString(urdf_model, content.str());
}

bool Model::initString(const urdf::ModelInterface& urdf_model, const std::string& xmlstring)
{
  tinyxml2::XMLDocument xml_doc;
  if (xml_doc.Parse(xmlstring.c_str()) != tinyxml2::XML_SUCCESS)
  {
    ROS_ERROR_NAMED("srdf", "The SRDF is not well-formed XML: %s", xml_doc.ErrorStr());
    return false;
  }
  return initXml(urdf_model, &xml_doc);
}

void Model::clear()
{
  name_.clear();
  groups_.clear();
  group_states_.clear();
  virtual_joints_.clear();
  end_effectors_.clear();
  link_sphere_approximations_.clear();
  no_default_collision_links_.clear();
  enabled_collision_pairs_.clear();
  disabled_collision_pairs_.clear();
  passive_joints_.clear();
  joint_properties_.clear();
}
}  // namespace srdf

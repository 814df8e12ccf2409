// srdf::Model: the robot's semantic description (SRDF) as srdfdom reads it (ros-planning/srdfdom noetic-devel,
// include/srdfdom/model.h). srdfdom is not packaged by Debian; this reader is the workspace's own, on tinyxml2 as
// srdfdom's, with its class, structs and accessors. Provided: groups (joints, links, chains, subgroups), group states,
// end effectors, virtual joints, passive joints, disabled and enabled collision pairs, disable_default_collisions,
// link sphere approximations and joint properties. Not provided: srdf::SRDFWriter (srdfdom/srdf_writer.h).
// Elements naming joints or links the URDF lacks are dropped with a ROS error, as srdfdom drops them
// (srdfdom src/model.cpp, noetic-devel).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <tinyxml2.h>
#include <urdf/model.h>

namespace srdf
{
class Model
{
public:
  using PropertyMap = std::map<std::string, std::string>;
  using JointPropertyMap = std::map<std::string, PropertyMap>;

  Model() = default;
  ~Model() = default;

  bool initXml(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* xml);
  bool initXml(const urdf::ModelInterface& urdf_model, tinyxml2::XMLDocument* xml);
  bool initFile(const urdf::ModelInterface& urdf_model, const std::string& filename);
  bool initString(const urdf::ModelInterface& urdf_model, const std::string& xmlstring);

  /// A planning group: joints, links, base-to-tip chains and other groups, as the SRDF lists them
  struct Group
  {
    std::string name_;
    std::vector<std::string> joints_;
    std::vector<std::string> links_;
    std::vector<std::pair<std::string, std::string>> chains_;
    std::vector<std::string> subgroups_;
  };

  /// The joint between a frame outside the robot (parent_frame_) and the URDF's root link (child_link_)
  struct VirtualJoint
  {
    std::string name_;
    std::string type_;
    std::string parent_frame_;
    std::string child_link_;
  };

  struct EndEffector
  {
    std::string name_;
    std::string parent_link_;
    std::string parent_group_;
    std::string component_group_;
  };

  /// A named configuration of a group: joint name -> its variable values
  struct GroupState
  {
    std::string name_;
    std::string group_;
    std::map<std::string, std::vector<double>> joint_values_;
  };

  struct Sphere
  {
    double center_x_;
    double center_y_;
    double center_z_;
    double radius_;
  };

  struct LinkSpheres
  {
    std::string link_;
    std::vector<Sphere> spheres_;
  };

  struct CollisionPair
  {
    std::string link1_;
    std::string link2_;
    std::string reason_;
  };

  struct PassiveJoint
  {
    std::string name_;
  };

  const std::string& getName() const
  {
    return name_;
  }
  const std::vector<std::string>& getNoDefaultCollisionLinks() const
  {
    return no_default_collision_links_;
  }
  const std::vector<CollisionPair>& getEnabledCollisionPairs() const
  {
    return enabled_collision_pairs_;
  }
  const std::vector<CollisionPair>& getDisabledCollisionPairs() const
  {
    return disabled_collision_pairs_;
  }
  const std::vector<Group>& getGroups() const
  {
    return groups_;
  }
  const std::vector<VirtualJoint>& getVirtualJoints() const
  {
    return virtual_joints_;
  }
  const std::vector<EndEffector>& getEndEffectors() const
  {
    return end_effectors_;
  }
  const std::vector<GroupState>& getGroupStates() const
  {
    return group_states_;
  }
  const std::vector<PassiveJoint>& getPassiveJoints() const
  {
    return passive_joints_;
  }
  const std::vector<LinkSpheres>& getLinkSphereApproximations() const
  {
    return link_sphere_approximations_;
  }
  /// The properties of one joint (empty when it has none)
  const PropertyMap& getJointProperties(const std::string& joint_name) const;
  const JointPropertyMap& getJointProperties() const
  {
    return joint_properties_;
  }

  void clear();

private:
  bool isValidJoint(const urdf::ModelInterface& urdf_model, const std::string& name) const;
  void loadVirtualJoints(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* robot_xml);
  void loadGroups(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* robot_xml);
  void loadGroupStates(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* robot_xml);
  void loadEndEffectors(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* robot_xml);
  void loadLinkSphereApproximations(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* robot_xml);
  void loadCollisionDefaults(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* robot_xml);
  void loadCollisionPairs(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* robot_xml, const char* tag_name,
                          std::vector<CollisionPair>& pairs);
  void loadPassiveJoints(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* robot_xml);
  void loadJointProperties(const urdf::ModelInterface& urdf_model, tinyxml2::XMLElement* robot_xml);

  std::string name_;
  std::vector<Group> groups_;
  std::vector<GroupState> group_states_;
  std::vector<VirtualJoint> virtual_joints_;
  std::vector<EndEffector> end_effectors_;
  std::vector<LinkSpheres> link_sphere_approximations_;
  std::vector<std::string> no_default_collision_links_;
  std::vector<CollisionPair> enabled_collision_pairs_;
  std::vector<CollisionPair> disabled_collision_pairs_;
  std::vector<PassiveJoint> passive_joints_;
  JointPropertyMap joint_properties_;
};
typedef std::shared_ptr<Model> ModelSharedPtr;
typedef std::shared_ptr<const Model> ModelConstSharedPtr;
}  // namespace srdf

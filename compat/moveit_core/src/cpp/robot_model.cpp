// moveit::core::RobotModel built from urdf::ModelInterface and srdf::Model. What MoveIt does and this follows
// (noetic-devel moveit_core/robot_model/src/robot_model.cpp): the SRDF's virtual joint whose child is the URDF's root
// link becomes the root joint and its parent frame the model frame (else a fixed root joint named
// ASSUMED_FIXED_ROOT_JOINT and the root link's frame); continuous joints are revolute joints without position bounds;
// mimic joints are not active; a group is the union of its joints, its links' parent joints, its chains' joints and
// its subgroups' joints, ordered as the model's joints.
#include <moveit/robot_model/robot_model.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <set>
#include <stdexcept>

#include <ros/console.h>

namespace moveit
{
namespace core
{
namespace
{
const char LOGNAME[] = "robot_model";

Eigen::Isometry3d urdfPoseToEigen(const urdf::Pose& pose)
{
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  t.linear() = Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
                   .normalized()
                   .toRotationMatrix();
  return t;
}

JointModel::JointType virtualJointType(const std::string& type)
{
  if (type == "planar")
    return JointModel::PLANAR;
  if (type == "floating")
    return JointModel::FLOATING;
  return JointModel::FIXED;
}
}  // namespace

RobotModel::RobotModel(const urdf::ModelInterfaceSharedPtr& urdf_model, const srdf::ModelConstSharedPtr& srdf_model)
  : urdf_(urdf_model), srdf_(srdf_model ? srdf_model : std::make_shared<const srdf::Model>())
{
  if (!urdf_)
  {
    ROS_ERROR_NAMED(LOGNAME, "RobotModel: no URDF model given");
    return;
  }
  buildModel(*urdf_, *srdf_);
}

RobotModel::~RobotModel()
{
  for (JointModelGroup* group : joint_model_groups_)
    delete group;
  for (JointModel* joint : joint_model_vector_)
    delete joint;
  for (LinkModel* link : link_model_vector_)
    delete link;
}

void RobotModel::buildModel(const urdf::ModelInterface& urdf_model, const srdf::Model& srdf_model)
{
  model_name_ = urdf_model.getName();
  const urdf::LinkConstSharedPtr root = urdf_model.getRoot();
  if (!root)
  {
    ROS_ERROR_NAMED(LOGNAME, "The URDF of '%s' has no root link", model_name_.c_str());
    return;
  }
  model_frame_ = root->name;
  buildTree(urdf_model, srdf_model);
  buildMimic(urdf_model);
  buildJointInfo();
  buildGroups(srdf_model);
  buildGroupStates(srdf_model);
  buildGroupsInfoEndEffectors(srdf_model);
}

void RobotModel::buildTree(const urdf::ModelInterface& urdf_model, const srdf::Model& srdf_model)
{
  const urdf::LinkConstSharedPtr root = urdf_model.getRoot();
  JointModel* root_joint = nullptr;
  for (const srdf::Model::VirtualJoint& vj : srdf_model.getVirtualJoints())
    if (vj.child_link_ == root->name)
    {
      root_joint = new JointModel(vj.name_, virtualJointType(vj.type_));
      model_frame_ = vj.parent_frame_;
      break;
    }
    else
      ROS_WARN_NAMED(LOGNAME, "Virtual joint '%s' is not attached to the root link '%s' and is left out",
                     vj.name_.c_str(), root->name.c_str());
  if (!root_joint)
    root_joint = new JointModel("ASSUMED_FIXED_ROOT_JOINT", JointModel::FIXED);

  std::set<std::string> passive;
  for (const srdf::Model::PassiveJoint& pj : srdf_model.getPassiveJoints())
    passive.insert(pj.name_);

  // Depth-first: a joint and its child link get the next indices
  std::function<void(const urdf::LinkConstSharedPtr&, JointModel*, LinkModel*, const Eigen::Isometry3d&)> add =
      [&](const urdf::LinkConstSharedPtr& urdf_link, JointModel* joint, LinkModel* parent_link,
          const Eigen::Isometry3d& origin) {
        joint->setJointIndex(joint_model_vector_.size());
        joint->setParentLinkModel(parent_link);
        joint->setPassive(passive.count(joint->getName()) > 0);
        joint_model_vector_.push_back(joint);
        joint_model_map_[joint->getName()] = joint;

        LinkModel* link = new LinkModel(urdf_link->name);
        link->setLinkIndex(link_model_vector_.size());
        link->setParentJointModel(joint);
        link->setParentLinkModel(parent_link);
        link->setJointOriginTransform(origin);
        joint->setChildLinkModel(link);
        if (urdf_link->visual && urdf_link->visual->geometry &&
            urdf_link->visual->geometry->type == urdf::Geometry::MESH)
        {
          const auto* mesh = static_cast<const urdf::Mesh*>(urdf_link->visual->geometry.get());
          link->setVisualMesh(mesh->filename, urdfPoseToEigen(urdf_link->visual->origin),
                              Eigen::Vector3d(mesh->scale.x, mesh->scale.y, mesh->scale.z));
        }
        link_model_vector_.push_back(link);
        link_model_map_[link->getName()] = link;
        if (parent_link)
          parent_link->addChildJointModel(joint);

        for (const urdf::LinkSharedPtr& child : urdf_link->child_links)
        {
          const urdf::JointSharedPtr& uj = child->parent_joint;
          JointModel* child_joint = nullptr;
          switch (uj->type)
          {
            case urdf::Joint::REVOLUTE:
            case urdf::Joint::CONTINUOUS:
              child_joint = new JointModel(uj->name, JointModel::REVOLUTE);
              break;
            case urdf::Joint::PRISMATIC:
              child_joint = new JointModel(uj->name, JointModel::PRISMATIC);
              break;
            case urdf::Joint::PLANAR:
              child_joint = new JointModel(uj->name, JointModel::PLANAR);
              break;
            case urdf::Joint::FLOATING:
              child_joint = new JointModel(uj->name, JointModel::FLOATING);
              break;
            default:
              child_joint = new JointModel(uj->name, JointModel::FIXED);
          }
          if (child_joint->getType() == JointModel::REVOLUTE || child_joint->getType() == JointModel::PRISMATIC)
          {
            child_joint->setAxis(Eigen::Vector3d(uj->axis.x, uj->axis.y, uj->axis.z));
            VariableBounds b;
            b.position_bounded_ = true;
            if (uj->limits)
            {
              b.min_position_ = uj->limits->lower;
              b.max_position_ = uj->limits->upper;
              // URDF's velocity limit bounds the joint's speed both ways; 0 means none (robot_model.cpp l. 1240-1260)
              if (uj->limits->velocity > 0.0)
              {
                b.velocity_bounded_ = true;
                b.min_velocity_ = -uj->limits->velocity;
                b.max_velocity_ = uj->limits->velocity;
              }
            }
            if (uj->safety)
            {
              b.min_position_ = std::max(b.min_position_, uj->safety->soft_lower_limit);
              b.max_position_ = std::min(b.max_position_, uj->safety->soft_upper_limit);
            }
            child_joint->setVariableBounds(child_joint->getName(), b);
            if (uj->type == urdf::Joint::CONTINUOUS)
              child_joint->setContinuous(true);
          }
          add(child, child_joint, link, urdfPoseToEigen(uj->parent_to_joint_origin_transform));
        }
      };
  add(root, root_joint, nullptr, Eigen::Isometry3d::Identity());
  root_joint_ = root_joint;
  root_link_ = link_model_vector_.front();

  for (LinkModel* link : link_model_vector_)
  {
    link_model_vector_const_.push_back(link);
    link_model_names_vector_.push_back(link->getName());
  }
  for (JointModel* joint : joint_model_vector_)
  {
    joint_model_vector_const_.push_back(joint);
    joint_model_names_vector_.push_back(joint->getName());
  }

  // Descendants: every joint collects the joints and links below it (its child link included)
  for (auto it = joint_model_vector_.rbegin(); it != joint_model_vector_.rend(); ++it)
  {
    JointModel* joint = *it;
    const LinkModel* child = joint->getChildLinkModel();
    joint->addDescendantLinkModel(child);
    for (const JointModel* below : child->getChildJointModels())
    {
      joint->addDescendantJointModel(below);
      for (const JointModel* deeper : below->getDescendantJointModels())
        joint->addDescendantJointModel(deeper);
      for (const LinkModel* link : below->getDescendantLinkModels())
        joint->addDescendantLinkModel(link);
    }
  }

  // Links rigidly attached to each other through fixed joints
  for (LinkModel* link : link_model_vector_)
  {
    Eigen::Isometry3d to_parent;
    const LinkModel* base = getRigidlyConnectedParentLinkModel(link, to_parent);
    if (base != link)
    {
      link_model_map_[base->getName()]->addAssociatedFixedTransform(link, to_parent);
      link->addAssociatedFixedTransform(base, to_parent.inverse());
    }
  }
}

void RobotModel::buildMimic(const urdf::ModelInterface& urdf_model)
{
  for (JointModel* joint : joint_model_vector_)
  {
    const urdf::JointConstSharedPtr uj = urdf_model.getJoint(joint->getName());
    if (!uj || !uj->mimic)
      continue;
    auto source = joint_model_map_.find(uj->mimic->joint_name);
    if (source == joint_model_map_.end() || source->second->getVariableCount() != joint->getVariableCount())
    {
      ROS_ERROR_NAMED(LOGNAME, "Joint '%s' mimics '%s', which the model does not have or which differs in type",
                      joint->getName().c_str(), uj->mimic->joint_name.c_str());
      continue;
    }
    joint->setMimic(source->second, uj->mimic->multiplier, uj->mimic->offset);
    source->second->addMimicRequest(joint);
    mimic_joints_.push_back(joint);
  }
}

void RobotModel::buildJointInfo()
{
  for (JointModel* joint : joint_model_vector_)
  {
    joint->setFirstVariableIndex(variable_names_.size());
    for (const std::string& name : joint->getVariableNames())
    {
      variable_index_map_[name] = variable_names_.size();
      variable_names_.push_back(name);
      joints_of_variable_.push_back(joint);
    }
    if (joint->getVariableCount() == 0)
      continue;
    if (joint->getVariableCount() == 1)
      single_dof_joints_.push_back(joint);
    else
      multi_dof_joints_.push_back(joint);
    if (joint->isContinuous() || joint->getType() == JointModel::PLANAR)
      continuous_joint_model_vector_.push_back(joint);
    if (!joint->getMimic())
    {
      active_joint_model_vector_.push_back(joint);
      active_joint_model_vector_const_.push_back(joint);
      active_joint_model_names_vector_.push_back(joint->getName());
      active_joint_models_bounds_.push_back(&joint->getVariableBounds());
    }
  }
  variable_count_ = variable_names_.size();
}

void RobotModel::buildGroups(const srdf::Model& srdf_model)
{
  const std::vector<srdf::Model::Group>& groups = srdf_model.getGroups();
  // A group may name subgroups defined after it: add groups until no more can be added
  std::vector<bool> processed(groups.size(), false);
  bool added = true;
  while (added)
  {
    added = false;
    for (std::size_t i = 0; i < groups.size(); ++i)
    {
      if (processed[i])
        continue;
      bool ready = true;
      for (const std::string& sub : groups[i].subgroups_)
        ready = ready && hasJointModelGroup(sub);
      if (!ready)
        continue;
      processed[i] = true;
      added = true;
      if (!addJointModelGroup(groups[i], srdf_model))
        ROS_WARN_NAMED(LOGNAME, "Group '%s' could not be built and is left out", groups[i].name_.c_str());
    }
  }
  for (std::size_t i = 0; i < groups.size(); ++i)
    if (!processed[i])
      ROS_WARN_NAMED(LOGNAME, "Group '%s' names subgroups that are not built and is left out", groups[i].name_.c_str());

  // A group whose joints all belong to another group is that group's subgroup
  for (JointModelGroup* group : joint_model_groups_)
  {
    std::vector<std::string> subgroups;
    const std::set<std::string> mine(group->getJointModelNames().begin(), group->getJointModelNames().end());
    for (const JointModelGroup* other : joint_model_groups_)
    {
      if (other == group || other->getJointModelNames().size() >= mine.size())
        continue;
      bool inside = true;
      for (const std::string& j : other->getJointModelNames())
        inside = inside && mine.count(j) > 0;
      if (inside)
        subgroups.push_back(other->getName());
    }
    group->setSubgroupNames(subgroups);
  }
}

bool RobotModel::addJointModelGroup(const srdf::Model::Group& gc, const srdf::Model& /*srdf_model*/)
{
  if (joint_model_group_map_.count(gc.name_))
  {
    ROS_WARN_NAMED(LOGNAME, "Group '%s' is defined twice; the first definition is kept", gc.name_.c_str());
    return false;
  }
  std::set<const JointModel*> joints;
  for (const std::string& name : gc.joints_)
  {
    auto it = joint_model_map_.find(name);
    if (it != joint_model_map_.end())
      joints.insert(it->second);
  }
  for (const std::pair<std::string, std::string>& chain : gc.chains_)
  {
    const LinkModel* base = getLinkModel(chain.first);
    const LinkModel* tip = getLinkModel(chain.second);
    if (!base || !tip)
      return false;
    std::vector<const JointModel*> path;
    for (const LinkModel* link = tip; link && link != base; link = link->getParentLinkModel())
      path.push_back(link->getParentJointModel());
    bool reached = false;
    for (const LinkModel* link = tip; link; link = link->getParentLinkModel())
      reached = reached || link == base;
    if (!reached)
    {
      ROS_ERROR_NAMED(LOGNAME, "Group '%s': link '%s' is not an ancestor of '%s'", gc.name_.c_str(),
                      chain.first.c_str(), chain.second.c_str());
      return false;
    }
    joints.insert(path.begin(), path.end());
  }
  for (const std::string& name : gc.links_)
  {
    const LinkModel* link = getLinkModel(name);
    if (link && link->getParentJointModel())
      joints.insert(link->getParentJointModel());
  }
  for (const std::string& sub : gc.subgroups_)
  {
    const JointModelGroup* sg = getJointModelGroup(sub);
    joints.insert(sg->getJointModels().begin(), sg->getJointModels().end());
  }
  if (joints.empty())
  {
    ROS_WARN_NAMED(LOGNAME, "Group '%s' has no joints", gc.name_.c_str());
    return false;
  }
  // A mimic joint comes with the joint it follows
  for (const JointModel* joint : std::vector<const JointModel*>(joints.begin(), joints.end()))
    if (joint->getMimic())
      joints.insert(joint->getMimic());
  std::vector<const JointModel*> ordered(joints.begin(), joints.end());
  std::sort(ordered.begin(), ordered.end(),
            [](const JointModel* a, const JointModel* b) { return a->getJointIndex() < b->getJointIndex(); });
  JointModelGroup* group = new JointModelGroup(gc.name_, gc, ordered, this);
  joint_model_groups_.push_back(group);
  joint_model_groups_const_.push_back(group);
  joint_model_group_names_.push_back(gc.name_);
  joint_model_group_map_[gc.name_] = group;
  return true;
}

void RobotModel::buildGroupStates(const srdf::Model& srdf_model)
{
  for (const srdf::Model::GroupState& gs : srdf_model.getGroupStates())
  {
    auto it = joint_model_group_map_.find(gs.group_);
    if (it == joint_model_group_map_.end())
      continue;
    JointModelGroup* group = it->second;
    std::map<std::string, double> state;
    for (const auto& jv : gs.joint_values_)
    {
      if (!group->hasJointModel(jv.first))
      {
        ROS_ERROR_NAMED(LOGNAME, "Group state '%s' names joint '%s', which is not in group '%s'", gs.name_.c_str(),
                        jv.first.c_str(), gs.group_.c_str());
        continue;
      }
      const JointModel* joint = group->getJointModel(jv.first);
      if (jv.second.size() != joint->getVariableCount())
      {
        ROS_ERROR_NAMED(LOGNAME, "Group state '%s' gives joint '%s' %zu values; it has %zu variables",
                        gs.name_.c_str(), jv.first.c_str(), jv.second.size(), joint->getVariableCount());
        continue;
      }
      for (std::size_t i = 0; i < jv.second.size(); ++i)
        state[joint->getVariableNames()[i]] = jv.second[i];
    }
    if (!state.empty())
      group->addDefaultState(gs.name_, state);
  }
}

void RobotModel::buildGroupsInfoEndEffectors(const srdf::Model& srdf_model)
{
  for (const srdf::Model::EndEffector& eef : srdf_model.getEndEffectors())
  {
    auto it = joint_model_group_map_.find(eef.component_group_);
    if (it == joint_model_group_map_.end())
      continue;
    JointModelGroup* eef_group = it->second;
    eef_group->setEndEffectorName(eef.name_);
    end_effectors_map_[eef.name_] = eef_group;
    end_effectors_.push_back(eef_group);

    // The parent group named, else every group holding the parent link and none of the end effector's joints
    for (JointModelGroup* group : joint_model_groups_)
    {
      if (group == eef_group)
        continue;
      bool attach = false;
      if (!eef.parent_group_.empty())
        attach = group->getName() == eef.parent_group_;
      else if (group->hasLinkModel(eef.parent_link_))
      {
        attach = true;
        for (const std::string& j : eef_group->getJointModelNames())
          attach = attach && !group->hasJointModel(j);
      }
      if (attach)
      {
        group->attachEndEffector(eef.name_);
        if (eef.parent_group_.empty())
          eef_group->setEndEffectorParent(group->getName(), eef.parent_link_);
      }
    }
    if (!eef.parent_group_.empty() || eef_group->getEndEffectorParentGroup().second.empty())
      eef_group->setEndEffectorParent(eef.parent_group_, eef.parent_link_);
  }
}

const std::string& RobotModel::getRootJointName() const
{
  static const std::string empty;
  return root_joint_ ? root_joint_->getName() : empty;
}

const std::string& RobotModel::getRootLinkName() const
{
  static const std::string empty;
  return root_link_ ? root_link_->getName() : empty;
}

bool RobotModel::hasJointModel(const std::string& name) const
{
  return joint_model_map_.count(name) > 0;
}

const JointModel* RobotModel::getJointModel(const std::string& name) const
{
  auto it = joint_model_map_.find(name);
  if (it != joint_model_map_.end())
    return it->second;
  ROS_ERROR_NAMED(LOGNAME, "Joint '%s' not found in model '%s'", name.c_str(), model_name_.c_str());
  return nullptr;
}

JointModel* RobotModel::getJointModel(const std::string& name)
{
  // the const lookup's answer: the model owns its joints non-const
  return const_cast<JointModel*>(static_cast<const RobotModel*>(this)->getJointModel(name));
}

const JointModel* RobotModel::getJointModel(int index) const
{
  if (index < 0 || index >= static_cast<int>(joint_model_vector_.size()))
  {
    ROS_ERROR_NAMED(LOGNAME, "Joint index %i out of bounds", index);
    return nullptr;
  }
  return joint_model_vector_[index];
}

bool RobotModel::hasLinkModel(const std::string& name) const
{
  return link_model_map_.count(name) > 0;
}

const LinkModel* RobotModel::getLinkModel(const std::string& name, bool* has_link) const
{
  auto it = link_model_map_.find(name);
  if (has_link)
    *has_link = it != link_model_map_.end();
  if (it != link_model_map_.end())
    return it->second;
  if (!has_link)
    ROS_ERROR_NAMED(LOGNAME, "Link '%s' not found in model '%s'", name.c_str(), model_name_.c_str());
  return nullptr;
}

LinkModel* RobotModel::getLinkModel(const std::string& name, bool* has_link)
{
  // the const lookup's answer: the model owns its links non-const
  return const_cast<LinkModel*>(static_cast<const RobotModel*>(this)->getLinkModel(name, has_link));
}

const LinkModel* RobotModel::getLinkModel(int index) const
{
  if (index < 0 || index >= static_cast<int>(link_model_vector_.size()))
  {
    ROS_ERROR_NAMED(LOGNAME, "Link index %i out of bounds", index);
    return nullptr;
  }
  return link_model_vector_[index];
}

const LinkModel* RobotModel::getRigidlyConnectedParentLinkModel(const LinkModel* link, Eigen::Isometry3d& transform,
                                                                const JointModelGroup* jmg)
{
  transform.setIdentity();
  if (!link)
    return link;
  const LinkModel* parent = link->getParentLinkModel();
  const JointModel* joint = link->getParentJointModel();
  // up across fixed joints and, given a group with joints, across joints the group does not move (l. 1280-1315 on
  // noetic-devel): the link that moves a tool fixed to it
  auto rigid = [jmg](const JointModel* j) {
    return j->getType() == JointModel::FIXED ||
           (jmg && !jmg->getJointModels().empty() && !jmg->hasJointModel(j->getName()));
  };
  while (parent && rigid(joint))
  {
    transform = link->getJointOriginTransform() * transform;
    link = parent;
    joint = link->getParentJointModel();
    parent = link->getParentLinkModel();
  }
  return link;
}

void RobotModel::getVariableRandomPositions(random_numbers::RandomNumberGenerator& rng, double* values) const
{
  for (const JointModel* joint : active_joint_model_vector_)
    joint->getVariableRandomPositions(rng, values + joint->getFirstVariableIndex());
  updateMimicJoints(values);
}

void RobotModel::getVariableDefaultPositions(double* values) const
{
  for (const JointModel* joint : joint_model_vector_)
    joint->getVariableDefaultPositions(values + joint->getFirstVariableIndex());
  updateMimicJoints(values);
}

void RobotModel::getVariableRandomPositions(random_numbers::RandomNumberGenerator& rng,
                                            std::map<std::string, double>& values) const
{
  std::vector<double> v;
  getVariableRandomPositions(rng, v);
  values.clear();
  for (std::size_t i = 0; i < variable_names_.size(); ++i)
    values[variable_names_[i]] = v[i];
}

void RobotModel::getVariableDefaultPositions(std::map<std::string, double>& values) const
{
  std::vector<double> v;
  getVariableDefaultPositions(v);
  values.clear();
  for (std::size_t i = 0; i < variable_names_.size(); ++i)
    values[variable_names_[i]] = v[i];
}

bool RobotModel::enforcePositionBounds(double* state, const JointBoundsVector& bounds) const
{
  bool changed = false;
  for (std::size_t i = 0; i < active_joint_model_vector_.size(); ++i)
    changed = active_joint_model_vector_[i]->enforcePositionBounds(
                  state + active_joint_model_vector_[i]->getFirstVariableIndex(), *bounds[i]) ||
              changed;
  if (changed)
    updateMimicJoints(state);
  return changed;
}

bool RobotModel::satisfiesPositionBounds(const double* state, const JointBoundsVector& bounds, double margin) const
{
  for (std::size_t i = 0; i < active_joint_model_vector_.size(); ++i)
    if (!active_joint_model_vector_[i]->satisfiesPositionBounds(
            state + active_joint_model_vector_[i]->getFirstVariableIndex(), *bounds[i], margin))
      return false;
  return true;
}

double RobotModel::getMaximumExtent(const JointBoundsVector& bounds) const
{
  double sum = 0.0;
  for (std::size_t i = 0; i < active_joint_model_vector_.size(); ++i)
    sum += active_joint_model_vector_[i]->getMaximumExtent(*bounds[i]);
  return sum;
}

double RobotModel::distance(const double* a, const double* b) const
{
  double d = 0.0;
  for (const JointModel* joint : active_joint_model_vector_)
    d += joint->getDistanceFactor() *
         joint->distance(a + joint->getFirstVariableIndex(), b + joint->getFirstVariableIndex());
  return d;
}

void RobotModel::interpolate(const double* from, const double* to, double t, double* state) const
{
  for (const JointModel* joint : active_joint_model_vector_)
    joint->interpolate(from + joint->getFirstVariableIndex(), to + joint->getFirstVariableIndex(), t,
                       state + joint->getFirstVariableIndex());
  updateMimicJoints(state);
}

bool RobotModel::hasJointModelGroup(const std::string& name) const
{
  return joint_model_group_map_.count(name) > 0;
}

const JointModelGroup* RobotModel::getJointModelGroup(const std::string& name) const
{
  auto it = joint_model_group_map_.find(name);
  if (it != joint_model_group_map_.end())
    return it->second;
  ROS_ERROR_NAMED(LOGNAME, "Group '%s' not found in model '%s'", name.c_str(), model_name_.c_str());
  return nullptr;
}

JointModelGroup* RobotModel::getJointModelGroup(const std::string& name)
{
  // the const lookup's answer: the model owns its groups non-const
  return const_cast<JointModelGroup*>(static_cast<const RobotModel*>(this)->getJointModelGroup(name));
}

bool RobotModel::hasEndEffector(const std::string& eef) const
{
  return end_effectors_map_.count(eef) > 0;
}

const JointModelGroup* RobotModel::getEndEffector(const std::string& name) const
{
  auto it = end_effectors_map_.find(name);
  if (it != end_effectors_map_.end())
    return it->second;
  ROS_ERROR_NAMED(LOGNAME, "End effector '%s' not found in model '%s'", name.c_str(), model_name_.c_str());
  return nullptr;
}

JointModelGroup* RobotModel::getEndEffector(const std::string& name)
{
  auto it = end_effectors_map_.find(name);
  if (it != end_effectors_map_.end())
    return it->second;
  ROS_ERROR_NAMED(LOGNAME, "End effector '%s' not found in model '%s'", name.c_str(), model_name_.c_str());
  return nullptr;
}

void RobotModel::getMissingVariableNames(const std::vector<std::string>& variables,
                                         std::vector<std::string>& missing_variables) const
{
  missing_variables.clear();
  const std::set<std::string> given(variables.begin(), variables.end());
  for (const std::string& name : variable_names_)
    if (!given.count(name) && !getJointOfVariable(name)->getMimic())
      missing_variables.push_back(name);
}

int RobotModel::getVariableIndex(const std::string& variable) const
{
  auto it = variable_index_map_.find(variable);
  if (it == variable_index_map_.end())
    throw std::runtime_error("Variable '" + variable + "' is not known to model '" + model_name_ + "'");
  return it->second;
}

const JointModel* RobotModel::getCommonRoot(const JointModel* a, const JointModel* b) const
{
  std::set<const JointModel*> ancestors_of_a;
  for (const JointModel* j = a; j; j = j->getParentLinkModel() ? j->getParentLinkModel()->getParentJointModel() : nullptr)
    ancestors_of_a.insert(j);
  for (const JointModel* j = b; j; j = j->getParentLinkModel() ? j->getParentLinkModel()->getParentJointModel() : nullptr)
    if (ancestors_of_a.count(j))
      return j;
  return root_joint_;
}

void RobotModel::setKinematicsAllocators(const std::map<std::string, SolverAllocatorFn>& allocators)
{
  for (JointModelGroup* group : joint_model_groups_)
  {
    auto it = allocators.find(group->getName());
    if (it != allocators.end())
      group->setSolverAllocators(it->second);
  }
}

void RobotModel::updateMimicJoints(double* values) const
{
  for (const JointModel* joint : mimic_joints_)
  {
    const int src = joint->getMimic()->getFirstVariableIndex();
    const int dest = joint->getFirstVariableIndex();
    for (std::size_t k = 0; k < joint->getVariableCount(); ++k)
      values[dest + k] = values[src + k] * joint->getMimicFactor() + joint->getMimicOffset();
  }
}

void RobotModel::printModelInfo(std::ostream& out) const
{
  out << "Model " << model_name_ << " in frame " << model_frame_ << ", using " << variable_count_ << " variables"
      << std::endl;
  out << "Joints: " << std::endl;
  for (const JointModel* joint : joint_model_vector_)
  {
    out << " '" << joint->getName() << "' (" << joint->getTypeName() << ")" << std::endl;
    out << "  * Joint Index: " << joint->getJointIndex() << std::endl;
    for (std::size_t i = 0; i < joint->getVariableCount(); ++i)
      out << "  * " << joint->getVariableNames()[i] << ": " << joint->getVariableBounds()[i] << std::endl;
  }
  out << "Links: " << std::endl;
  for (const LinkModel* link : link_model_vector_)
    out << " '" << link->getName() << "' with parent joint '" << link->getParentJointModel()->getName() << "'"
        << std::endl;
  out << "Available groups: " << std::endl;
  for (const JointModelGroup* group : joint_model_groups_)
    group->printGroupInfo(out);
}
}  // namespace core
}  // namespace moveit

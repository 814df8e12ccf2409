// moveit::core::JointModelGroup: a group's joints, variables and links derived from the joints RobotModel gives it
// (ordered as the model's joints), as MoveIt's joint_model_group.cpp (noetic-devel) derives them.
#include <moveit/robot_model/joint_model_group.h>
#include <moveit/robot_model/robot_model.h>

#include <algorithm>
#include <cmath>

#include <ros/console.h>

namespace moveit
{
namespace core
{
namespace
{
const char LOGNAME[] = "robot_model.jmg";
}

JointModelGroup::JointModelGroup(const std::string& name, const srdf::Model::Group& config,
                                 const std::vector<const JointModel*>& joint_vector, const RobotModel* parent_model)
  : parent_model_(parent_model), name_(name), config_(config)
{
  int group_index = 0;
  for (const JointModel* joint : joint_vector)
  {
    joint_model_vector_.push_back(joint);
    joint_model_name_vector_.push_back(joint->getName());
    joint_model_map_[joint->getName()] = joint;
    if (joint->getType() == JointModel::FIXED)
      fixed_joints_.push_back(joint);
    else if (joint->getMimic())
      mimic_joints_.push_back(joint);
    else
    {
      active_joint_model_vector_.push_back(joint);
      active_joint_model_name_vector_.push_back(joint->getName());
      active_joint_model_start_index_.push_back(group_index);
      active_joint_models_bounds_.push_back(&joint->getVariableBounds());
      active_variable_count_ += joint->getVariableCount();
    }
    if (joint->isContinuous() || joint->getType() == JointModel::PLANAR)
      continuous_joint_model_vector_.push_back(joint);
    if (joint->getVariableCount() > 1)
      is_single_dof_ = false;
    for (std::size_t k = 0; k < joint->getVariableCount(); ++k)
    {
      variable_names_.push_back(joint->getVariableNames()[k]);
      variable_names_set_.insert(joint->getVariableNames()[k]);
      variable_group_index_map_[joint->getVariableNames()[k]] = group_index++;
      variable_index_list_.push_back(joint->getFirstVariableIndex() + k);
    }
  }
  variable_count_ = variable_names_.size();
  for (std::size_t i = 1; i < variable_index_list_.size(); ++i)
    if (variable_index_list_[i] != variable_index_list_[i - 1] + 1)
      is_contiguous_index_list_ = false;

  for (const JointModel* joint : joint_model_vector_)
  {
    const LinkModel* parent = joint->getParentLinkModel();
    if (!parent || !hasJointModel(parent->getParentJointModel()->getName()))
      joint_roots_.push_back(joint);
    link_model_vector_.push_back(joint->getChildLinkModel());
    link_model_name_vector_.push_back(joint->getChildLinkModel()->getName());
    link_model_map_[joint->getChildLinkModel()->getName()] = joint->getChildLinkModel();
  }
  for (const JointModel* root : joint_roots_)
    for (const LinkModel* link : root->getDescendantLinkModels())
      if (updated_link_model_set_.insert(link).second)
        updated_link_model_vector_.push_back(link);
  std::sort(updated_link_model_vector_.begin(), updated_link_model_vector_.end(),
            [](const LinkModel* a, const LinkModel* b) { return a->getLinkIndex() < b->getLinkIndex(); });
  for (const LinkModel* link : updated_link_model_vector_)
  {
    updated_link_model_name_vector_.push_back(link->getName());
    updated_link_model_name_set_.insert(link->getName());
  }

  common_root_ = joint_roots_.empty() ? nullptr : joint_roots_.front();
  for (const JointModel* root : joint_roots_)
    common_root_ = parent_model_->getCommonRoot(common_root_, root);

  // A chain: one root, and each active joint lies below the previous one
  is_chain_ = joint_roots_.size() == 1 && !active_joint_model_vector_.empty();
  for (std::size_t i = 1; is_chain_ && i < active_joint_model_vector_.size(); ++i)
  {
    const auto& below = active_joint_model_vector_[i - 1]->getDescendantJointModels();
    is_chain_ = std::find(below.begin(), below.end(), active_joint_model_vector_[i]) != below.end();
  }

  for (const JointModel* joint : mimic_joints_)
    if (hasJointModel(joint->getMimic()->getName()))
      group_mimic_update_.push_back(GroupMimicUpdate{ variable_group_index_map_[joint->getMimic()->getName()],
                                                      variable_group_index_map_[joint->getName()],
                                                      joint->getMimicFactor(), joint->getMimicOffset() });
}

JointModelGroup::~JointModelGroup() = default;

bool JointModelGroup::hasJointModel(const std::string& joint) const
{
  return joint_model_map_.count(joint) > 0;
}

bool JointModelGroup::hasLinkModel(const std::string& link) const
{
  return link_model_map_.count(link) > 0;
}

const JointModel* JointModelGroup::getJointModel(const std::string& name) const
{
  auto it = joint_model_map_.find(name);
  if (it != joint_model_map_.end())
    return it->second;
  ROS_ERROR_NAMED(LOGNAME, "Joint '%s' not found in group '%s'", name.c_str(), name_.c_str());
  return nullptr;
}

const LinkModel* JointModelGroup::getLinkModel(const std::string& name) const
{
  auto it = link_model_map_.find(name);
  if (it != link_model_map_.end())
    return it->second;
  ROS_ERROR_NAMED(LOGNAME, "Link '%s' not found in group '%s'", name.c_str(), name_.c_str());
  return nullptr;
}

int JointModelGroup::getVariableGroupIndex(const std::string& variable) const
{
  auto it = variable_group_index_map_.find(variable);
  if (it != variable_group_index_map_.end())
    return it->second;
  ROS_ERROR_NAMED(LOGNAME, "Variable '%s' is not part of group '%s'", variable.c_str(), name_.c_str());
  return -1;
}

void JointModelGroup::addDefaultState(const std::string& name, const std::map<std::string, double>& default_state)
{
  if (!default_states_.count(name))
    default_states_names_.push_back(name);
  default_states_[name] = default_state;
}

bool JointModelGroup::getVariableDefaultPositions(const std::string& name, std::map<std::string, double>& values) const
{
  auto it = default_states_.find(name);
  if (it == default_states_.end())
    return false;
  values = it->second;
  return true;
}

void JointModelGroup::getVariableDefaultPositions(std::map<std::string, double>& values) const
{
  std::vector<double> v;
  getVariableDefaultPositions(v);
  for (std::size_t i = 0; i < variable_names_.size(); ++i)
    values[variable_names_[i]] = v[i];
}

void JointModelGroup::getVariableDefaultPositions(double* values) const
{
  int index = 0;
  for (const JointModel* joint : joint_model_vector_)
  {
    joint->getVariableDefaultPositions(values + index);
    index += joint->getVariableCount();
  }
  updateMimicJoints(values);
}

void JointModelGroup::getVariableRandomPositions(random_numbers::RandomNumberGenerator& rng, double* values,
                                                 const JointBoundsVector& bounds) const
{
  for (std::size_t i = 0; i < active_joint_model_vector_.size(); ++i)
    active_joint_model_vector_[i]->getVariableRandomPositions(rng, values + active_joint_model_start_index_[i],
                                                              *bounds[i]);
  updateMimicJoints(values);
}

void JointModelGroup::getVariableRandomPositionsNearBy(random_numbers::RandomNumberGenerator& rng, double* values,
                                                       const JointBoundsVector& bounds, const double* seed,
                                                       const double distance) const
{
  for (std::size_t i = 0; i < active_joint_model_vector_.size(); ++i)
    active_joint_model_vector_[i]->getVariableRandomPositionsNearBy(rng, values + active_joint_model_start_index_[i],
                                                                    *bounds[i],
                                                                    seed + active_joint_model_start_index_[i], distance);
  updateMimicJoints(values);
}

bool JointModelGroup::enforcePositionBounds(double* state, const JointBoundsVector& bounds) const
{
  bool changed = false;
  for (std::size_t i = 0; i < active_joint_model_vector_.size(); ++i)
    changed = active_joint_model_vector_[i]->enforcePositionBounds(state + active_joint_model_start_index_[i],
                                                                   *bounds[i]) ||
              changed;
  if (changed)
    updateMimicJoints(state);
  return changed;
}

bool JointModelGroup::satisfiesPositionBounds(const double* state, const JointBoundsVector& bounds, double margin) const
{
  for (std::size_t i = 0; i < active_joint_model_vector_.size(); ++i)
    if (!active_joint_model_vector_[i]->satisfiesPositionBounds(state + active_joint_model_start_index_[i], *bounds[i],
                                                                margin))
      return false;
  return true;
}

double JointModelGroup::getMaximumExtent(const JointBoundsVector& bounds) const
{
  double sum = 0.0;
  for (std::size_t i = 0; i < active_joint_model_vector_.size(); ++i)
    sum += active_joint_model_vector_[i]->getMaximumExtent(*bounds[i]);
  return sum;
}

double JointModelGroup::distance(const double* a, const double* b) const
{
  double d = 0.0;
  for (std::size_t i = 0; i < active_joint_model_vector_.size(); ++i)
    d += active_joint_model_vector_[i]->getDistanceFactor() *
         active_joint_model_vector_[i]->distance(a + active_joint_model_start_index_[i],
                                                 b + active_joint_model_start_index_[i]);
  return d;
}

void JointModelGroup::interpolate(const double* from, const double* to, double t, double* state) const
{
  for (std::size_t i = 0; i < active_joint_model_vector_.size(); ++i)
    active_joint_model_vector_[i]->interpolate(from + active_joint_model_start_index_[i],
                                               to + active_joint_model_start_index_[i], t,
                                               state + active_joint_model_start_index_[i]);
  updateMimicJoints(state);
}

void JointModelGroup::updateMimicJoints(double* values) const
{
  for (const GroupMimicUpdate& m : group_mimic_update_)
    values[m.dest] = values[m.src] * m.factor + m.offset;
}

void JointModelGroup::setSubgroupNames(const std::vector<std::string>& subgroups)
{
  subgroup_names_ = subgroups;
  subgroup_names_set_ = std::set<std::string>(subgroups.begin(), subgroups.end());
}

void JointModelGroup::getSubgroups(std::vector<const JointModelGroup*>& sub_groups) const
{
  sub_groups.clear();
  for (const std::string& name : subgroup_names_)
    sub_groups.push_back(parent_model_->getJointModelGroup(name));
}

void JointModelGroup::setEndEffectorName(const std::string& name)
{
  end_effector_name_ = name;
}

void JointModelGroup::setEndEffectorParent(const std::string& group, const std::string& link)
{
  end_effector_parent_ = std::make_pair(group, link);
}

void JointModelGroup::attachEndEffector(const std::string& eef_name)
{
  if (std::find(attached_end_effector_names_.begin(), attached_end_effector_names_.end(), eef_name) ==
      attached_end_effector_names_.end())
    attached_end_effector_names_.push_back(eef_name);
}

bool JointModelGroup::getEndEffectorTips(std::vector<const LinkModel*>& tips) const
{
  std::vector<std::string> names;
  if (!getEndEffectorTips(names))
    return false;
  tips.clear();
  for (const std::string& name : names)
    tips.push_back(parent_model_->getLinkModel(name));
  return true;
}

bool JointModelGroup::getEndEffectorTips(std::vector<std::string>& tips) const
{
  tips.clear();
  std::vector<const JointModelGroup*> groups;
  getSubgroups(groups);
  groups.insert(groups.begin(), this);
  for (const JointModelGroup* group : groups)
    for (const std::string& eef_name : group->getAttachedEndEffectorNames())
    {
      const JointModelGroup* eef = parent_model_->getEndEffector(eef_name);
      if (!eef)
        return false;
      const std::string& tip = eef->getEndEffectorParentGroup().second;
      if (std::find(tips.begin(), tips.end(), tip) == tips.end())
        tips.push_back(tip);
    }
  return true;
}

const LinkModel* JointModelGroup::getOnlyOneEndEffectorTip() const
{
  std::vector<const LinkModel*> tips;
  getEndEffectorTips(tips);
  if (tips.size() == 1)
    return tips.front();
  ROS_ERROR_NAMED(LOGNAME, "Group '%s' has %zu end-effector tips; one was expected", name_.c_str(), tips.size());
  return nullptr;
}

void JointModelGroup::setSolverAllocators(const std::pair<SolverAllocatorFn, SolverAllocatorMapFn>& solvers)
{
  group_kinematics_.first.reset();
  group_kinematics_.first.allocator_ = solvers.first;
  if (!solvers.first)
    return;
  group_kinematics_.first.solver_instance_ = solvers.first(this);
  if (!group_kinematics_.first.solver_instance_)
    return;
  group_kinematics_.first.solver_instance_->setDefaultTimeout(group_kinematics_.first.default_ik_timeout_);
  if (!computeIKIndexBijection(group_kinematics_.first.solver_instance_->getJointNames(),
                               group_kinematics_.first.bijection_))
    group_kinematics_.first.reset();
}

bool JointModelGroup::computeIKIndexBijection(const std::vector<std::string>& ik_jnames,
                                              std::vector<unsigned int>& joint_bijection) const
{
  joint_bijection.clear();
  for (const std::string& name : ik_jnames)
  {
    auto it = variable_group_index_map_.find(name);
    if (it == variable_group_index_map_.end())
    {
      ROS_ERROR_NAMED(LOGNAME, "IK solver joint '%s' is not in group '%s'", name.c_str(), name_.c_str());
      return false;
    }
    joint_bijection.push_back(it->second);
  }
  return true;
}

bool JointModelGroup::canSetStateFromIK(const std::string& tip) const
{
  const kinematics::KinematicsBaseConstPtr solver = getSolverInstance();
  if (!solver)
    return false;
  for (const std::string& frame : solver->getTipFrames())
    if (frame == tip || frame == "/" + tip)
      return true;
  return false;
}

bool JointModelGroup::setRedundantJoints(const std::vector<std::string>& joints)
{
  const kinematics::KinematicsBasePtr& solver = group_kinematics_.first.solver_instance_;
  return solver && solver->setRedundantJoints(joints);
}

void JointModelGroup::setDefaultIKTimeout(double ik_timeout)
{
  group_kinematics_.first.default_ik_timeout_ = ik_timeout;
  if (group_kinematics_.first.solver_instance_)
    group_kinematics_.first.solver_instance_->setDefaultTimeout(ik_timeout);
}

bool JointModelGroup::isValidVelocityMove(const std::vector<double>& from, const std::vector<double>& to,
                                          double dt) const
{
  return from.size() == to.size() && isValidVelocityMove(from.data(), to.data(), from.size(), dt);
}

bool JointModelGroup::isValidVelocityMove(const double* from, const double* to, std::size_t array_size,
                                          double dt) const
{
  for (std::size_t i = 0; i < active_joint_model_vector_.size(); ++i)
  {
    const JointModel* joint = active_joint_model_vector_[i];
    for (std::size_t k = 0; k < joint->getVariableCount(); ++k)
    {
      const std::size_t index = active_joint_model_start_index_[i] + k;
      if (index >= array_size)
        return false;
      const VariableBounds& b = joint->getVariableBounds()[k];
      if (b.velocity_bounded_ && std::fabs(to[index] - from[index]) / dt > b.max_velocity_)
        return false;
    }
  }
  return true;
}

void JointModelGroup::printGroupInfo(std::ostream& out) const
{
  out << "Group '" << name_ << "' using " << variable_count_ << " variables" << std::endl;
  out << "  * Joints:" << std::endl;
  for (const JointModel* joint : joint_model_vector_)
    out << "    '" << joint->getName() << "' (" << joint->getTypeName() << ")" << std::endl;
  out << "  * Variables:" << std::endl;
  for (const std::string& name : variable_names_)
    out << "    '" << name << "', index " << variable_index_list_[variable_group_index_map_.at(name)] << std::endl;
  out << "  * " << (is_chain_ ? "Chain" : "Not a chain") << std::endl;
  if (!end_effector_name_.empty())
    out << "  * End effector '" << end_effector_name_ << "' on link '" << end_effector_parent_.second << "'"
        << std::endl;
  if (!default_states_names_.empty())
  {
    out << "  * Default states:" << std::endl;
    for (const std::string& name : default_states_names_)
      out << "    " << name << std::endl;
  }
}
}  // namespace core
}  // namespace moveit

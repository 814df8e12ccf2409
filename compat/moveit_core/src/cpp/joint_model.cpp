// moveit::core::JointModel and LinkModel: one concrete joint class for MoveIt's five joint types. The per-type
// behaviour follows MoveIt's subclasses (noetic-devel moveit_core/robot_model/src/{revolute,prismatic,planar,floating,
// fixed}_joint_model.cpp): variable names and defaults, continuous joints wrapped into [-pi, pi], quaternions
// normalised.
#include <moveit/robot_model/joint_model.h>
#include <moveit/robot_model/link_model.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <ros/console.h>

namespace moveit
{
namespace core
{
namespace
{
// Where a translation has no limits, random positions are drawn from [-extent, extent] (metres): what MoveIt's
// planar and floating joints sample is bounded by the bounds they are given; unbounded ones need some range
constexpr double UNBOUNDED_TRANSLATION_SAMPLE_EXTENT = 1.0;
const double INF = std::numeric_limits<double>::infinity();

// The shortest signed angle from a to b
double angularDifference(double a, double b)
{
  return std::remainder(b - a, 2.0 * M_PI);
}
}  // namespace

JointModel::JointModel(const std::string& name, JointType type) : name_(name), type_(type)
{
  VariableBounds unbounded;
  unbounded.min_position_ = -INF;
  unbounded.max_position_ = INF;
  VariableBounds angle;
  angle.min_position_ = -M_PI;
  angle.max_position_ = M_PI;
  VariableBounds unit;
  unit.min_position_ = -1.0;
  unit.max_position_ = 1.0;
  unit.position_bounded_ = true;
  switch (type_)
  {
    case REVOLUTE:
    case PRISMATIC:
      variable_names_.push_back(name_);
      variable_bounds_.push_back(VariableBounds());
      variable_bounds_.back().position_bounded_ = true;
      break;
    case PLANAR:
      local_variable_names_ = { "x", "y", "theta" };
      variable_bounds_ = { unbounded, unbounded, angle };
      break;
    case FLOATING:
      local_variable_names_ = { "trans_x", "trans_y", "trans_z", "rot_x", "rot_y", "rot_z", "rot_w" };
      variable_bounds_ = { unbounded, unbounded, unbounded, unit, unit, unit, unit };
      break;
    default:
      break;
  }
  for (const std::string& local : local_variable_names_)
    variable_names_.push_back(name_ + "/" + local);
  for (std::size_t i = 0; i < variable_names_.size(); ++i)
  {
    variable_index_map_[variable_names_[i]] = i;
    if (!local_variable_names_.empty())
      variable_index_map_[local_variable_names_[i]] = i;
  }
  computeVariableBoundsMsg();
}

JointModel::~JointModel() = default;

std::string JointModel::getTypeName() const
{
  switch (type_)
  {
    case REVOLUTE:
      return "Revolute";
    case PRISMATIC:
      return "Prismatic";
    case PLANAR:
      return "Planar";
    case FLOATING:
      return "Floating";
    case FIXED:
      return "Fixed";
    default:
      return "Unknown";
  }
}

int JointModel::getLocalVariableIndex(const std::string& variable) const
{
  auto it = variable_index_map_.find(variable);
  if (it == variable_index_map_.end())
    throw std::runtime_error("Joint '" + name_ + "' has no variable '" + variable + "'");
  return it->second;
}

void JointModel::setAxis(const Eigen::Vector3d& axis)
{
  axis_ = axis.normalized();
}

void JointModel::setContinuous(bool flag)
{
  continuous_ = flag;
  if (flag && type_ == REVOLUTE)
  {
    variable_bounds_[0].min_position_ = -M_PI;
    variable_bounds_[0].max_position_ = M_PI;
    variable_bounds_[0].position_bounded_ = false;
    computeVariableBoundsMsg();
  }
}

void JointModel::getVariableDefaultPositions(double* values, const Bounds& bounds) const
{
  if (type_ == FLOATING)
  {
    std::fill(values, values + 6, 0.0);
    values[6] = 1.0;
    return;
  }
  // 0 when the bounds allow it, else the middle of the range (MoveIt's revolute/prismatic/planar defaults)
  for (std::size_t i = 0; i < variable_names_.size(); ++i)
  {
    const VariableBounds& b = bounds[i];
    values[i] = (b.min_position_ <= 0.0 && b.max_position_ >= 0.0) ? 0.0 : (b.min_position_ + b.max_position_) / 2.0;
  }
}

void JointModel::getVariableRandomPositions(random_numbers::RandomNumberGenerator& rng, double* values,
                                            const Bounds& bounds) const
{
  if (type_ == FLOATING)
  {
    for (int i = 0; i < 3; ++i)
    {
      const bool finite = std::isfinite(bounds[i].min_position_) && std::isfinite(bounds[i].max_position_);
      values[i] = finite ? rng.uniformReal(bounds[i].min_position_, bounds[i].max_position_) :
                           rng.uniformReal(-UNBOUNDED_TRANSLATION_SAMPLE_EXTENT, UNBOUNDED_TRANSLATION_SAMPLE_EXTENT);
    }
    double q[4];
    rng.quaternion(q);
    std::copy(q, q + 4, values + 3);
    return;
  }
  for (std::size_t i = 0; i < variable_names_.size(); ++i)
  {
    const VariableBounds& b = bounds[i];
    const bool finite = std::isfinite(b.min_position_) && std::isfinite(b.max_position_);
    values[i] = finite ? rng.uniformReal(b.min_position_, b.max_position_) :
                         rng.uniformReal(-UNBOUNDED_TRANSLATION_SAMPLE_EXTENT, UNBOUNDED_TRANSLATION_SAMPLE_EXTENT);
  }
}

void JointModel::getVariableRandomPositionsNearBy(random_numbers::RandomNumberGenerator& rng, double* values,
                                                  const Bounds& bounds, const double* seed, const double distance) const
{
  if (type_ == FLOATING)
  {
    getVariableRandomPositions(rng, values, bounds);
    return;
  }
  for (std::size_t i = 0; i < variable_names_.size(); ++i)
  {
    const VariableBounds& b = bounds[i];
    values[i] = rng.uniformReal(std::max(b.min_position_, seed[i] - distance),
                                std::min(b.max_position_, seed[i] + distance));
  }
}

bool JointModel::satisfiesPositionBounds(const double* values, const Bounds& bounds, double margin) const
{
  switch (type_)
  {
    case FIXED:
      return true;
    case FLOATING:
    {
      for (int i = 0; i < 3; ++i)
        if (values[i] < bounds[i].min_position_ - margin || values[i] > bounds[i].max_position_ + margin)
          return false;
      const double norm2 = values[3] * values[3] + values[4] * values[4] + values[5] * values[5] + values[6] * values[6];
      // A quaternion is in bounds when it is (nearly) a unit one
      return std::fabs(norm2 - 1.0) <= std::numeric_limits<float>::epsilon() * 10.0;
    }
    case PLANAR:
      for (int i = 0; i < 2; ++i)
        if (values[i] < bounds[i].min_position_ - margin || values[i] > bounds[i].max_position_ + margin)
          return false;
      return true;
    default:
      if (continuous_)
        return true;
      return !(values[0] < bounds[0].min_position_ - margin || values[0] > bounds[0].max_position_ + margin);
  }
}

bool JointModel::enforcePositionBounds(double* values, const Bounds& bounds) const
{
  bool changed = false;
  switch (type_)
  {
    case FIXED:
      return false;
    case FLOATING:
    {
      for (int i = 0; i < 3; ++i)
      {
        const double v = std::min(std::max(values[i], bounds[i].min_position_), bounds[i].max_position_);
        changed = changed || v != values[i];
        values[i] = v;
      }
      Eigen::Quaterniond q(values[6], values[3], values[4], values[5]);
      const double norm = q.norm();
      if (norm <= std::numeric_limits<double>::epsilon())
      {
        values[3] = values[4] = values[5] = 0.0;
        values[6] = 1.0;
        return true;
      }
      if (std::fabs(norm - 1.0) > std::numeric_limits<double>::epsilon())
      {
        for (int i = 3; i < 7; ++i)
          values[i] /= norm;
        changed = true;
      }
      return changed;
    }
    case PLANAR:
      for (int i = 0; i < 2; ++i)
      {
        const double v = std::min(std::max(values[i], bounds[i].min_position_), bounds[i].max_position_);
        changed = changed || v != values[i];
        values[i] = v;
      }
      changed = harmonizePosition(values, bounds) || changed;
      return changed;
    default:
      if (continuous_)
        return harmonizePosition(values, bounds);
      {
        const double v = std::min(std::max(values[0], bounds[0].min_position_), bounds[0].max_position_);
        changed = v != values[0];
        values[0] = v;
      }
      return changed;
  }
}

bool JointModel::harmonizePosition(double* values, const Bounds& /*bounds*/) const
{
  double* angle = nullptr;
  if (type_ == REVOLUTE && continuous_)
    angle = values;
  else if (type_ == PLANAR)
    angle = values + 2;
  if (!angle || (*angle >= -M_PI && *angle <= M_PI))
    return false;
  *angle = std::remainder(*angle, 2.0 * M_PI);
  return true;
}

bool JointModel::satisfiesVelocityBounds(const double* values, const Bounds& bounds, double margin) const
{
  for (std::size_t i = 0; i < variable_names_.size(); ++i)
    if (bounds[i].velocity_bounded_ &&
        (values[i] < bounds[i].min_velocity_ - margin || values[i] > bounds[i].max_velocity_ + margin))
      return false;
  return true;
}

bool JointModel::enforceVelocityBounds(double* values, const Bounds& bounds) const
{
  bool changed = false;
  for (std::size_t i = 0; i < variable_names_.size(); ++i)
    if (bounds[i].velocity_bounded_)
    {
      const double v = std::min(std::max(values[i], bounds[i].min_velocity_), bounds[i].max_velocity_);
      changed = changed || v != values[i];
      values[i] = v;
    }
  return changed;
}

bool JointModel::satisfiesAccelerationBounds(const double* values, const Bounds& bounds, double margin) const
{
  for (std::size_t i = 0; i < variable_names_.size(); ++i)
    if (bounds[i].acceleration_bounded_ &&
        (values[i] < bounds[i].min_acceleration_ - margin || values[i] > bounds[i].max_acceleration_ + margin))
      return false;
  return true;
}

const VariableBounds& JointModel::getVariableBounds(const std::string& variable) const
{
  return variable_bounds_[getLocalVariableIndex(variable)];
}

void JointModel::setVariableBounds(const std::string& variable, const VariableBounds& bounds)
{
  variable_bounds_[getLocalVariableIndex(variable)] = bounds;
  computeVariableBoundsMsg();
}

void JointModel::setVariableBounds(const std::vector<moveit_msgs::JointLimits>& jlim)
{
  for (std::size_t j = 0; j < variable_names_.size(); ++j)
    for (const moveit_msgs::JointLimits& limit : jlim)
    {
      if (limit.joint_name != variable_names_[j])
        continue;
      VariableBounds& b = variable_bounds_[j];
      if (limit.has_position_limits)
      {
        b.position_bounded_ = true;
        b.min_position_ = limit.min_position;
        b.max_position_ = limit.max_position;
      }
      else
        b.position_bounded_ = false;
      if (limit.has_velocity_limits)
      {
        b.velocity_bounded_ = true;
        b.min_velocity_ = -limit.max_velocity;
        b.max_velocity_ = limit.max_velocity;
      }
      else
        b.velocity_bounded_ = false;
      if (limit.has_acceleration_limits)
      {
        b.acceleration_bounded_ = true;
        b.min_acceleration_ = -limit.max_acceleration;
        b.max_acceleration_ = limit.max_acceleration;
      }
      else
        b.acceleration_bounded_ = false;
      break;
    }
  computeVariableBoundsMsg();
}

void JointModel::computeVariableBoundsMsg()
{
  variable_bounds_msg_.clear();
  for (std::size_t i = 0; i < variable_names_.size(); ++i)
  {
    const VariableBounds& b = variable_bounds_[i];
    moveit_msgs::JointLimits limit;
    limit.joint_name = variable_names_[i];
    limit.has_position_limits = b.position_bounded_;
    limit.min_position = b.min_position_;
    limit.max_position = b.max_position_;
    limit.has_velocity_limits = b.velocity_bounded_;
    limit.max_velocity = std::min(std::fabs(b.min_velocity_), std::fabs(b.max_velocity_));
    limit.has_acceleration_limits = b.acceleration_bounded_;
    limit.max_acceleration = std::min(std::fabs(b.min_acceleration_), std::fabs(b.max_acceleration_));
    variable_bounds_msg_.push_back(limit);
  }
}

double JointModel::distance(const double* a, const double* b) const
{
  switch (type_)
  {
    case FIXED:
      return 0.0;
    case PLANAR:
      return std::hypot(a[0] - b[0], a[1] - b[1]) + std::fabs(angularDifference(a[2], b[2]));
    case FLOATING:
    {
      const Eigen::Quaterniond qa(a[6], a[3], a[4], a[5]);
      const Eigen::Quaterniond qb(b[6], b[3], b[4], b[5]);
      return Eigen::Vector3d(a[0] - b[0], a[1] - b[1], a[2] - b[2]).norm() + qa.angularDistance(qb);
    }
    default:
      return continuous_ ? std::fabs(angularDifference(a[0], b[0])) : std::fabs(a[0] - b[0]);
  }
}

unsigned int JointModel::getStateSpaceDimension() const
{
  // A floating joint has 6 degrees of freedom held in 7 variables
  return type_ == FLOATING ? 6 : variable_names_.size();
}

void JointModel::setMimic(const JointModel* mimic, double factor, double offset)
{
  mimic_ = mimic;
  mimic_factor_ = factor;
  mimic_offset_ = offset;
}

void JointModel::addMimicRequest(const JointModel* joint)
{
  mimic_requests_.push_back(joint);
}

void JointModel::addDescendantJointModel(const JointModel* joint)
{
  descendant_joint_models_.push_back(joint);
  if (joint->getType() != FIXED)
    non_fixed_descendant_joint_models_.push_back(joint);
}

void JointModel::addDescendantLinkModel(const LinkModel* link)
{
  descendant_link_models_.push_back(link);
}

void JointModel::interpolate(const double* from, const double* to, const double t, double* state) const
{
  switch (type_)
  {
    case FIXED:
      return;
    case FLOATING:
    {
      for (int i = 0; i < 3; ++i)
        state[i] = from[i] + (to[i] - from[i]) * t;
      const Eigen::Quaterniond qa(from[6], from[3], from[4], from[5]);
      const Eigen::Quaterniond qb(to[6], to[3], to[4], to[5]);
      const Eigen::Quaterniond q = qa.slerp(t, qb);
      state[3] = q.x();
      state[4] = q.y();
      state[5] = q.z();
      state[6] = q.w();
      return;
    }
    case PLANAR:
      state[0] = from[0] + (to[0] - from[0]) * t;
      state[1] = from[1] + (to[1] - from[1]) * t;
      state[2] = std::remainder(from[2] + angularDifference(from[2], to[2]) * t, 2.0 * M_PI);
      return;
    default:
      state[0] = continuous_ ? std::remainder(from[0] + angularDifference(from[0], to[0]) * t, 2.0 * M_PI) :
                               from[0] + (to[0] - from[0]) * t;
  }
}

double JointModel::getMaximumExtent(const Bounds& bounds) const
{
  double sum = 0.0;
  for (std::size_t i = 0; i < variable_names_.size(); ++i)
    if (std::isfinite(bounds[i].min_position_) && std::isfinite(bounds[i].max_position_))
      sum += (bounds[i].max_position_ - bounds[i].min_position_) * (bounds[i].max_position_ - bounds[i].min_position_);
  return std::sqrt(sum);
}

void JointModel::computeTransform(const double* values, Eigen::Isometry3d& transf) const
{
  transf.setIdentity();
  switch (type_)
  {
    case REVOLUTE:
      transf.linear() = Eigen::AngleAxisd(values[0], axis_).toRotationMatrix();
      break;
    case PRISMATIC:
      transf.translation() = axis_ * values[0];
      break;
    case PLANAR:
      transf.translation() = Eigen::Vector3d(values[0], values[1], 0.0);
      transf.linear() = Eigen::AngleAxisd(values[2], Eigen::Vector3d::UnitZ()).toRotationMatrix();
      break;
    case FLOATING:
      transf.translation() = Eigen::Vector3d(values[0], values[1], values[2]);
      transf.linear() = Eigen::Quaterniond(values[6], values[3], values[4], values[5]).normalized().toRotationMatrix();
      break;
    default:
      break;
  }
}

void JointModel::computeVariablePositions(const Eigen::Isometry3d& transf, double* values) const
{
  switch (type_)
  {
    case REVOLUTE:
    {
      const Eigen::AngleAxisd aa(transf.linear());
      values[0] = aa.angle() * aa.axis().dot(axis_);
      break;
    }
    case PRISMATIC:
      values[0] = transf.translation().dot(axis_);
      break;
    case PLANAR:
    {
      values[0] = transf.translation().x();
      values[1] = transf.translation().y();
      const Eigen::Matrix3d r = transf.linear();
      values[2] = std::atan2(r(1, 0), r(0, 0));
      break;
    }
    case FLOATING:
    {
      values[0] = transf.translation().x();
      values[1] = transf.translation().y();
      values[2] = transf.translation().z();
      const Eigen::Quaterniond q(transf.linear());
      values[3] = q.x();
      values[4] = q.y();
      values[5] = q.z();
      values[6] = q.w();
      break;
    }
    default:
      break;
  }
}

std::ostream& operator<<(std::ostream& out, const VariableBounds& b)
{
  out << "P." << (b.position_bounded_ ? "bounded" : "unbounded") << " [" << b.min_position_ << ", " << b.max_position_
      << "]; V." << (b.velocity_bounded_ ? "bounded" : "unbounded") << " [" << b.min_velocity_ << ", "
      << b.max_velocity_ << "]; A." << (b.acceleration_bounded_ ? "bounded" : "unbounded") << " ["
      << b.min_acceleration_ << ", " << b.max_acceleration_ << "];";
  return out;
}

LinkModel::LinkModel(const std::string& name) : name_(name)
{
}

LinkModel::~LinkModel() = default;

void LinkModel::setParentJointModel(const JointModel* joint)
{
  parent_joint_model_ = joint;
  is_parent_joint_fixed_ = joint->getType() == JointModel::FIXED;
}

void LinkModel::setJointOriginTransform(const Eigen::Isometry3d& transform)
{
  joint_origin_transform_ = transform;
  joint_origin_transform_is_identity_ =
      transform.linear().isIdentity() && transform.translation().norm() < std::numeric_limits<double>::epsilon();
}

void LinkModel::setVisualMesh(const std::string& visual_mesh, const Eigen::Isometry3d& origin,
                              const Eigen::Vector3d& scale)
{
  visual_mesh_filename_ = visual_mesh;
  visual_mesh_origin_ = origin;
  visual_mesh_scale_ = scale;
}
}  // namespace core
}  // namespace moveit

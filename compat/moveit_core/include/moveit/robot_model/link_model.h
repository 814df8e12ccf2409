// moveit::core::LinkModel (MoveIt noetic-devel moveit_core/robot_model/include/moveit/robot_model/link_model.h), the
// workspace's own implementation.
//
// Provided: name, index, parent joint and link, child joints, the fixed transform from the parent link to this
// link's joint frame (the URDF joint origin), links rigidly attached through fixed joints
// (getAssociatedFixedTransforms), the visual mesh's file name, origin and scale when the URDF gives one.
// Not provided: collision shapes (getShapes, setGeometry, getCollisionOriginTransforms, extents): geometric_shapes is
// not packaged by Debian; move_group (Python) does collision checking.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>
#include <eigen_stl_containers/eigen_stl_containers.h>

namespace moveit
{
namespace core
{
class JointModel;
class LinkModel;

using LinkModelMap = std::map<std::string, LinkModel*>;
using LinkModelMapConst = std::map<std::string, const LinkModel*>;
using LinkTransformMap = std::map<const LinkModel*, Eigen::Isometry3d, std::less<const LinkModel*>,
                                  Eigen::aligned_allocator<std::pair<const LinkModel* const, Eigen::Isometry3d>>>;

class LinkModel
{
public:
  EIGEN_MAKE_ALIGNED_OPERATOR_NEW

  LinkModel(const std::string& name);
  ~LinkModel();

  const std::string& getName() const
  {
    return name_;
  }
  int getLinkIndex() const
  {
    return link_index_;
  }
  void setLinkIndex(int index)
  {
    link_index_ = index;
  }
  const JointModel* getParentJointModel() const
  {
    return parent_joint_model_;
  }
  void setParentJointModel(const JointModel* joint);
  const LinkModel* getParentLinkModel() const
  {
    return parent_link_model_;
  }
  void setParentLinkModel(const LinkModel* link)
  {
    parent_link_model_ = link;
  }
  const std::vector<const JointModel*>& getChildJointModels() const
  {
    return child_joint_models_;
  }
  void addChildJointModel(const JointModel* joint)
  {
    child_joint_models_.push_back(joint);
  }

  /// The fixed transform from the parent link's frame to the parent joint's frame (the URDF joint's <origin>)
  const Eigen::Isometry3d& getJointOriginTransform() const
  {
    return joint_origin_transform_;
  }
  bool jointOriginTransformIsIdentity() const
  {
    return joint_origin_transform_is_identity_;
  }
  bool parentJointIsFixed() const
  {
    return is_parent_joint_fixed_;
  }
  void setJointOriginTransform(const Eigen::Isometry3d& transform);

  /// Links attached to this one through fixed joints only, with their transform relative to this link
  const LinkTransformMap& getAssociatedFixedTransforms() const
  {
    return associated_fixed_transforms_;
  }
  void addAssociatedFixedTransform(const LinkModel* link_model, const Eigen::Isometry3d& transform)
  {
    associated_fixed_transforms_[link_model] = transform;
  }

  const std::string& getVisualMeshFilename() const
  {
    return visual_mesh_filename_;
  }
  const Eigen::Vector3d& getVisualMeshScale() const
  {
    return visual_mesh_scale_;
  }
  const Eigen::Isometry3d& getVisualMeshOrigin() const
  {
    return visual_mesh_origin_;
  }
  void setVisualMesh(const std::string& visual_mesh, const Eigen::Isometry3d& origin, const Eigen::Vector3d& scale);

private:
  std::string name_;
  const JointModel* parent_joint_model_ = nullptr;
  const LinkModel* parent_link_model_ = nullptr;
  std::vector<const JointModel*> child_joint_models_;
  bool is_parent_joint_fixed_ = false;
  bool joint_origin_transform_is_identity_ = true;
  Eigen::Isometry3d joint_origin_transform_ = Eigen::Isometry3d::Identity();
  LinkTransformMap associated_fixed_transforms_;
  std::string visual_mesh_filename_;
  Eigen::Isometry3d visual_mesh_origin_ = Eigen::Isometry3d::Identity();
  Eigen::Vector3d visual_mesh_scale_ = Eigen::Vector3d::Ones();
  int link_index_ = -1;
};
}  // namespace core
}  // namespace moveit

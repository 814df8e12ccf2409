/* Shapes as MoveIt draws them (moveit_ros/visualization/rviz_plugin_render_tools/src/
 * render_shapes.cpp l. 88-171 and 190-198 on noetic-devel): a sphere scaled to its diameter, a box to its
 * size, a cylinder and a cone with their axis turned from rviz's y to z, a plane as a 10 m x
 * 10 m x 1 mm box at half alpha, a mesh as triangles with their face normals. */
#include "collision_object_visual.h"

#include <OgreSceneManager.h>
#include <OgreSceneNode.h>
#include <rviz/ogre_helpers/mesh_shape.h>
#include <shape_msgs/SolidPrimitive.h>

namespace moveit_rviz_plugin
{
namespace
{
const float PLANE_SIZE = 10.0f;        // m, render_shapes.cpp l. 122
const float PLANE_THICKNESS = 0.001f;  // m, idem
const float PLANE_ALPHA_FACTOR = 0.5f; // render_shapes.cpp l. 123

Ogre::Vector3 vector(const geometry_msgs::Point& p)
{
  return Ogre::Vector3(p.x, p.y, p.z);
}

Ogre::Quaternion rotation(const geometry_msgs::Quaternion& q)
{
  Ogre::Quaternion result(q.w, q.x, q.y, q.z);
  if (result.Norm() < 1e-9)  // an all-zero quaternion, common in hand-written messages: identity
    return Ogre::Quaternion::IDENTITY;
  result.normalise();
  return result;
}

// the object's pose composed with a shape's pose (both given, as MoveIt 1.1 reads them)
void place(rviz::Shape& shape, const geometry_msgs::Pose& object, const geometry_msgs::Pose& local,
           const Ogre::Quaternion& fix = Ogre::Quaternion::IDENTITY)
{
  const Ogre::Quaternion object_rotation = rotation(object.orientation);
  shape.setPosition(vector(object.position) + object_rotation * vector(local.position));
  shape.setOrientation(object_rotation * rotation(local.orientation) * fix);
}
}  // namespace

CollisionObjectVisual::CollisionObjectVisual(Ogre::SceneManager* scene_manager, Ogre::SceneNode* parent)
  : scene_manager_(scene_manager), node_(parent->createChildSceneNode()), color_(Ogre::ColourValue::White)
{
}

CollisionObjectVisual::~CollisionObjectVisual()
{
  shapes_.clear();
  scene_manager_->destroySceneNode(node_);
}

void CollisionObjectVisual::setShapes(const moveit_msgs::CollisionObject& object)
{
  shapes_.clear();
  // cylinders and cones: render_shapes.cpp l. 190-198, rviz's axis is y, the message's z
  const Ogre::Quaternion axis_fix(Ogre::Radian(Ogre::Math::HALF_PI), Ogre::Vector3::UNIT_X);
  for (size_t i = 0; i < object.primitives.size() && i < object.primitive_poses.size(); ++i)
  {
    const shape_msgs::SolidPrimitive& primitive = object.primitives[i];
    const auto& d = primitive.dimensions;
    std::unique_ptr<rviz::Shape> shape;
    Ogre::Quaternion fix = Ogre::Quaternion::IDENTITY;
    using P = shape_msgs::SolidPrimitive;
    if (primitive.type == P::BOX && d.size() >= 3)
    {
      shape.reset(new rviz::Shape(rviz::Shape::Cube, scene_manager_, node_));
      shape->setScale(Ogre::Vector3(d[P::BOX_X], d[P::BOX_Y], d[P::BOX_Z]));
    }
    else if (primitive.type == P::SPHERE && d.size() >= 1)
    {
      shape.reset(new rviz::Shape(rviz::Shape::Sphere, scene_manager_, node_));
      const double diameter = 2.0 * d[P::SPHERE_RADIUS];
      shape->setScale(Ogre::Vector3(diameter, diameter, diameter));
    }
    else if ((primitive.type == P::CYLINDER || primitive.type == P::CONE) && d.size() >= 2)
    {
      const bool cylinder = primitive.type == P::CYLINDER;
      shape.reset(new rviz::Shape(cylinder ? rviz::Shape::Cylinder : rviz::Shape::Cone, scene_manager_, node_));
      const double diameter = 2.0 * d[cylinder ? P::CYLINDER_RADIUS : P::CONE_RADIUS];
      const double height = d[cylinder ? P::CYLINDER_HEIGHT : P::CONE_HEIGHT];
      shape->setScale(Ogre::Vector3(diameter, height, diameter));
      fix = axis_fix;
    }
    if (!shape)
      continue;  // a primitive without its dimensions: move_group refuses it; nothing to draw
    place(*shape, object.pose, object.primitive_poses[i], fix);
    shapes_.push_back({ std::move(shape), 1.0f });
  }
  for (size_t i = 0; i < object.meshes.size() && i < object.mesh_poses.size(); ++i)
  {
    const shape_msgs::Mesh& mesh = object.meshes[i];
    if (mesh.triangles.empty())
      continue;
    auto* drawn = new rviz::MeshShape(scene_manager_, node_);
    drawn->estimateVertexCount(mesh.triangles.size() * 3);
    drawn->beginTriangles();
    for (const auto& triangle : mesh.triangles)
    {
      bool valid = true;
      for (auto index : triangle.vertex_indices)
        valid = valid && index < mesh.vertices.size();
      if (!valid)
        continue;
      const Ogre::Vector3 a = vector(mesh.vertices[triangle.vertex_indices[0]]);
      const Ogre::Vector3 b = vector(mesh.vertices[triangle.vertex_indices[1]]);
      const Ogre::Vector3 c = vector(mesh.vertices[triangle.vertex_indices[2]]);
      const Ogre::Vector3 normal = (b - a).crossProduct(c - a).normalisedCopy();
      drawn->addVertex(a, normal);
      drawn->addVertex(b, normal);
      drawn->addVertex(c, normal);
    }
    drawn->endTriangles();
    place(*drawn, object.pose, object.mesh_poses[i]);
    shapes_.push_back({ std::unique_ptr<rviz::Shape>(drawn), 1.0f });
  }
  for (size_t i = 0; i < object.planes.size() && i < object.plane_poses.size(); ++i)
  {
    const auto& coef = object.planes[i].coef;
    Ogre::Vector3 normal(coef[0], coef[1], coef[2]);
    const double norm = normal.length();
    if (norm < 1e-12)
      continue;
    normal /= norm;
    std::unique_ptr<rviz::Shape> shape(new rviz::Shape(rviz::Shape::Cube, scene_manager_, node_));
    shape->setScale(Ogre::Vector3(PLANE_SIZE, PLANE_SIZE, PLANE_THICKNESS));
    // render_shapes.cpp l. 124-131: the box turned from z to the normal, moved by d along it
    geometry_msgs::Pose local = object.plane_poses[i];
    const Ogre::Quaternion offset = Ogre::Vector3::UNIT_Z.getRotationTo(normal);
    const Ogre::Vector3 shift = normal * (coef[3] / norm);
    const Ogre::Quaternion local_rotation = rotation(local.orientation);
    const Ogre::Vector3 local_position = vector(local.position) + local_rotation * shift;
    local.position.x = local_position.x;
    local.position.y = local_position.y;
    local.position.z = local_position.z;
    place(*shape, object.pose, local, offset);
    shapes_.push_back({ std::move(shape), PLANE_ALPHA_FACTOR });
  }
  setColor(color_);
}

void CollisionObjectVisual::setColor(const Ogre::ColourValue& color)
{
  color_ = color;
  for (auto& drawn : shapes_)
    drawn.shape->setColor(color.r, color.g, color.b, color.a * drawn.alpha_factor);
}

void CollisionObjectVisual::setVisible(bool visible)
{
  node_->setVisible(visible);
}
}  // namespace moveit_rviz_plugin

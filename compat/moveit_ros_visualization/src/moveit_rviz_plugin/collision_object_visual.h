/* One collision object drawn with rviz's shapes: its primitives (box, sphere, cylinder,
 * cone), meshes and planes, each at its pose in the object's frame, under one scene node
 * that the owner places (in the fixed frame for world objects, on a link for attached
 * ones). */
#pragma once

#include <memory>
#include <vector>

#include <OgreColourValue.h>
#include <moveit_msgs/CollisionObject.h>
#include <rviz/ogre_helpers/shape.h>

namespace Ogre
{
class SceneManager;
class SceneNode;
}  // namespace Ogre

namespace moveit_rviz_plugin
{
class CollisionObjectVisual
{
public:
  CollisionObjectVisual(Ogre::SceneManager* scene_manager, Ogre::SceneNode* parent);
  ~CollisionObjectVisual();
  CollisionObjectVisual(const CollisionObjectVisual&) = delete;
  CollisionObjectVisual& operator=(const CollisionObjectVisual&) = delete;

  /* Draws the object's shapes (replacing what was drawn), their poses composed with the
   * object's own pose. */
  void setShapes(const moveit_msgs::CollisionObject& object);
  void setColor(const Ogre::ColourValue& color);
  void setVisible(bool visible);

  /* The node whose pose is the object's frame (its header frame, or the link it is attached
   * to). */
  Ogre::SceneNode* node() const { return node_; }

private:
  struct DrawnShape
  {
    std::unique_ptr<rviz::Shape> shape;
    float alpha_factor;  // planes are drawn at half the alpha, as MoveIt's RenderShapes does
  };

  Ogre::SceneManager* scene_manager_;
  Ogre::SceneNode* node_;
  std::vector<DrawnShape> shapes_;
  Ogre::ColourValue color_;
};
}  // namespace moveit_rviz_plugin

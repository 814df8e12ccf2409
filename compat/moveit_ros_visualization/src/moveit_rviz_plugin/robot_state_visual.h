/* A robot state drawn in rviz: rviz's own Robot (links from the URDF, visual and collision
 * geometry, the "Links" properties) posed by our forward kinematics, and the state's attached
 * bodies drawn on their links. One class for the scene's robot, a planned path's states, the
 * start and goal states and the RobotState display. */
#pragma once

#include <map>
#include <memory>
#include <string>

#include <OgreColourValue.h>
#include <OgreQuaternion.h>
#include <OgreVector3.h>
#include <moveit_msgs/AttachedCollisionObject.h>
#include <rviz/robot/robot.h>

#include "collision_object_visual.h"
#include "robot_kinematics.h"

namespace rviz
{
class DisplayContext;
class Property;
}  // namespace rviz

namespace moveit_rviz_plugin
{
class RobotStateVisual
{
public:
  RobotStateVisual(Ogre::SceneNode* parent, rviz::DisplayContext* context, const std::string& name,
                   rviz::Property* links_parent);
  ~RobotStateVisual();

  void load(const RobotKinematics& kinematics);
  void clear();

  /* Poses the links at `positions` and draws `attached` on their links. */
  void update(const JointPositions& positions, const std::vector<moveit_msgs::AttachedCollisionObject>& attached);
  /* The same with the links' poses already computed (RobotKinematics::linkPoses). */
  void update(const LinkPoses& poses, const std::vector<moveit_msgs::AttachedCollisionObject>& attached);

  /* The root link's pose in the display's frame. */
  void setPose(const Ogre::Vector3& position, const Ogre::Quaternion& orientation);

  void setVisible(bool visible);
  void setVisualVisible(bool visible);
  void setCollisionVisible(bool visible);
  void setAlpha(float alpha);
  /* Every link in one colour (start and goal states, a path's robot colour); unset: the
   * URDF's materials. */
  void setColor(const Ogre::ColourValue& color);
  void unsetColor();
  void setAttachedBodyColor(const Ogre::ColourValue& color);
  /* Highlights (DisplayRobotState's highlight_links): each named link in its colour. */
  void setHighlights(const std::map<std::string, Ogre::ColourValue>& highlights);

private:
  void applyColors();

  rviz::DisplayContext* context_;
  Ogre::SceneNode* node_;
  std::unique_ptr<rviz::Robot> robot_;
  const RobotKinematics* kinematics_ = nullptr;
  std::map<std::string, std::unique_ptr<CollisionObjectVisual>> attached_;
  bool has_color_ = false;
  Ogre::ColourValue color_;
  Ogre::ColourValue attached_color_;
  float alpha_ = 1.0f;
  bool visible_ = true;
  std::map<std::string, Ogre::ColourValue> highlights_;
};
}  // namespace moveit_rviz_plugin

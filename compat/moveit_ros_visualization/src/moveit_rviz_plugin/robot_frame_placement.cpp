/* The planning frame's pose in the fixed frame (MoveIt: PlanningSceneDisplay::
 * calculateOffsetPosition, planning_scene_display.cpp on noetic-devel). */
#include "robot_frame_placement.h"

#include <OgreSceneNode.h>
#include <rviz/display.h>
#include <rviz/display_context.h>
#include <rviz/frame_manager.h>

namespace moveit_rviz_plugin
{
void placeAtFrame(Ogre::SceneNode* node, const std::string& frame, rviz::DisplayContext* context,
                  rviz::Display* display)
{
  Ogre::Vector3 position;
  Ogre::Quaternion orientation;
  if (context->getFrameManager()->getTransform(frame, ros::Time(0), position, orientation))
  {
    node->setPosition(position);
    node->setOrientation(orientation);
    display->deleteStatusStd("Planning Frame");
    return;
  }
  node->setPosition(Ogre::Vector3::ZERO);
  node->setOrientation(Ogre::Quaternion::IDENTITY);
  display->setStatusStd(rviz::StatusProperty::Warn, "Planning Frame",
                        "no transform from the planning frame '" + frame + "' to the fixed frame '" +
                            context->getFixedFrame().toStdString() + "': drawn at the fixed frame's origin");
}
}  // namespace moveit_rviz_plugin

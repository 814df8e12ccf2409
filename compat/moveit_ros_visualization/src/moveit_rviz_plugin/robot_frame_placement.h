/* Where a display draws the robot: its planning frame (the model frame) looked up in the
 * fixed frame through rviz's FrameManager, at the fixed frame's origin when TF has no such
 * transform (MoveIt's displays' calculateOffsetPosition). */
#pragma once

#include <string>

namespace Ogre
{
class SceneNode;
}
namespace rviz
{
class Display;
class DisplayContext;
}  // namespace rviz

namespace moveit_rviz_plugin
{
/* Places `node` at `frame`; a missing transform is the display's "Planning Frame" warning. */
void placeAtFrame(Ogre::SceneNode* node, const std::string& frame, rviz::DisplayContext* context,
                  rviz::Display* display);
}  // namespace moveit_rviz_plugin

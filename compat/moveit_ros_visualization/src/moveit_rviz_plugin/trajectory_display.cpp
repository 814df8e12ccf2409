/* The Trajectory display: "Robot Description" and TrajectoryVisualization's properties
 * (moveit_ros/visualization/trajectory_rviz_plugin/src/trajectory_display.cpp l. 45-55 on
 * noetic-devel). */
#include "trajectory_display.h"

#include <OgreSceneNode.h>

#include "robot_frame_placement.h"

namespace moveit_rviz_plugin
{
TrajectoryDisplay::TrajectoryDisplay()
{
  trajectory_visual_.reset(new TrajectoryVisualization(this, this));
}

TrajectoryDisplay::~TrajectoryDisplay()
{
  trajectory_visual_.reset();
}

void TrajectoryDisplay::onInitialize()
{
  Display::onInitialize();
  trajectory_visual_->onInitialize(scene_node_->createChildSceneNode(), context_, update_nh_);
}

void TrajectoryDisplay::onRobotModelLoaded()
{
  trajectory_visual_->onRobotModelLoaded(kinematics_);
}

void TrajectoryDisplay::onEnable()
{
  Display::onEnable();
  if (!robotModelLoaded())
    loadRobotModel();
  trajectory_visual_->onEnable();
}

void TrajectoryDisplay::onDisable()
{
  trajectory_visual_->onDisable();
  Display::onDisable();
}

void TrajectoryDisplay::reset()
{
  Display::reset();
  forgetRobotModel();
  if (isEnabled())
    loadRobotModel();
  trajectory_visual_->reset();
}

void TrajectoryDisplay::update(float wall_dt, float ros_dt)
{
  Display::update(wall_dt, ros_dt);
  if (!ensureRobotModel(wall_dt))
    return;
  placeAtFrame(scene_node_, planningFrame(), context_, this);
  trajectory_visual_->update(wall_dt, ros_dt);
}

}  // namespace moveit_rviz_plugin

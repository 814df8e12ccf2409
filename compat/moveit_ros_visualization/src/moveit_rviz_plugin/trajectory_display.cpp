/* The Trajectory display: "Robot Description" and TrajectoryVisualization's properties
 * (moveit_ros/visualization/trajectory_rviz_plugin/src/trajectory_display.cpp l. 45-55 on
 * noetic-devel). */
#include "trajectory_display.h"

#include <OgreSceneNode.h>
#include <rviz/properties/string_property.h>

#include "robot_frame_placement.h"
#include "robot_model_loader.h"

namespace moveit_rviz_plugin
{
TrajectoryDisplay::TrajectoryDisplay()
{
  robot_description_property_ =
      new rviz::StringProperty("Robot Description", "robot_description",
                               "The name of the ROS parameter where the URDF for the robot is loaded", this,
                               SLOT(changedRobotDescription()), this);
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

void TrajectoryDisplay::loadRobotModel()
{
  const RobotModelLoad load = moveit_rviz_plugin::loadRobotModel(robot_description_property_->getStdString(), kinematics_, srdf_);
  if (!load.ok)
  {
    setStatusStd(rviz::StatusProperty::Error, "Robot Model", load.error);
    return;
  }
  setStatusStd(rviz::StatusProperty::Ok, "Robot Model", "loaded from '" + load.key + "'");
  planning_frame_ = load.planning_frame;
  robot_loaded_ = true;
  trajectory_visual_->onRobotModelLoaded(kinematics_);
}

void TrajectoryDisplay::onEnable()
{
  Display::onEnable();
  if (!robot_loaded_)
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
  robot_loaded_ = false;
  if (isEnabled())
    loadRobotModel();
  trajectory_visual_->reset();
}

void TrajectoryDisplay::update(float wall_dt, float ros_dt)
{
  Display::update(wall_dt, ros_dt);
  if (!robot_loaded_)
  {
    robot_retry_ += wall_dt;
    if (robot_retry_ < ROBOT_RETRY_PERIOD)
      return;
    robot_retry_ = 0.0f;
    loadRobotModel();
    if (!robot_loaded_)
      return;
  }
  placeAtFrame(scene_node_, planning_frame_, context_, this);
  trajectory_visual_->update(wall_dt, ros_dt);
}

void TrajectoryDisplay::changedRobotDescription()
{
  if (isEnabled())
    reset();
}
}  // namespace moveit_rviz_plugin

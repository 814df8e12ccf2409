/* The robot's reading shared by MoveIt's displays (rdf_loader's search: robot_model_loader). */
#include "robot_model_display.h"

#include <rviz/properties/string_property.h>

#include "robot_model_loader.h"

namespace moveit_rviz_plugin
{
RobotModelDisplay::RobotModelDisplay()
{
  robot_description_property_ =
      new rviz::StringProperty("Robot Description", "robot_description",
                               "The name of the ROS parameter where the URDF for the robot is loaded", this,
                               SLOT(changedRobotDescription()), this);
}

void RobotModelDisplay::changedRobotDescription()
{
  if (isEnabled())
    reset();
}

bool RobotModelDisplay::ensureRobotModel(float wall_dt)
{
  if (robot_loaded_)
    return true;
  since_retry_ += wall_dt;
  if (since_retry_ < ROBOT_RETRY_PERIOD)
    return false;
  since_retry_ = 0.0f;
  loadRobotModel();
  return robot_loaded_;
}

void RobotModelDisplay::loadRobotModel()
{
  const RobotModelLoad load =
      moveit_rviz_plugin::loadRobotModel(robot_description_property_->getStdString(), kinematics_, srdf_);
  if (!load.ok)
  {
    setStatusStd(rviz::StatusProperty::Error, "Robot Model", load.error);
    return;
  }
  if (load.srdf_problem.empty())
    deleteStatusStd("Robot Semantics");
  else
    setStatusStd(rviz::StatusProperty::Warn, "Robot Semantics", load.srdf_problem);
  setStatusStd(rviz::StatusProperty::Ok, "Robot Model", "loaded from '" + load.key + "'");
  planning_frame_ = load.planning_frame;
  robot_loaded_ = true;
  onRobotModelLoaded();
}
}  // namespace moveit_rviz_plugin

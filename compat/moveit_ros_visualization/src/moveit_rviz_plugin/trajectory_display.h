/* moveit_rviz_plugin/Trajectory: planned paths from `move_group/display_planned_path`
 * animated on the robot (TrajectoryVisualization), without a planning scene. */
#pragma once

#include <memory>

#include <rviz/display.h>

#include "robot_kinematics.h"
#include "srdf_model.h"
#include "trajectory_visualization.h"

namespace rviz
{
class StringProperty;
}

namespace moveit_rviz_plugin
{
class TrajectoryDisplay : public rviz::Display
{
  Q_OBJECT
public:
  TrajectoryDisplay();
  ~TrajectoryDisplay() override;

  void update(float wall_dt, float ros_dt) override;
  void reset() override;

private Q_SLOTS:
  void changedRobotDescription();

private:
  void onInitialize() override;
  void onEnable() override;
  void onDisable() override;
  void loadRobotModel();

  rviz::StringProperty* robot_description_property_;
  std::unique_ptr<TrajectoryVisualization> trajectory_visual_;
  RobotKinematics kinematics_;
  SrdfModel srdf_;
  std::string planning_frame_;
  bool robot_loaded_ = false;
  float robot_retry_ = 0.0f;
};
}  // namespace moveit_rviz_plugin

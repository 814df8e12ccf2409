/* moveit_rviz_plugin/Trajectory: planned paths from `move_group/display_planned_path`
 * animated on the robot (TrajectoryVisualization), without a planning scene. */
#pragma once

#include <memory>

#include "robot_model_display.h"
#include "trajectory_visualization.h"

namespace moveit_rviz_plugin
{
class TrajectoryDisplay : public RobotModelDisplay
{
  Q_OBJECT
public:
  TrajectoryDisplay();
  ~TrajectoryDisplay() override;

  void update(float wall_dt, float ros_dt) override;
  void reset() override;

private:
  void onInitialize() override;
  void onEnable() override;
  void onDisable() override;
  void onRobotModelLoaded() override;

  std::unique_ptr<TrajectoryVisualization> trajectory_visual_;
};
}  // namespace moveit_rviz_plugin

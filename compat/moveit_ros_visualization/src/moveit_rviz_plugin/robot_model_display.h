/* What MoveIt's displays share: the "Robot Description" property, the robot's URDF and SRDF
 * read from the parameter server (again once a second while they are missing, as a display
 * may start before the launch file sets them), and the planning frame they draw in. */
#pragma once

#include <string>

#include <rviz/display.h>

#include "robot_kinematics.h"
#include "srdf_model.h"

namespace rviz
{
class StringProperty;
}

namespace moveit_rviz_plugin
{
class RobotModelDisplay : public rviz::Display
{
  Q_OBJECT
public:
  RobotModelDisplay();

protected Q_SLOTS:
  void changedRobotDescription();

protected:
  /* True once the robot is read; otherwise tries again when a retry is due. */
  bool ensureRobotModel(float wall_dt);
  /* Reads the robot now (the display's "Robot Model" status says how it went). */
  void loadRobotModel();
  /* Forgets the robot, so that the next ensureRobotModel reads it anew. */
  void forgetRobotModel() { robot_loaded_ = false; }
  /* Called once the URDF and SRDF are read (and again when they change). */
  virtual void onRobotModelLoaded() = 0;

  bool robotModelLoaded() const { return robot_loaded_; }
  /* The frame the robot and the scene are expressed in: the SRDF's virtual joint parent,
   * else the URDF's root link. */
  const std::string& planningFrame() const { return planning_frame_; }

  rviz::StringProperty* robot_description_property_;
  RobotKinematics kinematics_;
  SrdfModel srdf_;

private:
  bool robot_loaded_ = false;
  float since_retry_ = 0.0f;
  std::string planning_frame_;
};
}  // namespace moveit_rviz_plugin

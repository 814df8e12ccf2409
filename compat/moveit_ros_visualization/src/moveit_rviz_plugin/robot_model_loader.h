/* Reading the robot's URDF and SRDF from the parameter server as MoveIt's RobotModelLoader
 * (rdf_loader) does: the parameter searched upwards from the node's namespace, the SRDF
 * beside it as `<name>_semantic`. */
#pragma once

#include <string>

#include "robot_kinematics.h"
#include "srdf_model.h"

namespace moveit_rviz_plugin
{
/* s between a display's tries to read a robot description not set yet */
constexpr float ROBOT_RETRY_PERIOD = 1.0f;

struct RobotModelLoad
{
  bool ok = false;
  std::string key;            // the parameter the URDF came from
  std::string error;          // why the URDF could not be read (ok false)
  std::string srdf_problem;   // why there are no semantics (ok may still be true)
  std::string planning_frame; // the SRDF's virtual joint parent, else the URDF's root link
};

RobotModelLoad loadRobotModel(const std::string& parameter, RobotKinematics& kinematics, SrdfModel& srdf);
}  // namespace moveit_rviz_plugin

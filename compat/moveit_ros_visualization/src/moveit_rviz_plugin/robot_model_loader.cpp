/* rdf_loader's search (moveit_ros/planning/rdf_loader/src/rdf_loader.cpp on noetic-devel:
 * nh.searchParam(robot_description), then `<found>_semantic`). */
#include "robot_model_loader.h"

#include <ros/ros.h>

namespace moveit_rviz_plugin
{
RobotModelLoad loadRobotModel(const std::string& parameter, RobotKinematics& kinematics, SrdfModel& srdf)
{
  RobotModelLoad load;
  ros::NodeHandle private_handle("~");
  std::string urdf_xml, srdf_xml;
  if (!private_handle.searchParam(parameter, load.key) || !private_handle.getParam(load.key, urdf_xml))
  {
    load.error = "no robot description on the parameter server at '" + parameter + "' (waiting for it)";
    return load;
  }
  if (!kinematics.load(urdf_xml, load.error))
  {
    load.error = "'" + load.key + "': " + load.error;
    return load;
  }
  srdf = SrdfModel();
  std::string error;
  if (!private_handle.getParam(load.key + "_semantic", srdf_xml))
    load.srdf_problem = "no semantic description at '" + load.key + "_semantic': no planning groups or named states";
  else if (!srdf.parse(srdf_xml, error))
    load.srdf_problem = "'" + load.key + "_semantic': " + error;
  load.planning_frame =
      srdf.virtual_joint_parent_frame.empty() ? kinematics.rootLink() : srdf.virtual_joint_parent_frame;
  load.ok = true;
  return load;
}
}  // namespace moveit_rviz_plugin

// A user's program in the style of MoveIt's C++ tutorial (move_group_interface_tutorial.cpp):
// MoveItVisualTools on the robot's root link, a title, a labelled axis, an arrow, a cuboid, a
// line, the trajectory line of the arm's tool through a small trajectory, the trajectory for
// rviz to animate and a coloured robot state; then prompt() until "next" arrives from the
// RvizVisualToolsGui topic, and a last text. test/visual_tools.test checks what it publishes.
//
// Parameters: ~group (the planning group), ~trajectory (a flat list of the group's positions,
// one waypoint after another), ~tip_link (the link traced) or ~by_group (true: trace the
// group's end-effector tips, as Interbotix's interbotix_moveit_interface does), ~base_frame
// (the markers' frame; the model's root link by default), ~robot_trajectory (true: the line and
// the path published from a robot_trajectory::RobotTrajectory of the same waypoints, over the
// model's default state, instead of the message).
#include <ros/ros.h>

#include <moveit/robot_model_loader/robot_model_loader.h>
#include <moveit/robot_state/robot_state.h>
#include <moveit/robot_trajectory/robot_trajectory.h>
#include <moveit_visual_tools/moveit_visual_tools.h>

#include <string>
#include <vector>

namespace rvt = rviz_visual_tools;

namespace
{
// What a test adds to a user's program: wait until the checker listens on every topic, so that
// nothing published is lost (upstream's own waits give up after 0.5 s)
class ListenedVisualTools : public moveit_visual_tools::MoveItVisualTools
{
public:
  using MoveItVisualTools::MoveItVisualTools;

  void waitForListeners()
  {
    loadMarkerPub();
    loadTrajectoryPub(moveit_visual_tools::DISPLAY_PLANNED_PATH_TOPIC, false);
    loadRobotStatePub("", false);
    const bool blocking = true;
    waitForSubscriber(pub_rviz_markers_, 0, blocking);
    waitForSubscriber(pub_display_path_, 0, blocking);
    waitForSubscriber(pub_robot_state_, 0, blocking);
  }
};
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "visual_tools_demo");
  ros::NodeHandle private_nh("~");
  ros::AsyncSpinner spinner(1);
  spinner.start();

  std::string group_name;
  std::string tip_link;
  std::string base_frame;
  bool by_group = false;
  bool use_robot_trajectory = false;
  std::vector<double> flat_trajectory;
  private_nh.param<std::string>("group", group_name, "manipulator");
  private_nh.param<std::string>("tip_link", tip_link, "tool0");
  private_nh.param("by_group", by_group, false);
  private_nh.param("robot_trajectory", use_robot_trajectory, false);
  private_nh.getParam("trajectory", flat_trajectory);

  robot_model_loader::RobotModelLoader robot_model_loader("robot_description");
  const moveit::core::RobotModelPtr& robot_model = robot_model_loader.getModel();
  if (!robot_model)
  {
    ROS_ERROR("visual_tools_demo: no robot model");
    return 1;
  }
  const moveit::core::JointModelGroup* joint_model_group = robot_model->getJointModelGroup(group_name);
  if (!joint_model_group || flat_trajectory.empty() ||
      flat_trajectory.size() % joint_model_group->getVariableCount() != 0)
  {
    ROS_ERROR("visual_tools_demo: group '%s' unknown or ~trajectory not whole waypoints of it", group_name.c_str());
    return 1;
  }

  private_nh.param<std::string>("base_frame", base_frame, robot_model->getRootLinkName());
  ListenedVisualTools visual_tools(base_frame);
  visual_tools.deleteAllMarkers();
  visual_tools.loadRemoteControl();
  visual_tools.waitForListeners();

  // The waiting state as a sphere: red while prompt() waits, green once released
  Eigen::Isometry3d lamp_pose = Eigen::Isometry3d::Identity();
  lamp_pose.translation().z() = 1.2;
  const std::size_t lamp_id = 1;
  visual_tools.getRemoteControl()->setDisplayWaitingState([&](bool waiting) {
    visual_tools.publishSphere(lamp_pose, waiting ? rvt::RED : rvt::GREEN, rvt::XLARGE, "Waiting", lamp_id);
    visual_tools.trigger();
  });

  Eigen::Isometry3d text_pose = Eigen::Isometry3d::Identity();
  text_pose.translation().z() = 1.0;
  visual_tools.publishText(text_pose, "MoveItVisualTools Demo", rvt::WHITE, rvt::XLARGE);

  Eigen::Isometry3d pose1 = Eigen::Isometry3d::Identity();
  pose1.translation() = Eigen::Vector3d(0.28, -0.2, 0.5);
  pose1.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  visual_tools.publishAxisLabeled(pose1, "pose1");

  Eigen::Isometry3d arrow_pose = Eigen::Isometry3d::Identity();
  arrow_pose.translation() = Eigen::Vector3d(0.0, 0.4, 0.3);
  visual_tools.publishArrow(arrow_pose, rvt::RED, rvt::LARGE);

  visual_tools.publishCuboid(Eigen::Vector3d(0.3, 0.3, 0.0), Eigen::Vector3d(0.4, 0.5, 0.1), rvt::BLUE);
  visual_tools.publishLine(Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(0.0, 0.0, 0.5), rvt::YELLOW, rvt::SMALL);

  // The trajectory the tutorial's plan would hold: the group's joints, one point per waypoint
  moveit_msgs::RobotTrajectory trajectory;
  trajectory.joint_trajectory.joint_names = joint_model_group->getVariableNames();
  const std::size_t dof = joint_model_group->getVariableCount();
  for (std::size_t start = 0; start < flat_trajectory.size(); start += dof)
  {
    trajectory_msgs::JointTrajectoryPoint point;
    point.positions.assign(flat_trajectory.begin() + start, flat_trajectory.begin() + start + dof);
    point.time_from_start = ros::Duration(static_cast<double>(start / dof));
    trajectory.joint_trajectory.points.push_back(point);
  }
  moveit::core::RobotState start_state(robot_model);
  start_state.setToDefaultValues();
  auto robot_trajectory = std::make_shared<robot_trajectory::RobotTrajectory>(robot_model, group_name);
  robot_trajectory->setRobotTrajectoryMsg(start_state, trajectory);
  bool traced = false;
  if (use_robot_trajectory)
  {
    traced = by_group ? visual_tools.publishTrajectoryLine(robot_trajectory, joint_model_group) :
                        visual_tools.publishTrajectoryLine(robot_trajectory, robot_model->getLinkModel(tip_link));
  }
  else
  {
    traced = by_group ? visual_tools.publishTrajectoryLine(trajectory, joint_model_group) :
                        visual_tools.publishTrajectoryLine(trajectory, robot_model->getLinkModel(tip_link),
                                                           joint_model_group);
  }
  if (!traced)
  {
    ROS_ERROR("visual_tools_demo: publishTrajectoryLine failed");
    return 1;
  }

  if (use_robot_trajectory)
    visual_tools.publishTrajectoryPath(*robot_trajectory);
  else
    visual_tools.publishTrajectoryPath(trajectory, start_state);
  visual_tools.publishRobotState(trajectory.joint_trajectory.points.back().positions, joint_model_group, rvt::ORANGE);
  visual_tools.trigger();

  visual_tools.prompt("Press 'next' in the RvizVisualToolsGui window to continue the demo");

  visual_tools.publishText(text_pose, "Demo finished", rvt::WHITE, rvt::XLARGE);
  visual_tools.trigger();
  // Exiting now could drop the last message before it leaves the socket: stay until rostest
  // ends the test
  ros::waitForShutdown();
  return 0;
}

// moveit_visual_tools::MoveItVisualTools, written anew with upstream's semantics
// (moveit_visual_tools noetic-devel 3.6.1 src/moveit_visual_tools.cpp; "l." below are its lines).
#include <moveit_visual_tools/moveit_visual_tools.h>

#include <moveit/robot_state/conversions.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace moveit_visual_tools
{
namespace
{
const std::string LOGNAME = "visual_tools";

// Queues of the DisplayTrajectory and DisplayRobotState publishers (l. 346, 364)
const std::size_t DISPLAY_PATH_QUEUE_SIZE = 10;
const std::size_t ROBOT_STATE_QUEUE_SIZE = 1;
// A trajectory line's cylinders: radius in metres (l. 1360)
const double TRAJECTORY_LINE_RADIUS = 0.005;
// An untimed DisplayTrajectory lasts this long a waypoint in rviz (l. 1273-1276)
const double RVIZ_SECONDS_PER_WAYPOINT = 0.05;
// A RobotTrajectory without times is shown this many seconds a waypoint ("1 hz" in the comment, i * 2 in the code:
// l. 1213-1223)
const double UNTIMED_WAYPOINT_SECONDS = 2.0;
// A blocking publishTrajectoryPath checks ROS every so often while waiting (l. 1281)
const double ANIMATION_CHECK_INTERVAL = 0.25;
// showJointLimits draws a joint's range in this many steps (l. 1592)
const double JOINT_LIMIT_STEPS = 20.0;
// The virtual joint applyVirtualJointTransform moves (l. 1639, 1668)
const std::string VJOINT_NAME = "virtual_joint";

const char* const CONSOLE_RED = "\033[31m";
const char* const CONSOLE_RESET = "\033[0m";

// publishTrajectoryLine by group: publish_tip for each end-effector tip of arm_jmg, false at the first that fails or
// when the group has none (l. 1369-1394 and 1403-1428, the same for a message and a RobotTrajectory)
template <typename PublishTip>
bool publishForEachTip(const moveit::core::JointModelGroup* arm_jmg, PublishTip publish_tip)
{
  if (!arm_jmg)
  {
    ROS_FATAL_STREAM_NAMED(LOGNAME, "arm_jmg is NULL");
    return false;
  }
  std::vector<const moveit::core::LinkModel*> tips;
  if (!arm_jmg->getEndEffectorTips(tips) || tips.empty())
  {
    ROS_ERROR_STREAM_NAMED(LOGNAME, "Unable to get end effector tips from jmg");
    return false;
  }
  for (const moveit::core::LinkModel* tip : tips)
  {
    if (!publish_tip(tip))
      return false;
  }
  return true;
}
}  // namespace

MoveItVisualTools::MoveItVisualTools()
  : RvizVisualTools("", rviz_visual_tools::RVIZ_MARKER_TOPIC)
  , robot_state_topic_(DISPLAY_ROBOT_STATE_TOPIC)
  , planning_scene_topic_(PLANNING_SCENE_TOPIC)
{
  // Markers in the model frame of robot_description (l. 70-77)
  if (loadSharedRobotState())
  {
    setBaseFrame(robot_model_->getModelFrame());
  }
}

MoveItVisualTools::MoveItVisualTools(const std::string& base_frame, const std::string& marker_topic,
                                     moveit::core::RobotModelConstPtr robot_model)
  : RvizVisualTools(base_frame, marker_topic)
  , robot_state_topic_(DISPLAY_ROBOT_STATE_TOPIC)
  , planning_scene_topic_(PLANNING_SCENE_TOPIC)
  , robot_model_(std::move(robot_model))
{
  // Upstream's constructor leaves the robot state topic empty (l. 88-92), so that its
  // DisplayRobotState went to the node's own name; here it is DISPLAY_ROBOT_STATE_TOPIC, as
  // with the other constructors.
}

bool MoveItVisualTools::loadSharedRobotState()
{
  // The model given, else robot_description's (upstream asks its PlanningSceneMonitor, which
  // loads robot_description the same way, l. 207-233)
  if (shared_robot_state_)
  {
    return true;
  }
  if (!robot_model_)
  {
    rm_loader_ = std::make_shared<robot_model_loader::RobotModelLoader>(ROBOT_DESCRIPTION);
    robot_model_ = rm_loader_->getModel();
    if (!robot_model_)
    {
      ROS_ERROR_STREAM_NAMED(LOGNAME, "Unable to load the robot model from '" << ROBOT_DESCRIPTION << "'");
      return false;
    }
  }
  shared_robot_state_ = std::make_shared<moveit::core::RobotState>(robot_model_);
  shared_robot_state_->setToDefaultValues();
  shared_robot_state_->update(true);
  hidden_robot_state_ = std::make_shared<moveit::core::RobotState>(*shared_robot_state_);
  root_robot_state_ = std::make_shared<moveit::core::RobotState>(*shared_robot_state_);
  return true;
}

moveit::core::RobotStatePtr& MoveItVisualTools::getSharedRobotState()
{
  loadSharedRobotState();
  return shared_robot_state_;
}

moveit::core::RobotModelConstPtr MoveItVisualTools::getRobotModel()
{
  loadSharedRobotState();
  return robot_model_;
}

void MoveItVisualTools::loadTrajectoryPub(const std::string& display_planned_path_topic, bool blocking)
{
  if (pub_display_path_)
  {
    return;
  }
  pub_display_path_ =
      nh_.advertise<moveit_msgs::DisplayTrajectory>(display_planned_path_topic, DISPLAY_PATH_QUEUE_SIZE, false);
  ROS_DEBUG_STREAM_NAMED(LOGNAME, "Publishing MoveIt trajectory on topic " << pub_display_path_.getTopic());
  if (blocking)
  {
    waitForSubscriber(pub_display_path_);
  }
}

void MoveItVisualTools::loadRobotStatePub(const std::string& robot_state_topic, bool blocking)
{
  if (pub_robot_state_)
  {
    return;
  }
  if (!robot_state_topic.empty())
  {
    robot_state_topic_ = robot_state_topic;
  }
  pub_robot_state_ = nh_.advertise<moveit_msgs::DisplayRobotState>(robot_state_topic_, ROBOT_STATE_QUEUE_SIZE);
  ROS_DEBUG_STREAM_NAMED(LOGNAME, "Publishing MoveIt robot state on topic " << pub_robot_state_.getTopic());
  if (blocking)
  {
    waitForSubscriber(pub_robot_state_);
  }
}

bool MoveItVisualTools::notProvided(const std::string& method) const
{
  ROS_ERROR_STREAM_NAMED(LOGNAME, "MoveItVisualTools::" << method
                                                        << " is not provided here (compat/moveit_visual_tools: there "
                                                           "is no C++ PlanningSceneMonitor): add collision objects "
                                                           "with moveit::planning_interface::PlanningSceneInterface");
  return false;
}

bool MoveItVisualTools::loadPlanningSceneMonitor()
{
  return notProvided("loadPlanningSceneMonitor");
}

bool MoveItVisualTools::processCollisionObjectMsg(const moveit_msgs::CollisionObject& /*msg*/,
                                                  const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("processCollisionObjectMsg");
}

bool MoveItVisualTools::processAttachedCollisionObjectMsg(const moveit_msgs::AttachedCollisionObject& /*msg*/)
{
  return notProvided("processAttachedCollisionObjectMsg");
}

bool MoveItVisualTools::moveCollisionObject(const Eigen::Isometry3d& /*pose*/, const std::string& /*name*/,
                                            const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("moveCollisionObject");
}

bool MoveItVisualTools::moveCollisionObject(const geometry_msgs::Pose& /*pose*/, const std::string& /*name*/,
                                            const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("moveCollisionObject");
}

bool MoveItVisualTools::triggerPlanningSceneUpdate()
{
  return notProvided("triggerPlanningSceneUpdate");
}

bool MoveItVisualTools::removeAllCollisionObjects()
{
  return notProvided("removeAllCollisionObjects");
}

bool MoveItVisualTools::cleanupCO(const std::string& /*name*/)
{
  return notProvided("cleanupCO");
}

bool MoveItVisualTools::cleanupACO(const std::string& /*name*/)
{
  return notProvided("cleanupACO");
}

bool MoveItVisualTools::attachCO(const std::string& /*name*/, const std::string& /*ee_parent_link*/)
{
  return notProvided("attachCO");
}

bool MoveItVisualTools::publishCollisionFloor(double /*z*/, const std::string& /*plane_name*/,
                                              const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("publishCollisionFloor");
}

bool MoveItVisualTools::publishCollisionBlock(const geometry_msgs::Pose& /*block_pose*/,
                                              const std::string& /*block_name*/, double /*block_size*/,
                                              const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("publishCollisionBlock");
}

bool MoveItVisualTools::publishCollisionCuboid(const Eigen::Vector3d& /*point1*/, const Eigen::Vector3d& /*point2*/,
                                               const std::string& /*name*/,
                                               const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("publishCollisionCuboid");
}

bool MoveItVisualTools::publishCollisionCuboid(const geometry_msgs::Point& /*point1*/,
                                               const geometry_msgs::Point& /*point2*/, const std::string& /*name*/,
                                               const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("publishCollisionCuboid");
}

bool MoveItVisualTools::publishCollisionCuboid(const Eigen::Isometry3d& /*pose*/, double /*width*/, double /*depth*/,
                                               double /*height*/, const std::string& /*name*/,
                                               const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("publishCollisionCuboid");
}

bool MoveItVisualTools::publishCollisionCuboid(const geometry_msgs::Pose& /*pose*/, double /*width*/,
                                               double /*depth*/, double /*height*/, const std::string& /*name*/,
                                               const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("publishCollisionCuboid");
}

bool MoveItVisualTools::publishCollisionCylinder(const geometry_msgs::Point& /*a*/, const geometry_msgs::Point& /*b*/,
                                                 const std::string& /*object_name*/, double /*radius*/,
                                                 const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("publishCollisionCylinder");
}

bool MoveItVisualTools::publishCollisionCylinder(const Eigen::Vector3d& /*a*/, const Eigen::Vector3d& /*b*/,
                                                 const std::string& /*object_name*/, double /*radius*/,
                                                 const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("publishCollisionCylinder");
}

bool MoveItVisualTools::publishCollisionCylinder(const Eigen::Isometry3d& /*object_pose*/,
                                                 const std::string& /*object_name*/, double /*radius*/,
                                                 double /*height*/, const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("publishCollisionCylinder");
}

bool MoveItVisualTools::publishCollisionCylinder(const geometry_msgs::Pose& /*object_pose*/,
                                                 const std::string& /*object_name*/, double /*radius*/,
                                                 double /*height*/, const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("publishCollisionCylinder");
}

bool MoveItVisualTools::publishCollisionMesh(const geometry_msgs::Pose& /*object_pose*/,
                                             const std::string& /*object_name*/, const std::string& /*mesh_path*/,
                                             const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("publishCollisionMesh");
}

bool MoveItVisualTools::publishCollisionMesh(const Eigen::Isometry3d& /*object_pose*/,
                                             const std::string& /*object_name*/, const std::string& /*mesh_path*/,
                                             const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("publishCollisionMesh");
}

bool MoveItVisualTools::publishCollisionMesh(const Eigen::Isometry3d& /*object_pose*/,
                                             const std::string& /*object_name*/, const shape_msgs::Mesh& /*mesh_msg*/,
                                             const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("publishCollisionMesh");
}

bool MoveItVisualTools::publishCollisionMesh(const geometry_msgs::Pose& /*object_pose*/,
                                             const std::string& /*object_name*/, const shape_msgs::Mesh& /*mesh_msg*/,
                                             const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("publishCollisionMesh");
}

bool MoveItVisualTools::publishCollisionWall(double /*x*/, double /*y*/, double /*angle*/, double /*width*/,
                                             double /*height*/, const std::string& /*name*/,
                                             const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("publishCollisionWall");
}

bool MoveItVisualTools::publishCollisionWall(double /*x*/, double /*y*/, double /*z*/, double /*angle*/,
                                             double /*width*/, double /*height*/, const std::string& /*name*/,
                                             const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("publishCollisionWall");
}

bool MoveItVisualTools::publishCollisionTable(double /*x*/, double /*y*/, double /*z*/, double /*angle*/,
                                              double /*width*/, double /*height*/, double /*depth*/,
                                              const std::string& /*name*/, const rviz_visual_tools::colors& /*color*/)
{
  return notProvided("publishCollisionTable");
}

bool MoveItVisualTools::loadCollisionSceneFromFile(const std::string& /*path*/)
{
  return notProvided("loadCollisionSceneFromFile");
}

bool MoveItVisualTools::loadCollisionSceneFromFile(const std::string& /*path*/, const Eigen::Isometry3d& /*offset*/)
{
  return notProvided("loadCollisionSceneFromFile");
}

bool MoveItVisualTools::publishWorkspaceParameters(const moveit_msgs::WorkspaceParameters& params)
{
  // l. 1064-1068
  return publishCuboid(convertPoint(params.min_corner), convertPoint(params.max_corner), rviz_visual_tools::TRANSLUCENT,
                       "Planning_Workspace", 1);
}

bool MoveItVisualTools::publishIKSolutions(const std::vector<trajectory_msgs::JointTrajectoryPoint>& ik_solutions,
                                           const moveit::core::JointModelGroup* arm_jmg, double display_time)
{
  // Each solution display_time after the previous, the last one repeated so that it shows
  // whole (l. 544-584)
  if (ik_solutions.empty())
  {
    ROS_WARN_STREAM_NAMED(LOGNAME, "Empty ik_solutions vector passed into publishIKSolutions()");
    return false;
  }
  if (!loadSharedRobotState())
  {
    return false;
  }
  moveit_msgs::RobotTrajectory trajectory_msg;
  trajectory_msg.joint_trajectory.header.frame_id = base_frame_;
  trajectory_msg.joint_trajectory.joint_names = arm_jmg->getActiveJointModelNames();
  double running_time = 0;
  for (const trajectory_msgs::JointTrajectoryPoint& solution : ik_solutions)
  {
    trajectory_msgs::JointTrajectoryPoint timed = solution;
    timed.time_from_start = ros::Duration(running_time);
    trajectory_msg.joint_trajectory.points.push_back(timed);
    running_time += display_time;
  }
  trajectory_msgs::JointTrajectoryPoint last = trajectory_msg.joint_trajectory.points.back();
  last.time_from_start = ros::Duration(running_time);
  trajectory_msg.joint_trajectory.points.push_back(last);
  return publishTrajectoryPath(trajectory_msg, *shared_robot_state_, true);
}

bool MoveItVisualTools::publishTrajectoryPoint(const trajectory_msgs::JointTrajectoryPoint& trajectory_pt,
                                               const std::string& planning_group, double display_time)
{
  // The point at 0 and again at display_time (l. 1145-1172)
  if (!loadSharedRobotState())
  {
    return false;
  }
  const moveit::core::JointModelGroup* jmg = robot_model_->getJointModelGroup(planning_group);
  if (jmg == nullptr)
  {
    ROS_ERROR_STREAM_NAMED("publishTrajectoryPoint", "Could not find joint model group " << planning_group);
    return false;
  }
  trajectory_msgs::JointTrajectoryPoint timed = trajectory_pt;
  timed.time_from_start = ros::Duration(display_time);
  moveit_msgs::RobotTrajectory trajectory_msg;
  trajectory_msg.joint_trajectory.header.frame_id = base_frame_;
  trajectory_msg.joint_trajectory.joint_names = jmg->getJointModelNames();
  trajectory_msg.joint_trajectory.points.push_back(trajectory_pt);
  trajectory_msg.joint_trajectory.points.push_back(timed);
  return publishTrajectoryPath(trajectory_msg, *shared_robot_state_, true);
}

bool MoveItVisualTools::publishTrajectoryPath(const std::vector<moveit::core::RobotStatePtr>& trajectory,
                                              const moveit::core::JointModelGroup* jmg, double speed, bool blocking)
{
  // The group's positions of each state. Upstream adds each state `duration_from_previous`
  // after the one before while that duration grows by `speed` each time (l. 1183-1188), so
  // state k is shown at speed * (k + 1) * (k + 2) / 2 s: kept.
  moveit_msgs::RobotTrajectory trajectory_msg;
  trajectory_msg.joint_trajectory.joint_names = jmg->getVariableNames();
  double duration_from_previous = 0;
  double time_from_start = 0;
  for (const moveit::core::RobotStatePtr& state : trajectory)
  {
    duration_from_previous += speed;
    time_from_start += duration_from_previous;
    trajectory_msgs::JointTrajectoryPoint point;
    state->copyJointGroupPositions(jmg, point.positions);
    point.time_from_start = ros::Duration(time_from_start);
    trajectory_msg.joint_trajectory.points.push_back(point);
  }
  moveit_msgs::RobotState start_msg;
  if (!trajectory.empty())
  {
    moveit::core::robotStateToRobotStateMsg(*trajectory.front(), start_msg);
  }
  return publishTrajectoryPath(trajectory_msg, start_msg, blocking);
}

bool MoveItVisualTools::publishTrajectoryPath(const moveit_msgs::RobotTrajectory& trajectory_msg,
                                              const moveit::core::RobotStateConstPtr& robot_state, bool blocking)
{
  return publishTrajectoryPath(trajectory_msg, *robot_state, blocking);
}

bool MoveItVisualTools::publishTrajectoryPath(const moveit_msgs::RobotTrajectory& trajectory_msg,
                                              const moveit::core::RobotState& robot_state, bool blocking)
{
  moveit_msgs::RobotState start_msg;
  moveit::core::robotStateToRobotStateMsg(robot_state, start_msg);
  return publishTrajectoryPath(trajectory_msg, start_msg, blocking);
}

bool MoveItVisualTools::publishTrajectoryPath(const moveit_msgs::RobotTrajectory& trajectory_msg,
                                              const moveit_msgs::RobotState& robot_state, bool blocking)
{
  // One trajectory in a DisplayTrajectory named by the model (l. 1248-1293)
  if (trajectory_msg.joint_trajectory.points.empty())
  {
    ROS_WARN_STREAM_NAMED(LOGNAME, "Unable to publish trajectory path because trajectory has zero points");
    return false;
  }
  if (!loadSharedRobotState())
  {
    return false;
  }
  moveit_msgs::DisplayTrajectory display_trajectory_msg;
  display_trajectory_msg.model_id = robot_model_->getName();
  display_trajectory_msg.trajectory.push_back(trajectory_msg);
  display_trajectory_msg.trajectory_start = robot_state;
  publishTrajectoryPath(display_trajectory_msg);

  if (blocking)
  {
    double duration = trajectory_msg.joint_trajectory.points.back().time_from_start.toSec();
    if (duration < std::numeric_limits<double>::epsilon())
    {
      duration = RVIZ_SECONDS_PER_WAYPOINT * trajectory_msg.joint_trajectory.points.size();
    }
    ROS_DEBUG_STREAM_NAMED(LOGNAME, "Waiting for trajectory animation " << duration << " seconds");
    // The animation's own length in rviz: nothing here can tell when rviz has shown it
    for (double waited = 0; ros::ok() && waited <= duration; waited += ANIMATION_CHECK_INTERVAL)
    {
      ros::Duration(ANIMATION_CHECK_INTERVAL).sleep();
    }
  }
  return true;
}

void MoveItVisualTools::publishTrajectoryPath(const moveit_msgs::DisplayTrajectory& display_trajectory_msg)
{
  loadTrajectoryPub();
  pub_display_path_.publish(display_trajectory_msg);
  ros::spinOnce();
}

bool MoveItVisualTools::linkPoses(const moveit_msgs::RobotTrajectory& trajectory_msg,
                                  const moveit::core::LinkModel* link, EigenSTL::vector_Isometry3d& poses)
{
  // Each point's positions set by name on a copy of the shared state (default values for the
  // joints the message does not name), as RobotTrajectory::setRobotTrajectoryMsg does for
  // upstream (l. 1317-1321)
  const trajectory_msgs::JointTrajectory& joint_trajectory = trajectory_msg.joint_trajectory;
  const std::vector<std::string>& variables = robot_model_->getVariableNames();
  for (const std::string& name : joint_trajectory.joint_names)
  {
    if (std::find(variables.begin(), variables.end(), name) == variables.end())
    {
      ROS_ERROR_STREAM_NAMED(LOGNAME, "The trajectory's joint '" << name << "' is not in the model '"
                                                                 << robot_model_->getName() << "'");
      return false;
    }
  }
  moveit::core::RobotState state(*shared_robot_state_);
  for (std::size_t i = 0; i < joint_trajectory.points.size(); ++i)
  {
    if (joint_trajectory.points[i].positions.size() != joint_trajectory.joint_names.size())
    {
      ROS_ERROR_STREAM_NAMED(LOGNAME, "Trajectory point " << i << " has " << joint_trajectory.points[i].positions.size()
                                                          << " positions for " << joint_trajectory.joint_names.size()
                                                          << " joints");
      return false;
    }
    moveit::core::jointTrajPointToRobotState(joint_trajectory, i, state);
    state.update();
    poses.push_back(state.getGlobalLinkTransform(link));
  }
  return true;
}

bool MoveItVisualTools::publishTrajectoryLine(const moveit_msgs::RobotTrajectory& trajectory_msg,
                                              const moveit::core::LinkModel* ee_parent_link,
                                              const moveit::core::JointModelGroup* arm_jmg,
                                              const rviz_visual_tools::colors& color)
{
  // A MEDIUM sphere at the link in each waypoint and 5 mm cylinders between them (l. 1303-1367)
  if (!arm_jmg)
  {
    ROS_FATAL_STREAM_NAMED(LOGNAME, "arm_jmg is NULL");
    return false;
  }
  if (!ee_parent_link)
  {
    ROS_FATAL_STREAM_NAMED(LOGNAME, "ee_parent_link is NULL");
    return false;
  }
  if (!loadSharedRobotState())
  {
    return false;
  }
  // The link may come from another instance of the same robot's model (a MoveGroupInterface's,
  // as in MoveIt's tutorial): this model's link of that name is traced.
  const moveit::core::LinkModel* link = robot_model_->getLinkModel(ee_parent_link->getName());
  if (!link)
  {
    ROS_ERROR_STREAM_NAMED(LOGNAME, "Link '" << ee_parent_link->getName() << "' is not in the model '"
                                             << robot_model_->getName() << "'");
    return false;
  }
  EigenSTL::vector_Isometry3d tip_poses;
  if (!linkPoses(trajectory_msg, link, tip_poses))
  {
    return false;
  }
  EigenSTL::vector_Vector3d path;
  for (std::size_t i = 0; i < tip_poses.size(); ++i)
  {
    if (std::isnan(tip_poses[i].translation().x()))
    {
      ROS_ERROR_STREAM_NAMED(LOGNAME, "NAN DETECTED AT TRAJECTORY POINT i=" << i);
      return false;
    }
    path.push_back(tip_poses[i].translation());
    publishSphere(tip_poses[i], color, rviz_visual_tools::MEDIUM);
  }
  publishPath(path, color, TRAJECTORY_LINE_RADIUS);
  return true;
}

bool MoveItVisualTools::publishTrajectoryLine(const moveit_msgs::RobotTrajectory& trajectory_msg,
                                              const moveit::core::JointModelGroup* arm_jmg,
                                              const rviz_visual_tools::colors& color)
{
  return publishForEachTip(arm_jmg, [&](const moveit::core::LinkModel* tip) {
    return publishTrajectoryLine(trajectory_msg, tip, arm_jmg, color);
  });
}

bool MoveItVisualTools::publishTrajectoryPath(const robot_trajectory::RobotTrajectoryPtr& trajectory, bool blocking)
{
  return publishTrajectoryPath(*trajectory, blocking);
}

bool MoveItVisualTools::publishTrajectoryPath(const robot_trajectory::RobotTrajectory& trajectory, bool blocking)
{
  // The message of the trajectory, started at its first waypoint; when the second point has no time the points are
  // spread UNTIMED_WAYPOINT_SECONDS apart (l. 1208-1231)
  moveit_msgs::RobotTrajectory trajectory_msg;
  trajectory.getRobotTrajectoryMsg(trajectory_msg);
  std::vector<trajectory_msgs::JointTrajectoryPoint>& points = trajectory_msg.joint_trajectory.points;
  if (points.size() > 1 && points[1].time_from_start == ros::Duration(0))
  {
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      points[i].time_from_start = ros::Duration(UNTIMED_WAYPOINT_SECONDS * static_cast<double>(i));
    }
  }
  moveit_msgs::RobotState start_msg;
  if (!trajectory.empty())
  {
    moveit::core::robotStateToRobotStateMsg(trajectory.getFirstWayPoint(), start_msg);
  }
  return publishTrajectoryPath(trajectory_msg, start_msg, blocking);
}

bool MoveItVisualTools::publishTrajectoryLine(const robot_trajectory::RobotTrajectoryPtr& robot_trajectory,
                                              const moveit::core::LinkModel* ee_parent_link,
                                              const rviz_visual_tools::colors& color)
{
  return publishTrajectoryLine(*robot_trajectory, ee_parent_link, color);
}

bool MoveItVisualTools::publishTrajectoryLine(const robot_trajectory::RobotTrajectory& robot_trajectory,
                                              const moveit::core::LinkModel* ee_parent_link,
                                              const rviz_visual_tools::colors& color)
{
  // The link's pose in each waypoint, a MEDIUM sphere there and 5 mm cylinders between (l. 1333-1367)
  if (!ee_parent_link)
  {
    ROS_FATAL_STREAM_NAMED(LOGNAME, "ee_parent_link is NULL");
    return false;
  }
  EigenSTL::vector_Vector3d path;
  for (std::size_t i = 0; i < robot_trajectory.getWayPointCount(); ++i)
  {
    const moveit::core::RobotState& waypoint = robot_trajectory.getWayPoint(i);
    // the link may come from another model of the same robot: the waypoint's link of that name
    const moveit::core::LinkModel* link = waypoint.getRobotModel()->getLinkModel(ee_parent_link->getName());
    if (!link)
    {
      ROS_ERROR_STREAM_NAMED(LOGNAME, "Link '" << ee_parent_link->getName() << "' is not in the trajectory's model '"
                                               << waypoint.getRobotModel()->getName() << "'");
      return false;
    }
    const Eigen::Isometry3d& tip_pose = waypoint.getGlobalLinkTransform(link);
    if (std::isnan(tip_pose.translation().x()))
    {
      ROS_ERROR_STREAM_NAMED(LOGNAME, "NAN DETECTED AT TRAJECTORY POINT i=" << i);
      return false;
    }
    path.push_back(tip_pose.translation());
    publishSphere(tip_pose, color, rviz_visual_tools::MEDIUM);
  }
  publishPath(path, color, TRAJECTORY_LINE_RADIUS);
  return true;
}

bool MoveItVisualTools::publishTrajectoryLine(const robot_trajectory::RobotTrajectoryPtr& robot_trajectory,
                                              const moveit::core::JointModelGroup* arm_jmg,
                                              const rviz_visual_tools::colors& color)
{
  return publishTrajectoryLine(*robot_trajectory, arm_jmg, color);
}

bool MoveItVisualTools::publishTrajectoryLine(const robot_trajectory::RobotTrajectory& robot_trajectory,
                                              const moveit::core::JointModelGroup* arm_jmg,
                                              const rviz_visual_tools::colors& color)
{
  return publishForEachTip(arm_jmg, [&](const moveit::core::LinkModel* tip) {
    return publishTrajectoryLine(robot_trajectory, tip, color);
  });
}

bool MoveItVisualTools::publishTrajectoryPoints(const std::vector<moveit::core::RobotStatePtr>& robot_state_trajectory,
                                                const moveit::core::LinkModel* ee_parent_link,
                                                const rviz_visual_tools::colors& color)
{
  for (const moveit::core::RobotStatePtr& state : robot_state_trajectory)
  {
    const moveit::core::LinkModel* link = state->getRobotModel()->getLinkModel(ee_parent_link->getName());
    publishSphere(state->getGlobalLinkTransform(link), color);
  }
  return true;
}

void MoveItVisualTools::enableRobotStateRootOffet(const Eigen::Isometry3d& offset)
{
  robot_state_root_offset_enabled_ = true;
  robot_state_root_offset_ = offset;
}

void MoveItVisualTools::disableRobotStateRootOffet()
{
  robot_state_root_offset_enabled_ = false;
}

bool MoveItVisualTools::publishRobotState(const trajectory_msgs::JointTrajectoryPoint& trajectory_pt,
                                          const moveit::core::JointModelGroup* jmg,
                                          const rviz_visual_tools::colors& color)
{
  return publishRobotState(trajectory_pt.positions, jmg, color);
}

bool MoveItVisualTools::publishRobotState(const std::vector<double>& joint_positions,
                                          const moveit::core::JointModelGroup* jmg,
                                          const rviz_visual_tools::colors& color)
{
  // The group's positions on default values elsewhere (l. 1462-1475)
  if (!loadSharedRobotState())
  {
    return false;
  }
  shared_robot_state_->setToDefaultValues();
  shared_robot_state_->setJointGroupPositions(jmg, joint_positions);
  return publishRobotState(*shared_robot_state_, color);
}

bool MoveItVisualTools::publishRobotState(const moveit::core::RobotStatePtr& robot_state,
                                          const rviz_visual_tools::colors& color,
                                          const std::vector<std::string>& highlight_links)
{
  return publishRobotState(*robot_state, color, highlight_links);
}

bool MoveItVisualTools::publishRobotState(const moveit::core::RobotState& robot_state,
                                          const rviz_visual_tools::colors& color,
                                          const std::vector<std::string>& highlight_links)
{
  // One cached message per colour, its highlights made on first use (l. 1484-1548). Upstream
  // colours the links that have collision geometry; this moveit_core does not model geometry, so
  // every link is named (rviz's RobotState display skips links it draws nothing for).
  const rviz_visual_tools::colors base_color = highlight_links.empty() ? color : rviz_visual_tools::DEFAULT;
  moveit_msgs::DisplayRobotState& display_robot_msg = display_robot_msgs_[base_color];
  if (display_robot_msg.highlight_links.empty() && color != rviz_visual_tools::DEFAULT)
  {
    const std::vector<std::string>& link_names =
        highlight_links.empty() ? robot_state.getRobotModel()->getLinkModelNames() : highlight_links;
    const std_msgs::ColorRGBA color_rgba = getColor(color);
    for (const std::string& link_name : link_names)
    {
      moveit_msgs::ObjectColor object_color;
      object_color.id = link_name;
      object_color.color = color_rgba;
      display_robot_msg.highlight_links.push_back(object_color);
    }
  }

  if (robot_state_root_offset_enabled_ && loadSharedRobotState())
  {
    *shared_robot_state_ = robot_state;
    applyVirtualJointTransform(*shared_robot_state_, robot_state_root_offset_);
    moveit::core::robotStateToRobotStateMsg(*shared_robot_state_, display_robot_msg.state);
  }
  else
  {
    moveit::core::robotStateToRobotStateMsg(robot_state, display_robot_msg.state);
  }
  publishRobotState(display_robot_msg);

  if (!highlight_links.empty())
  {
    display_robot_msg.highlight_links.clear();
  }
  return true;
}

void MoveItVisualTools::publishRobotState(const moveit_msgs::DisplayRobotState& display_robot_state_msg)
{
  loadRobotStatePub();
  pub_robot_state_.publish(display_robot_state_msg);
  ros::spinOnce();
}

bool MoveItVisualTools::hideRobot()
{
  moveit_msgs::DisplayRobotState display_robot_state_msg;
  display_robot_state_msg.hide = true;
  publishRobotState(display_robot_state_msg);
  return true;
}

void MoveItVisualTools::showJointLimits(const moveit::core::RobotStatePtr& robot_state)
{
  // A bar of the range with | at the position, red when out of bounds (l. 1568-1623)
  for (const moveit::core::JointModel* joint : robot_state->getRobotModel()->getActiveJointModels())
  {
    if (joint->getVariableCount() > 1)
    {
      continue;
    }
    const double current_value = robot_state->getVariablePosition(joint->getName());
    const bool out_of_bounds = !robot_state->satisfiesBounds(joint);
    const moveit::core::VariableBounds& bound = joint->getVariableBounds()[0];
    if (out_of_bounds)
    {
      std::cout << CONSOLE_RED;
    }
    std::cout << "   " << std::fixed << std::setprecision(5) << bound.min_position_ << "\t";
    const double step = (bound.max_position_ - bound.min_position_) / JOINT_LIMIT_STEPS;
    bool marker_shown = false;
    for (double value = bound.min_position_; value < bound.max_position_; value += step)
    {
      if (!marker_shown && current_value < value)
      {
        std::cout << "|";
        marker_shown = true;
      }
      else
      {
        std::cout << "-";
      }
    }
    std::cout << " \t" << std::fixed << std::setprecision(5) << bound.max_position_ << "  \t" << joint->getName()
              << " current: " << std::fixed << std::setprecision(5) << current_value << std::endl;
    if (out_of_bounds)
    {
      std::cout << CONSOLE_RESET;
    }
  }
}

bool MoveItVisualTools::checkForVirtualJoint(const moveit::core::RobotState& robot_state)
{
  // A floating joint named "virtual_joint" (l. 1637-1663)
  const moveit::core::RobotModelConstPtr& model = robot_state.getRobotModel();
  if (!model->hasJointModel(VJOINT_NAME))
  {
    ROS_WARN_STREAM_NAMED("moveit_visual_tools", "Joint '" << VJOINT_NAME << "' does not exist.");
    return false;
  }
  if (!model->getJointModel(VJOINT_NAME)->hasVariable(VJOINT_NAME + "/trans_x"))
  {
    ROS_WARN_STREAM_NAMED("moveit_visual_tools", "Variables for joint '" << VJOINT_NAME
                                                                         << "' do not exist. Try making this vjoint "
                                                                            "floating");
    ROS_WARN_STREAM_NAMED("moveit_visual_tools", "The only available joint variables are:");
    for (const std::string& name : model->getJointModel(VJOINT_NAME)->getVariableNames())
    {
      std::cout << name << "\n";
    }
    return false;
  }
  return true;
}

bool MoveItVisualTools::applyVirtualJointTransform(moveit::core::RobotState& robot_state,
                                                   const Eigen::Isometry3d& offset)
{
  // l. 1665-1691
  if (!checkForVirtualJoint(robot_state))
  {
    ROS_WARN_STREAM_NAMED("moveit_visual_tools", "Unable to apply virtual joint transform, hideRobot() functionality "
                                                 "is disabled");
    return false;
  }
  robot_state.setVariablePosition(VJOINT_NAME + "/trans_x", offset.translation().x());
  robot_state.setVariablePosition(VJOINT_NAME + "/trans_y", offset.translation().y());
  robot_state.setVariablePosition(VJOINT_NAME + "/trans_z", offset.translation().z());
  const Eigen::Quaterniond q(offset.rotation());
  robot_state.setVariablePosition(VJOINT_NAME + "/rot_x", q.x());
  robot_state.setVariablePosition(VJOINT_NAME + "/rot_y", q.y());
  robot_state.setVariablePosition(VJOINT_NAME + "/rot_z", q.z());
  robot_state.setVariablePosition(VJOINT_NAME + "/rot_w", q.w());
  return true;
}

}  // namespace moveit_visual_tools

// MoveIt's MoveGroupInterface over this workspace's move_group. What each call sends, and which goal fields it fills,
// follows MoveIt's moveit_ros/planning_interface/move_group_interface/src/move_group_interface.cpp (noetic-devel
// 7c0343f0, "upstream" below, cited by line); the code is this workspace's.
#include <moveit/move_group_interface/move_group_interface.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include <moveit/common_planning_interface_objects/common_objects.h>
#include <moveit/kinematic_constraints/utils.h>
#include <moveit/robot_state/conversions.h>
#include <moveit_msgs/ApplyPlanningScene.h>
#include <moveit_msgs/ExecuteTrajectoryAction.h>
#include <moveit_msgs/GetCartesianPath.h>
#include <moveit_msgs/GetPlannerParams.h>
#include <moveit_msgs/GraspPlanning.h>
#include <moveit_msgs/PickupAction.h>
#include <moveit_msgs/PlaceAction.h>
#include <moveit_msgs/QueryPlannerInterfaces.h>
#include <moveit_msgs/SetPlannerParams.h>
#include <random_numbers/random_numbers.h>
#include <moveit/planning_scene_interface/planning_scene_interface.h>
#include <ros/callback_queue.h>
#include <std_msgs/String.h>
#include <tf2/LinearMath/Matrix3x3.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include "current_state_monitor.h"
#include "wait_for_subscriber.h"

namespace moveit
{
namespace planning_interface
{
const std::string MoveGroupInterface::ROBOT_DESCRIPTION = "robot_description";  // NOLINT
// defined here too: before C++17 a constant bound to a reference (ros::NodeHandle::param's default) needs a definition
constexpr double MoveGroupInterface::DEFAULT_GOAL_JOINT_TOLERANCE;
constexpr double MoveGroupInterface::DEFAULT_GOAL_POSITION_TOLERANCE;
constexpr double MoveGroupInterface::DEFAULT_GOAL_ORIENTATION_TOLERANCE;
constexpr double MoveGroupInterface::DEFAULT_ALLOWED_PLANNING_TIME;
constexpr int MoveGroupInterface::DEFAULT_NUM_PLANNING_ATTEMPTS;

namespace
{
const char LOGNAME[] = "move_group_interface";

// move_group's names (move_group/capability_names.h), relative to the interface's node handle
const char MOVE_ACTION[] = "move_group";
const char EXECUTE_ACTION[] = "execute_trajectory";
const char PICKUP_ACTION[] = "pickup";
const char PLACE_ACTION[] = "place";
const char QUERY_PLANNERS_SERVICE[] = "query_planner_interface";
const char GET_PLANNER_PARAMS_SERVICE[] = "get_planner_params";
const char SET_PLANNER_PARAMS_SERVICE[] = "set_planner_params";
const char CARTESIAN_PATH_SERVICE[] = "compute_cartesian_path";
const char APPLY_PLANNING_SCENE_SERVICE[] = "apply_planning_scene";
const char GRASP_PLANNING_SERVICE[] = "plan_grasps";
// trajectory_execution_manager's EXECUTION_EVENT_TOPIC
const char EXECUTION_EVENT_TOPIC[] = "trajectory_execution_event";

// While waiting for an action server, the node handle's queue is served this often (upstream l. 206, 224)
const double SERVER_POLL_SECONDS = 0.001;
// Scaling factors' fallback when robot_description_planning has none (upstream l. 144-146, 417-418)
const double DEFAULT_SCALING_FACTOR = 0.1;
// Seconds a state read for a query waits for joint_states (upstream getCurrentState's default, l. 661)
const double CURRENT_STATE_WAIT_SECONDS = 1.0;
// MoveIt's place locations (upstream posesToPlaceLocations, l. 696-699)
const double PRE_PLACE_MIN_DISTANCE = 0.1;
const double PRE_PLACE_DESIRED_DISTANCE = 0.2;
const double POST_PLACE_DESIRED_DISTANCE = 0.2;

enum ActiveTargetType
{
  JOINT,
  POSE,
  POSITION,
  ORIENTATION
};

std::string stripSlash(const std::string& frame)
{
  return !frame.empty() && frame[0] == '/' ? frame.substr(1) : frame;
}

Eigen::Isometry3d poseToEigen(const geometry_msgs::Pose& pose)
{
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  result.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  result.linear() =
      Eigen::Quaterniond(pose.orientation.w, pose.orientation.x, pose.orientation.y, pose.orientation.z)
          .normalized()
          .toRotationMatrix();
  return result;
}

geometry_msgs::Pose eigenToPose(const Eigen::Isometry3d& transform)
{
  geometry_msgs::Pose pose;
  pose.position.x = transform.translation().x();
  pose.position.y = transform.translation().y();
  pose.position.z = transform.translation().z();
  const Eigen::Quaterniond q(transform.rotation());
  pose.orientation.x = q.x();
  pose.orientation.y = q.y();
  pose.orientation.z = q.z();
  pose.orientation.w = q.w();
  return pose;
}

// How a call reports an action that did not succeed, as noetic-devel's move_group_interface.cpp does: plan() and
// execute() at INFO as "<state>: <text>" (l. 899-900, 938-939); move(), pick() and place() at WARN as
// "Fail: <state>: <text>" (l. 854-855, 764-765, 734-735)
enum class FailureReport
{
  INFO_STATE,
  WARN_FAIL
};

template <typename Action>
moveit::core::MoveItErrorCode waitForResult(actionlib::SimpleActionClient<Action>& client, const char* name,
                                            FailureReport report)
{
  if (!client.waitForResult())
    ROS_INFO_NAMED(LOGNAME, "%s action returned early", name);
  const actionlib::SimpleClientGoalState state = client.getState();
  if (state != actionlib::SimpleClientGoalState::SUCCEEDED)
  {
    if (report == FailureReport::WARN_FAIL)
      ROS_WARN_STREAM_NAMED(LOGNAME, "Fail: " << state.toString() << ": " << state.getText());
    else
      ROS_INFO_STREAM_NAMED(LOGNAME, state.toString() << ": " << state.getText());
  }
  auto result = client.getResult();
  // a goal lost before move_group answered leaves no result: a failure to communicate
  return result ? moveit::core::MoveItErrorCode(result->error_code) :
                  moveit::core::MoveItErrorCode(moveit_msgs::MoveItErrorCodes::COMMUNICATION_FAILURE);
}
}  // namespace

class MoveGroupInterface::MoveGroupInterfaceImpl
{
public:
  MoveGroupInterfaceImpl(const Options& opt, const std::shared_ptr<tf2_ros::Buffer>& tf_buffer,
                         const ros::WallDuration& wait_for_servers)
    : opt_(opt), node_handle_(opt.node_handle_), tf_buffer_(tf_buffer)
  {
    robot_model_ = opt.robot_model_ ? opt.robot_model_ : getSharedRobotModel(opt.robot_description_);
    if (!robot_model_)
      fail("Unable to construct robot model. Please make sure all needed information is on the parameter server "
           "(robot_description '" +
           opt.robot_description_ + "')");
    if (!robot_model_->hasJointModelGroup(opt.group_name_))
      fail("Group '" + opt.group_name_ + "' was not found.");
    joint_model_group_ = robot_model_->getJointModelGroup(opt.group_name_);

    setStartStateToCurrentState();
    joint_state_target_ = std::make_shared<moveit::core::RobotState>(robot_model_);
    joint_state_target_->setToDefaultValues();

    // tolerances and scaling factors from the config's parameters, as upstream l. 133-146
    const std::string desc = opt.robot_description_.empty() ? ROBOT_DESCRIPTION : opt.robot_description_;
    const std::string kinematics = desc + "_kinematics/" + opt.group_name_ + "/";
    node_handle_.param<double>(kinematics + "goal_joint_tolerance", goal_joint_tolerance_,
                               DEFAULT_GOAL_JOINT_TOLERANCE);
    node_handle_.param<double>(kinematics + "goal_position_tolerance", goal_position_tolerance_,
                               DEFAULT_GOAL_POSITION_TOLERANCE);
    node_handle_.param<double>(kinematics + "goal_orientation_tolerance", goal_orientation_tolerance_,
                               DEFAULT_GOAL_ORIENTATION_TOLERANCE);
    const std::string planning = desc + "_planning/";
    node_handle_.param<double>(planning + "default_velocity_scaling_factor", max_velocity_scaling_factor_,
                               DEFAULT_SCALING_FACTOR);
    node_handle_.param<double>(planning + "default_acceleration_scaling_factor", max_acceleration_scaling_factor_,
                               DEFAULT_SCALING_FACTOR);

    // a chain's end effector link is its last link (upstream l. 149-150)
    if (joint_model_group_->isChain())
      end_effector_link_ = joint_model_group_->getLinkModelNames().back();
    pose_reference_frame_ = robot_model_->getModelFrame();

    trajectory_event_publisher_ = node_handle_.advertise<std_msgs::String>(EXECUTION_EVENT_TOPIC, 1, false);
    state_monitor_ = std::make_unique<detail::CurrentStateMonitor>(robot_model_, node_handle_);

    // zero waits for ever (upstream l. 159-163)
    const ros::WallTime deadline =
        wait_for_servers == ros::WallDuration() ? ros::WallTime() : ros::WallTime::now() + wait_for_servers;
    const double allotted = wait_for_servers.toSec();
    move_client_ = std::make_unique<actionlib::SimpleActionClient<moveit_msgs::MoveGroupAction>>(node_handle_,
                                                                                                  MOVE_ACTION, false);
    waitForAction(*move_client_, MOVE_ACTION, deadline, allotted);
    pick_client_ =
        std::make_unique<actionlib::SimpleActionClient<moveit_msgs::PickupAction>>(node_handle_, PICKUP_ACTION, false);
    waitForAction(*pick_client_, PICKUP_ACTION, deadline, allotted);
    place_client_ =
        std::make_unique<actionlib::SimpleActionClient<moveit_msgs::PlaceAction>>(node_handle_, PLACE_ACTION, false);
    waitForAction(*place_client_, PLACE_ACTION, deadline, allotted);
    execute_client_ = std::make_unique<actionlib::SimpleActionClient<moveit_msgs::ExecuteTrajectoryAction>>(
        node_handle_, EXECUTE_ACTION, false);
    waitForAction(*execute_client_, EXECUTE_ACTION, deadline, allotted);

    query_service_ = node_handle_.serviceClient<moveit_msgs::QueryPlannerInterfaces>(QUERY_PLANNERS_SERVICE);
    get_params_service_ = node_handle_.serviceClient<moveit_msgs::GetPlannerParams>(GET_PLANNER_PARAMS_SERVICE);
    set_params_service_ = node_handle_.serviceClient<moveit_msgs::SetPlannerParams>(SET_PLANNER_PARAMS_SERVICE);
    cartesian_path_service_ = node_handle_.serviceClient<moveit_msgs::GetCartesianPath>(CARTESIAN_PATH_SERVICE);
    apply_scene_service_ = node_handle_.serviceClient<moveit_msgs::ApplyPlanningScene>(APPLY_PLANNING_SCENE_SERVICE);
    plan_grasps_service_ = node_handle_.serviceClient<moveit_msgs::GraspPlanning>(GRASP_PLANNING_SERVICE);

    ROS_INFO_STREAM_NAMED(LOGNAME, "Ready to take commands for planning group " << opt.group_name_ << ".");
  }

  [[noreturn]] static void fail(const std::string& error)
  {
    ROS_FATAL_STREAM_NAMED(LOGNAME, error);
    throw std::runtime_error(error);
  }

  template <typename Client>
  void waitForAction(Client& client, const std::string& name, const ros::WallTime& deadline, double allotted) const
  {
    // the node handle's queue is served meanwhile, so a node that has not started spinning yet connects too
    // (upstream l. 196-250)
    ros::CallbackQueue* queue = dynamic_cast<ros::CallbackQueue*>(node_handle_.getCallbackQueue());
    while (node_handle_.ok() && !client.isServerConnected() &&
           (deadline.isZero() || ros::WallTime::now() < deadline))
    {
      ros::WallDuration(SERVER_POLL_SECONDS).sleep();
      if (queue)
        queue->callAvailable();
      else
        ROS_WARN_ONCE_NAMED(LOGNAME, "Non-default CallbackQueue: Waiting for external queue handling.");
    }
    if (!client.isServerConnected())
    {
      std::ostringstream error;
      error << "Unable to connect to move_group action server '" << node_handle_.resolveName(name)
            << "' within allotted time (" << allotted << "s)";
      throw std::runtime_error(error.str());
    }
  }

  // --- state ---------------------------------------------------------------------------------------------------------
  bool getCurrentState(moveit::core::RobotStatePtr& state, double wait = CURRENT_STATE_WAIT_SECONDS) const
  {
    if (!state_monitor_->isActive())
      state_monitor_->startStateMonitor();
    if (!state_monitor_->waitForCurrentState(ros::Time::now(), wait))
    {
      ROS_ERROR_NAMED(LOGNAME, "Failed to fetch current robot state");
      return false;
    }
    state = state_monitor_->getCurrentState();
    return true;
  }

  bool startStateMonitor(double wait)
  {
    if (!state_monitor_->isActive())
      state_monitor_->startStateMonitor();
    state_monitor_->waitForCompleteState(opt_.group_name_, wait);
    return true;
  }

  moveit::core::RobotStatePtr getStartState()
  {
    moveit::core::RobotStatePtr state;
    if (!getCurrentState(state))
      return state;
    moveit::core::robotStateMsgToRobotState(considered_start_state_, *state, true);
    return state;
  }

  void setStartState(const moveit_msgs::RobotState& start_state)
  {
    considered_start_state_ = start_state;
  }

  void setStartState(const moveit::core::RobotState& start_state)
  {
    considered_start_state_ = moveit_msgs::RobotState();
    moveit::core::robotStateToRobotStateMsg(start_state, considered_start_state_, true);
  }

  void setStartStateToCurrentState()
  {
    considered_start_state_ = moveit_msgs::RobotState();
    considered_start_state_.is_diff = true;
  }

  // --- targets -------------------------------------------------------------------------------------------------------
  bool setJointValueTargetFromPose(const geometry_msgs::Pose& eef_pose, const std::string& end_effector_link,
                                   const std::string& frame, bool approximate)
  {
    // IK from the start state (upstream l. 478-532)
    const std::string& eef = end_effector_link.empty() ? end_effector_link_ : end_effector_link;
    if (eef.empty())
    {
      ROS_ERROR_NAMED(LOGNAME, "No end-effector to set the pose for");
      return false;
    }
    moveit::core::RobotStatePtr start = getStartState();
    if (!start)
      return false;
    active_target_ = JOINT;
    start->enforceBounds();
    *joint_state_target_ = *start;
    if (!joint_state_target_->satisfiesBounds(goal_joint_tolerance_))
      return false;

    kinematics::KinematicsQueryOptions options;
    options.return_approximate_solution = approximate;
    Eigen::Isometry3d pose = poseToEigen(eef_pose);
    if (!frame.empty() && stripSlash(frame) != stripSlash(robot_model_->getModelFrame()))
    {
      // a link's frame is known to the state; anything else is not (upstream asks the state's frames, l. 505-524)
      const moveit::core::LinkModel* link = robot_model_->getLinkModel(stripSlash(frame));
      if (!link)
      {
        ROS_ERROR_NAMED(LOGNAME, "Unable to transform from frame '%s' to frame '%s'", frame.c_str(),
                        robot_model_->getModelFrame().c_str());
        return false;
      }
      joint_state_target_->update();
      pose = joint_state_target_->getGlobalLinkTransform(link) * pose;
    }
    return joint_state_target_->setFromIK(joint_model_group_, pose, eef, 0.0,
                                          moveit::core::GroupStateValidityCallbackFn(), options);
  }

  bool setPoseTargets(const std::vector<geometry_msgs::PoseStamped>& poses, const std::string& end_effector_link)
  {
    const std::string& eef = end_effector_link.empty() ? end_effector_link_ : end_effector_link;
    if (eef.empty())
    {
      ROS_ERROR_NAMED(LOGNAME, "No end-effector to set the pose for");
      return false;
    }
    std::vector<geometry_msgs::PoseStamped>& stored = pose_targets_[eef];
    stored = poses;
    // no stamp is kept: an old one would ask TF for a stale transform (upstream l. 575-578)
    for (geometry_msgs::PoseStamped& pose : stored)
      pose.header.stamp = ros::Time(0);
    return true;
  }

  bool hasPoseTarget(const std::string& end_effector_link) const
  {
    const std::string& eef = end_effector_link.empty() ? end_effector_link_ : end_effector_link;
    return pose_targets_.find(eef) != pose_targets_.end();
  }

  const std::vector<geometry_msgs::PoseStamped>* findPoseTargets(const std::string& end_effector_link) const
  {
    const std::string& eef = end_effector_link.empty() ? end_effector_link_ : end_effector_link;
    auto it = pose_targets_.find(eef);
    return it == pose_targets_.end() || it->second.empty() ? nullptr : &it->second;
  }

  // --- requests ------------------------------------------------------------------------------------------------------
  void constructMotionPlanRequest(moveit_msgs::MotionPlanRequest& request) const
  {
    // the fields upstream fills (l. 1083-1137)
    request.group_name = opt_.group_name_;
    request.num_planning_attempts = num_planning_attempts_;
    request.max_velocity_scaling_factor = max_velocity_scaling_factor_;
    request.max_acceleration_scaling_factor = max_acceleration_scaling_factor_;
    request.cartesian_speed_limited_link = cartesian_speed_limited_link_;
    request.max_cartesian_speed = max_cartesian_speed_;
    request.allowed_planning_time = allowed_planning_time_;
    request.pipeline_id = planning_pipeline_id_;
    request.planner_id = planner_id_;
    request.workspace_parameters = workspace_parameters_;
    request.start_state = considered_start_state_;

    if (active_target_ == JOINT)
    {
      request.goal_constraints.resize(1);
      request.goal_constraints[0] =
          kinematic_constraints::constructGoalConstraints(*joint_state_target_, joint_model_group_, goal_joint_tolerance_);
    }
    else
    {
      // one goal per index: every end effector's i-th pose together (upstream l. 1103-1130)
      std::size_t goal_count = 0;
      for (const auto& target : pose_targets_)
        goal_count = std::max(goal_count, target.second.size());
      request.goal_constraints.resize(goal_count);
      for (const auto& target : pose_targets_)
      {
        for (std::size_t i = 0; i < target.second.size(); ++i)
        {
          moveit_msgs::Constraints c = kinematic_constraints::constructGoalConstraints(
              target.first, target.second[i], goal_position_tolerance_, goal_orientation_tolerance_);
          if (active_target_ == ORIENTATION)
            c.position_constraints.clear();
          if (active_target_ == POSITION)
            c.orientation_constraints.clear();
          request.goal_constraints[i] = kinematic_constraints::mergeConstraints(request.goal_constraints[i], c);
        }
      }
    }
    if (path_constraints_)
      request.path_constraints = *path_constraints_;
    if (trajectory_constraints_)
      request.trajectory_constraints = *trajectory_constraints_;
  }

  void fillPlanningOptions(moveit_msgs::PlanningOptions& options, bool plan_only) const
  {
    // the fields upstream fills: a plan neither looks around nor replans (l. 834-838); a move, pick or place
    // carries the settings (l. 875-880, 1162-1167); the attempts are kept but not sent, as upstream
    options.plan_only = plan_only;
    if (!plan_only)
    {
      options.look_around = can_look_;
      options.replan = can_replan_;
      options.replan_delay = replan_delay_;
    }
    options.planning_scene_diff.is_diff = true;
    options.planning_scene_diff.robot_state.is_diff = true;
  }

  moveit::core::MoveItErrorCode plan(Plan& plan)
  {
    if (!move_client_->isServerConnected())
    {
      ROS_WARN_STREAM_NAMED(LOGNAME, "move action server not connected");
      return moveit::core::MoveItErrorCode::COMMUNICATION_FAILURE;
    }
    moveit_msgs::MoveGroupGoal goal;
    constructMotionPlanRequest(goal.request);
    fillPlanningOptions(goal.planning_options, true);
    move_client_->sendGoal(goal);
    const moveit::core::MoveItErrorCode code = waitForResult(*move_client_, "MoveGroup", FailureReport::INFO_STATE);
    auto result = move_client_->getResult();
    if (result && move_client_->getState() == actionlib::SimpleClientGoalState::SUCCEEDED)
    {
      plan.trajectory_ = result->planned_trajectory;
      plan.start_state_ = result->trajectory_start;
      plan.planning_time_ = result->planning_time;
    }
    return code;
  }

  moveit::core::MoveItErrorCode move(bool wait)
  {
    if (!move_client_->isServerConnected())
    {
      ROS_WARN_STREAM_NAMED(LOGNAME, "move action server not connected");
      return moveit::core::MoveItErrorCode::COMMUNICATION_FAILURE;
    }
    moveit_msgs::MoveGroupGoal goal;
    constructMotionPlanRequest(goal.request);
    fillPlanningOptions(goal.planning_options, false);
    move_client_->sendGoal(goal);
    if (!wait)
      return moveit::core::MoveItErrorCode::SUCCESS;
    return waitForResult(*move_client_, "MoveGroup", FailureReport::WARN_FAIL);
  }

  moveit::core::MoveItErrorCode execute(const moveit_msgs::RobotTrajectory& trajectory, bool wait)
  {
    if (!execute_client_->isServerConnected())
    {
      ROS_WARN_STREAM_NAMED(LOGNAME, "execute action server not connected");
      return moveit::core::MoveItErrorCode::COMMUNICATION_FAILURE;
    }
    moveit_msgs::ExecuteTrajectoryGoal goal;
    goal.trajectory = trajectory;
    execute_client_->sendGoal(goal);
    if (!wait)
      return moveit::core::MoveItErrorCode::SUCCESS;
    return waitForResult(*execute_client_, "ExecuteTrajectory", FailureReport::INFO_STATE);
  }

  double computeCartesianPath(const std::vector<geometry_msgs::Pose>& waypoints, double step, double jump_threshold,
                              moveit_msgs::RobotTrajectory& trajectory,
                              const moveit_msgs::Constraints& path_constraints, bool avoid_collisions,
                              moveit_msgs::MoveItErrorCodes& error_code)
  {
    // the request upstream sends (l. 944-980)
    moveit_msgs::GetCartesianPath srv;
    srv.request.start_state = considered_start_state_;
    srv.request.group_name = opt_.group_name_;
    srv.request.header.frame_id = pose_reference_frame_;
    srv.request.header.stamp = ros::Time::now();
    srv.request.waypoints = waypoints;
    srv.request.max_step = step;
    srv.request.jump_threshold = jump_threshold;
    srv.request.path_constraints = path_constraints;
    srv.request.avoid_collisions = avoid_collisions;
    srv.request.link_name = end_effector_link_;
    srv.request.cartesian_speed_limited_link = cartesian_speed_limited_link_;
    srv.request.max_cartesian_speed = max_cartesian_speed_;
    if (!cartesian_path_service_.call(srv))
    {
      ROS_ERROR_NAMED(LOGNAME, "Could not call the service '%s'", cartesian_path_service_.getService().c_str());
      error_code.val = moveit_msgs::MoveItErrorCodes::FAILURE;
      return -1.0;
    }
    error_code = srv.response.error_code;
    if (srv.response.error_code.val != moveit_msgs::MoveItErrorCodes::SUCCESS)
      return -1.0;
    trajectory = srv.response.solution;
    return srv.response.fraction;
  }

  void stop()
  {
    // "stop" on the execution event topic ends the running trajectory (upstream l. 982-990)
    std_msgs::String event;
    event.data = "stop";
    detail::waitForSubscriber(trajectory_event_publisher_);
    trajectory_event_publisher_.publish(event);
  }

  bool applyAttached(const moveit_msgs::AttachedCollisionObject& object)
  {
    // upstream publishes on attached_collision_object and cannot know whether move_group applied it; here the same
    // message goes in a scene diff through apply_planning_scene, so the call returns once it is applied
    moveit_msgs::ApplyPlanningScene srv;
    srv.request.scene.is_diff = true;
    srv.request.scene.robot_state.is_diff = true;
    srv.request.scene.robot_state.attached_collision_objects.push_back(object);
    if (!apply_scene_service_.call(srv))
    {
      ROS_ERROR_NAMED(LOGNAME, "Could not call the service '%s'", apply_scene_service_.getService().c_str());
      return false;
    }
    return srv.response.success;
  }

  bool attachObject(const std::string& object, const std::string& link, const std::vector<std::string>& touch_links)
  {
    // the link: given, else the end effector link, else the group's first (upstream l. 992-1016)
    std::string l = link.empty() ? end_effector_link_ : link;
    if (l.empty() && !joint_model_group_->getLinkModelNames().empty())
      l = joint_model_group_->getLinkModelNames().front();
    if (l.empty())
    {
      ROS_ERROR_NAMED(LOGNAME, "No known link to attach object '%s' to", object.c_str());
      return false;
    }
    moveit_msgs::AttachedCollisionObject aco;
    aco.object.id = object;
    aco.link_name = l;
    aco.touch_links = touch_links.empty() ? std::vector<std::string>{ l } : touch_links;
    aco.object.operation = moveit_msgs::CollisionObject::ADD;
    return applyAttached(aco);
  }

  bool detachObject(const std::string& name)
  {
    // a link of the group names the link; anything else an object; nothing: every link of the group (upstream
    // l. 1018-1040)
    moveit_msgs::AttachedCollisionObject aco;
    aco.object.operation = moveit_msgs::CollisionObject::REMOVE;
    if (!name.empty() && joint_model_group_->hasLinkModel(name))
      aco.link_name = name;
    else
      aco.object.id = name;
    if (!aco.link_name.empty() || !aco.object.id.empty())
      return applyAttached(aco);
    bool ok = true;
    for (const std::string& link : joint_model_group_->getLinkModelNames())
    {
      aco.link_name = link;
      ok = applyAttached(aco) && ok;
    }
    return ok;
  }

  void setMaxScalingFactor(double& variable, double value, const char* name)
  {
    // above 1 is 1; 0 or below is the config's default (upstream l. 408-428)
    if (value > 1.0)
    {
      ROS_WARN_NAMED(LOGNAME, "Limiting max_%s (%.2f) to 1.0.", name, value);
      variable = 1.0;
    }
    else if (value <= 0.0)
    {
      node_handle_.param<double>(std::string("robot_description_planning/default_") + name, variable,
                                 DEFAULT_SCALING_FACTOR);
      if (value < 0.0)
        ROS_WARN_NAMED(LOGNAME, "max_%s < 0.0! Setting to default: %.2f.", name, variable);
    }
    else
      variable = value;
  }

  moveit_msgs::PickupGoal constructPickupGoal(const std::string& object, std::vector<moveit_msgs::Grasp>&& grasps,
                                              bool plan_only, const std::string& end_effector) const
  {
    moveit_msgs::PickupGoal goal;
    goal.target_name = object;
    goal.group_name = opt_.group_name_;
    goal.end_effector = end_effector;
    goal.support_surface_name = support_surface_;
    goal.possible_grasps = std::move(grasps);
    goal.allow_gripper_support_collision = !support_surface_.empty();
    if (path_constraints_)
      goal.path_constraints = *path_constraints_;
    goal.planner_id = planner_id_;
    goal.allowed_planning_time = allowed_planning_time_;
    fillPlanningOptions(goal.planning_options, false);
    goal.planning_options.plan_only = plan_only;
    return goal;
  }

  moveit_msgs::PlaceGoal constructPlaceGoal(const std::string& object,
                                            std::vector<moveit_msgs::PlaceLocation>&& locations, bool plan_only) const
  {
    moveit_msgs::PlaceGoal goal;
    goal.group_name = opt_.group_name_;
    goal.attached_object_name = object;
    goal.support_surface_name = support_surface_;
    goal.place_locations = std::move(locations);
    goal.allow_gripper_support_collision = !support_surface_.empty();
    if (path_constraints_)
      goal.path_constraints = *path_constraints_;
    goal.planner_id = planner_id_;
    goal.allowed_planning_time = allowed_planning_time_;
    fillPlanningOptions(goal.planning_options, false);
    goal.planning_options.plan_only = plan_only;
    return goal;
  }

  template <typename Client, typename Goal>
  moveit::core::MoveItErrorCode sendPickPlace(Client& client, const Goal& goal, const char* name)
  {
    if (!client.isServerConnected())
    {
      ROS_WARN_STREAM_NAMED(LOGNAME, name << " action server not connected");
      return moveit::core::MoveItErrorCode::COMMUNICATION_FAILURE;
    }
    client.sendGoal(goal);
    return waitForResult(client, name, FailureReport::WARN_FAIL);
  }

  Options opt_;
  ros::NodeHandle node_handle_;
  std::shared_ptr<tf2_ros::Buffer> tf_buffer_;
  moveit::core::RobotModelConstPtr robot_model_;
  const moveit::core::JointModelGroup* joint_model_group_ = nullptr;
  std::unique_ptr<detail::CurrentStateMonitor> state_monitor_;
  std::unique_ptr<actionlib::SimpleActionClient<moveit_msgs::MoveGroupAction>> move_client_;
  std::unique_ptr<actionlib::SimpleActionClient<moveit_msgs::ExecuteTrajectoryAction>> execute_client_;
  std::unique_ptr<actionlib::SimpleActionClient<moveit_msgs::PickupAction>> pick_client_;
  std::unique_ptr<actionlib::SimpleActionClient<moveit_msgs::PlaceAction>> place_client_;
  ros::Publisher trajectory_event_publisher_;
  ros::ServiceClient query_service_;
  ros::ServiceClient get_params_service_;
  ros::ServiceClient set_params_service_;
  ros::ServiceClient cartesian_path_service_;
  ros::ServiceClient apply_scene_service_;
  ros::ServiceClient plan_grasps_service_;

  // the request's settings, upstream's defaults (l. 120-131)
  moveit_msgs::RobotState considered_start_state_;
  moveit_msgs::WorkspaceParameters workspace_parameters_;
  double allowed_planning_time_ = DEFAULT_ALLOWED_PLANNING_TIME;
  std::string planning_pipeline_id_;
  std::string planner_id_;
  unsigned int num_planning_attempts_ = DEFAULT_NUM_PLANNING_ATTEMPTS;
  double max_velocity_scaling_factor_ = DEFAULT_SCALING_FACTOR;
  double max_acceleration_scaling_factor_ = DEFAULT_SCALING_FACTOR;
  std::string cartesian_speed_limited_link_;
  double max_cartesian_speed_ = 0.0;
  double goal_joint_tolerance_ = DEFAULT_GOAL_JOINT_TOLERANCE;
  double goal_position_tolerance_ = DEFAULT_GOAL_POSITION_TOLERANCE;
  double goal_orientation_tolerance_ = DEFAULT_GOAL_ORIENTATION_TOLERANCE;
  bool can_look_ = false;
  int32_t look_around_attempts_ = 0;
  bool can_replan_ = false;
  int32_t replan_attempts_ = 1;
  double replan_delay_ = 2.0;

  moveit::core::RobotStatePtr joint_state_target_;
  std::map<std::string, std::vector<geometry_msgs::PoseStamped>> pose_targets_;
  ActiveTargetType active_target_ = JOINT;
  std::unique_ptr<moveit_msgs::Constraints> path_constraints_;
  std::unique_ptr<moveit_msgs::TrajectoryConstraints> trajectory_constraints_;
  std::string end_effector_link_;
  std::string pose_reference_frame_;
  std::string support_surface_;
  // getRandomJointValues' generator (upstream borrows the target state's, l. 2105)
  mutable random_numbers::RandomNumberGenerator rng_;
};

// --- construction ----------------------------------------------------------------------------------------------------
MoveGroupInterface::MoveGroupInterface(const std::string& group_name, const std::shared_ptr<tf2_ros::Buffer>& tf_buffer,
                                       const ros::WallDuration& wait_for_servers)
{
  if (!ros::ok())
    throw std::runtime_error("ROS does not seem to be running");
  impl_ = new MoveGroupInterfaceImpl(Options(group_name), tf_buffer ? tf_buffer : getSharedTF(), wait_for_servers);
}

MoveGroupInterface::MoveGroupInterface(const std::string& group, const std::shared_ptr<tf2_ros::Buffer>& tf_buffer,
                                       const ros::Duration& wait_for_servers)
  : MoveGroupInterface(group, tf_buffer, ros::WallDuration(wait_for_servers.toSec()))
{
}

MoveGroupInterface::MoveGroupInterface(const Options& opt, const std::shared_ptr<tf2_ros::Buffer>& tf_buffer,
                                       const ros::WallDuration& wait_for_servers)
{
  impl_ = new MoveGroupInterfaceImpl(opt, tf_buffer ? tf_buffer : getSharedTF(), wait_for_servers);
}

MoveGroupInterface::MoveGroupInterface(const Options& opt, const std::shared_ptr<tf2_ros::Buffer>& tf_buffer,
                                       const ros::Duration& wait_for_servers)
  : MoveGroupInterface(opt, tf_buffer, ros::WallDuration(wait_for_servers.toSec()))
{
}

MoveGroupInterface::~MoveGroupInterface()
{
  delete impl_;
}

MoveGroupInterface::MoveGroupInterface(MoveGroupInterface&& other) noexcept
  : remembered_joint_values_(std::move(other.remembered_joint_values_)), impl_(other.impl_)
{
  other.impl_ = nullptr;
}

MoveGroupInterface& MoveGroupInterface::operator=(MoveGroupInterface&& other) noexcept
{
  if (this != &other)
  {
    delete impl_;
    impl_ = other.impl_;
    remembered_joint_values_ = std::move(other.remembered_joint_values_);
    other.impl_ = nullptr;
  }
  return *this;
}

// --- the group and the model -----------------------------------------------------------------------------------------
const std::string& MoveGroupInterface::getName() const
{
  return impl_->opt_.group_name_;
}

const std::vector<std::string>& MoveGroupInterface::getNamedTargets() const
{
  return impl_->joint_model_group_->getDefaultStateNames();
}

moveit::core::RobotModelConstPtr MoveGroupInterface::getRobotModel() const
{
  return impl_->robot_model_;
}

const ros::NodeHandle& MoveGroupInterface::getNodeHandle() const
{
  return impl_->opt_.node_handle_;
}

const std::string& MoveGroupInterface::getPlanningFrame() const
{
  return impl_->robot_model_->getModelFrame();
}

const std::vector<std::string>& MoveGroupInterface::getJointModelGroupNames() const
{
  return impl_->robot_model_->getJointModelGroupNames();
}

const std::vector<std::string>& MoveGroupInterface::getLinkNames() const
{
  return impl_->joint_model_group_->getLinkModelNames();
}

std::map<std::string, double> MoveGroupInterface::getNamedTargetValues(const std::string& name) const
{
  std::map<std::string, double> positions;
  auto it = remembered_joint_values_.find(name);
  if (it != remembered_joint_values_.end())
  {
    const std::vector<std::string>& names = impl_->joint_model_group_->getVariableNames();
    for (std::size_t i = 0; i < names.size() && i < it->second.size(); ++i)
      positions[names[i]] = it->second[i];
  }
  else
    impl_->joint_model_group_->getVariableDefaultPositions(name, positions);
  return positions;
}

const std::vector<std::string>& MoveGroupInterface::getJoints() const
{
  return impl_->joint_model_group_->getJointModelNames();
}

const std::vector<std::string>& MoveGroupInterface::getVariableNames() const
{
  return impl_->joint_model_group_->getVariableNames();
}

const std::vector<std::string>& MoveGroupInterface::getActiveJoints() const
{
  return impl_->joint_model_group_->getActiveJointModelNames();
}

unsigned int MoveGroupInterface::getVariableCount() const
{
  return impl_->joint_model_group_->getVariableCount();
}

// --- planner settings ------------------------------------------------------------------------------------------------
bool MoveGroupInterface::getInterfaceDescriptions(std::vector<moveit_msgs::PlannerInterfaceDescription>& desc) const
{
  moveit_msgs::QueryPlannerInterfaces srv;
  if (!impl_->query_service_.call(srv) || srv.response.planner_interfaces.empty())
    return false;
  desc = srv.response.planner_interfaces;
  return true;
}

bool MoveGroupInterface::getInterfaceDescription(moveit_msgs::PlannerInterfaceDescription& desc) const
{
  std::vector<moveit_msgs::PlannerInterfaceDescription> all;
  if (!getInterfaceDescriptions(all))
    return false;
  desc = all.front();
  return true;
}

std::map<std::string, std::string> MoveGroupInterface::getPlannerParams(const std::string& planner_id,
                                                                        const std::string& group) const
{
  std::map<std::string, std::string> result;
  moveit_msgs::GetPlannerParams srv;
  srv.request.planner_config = planner_id;
  srv.request.group = group;
  if (!impl_->get_params_service_.call(srv))
  {
    ROS_ERROR_NAMED(LOGNAME, "getPlannerParams: the service '%s' is not served (this move_group does not provide it)",
                    impl_->get_params_service_.getService().c_str());
    return result;
  }
  for (std::size_t i = 0; i < srv.response.params.keys.size() && i < srv.response.params.values.size(); ++i)
    result[srv.response.params.keys[i]] = srv.response.params.values[i];
  return result;
}

void MoveGroupInterface::setPlannerParams(const std::string& planner_id, const std::string& group,
                                          const std::map<std::string, std::string>& params, bool bReplace)
{
  moveit_msgs::SetPlannerParams srv;
  srv.request.planner_config = planner_id;
  srv.request.group = group;
  srv.request.replace = bReplace;
  for (const auto& param : params)
  {
    srv.request.params.keys.push_back(param.first);
    srv.request.params.values.push_back(param.second);
  }
  if (!impl_->set_params_service_.call(srv))
    ROS_ERROR_NAMED(LOGNAME, "setPlannerParams: the service '%s' is not served (this move_group does not provide it)",
                    impl_->set_params_service_.getService().c_str());
}

std::string MoveGroupInterface::getDefaultPlanningPipelineId() const
{
  std::string pipeline;
  impl_->node_handle_.getParam("move_group/default_planning_pipeline", pipeline);
  return pipeline;
}

void MoveGroupInterface::setPlanningPipelineId(const std::string& pipeline_id)
{
  if (pipeline_id != impl_->planning_pipeline_id_)
  {
    impl_->planning_pipeline_id_ = pipeline_id;
    impl_->planner_id_.clear();  // a planner id belongs to its pipeline (upstream l. 349-356)
  }
}

const std::string& MoveGroupInterface::getPlanningPipelineId() const
{
  return impl_->planning_pipeline_id_;
}

std::string MoveGroupInterface::getDefaultPlannerId(const std::string& group) const
{
  std::string pipeline = impl_->planning_pipeline_id_.empty() ? getDefaultPlanningPipelineId() :
                                                                impl_->planning_pipeline_id_;
  std::string name = "move_group";
  if (!pipeline.empty())
    name += "/planning_pipelines/" + pipeline;
  if (!group.empty())
    name += "/" + group;
  name += "/default_planner_config";
  std::string planner;
  impl_->node_handle_.getParam(name, planner);
  return planner;
}

void MoveGroupInterface::setPlannerId(const std::string& planner_id)
{
  impl_->planner_id_ = planner_id;
}

const std::string& MoveGroupInterface::getPlannerId() const
{
  return impl_->planner_id_;
}

void MoveGroupInterface::setPlanningTime(double seconds)
{
  if (seconds > 0.0)
    impl_->allowed_planning_time_ = seconds;
}

double MoveGroupInterface::getPlanningTime() const
{
  return impl_->allowed_planning_time_;
}

void MoveGroupInterface::setNumPlanningAttempts(unsigned int num_planning_attempts)
{
  impl_->num_planning_attempts_ = num_planning_attempts;
}

void MoveGroupInterface::setMaxVelocityScalingFactor(double max_velocity_scaling_factor)
{
  impl_->setMaxScalingFactor(impl_->max_velocity_scaling_factor_, max_velocity_scaling_factor,
                             "velocity_scaling_factor");
}

void MoveGroupInterface::setMaxAccelerationScalingFactor(double max_acceleration_scaling_factor)
{
  impl_->setMaxScalingFactor(impl_->max_acceleration_scaling_factor_, max_acceleration_scaling_factor,
                             "acceleration_scaling_factor");
}

void MoveGroupInterface::limitMaxCartesianLinkSpeed(const double max_speed, const std::string& link_name)
{
  impl_->cartesian_speed_limited_link_ = link_name;
  impl_->max_cartesian_speed_ = max_speed;
}

void MoveGroupInterface::clearMaxCartesianLinkSpeed()
{
  impl_->cartesian_speed_limited_link_.clear();
  impl_->max_cartesian_speed_ = 0.0;
}

// --- tolerances and workspace ----------------------------------------------------------------------------------------
double MoveGroupInterface::getGoalJointTolerance() const
{
  return impl_->goal_joint_tolerance_;
}

double MoveGroupInterface::getGoalPositionTolerance() const
{
  return impl_->goal_position_tolerance_;
}

double MoveGroupInterface::getGoalOrientationTolerance() const
{
  return impl_->goal_orientation_tolerance_;
}

void MoveGroupInterface::setGoalTolerance(double tolerance)
{
  setGoalJointTolerance(tolerance);
  setGoalPositionTolerance(tolerance);
  setGoalOrientationTolerance(tolerance);
}

void MoveGroupInterface::setGoalJointTolerance(double tolerance)
{
  impl_->goal_joint_tolerance_ = tolerance;
}

void MoveGroupInterface::setGoalPositionTolerance(double tolerance)
{
  impl_->goal_position_tolerance_ = tolerance;
}

void MoveGroupInterface::setGoalOrientationTolerance(double tolerance)
{
  impl_->goal_orientation_tolerance_ = tolerance;
}

void MoveGroupInterface::setWorkspace(double minx, double miny, double minz, double maxx, double maxy, double maxz)
{
  moveit_msgs::WorkspaceParameters& w = impl_->workspace_parameters_;
  w.header.frame_id = impl_->robot_model_->getModelFrame();
  w.header.stamp = ros::Time::now();
  w.min_corner.x = minx;
  w.min_corner.y = miny;
  w.min_corner.z = minz;
  w.max_corner.x = maxx;
  w.max_corner.y = maxy;
  w.max_corner.z = maxz;
}

// --- start state -----------------------------------------------------------------------------------------------------
void MoveGroupInterface::setStartState(const moveit_msgs::RobotState& start_state)
{
  impl_->setStartState(start_state);
}

void MoveGroupInterface::setStartState(const moveit::core::RobotState& start_state)
{
  impl_->setStartState(start_state);
}

void MoveGroupInterface::setStartStateToCurrentState()
{
  impl_->setStartStateToCurrentState();
}

void MoveGroupInterface::setSupportSurfaceName(const std::string& name)
{
  impl_->support_surface_ = name;
}

// --- joint-space targets ---------------------------------------------------------------------------------------------
bool MoveGroupInterface::setJointValueTarget(const std::vector<double>& joint_values)
{
  const moveit::core::JointModelGroup* jmg = impl_->joint_model_group_;
  if (joint_values.size() != jmg->getVariableCount())
  {
    ROS_DEBUG_STREAM_NAMED(LOGNAME, "Provided joint value list has length " << joint_values.size() << " but group "
                                                                            << jmg->getName() << " has "
                                                                            << jmg->getVariableCount() << " joints");
    return false;
  }
  impl_->active_target_ = JOINT;
  impl_->joint_state_target_->setJointGroupPositions(jmg, joint_values);
  return impl_->joint_state_target_->satisfiesBounds(jmg, impl_->goal_joint_tolerance_);
}

bool MoveGroupInterface::setJointValueTarget(const std::map<std::string, double>& variable_values)
{
  const std::vector<std::string>& allowed = impl_->joint_model_group_->getVariableNames();
  for (const auto& pair : variable_values)
    if (std::find(allowed.begin(), allowed.end(), pair.first) == allowed.end())
    {
      ROS_ERROR_STREAM_NAMED(LOGNAME, "joint variable " << pair.first << " is not part of group "
                                                        << impl_->joint_model_group_->getName());
      return false;
    }
  impl_->active_target_ = JOINT;
  impl_->joint_state_target_->setVariablePositions(variable_values);
  return impl_->joint_state_target_->satisfiesBounds(impl_->goal_joint_tolerance_);
}

bool MoveGroupInterface::setJointValueTarget(const std::vector<std::string>& variable_names,
                                             const std::vector<double>& variable_values)
{
  if (variable_names.size() != variable_values.size())
  {
    ROS_ERROR_STREAM_NAMED(LOGNAME, "sizes of name and position arrays do not match");
    return false;
  }
  std::map<std::string, double> values;
  for (std::size_t i = 0; i < variable_names.size(); ++i)
    values[variable_names[i]] = variable_values[i];
  return setJointValueTarget(values);
}

bool MoveGroupInterface::setJointValueTarget(const moveit::core::RobotState& robot_state)
{
  impl_->active_target_ = JOINT;
  *impl_->joint_state_target_ = robot_state;
  return impl_->joint_state_target_->satisfiesBounds(impl_->goal_joint_tolerance_);
}

bool MoveGroupInterface::setJointValueTarget(const std::string& joint_name, const std::vector<double>& values)
{
  impl_->active_target_ = JOINT;
  const moveit::core::JointModel* jm = impl_->joint_model_group_->getJointModel(joint_name);
  if (jm && jm->getVariableCount() == values.size())
  {
    impl_->joint_state_target_->setJointPositions(jm, values);
    return impl_->joint_state_target_->satisfiesBounds(jm, impl_->goal_joint_tolerance_);
  }
  ROS_ERROR_STREAM_NAMED(LOGNAME,
                         "joint " << joint_name << " is not part of group " << impl_->joint_model_group_->getName());
  return false;
}

bool MoveGroupInterface::setJointValueTarget(const std::string& joint_name, double value)
{
  return setJointValueTarget(joint_name, std::vector<double>{ value });
}

bool MoveGroupInterface::setJointValueTarget(const sensor_msgs::JointState& state)
{
  return setJointValueTarget(state.name, state.position);
}

bool MoveGroupInterface::setJointValueTarget(const geometry_msgs::Pose& eef_pose, const std::string& end_effector_link)
{
  return impl_->setJointValueTargetFromPose(eef_pose, end_effector_link, "", false);
}

bool MoveGroupInterface::setJointValueTarget(const geometry_msgs::PoseStamped& eef_pose,
                                             const std::string& end_effector_link)
{
  return impl_->setJointValueTargetFromPose(eef_pose.pose, end_effector_link, eef_pose.header.frame_id, false);
}

bool MoveGroupInterface::setJointValueTarget(const Eigen::Isometry3d& eef_pose, const std::string& end_effector_link)
{
  return setJointValueTarget(eigenToPose(eef_pose), end_effector_link);
}

bool MoveGroupInterface::setApproximateJointValueTarget(const geometry_msgs::Pose& eef_pose,
                                                        const std::string& end_effector_link)
{
  return impl_->setJointValueTargetFromPose(eef_pose, end_effector_link, "", true);
}

bool MoveGroupInterface::setApproximateJointValueTarget(const geometry_msgs::PoseStamped& eef_pose,
                                                        const std::string& end_effector_link)
{
  return impl_->setJointValueTargetFromPose(eef_pose.pose, end_effector_link, eef_pose.header.frame_id, true);
}

bool MoveGroupInterface::setApproximateJointValueTarget(const Eigen::Isometry3d& eef_pose,
                                                        const std::string& end_effector_link)
{
  return setApproximateJointValueTarget(eigenToPose(eef_pose), end_effector_link);
}

void MoveGroupInterface::setRandomTarget()
{
  impl_->joint_state_target_->setToRandomPositions();
  impl_->active_target_ = JOINT;
}

bool MoveGroupInterface::setNamedTarget(const std::string& name)
{
  auto it = remembered_joint_values_.find(name);
  if (it != remembered_joint_values_.end())
    return setJointValueTarget(it->second);
  if (impl_->joint_state_target_->setToDefaultValues(impl_->joint_model_group_, name))
  {
    impl_->active_target_ = JOINT;
    return true;
  }
  ROS_ERROR_NAMED(LOGNAME, "The requested named target '%s' does not exist", name.c_str());
  return false;
}

void MoveGroupInterface::getJointValueTarget(std::vector<double>& group_variable_values) const
{
  impl_->joint_state_target_->copyJointGroupPositions(impl_->joint_model_group_, group_variable_values);
}

const moveit::core::RobotState& MoveGroupInterface::getJointValueTarget() const
{
  return *impl_->joint_state_target_;
}

const moveit::core::RobotState& MoveGroupInterface::getTargetRobotState() const
{
  return *impl_->joint_state_target_;
}

// --- Cartesian targets -----------------------------------------------------------------------------------------------
namespace
{
// an earlier target of the link, brought into the reference frame, is the base of a position or orientation target
// (upstream l. 1949-1980)
geometry_msgs::PoseStamped baseTarget(const tf2_ros::Buffer& tf, const std::string& reference_frame,
                                      const geometry_msgs::PoseStamped* earlier)
{
  geometry_msgs::PoseStamped target;
  if (earlier)
  {
    target = *earlier;
    if (target.header.frame_id != reference_frame)
    {
      tf.transform(*earlier, target, reference_frame);
      target.header.stamp = ros::Time(0);
    }
    return target;
  }
  target.pose.orientation.w = 1.0;
  target.header.frame_id = reference_frame;
  return target;
}
}  // namespace

bool MoveGroupInterface::setPositionTarget(double x, double y, double z, const std::string& end_effector_link)
{
  const std::vector<geometry_msgs::PoseStamped>* earlier = impl_->findPoseTargets(end_effector_link);
  geometry_msgs::PoseStamped target =
      baseTarget(*impl_->tf_buffer_, impl_->pose_reference_frame_, earlier ? &earlier->front() : nullptr);
  target.pose.position.x = x;
  target.pose.position.y = y;
  target.pose.position.z = z;
  const bool result = setPoseTarget(target, end_effector_link);
  impl_->active_target_ = POSITION;
  return result;
}

bool MoveGroupInterface::setRPYTarget(double roll, double pitch, double yaw, const std::string& end_effector_link)
{
  const std::vector<geometry_msgs::PoseStamped>* earlier = impl_->findPoseTargets(end_effector_link);
  geometry_msgs::PoseStamped target =
      baseTarget(*impl_->tf_buffer_, impl_->pose_reference_frame_, earlier ? &earlier->front() : nullptr);
  if (!earlier)
    target.pose.position = geometry_msgs::Point();
  tf2::Quaternion q;
  q.setRPY(roll, pitch, yaw);
  target.pose.orientation = tf2::toMsg(q);
  const bool result = setPoseTarget(target, end_effector_link);
  impl_->active_target_ = ORIENTATION;
  return result;
}

bool MoveGroupInterface::setOrientationTarget(double x, double y, double z, double w,
                                              const std::string& end_effector_link)
{
  const std::vector<geometry_msgs::PoseStamped>* earlier = impl_->findPoseTargets(end_effector_link);
  geometry_msgs::PoseStamped target =
      baseTarget(*impl_->tf_buffer_, impl_->pose_reference_frame_, earlier ? &earlier->front() : nullptr);
  target.pose.orientation.x = x;
  target.pose.orientation.y = y;
  target.pose.orientation.z = z;
  target.pose.orientation.w = w;
  const bool result = setPoseTarget(target, end_effector_link);
  impl_->active_target_ = ORIENTATION;
  return result;
}

bool MoveGroupInterface::setPoseTarget(const Eigen::Isometry3d& pose, const std::string& end_effector_link)
{
  return setPoseTarget(eigenToPose(pose), end_effector_link);
}

bool MoveGroupInterface::setPoseTarget(const geometry_msgs::Pose& target, const std::string& end_effector_link)
{
  return setPoseTargets(std::vector<geometry_msgs::Pose>{ target }, end_effector_link);
}

bool MoveGroupInterface::setPoseTarget(const geometry_msgs::PoseStamped& target, const std::string& end_effector_link)
{
  return setPoseTargets(std::vector<geometry_msgs::PoseStamped>{ target }, end_effector_link);
}

bool MoveGroupInterface::setPoseTargets(const EigenSTL::vector_Isometry3d& target, const std::string& end_effector_link)
{
  std::vector<geometry_msgs::Pose> poses;
  for (const Eigen::Isometry3d& pose : target)
    poses.push_back(eigenToPose(pose));
  return setPoseTargets(poses, end_effector_link);
}

bool MoveGroupInterface::setPoseTargets(const std::vector<geometry_msgs::Pose>& target,
                                        const std::string& end_effector_link)
{
  // poses without a frame are in the pose reference frame
  std::vector<geometry_msgs::PoseStamped> stamped(target.size());
  const ros::Time now = ros::Time::now();
  for (std::size_t i = 0; i < target.size(); ++i)
  {
    stamped[i].pose = target[i];
    stamped[i].header.stamp = now;
    stamped[i].header.frame_id = impl_->pose_reference_frame_;
  }
  return setPoseTargets(stamped, end_effector_link);
}

bool MoveGroupInterface::setPoseTargets(const std::vector<geometry_msgs::PoseStamped>& target,
                                        const std::string& end_effector_link)
{
  if (target.empty())
  {
    ROS_ERROR_NAMED(LOGNAME, "No pose specified as goal target");
    return false;
  }
  impl_->active_target_ = POSE;
  return impl_->setPoseTargets(target, end_effector_link);
}

void MoveGroupInterface::setPoseReferenceFrame(const std::string& pose_reference_frame)
{
  impl_->pose_reference_frame_ = pose_reference_frame;
}

bool MoveGroupInterface::setEndEffectorLink(const std::string& link_name)
{
  // as upstream (l. 1841-1848): refused while the group has no end effector link of its own
  if (impl_->end_effector_link_.empty() || link_name.empty())
    return false;
  impl_->end_effector_link_ = link_name;
  impl_->active_target_ = POSE;
  return true;
}

bool MoveGroupInterface::setEndEffector(const std::string& eef_name)
{
  const moveit::core::JointModelGroup* jmg = impl_->robot_model_->getEndEffector(eef_name);
  return jmg ? setEndEffectorLink(jmg->getEndEffectorParentGroup().second) : false;
}

void MoveGroupInterface::clearPoseTarget(const std::string& end_effector_link)
{
  impl_->pose_targets_.erase(end_effector_link);
}

void MoveGroupInterface::clearPoseTargets()
{
  impl_->pose_targets_.clear();
}

const geometry_msgs::PoseStamped& MoveGroupInterface::getPoseTarget(const std::string& end_effector_link) const
{
  const std::vector<geometry_msgs::PoseStamped>* poses = impl_->findPoseTargets(end_effector_link);
  if (poses)
    return poses->front();
  static const geometry_msgs::PoseStamped UNKNOWN;
  ROS_ERROR_NAMED(LOGNAME, "Pose for end-effector '%s' not known.",
                  (end_effector_link.empty() ? impl_->end_effector_link_ : end_effector_link).c_str());
  return UNKNOWN;
}

const std::vector<geometry_msgs::PoseStamped>&
MoveGroupInterface::getPoseTargets(const std::string& end_effector_link) const
{
  const std::vector<geometry_msgs::PoseStamped>* poses = impl_->findPoseTargets(end_effector_link);
  if (poses)
    return *poses;
  static const std::vector<geometry_msgs::PoseStamped> EMPTY;
  ROS_ERROR_NAMED(LOGNAME, "Poses for end-effector '%s' are not known.",
                  (end_effector_link.empty() ? impl_->end_effector_link_ : end_effector_link).c_str());
  return EMPTY;
}

const std::string& MoveGroupInterface::getEndEffectorLink() const
{
  return impl_->end_effector_link_;
}

const std::string& MoveGroupInterface::getEndEffector() const
{
  // the end effector attached to the group that holds the end effector link (upstream l. 550-561)
  if (!impl_->end_effector_link_.empty())
    for (const std::string& eef : impl_->joint_model_group_->getAttachedEndEffectorNames())
    {
      const moveit::core::JointModelGroup* jmg = impl_->robot_model_->getEndEffector(eef);
      if (jmg && jmg->hasLinkModel(impl_->end_effector_link_))
        return eef;
    }
  static const std::string EMPTY;
  return EMPTY;
}

const std::string& MoveGroupInterface::getPoseReferenceFrame() const
{
  return impl_->pose_reference_frame_;
}

// --- planning and execution ------------------------------------------------------------------------------------------
moveit::core::MoveItErrorCode MoveGroupInterface::asyncMove()
{
  return impl_->move(false);
}

actionlib::SimpleActionClient<moveit_msgs::MoveGroupAction>& MoveGroupInterface::getMoveGroupClient() const
{
  return *impl_->move_client_;
}

moveit::core::MoveItErrorCode MoveGroupInterface::move()
{
  return impl_->move(true);
}

moveit::core::MoveItErrorCode MoveGroupInterface::plan(Plan& plan)
{
  return impl_->plan(plan);
}

moveit::core::MoveItErrorCode MoveGroupInterface::asyncExecute(const Plan& plan)
{
  return impl_->execute(plan.trajectory_, false);
}

moveit::core::MoveItErrorCode MoveGroupInterface::asyncExecute(const moveit_msgs::RobotTrajectory& trajectory)
{
  return impl_->execute(trajectory, false);
}

moveit::core::MoveItErrorCode MoveGroupInterface::execute(const Plan& plan)
{
  return impl_->execute(plan.trajectory_, true);
}

moveit::core::MoveItErrorCode MoveGroupInterface::execute(const moveit_msgs::RobotTrajectory& trajectory)
{
  return impl_->execute(trajectory, true);
}

double MoveGroupInterface::computeCartesianPath(const std::vector<geometry_msgs::Pose>& waypoints, double eef_step,
                                                double jump_threshold, moveit_msgs::RobotTrajectory& trajectory,
                                                bool avoid_collisions, moveit_msgs::MoveItErrorCodes* error_code)
{
  return computeCartesianPath(waypoints, eef_step, jump_threshold, trajectory, moveit_msgs::Constraints(),
                              avoid_collisions, error_code);
}

double MoveGroupInterface::computeCartesianPath(const std::vector<geometry_msgs::Pose>& waypoints, double eef_step,
                                                double jump_threshold, moveit_msgs::RobotTrajectory& trajectory,
                                                const moveit_msgs::Constraints& path_constraints, bool avoid_collisions,
                                                moveit_msgs::MoveItErrorCodes* error_code)
{
  moveit_msgs::MoveItErrorCodes unused;
  return impl_->computeCartesianPath(waypoints, eef_step, jump_threshold, trajectory, path_constraints,
                                     avoid_collisions, error_code ? *error_code : unused);
}

void MoveGroupInterface::stop()
{
  impl_->stop();
}

void MoveGroupInterface::allowReplanning(bool flag)
{
  impl_->can_replan_ = flag;
}

void MoveGroupInterface::setReplanAttempts(int32_t attempts)
{
  if (attempts < 0)
    ROS_ERROR_NAMED(LOGNAME, "Tried to set negative number of replan attempts");
  else
    impl_->replan_attempts_ = attempts;
}

void MoveGroupInterface::setReplanDelay(double delay)
{
  if (delay < 0.0)
    ROS_ERROR_NAMED(LOGNAME, "Tried to set negative replan delay");
  else
    impl_->replan_delay_ = delay;
}

void MoveGroupInterface::allowLooking(bool flag)
{
  impl_->can_look_ = flag;
}

void MoveGroupInterface::setLookAroundAttempts(int32_t attempts)
{
  if (attempts < 0)
    ROS_ERROR_NAMED(LOGNAME, "Tried to set negative number of look-around attempts");
  else
    impl_->look_around_attempts_ = attempts;
}

void MoveGroupInterface::constructMotionPlanRequest(moveit_msgs::MotionPlanRequest& request)
{
  impl_->constructMotionPlanRequest(request);
}

// --- pick and place --------------------------------------------------------------------------------------------------
moveit_msgs::PickupGoal MoveGroupInterface::constructPickupGoal(const std::string& object,
                                                                std::vector<moveit_msgs::Grasp> grasps,
                                                                bool plan_only) const
{
  return impl_->constructPickupGoal(object, std::move(grasps), plan_only, getEndEffector());
}

moveit_msgs::PlaceGoal MoveGroupInterface::constructPlaceGoal(const std::string& object,
                                                              std::vector<moveit_msgs::PlaceLocation> locations,
                                                              bool plan_only) const
{
  return impl_->constructPlaceGoal(object, std::move(locations), plan_only);
}

std::vector<moveit_msgs::PlaceLocation>
MoveGroupInterface::posesToPlaceLocations(const std::vector<geometry_msgs::PoseStamped>& poses) const
{
  // approach down the model frame's z, retreat back along the end effector's x (upstream l. 684-710)
  std::vector<moveit_msgs::PlaceLocation> locations;
  for (const geometry_msgs::PoseStamped& pose : poses)
  {
    moveit_msgs::PlaceLocation location;
    location.pre_place_approach.direction.vector.z = -1.0;
    location.post_place_retreat.direction.vector.x = -1.0;
    location.pre_place_approach.direction.header.frame_id = impl_->robot_model_->getModelFrame();
    location.post_place_retreat.direction.header.frame_id = impl_->end_effector_link_;
    location.pre_place_approach.min_distance = PRE_PLACE_MIN_DISTANCE;
    location.pre_place_approach.desired_distance = PRE_PLACE_DESIRED_DISTANCE;
    location.post_place_retreat.min_distance = 0.0;
    location.post_place_retreat.desired_distance = POST_PLACE_DESIRED_DISTANCE;
    location.place_pose = pose;
    locations.push_back(location);
  }
  return locations;
}

moveit::core::MoveItErrorCode MoveGroupInterface::pick(const moveit_msgs::PickupGoal& goal)
{
  return impl_->sendPickPlace(*impl_->pick_client_, goal, "Pickup");
}

moveit::core::MoveItErrorCode MoveGroupInterface::place(const moveit_msgs::PlaceGoal& goal)
{
  return impl_->sendPickPlace(*impl_->place_client_, goal, "Place");
}

moveit::core::MoveItErrorCode MoveGroupInterface::planGraspsAndPick(const std::string& object, bool plan_only)
{
  if (object.empty())
    return planGraspsAndPick(moveit_msgs::CollisionObject(), plan_only);
  PlanningSceneInterface psi;
  std::map<std::string, moveit_msgs::CollisionObject> objects = psi.getObjects({ object });
  if (objects.empty())
  {
    ROS_ERROR_STREAM_NAMED(LOGNAME,
                           "Asked for grasps for the object '" << object << "', but the object could not be found");
    return moveit::core::MoveItErrorCode::INVALID_OBJECT_NAME;
  }
  return planGraspsAndPick(objects[object], plan_only);
}

moveit::core::MoveItErrorCode MoveGroupInterface::planGraspsAndPick(const moveit_msgs::CollisionObject& object,
                                                                    bool plan_only)
{
  if (!impl_->plan_grasps_service_.exists())
  {
    ROS_ERROR_STREAM_NAMED(LOGNAME, "Grasp planning service '" << impl_->plan_grasps_service_.getService()
                                                               << "' is not available. This has to be implemented "
                                                                  "and started separately.");
    return moveit::core::MoveItErrorCode::COMMUNICATION_FAILURE;
  }
  moveit_msgs::GraspPlanning srv;
  srv.request.group_name = impl_->opt_.group_name_;
  srv.request.target = object;
  srv.request.support_surfaces.push_back(impl_->support_surface_);
  if (!impl_->plan_grasps_service_.call(srv) ||
      srv.response.error_code.val != moveit_msgs::MoveItErrorCodes::SUCCESS)
  {
    ROS_ERROR_NAMED(LOGNAME, "Grasp planning failed. Unable to pick.");
    return moveit::core::MoveItErrorCode::FAILURE;
  }
  return pick(constructPickupGoal(object.id, std::move(srv.response.grasps), plan_only));
}

// --- attached objects ------------------------------------------------------------------------------------------------
bool MoveGroupInterface::attachObject(const std::string& object, const std::string& link)
{
  return attachObject(object, link, std::vector<std::string>());
}

bool MoveGroupInterface::attachObject(const std::string& object, const std::string& link,
                                      const std::vector<std::string>& touch_links)
{
  return impl_->attachObject(object, link, touch_links);
}

bool MoveGroupInterface::detachObject(const std::string& name)
{
  return impl_->detachObject(name);
}

// --- the current state -----------------------------------------------------------------------------------------------
bool MoveGroupInterface::startStateMonitor(double wait)
{
  return impl_->startStateMonitor(wait);
}

std::vector<double> MoveGroupInterface::getCurrentJointValues() const
{
  std::vector<double> values;
  moveit::core::RobotStatePtr state;
  if (impl_->getCurrentState(state))
    state->copyJointGroupPositions(impl_->joint_model_group_, values);
  return values;
}

moveit::core::RobotStatePtr MoveGroupInterface::getCurrentState(double wait) const
{
  moveit::core::RobotStatePtr state;
  impl_->getCurrentState(state, wait);
  return state;
}

namespace
{
geometry_msgs::PoseStamped linkPose(const moveit::core::RobotState* state, const std::string& link,
                                    const std::string& frame)
{
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  if (state)
  {
    const moveit::core::LinkModel* lm = state->getRobotModel()->getLinkModel(link);
    if (lm)
      pose = state->getGlobalLinkTransform(lm);
    else
      ROS_ERROR_NAMED(LOGNAME, "The robot has no link '%s'", link.c_str());
  }
  geometry_msgs::PoseStamped result;
  result.header.stamp = ros::Time::now();
  result.header.frame_id = frame;
  result.pose = eigenToPose(pose);
  return result;
}
}  // namespace

geometry_msgs::PoseStamped MoveGroupInterface::getCurrentPose(const std::string& end_effector_link) const
{
  const std::string& eef = end_effector_link.empty() ? getEndEffectorLink() : end_effector_link;
  moveit::core::RobotStatePtr state;
  if (eef.empty())
    ROS_ERROR_NAMED(LOGNAME, "No end-effector specified");
  else
    impl_->getCurrentState(state);
  return linkPose(state.get(), eef, getPlanningFrame());
}

std::vector<double> MoveGroupInterface::getCurrentRPY(const std::string& end_effector_link) const
{
  std::vector<double> result;
  const std::string& eef = end_effector_link.empty() ? getEndEffectorLink() : end_effector_link;
  moveit::core::RobotStatePtr state;
  if (eef.empty())
  {
    ROS_ERROR_NAMED(LOGNAME, "No end-effector specified");
    return result;
  }
  if (!impl_->getCurrentState(state) || !impl_->robot_model_->getLinkModel(eef))
    return result;
  // roll, pitch, yaw about the fixed X, Y, Z axes, as tf2::getEulerYPR gives them (upstream l. 2173-2178)
  const geometry_msgs::Quaternion& o = linkPose(state.get(), eef, getPlanningFrame()).pose.orientation;
  double roll, pitch, yaw;
  tf2::Matrix3x3(tf2::Quaternion(o.x, o.y, o.z, o.w)).getRPY(roll, pitch, yaw);
  return { roll, pitch, yaw };
}

std::vector<double> MoveGroupInterface::getRandomJointValues() const
{
  std::vector<double> values;
  impl_->joint_model_group_->getVariableRandomPositions(impl_->rng_, values);
  return values;
}

geometry_msgs::PoseStamped MoveGroupInterface::getRandomPose(const std::string& end_effector_link) const
{
  const std::string& eef = end_effector_link.empty() ? getEndEffectorLink() : end_effector_link;
  moveit::core::RobotStatePtr state;
  if (eef.empty())
    ROS_ERROR_NAMED(LOGNAME, "No end-effector specified");
  else if (impl_->getCurrentState(state))
  {
    state->setToRandomPositions(impl_->joint_model_group_);
    state->update();
  }
  return linkPose(state.get(), eef, getPlanningFrame());
}

// --- remembered joint values -----------------------------------------------------------------------------------------
void MoveGroupInterface::rememberJointValues(const std::string& name)
{
  rememberJointValues(name, getCurrentJointValues());
}

void MoveGroupInterface::rememberJointValues(const std::string& name, const std::vector<double>& values)
{
  remembered_joint_values_[name] = values;
}

void MoveGroupInterface::forgetJointValues(const std::string& name)
{
  remembered_joint_values_.erase(name);
}

// --- constraints -----------------------------------------------------------------------------------------------------
void MoveGroupInterface::setConstraintsDatabase(const std::string& host, unsigned int port)
{
  ROS_ERROR_NAMED(LOGNAME, "setConstraintsDatabase(%s, %u): MoveIt's constraints database (warehouse_ros) is not "
                           "provided here; give path constraints as moveit_msgs::Constraints",
                  host.c_str(), port);
}

std::vector<std::string> MoveGroupInterface::getKnownConstraints() const
{
  ROS_ERROR_NAMED(LOGNAME, "getKnownConstraints: MoveIt's constraints database (warehouse_ros) is not provided here");
  return {};
}

moveit_msgs::Constraints MoveGroupInterface::getPathConstraints() const
{
  return impl_->path_constraints_ ? *impl_->path_constraints_ : moveit_msgs::Constraints();
}

bool MoveGroupInterface::setPathConstraints(const std::string& constraint)
{
  ROS_ERROR_NAMED(LOGNAME, "setPathConstraints('%s'): constraints by name come from MoveIt's constraints database "
                           "(warehouse_ros), not provided here; give them as moveit_msgs::Constraints",
                  constraint.c_str());
  return false;
}

void MoveGroupInterface::setPathConstraints(const moveit_msgs::Constraints& constraint)
{
  impl_->path_constraints_ = std::make_unique<moveit_msgs::Constraints>(constraint);
}

void MoveGroupInterface::clearPathConstraints()
{
  impl_->path_constraints_.reset();
}

moveit_msgs::TrajectoryConstraints MoveGroupInterface::getTrajectoryConstraints() const
{
  return impl_->trajectory_constraints_ ? *impl_->trajectory_constraints_ : moveit_msgs::TrajectoryConstraints();
}

void MoveGroupInterface::setTrajectoryConstraints(const moveit_msgs::TrajectoryConstraints& constraint)
{
  impl_->trajectory_constraints_ = std::make_unique<moveit_msgs::TrajectoryConstraints>(constraint);
}

void MoveGroupInterface::clearTrajectoryConstraints()
{
  impl_->trajectory_constraints_.reset();
}

}  // namespace planning_interface
}  // namespace moveit

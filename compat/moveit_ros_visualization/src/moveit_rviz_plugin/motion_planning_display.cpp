/* The MotionPlanning display: properties and saved keys as MoveIt's
 * (motion_planning_display.cpp l. 86-172, 1335-1420 on noetic-devel), the goal marker on the
 * group's end-effector link served on MoveIt's topic
 * (rviz_moveit_motion_planning_display/robot_interaction_interactive_marker_topic) and shown
 * through a child rviz/InteractiveMarkers display (l. 248), the remote-control topics of
 * motion_planning_frame.cpp l. 248-262 (/rviz/moveit/plan, execute, stop, update_start_state,
 * update_goal_state, update_custom_start_state, update_custom_goal_state) when "Allow
 * External Comm." is on, as MoveIt's frame serves them. */
#include "motion_planning_display.h"

#include <QComboBox>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>

#include <moveit_msgs/GetPositionIK.h>
#include <moveit_msgs/GetStateValidity.h>
#include <moveit_msgs/MoveItErrorCodes.h>
#include <moveit_msgs/PlanningScene.h>
#include <rviz/config.h>
#include <rviz/display_context.h>
#include <rviz/display_factory.h>
#include <rviz/properties/bool_property.h>
#include <rviz/properties/color_property.h>
#include <rviz/properties/enum_property.h>
#include <rviz/properties/float_property.h>
#include <std_msgs/String.h>

#include "message_checks.h"

namespace moveit_rviz_plugin
{
namespace
{
const char MARKER_TOPIC[] = "rviz_moveit_motion_planning_display/robot_interaction_interactive_marker_topic";
const char MARKER_NAME[] = "EE:goal";
const double DEFAULT_MARKER_SCALE = 0.25; // m, robot_interaction.cpp l. 116: no link shape to size it by
const double GOAL_JOINT_TOLERANCE = 1e-4; // rad or m: MoveGroupInterface's default goal_joint_tolerance
const double IK_TIMEOUT = 0.1;            // s per compute_ik call while the marker moves
const int RANDOM_VALID_TRIES = 100;       // states drawn for "<random valid>"
const double SERVICE_WAIT = 2.0;          // s to wait for a move_group service on first use
const char CURRENT[] = "<current>";
const char RANDOM_VALID[] = "<random valid>";
const char RANDOM[] = "<random>";
const char PREVIOUS[] = "<previous>";

QString errorCodeName(int value)
{
  using E = moveit_msgs::MoveItErrorCodes;
  static const std::map<int, const char*> names = {
    { E::SUCCESS, "SUCCESS" },
    { E::FAILURE, "FAILURE" },
    { E::PLANNING_FAILED, "PLANNING_FAILED" },
    { E::INVALID_MOTION_PLAN, "INVALID_MOTION_PLAN" },
    { E::MOTION_PLAN_INVALIDATED_BY_ENVIRONMENT_CHANGE, "MOTION_PLAN_INVALIDATED_BY_ENVIRONMENT_CHANGE" },
    { E::CONTROL_FAILED, "CONTROL_FAILED" },
    { E::UNABLE_TO_AQUIRE_SENSOR_DATA, "UNABLE_TO_AQUIRE_SENSOR_DATA" },
    { E::TIMED_OUT, "TIMED_OUT" },
    { E::PREEMPTED, "PREEMPTED" },
    { E::START_STATE_IN_COLLISION, "START_STATE_IN_COLLISION" },
    { E::START_STATE_VIOLATES_PATH_CONSTRAINTS, "START_STATE_VIOLATES_PATH_CONSTRAINTS" },
    { E::START_STATE_INVALID, "START_STATE_INVALID" },
    { E::GOAL_IN_COLLISION, "GOAL_IN_COLLISION" },
    { E::GOAL_VIOLATES_PATH_CONSTRAINTS, "GOAL_VIOLATES_PATH_CONSTRAINTS" },
    { E::GOAL_CONSTRAINTS_VIOLATED, "GOAL_CONSTRAINTS_VIOLATED" },
    { E::GOAL_STATE_INVALID, "GOAL_STATE_INVALID" },
    { E::UNRECOGNIZED_GOAL_TYPE, "UNRECOGNIZED_GOAL_TYPE" },
    { E::INVALID_GROUP_NAME, "INVALID_GROUP_NAME" },
    { E::INVALID_GOAL_CONSTRAINTS, "INVALID_GOAL_CONSTRAINTS" },
    { E::INVALID_ROBOT_STATE, "INVALID_ROBOT_STATE" },
    { E::INVALID_LINK_NAME, "INVALID_LINK_NAME" },
    { E::INVALID_OBJECT_NAME, "INVALID_OBJECT_NAME" },
    { E::FRAME_TRANSFORM_FAILURE, "FRAME_TRANSFORM_FAILURE" },
    { E::COLLISION_CHECKING_UNAVAILABLE, "COLLISION_CHECKING_UNAVAILABLE" },
    { E::ROBOT_STATE_STALE, "ROBOT_STATE_STALE" },
    { E::SENSOR_INFO_STALE, "SENSOR_INFO_STALE" },
    { E::COMMUNICATION_FAILURE, "COMMUNICATION_FAILURE" },
    { E::CRASH, "CRASH" },
    { E::ABORT, "ABORT" },
    { E::NO_IK_SOLUTION, "NO_IK_SOLUTION" },
  };
  auto found = names.find(value);
  return found != names.end() ? QString(found->second) : QString("error code %1").arg(value);
}

Ogre::ColourValue colour(const QColor& color)
{
  return Ogre::ColourValue(color.redF(), color.greenF(), color.blueF());
}

moveit_msgs::RobotState robotStateMsg(const JointPositions& positions)
{
  moveit_msgs::RobotState state;
  for (const auto& joint : positions)
  {
    state.joint_state.name.push_back(joint.first);
    state.joint_state.position.push_back(joint.second);
  }
  return state;
}

void mergeRobotState(const moveit_msgs::RobotState& message, JointPositions& positions)
{
  if (!nonFiniteJoint(message.joint_state).empty())
  {
    ROS_ERROR_STREAM("MotionPlanning: a robot state whose joint '" << nonFiniteJoint(message.joint_state)
                                                                   << "' is not a finite number: ignored");
    return;
  }
  const sensor_msgs::JointState& joints = message.joint_state;
  for (size_t i = 0; i < joints.name.size() && i < joints.position.size(); ++i)
    positions[joints.name[i]] = joints.position[i];
}
}  // namespace

MotionPlanningDisplay::MotionPlanningDisplay() : PlanningSceneDisplay(true, true), random_(std::random_device()())
{
  plan_category_ = new rviz::Property("Planning Request", QVariant(), "", this);
  metrics_category_ = new rviz::Property("Planning Metrics", QVariant(), "", this);
  path_category_ = new rviz::Property("Planned Path", QVariant(), "", this);

  // the metrics are not computed here; their keys load as MoveIt saves them
  new rviz::BoolProperty("Show Weight Limit", false, "Shows the weight limit at a particular pose for an end-effector",
                         metrics_category_);
  new rviz::BoolProperty("Show Manipulability Index", false, "Shows the manipulability index for an end-effector",
                         metrics_category_);
  new rviz::BoolProperty("Show Manipulability", false, "Shows the manipulability for an end-effector",
                         metrics_category_);
  new rviz::BoolProperty("Show Joint Torques", false, "Shows the joint torques for a given configuration and payload",
                         metrics_category_);
  new rviz::FloatProperty("Payload", 1.0f, "Specify the payload at the end effector (kg)", metrics_category_);
  new rviz::FloatProperty("TextHeight", 0.08f, "Text height", metrics_category_);

  planning_group_property_ =
      new rviz::EnumProperty("Planning Group", "", "The name of the group of links to plan for (from the ones defined in the SRDF)",
                             plan_category_, SLOT(changedPlanningGroup()), this);
  show_workspace_property_ = new rviz::BoolProperty(
      "Show Workspace", false, "Shows the axis-aligned bounding box for the workspace allowed for planning", plan_category_);
  query_start_state_property_ =
      new rviz::BoolProperty("Query Start State", false, "Set a custom start state for the motion planning query",
                             plan_category_, SLOT(changedQueryStartState()), this);
  query_goal_state_property_ = new rviz::BoolProperty("Query Goal State", true, "Shows the goal state for the motion planning query",
                                                      plan_category_, SLOT(changedQueryGoalState()), this);
  query_marker_scale_property_ = new rviz::FloatProperty(
      "Interactive Marker Size", 0.0f, "Specifies scale of the interactive marker overlayed on the robot. 0 is auto scale.",
      plan_category_, SLOT(changedQueryMarkerScale()), this);
  query_marker_scale_property_->setMin(0.0f);
  query_start_color_property_ = new rviz::ColorProperty("Start State Color", QColor(0, 255, 0), "The highlight color for the start state",
                                                        plan_category_, SLOT(changedQueryLook()), this);
  query_start_alpha_property_ = new rviz::FloatProperty("Start State Alpha", 1.0f, "Specifies the alpha for the robot links",
                                                        plan_category_, SLOT(changedQueryLook()), this);
  query_start_alpha_property_->setMin(0.0);
  query_start_alpha_property_->setMax(1.0);
  query_goal_color_property_ = new rviz::ColorProperty("Goal State Color", QColor(250, 128, 0), "The highlight color for the goal state",
                                                       plan_category_, SLOT(changedQueryLook()), this);
  query_goal_alpha_property_ = new rviz::FloatProperty("Goal State Alpha", 1.0f, "Specifies the alpha for the robot links",
                                                       plan_category_, SLOT(changedQueryLook()), this);
  query_goal_alpha_property_->setMin(0.0);
  query_goal_alpha_property_->setMax(1.0);
  query_colliding_link_color_property_ = new rviz::ColorProperty(
      "Colliding Link Color", QColor(255, 0, 0), "The highlight color for colliding links", plan_category_);
  query_outside_joint_limits_link_color_property_ =
      new rviz::ColorProperty("Joint Violation Color", QColor(255, 0, 255),
                              "The highlight color for child links of joints that are outside bounds", plan_category_);

  trajectory_visual_.reset(new TrajectoryVisualization(path_category_, this));
}

MotionPlanningDisplay::~MotionPlanningDisplay()
{
  remote_subscribers_.clear();
  marker_server_.reset();
  delete marker_display_;
  trajectory_visual_.reset();
  query_start_robot_.reset();
  query_goal_robot_.reset();
  delete frame_.data();
}

void MotionPlanningDisplay::onInitialize()
{
  PlanningSceneDisplay::onInitialize();
  trajectory_visual_->onInitialize(planning_scene_node_, context_, update_nh_);
  query_start_robot_.reset(new RobotStateVisual(planning_scene_node_, context_, "Planning Request", nullptr));
  query_goal_robot_.reset(new RobotStateVisual(planning_scene_node_, context_, "Planning Request", nullptr));
  query_start_robot_->setVisible(false);
  query_goal_robot_->setVisible(false);

  frame_ = new MotionPlanningFrame;
  setAssociatedWidget(frame_);
  connect(frame_->planning_group, SIGNAL(activated(int)), this, SLOT(groupChosen(int)));
  connect(frame_->start_state, SIGNAL(activated(int)), this, SLOT(startStateChosen(int)));
  connect(frame_->goal_state, SIGNAL(activated(int)), this, SLOT(goalStateChosen(int)));
  connect(frame_->plan_button, SIGNAL(clicked()), this, SLOT(planButtonClicked()));
  connect(frame_->execute_button, SIGNAL(clicked()), this, SLOT(executeButtonClicked()));
  connect(frame_->plan_and_execute_button, SIGNAL(clicked()), this, SLOT(planAndExecuteButtonClicked()));
  connect(frame_->stop_button, SIGNAL(clicked()), this, SLOT(stopButtonClicked()));
  connect(frame_->add_box_button, SIGNAL(clicked()), this, SLOT(addBoxButtonClicked()));
  connect(frame_->remove_object_button, SIGNAL(clicked()), this, SLOT(removeObjectButtonClicked()));
  connect(frame_->allow_external_program, SIGNAL(toggled(bool)), this, SLOT(allowExternalProgram(bool)));

  marker_display_ = context_->getDisplayFactory()->make("rviz/InteractiveMarkers");
  if (marker_display_)
  {
    marker_display_->initialize(context_);
    marker_display_->subProp("Update Topic")->setValue(QString(MARKER_TOPIC) + "/update");
    marker_display_->setEnabled(true);
  }
}

void MotionPlanningDisplay::onEnable()
{
  PlanningSceneDisplay::onEnable();
  trajectory_visual_->onEnable();
  action_prefix_ = moveGroupPrefix();
  move_group_client_.reset(
      new actionlib::SimpleActionClient<moveit_msgs::MoveGroupAction>(update_nh_, action_prefix_ + "move_group", false));
  execute_client_.reset(new actionlib::SimpleActionClient<moveit_msgs::ExecuteTrajectoryAction>(
      update_nh_, action_prefix_ + "execute_trajectory", false));
  planning_scene_publisher_ = update_nh_.advertise<moveit_msgs::PlanningScene>(action_prefix_ + "planning_scene", 1);
  execution_event_publisher_ = update_nh_.advertise<std_msgs::String>(action_prefix_ + "trajectory_execution_event", 1);
  ik_client_ = update_nh_.serviceClient<moveit_msgs::GetPositionIK>(action_prefix_ + "compute_ik");
  validity_client_ = update_nh_.serviceClient<moveit_msgs::GetStateValidity>(action_prefix_ + "check_state_validity");
  if (!marker_server_)
    marker_server_.reset(new interactive_markers::InteractiveMarkerServer(MARKER_TOPIC, "", false));
  if (marker_display_)
    marker_display_->setEnabled(true);
  if (frame_ && frame_->allow_external_program->isChecked())
    allowExternalProgram(true);
  query_changed_ = true;
}

void MotionPlanningDisplay::onDisable()
{
  remote_subscribers_.clear();
  move_group_client_.reset();
  execute_client_.reset();
  if (marker_server_)
  {
    marker_server_->clear();
    marker_server_->applyChanges();
  }
  if (marker_display_)
    marker_display_->setEnabled(false);
  trajectory_visual_->onDisable();
  query_start_robot_->setVisible(false);
  query_goal_robot_->setVisible(false);
  PlanningSceneDisplay::onDisable();
}

void MotionPlanningDisplay::reset()
{
  PlanningSceneDisplay::reset();
  trajectory_visual_->reset();
}

void MotionPlanningDisplay::onRobotModelLoaded()
{
  PlanningSceneDisplay::onRobotModelLoaded();
  trajectory_visual_->onRobotModelLoaded(kinematics_);
  query_start_robot_->load(kinematics_);
  query_goal_robot_->load(kinematics_);
  changedQueryLook();
  const QString chosen = planning_group_property_->getString();
  planning_group_property_->clearOptions();
  frame_->planning_group->clear();
  for (const auto& group : srdf_.groups)
  {
    planning_group_property_->addOptionStd(group.name);
    frame_->planning_group->addItem(QString::fromStdString(group.name));
  }
  if (srdf_.group(chosen.toStdString()) == nullptr && !srdf_.groups.empty())
    planning_group_property_->setStdString(srdf_.groups.front().name);
  changedPlanningGroup();
  goal_initialised_ = false;
}

std::string MotionPlanningDisplay::currentGroup() const
{
  return planning_group_property_->getStdString();
}

void MotionPlanningDisplay::changedPlanningGroup()
{
  if (!frame_)
    return;
  const int index = frame_->planning_group->findText(planning_group_property_->getString());
  if (index >= 0)
    frame_->planning_group->setCurrentIndex(index);
  fillStateChoices();
  marker_link_ = robotModelLoaded() ? kinematics_.groupTipLink(srdf_, currentGroup()) : std::string();
  query_changed_ = true;
  publishGoalMarker();
}

void MotionPlanningDisplay::groupChosen(int index)
{
  planning_group_property_->setString(frame_->planning_group->itemText(index));
}

void MotionPlanningDisplay::fillStateChoices()
{
  for (QComboBox* box : { frame_->start_state, frame_->goal_state })
  {
    box->clear();
    box->addItem(CURRENT);
    box->addItem(RANDOM_VALID);
    box->addItem(RANDOM);
    box->addItem(PREVIOUS);
    for (const SrdfGroupState* state : srdf_.statesOf(currentGroup()))
      box->addItem(QString::fromStdString(state->name));
  }
}

bool MotionPlanningDisplay::chooseState(const QString& choice, JointPositions& state, const JointPositions& base)
{
  const std::vector<std::string> joints = kinematics_.groupJoints(srdf_, currentGroup());
  state = base;
  if (choice == CURRENT)
  {
    state = sceneJointPositions();
    return true;
  }
  if (choice == PREVIOUS)
  {
    state = previous_start_.empty() ? sceneJointPositions() : previous_start_;
    return true;
  }
  if (choice == RANDOM || choice == RANDOM_VALID)
  {
    const bool check = choice == RANDOM_VALID && validity_client_.waitForExistence(ros::Duration(SERVICE_WAIT));
    for (int attempt = 0; attempt < RANDOM_VALID_TRIES; ++attempt)
    {
      for (const auto& joint : joints)
        state[joint] = kinematics_.randomPosition(joint, random_);
      if (!check)
        return true;
      moveit_msgs::GetStateValidity validity;
      validity.request.robot_state = robotStateMsg(state);
      validity.request.group_name = currentGroup();
      if (validity_client_.call(validity) && validity.response.valid)
        return true;
    }
    showResult(QString("no valid random state in %1 tries").arg(RANDOM_VALID_TRIES));
    return false;
  }
  for (const SrdfGroupState* named : srdf_.statesOf(currentGroup()))
    if (QString::fromStdString(named->name) == choice)
    {
      for (const auto& value : named->values)
        if (!value.second.empty())
          state[value.first] = value.second.front();
      return true;
    }
  return false;
}

void MotionPlanningDisplay::startStateChosen(int index)
{
  const QString choice = frame_->start_state->itemText(index);
  start_is_current_ = choice == CURRENT;
  JointPositions state;
  if (chooseState(choice, state, query_start_))
    query_start_ = state;
  query_changed_ = true;
}

void MotionPlanningDisplay::goalStateChosen(int index)
{
  JointPositions state;
  if (chooseState(frame_->goal_state->itemText(index), state, query_goal_))
    query_goal_ = state;
  goal_initialised_ = true;
  query_changed_ = true;
  publishGoalMarker();
}

void MotionPlanningDisplay::changedQueryStartState()
{
  query_changed_ = true;
}

void MotionPlanningDisplay::changedQueryGoalState()
{
  query_changed_ = true;
  publishGoalMarker();
}

void MotionPlanningDisplay::changedQueryMarkerScale()
{
  publishGoalMarker();
}

void MotionPlanningDisplay::changedQueryLook()
{
  if (!query_start_robot_)
    return;
  query_start_robot_->setColor(colour(query_start_color_property_->getColor()));
  query_start_robot_->setAlpha(query_start_alpha_property_->getFloat());
  query_goal_robot_->setColor(colour(query_goal_color_property_->getColor()));
  query_goal_robot_->setAlpha(query_goal_alpha_property_->getFloat());
  query_changed_ = true;
}

void MotionPlanningDisplay::update(float wall_dt, float ros_dt)
{
  PlanningSceneDisplay::update(wall_dt, ros_dt);
  if (!robotModelLoaded())
    return;
  trajectory_visual_->setCurrentState(sceneJointPositions());
  trajectory_visual_->update(wall_dt, ros_dt);
  if (start_is_current_ && query_start_ != sceneJointPositions())
  {
    query_start_ = sceneJointPositions();
    query_changed_ = true;
  }
  if (!goal_initialised_ && !sceneJointPositions().empty())
  {
    // MoveIt's goal state starts as the current state
    query_goal_ = sceneJointPositions();
    goal_initialised_ = true;
    query_changed_ = true;
    publishGoalMarker();
  }
  if (marker_pose_pending_)
    applyMarkerPose();
  if (query_changed_)
  {
    query_changed_ = false;
    query_start_robot_->update(query_start_, {});
    query_goal_robot_->update(query_goal_, {});
    query_start_robot_->setVisible(isEnabled() && query_start_state_property_->getBool());
    query_goal_robot_->setVisible(isEnabled() && query_goal_state_property_->getBool());
  }
  if (marker_display_ && marker_display_->isEnabled())
    marker_display_->update(wall_dt, ros_dt);
}

// the Scene Objects list follows the world as drawn
void MotionPlanningDisplay::onSceneRendered()
{
  QStringList names;
  for (const auto& object : worldObjects())
    names << QString::fromStdString(object.first);
  QStringList shown;
  for (int i = 0; i < frame_->scene_objects->count(); ++i)
    shown << frame_->scene_objects->item(i)->text();
  if (names != shown)
  {
    frame_->scene_objects->clear();
    frame_->scene_objects->addItems(names);
  }
}

void MotionPlanningDisplay::showResult(const QString& text)
{
  if (frame_)
    frame_->result_label->setText(text);
  setStatusStd(rviz::StatusProperty::Ok, "Planning", text.toStdString());
}

void MotionPlanningDisplay::sendMoveGroupGoal(bool plan_only)
{
  if (!move_group_client_ || !move_group_client_->isServerConnected())
  {
    showResult("move_group's action '" + QString::fromStdString(action_prefix_) + "move_group' is not connected");
    return;
  }
  const std::string group = currentGroup();
  const std::vector<std::string> joints = kinematics_.groupJoints(srdf_, group);
  if (joints.empty())
  {
    showResult("the planning group '" + QString::fromStdString(group) + "' has no joints to plan for");
    return;
  }
  moveit_msgs::MoveGroupGoal goal;
  moveit_msgs::MotionPlanRequest& request = goal.request;
  request.group_name = group;
  request.num_planning_attempts = frame_->planning_attempts->value();
  request.allowed_planning_time = frame_->planning_time->value();
  request.max_velocity_scaling_factor = frame_->velocity_scaling_factor->value();
  request.max_acceleration_scaling_factor = frame_->acceleration_scaling_factor->value();
  request.workspace_parameters.header.frame_id = planningFrame();
  if (start_is_current_)
    request.start_state.is_diff = true;
  else
    request.start_state = robotStateMsg(query_start_);
  moveit_msgs::Constraints constraints;
  for (const auto& joint : joints)
  {
    moveit_msgs::JointConstraint constraint;
    constraint.joint_name = joint;
    auto found = query_goal_.find(joint);
    constraint.position = found != query_goal_.end() ? found->second : kinematics_.defaultPosition(joint);
    constraint.tolerance_above = constraint.tolerance_below = GOAL_JOINT_TOLERANCE;
    constraint.weight = 1.0;
    constraints.joint_constraints.push_back(constraint);
  }
  request.goal_constraints.push_back(constraints);
  goal.planning_options.plan_only = plan_only;
  goal.planning_options.planning_scene_diff.is_diff = true;
  goal.planning_options.planning_scene_diff.robot_state.is_diff = true;
  previous_start_ = start_is_current_ ? sceneJointPositions() : query_start_;
  showResult(plan_only ? "Planning..." : "Planning and executing...");
  frame_->execute_button->setEnabled(false);
  const ros::WallTime started = ros::WallTime::now();
  move_group_client_->sendGoal(goal,
                               [this, plan_only, started](const actionlib::SimpleClientGoalState& state,
                                                          const moveit_msgs::MoveGroupResultConstPtr& result) {
                                 moveGroupDone(state, result, plan_only, started);
                               });
}

void MotionPlanningDisplay::moveGroupDone(const actionlib::SimpleClientGoalState& state,
                                          const moveit_msgs::MoveGroupResultConstPtr& result, bool plan_only,
                                          ros::WallTime started)
{
  const double seconds = (ros::WallTime::now() - started).toSec();
  if (!result)
  {
    showResult(QString("move_group gave no result (%1)").arg(QString::fromStdString(state.toString())));
    return;
  }
  const int code = result->error_code.val;
  if (code == moveit_msgs::MoveItErrorCodes::SUCCESS)
  {
    last_plan_ = result->planned_trajectory;
    have_plan_ = plan_only;
    frame_->execute_button->setEnabled(have_plan_);
    showResult(QString("%1: SUCCESS, planned in %2 s")
                   .arg(plan_only ? "Plan" : "Plan & Execute")
                   .arg(result->planning_time > 0 ? result->planning_time : seconds, 0, 'f', 3));
  }
  else
  {
    have_plan_ = false;
    showResult(QString("%1: %2").arg(plan_only ? "Plan" : "Plan & Execute").arg(errorCodeName(code)));
  }
}

void MotionPlanningDisplay::executeDone(const actionlib::SimpleClientGoalState& state,
                                        const moveit_msgs::ExecuteTrajectoryResultConstPtr& result)
{
  if (!result)
    showResult(QString("Execute: no result (%1)").arg(QString::fromStdString(state.toString())));
  else
    showResult(QString("Execute: %1").arg(errorCodeName(result->error_code.val)));
}

void MotionPlanningDisplay::planButtonClicked()
{
  sendMoveGroupGoal(true);
}

void MotionPlanningDisplay::planAndExecuteButtonClicked()
{
  sendMoveGroupGoal(false);
}

void MotionPlanningDisplay::executeButtonClicked()
{
  if (!have_plan_)
  {
    showResult("Execute: no plan to execute (press Plan first)");
    return;
  }
  if (!execute_client_ || !execute_client_->isServerConnected())
  {
    showResult("move_group's action '" + QString::fromStdString(action_prefix_) + "execute_trajectory' is not connected");
    return;
  }
  moveit_msgs::ExecuteTrajectoryGoal goal;
  goal.trajectory = last_plan_;
  have_plan_ = false;
  frame_->execute_button->setEnabled(false);
  showResult("Executing...");
  execute_client_->sendGoal(goal, [this](const actionlib::SimpleClientGoalState& state,
                                         const moveit_msgs::ExecuteTrajectoryResultConstPtr& result) {
    executeDone(state, result);
  });
}

void MotionPlanningDisplay::stopButtonClicked()
{
  // MoveGroupInterface::stop: "stop" on trajectory_execution_event
  std_msgs::String event;
  event.data = "stop";
  execution_event_publisher_.publish(event);
  if (move_group_client_ && move_group_client_->isServerConnected())
    move_group_client_->cancelAllGoals();
  showResult("Stop requested");
}

void MotionPlanningDisplay::addBoxButtonClicked()
{
  moveit_msgs::PlanningScene scene;
  scene.is_diff = true;
  scene.robot_state.is_diff = true;
  moveit_msgs::CollisionObject box;
  box.header.frame_id = planningFrame();
  box.id = "Box_" + std::to_string(box_count_++);
  while (worldObjects().count(box.id))
    box.id = "Box_" + std::to_string(box_count_++);
  box.pose.orientation.w = 1.0;
  shape_msgs::SolidPrimitive primitive;
  primitive.type = shape_msgs::SolidPrimitive::BOX;
  for (int i = 0; i < 3; ++i)
    primitive.dimensions.push_back(frame_->box_size[i]->value());
  geometry_msgs::Pose pose;
  pose.position.x = frame_->box_position[0]->value();
  pose.position.y = frame_->box_position[1]->value();
  pose.position.z = frame_->box_position[2]->value();
  pose.orientation.w = 1.0;
  box.primitives.push_back(primitive);
  box.primitive_poses.push_back(pose);
  box.operation = moveit_msgs::CollisionObject::ADD;
  scene.world.collision_objects.push_back(box);
  planning_scene_publisher_.publish(scene);
  showResult("Added " + QString::fromStdString(box.id));
}

void MotionPlanningDisplay::removeObjectButtonClicked()
{
  QListWidgetItem* item = frame_->scene_objects->currentItem();
  if (!item)
    return;
  moveit_msgs::PlanningScene scene;
  scene.is_diff = true;
  scene.robot_state.is_diff = true;
  moveit_msgs::CollisionObject object;
  object.header.frame_id = planningFrame();
  object.id = item->text().toStdString();
  object.operation = moveit_msgs::CollisionObject::REMOVE;
  scene.world.collision_objects.push_back(object);
  planning_scene_publisher_.publish(scene);
}

void MotionPlanningDisplay::publishGoalMarker()
{
  if (!marker_server_)
    return;
  marker_server_->clear();
  if (!robotModelLoaded() || marker_link_.empty() || !query_goal_state_property_->getBool() || !isEnabled())
  {
    marker_server_->applyChanges();
    return;
  }
  const LinkPoses poses = kinematics_.linkPoses(query_goal_);
  auto link = poses.find(marker_link_);
  if (link == poses.end())
  {
    marker_server_->applyChanges();
    return;
  }
  visualization_msgs::InteractiveMarker marker;
  marker.header.frame_id = planningFrame();
  marker.name = MARKER_NAME;
  const float size = query_marker_scale_property_->getFloat();
  const double link_size = kinematics_.markerSize(marker_link_);
  marker.scale = size > 0.0f ? size : (link_size > 0.0 ? link_size : DEFAULT_MARKER_SCALE);
  marker.pose.position.x = link->second.p.x();
  marker.pose.position.y = link->second.p.y();
  marker.pose.position.z = link->second.p.z();
  link->second.M.GetQuaternion(marker.pose.orientation.x, marker.pose.orientation.y, marker.pose.orientation.z,
                               marker.pose.orientation.w);
  // six controls: a move and a rotate along each axis (interactive_markers' 6-DOF pattern)
  const double h = M_SQRT1_2;
  const double axes[3][4] = { { h, h, 0, 0 }, { h, 0, 0, h }, { h, 0, h, 0 } };
  const char* names[3] = { "x", "y", "z" };
  for (int i = 0; i < 3; ++i)
    for (bool rotate : { false, true })
    {
      visualization_msgs::InteractiveMarkerControl control;
      control.orientation.w = axes[i][0];
      control.orientation.x = axes[i][1];
      control.orientation.y = axes[i][2];
      control.orientation.z = axes[i][3];
      control.name = std::string(rotate ? "rotate_" : "move_") + names[i];
      control.interaction_mode = rotate ? visualization_msgs::InteractiveMarkerControl::ROTATE_AXIS :
                                          visualization_msgs::InteractiveMarkerControl::MOVE_AXIS;
      marker.controls.push_back(control);
    }
  marker_server_->insert(marker, [this](const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback) {
    goalMarkerFeedback(feedback);
  });
  marker_server_->applyChanges();
}

void MotionPlanningDisplay::goalMarkerFeedback(const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback)
{
  if (feedback->event_type != visualization_msgs::InteractiveMarkerFeedback::POSE_UPDATE &&
      feedback->event_type != visualization_msgs::InteractiveMarkerFeedback::MOUSE_UP)
    return;
  if (!finite(feedback->pose))
    return;
  marker_pose_ = feedback->pose;
  marker_pose_pending_ = true;
}

void MotionPlanningDisplay::applyMarkerPose()
{
  marker_pose_pending_ = false;
  if (!ik_client_.exists())
  {
    showResult("compute_ik is not served: the goal marker cannot move the goal state");
    return;
  }
  moveit_msgs::GetPositionIK ik;
  ik.request.ik_request.group_name = currentGroup();
  ik.request.ik_request.robot_state = robotStateMsg(query_goal_);
  ik.request.ik_request.ik_link_name = marker_link_;
  ik.request.ik_request.pose_stamped.header.frame_id = planningFrame();
  ik.request.ik_request.pose_stamped.pose = marker_pose_;
  ik.request.ik_request.timeout = ros::Duration(IK_TIMEOUT);
  ik.request.ik_request.avoid_collisions = false;
  if (ik_client_.call(ik) && ik.response.error_code.val == moveit_msgs::MoveItErrorCodes::SUCCESS)
  {
    mergeRobotState(ik.response.solution, query_goal_);
    query_changed_ = true;
    deleteStatusStd("Goal Marker");
  }
  else
    setStatusStd(rviz::StatusProperty::Warn, "Goal Marker",
                 "no IK solution for the marker's pose: " + errorCodeName(ik.response.error_code.val).toStdString());
}

void MotionPlanningDisplay::allowExternalProgram(bool allow)
{
  remote_subscribers_.clear();
  if (!allow || !isEnabled())
    return;
  ros::NodeHandle handle;
  remote_subscribers_.push_back(handle.subscribe("/rviz/moveit/plan", 1, &MotionPlanningDisplay::remotePlan, this));
  remote_subscribers_.push_back(handle.subscribe("/rviz/moveit/execute", 1, &MotionPlanningDisplay::remoteExecute, this));
  remote_subscribers_.push_back(handle.subscribe("/rviz/moveit/stop", 1, &MotionPlanningDisplay::remoteStop, this));
  remote_subscribers_.push_back(
      handle.subscribe("/rviz/moveit/update_start_state", 1, &MotionPlanningDisplay::remoteUpdateStartState, this));
  remote_subscribers_.push_back(
      handle.subscribe("/rviz/moveit/update_goal_state", 1, &MotionPlanningDisplay::remoteUpdateGoalState, this));
  remote_subscribers_.push_back(handle.subscribe("/rviz/moveit/update_custom_start_state", 1,
                                                 &MotionPlanningDisplay::remoteUpdateCustomStartState, this));
  remote_subscribers_.push_back(handle.subscribe("/rviz/moveit/update_custom_goal_state", 1,
                                                 &MotionPlanningDisplay::remoteUpdateCustomGoalState, this));
}

void MotionPlanningDisplay::remotePlan(const std_msgs::EmptyConstPtr&)
{
  planButtonClicked();
}

void MotionPlanningDisplay::remoteExecute(const std_msgs::EmptyConstPtr&)
{
  executeButtonClicked();
}

void MotionPlanningDisplay::remoteStop(const std_msgs::EmptyConstPtr&)
{
  stopButtonClicked();
}

void MotionPlanningDisplay::remoteUpdateStartState(const std_msgs::EmptyConstPtr&)
{
  // motion_planning_frame_planning.cpp l. 559-571: the start state becomes the current state
  start_is_current_ = true;
  query_start_ = sceneJointPositions();
  query_changed_ = true;
}

void MotionPlanningDisplay::remoteUpdateGoalState(const std_msgs::EmptyConstPtr&)
{
  query_goal_ = sceneJointPositions();
  query_changed_ = true;
  publishGoalMarker();
}

void MotionPlanningDisplay::remoteUpdateCustomStartState(const moveit_msgs::RobotStateConstPtr& state)
{
  start_is_current_ = false;
  query_start_ = sceneJointPositions();
  mergeRobotState(*state, query_start_);
  query_changed_ = true;
}

void MotionPlanningDisplay::remoteUpdateCustomGoalState(const moveit_msgs::RobotStateConstPtr& state)
{
  query_goal_ = sceneJointPositions();
  mergeRobotState(*state, query_goal_);
  goal_initialised_ = true;
  query_changed_ = true;
  publishGoalMarker();
}

void MotionPlanningDisplay::load(const rviz::Config& config)
{
  PlanningSceneDisplay::load(config);
  if (!frame_)
    return;
  float value;
  int count;
  bool flag;
  if (config.mapGetFloat("MoveIt_Planning_Time", &value))
    frame_->planning_time->setValue(value);
  if (config.mapGetInt("MoveIt_Planning_Attempts", &count))
    frame_->planning_attempts->setValue(count);
  if (config.mapGetFloat("Velocity_Scaling_Factor", &value))
    frame_->velocity_scaling_factor->setValue(value);
  if (config.mapGetFloat("Acceleration_Scaling_Factor", &value))
    frame_->acceleration_scaling_factor->setValue(value);
  if (config.mapGetBool("MoveIt_Allow_External_Program", &flag))
    frame_->allow_external_program->setChecked(flag);
}

void MotionPlanningDisplay::save(rviz::Config config) const
{
  PlanningSceneDisplay::save(config);
  if (!frame_)
    return;
  config.mapSetValue("MoveIt_Planning_Time", frame_->planning_time->value());
  config.mapSetValue("MoveIt_Planning_Attempts", frame_->planning_attempts->value());
  config.mapSetValue("Velocity_Scaling_Factor", frame_->velocity_scaling_factor->value());
  config.mapSetValue("Acceleration_Scaling_Factor", frame_->acceleration_scaling_factor->value());
  config.mapSetValue("MoveIt_Allow_External_Program", frame_->allow_external_program->isChecked());
}
}  // namespace moveit_rviz_plugin

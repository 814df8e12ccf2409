/* moveit_rviz_plugin/MotionPlanning: the planning scene (PlanningSceneDisplay), the planned
 * path (TrajectoryVisualization under "Planned Path"), the query's start and goal states, an
 * interactive marker on the group's end effector that moves the goal through move_group's
 * compute_ik, and the panel whose buttons plan and execute through move_group's actions
 * (`move_group`, `execute_trajectory`), as MoveIt's MotionPlanningDisplay does. Properties and
 * saved keys: motion_planning_display.cpp l. 86-172 and 1335-1420 (noetic-devel). */
#pragma once

#include <memory>
#include <random>
#include <string>

#include <QPointer>
#include <actionlib/client/simple_action_client.h>
#include <interactive_markers/interactive_marker_server.h>
#include <moveit_msgs/ExecuteTrajectoryAction.h>
#include <moveit_msgs/MoveGroupAction.h>
#include <moveit_msgs/RobotState.h>
#include <std_msgs/Empty.h>

#include "motion_planning_frame.h"
#include "planning_scene_display.h"
#include "trajectory_visualization.h"

namespace rviz
{
class Config;
class Display;
}  // namespace rviz

namespace moveit_rviz_plugin
{
class MotionPlanningDisplay : public PlanningSceneDisplay
{
  Q_OBJECT
public:
  MotionPlanningDisplay();
  ~MotionPlanningDisplay() override;

  void update(float wall_dt, float ros_dt) override;
  void reset() override;
  void load(const rviz::Config& config) override;
  void save(rviz::Config config) const override;

private Q_SLOTS:
  void changedPlanningGroup();
  void changedQueryStartState();
  void changedQueryGoalState();
  void changedQueryLook();
  void changedQueryMarkerScale();
  void startStateChosen(int index);
  void goalStateChosen(int index);
  void groupChosen(int index);
  void planButtonClicked();
  void executeButtonClicked();
  void planAndExecuteButtonClicked();
  void stopButtonClicked();
  void addBoxButtonClicked();
  void removeObjectButtonClicked();
  void allowExternalProgram(bool allow);

private:
  void onInitialize() override;
  void onEnable() override;
  void onDisable() override;
  void onRobotModelLoaded() override;
  void onSceneRendered() override;

  std::string currentGroup() const;
  void fillStateChoices();
  /* The positions a choice ("<current>", "<random valid>", "<previous>", a named state)
   * gives the group's joints over `base`. */
  bool chooseState(const QString& choice, JointPositions& state, const JointPositions& base);
  void sendMoveGroupGoal(bool plan_only);
  void moveGroupDone(const actionlib::SimpleClientGoalState& state, const moveit_msgs::MoveGroupResultConstPtr& result,
                     bool plan_only, ros::WallTime started);
  void executeDone(const actionlib::SimpleClientGoalState& state,
                   const moveit_msgs::ExecuteTrajectoryResultConstPtr& result);
  void showResult(const QString& text);
  void publishGoalMarker();
  void goalMarkerFeedback(const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback);
  void applyMarkerPose();

  void remotePlan(const std_msgs::EmptyConstPtr&);
  void remoteExecute(const std_msgs::EmptyConstPtr&);
  void remoteStop(const std_msgs::EmptyConstPtr&);
  void remoteUpdateStartState(const std_msgs::EmptyConstPtr&);
  void remoteUpdateGoalState(const std_msgs::EmptyConstPtr&);
  void remoteUpdateCustomStartState(const moveit_msgs::RobotStateConstPtr& state);
  void remoteUpdateCustomGoalState(const moveit_msgs::RobotStateConstPtr& state);

  rviz::Property* plan_category_;
  rviz::Property* metrics_category_;
  rviz::Property* path_category_;
  rviz::EnumProperty* planning_group_property_;
  rviz::BoolProperty* show_workspace_property_;
  rviz::BoolProperty* query_start_state_property_;
  rviz::BoolProperty* query_goal_state_property_;
  rviz::FloatProperty* query_marker_scale_property_;
  rviz::ColorProperty* query_start_color_property_;
  rviz::FloatProperty* query_start_alpha_property_;
  rviz::ColorProperty* query_goal_color_property_;
  rviz::FloatProperty* query_goal_alpha_property_;
  rviz::ColorProperty* query_colliding_link_color_property_;
  rviz::ColorProperty* query_outside_joint_limits_link_color_property_;

  std::unique_ptr<TrajectoryVisualization> trajectory_visual_;
  // rviz's dock owns the panel once it is the display's associated widget (and deletes it
  // with the dock): the pointer goes null if that happens first
  QPointer<MotionPlanningFrame> frame_;
  std::unique_ptr<RobotStateVisual> query_start_robot_;
  std::unique_ptr<RobotStateVisual> query_goal_robot_;
  JointPositions query_start_;
  JointPositions query_goal_;
  JointPositions previous_start_;
  bool start_is_current_ = true;
  bool goal_initialised_ = false;
  bool query_changed_ = true;
  std::mt19937 random_;

  std::unique_ptr<actionlib::SimpleActionClient<moveit_msgs::MoveGroupAction>> move_group_client_;
  std::unique_ptr<actionlib::SimpleActionClient<moveit_msgs::ExecuteTrajectoryAction>> execute_client_;
  std::string action_prefix_;
  moveit_msgs::RobotTrajectory last_plan_;
  bool have_plan_ = false;
  ros::Publisher planning_scene_publisher_;
  ros::Publisher execution_event_publisher_;
  ros::ServiceClient ik_client_;
  ros::ServiceClient validity_client_;
  std::vector<ros::Subscriber> remote_subscribers_;

  std::unique_ptr<interactive_markers::InteractiveMarkerServer> marker_server_;
  rviz::Display* marker_display_ = nullptr;
  bool marker_pose_pending_ = false;
  geometry_msgs::Pose marker_pose_;
  std::string marker_link_;
  int box_count_ = 0;
};
}  // namespace moveit_rviz_plugin

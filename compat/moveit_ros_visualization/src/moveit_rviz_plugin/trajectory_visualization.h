/* A planned path animated in rviz, as MoveIt's TrajectoryVisualization animates it: the
 * waypoints of a DisplayTrajectory (its start state, then each joint trajectory's points)
 * shown one after the other at the path's own timing scaled by "State Display Time" ("3x":
 * three times as fast; "0.1s": a fixed time per waypoint), looped or not, with a trail.
 * Properties: names and defaults of trajectory_visualization.cpp l. 68-137 (noetic-devel).
 * Used by the Trajectory display and by MotionPlanning's "Planned Path". */
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <QObject>
#include <moveit_msgs/DisplayTrajectory.h>
#include <ros/ros.h>

#include "robot_kinematics.h"
#include "robot_state_visual.h"

namespace rviz
{
class BoolProperty;
class ColorProperty;
class Display;
class DisplayContext;
class EditableEnumProperty;
class FloatProperty;
class IntProperty;
class Property;
class RosTopicProperty;
}  // namespace rviz

namespace moveit_rviz_plugin
{
class TrajectoryVisualization : public QObject
{
  Q_OBJECT
public:
  TrajectoryVisualization(rviz::Property* widget, rviz::Display* display);
  ~TrajectoryVisualization() override;

  void onInitialize(Ogre::SceneNode* node, rviz::DisplayContext* context, const ros::NodeHandle& handle);
  void onRobotModelLoaded(const RobotKinematics& kinematics);
  void onEnable();
  void onDisable();
  void reset();
  void update(float wall_dt, float ros_dt);

  /* Shows a path (the display's own subscription calls it too). */
  void showTrajectory(const moveit_msgs::DisplayTrajectory& trajectory);
  /* The scene's current joint positions: a path's start state fills the joints its
   * messages leave out. */
  void setCurrentState(const JointPositions& positions) { current_ = positions; }

private Q_SLOTS:
  void changedTrajectoryTopic();
  void changedRobotPathAlpha();
  void changedDisplayPathVisualEnabled();
  void changedDisplayPathCollisionEnabled();
  void changedShowTrail();
  void changedTrailStepSize();
  void changedRobotColor();
  void enabledRobotColor();

private:
  struct Waypoint
  {
    JointPositions positions;
    double from_previous;  // s
  };

  void incomingDisplayTrajectory(const moveit_msgs::DisplayTrajectory::ConstPtr& message);
  /* < 0: a factor of the path's timing (-3 for "3x"); > 0: seconds per waypoint. */
  float stateDisplayTime();
  void showWaypoint(size_t index);
  void buildTrail();
  void applyLook(RobotStateVisual& visual);

  rviz::Display* display_;
  rviz::DisplayContext* context_ = nullptr;
  Ogre::SceneNode* node_ = nullptr;
  ros::NodeHandle handle_;
  ros::Subscriber subscriber_;
  const RobotKinematics* kinematics_ = nullptr;
  std::unique_ptr<RobotStateVisual> path_robot_;
  std::vector<std::unique_ptr<RobotStateVisual>> trail_;
  JointPositions current_;

  std::mutex incoming_lock_;
  std::vector<Waypoint> to_display_;
  std::vector<Waypoint> displaying_;
  std::vector<moveit_msgs::AttachedCollisionObject> displaying_attached_;
  bool animating_ = false;
  bool interrupt_ = false;
  long current_waypoint_ = -1;
  float waypoint_time_ = 0.0f;

  rviz::RosTopicProperty* trajectory_topic_property_;
  rviz::BoolProperty* display_path_visual_enabled_property_;
  rviz::BoolProperty* display_path_collision_enabled_property_;
  rviz::FloatProperty* robot_path_alpha_property_;
  rviz::EditableEnumProperty* state_display_time_property_;
  rviz::BoolProperty* use_sim_time_property_;
  rviz::BoolProperty* loop_display_property_;
  rviz::BoolProperty* trail_display_property_;
  rviz::IntProperty* trail_step_size_property_;
  rviz::BoolProperty* interrupt_display_property_;
  rviz::ColorProperty* robot_color_property_;
  rviz::BoolProperty* enable_robot_color_property_;
};
}  // namespace moveit_rviz_plugin

/* moveit_rviz_plugin/RobotState: a robot state from `display_robot_state`
 * (moveit_msgs/DisplayRobotState), its attached bodies and link highlights. Properties:
 * names and defaults of robot_state_display.cpp l. 62-104 (noetic-devel). */
#pragma once

#include <memory>

#include <moveit_msgs/DisplayRobotState.h>
#include <ros/ros.h>
#include "robot_model_display.h"
#include "robot_state_visual.h"

namespace rviz
{
class BoolProperty;
class ColorProperty;
class FloatProperty;
class RosTopicProperty;
class StringProperty;
}  // namespace rviz

namespace moveit_rviz_plugin
{
class RobotStateDisplay : public RobotModelDisplay
{
  Q_OBJECT
public:
  RobotStateDisplay();
  ~RobotStateDisplay() override;

  void update(float wall_dt, float ros_dt) override;
  void reset() override;

private Q_SLOTS:
  void changedRobotStateTopic();
  void changedLook();

private:
  void onInitialize() override;
  void onEnable() override;
  void onDisable() override;
  void onRobotModelLoaded() override;
  void incomingRobotState(const moveit_msgs::DisplayRobotState::ConstPtr& message);
  void render();

  rviz::RosTopicProperty* robot_state_topic_property_;
  rviz::StringProperty* root_link_name_property_;
  rviz::FloatProperty* robot_alpha_property_;
  rviz::ColorProperty* attached_body_color_property_;
  rviz::BoolProperty* enable_link_highlight_;
  rviz::BoolProperty* enable_visual_visible_;
  rviz::BoolProperty* enable_collision_visible_;
  rviz::BoolProperty* show_all_links_;

  ros::Subscriber subscriber_;
  std::unique_ptr<RobotStateVisual> robot_;
  bool changed_ = false;
  bool hidden_ = false;
  JointPositions positions_;
  std::vector<moveit_msgs::AttachedCollisionObject> attached_;
  std::map<std::string, Ogre::ColourValue> highlights_;
};
}  // namespace moveit_rviz_plugin

/* moveit_rviz_plugin/PlanningScene: the planning scene move_group monitors, as MoveIt's
 * display draws it: the robot in the scene's state, the world's collision objects and the
 * attached ones, read from `move_group/monitored_planning_scene` (full scenes and diffs).
 * Its properties carry MoveIt's names so saved configs load unchanged
 * (moveit_ros/visualization/planning_scene_rviz_plugin/src/planning_scene_display.cpp
 * l. 66-155 on noetic-devel). MotionPlanningDisplay derives from it, as MoveIt's does. */
#pragma once

#include <map>
#include <memory>
#include <string>

#include <moveit_msgs/PlanningScene.h>
#include <ros/ros.h>
#include "collision_object_visual.h"
#include "robot_model_display.h"
#include "robot_state_visual.h"

namespace rviz
{
class BoolProperty;
class ColorProperty;
class EnumProperty;
class FloatProperty;
class RosTopicProperty;
class StringProperty;
}  // namespace rviz

namespace moveit_rviz_plugin
{
class PlanningSceneDisplay : public RobotModelDisplay
{
  Q_OBJECT
public:
  explicit PlanningSceneDisplay(bool listen_to_planning_scene = true, bool show_scene_robot = true);
  ~PlanningSceneDisplay() override;

  void update(float wall_dt, float ros_dt) override;
  void reset() override;

  /* The scene as last received (for tests and the MotionPlanning panel). */
  const std::map<std::string, moveit_msgs::CollisionObject>& worldObjects() const { return world_; }
  const JointPositions& sceneJointPositions() const { return scene_joints_; }

protected Q_SLOTS:
  void changedMoveGroupNS();
  void changedPlanningSceneTopic();
  void changedSceneEnabled();
  void changedSceneAlpha();
  void changedSceneColor();
  void changedSceneRobotVisualEnabled();
  void changedSceneRobotCollisionEnabled();
  void changedRobotSceneAlpha();
  void changedAttachedBodyColor();

protected:
  void onInitialize() override;
  void onEnable() override;
  void onDisable() override;
  void fixedFrameChanged() override;

  void onRobotModelLoaded() override;
  /* Called after each redraw of a changed scene (the world's objects as just drawn). */
  virtual void onSceneRendered();
  /* The namespace move_group's topics, services and actions are under ("" or "ns/"). */
  std::string moveGroupPrefix() const;
  Ogre::SceneNode* planning_scene_node_ = nullptr;  // at the planning frame, in the fixed frame

  rviz::Property* scene_category_;
  rviz::Property* robot_category_ = nullptr;
  rviz::StringProperty* move_group_ns_property_;
  rviz::RosTopicProperty* planning_scene_topic_property_ = nullptr;
  rviz::StringProperty* scene_name_property_;
  rviz::BoolProperty* scene_enabled_property_;
  rviz::FloatProperty* scene_alpha_property_;
  rviz::ColorProperty* scene_color_property_;
  rviz::EnumProperty* octree_render_property_;
  rviz::EnumProperty* octree_coloring_property_;
  rviz::FloatProperty* scene_display_time_property_;
  rviz::BoolProperty* scene_robot_visual_enabled_property_ = nullptr;
  rviz::BoolProperty* scene_robot_collision_enabled_property_ = nullptr;
  rviz::FloatProperty* robot_alpha_property_ = nullptr;
  rviz::ColorProperty* attached_body_color_property_ = nullptr;

private:
  void subscribe();
  void unsubscribe();
  void incomingPlanningScene(const moveit_msgs::PlanningScene::ConstPtr& scene);
  void applyWorldObject(const moveit_msgs::CollisionObject& object);
  void applyAttachedObject(const moveit_msgs::AttachedCollisionObject& object);
  void renderScene();
  void placePlanningFrame();
  Ogre::ColourValue objectColor(const std::string& id) const;
  bool objectPose(const std::string& frame, const LinkPoses& links, Ogre::Vector3& position,
                  Ogre::Quaternion& orientation);

  const bool listen_to_planning_scene_;
  const bool show_scene_robot_;
  bool scene_changed_ = false;
  ros::Subscriber scene_subscriber_;
  std::unique_ptr<RobotStateVisual> scene_robot_;
  std::map<std::string, moveit_msgs::CollisionObject> world_;
  std::map<std::string, moveit_msgs::AttachedCollisionObject> attached_;
  std::map<std::string, std_msgs::ColorRGBA> object_colors_;
  JointPositions scene_joints_;
  std::map<std::string, std::unique_ptr<CollisionObjectVisual>> world_visuals_;
};
}  // namespace moveit_rviz_plugin

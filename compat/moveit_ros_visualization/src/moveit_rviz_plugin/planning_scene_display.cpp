/* The PlanningScene display: properties (names and defaults of planning_scene_display.cpp
 * l. 66-155 on noetic-devel), the scene kept from full scenes and diffs as
 * planning_scene::PlanningScene::usePlanningSceneMsg / setPlanningSceneDiffMsg apply them
 * (an ADD replaces an object of the same id, REMOVE with an empty id clears the world), and
 * drawn at the planning frame's pose in the fixed frame. */
#include "planning_scene_display.h"
#include "message_checks.h"
#include "robot_frame_placement.h"

#include <OgreSceneManager.h>
#include <OgreSceneNode.h>
#include <rviz/display_context.h>
#include <rviz/frame_manager.h>
#include <rviz/properties/bool_property.h>
#include <rviz/properties/color_property.h>
#include <rviz/properties/enum_property.h>
#include <rviz/properties/float_property.h>
#include <rviz/properties/ros_topic_property.h>
#include <rviz/properties/string_property.h>

namespace moveit_rviz_plugin
{
namespace
{

Ogre::ColourValue colour(const QColor& color, float alpha)
{
  return Ogre::ColourValue(color.redF(), color.greenF(), color.blueF(), alpha);
}
}  // namespace

PlanningSceneDisplay::PlanningSceneDisplay(bool listen_to_planning_scene, bool show_scene_robot)
  : listen_to_planning_scene_(listen_to_planning_scene), show_scene_robot_(show_scene_robot)
{
  move_group_ns_property_ =
      new rviz::StringProperty("Move Group Namespace", "", "The name of the ROS namespace in which the move_group node is running",
                               this, SLOT(changedMoveGroupNS()), this);
  if (listen_to_planning_scene_)
    planning_scene_topic_property_ =
        new rviz::RosTopicProperty("Planning Scene Topic", "move_group/monitored_planning_scene",
                                   ros::message_traits::datatype<moveit_msgs::PlanningScene>(),
                                   "The topic on which the moveit_msgs::PlanningScene messages are received", this,
                                   SLOT(changedPlanningSceneTopic()), this);

  scene_category_ = new rviz::Property("Scene Geometry", QVariant(), "", this);
  scene_name_property_ = new rviz::StringProperty("Scene Name", "(noname)", "Shows the name of the planning scene",
                                                  scene_category_);
  scene_name_property_->setShouldBeSaved(false);
  scene_name_property_->setReadOnly(true);
  scene_enabled_property_ =
      new rviz::BoolProperty("Show Scene Geometry", true, "Indicates whether planning scenes should be displayed",
                             scene_category_, SLOT(changedSceneEnabled()), this);
  scene_alpha_property_ = new rviz::FloatProperty("Scene Alpha", 0.9f, "Specifies the alpha for the scene geometry",
                                                  scene_category_, SLOT(changedSceneAlpha()), this);
  scene_alpha_property_->setMin(0.0);
  scene_alpha_property_->setMax(1.0);
  scene_color_property_ = new rviz::ColorProperty("Scene Color", QColor(50, 230, 50),
                                                  "The color for the planning scene obstacles (if a color is not defined)",
                                                  scene_category_, SLOT(changedSceneColor()), this);
  // octomaps are not drawn here (move_group keeps none); the keys load as MoveIt saves them
  octree_render_property_ =
      new rviz::EnumProperty("Voxel Rendering", "Occupied Voxels", "Select voxel type.", scene_category_);
  octree_render_property_->addOption("Occupied Voxels", 1);
  octree_render_property_->addOption("Free Voxels", 2);
  octree_render_property_->addOption("All Voxels", 3);
  octree_coloring_property_ =
      new rviz::EnumProperty("Voxel Coloring", "Z-Axis", "Select voxel coloring mode", scene_category_);
  octree_coloring_property_->addOption("Z-Axis", 0);
  octree_coloring_property_->addOption("Cell Probability", 1);
  scene_display_time_property_ =
      new rviz::FloatProperty("Scene Display Time", 0.01f,
                              "The amount of wall-time to wait in between rendering updates to the planning scene (if any)",
                              scene_category_);
  scene_display_time_property_->setMin(0.0001);

  if (show_scene_robot_)
  {
    robot_category_ = new rviz::Property("Scene Robot", QVariant(), "", this);
    scene_robot_visual_enabled_property_ = new rviz::BoolProperty(
        "Show Robot Visual", true,
        "Indicates whether the robot state specified by the planning scene should be displayed as defined for "
        "visualisation purposes.",
        robot_category_, SLOT(changedSceneRobotVisualEnabled()), this);
    scene_robot_collision_enabled_property_ = new rviz::BoolProperty(
        "Show Robot Collision", false,
        "Indicates whether the robot state specified by the planning scene should be displayed as defined for "
        "collision detection purposes.",
        robot_category_, SLOT(changedSceneRobotCollisionEnabled()), this);
    robot_alpha_property_ = new rviz::FloatProperty("Robot Alpha", 1.0f, "Specifies the alpha for the robot links",
                                                    robot_category_, SLOT(changedRobotSceneAlpha()), this);
    robot_alpha_property_->setMin(0.0);
    robot_alpha_property_->setMax(1.0);
    attached_body_color_property_ =
        new rviz::ColorProperty("Attached Body Color", QColor(150, 50, 150), "The color for the attached bodies",
                                robot_category_, SLOT(changedAttachedBodyColor()), this);
  }
}

PlanningSceneDisplay::~PlanningSceneDisplay()
{
  world_visuals_.clear();
  scene_robot_.reset();
}

void PlanningSceneDisplay::onInitialize()
{
  Display::onInitialize();
  planning_scene_node_ = scene_node_->createChildSceneNode();
  if (show_scene_robot_)
  {
    scene_robot_.reset(new RobotStateVisual(planning_scene_node_, context_, "Planning Scene", robot_category_));
    scene_robot_->setVisualVisible(scene_robot_visual_enabled_property_->getBool());
    scene_robot_->setCollisionVisible(scene_robot_collision_enabled_property_->getBool());
    scene_robot_->setAttachedBodyColor(colour(attached_body_color_property_->getColor(), 1.0f));
    scene_robot_->setVisible(false);
  }
}

void PlanningSceneDisplay::onEnable()
{
  Display::onEnable();
  if (!robotModelLoaded())
    loadRobotModel();
  subscribe();
  if (scene_robot_)
    scene_robot_->setVisible(robotModelLoaded());
  scene_changed_ = true;
}

void PlanningSceneDisplay::onDisable()
{
  unsubscribe();
  if (scene_robot_)
    scene_robot_->setVisible(false);
  for (auto& visual : world_visuals_)
    visual.second->setVisible(false);
  Display::onDisable();
}

void PlanningSceneDisplay::reset()
{
  world_.clear();
  attached_.clear();
  object_colors_.clear();
  world_visuals_.clear();
  forgetRobotModel();
  Display::reset();
  if (isEnabled())
  {
    loadRobotModel();
    unsubscribe();
    subscribe();
  }
}

std::string PlanningSceneDisplay::moveGroupPrefix() const
{
  std::string ns = move_group_ns_property_->getStdString();
  if (!ns.empty() && ns.back() != '/')
    ns += '/';
  return ns;
}

void PlanningSceneDisplay::onRobotModelLoaded()
{
  if (scene_robot_)
  {
    scene_robot_->load(kinematics_);
    scene_robot_->setAlpha(robot_alpha_property_->getFloat());
    scene_robot_->setVisible(isEnabled());
  }
  scene_changed_ = true;
}

void PlanningSceneDisplay::subscribe()
{
  if (!planning_scene_topic_property_ || !isEnabled())
    return;
  const std::string topic = moveGroupPrefix() + planning_scene_topic_property_->getStdString();
  try
  {
    scene_subscriber_ = update_nh_.subscribe(topic, 2, &PlanningSceneDisplay::incomingPlanningScene, this);
    setStatusStd(rviz::StatusProperty::Ok, "Planning Scene", "listening on " + scene_subscriber_.getTopic());
  }
  catch (const ros::Exception& error)
  {
    setStatusStd(rviz::StatusProperty::Error, "Planning Scene", std::string("cannot subscribe: ") + error.what());
  }
}

void PlanningSceneDisplay::unsubscribe()
{
  scene_subscriber_.shutdown();
}

void PlanningSceneDisplay::incomingPlanningScene(const moveit_msgs::PlanningScene::ConstPtr& scene)
{
  const std::string bad_joint = nonFiniteJoint(scene->robot_state.joint_state);
  if (!bad_joint.empty())
  {
    setStatusStd(rviz::StatusProperty::Error, "Planning Scene",
                 "a scene whose joint '" + bad_joint + "' is not a finite number: scene ignored");
    return;
  }
  const bool diff = scene->is_diff;
  if (!diff)
  {
    world_.clear();
    attached_.clear();
    object_colors_.clear();
    scene_joints_.clear();
  }
  if (!scene->name.empty() || !diff)
    scene_name_property_->setStdString(scene->name.empty() ? "(noname)" : scene->name);
  const sensor_msgs::JointState& joints = scene->robot_state.joint_state;
  for (size_t i = 0; i < joints.name.size() && i < joints.position.size(); ++i)
    scene_joints_[joints.name[i]] = joints.position[i];
  if (!scene->robot_state.is_diff)
    attached_.clear();
  for (const auto& object : scene->robot_state.attached_collision_objects)
    if (nonFinitePart(object.object).empty())
      applyAttachedObject(object);
  std::string refused;
  for (const auto& object : scene->world.collision_objects)
  {
    const std::string part = nonFinitePart(object);
    if (part.empty())
      applyWorldObject(object);
    else
      refused += (refused.empty() ? "" : "; ") + object.id + " (" + part + " not finite)";
  }
  if (refused.empty())
    deleteStatusStd("Refused Objects");
  else
    setStatusStd(rviz::StatusProperty::Error, "Refused Objects", refused);
  for (const auto& color : scene->object_colors)
    object_colors_[color.id] = color.color;
  scene_changed_ = true;
}

void PlanningSceneDisplay::applyWorldObject(const moveit_msgs::CollisionObject& object)
{
  using C = moveit_msgs::CollisionObject;
  switch (object.operation)
  {
    case C::REMOVE:
      if (object.id.empty())
        world_.clear();
      else
        world_.erase(object.id);
      break;
    case C::APPEND:
    {
      auto found = world_.find(object.id);
      if (found == world_.end())
      {
        world_[object.id] = object;
        break;
      }
      C& kept = found->second;
      kept.primitives.insert(kept.primitives.end(), object.primitives.begin(), object.primitives.end());
      kept.primitive_poses.insert(kept.primitive_poses.end(), object.primitive_poses.begin(),
                                  object.primitive_poses.end());
      kept.meshes.insert(kept.meshes.end(), object.meshes.begin(), object.meshes.end());
      kept.mesh_poses.insert(kept.mesh_poses.end(), object.mesh_poses.begin(), object.mesh_poses.end());
      kept.planes.insert(kept.planes.end(), object.planes.begin(), object.planes.end());
      kept.plane_poses.insert(kept.plane_poses.end(), object.plane_poses.begin(), object.plane_poses.end());
      break;
    }
    case C::MOVE:
    {
      auto found = world_.find(object.id);
      if (found == world_.end())
        break;
      found->second.header = object.header;
      found->second.pose = object.pose;
      if (object.primitive_poses.size() == found->second.primitive_poses.size())
        found->second.primitive_poses = object.primitive_poses;
      break;
    }
    default:  // ADD: an object of the same id is replaced
      world_[object.id] = object;
  }
}

void PlanningSceneDisplay::applyAttachedObject(const moveit_msgs::AttachedCollisionObject& object)
{
  if (object.object.operation == moveit_msgs::CollisionObject::REMOVE)
  {
    if (object.object.id.empty())
      attached_.clear();
    else
      attached_.erase(object.object.id);
    return;
  }
  attached_[object.object.id] = object;
}

void PlanningSceneDisplay::update(float wall_dt, float ros_dt)
{
  Display::update(wall_dt, ros_dt);
  if (!ensureRobotModel(wall_dt))
    return;
  placePlanningFrame();
  if (scene_changed_)
  {
    scene_changed_ = false;
    renderScene();
  }
}

void PlanningSceneDisplay::placePlanningFrame()
{
  placeAtFrame(planning_scene_node_, planningFrame(), context_, this);
}

bool PlanningSceneDisplay::objectPose(const std::string& frame, const LinkPoses& links, Ogre::Vector3& position,
                                      Ogre::Quaternion& orientation)
{
  position = Ogre::Vector3::ZERO;
  orientation = Ogre::Quaternion::IDENTITY;
  if (frame.empty() || frame == planningFrame() || frame == "/" + planningFrame())
    return true;
  auto link = links.find(frame);
  if (link != links.end())
  {
    // a robot link: where the scene's state puts it (the planning frame is the root's frame)
    const KDL::Frame& pose = link->second;
    double x, y, z, w;
    pose.M.GetQuaternion(x, y, z, w);
    position = Ogre::Vector3(pose.p.x(), pose.p.y(), pose.p.z());
    orientation = Ogre::Quaternion(w, x, y, z);
    return true;
  }
  Ogre::Vector3 frame_position, planning_position = planning_scene_node_->getPosition();
  Ogre::Quaternion frame_orientation, planning_orientation = planning_scene_node_->getOrientation();
  if (!context_->getFrameManager()->getTransform(frame, ros::Time(0), frame_position, frame_orientation))
    return false;
  orientation = planning_orientation.Inverse() * frame_orientation;
  position = planning_orientation.Inverse() * (frame_position - planning_position);
  return true;
}

Ogre::ColourValue PlanningSceneDisplay::objectColor(const std::string& id) const
{
  auto found = object_colors_.find(id);
  const float alpha = scene_alpha_property_->getFloat();
  if (found != object_colors_.end())
    return Ogre::ColourValue(found->second.r, found->second.g, found->second.b, found->second.a * alpha);
  return colour(scene_color_property_->getColor(), alpha);
}

void PlanningSceneDisplay::renderScene()
{
  std::map<std::string, std::unique_ptr<CollisionObjectVisual>> drawn;
  std::string unplaced;
  const LinkPoses links = kinematics_.linkPoses(scene_joints_);
  for (const auto& entry : world_)
  {
    auto visual = std::move(world_visuals_[entry.first]);
    if (!visual)
      visual.reset(new CollisionObjectVisual(context_->getSceneManager(), planning_scene_node_));
    visual->setShapes(entry.second);
    Ogre::Vector3 position;
    Ogre::Quaternion orientation;
    if (!objectPose(entry.second.header.frame_id, links, position, orientation))
      unplaced += (unplaced.empty() ? "" : ", ") + entry.first + " (frame '" + entry.second.header.frame_id + "')";
    visual->node()->setPosition(position);
    visual->node()->setOrientation(orientation);
    visual->setColor(objectColor(entry.first));
    visual->setVisible(isEnabled() && scene_enabled_property_->getBool());
    drawn[entry.first] = std::move(visual);
  }
  world_visuals_ = std::move(drawn);
  if (unplaced.empty())
    deleteStatusStd("Scene Objects");
  else
    setStatusStd(rviz::StatusProperty::Warn, "Scene Objects", "no transform for " + unplaced);
  if (scene_robot_ && robotModelLoaded())
  {
    std::vector<moveit_msgs::AttachedCollisionObject> attached;
    for (const auto& entry : attached_)
      attached.push_back(entry.second);
    scene_robot_->update(links, attached);
  }
  onSceneRendered();
}

void PlanningSceneDisplay::onSceneRendered()
{
}

void PlanningSceneDisplay::fixedFrameChanged()
{
  Display::fixedFrameChanged();
  scene_changed_ = true;
}

void PlanningSceneDisplay::changedMoveGroupNS()
{
  if (isEnabled())
  {
    unsubscribe();
    subscribe();
  }
}


void PlanningSceneDisplay::changedPlanningSceneTopic()
{
  changedMoveGroupNS();
}

void PlanningSceneDisplay::changedSceneEnabled()
{
  scene_changed_ = true;
}

void PlanningSceneDisplay::changedSceneAlpha()
{
  scene_changed_ = true;
}

void PlanningSceneDisplay::changedSceneColor()
{
  scene_changed_ = true;
}

void PlanningSceneDisplay::changedSceneRobotVisualEnabled()
{
  if (scene_robot_)
    scene_robot_->setVisualVisible(scene_robot_visual_enabled_property_->getBool());
}

void PlanningSceneDisplay::changedSceneRobotCollisionEnabled()
{
  if (scene_robot_)
    scene_robot_->setCollisionVisible(scene_robot_collision_enabled_property_->getBool());
}

void PlanningSceneDisplay::changedRobotSceneAlpha()
{
  if (scene_robot_)
    scene_robot_->setAlpha(robot_alpha_property_->getFloat());
}

void PlanningSceneDisplay::changedAttachedBodyColor()
{
  if (scene_robot_)
    scene_robot_->setAttachedBodyColor(colour(attached_body_color_property_->getColor(), 1.0f));
}
}  // namespace moveit_rviz_plugin

// MoveIt's PlanningSceneInterface over this workspace's move_group; semantics as MoveIt's
// moveit_ros/planning_interface/planning_scene_interface/src/planning_scene_interface.cpp (noetic-devel 7c0343f0),
// cited by line where reproduced.
#include <moveit/planning_scene_interface/planning_scene_interface.h>

#include <algorithm>
#include <stdexcept>

#include <Eigen/Geometry>
#include <moveit_msgs/ApplyPlanningScene.h>
#include <moveit_msgs/GetPlanningScene.h>
#include <moveit_msgs/PlanningSceneComponents.h>
#include <ros/ros.h>

#include "wait_for_subscriber.h"

namespace moveit
{
namespace planning_interface
{
namespace
{
const char LOGNAME[] = "planning_scene_interface";
// move_group's names (move_group/capability_names.h), relative to the interface's namespace
const char GET_PLANNING_SCENE_SERVICE[] = "get_planning_scene";
const char APPLY_PLANNING_SCENE_SERVICE[] = "apply_planning_scene";
const char PLANNING_SCENE_TOPIC[] = "planning_scene";
// MoveIt warns after 5 s of waiting for a service, then waits on (planning_scene_interface.cpp l. 304-313)
const double SERVICE_WARNING_SECONDS = 5.0;

Eigen::Isometry3d toEigen(const geometry_msgs::Pose& pose)
{
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  result.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  Eigen::Quaterniond q(pose.orientation.w, pose.orientation.x, pose.orientation.y, pose.orientation.z);
  // an unset orientation (all zero) is read as the identity, as MoveIt's message checks do
  result.linear() = q.norm() > 0.0 ? q.normalized().toRotationMatrix() : Eigen::Matrix3d::Identity();
  return result;
}

bool inside(const Eigen::Vector3d& p, double minx, double miny, double minz, double maxx, double maxy, double maxz)
{
  return p.x() >= minx && p.x() <= maxx && p.y() >= miny && p.y() <= maxy && p.z() >= minz && p.z() <= maxz;
}

// Colours without an id take their object's id, up to the first that has one (l. 264-270, 397-403)
void nameColours(std::vector<moveit_msgs::ObjectColor>& colours,
                 const std::vector<moveit_msgs::CollisionObject>& objects)
{
  for (std::size_t i = 0; i < colours.size(); ++i)
  {
    if (!colours[i].id.empty() || i >= objects.size())
      break;
    colours[i].id = objects[i].id;
  }
}
}  // namespace

class PlanningSceneInterface::PlanningSceneInterfaceImpl
{
public:
  PlanningSceneInterfaceImpl(const std::string& ns, bool wait) : node_handle_(ns)
  {
    diff_publisher_ = node_handle_.advertise<moveit_msgs::PlanningScene>(PLANNING_SCENE_TOPIC, 1);
    get_scene_ = node_handle_.serviceClient<moveit_msgs::GetPlanningScene>(GET_PLANNING_SCENE_SERVICE);
    apply_scene_ = node_handle_.serviceClient<moveit_msgs::ApplyPlanningScene>(APPLY_PLANNING_SCENE_SERVICE);
    if (wait)
    {
      waitForService(get_scene_);
      waitForService(apply_scene_);
    }
    else if (!get_scene_.exists() || !apply_scene_.exists())
    {
      throw std::runtime_error("PlanningSceneInterface: move_group's services '" + get_scene_.getService() +
                               "' and '" + apply_scene_.getService() + "' are not advertised");
    }
  }

  bool getScene(uint32_t components, moveit_msgs::PlanningScene& scene, const char* purpose)
  {
    moveit_msgs::GetPlanningScene srv;
    srv.request.components.components = components;
    if (!get_scene_.call(srv))
    {
      ROS_WARN_NAMED(LOGNAME, "Could not call the service '%s' to get %s", get_scene_.getService().c_str(), purpose);
      return false;
    }
    scene = srv.response.scene;
    return true;
  }

  bool apply(const moveit_msgs::PlanningScene& scene)
  {
    moveit_msgs::ApplyPlanningScene srv;
    srv.request.scene = scene;
    if (!apply_scene_.call(srv))
    {
      ROS_WARN_NAMED(LOGNAME, "Failed to call the service '%s'", apply_scene_.getService().c_str());
      return false;
    }
    return srv.response.success;
  }

  void publishDiff(const moveit_msgs::PlanningScene& scene) const
  {
    // A message published before move_group's subscription is connected is lost; MoveIt's interface publishes at
    // once (l. 273, 287), this one first waits (bounded) for the connection
    detail::waitForSubscriber(diff_publisher_);
    diff_publisher_.publish(scene);
  }

  ros::NodeHandle node_handle_;
  ros::ServiceClient get_scene_;
  ros::ServiceClient apply_scene_;
  ros::Publisher diff_publisher_;

private:
  static void waitForService(ros::ServiceClient& client)
  {
    if (client.waitForExistence(ros::Duration(SERVICE_WARNING_SECONDS)))
      return;
    ROS_WARN_STREAM_NAMED(LOGNAME, "service '" << client.getService() << "' not advertised yet. Continue waiting...");
    client.waitForExistence();
  }
};

PlanningSceneInterface::PlanningSceneInterface(const std::string& ns, bool wait)
  : impl_(new PlanningSceneInterfaceImpl(ns, wait))
{
}

PlanningSceneInterface::~PlanningSceneInterface()
{
  delete impl_;
}

std::vector<std::string> PlanningSceneInterface::getKnownObjectNames(bool with_type)
{
  std::vector<std::string> result;
  moveit_msgs::PlanningScene scene;
  if (!impl_->getScene(moveit_msgs::PlanningSceneComponents::WORLD_OBJECT_NAMES, scene, "object names"))
    return result;
  for (const moveit_msgs::CollisionObject& object : scene.world.collision_objects)
    if (!with_type || !object.type.key.empty())
      result.push_back(object.id);
  return result;
}

std::vector<std::string> PlanningSceneInterface::getKnownObjectNamesInROI(double minx, double miny, double minz,
                                                                          double maxx, double maxy, double maxz,
                                                                          bool with_type,
                                                                          std::vector<std::string>& types)
{
  std::vector<std::string> result;
  moveit_msgs::PlanningScene scene;
  if (!impl_->getScene(moveit_msgs::PlanningSceneComponents::WORLD_OBJECT_GEOMETRY, scene, "object names"))
    return result;
  for (const moveit_msgs::CollisionObject& object : scene.world.collision_objects)
  {
    if (with_type && object.type.key.empty())
      continue;
    // an object with no posed shape is in no region (l. 116-117); each shape's pose is composed with the
    // object's pose before the test (l. 119-150)
    if (object.mesh_poses.empty() && object.primitive_poses.empty())
      continue;
    const Eigen::Isometry3d frame = toEigen(object.pose);
    bool all_inside = true;
    for (const auto* poses : { &object.mesh_poses, &object.primitive_poses })
      for (const geometry_msgs::Pose& shape_pose : *poses)
        all_inside = all_inside &&
                     inside((frame * toEigen(shape_pose)).translation(), minx, miny, minz, maxx, maxy, maxz);
    if (!all_inside)
      continue;
    result.push_back(object.id);
    if (with_type)
      types.push_back(object.type.key);
  }
  return result;
}

std::map<std::string, geometry_msgs::Pose>
PlanningSceneInterface::getObjectPoses(const std::vector<std::string>& object_ids)
{
  std::map<std::string, geometry_msgs::Pose> result;
  moveit_msgs::PlanningScene scene;
  if (!impl_->getScene(moveit_msgs::PlanningSceneComponents::WORLD_OBJECT_GEOMETRY, scene, "object poses"))
    return result;
  for (const moveit_msgs::CollisionObject& object : scene.world.collision_objects)
    if (std::find(object_ids.begin(), object_ids.end(), object.id) != object_ids.end())
      result[object.id] = object.pose;
  return result;
}

std::map<std::string, moveit_msgs::CollisionObject>
PlanningSceneInterface::getObjects(const std::vector<std::string>& object_ids)
{
  std::map<std::string, moveit_msgs::CollisionObject> result;
  moveit_msgs::PlanningScene scene;
  if (!impl_->getScene(moveit_msgs::PlanningSceneComponents::WORLD_OBJECT_GEOMETRY, scene, "object geometries"))
    return result;
  for (const moveit_msgs::CollisionObject& object : scene.world.collision_objects)
    if (object_ids.empty() || std::find(object_ids.begin(), object_ids.end(), object.id) != object_ids.end())
      result[object.id] = object;
  return result;
}

std::map<std::string, moveit_msgs::AttachedCollisionObject>
PlanningSceneInterface::getAttachedObjects(const std::vector<std::string>& object_ids)
{
  std::map<std::string, moveit_msgs::AttachedCollisionObject> result;
  moveit_msgs::PlanningScene scene;
  if (!impl_->getScene(moveit_msgs::PlanningSceneComponents::ROBOT_STATE_ATTACHED_OBJECTS, scene,
                       "attached object geometries"))
    return result;
  for (const moveit_msgs::AttachedCollisionObject& attached : scene.robot_state.attached_collision_objects)
    if (object_ids.empty() || std::find(object_ids.begin(), object_ids.end(), attached.object.id) != object_ids.end())
      result[attached.object.id] = attached;
  return result;
}

bool PlanningSceneInterface::applyCollisionObject(const moveit_msgs::CollisionObject& collision_object)
{
  return applyCollisionObjects({ collision_object });
}

bool PlanningSceneInterface::applyCollisionObject(const moveit_msgs::CollisionObject& collision_object,
                                                  const std_msgs::ColorRGBA& object_color)
{
  moveit_msgs::ObjectColor colour;
  colour.id = collision_object.id;
  colour.color = object_color;
  return applyCollisionObjects({ collision_object }, { colour });
}

bool PlanningSceneInterface::applyCollisionObjects(const std::vector<moveit_msgs::CollisionObject>& collision_objects,
                                                   const std::vector<moveit_msgs::ObjectColor>& object_colors)
{
  moveit_msgs::PlanningScene scene;
  scene.is_diff = true;
  scene.robot_state.is_diff = true;
  scene.world.collision_objects = collision_objects;
  scene.object_colors = object_colors;
  nameColours(scene.object_colors, collision_objects);
  return applyPlanningScene(scene);
}

bool PlanningSceneInterface::applyAttachedCollisionObject(
    const moveit_msgs::AttachedCollisionObject& attached_collision_object)
{
  return applyAttachedCollisionObjects({ attached_collision_object });
}

bool PlanningSceneInterface::applyAttachedCollisionObjects(
    const std::vector<moveit_msgs::AttachedCollisionObject>& attached_collision_objects)
{
  moveit_msgs::PlanningScene scene;
  scene.is_diff = true;
  scene.robot_state.is_diff = true;
  scene.robot_state.attached_collision_objects = attached_collision_objects;
  return applyPlanningScene(scene);
}

bool PlanningSceneInterface::applyPlanningScene(const moveit_msgs::PlanningScene& ps)
{
  return impl_->apply(ps);
}

moveit_msgs::PlanningScene PlanningSceneInterface::getPlanningSceneMsg(uint32_t components)
{
  moveit_msgs::PlanningScene scene;
  impl_->getScene(components, scene, "the planning scene");
  return scene;
}

void PlanningSceneInterface::addCollisionObjects(const std::vector<moveit_msgs::CollisionObject>& collision_objects,
                                                 const std::vector<moveit_msgs::ObjectColor>& object_colors) const
{
  moveit_msgs::PlanningScene scene;
  scene.is_diff = true;
  scene.world.collision_objects = collision_objects;
  scene.object_colors = object_colors;
  nameColours(scene.object_colors, collision_objects);
  impl_->publishDiff(scene);
}

void PlanningSceneInterface::removeCollisionObjects(const std::vector<std::string>& object_ids) const
{
  moveit_msgs::PlanningScene scene;
  scene.is_diff = true;
  for (const std::string& id : object_ids)
  {
    moveit_msgs::CollisionObject object;
    object.id = id;
    object.operation = moveit_msgs::CollisionObject::REMOVE;
    scene.world.collision_objects.push_back(object);
  }
  impl_->publishDiff(scene);
}

bool PlanningSceneInterface::clear()
{
  // an attached and a world object, each REMOVE without an id: every one goes (l. 290-301)
  moveit_msgs::PlanningScene scene;
  scene.is_diff = true;
  scene.robot_state.is_diff = true;
  scene.robot_state.attached_collision_objects.resize(1);
  scene.robot_state.attached_collision_objects[0].object.operation = moveit_msgs::CollisionObject::REMOVE;
  scene.world.collision_objects.resize(1);
  scene.world.collision_objects[0].operation = moveit_msgs::CollisionObject::REMOVE;
  return applyPlanningScene(scene);
}

}  // namespace planning_interface
}  // namespace moveit

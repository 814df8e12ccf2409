// MoveIt's PlanningSceneInterface (moveit_ros_planning_interface, noetic-devel 7c0343f0), written here as a client of
// this workspace's move_group (compat/moveit_ros_move_group), the way MoveIt's own is a client of its move_group:
// world and attached objects are read through the `get_planning_scene` service and changed through
// `apply_planning_scene` (synchronous) or the `planning_scene` topic (asynchronous), names relative to the namespace
// given to the constructor.
//
// Provided: every member of MoveIt's class (the list below). Not provided: nothing of the class is missing; objects are
// kept as move_group keeps them (see compat/moveit_ros_move_group).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <geometry_msgs/Pose.h>
#include <moveit/macros/class_forward.h>
#include <moveit_msgs/AttachedCollisionObject.h>
#include <moveit_msgs/CollisionObject.h>
#include <moveit_msgs/ObjectColor.h>
#include <moveit_msgs/PlanningScene.h>
#include <std_msgs/ColorRGBA.h>

namespace moveit
{
namespace planning_interface
{
MOVEIT_CLASS_FORWARD(PlanningSceneInterface);  // PlanningSceneInterfacePtr, ConstPtr, WeakPtr ...

class PlanningSceneInterface
{
public:
  /** Services and the topic under \e ns ("" is the node's namespace, as move_group serves them). With \e wait, waits
      for `get_planning_scene` and `apply_planning_scene` (warning after 5 s, then for ever); without, throws
      std::runtime_error when either is not advertised. */
  explicit PlanningSceneInterface(const std::string& ns = "", bool wait = true);
  ~PlanningSceneInterface();

  PlanningSceneInterface(const PlanningSceneInterface&) = delete;
  PlanningSceneInterface& operator=(const PlanningSceneInterface&) = delete;

  /** Ids of the world's objects; with \e with_type only those whose type key is set. */
  std::vector<std::string> getKnownObjectNames(bool with_type = false);

  /** Ids of the world's objects whose every shape's pose lies inside the box (planning frame); with \e with_type only
      those with a type key, their keys appended to \e types. */
  std::vector<std::string> getKnownObjectNamesInROI(double minx, double miny, double minz, double maxx, double maxy,
                                                    double maxz, bool with_type, std::vector<std::string>& types);
  std::vector<std::string> getKnownObjectNamesInROI(double minx, double miny, double minz, double maxx, double maxy,
                                                    double maxz, bool with_type = false)
  {
    std::vector<std::string> types;
    return getKnownObjectNamesInROI(minx, miny, minz, maxx, maxy, maxz, with_type, types);
  }

  /** The pose of each named world object found. */
  std::map<std::string, geometry_msgs::Pose> getObjectPoses(const std::vector<std::string>& object_ids);

  /** The named world objects (all of them when \e object_ids is empty). */
  std::map<std::string, moveit_msgs::CollisionObject>
  getObjects(const std::vector<std::string>& object_ids = std::vector<std::string>());

  /** The named attached objects (all of them when \e object_ids is empty). */
  std::map<std::string, moveit_msgs::AttachedCollisionObject>
  getAttachedObjects(const std::vector<std::string>& object_ids = std::vector<std::string>());

  /** Synchronous changes through `apply_planning_scene`: true once move_group has applied them. */
  bool applyCollisionObject(const moveit_msgs::CollisionObject& collision_object);
  bool applyCollisionObject(const moveit_msgs::CollisionObject& collision_object,
                            const std_msgs::ColorRGBA& object_color);
  /** A colour without an id takes the id of the object at its index (up to the first colour that has one). */
  bool applyCollisionObjects(
      const std::vector<moveit_msgs::CollisionObject>& collision_objects,
      const std::vector<moveit_msgs::ObjectColor>& object_colors = std::vector<moveit_msgs::ObjectColor>());
  bool applyAttachedCollisionObject(const moveit_msgs::AttachedCollisionObject& attached_collision_object);
  bool
  applyAttachedCollisionObjects(const std::vector<moveit_msgs::AttachedCollisionObject>& attached_collision_objects);
  bool applyPlanningScene(const moveit_msgs::PlanningScene& ps);

  /** The scene's \e components (moveit_msgs::PlanningSceneComponents bits) from `get_planning_scene`. */
  moveit_msgs::PlanningScene getPlanningSceneMsg(uint32_t components);

  /** Asynchronous: a diff on the `planning_scene` topic (the objects appear once move_group has read it). */
  void addCollisionObjects(
      const std::vector<moveit_msgs::CollisionObject>& collision_objects,
      const std::vector<moveit_msgs::ObjectColor>& object_colors = std::vector<moveit_msgs::ObjectColor>()) const;
  void removeCollisionObjects(const std::vector<std::string>& object_ids) const;

  /** Removes every world and attached object, synchronously. */
  bool clear();

private:
  class PlanningSceneInterfaceImpl;
  PlanningSceneInterfaceImpl* impl_;
};
}  // namespace planning_interface
}  // namespace moveit

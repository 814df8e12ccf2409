"""``PlanningSceneInterface``: collision objects added, attached, detached and removed
through move_group, as Noetic's (1.1.14 and later): ``synchronous=True`` (the default)
applies each change with the ``apply_planning_scene`` service and returns once move_group
has it; ``synchronous=False`` publishes on ``collision_object`` and
``attached_collision_object``. The getters ask ``get_planning_scene``. Meshes are read with
trimesh (the real one needs pyassimp)."""
from __future__ import annotations

from typing import Dict, List

import rospy
from geometry_msgs.msg import Point, Pose, PoseStamped
from moveit_msgs.msg import (AttachedCollisionObject, CollisionObject, PlanningScene,
                             PlanningSceneComponents)
from moveit_msgs.srv import ApplyPlanningScene, GetPlanningScene
from shape_msgs.msg import Mesh, MeshTriangle, Plane, SolidPrimitive

from moveit_commander.exception import MoveItCommanderException
from moveit_commander.roscpp_initializer import ensure_node

SERVICE_WARNING = 5.0     # s: waiting for move_group's scene services is said after this


def _name(ns: str, name: str) -> str:
    return rospy.names.ns_join(ns, name) if ns else name


class PlanningSceneInterface:
    def __init__(self, ns: str = "", synchronous: bool = True, service_timeout: float = 5.0):
        ensure_node()
        self._ns, self._synchronous = ns, synchronous
        self._objects = rospy.Publisher(_name(ns, "collision_object"), CollisionObject,
                                        queue_size=100)
        self._attached = rospy.Publisher(_name(ns, "attached_collision_object"),
                                         AttachedCollisionObject, queue_size=100)
        self._get = rospy.ServiceProxy(_name(ns, "get_planning_scene"), GetPlanningScene)
        self._apply = rospy.ServiceProxy(_name(ns, "apply_planning_scene"), ApplyPlanningScene)
        for proxy in (self._get, self._apply):   # as the real one: until move_group is up
            while not rospy.is_shutdown():
                try:
                    proxy.wait_for_service(SERVICE_WARNING)
                    break
                except rospy.ROSException:
                    rospy.logwarn("PlanningSceneInterface: waiting for move_group's service "
                                  "%s", proxy.resolved_name)

    # --- building objects --------------------------------------------------------------

    @staticmethod
    def __make_existing(name: str) -> CollisionObject:
        return CollisionObject(id=name)

    @staticmethod
    def _object(name: str, pose: PoseStamped) -> CollisionObject:
        if not isinstance(pose, PoseStamped):
            raise MoveItCommanderException("a pose of the object (PoseStamped) is needed")
        co = CollisionObject(id=name, operation=CollisionObject.ADD)
        co.header = pose.header
        co.pose = pose.pose
        return co

    @staticmethod
    def _primitive(co: CollisionObject, kind: int, dimensions) -> CollisionObject:
        co.primitives = [SolidPrimitive(type=kind, dimensions=[float(d) for d in dimensions])]
        identity = Pose()
        identity.orientation.w = 1.0
        co.primitive_poses = [identity]
        return co

    @staticmethod
    def make_box(name, pose, size=(1, 1, 1)) -> CollisionObject:
        return PlanningSceneInterface._primitive(PlanningSceneInterface._object(name, pose),
                                                 SolidPrimitive.BOX, size)

    @staticmethod
    def make_sphere(name, pose, radius=1) -> CollisionObject:
        return PlanningSceneInterface._primitive(PlanningSceneInterface._object(name, pose),
                                                 SolidPrimitive.SPHERE, [radius])

    @staticmethod
    def make_cylinder(name, pose, height, radius) -> CollisionObject:
        return PlanningSceneInterface._primitive(PlanningSceneInterface._object(name, pose),
                                                 SolidPrimitive.CYLINDER, [height, radius])

    @staticmethod
    def make_cone(name, pose, height, radius) -> CollisionObject:
        return PlanningSceneInterface._primitive(PlanningSceneInterface._object(name, pose),
                                                 SolidPrimitive.CONE, [height, radius])

    @staticmethod
    def make_mesh(name, pose, filename, scale=(1, 1, 1)) -> CollisionObject:
        import trimesh
        try:
            mesh = trimesh.load(filename, force="mesh")
        except Exception as error:  # pylint: disable=broad-except
            raise MoveItCommanderException(f"Unable to load mesh '{filename}': {error}") \
                from error
        co = PlanningSceneInterface._object(name, pose)
        message = Mesh()
        for vertex in mesh.vertices:
            message.vertices.append(Point(*(float(v) * s for v, s in zip(vertex, scale))))
        for face in mesh.faces:
            message.triangles.append(MeshTriangle(vertex_indices=[int(i) for i in face]))
        co.meshes = [message]
        identity = Pose()
        identity.orientation.w = 1.0
        co.mesh_poses = [identity]
        return co

    def make_plane(self, name, pose, normal=(0, 0, 1), offset=0) -> CollisionObject:
        co = self._object(name, pose)
        co.planes = [Plane(coef=[float(normal[0]), float(normal[1]), float(normal[2]),
                                 float(offset)])]
        identity = Pose()
        identity.orientation.w = 1.0
        co.plane_poses = [identity]
        return co

    # --- changes -----------------------------------------------------------------------

    def __submit(self, message, attach: bool = False) -> None:
        if self._synchronous:
            diff = PlanningScene(is_diff=True)
            diff.robot_state.is_diff = True
            if attach:
                diff.robot_state.attached_collision_objects = [message]
            else:
                diff.world.collision_objects = [message]
            if not self.apply_planning_scene(diff):
                rospy.logerr("PlanningSceneInterface: move_group did not apply the change "
                             "(its log says why)")
        elif attach:
            self._attached.publish(message)
        else:
            self._objects.publish(message)

    def add_object(self, collision_object: CollisionObject) -> None:
        self.__submit(collision_object)

    def add_box(self, name, pose, size=(1, 1, 1)) -> None:
        self.__submit(self.make_box(name, pose, size))

    def add_sphere(self, name, pose, radius=1) -> None:
        self.__submit(self.make_sphere(name, pose, radius))

    def add_cylinder(self, name, pose, height, radius) -> None:
        self.__submit(self.make_cylinder(name, pose, height, radius))

    def add_cone(self, name, pose, height, radius) -> None:
        self.__submit(self.make_cone(name, pose, height, radius))

    def add_mesh(self, name, pose, filename, size=(1, 1, 1)) -> None:
        self.__submit(self.make_mesh(name, pose, filename, size))

    def add_plane(self, name, pose, normal=(0, 0, 1), offset=0) -> None:
        self.__submit(self.make_plane(name, pose, normal, offset))

    def attach_object(self, attached_object, link=None, touch_links=None) -> None:
        if isinstance(attached_object, str):
            attached_object = self.__make_existing(attached_object)
        if isinstance(attached_object, CollisionObject):
            aco = AttachedCollisionObject(object=attached_object, link_name=link or "")
        else:
            aco = attached_object
            if link:
                aco.link_name = link
        aco.object.operation = CollisionObject.ADD
        aco.touch_links = list(touch_links) if touch_links else [aco.link_name]
        self.__submit(aco, attach=True)

    def attach_box(self, link, name, pose=None, size=(1, 1, 1), touch_links=None) -> None:
        co = self.make_box(name, pose, size) if pose is not None else self.__make_existing(name)
        self.attach_object(co, link, touch_links)

    def attach_sphere(self, link, name, pose=None, radius=1, touch_links=None) -> None:
        co = self.make_sphere(name, pose, radius) if pose is not None \
            else self.__make_existing(name)
        self.attach_object(co, link, touch_links)

    def attach_cylinder(self, link, name, pose=None, height=1, radius=1,
                        touch_links=None) -> None:
        co = self.make_cylinder(name, pose, height, radius) if pose is not None \
            else self.__make_existing(name)
        self.attach_object(co, link, touch_links)

    def attach_mesh(self, link, name, pose=None, filename="", size=(1, 1, 1),
                    touch_links=None) -> None:
        co = self.make_mesh(name, pose, filename, size) if pose is not None \
            else self.__make_existing(name)
        self.attach_object(co, link, touch_links)

    def remove_world_object(self, name=None) -> None:
        self.__submit(CollisionObject(id=name or "", operation=CollisionObject.REMOVE))

    def remove_attached_object(self, link=None, name=None) -> None:
        aco = AttachedCollisionObject(link_name=link or "")
        aco.object.id = name or ""
        aco.object.operation = CollisionObject.REMOVE
        self.__submit(aco, attach=True)

    def clear(self) -> bool:
        diff = PlanningScene(is_diff=True)
        diff.robot_state.is_diff = True
        names = self.get_attached_objects()
        diff.robot_state.attached_collision_objects = [AttachedCollisionObject(
            object=CollisionObject(id=n, operation=CollisionObject.REMOVE)) for n in names]
        diff.world.collision_objects = [CollisionObject(operation=CollisionObject.REMOVE)]
        return self.apply_planning_scene(diff)

    # --- questions ---------------------------------------------------------------------

    def get_planning_scene(self, components: int) -> PlanningScene:
        return self._get(components=PlanningSceneComponents(components=components)).scene

    def apply_planning_scene(self, planning_scene_message: PlanningScene) -> bool:
        try:
            return self._apply(scene=planning_scene_message).success
        except rospy.ServiceException as error:
            rospy.logerr("PlanningSceneInterface: apply_planning_scene failed: %s", error)
            return False

    def _world(self, components: int) -> List[CollisionObject]:
        return self.get_planning_scene(components).world.collision_objects

    def get_known_object_names(self, with_type: bool = False) -> List[str]:
        found = self._world(PlanningSceneComponents.WORLD_OBJECT_NAMES)
        return [o.id for o in found if not with_type or o.type.key]

    def get_known_object_names_in_roi(self, minx, miny, minz, maxx, maxy, maxz,
                                      with_type: bool = False) -> List[str]:
        names = []
        for obj in self._world(PlanningSceneComponents.WORLD_OBJECT_GEOMETRY):
            if with_type and not obj.type.key:
                continue
            poses = obj.primitive_poses + obj.mesh_poses + obj.plane_poses
            if not poses:
                continue
            inside = all(minx <= obj.pose.position.x + p.position.x <= maxx and
                         miny <= obj.pose.position.y + p.position.y <= maxy and
                         minz <= obj.pose.position.z + p.position.z <= maxz for p in poses)
            if inside:
                names.append(obj.id)
        return names

    def get_object_poses(self, object_ids) -> Dict[str, Pose]:
        return {o.id: o.pose for o in self._world(PlanningSceneComponents.WORLD_OBJECT_GEOMETRY)
                if o.id in object_ids}

    def get_objects(self, object_ids=None) -> Dict[str, CollisionObject]:
        return {o.id: o for o in self._world(PlanningSceneComponents.WORLD_OBJECT_GEOMETRY)
                if not object_ids or o.id in object_ids}

    def get_attached_objects(self, object_ids=None) -> Dict[str, AttachedCollisionObject]:
        scene = self.get_planning_scene(PlanningSceneComponents.ROBOT_STATE_ATTACHED_OBJECTS)
        return {a.object.id: a for a in scene.robot_state.attached_collision_objects
                if not object_ids or a.object.id in object_ids}

"""move_group's planning scene monitor: the scene kept from ``planning_scene`` (diffs and
full scenes), ``planning_scene_world``, ``collision_object`` and
``attached_collision_object``, the robot's state from ``joint_states``; the scene published
on ``~monitored_planning_scene`` when it changes (and its state twice a second). A message
that cannot be applied is logged with its reason and changes nothing."""
from __future__ import annotations

import threading

import rospy
from moveit_msgs.msg import (AttachedCollisionObject, CollisionObject, PlanningScene,
                             PlanningSceneWorld)

from moveit_core.planning_scene import PlanningScene as Scene, SceneError

STATE_PERIOD = 0.5        # s between publications of the robot's state on the scene topic


class SceneMonitor:
    def __init__(self, scene: Scene, current):
        self.scene, self.current = scene, current
        self.lock = threading.RLock()
        self.publisher = None

    def start(self) -> None:
        """Subscribes and advertises (the node's namespace, as MoveIt's)."""
        self.publisher = rospy.Publisher("~monitored_planning_scene", PlanningScene,
                                         queue_size=10, latch=True)
        rospy.Subscriber("planning_scene", PlanningScene, self._guarded(self.apply),
                         queue_size=100)
        rospy.Subscriber("planning_scene_world", PlanningSceneWorld,
                         self._guarded(self._world), queue_size=1)
        rospy.Subscriber("collision_object", CollisionObject,
                         self._guarded(self._object), queue_size=1024)
        rospy.Subscriber("attached_collision_object", AttachedCollisionObject,
                         self._guarded(self._attached), queue_size=1024)
        rospy.Timer(rospy.Duration(STATE_PERIOD), lambda _: self.publish())
        self.publish()

    def _guarded(self, callback):
        def handle(message):
            try:
                callback(message)
            except SceneError as error:
                rospy.logerr("planning scene: %s (message ignored)", error)
        return handle

    def snapshot(self) -> Scene:
        """The scene now, the robot at its current state: a copy a request may change."""
        with self.lock:
            self.scene.set_state(self.current.positions())
            return self.scene.copy()

    def apply(self, message: PlanningScene) -> None:
        with self.lock:
            self.scene.set_state(self.current.positions())
            self.scene.apply(message)
        self.publish()

    def _world(self, message: PlanningSceneWorld) -> None:
        self.apply(PlanningScene(world=message, is_diff=True))

    def _object(self, message: CollisionObject) -> None:
        with self.lock:
            self.scene.apply_collision_object(message)
        self.publish()

    def _attached(self, message: AttachedCollisionObject) -> None:
        with self.lock:
            self.scene.set_state(self.current.positions())
            self.scene.apply_attached_object(message)
        self.publish()

    def publish(self) -> None:
        if self.publisher is None:
            return
        with self.lock:
            self.scene.set_state(self.current.positions())
            message = self.scene.to_msg()
        self.publisher.publish(message)

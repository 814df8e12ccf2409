"""The planning scene on FCL: objects added, moved, appended and removed as MoveIt's
messages say; attached objects move with their link and touch their touch links; the
SRDF's disabled pairs are not checked; scene messages are all or nothing."""
import os

import numpy as np
import pytest
from geometry_msgs.msg import Pose
from moveit_msgs.msg import (AttachedCollisionObject, CollisionObject, PlanningScene as SceneMsg,
                             PlanningSceneComponents)
from shape_msgs.msg import SolidPrimitive

from moveit_core import robot_model
from moveit_core.planning_scene import PlanningScene, SceneError

DATA = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "data")
GRIPPER = "px100/ee_gripper_link"


@pytest.fixture
def scene():
    with open(os.path.join(DATA, "px100.urdf"), encoding="utf-8") as urdf, \
            open(os.path.join(DATA, "px100.srdf"), encoding="utf-8") as srdf:
        model = robot_model.load(urdf.read(), srdf.read())
    return PlanningScene(model)


def box(name, xyz, size=(0.05, 0.05, 0.05), frame="world", operation=CollisionObject.ADD):
    message = CollisionObject(id=name, operation=operation)
    message.header.frame_id = frame
    message.pose.position.x, message.pose.position.y, message.pose.position.z = xyz
    message.pose.orientation.w = 1.0
    message.primitives = [SolidPrimitive(type=SolidPrimitive.BOX, dimensions=list(size))]
    message.primitive_poses = [Pose()]          # an all-zero quaternion: the identity
    return message


def gripper_position(scene, positions=None):
    state = dict(scene.positions, **(positions or {}))
    return scene.model.link_poses(state)[GRIPPER][:3, 3]


def test_the_robot_alone_is_free_and_its_disabled_pairs_are_not_checked(scene):
    assert scene.contacts(first_only=False) == []
    scene.acm.set("px100/upper_arm_link", "px100/forearm_link", False)
    assert ("px100/upper_arm_link", "px100/forearm_link") in scene.contacts(first_only=False)


def test_the_arm_folded_onto_its_base_collides_with_itself(scene):
    folded = {"shoulder": -1.9, "elbow": 1.6, "wrist_angle": 2.1}
    assert ("px100/base_link", "px100/gripper_link") in scene.contacts(folded, first_only=False)


def test_add_move_append_remove(scene):
    scene.apply_collision_object(box("block", gripper_position(scene)))
    assert scene.in_collision(group="interbotix_arm")
    away = box("block", (0.0, 0.3, 0.1), operation=CollisionObject.MOVE)
    scene.apply_collision_object(away)
    assert not scene.in_collision()
    np.testing.assert_allclose(scene.objects["block"].pose[:3, 3], (0.0, 0.3, 0.1))
    # APPEND: a second box where the gripper is, relative to the same object
    scene.apply_collision_object(box("block", gripper_position(scene),
                                     operation=CollisionObject.APPEND))
    assert len(scene.objects["block"].body.shapes) == 2 and scene.in_collision()
    assert len(scene.to_msg().world.collision_objects[0].primitives) == 2
    scene.apply_collision_object(CollisionObject(id="block", operation=CollisionObject.REMOVE))
    assert scene.objects == {} and not scene.in_collision()
    with pytest.raises(SceneError, match="cannot remove collision object 'block'"):
        scene.apply_collision_object(CollisionObject(id="block", operation=CollisionObject.REMOVE))


def test_a_pose_in_a_link_frame(scene):
    scene.apply_collision_object(box("on_gripper", (0, 0, 0), frame=GRIPPER))
    np.testing.assert_allclose(scene.objects["on_gripper"].pose[:3, 3], gripper_position(scene),
                               atol=1e-12)
    with pytest.raises(SceneError, match="frame 'camera' is neither a link"):
        scene.apply_collision_object(box("x", (0, 0, 0), frame="camera"))


def test_an_attached_object_moves_with_its_link_and_touches_its_touch_links(scene):
    scene.apply_collision_object(box("cube", gripper_position(scene), size=(0.02, 0.02, 0.02)))
    attach = AttachedCollisionObject(link_name=GRIPPER, touch_links=[
        "px100/left_finger_link", "px100/right_finger_link", "px100/gripper_bar_link"])
    attach.object.id = "cube"
    scene.apply_attached_object(attach)
    assert "cube" not in scene.objects and scene.attached["cube"].link == GRIPPER
    assert not scene.in_collision()            # held by its touch links
    raised = {"shoulder": -0.6}
    scene.apply_collision_object(box("wall", gripper_position(scene, raised), size=(0.02, 0.3, 0.3)))
    # the cube alone would reach the wall: only the cube and the gripper's end are there
    assert ("cube", "wall") in scene.contacts(raised, "interbotix_arm", first_only=False)
    scene.set_state(raised)
    scene.apply_attached_object(AttachedCollisionObject(
        link_name=GRIPPER, object=CollisionObject(id="cube", operation=CollisionObject.REMOVE)))
    np.testing.assert_allclose(scene.objects["cube"].pose[:3, 3],
                               gripper_position(scene, raised), atol=1e-12)
    with pytest.raises(SceneError, match="cannot attach 'ghost': no shapes given"):
        scene.apply_attached_object(AttachedCollisionObject(
            link_name=GRIPPER, object=CollisionObject(id="ghost")))


def test_a_scene_message_is_all_or_nothing(scene):
    diff = SceneMsg(is_diff=True)
    diff.world.collision_objects = [box("a", (0.0, 0.3, 0.1)), box("b", (0, 0, 0), size=(0, 1, 1))]
    with pytest.raises(SceneError, match="dimensions \\[0.0, 1.0, 1.0\\]"):
        scene.apply(diff)
    assert scene.objects == {}
    diff.world.collision_objects = [box("a", (0.0, 0.3, 0.1))]
    scene.apply(diff)
    names = scene.to_msg(PlanningSceneComponents.WORLD_OBJECT_NAMES).world.collision_objects
    assert [o.id for o in names] == ["a"] and names[0].primitives == []
    scene.apply(SceneMsg(is_diff=False))          # a full scene without objects
    assert scene.objects == {}


def test_a_diff_removing_everything_removes_attached_objects_too(scene):
    """PlanningSceneInterface::clear()'s diff (planning_scene_interface.cpp:290-301): an
    attached REMOVE and a world REMOVE, both without an id. The robot state's attached
    objects are applied first (planning_scene.cpp:1286-1310), so the detached one, back in
    the world, goes with the world's REMOVE."""
    scene.apply_collision_object(box("cube", gripper_position(scene), size=(0.02, 0.02, 0.02)))
    scene.apply_collision_object(box("wall", (0.0, 0.3, 0.1)))
    attach = AttachedCollisionObject(link_name=GRIPPER)
    attach.object.id = "cube"
    scene.apply_attached_object(attach)
    clear = SceneMsg(is_diff=True)
    clear.robot_state.is_diff = True
    clear.robot_state.attached_collision_objects = [AttachedCollisionObject(
        object=CollisionObject(operation=CollisionObject.REMOVE))]
    clear.world.collision_objects = [CollisionObject(operation=CollisionObject.REMOVE)]
    scene.apply(clear)
    assert scene.objects == {} and scene.attached == {}

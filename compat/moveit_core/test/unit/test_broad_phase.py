"""The collision checks' fast paths give FCL's answers: the links' poses for many states at
once equal link_poses state by state, and the broad phase (bounding spheres and boxes) leaves
out no pair that FCL finds touching, for every kind of shape a scene holds (boxes turned and
not, spheres, cylinders, cones, meshes, planes, an attached object), in random states of the
px100 where some pairs touch and most do not."""
import os

import numpy as np
import pytest
from geometry_msgs.msg import Point, Pose
from moveit_msgs.msg import AttachedCollisionObject, CollisionObject
from shape_msgs.msg import Mesh, MeshTriangle, Plane, SolidPrimitive
from tf.transformations import quaternion_from_euler

from moveit_core import robot_model
from moveit_core.planning_scene import PlanningScene

DATA = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "data")
ARM = ["waist", "shoulder", "elbow", "wrist_angle", "left_finger"]
STATES = 400


@pytest.fixture(scope="module")
def model():
    with open(os.path.join(DATA, "px100.urdf"), encoding="utf-8") as urdf, \
            open(os.path.join(DATA, "px100.srdf"), encoding="utf-8") as srdf:
        return robot_model.load(urdf.read(), srdf.read())


def placed(name, xyz, rpy=(0.0, 0.0, 0.0)):
    message = CollisionObject(id=name, operation=CollisionObject.ADD)
    message.header.frame_id = "world"
    message.pose.position.x, message.pose.position.y, message.pose.position.z = xyz
    (message.pose.orientation.x, message.pose.orientation.y, message.pose.orientation.z,
     message.pose.orientation.w) = quaternion_from_euler(*rpy)
    return message


def solid(name, xyz, kind, dimensions, rpy=(0.0, 0.0, 0.0)):
    message = placed(name, xyz, rpy)
    message.primitives = [SolidPrimitive(type=kind, dimensions=list(dimensions))]
    message.primitive_poses = [Pose()]
    return message


def tetrahedron(name, xyz):
    message = placed(name, xyz)
    corners = [(0.0, 0.0, 0.0), (0.08, 0.0, 0.0), (0.0, 0.08, 0.0), (0.0, 0.0, 0.08)]
    message.meshes = [Mesh(vertices=[Point(*c) for c in corners],
                           triangles=[MeshTriangle(vertex_indices=t) for t in
                                      ((0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3))])]
    message.mesh_poses = [Pose()]
    message.mesh_poses[0].orientation.w = 1.0
    return message


@pytest.fixture(scope="module")
def scene(model):
    scene = PlanningScene(model)
    box, sphere, cylinder, cone = (SolidPrimitive.BOX, SolidPrimitive.SPHERE,
                                   SolidPrimitive.CYLINDER, SolidPrimitive.CONE)
    for message in (solid("table", (0.2, 0.0, -0.03), box, (0.8, 1.0, 0.05)),
                    solid("turned", (0.2, -0.12, 0.12), box, (0.05, 0.12, 0.04),
                          (0.3, -0.5, 0.9)),
                    solid("ball", (0.18, 0.1, 0.2), sphere, (0.04,)),
                    solid("post", (0.05, 0.2, 0.1), cylinder, (0.2, 0.02), (0.4, 0.0, 0.0)),
                    solid("cone", (0.25, 0.0, 0.25), cone, (0.08, 0.03)),
                    tetrahedron("tetra", (0.15, -0.05, 0.05))):
        scene.apply_collision_object(message)
    ceiling = placed("ceiling", (0.0, 0.0, 0.0))
    ceiling.planes = [Plane(coef=[0.0, 0.0, -1.0, 0.32])]      # the half space above 0.32 m
    ceiling.plane_poses = [Pose()]
    ceiling.plane_poses[0].orientation.w = 1.0
    scene.apply_collision_object(ceiling)
    held = AttachedCollisionObject(link_name="px100/ee_gripper_link")
    held.object = solid("held", (0.0, 0.0, 0.0), box, (0.03, 0.03, 0.03))
    held.object.header.frame_id = "px100/ee_gripper_link"
    held.touch_links = ["px100/left_finger_link", "px100/right_finger_link",
                        "px100/gripper_link", "px100/gripper_bar_link"]
    scene.apply_attached_object(held)
    return scene


@pytest.fixture(scope="module")
def states(model):
    rng = np.random.default_rng(3)
    lows = np.array([model.bounds[j].lower for j in ARM])
    highs = np.array([model.bounds[j].upper for j in ARM])
    return rng.uniform(lows, highs, size=(STATES, len(ARM)))


def every_pair_touching(scene, positions):
    """FCL on every pair the scene checks, no broad phase: their indices."""
    state = dict(scene.positions, **positions)
    poses = scene.model.link_poses(state)
    checks = scene._pairs_to_check(None)     # pylint: disable=protected-access
    world = scene._world_poses(checks, {k: v[None] for k, v in poses.items()}, 1)
    for index, body in enumerate(checks.bodies):
        body.place(world[index, 0])
    return {i for i, (a, b) in enumerate(checks.pairs) if a.touches(b)}


def near_pairs(scene, states):
    checks = scene._pairs_to_check(None)     # pylint: disable=protected-access
    poses = scene.model.link_poses_many(scene.positions, ARM, states)
    return checks.near(scene._world_poses(checks, poses, len(states)))  # pylint: disable=protected-access


def test_link_poses_for_many_states_equal_link_poses_one_by_one(model, states):
    many = model.link_poses_many({"right_finger": 0.03}, ARM, states)
    for k in range(0, STATES, 37):
        one = model.link_poses(dict(zip(ARM, states[k]), right_finger=0.03))
        for link, pose in one.items():
            np.testing.assert_allclose(many[link][k], pose, atol=1e-12, err_msg=link)


def test_the_broad_phase_leaves_out_no_contact(scene, states):
    near = near_pairs(scene, states)
    touching = 0
    for k, values in enumerate(states):
        found = every_pair_touching(scene, dict(zip(ARM, values)))
        assert found <= set(np.flatnonzero(near[:, k])), (k, found)
        touching += bool(found)
    # both answers occur, so the comparison says something
    assert 0.1 * STATES < touching < 0.9 * STATES, touching


def test_the_broad_phase_sends_few_pairs_to_fcl(scene, states):
    assert near_pairs(scene, states).mean() < 0.2


def test_first_collision_is_the_first_colliding_state_in_the_order_given(scene, states):
    order = list(range(STATES))[::-1]
    expected = next((k for k in order if scene.contacts(dict(zip(ARM, states[k])))), None)
    assert expected is not None
    assert scene.first_collision({}, ARM, states, None, order) == expected
    free = [k for k in range(STATES) if not scene.contacts(dict(zip(ARM, states[k])))]
    assert scene.first_collision({}, ARM, states[free], None, range(len(free))) is None

"""Each Interbotix arm described here with its MoveIt semantics, as xsarm_moveit.launch loads
them (the URDF and the SRDF from their xacro files with the robot's name): the groups'
joints, the named states within the joints' bounds and free of collisions, and no link pair
of this workspace's geometry in contact at every random state (a pair the SRDF would have
to disable, as a Setup-Assistant run does for this geometry)."""
import os

import numpy as np
import pytest
import rospkg

from moveit_core import robot_model
from moveit_core.planning_scene import PlanningScene
from urdf_tools.xacro_loader import expand

ARMS = {"px100": ["waist", "shoulder", "elbow", "wrist_angle"],
        "px150": ["waist", "shoulder", "elbow", "wrist_angle", "wrist_rotate"],
        "rx150": ["waist", "shoulder", "elbow", "wrist_angle", "wrist_rotate"],
        "rx200": ["waist", "shoulder", "elbow", "wrist_angle", "wrist_rotate"],
        "wx200": ["waist", "shoulder", "elbow", "wrist_angle", "wrist_rotate"],
        "wx250": ["waist", "shoulder", "elbow", "wrist_angle", "wrist_rotate"],
        "wx250s": ["waist", "shoulder", "elbow", "forearm_roll", "wrist_angle", "wrist_rotate"],
        "vx250": ["waist", "shoulder", "elbow", "wrist_angle", "wrist_rotate"],
        "vx300": ["waist", "shoulder", "elbow", "wrist_angle", "wrist_rotate"],
        "vx300s": ["waist", "shoulder", "elbow", "forearm_roll", "wrist_angle", "wrist_rotate"]}
STATES = ("Home", "Upright", "Sleep")
RANDOM_STATES = 400


def loaded(model_name):
    packages = rospkg.RosPack()
    urdf = expand(os.path.join(packages.get_path("interbotix_xsarm_descriptions"), "urdf",
                               f"{model_name}.urdf.xacro"), {"robot_name": model_name})
    srdf = expand(os.path.join(packages.get_path("interbotix_xsarm_moveit"), "config", "srdf",
                               f"{model_name}.srdf.xacro"), {"robot_name": model_name})
    return robot_model.load(urdf, srdf, {})


@pytest.fixture(scope="module", params=sorted(ARMS))
def arm(request):
    return request.param, loaded(request.param)


def test_the_arm_group_moves_the_arms_joints(arm):
    name, model = arm
    assert [j for j in model.group("interbotix_arm").variables] == ARMS[name]
    assert model.group("interbotix_gripper").variables == ["left_finger"]


def test_named_states_are_within_bounds_and_free(arm):
    name, model = arm
    scene = PlanningScene(model)
    for state in STATES:
        positions = dict(model.default_positions(), **model.named_state("interbotix_arm", state))
        assert model.within_bounds(positions) == [], (name, state)   # the joints outside
        assert scene.contacts(positions, None) == [], (name, state)


def test_no_pair_touches_in_every_state(arm):
    name, model = arm
    scene = PlanningScene(model)
    rng = np.random.default_rng(3)
    joints = ARMS[name]
    always = None
    for _ in range(RANDOM_STATES):
        positions = dict(model.default_positions(), **{
            j: rng.uniform(model.bounds[j].lower, model.bounds[j].upper) for j in joints})
        pairs = {tuple(sorted(map(str, c[:2]))) for c in scene.contacts(positions, None)}
        always = pairs if always is None else always & pairs
    assert not always, f"{name}: these links touch in all {RANDOM_STATES} states: {always}"

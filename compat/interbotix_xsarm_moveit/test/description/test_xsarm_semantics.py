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

STATES = ("Home", "Upright", "Sleep")
RANDOM_STATES = 400


def described_models():
    """Every arm interbotix_xsarm_descriptions describes (a config/<model>.yaml each)."""
    folder = os.path.join(rospkg.RosPack().get_path("interbotix_xsarm_descriptions"), "config")
    return sorted(name[:-len(".yaml")] for name in os.listdir(folder) if name.endswith(".yaml"))


def loaded(model_name):
    packages = rospkg.RosPack()
    urdf = expand(os.path.join(packages.get_path("interbotix_xsarm_descriptions"), "urdf",
                               f"{model_name}.urdf.xacro"), {"robot_name": model_name})
    srdf = expand(os.path.join(packages.get_path("interbotix_xsarm_moveit"), "config", "srdf",
                               f"{model_name}.srdf.xacro"), {"robot_name": model_name})
    return robot_model.load(urdf, srdf, {})


@pytest.fixture(scope="module", params=described_models())
def arm(request):
    return request.param, loaded(request.param)


def arm_joints(name, model):
    """The URDF's moving joints from the base to the gripper point, in order."""
    return [j for j in model.urdf.chain(f"{name}/base_link", f"{name}/ee_gripper_link")
            if j.movable]


def test_the_arm_group_moves_the_arms_joints(arm):
    name, model = arm
    assert model.group("interbotix_arm").variables == [j.name for j in arm_joints(name, model)]
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
    joints = [j.name for j in arm_joints(name, model)]
    always = None
    for _ in range(RANDOM_STATES):
        positions = dict(model.default_positions(), **{
            j: rng.uniform(model.bounds[j].lower, model.bounds[j].upper) for j in joints})
        pairs = {tuple(sorted(map(str, c[:2]))) for c in scene.contacts(positions, None)}
        always = pairs if always is None else always & pairs
    assert not always, f"{name}: these links touch in all {RANDOM_STATES} states: {always}"

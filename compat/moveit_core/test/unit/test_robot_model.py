"""The SRDF's groups resolved as MoveIt's JointModelGroup resolves them, bounds from
robot_description_planning, named states, and forward kinematics of every link checked
against urdf_tools' chain transforms."""
import math
import os

import numpy as np
import pytest

from moveit_core import robot_model
from moveit_core.robot_model import RobotModelError
from urdf_tools.kinematics import link_transform

DATA = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "data")


def read(name):
    with open(os.path.join(DATA, name), encoding="utf-8") as stream:
        return stream.read()


@pytest.fixture(scope="module")
def px100():
    limits = {"waist": {"has_velocity_limits": True, "max_velocity": 2.35,
                        "has_acceleration_limits": True, "max_acceleration": 5}}
    return robot_model.load(read("px100.urdf"), read("px100.srdf"), limits)


@pytest.fixture(scope="module")
def six():
    return robot_model.load(read("six_axis_arm.urdf"), read("six_axis_arm.srdf"))


def test_a_group_of_listed_joints_is_a_chain_to_its_last_link(px100):
    arm = px100.group("interbotix_arm")
    assert arm.variables == ["waist", "shoulder", "elbow", "wrist_angle"]
    assert arm.is_chain and arm.base_link == "px100/base_link"
    assert arm.tip_link == "px100/ee_gripper_link"
    assert arm.end_effector_links == ["px100/ee_gripper_link"]
    assert px100.model_frame == "world"        # no virtual joint: the URDF's root


def test_a_group_of_links_holds_their_parent_joints_and_is_no_chain(px100):
    gripper = px100.group("interbotix_gripper")
    assert gripper.variables == ["left_finger", "right_finger"]
    assert not gripper.is_chain


def test_chain_subgroups_and_virtual_joint(six):
    manipulator = six.group("manipulator")
    assert manipulator.variables == ["shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                                     "wrist_1_joint", "wrist_2_joint", "wrist_3_joint"]
    assert manipulator.tip_link == "tool0" and manipulator.is_chain
    assert six.group("arm_by_parts").variables == manipulator.variables
    assert six.group("arm_by_parts").subgroups == ["wrist"]
    assert six.model_frame == "world"


def test_bounds_from_the_urdf_and_robot_description_planning(px100):
    waist, shoulder = px100.bounds["waist"], px100.bounds["shoulder"]
    assert (waist.max_velocity, waist.max_acceleration) == (2.35, 5.0)
    assert shoulder.max_velocity == pytest.approx(math.pi) and shoulder.max_acceleration is None
    assert shoulder.lower == pytest.approx(math.radians(-111))
    assert px100.within_bounds({"shoulder": 2.0}) == [
        "shoulder = 2.0000 (bounds -1.9373 to 1.8675)"]
    # fingers' bounds do not hold 0: their default is the middle
    assert px100.default_positions()["left_finger"] == pytest.approx(0.026)


def test_named_states(px100):
    assert px100.named_state("interbotix_arm", "Sleep") == {
        "elbow": 1.5, "shoulder": -1.88, "waist": 0.0, "wrist_angle": 0.8}
    with pytest.raises(RobotModelError, match="has no state 'Rest' \\(it has: Home, Sleep\\)"):
        px100.named_state("interbotix_arm", "Rest")
    with pytest.raises(RobotModelError, match="no group 'arm' \\(the SRDF has: "):
        px100.group("arm")


def test_every_links_pose_is_the_chain_of_its_joints(six):
    rng = np.random.default_rng(3)
    for _ in range(20):
        positions = dict(zip(six.variables, rng.uniform(-2.5, 2.5, len(six.variables))))
        poses = six.link_poses(positions)
        for link in ("tool0", "wrist_2_link", "forearm_link"):
            expected = link_transform(six.urdf, "world", link, positions)
            np.testing.assert_allclose(poses[link], expected, atol=1e-12)


def test_a_mimic_joint_follows_its_leader():
    text = read("px100.urdf").replace(
        '<joint name="right_finger" type="prismatic">',
        '<joint name="right_finger" type="prismatic"><mimic joint="left_finger" multiplier="-1"/>')
    model = robot_model.load(text, read("px100.srdf"))
    assert "right_finger" not in model.variables
    assert model.group("interbotix_gripper").variables == ["left_finger"]
    assert model.complete({"left_finger": 0.03})["right_finger"] == pytest.approx(-0.03)


def test_a_group_that_contains_itself_is_refused():
    text = read("six_axis_arm.srdf").replace('<group name="wrist">',
                                             '<group name="wrist"><group name="arm_by_parts"/>')
    with pytest.raises(RobotModelError, match="contains itself"):
        robot_model.load(read("six_axis_arm.urdf"), text)

"""Interbotix's Modern Robotics numbers for the px100 (mr_descriptions) describe the arm this
workspace's interbotix_xsarm_descriptions gives, so that the poses InterbotixManipulatorXS
solves for are where the described (and simulated) gripper goes: forward kinematics by the
product of exponentials against the URDF's own chain, base_link to ee_gripper_link, at
zero and at random joint values within the limits."""
import os

import modern_robotics as mr
import numpy as np
import pytest
import rospkg

from interbotix_xs_modules import mr_descriptions
from interbotix_xs_modules.arm import robot_description
from urdf_tools.kinematics import link_transform
from urdf_tools.xacro_loader import load

ARM = ["waist", "shoulder", "elbow", "wrist_angle"]


@pytest.fixture(scope="module")
def px100():
    path = os.path.join(rospkg.RosPack().get_path("interbotix_xsarm_descriptions"), "urdf",
                        "px100.urdf.xacro")
    return load(path, {"robot_name": "px100"})


def test_m_is_the_grippers_pose_with_every_joint_at_zero(px100):
    home = link_transform(px100, "px100/base_link", "px100/ee_gripper_link", {})
    assert np.allclose(mr_descriptions.px100.M, home, atol=1e-9)


def test_the_product_of_exponentials_is_the_urdfs_chain(px100):
    rng = np.random.default_rng(7)
    for _ in range(200):
        values = [rng.uniform(px100.joints[n].limit.lower, px100.joints[n].limit.upper)
                  for n in ARM]
        expected = link_transform(px100, "px100/base_link", "px100/ee_gripper_link",
                                  dict(zip(ARM, values)))
        got = mr.FKinSpace(mr_descriptions.px100.M, mr_descriptions.px100.Slist, values)
        assert np.allclose(got, expected, atol=1e-9), values


def test_an_arm_without_a_description_is_named():
    with pytest.raises(ValueError, match="no kinematics for robot_model 'wx200' \\(it has: px100\\)"):
        robot_description("wx200")

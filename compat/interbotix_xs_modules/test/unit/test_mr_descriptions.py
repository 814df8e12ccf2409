"""Interbotix's Modern Robotics numbers for the X-series arms (mr_descriptions) describe the
arms this workspace's interbotix_xsarm_descriptions gives, so that the poses InterbotixManipulatorXS
solves for are where the described (and simulated) gripper goes: forward kinematics by the
product of exponentials against the URDF's own chain, base_link to ee_gripper_link, at
zero and at random joint values within the limits."""
import os

import modern_robotics as mr
import numpy as np
import pytest
import rospkg

from interbotix_xs_modules.arm import robot_description
from urdf_tools.kinematics import link_transform
from urdf_tools.xacro_loader import load

def described_models():
    """Every arm interbotix_xsarm_descriptions describes (a config/<model>.yaml each)."""
    folder = os.path.join(rospkg.RosPack().get_path("interbotix_xsarm_descriptions"), "config")
    return sorted(name[:-len(".yaml")] for name in os.listdir(folder) if name.endswith(".yaml"))


def described(model):
    path = os.path.join(rospkg.RosPack().get_path("interbotix_xsarm_descriptions"), "urdf",
                        f"{model}.urdf.xacro")
    return load(path, {"robot_name": model})


@pytest.mark.parametrize("model", described_models())
def test_m_is_the_grippers_pose_with_every_joint_at_zero(model):
    home = link_transform(described(model), f"{model}/base_link", f"{model}/ee_gripper_link", {})
    assert np.allclose(robot_description(model).M, home, atol=1e-9)


@pytest.mark.parametrize("model", described_models())
def test_the_product_of_exponentials_is_the_urdfs_chain(model):
    urdf, kinematics = described(model), robot_description(model)
    joints = [j.name for j in urdf.chain(f"{model}/base_link", f"{model}/ee_gripper_link")
              if j.movable]
    assert len(joints) == kinematics.Slist.shape[1]
    rng = np.random.default_rng(7)
    for _ in range(200):
        values = [rng.uniform(urdf.joints[n].limit.lower, urdf.joints[n].limit.upper)
                  for n in joints]
        expected = link_transform(urdf, f"{model}/base_link", f"{model}/ee_gripper_link",
                                  dict(zip(joints, values)))
        got = mr.FKinSpace(kinematics.M, kinematics.Slist, values)
        assert np.allclose(got, expected, atol=1e-9), values


def test_an_arm_without_a_description_is_named():
    with pytest.raises(ValueError, match="no kinematics for robot_model 'wx300' \\(it has: "
                                         "px100, px150, rx150, rx200, vx250, vx300, vx300s, "
                                         "wx200, wx250, wx250s\\)"):
        robot_description("wx300")

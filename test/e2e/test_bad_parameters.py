"""Nodes started by hand with bad private parameters stop at once with a message naming
the parameter, as ``rosrun`` users meet them."""
import subprocess

import pytest


def rosrun(env, *arguments):
    return subprocess.run(["rosrun", *arguments], env=env, capture_output=True, text=True,
                          timeout=60, check=False)


@pytest.mark.parametrize("parameter, value, says", [
    ("speed", "-1.0", "'speed' must be a positive number"),
    ("leg_time", "fast", "'leg_time' must be a positive number"),
])
def test_flip_names_a_bad_setting(master, parameter, value, says):
    result = rosrun(master, "diff_drive", "flip", f"_{parameter}:={value}")
    assert result.returncode == 2, result.stdout + result.stderr
    assert says in result.stdout + result.stderr


def test_mover_names_a_bad_waypoint(master):
    result = rosrun(master, "arm_move", "mover", "_waypoints:=[[0.1, 0.2]]")
    assert result.returncode == 1, result.stdout + result.stderr
    assert "~waypoints[0] must be [x, y, z, gripper_open]" in result.stdout + result.stderr

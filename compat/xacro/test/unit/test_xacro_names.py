"""xacro's names: `rosrun xacro xacro`, `$(find xacro)/xacro` and the older
`$(find xacro)/xacro.py` expand a file the same way, `$(find pkg)` included."""
import subprocess

import pytest

ROBOT = """<?xml version="1.0"?>
<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:property name="side" value="0.25"/>
  <link name="base"><visual><geometry><box size="${side} ${side} ${side/2}"/></geometry>
  </visual></link>
  <xacro:property name="here" value="$(find xacro)"/>
</robot>"""


def package_path():
    return subprocess.run(["rospack", "find", "xacro"], capture_output=True, text=True,
                          check=True).stdout.strip()


@pytest.mark.parametrize("command", [["rosrun", "xacro", "xacro"], ["{pkg}/xacro"],
                                     ["{pkg}/xacro.py"], ["{pkg}/xacro", "--inorder"]])
def test_each_name_expands_the_file(command, tmp_path):
    robot = tmp_path / "robot.urdf.xacro"
    robot.write_text(ROBOT)
    command = [part.format(pkg=package_path()) for part in command]
    result = subprocess.run(command + [str(robot)], capture_output=True, text=True,
                            timeout=60, check=False)
    assert result.returncode == 0, result.stderr
    assert '<box size="0.25 0.25 0.125"/>' in result.stdout


def test_a_missing_file_is_named(tmp_path):
    missing = str(tmp_path / "nothere.xacro")
    result = subprocess.run([f"{package_path()}/xacro", missing], capture_output=True,
                            text=True, timeout=60, check=False)
    assert result.returncode != 0 and "nothere.xacro" in result.stderr


CHECK_LIGHT_ROSLAUNCH = """
import importlib.machinery, sys
command = importlib.machinery.SourceFileLoader("xacro_command", sys.argv[1]).load_module()
command._light_roslaunch()
from roslaunch import substitution_args
print("light", "roslaunch.launch" not in sys.modules, substitution_args.__name__)
import roslaunch
print("whole", callable(roslaunch.main), "roslaunch.launch" in sys.modules)
"""


def test_xacro_loads_only_roslaunchs_substitution_args_and_the_rest_on_demand():
    """The command skips roslaunch's __init__ (170 ms of every launch's robot_description)
    until something asks for more than substitution_args; then roslaunch is whole."""
    result = subprocess.run(["python3", "-c", CHECK_LIGHT_ROSLAUNCH,
                             f"{package_path()}/xacro"],
                            capture_output=True, text=True, timeout=60, check=False)
    assert result.returncode == 0, result.stderr
    assert result.stdout.split("\n")[:2] == ["light True roslaunch.substitution_args",
                                              "whole True True"]

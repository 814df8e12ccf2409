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

"""xacro's names: `rosrun xacro xacro`, `$(find xacro)/xacro` and the older
`$(find xacro)/xacro.py` expand a file the same way, `$(find pkg)` included."""
import math
import os
import re
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


# Noetic's xacro language (1.14), which PyPI's 1.13 lacked: the xacro. namespace with
# load_yaml, yaml angle tags, python. and math. names, $(find) inside a yaml path
NOETIC = """<?xml version="1.0"?>
<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:property name="cfg" value="${xacro.load_yaml('$(find xacro)/../../test_results/KEY')}"/>
  <xacro:property name="joints" value="${python.len(cfg['joints'])}"/>
  <link name="base"/>
  <xacro:macro name="j" params="n limit:=${cfg['limit']}">
    <joint name="j${n}" type="revolute"><parent link="base"/><child link="l${n}"/>
      <limit lower="${-limit}" upper="${limit}" effort="1" velocity="${math.pi}"/></joint>
    <link name="l${n}"/>
  </xacro:macro>
  <xacro:j n="1"/>
  <xacro:if value="${joints == 2}"><xacro:j n="2" limit="${cfg['joints'][1]}"/></xacro:if>
</robot>"""
YAML = "limit: !degrees 90\njoints: [!radians 1.0, !degrees 45]\n"


def test_noetics_xacro_language_expands_with_find_resolved_by_rospkg(tmp_path):
    # the yaml lives where $(find xacro)/../.. reaches: a path that only rospkg's answer
    # (the package's folder in this workspace) makes right
    folder = os.path.join(os.path.dirname(os.path.dirname(package_path())), "test_results")
    os.makedirs(folder, exist_ok=True)
    key = f"noetic_{os.getpid()}.yaml"
    with open(os.path.join(folder, key), "w") as stream:
        stream.write(YAML)
    robot = tmp_path / "arm.urdf.xacro"
    robot.write_text(NOETIC.replace("KEY", key))
    result = subprocess.run([f"{package_path()}/xacro", str(robot)], capture_output=True,
                            text=True, timeout=60, check=False)
    os.remove(os.path.join(folder, key))
    assert result.returncode == 0, result.stderr
    limits = [dict(re.findall(r'(\w+)="([^"]+)"', attributes))
              for attributes in re.findall(r"<limit ([^>]*)/>", result.stdout)]
    assert [(float(limit["lower"]), float(limit["upper"]), float(limit["velocity"]))
            for limit in limits] == [
        pytest.approx((-math.pi / 2, math.pi / 2, math.pi)),
        pytest.approx((-math.pi / 4, math.pi / 4, math.pi))]


def test_a_package_that_is_not_there_is_named(tmp_path):
    robot = tmp_path / "robot.urdf.xacro"
    robot.write_text('<robot name="r"><link name="base"><visual><geometry>'
                     '<mesh filename="$(find no_such_package)/base.stl"/></geometry></visual>'
                     '</link></robot>')
    result = subprocess.run([f"{package_path()}/xacro", str(robot)], capture_output=True,
                            text=True, timeout=60, check=False)
    assert result.returncode != 0
    assert "no package 'no_such_package' on ROS_PACKAGE_PATH" in result.stderr


def test_a_missing_relative_file_is_named_as_typed_without_a_traceback(tmp_path):
    result = subprocess.run([f"{package_path()}/xacro", "robots/nothere.urdf"], cwd=tmp_path,
                            capture_output=True, text=True, timeout=60, check=False)
    assert result.returncode != 0
    assert "No such file or directory: robots/nothere.urdf" in result.stderr
    assert "Traceback" not in result.stderr

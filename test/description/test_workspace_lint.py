"""Checks every package, launch file and URDF in the workspace with ROS's own tools."""
import glob
import os
import subprocess

import pytest
import roslaunch.config
import roslaunch.depends
import roslaunch.rlutil

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# not the workspace's own files: build and test output, and test/fixtures (files written as a
# student writes them, built in a workspace of their own by the e2e tests)
SKIP = (os.sep + ".ws" + os.sep, os.sep + ".venv" + os.sep, os.sep + "test_results" + os.sep,
        os.sep + os.path.join("test", "fixtures") + os.sep)


def workspace_files(pattern):
    found = glob.glob(os.path.join(REPO, "**", pattern), recursive=True)
    return sorted(os.path.relpath(p, REPO) for p in found if not any(s in p for s in SKIP))


PACKAGES = [os.path.dirname(p) for p in workspace_files("package.xml")]
# roslaunch-check reads a launch file's package: tools/bench/bench.launch and the e2e tests'
# data (test/e2e/data) are in none (make bench and the e2e tests run them)
LAUNCH_FILES = [p for p in workspace_files("*.launch") + workspace_files("*.test")
                if ("/test/" not in p or p.endswith(".test"))
                and not p.startswith(("tools/", "test/"))]
URDF_FILES = workspace_files("*.urdf")


def _refuses(path):
    """A xacro that stops with xacro.fatal by design (Interbotix's models other than the
    px100 name the one provided: see test_other_interbotix_models_are_refused_by_name)."""
    with open(os.path.join(REPO, path), encoding="utf-8") as stream:
        return "xacro.fatal(" in stream.read()


# robot xacros (macro files live under inc/ and are not robots by themselves; an SRDF is
# semantics, not a robot)
XACRO_ROBOTS = [p for p in workspace_files("*.xacro")
                if f"{os.sep}inc{os.sep}" not in p and not p.endswith(".srdf.xacro")
                and not _refuses(p)]
REFUSING_XACROS = [p for p in workspace_files("*.xacro") if _refuses(p)]
# launch files that, as Interbotix's own, need the robot's arguments (robot_model's
# default is empty there too)
PX100 = ["robot_model:=px100", "dof:=4"]
LAUNCH_ARGUMENTS = {
    "compat/interbotix_xsarm_descriptions/launch/xsarm_description.launch": PX100,
    "compat/interbotix_xsarm_gazebo/launch/xsarm_gazebo.launch": PX100,
    "compat/interbotix_xsarm_moveit/launch/xsarm_moveit.launch": PX100,
    "compat/interbotix_xsarm_moveit/launch/move_group.launch": PX100 + ["robot_name:=px100"],
    "compat/interbotix_xsarm_moveit/launch/planning_context.launch": PX100 + ["robot_name:=px100"],
    "compat/interbotix_xsarm_ros_control/launch/xsarm_ros_control.launch": PX100,
    "compat/interbotix_xsarm_control/launch/xsarm_control.launch": PX100 + ["use_sim:=true"],
    # the 2020 course's files name the robot by robot_name
    "compat/interbotix_descriptions/launch/description.launch": ["robot_name:=px100"],
    "compat/interbotix_gazebo/launch/gazebo.launch": ["robot_name:=px100"],
    "compat/interbotix_moveit/launch/interbotix_moveit.launch": ["robot_name:=px100",
                                                                 "use_fake:=true"],
    "compat/interbotix_sdk/launch/arm_run.launch": ["robot_name:=px100"],
}


def run(command):
    return subprocess.run(command, cwd=REPO, capture_output=True, text=True, check=False,
                          timeout=120)


def test_the_workspace_has_packages_and_launch_files():
    assert "my_rb1_description" in PACKAGES
    assert "my_rb1_description/launch/display.launch" in LAUNCH_FILES


@pytest.mark.parametrize("package", PACKAGES)
def test_catkin_lint_finds_no_warnings(package):
    result = run(["catkin_lint", "-W2", "--strict", package])
    assert result.returncode == 0, result.stdout + result.stderr


@pytest.mark.parametrize("launch_file", LAUNCH_FILES)
def test_roslaunch_check_passes(launch_file):
    # what roslaunch-check runs, in this process (the script costs a second a file to start)
    path = os.path.join(REPO, launch_file)
    if launch_file not in LAUNCH_ARGUMENTS:
        error = roslaunch.rlutil.check_roslaunch(path)
        assert not error, error
        return
    # with the arguments a user gives: the file loads and its packages are declared
    roslaunch.config.load_config_default([(path, LAUNCH_ARGUMENTS[launch_file])],
                                         roslaunch.rlutil.DEFAULT_MASTER_PORT, verbose=False)
    _, _, missing = roslaunch.depends.roslaunch_deps([path])
    assert not any(missing.values()), missing


def test_every_launch_file_given_arguments_exists():
    assert set(LAUNCH_ARGUMENTS) <= set(LAUNCH_FILES)


@pytest.mark.parametrize("xacro_file", REFUSING_XACROS)
def test_other_interbotix_models_are_refused_by_name(xacro_file):
    expanded = run(["xacro", xacro_file])
    model = os.path.basename(xacro_file).split(".")[0]
    assert expanded.returncode != 0
    assert f"robot_model:={model}: this workspace's interbotix_xsarm_descriptions describes " \
        "the X-series arms px100, px150, rx150, rx200, wx200, wx250, wx250s, vx250, vx300 " \
        "and vx300s only" in expanded.stderr, expanded.stderr


@pytest.mark.parametrize("urdf", [p for p in URDF_FILES if "/e2e/data/" not in p])
def test_check_urdf_passes(urdf):
    result = run(["check_urdf", urdf])
    assert result.returncode == 0, result.stdout + result.stderr


@pytest.mark.parametrize("xacro_file", XACRO_ROBOTS)
def test_check_urdf_passes_on_expanded_xacro(xacro_file, tmp_path):
    expanded = run(["xacro", xacro_file])
    assert expanded.returncode == 0, expanded.stderr
    urdf = tmp_path / "expanded.urdf"
    urdf.write_text(expanded.stdout)
    result = run(["check_urdf", str(urdf)])
    assert result.returncode == 0, result.stdout + result.stderr

"""compat/: the Gazebo stack's names, and leaving them out where the real ones are installed."""
import glob
import os
import re
import subprocess
import xml.etree.ElementTree as ET

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
COMPAT = os.path.join(REPO, "compat")
SHIMS = sorted(os.path.basename(os.path.dirname(p))
               for p in glob.glob(os.path.join(COMPAT, "*", "package.xml")))
# the names course files and public robot packages use (the drop-in issue's list)
UPSTREAM_NAMES = {
    "gazebo_ros", "gazebo_msgs", "gazebo_plugins", "gazebo_ros_control", "gazebo_dev",
    "joint_state_controller", "effort_controllers", "position_controllers",
    "velocity_controllers", "joint_trajectory_controller", "diff_drive_controller", "xacro",
    "teleop_twist_keyboard", "urdf_tutorial", "rqt_robot_steering",
    "joint_state_publisher_gui", "controller_manager", "controller_manager_msgs",
    "control_msgs", "media_export", "turtlesim",
}


def test_every_upstream_name_is_a_package_here():
    assert UPSTREAM_NAMES <= set(SHIMS)


@pytest.mark.parametrize("folder", SHIMS)
def test_each_package_has_its_folders_name(folder):
    name = ET.parse(os.path.join(COMPAT, folder, "package.xml")).getroot().findtext("name")
    assert name == folder


def test_rospack_answers_rvizs_media_question():
    """rviz asks rospack at every start which packages export Ogre media under media_export
    (a package rviz depends on and Debian lacks); an unknown package prints an error."""
    result = subprocess.run(["rospack", "plugins", "--attrib=ogre_media_path", "media_export"],
                            capture_output=True, text=True, timeout=60, check=False)
    assert result.returncode == 0, result.stderr
    assert "no such package" not in result.stderr


# interfaces a course solution builds against, as a student's package does (arm_move's
# services carry moveit_msgs' error codes): on a machine with MoveIt its underlay has them
SOLUTION_INTERFACES = {"moveit_msgs", "octomap_msgs", "object_recognition_msgs"}
# the workspace's test packages (test/packages): robot packages' own Gazebo C++ plugins, which
# build against the real Gazebo where the shims are left out, and so are left out with them
# here, where no underlay has Gazebo
TEST_PACKAGES = sorted(os.path.basename(os.path.dirname(p)) for p in
                       glob.glob(os.path.join(REPO, "test", "packages", "*", "package.xml")))


def test_the_rest_configures_with_every_shim_left_out(tmp_path):
    """The README's recipe for machines with the real packages: blacklist every shim. With
    no underlay providing them (but the message packages a solution builds against), the
    configure passing shows that nothing else build-depends on one."""
    source = os.path.join(REPO, ".ws", "src")
    environment = {"PATH": "/usr/bin:/bin", "HOME": os.environ.get("HOME", "/root")}
    left_out = [shim for shim in SHIMS if shim not in SOLUTION_INTERFACES] + TEST_PACKAGES
    result = subprocess.run(
        ["cmake", "-S", source, "-B", str(tmp_path / "build"),
         f"-DCATKIN_DEVEL_PREFIX={tmp_path / 'devel'}", "-DPYTHON_EXECUTABLE=/usr/bin/python3",
         f"-DCATKIN_BLACKLIST_PACKAGES={';'.join(left_out)}"],
        env=environment, capture_output=True, text=True, timeout=300, check=False)
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
    traversed = re.findall(r"^-- ~~  - (\S+)$", result.stdout, re.M)
    others = {os.path.basename(os.path.dirname(p))
              for pattern in ("*", os.path.join("courses", "*"))
              for p in glob.glob(os.path.join(REPO, pattern, "package.xml"))}
    assert set(traversed) == others | SOLUTION_INTERFACES

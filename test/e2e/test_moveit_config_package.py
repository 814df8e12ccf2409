"""A Setup-Assistant-style MoveIt config package written here for an arm that is not the
px100 (test/fixtures/moveit_ws: six_axis_arm_description, six_axis_arm_moveit_config with
Noetic's layout (planning_pipelines, pass_all_args, $(dirname)), and six_axis_arm_demo, a
package whose CMakeLists finds moveit_commander, moveit_core, moveit_ros_planning and
moveit_ros_planning_interface, whose script follows MoveIt's Python tutorial and whose C++
node, on MoveGroupInterface and PlanningSceneInterface, follows its C++ tutorial). Built on
top of this workspace as a user's own; ``roslaunch six_axis_arm_moveit_config demo.launch``
with fake controllers; every target checked by the URDF's kinematics (urdf_tools, apart
from move_group's) at the joint positions /joint_states reports: <= 1 mm, <= 0.01 rad; the C++
tutorial's orientation path constraint (0.1 rad) checked at every planned waypoint."""
import json
import math
import os
import shutil
import subprocess

import numpy as np
import pytest
from tf.transformations import euler_from_matrix, quaternion_matrix

import headless
import rviz_view
from urdf_tools import load_urdf
from urdf_tools.kinematics import link_transform

FIXTURE = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                       "fixtures", "moveit_ws")
JOINTS = ["shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint", "wrist_1_joint",
          "wrist_2_joint", "wrist_3_joint"]
READY = [0.0, 0.4, 0.8, 0.3, 0.5, 0.0]   # not the wrist's singular 0 (Cartesian steps)
START_LIMIT = 60.0
RUN_LIMIT = 240.0
PLANNING_FAILED = -1      # MoveIt's answer to a goal inside a box (every failed solve)
SUCCESS = 1               # moveit_msgs/MoveItErrorCodes
METRES, RADIANS = 0.001, 0.01   # how close a reached target must be
SAME_FK = 1e-6            # the C++ RobotState's forward kinematics against urdf_tools'
KEEP_ORIENTATION = 0.1    # rad: the C++ tutorial's orientation path constraint, per axis


@pytest.fixture(scope="module")
def overlay(tmp_path_factory):
    workspace = tmp_path_factory.mktemp("moveit_ws")
    shutil.copytree(os.path.join(FIXTURE, "src"), workspace / "src")
    build = subprocess.run(["catkin_make", "-C", str(workspace),
                            "-DPYTHON_EXECUTABLE=/usr/bin/python3"], cwd=workspace,
                           capture_output=True, text=True, timeout=600, check=False)
    assert build.returncode == 0, build.stdout[-3000:] + build.stderr[-3000:]
    sourced = subprocess.run(["bash", "-c", "source devel/setup.bash && env -0"],
                             cwd=workspace, capture_output=True, text=True, check=True)
    return workspace, dict(line.split("=", 1) for line in sourced.stdout.split("\0")
                           if "=" in line)


def tool_pose(urdf, joints):
    return link_transform(urdf, "base_link", "tool0", dict(zip(JOINTS, joints)))


def pose_errors(urdf, joints, goal):
    """(metres, radians) between the tool at ``joints`` and ``goal`` [x y z qx qy qz qw]."""
    reached = tool_pose(urdf, joints)
    wanted = quaternion_matrix(goal[3:])
    turn = reached[:3, :3].T @ wanted[:3, :3]
    angle = math.acos(max(-1.0, min(1.0, (np.trace(turn) - 1) / 2)))
    return float(np.linalg.norm(reached[:3, 3] - goal[:3])), angle


def pose_matrix(pose):
    """4x4 of [x y z qx qy qz qw]."""
    matrix = quaternion_matrix(pose[3:])
    matrix[:3, 3] = pose[:3]
    return matrix


def matrix_errors(reached, wanted):
    """(metres, radians) between two 4x4 poses."""
    turn = reached[:3, :3].T @ wanted[:3, :3]
    angle = math.acos(max(-1.0, min(1.0, (np.trace(turn) - 1) / 2)))
    return float(np.linalg.norm(reached[:3, 3] - wanted[:3, 3])), angle


def run_steps(command, env, log_path):
    """Runs a demo node; its JSON lines by step."""
    run = subprocess.run(["rosrun", "six_axis_arm_demo", command], env=env,
                         capture_output=True, text=True, timeout=RUN_LIMIT, check=False)
    with open(log_path, "w", encoding="utf-8") as log:
        log.write(run.stdout + run.stderr)
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-3000:]
    return {s["step"]: s for s in (json.loads(line) for line in run.stdout.splitlines()
                                   if line.startswith("{"))}


def check_cpp_steps(urdf, steps):
    """The C++ tutorial's steps (move_group_interface_demo.cpp), each against the URDF's own
    kinematics at the joints /joint_states reported after it."""
    assert steps["info"]["frame"] == "world" and steps["info"]["eef"] == "tool0"
    assert steps["info"]["groups"] == ["manipulator"]
    assert set(steps["info"]["named"]) == {"home", "ready"}
    assert steps["info"]["variables"] == JOINTS
    # the Python script's box was removed through apply_planning_scene
    assert steps["cleared"]["ok"] and steps["cleared"]["objects"] == []

    assert steps["named"]["ok"]
    np.testing.assert_allclose(steps["named"]["joints"], READY, atol=RADIANS)

    pose = steps["pose"]
    assert pose["ok"] and pose["planned"] and pose["points"] >= 2, pose
    # the goal is RobotState's forward kinematics of the source joints: urdf_tools agrees
    metres, radians = pose_errors(urdf, pose["source"], np.array(pose["goal"]))
    assert metres <= SAME_FK and radians <= SAME_FK, (metres, radians)
    metres, radians = pose_errors(urdf, pose["joints"], np.array(pose["goal"]))
    assert metres <= METRES and radians <= RADIANS, (metres, radians)
    # getCurrentPose and getCurrentRPY: the tool where urdf_tools puts it at the reported joints
    metres, radians = pose_errors(urdf, pose["joints"], np.array(pose["current_pose"]))
    assert metres <= SAME_FK and radians <= SAME_FK, (metres, radians)
    np.testing.assert_allclose(
        pose["rpy"], euler_from_matrix(tool_pose(urdf, pose["joints"]), "sxyz"), atol=SAME_FK)

    ik = steps["ik"]
    assert ik["ok"] and ik["solved"], ik
    metres, radians = pose_errors(urdf, ik["joints"], np.array(ik["goal"]))
    assert metres <= METRES and radians <= RADIANS, (metres, radians)

    joint = steps["joint"]
    assert joint["ok"] and joint["accepted"] and joint["short_refused"], joint
    np.testing.assert_allclose(joint["joints"], joint["goal"], atol=RADIANS)

    # the tutorial's orientation path constraint: every planned waypoint keeps the tool within
    # 0.1 rad of its start orientation about each axis (kinematic_constraint.cpp's XYZ Euler
    # angles of the relative rotation), and the goal is reached
    constrained = steps["constrained"]
    assert constrained["ok"] and constrained["planned"], constrained
    kept = quaternion_matrix(constrained["start"][3:])
    for waypoint in constrained["waypoints"]:
        turn = kept[:3, :3].T @ tool_pose(urdf, waypoint)[:3, :3]
        angles = np.abs(euler_from_matrix(turn, "rxyz"))
        assert np.all(angles <= KEEP_ORIENTATION + SAME_FK), (waypoint, angles)
    metres, radians = pose_errors(urdf, constrained["joints"], np.array(constrained["goal"]))
    assert metres <= METRES and radians <= RADIANS, (metres, radians)

    cartesian = steps["cartesian"]
    assert cartesian["ok"] and cartesian["code"] == SUCCESS, cartesian
    assert cartesian["fraction"] == pytest.approx(1.0)
    metres, radians = pose_errors(urdf, cartesian["joints"], np.array(cartesian["goal"]))
    assert metres <= METRES and radians <= RADIANS, (metres, radians)

    attached = steps["attached"]
    assert attached["ok"] and attached["unknown_refused"] and attached["link"] == "tool0"
    assert "carried_box" in attached["world_after_add"]
    assert "carried_box" not in attached["world_after_attach"]
    # carried: after the move and the detach, the box keeps its place relative to the tool
    detached = steps["detached"]
    assert detached["ok"], detached
    np.testing.assert_allclose(detached["joints"], detached["goal"], atol=RADIANS)
    offset = np.linalg.inv(tool_pose(urdf, attached["joints"])) @ pose_matrix(attached["box"])
    expected = tool_pose(urdf, detached["joints"]) @ offset
    metres, radians = matrix_errors(pose_matrix(detached["box"]), expected)
    assert metres <= METRES and radians <= RADIANS, (metres, radians)
    # and it moved with the arm (far more than the tolerance)
    assert np.linalg.norm(np.array(detached["box"][:3]) - attached["box"][:3]) > 100 * METRES

    assert steps["removed"]["ok"] and steps["removed"]["objects"] == []


def cartesian_log(path):
    """move_group's lines about Cartesian paths (where one stopped and why)."""
    with open(path, encoding="utf-8", errors="replace") as log:
        return [line.strip() for line in log if "artesian" in line]


def test_a_setup_assistant_config_runs_the_tutorials_steps(overlay, ros_env, results_dir):
    workspace, overlay_env = overlay
    env = dict(overlay_env, ROS_MASTER_URI=ros_env["ROS_MASTER_URI"], ROS_HOME=ros_env["ROS_HOME"])
    env.pop("DISPLAY", None)
    urdf = load_urdf(str(workspace / "src" / "six_axis_arm_description" / "urdf" /
                         "six_axis_arm.urdf"))
    with headless.roslaunch(["six_axis_arm_moveit_config", "demo.launch", "use_rviz:=false"],
                            env, os.path.join(results_dir, "demo.log")) as launch:
        def up():
            assert launch.running(), launch.output()[-3000:]
            return "You can start planning now!" in launch.output()
        headless.wait_until(up, START_LIMIT, "move_group")
        steps = run_steps("demo_mover.py", env, os.path.join(results_dir, "demo_mover.log"))
        # the C++ tutorial's steps on the same move_group, after the Python ones
        cpp_steps = run_steps("move_group_interface_demo", env,
                              os.path.join(results_dir, "move_group_interface_demo.log"))
    assert steps["info"] == {"step": "info", "frame": "world", "eef": "tool0",
                             "groups": ["manipulator"]}
    assert steps["named"]["ok"]
    np.testing.assert_allclose(steps["named"]["joints"], READY, atol=0.01)
    assert steps["joint"]["ok"]
    np.testing.assert_allclose(steps["joint"]["joints"], steps["joint"]["goal"], atol=0.01)
    assert steps["pose"]["ok"]
    metres, radians = pose_errors(urdf, steps["pose"]["joints"], np.array(steps["pose"]["goal"]))
    assert metres <= 0.001 and radians <= 0.01, (metres, radians)
    assert steps["cartesian"]["ok"] and steps["cartesian"]["fraction"] == pytest.approx(1.0), (
        steps["cartesian"], cartesian_log(os.path.join(results_dir, "demo.log")))
    metres, radians = pose_errors(urdf, steps["cartesian"]["joints"],
                                  np.array(steps["cartesian"]["goal"]))
    assert metres <= 0.001 and radians <= 0.01, (metres, radians)
    assert not steps["blocked"]["ok"] and steps["blocked"]["code"] == PLANNING_FAILED
    assert steps["blocked"]["objects"] == ["box"]
    check_cpp_steps(urdf, cpp_steps)


# MoveIt's goal state colour (Goal State Color 250; 128; 0 in the config), lit: the
# MotionPlanning display draws the query's goal state over the arm
GOAL_STATE_PIXELS = 300


def goal_orange(red, green, blue):
    # lit, it reads about (223, 56, 0); the goal marker's red rings have almost no green
    return (red > 180) & (green > 40) & (green < 110) & (blue < 40)


def test_demo_launch_opens_moveits_rviz(overlay, screen_env, results_dir):
    """demo.launch with its rviz (use_rviz's default) and the package's Setup-Assistant-style
    moveit.rviz: every display class loads (no PluginlibFactory error in rviz's log) and the
    MotionPlanning display draws the arm's goal state."""
    _, overlay_env = overlay
    env = dict(overlay_env, **{key: screen_env[key] for key in
                               ("ROS_MASTER_URI", "ROS_HOME", "DISPLAY", "LIBGL_ALWAYS_SOFTWARE")})
    shot = os.path.join(results_dir, "demo_rviz.png")

    def picture(launch):
        headless.wait_until(lambda: "You can start planning now!" in launch.output()
                            or not launch.running(), START_LIMIT, "move_group")
        headless.stable_screenshot(env["DISPLAY"], shot, "RViz", launch)
        assert launch.running(), launch.output()[-3000:]
        return launch.output()

    output = headless.run_while_node_lives(["six_axis_arm_moveit_config", "demo.launch"], env,
                                           os.path.join(results_dir, "demo_rviz.log"), picture)
    assert "PluginlibFactory" not in output and "failed to load" not in output, output[-3000:]
    picture_array = rviz_view.image(shot)
    orange = int(rviz_view.mask(picture_array, goal_orange,
                                rviz_view.view_rect(picture_array)).sum())
    assert orange > GOAL_STATE_PIXELS, f"{orange} pixels in the goal state's colour"

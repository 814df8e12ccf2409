"""The arm homework's MoveIt launch lines, as students type them, with a student-style
moveit_commander mover (test/fixtures/moveit_scripts/px100_mover.py):
    roslaunch interbotix_xsarm_moveit xsarm_moveit.launch robot_model:=px100 dof:=4 use_fake:=true
    roslaunch interbotix_xsarm_moveit xsarm_moveit.launch robot_model:=px100 dof:=4 use_gazebo:=true
The gripper's true position is the URDF's kinematics (urdf_tools, apart from move_group's)
at the joint positions the robot reports: the fake controllers' in the first case, the
simulator's joint_state_controller's (its joints' true positions) in the second."""
import json
import os
import subprocess

import numpy as np
import rospy  # noqa: F401  (genpy's message classes need rospy's time)
import yaml

import headless
from urdf_tools import parse_urdf
from urdf_tools.kinematics import link_transform

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MOVER = os.path.join(REPO, "test", "fixtures", "moveit_scripts", "px100_mover.py")
ARM = ["waist", "shoulder", "elbow", "wrist_angle"]
TIP = "px100/ee_gripper_link"
START_LIMIT = 60.0       # s (wall): move_group's actions answering after roslaunch
MOVER_LIMIT = 240.0      # s (wall): the mover's whole run
# MoveIt's OMPL context answers every failed solve PLANNING_FAILED: a goal inside a box and
# one out of reach alike (students' tests assert it)
PLANNING_FAILED = -1


def run_mover(env, log_path):
    done = subprocess.run(["/usr/bin/python3", MOVER], env=env, capture_output=True, text=True,
                          timeout=MOVER_LIMIT, check=False)
    with open(log_path, "w", encoding="utf-8") as log:
        log.write(done.stdout + done.stderr)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-3000:]
    return {step["step"]: step for step in
            (json.loads(line) for line in done.stdout.splitlines() if line.startswith("{"))}


def true_gripper(env, urdf):
    """The gripper where the robot's reported joints put it (urdf_tools' kinematics)."""
    echo = subprocess.run(["rostopic", "echo", "-n", "1", "/px100/joint_states"], env=env,
                          capture_output=True, text=True, timeout=30, check=True)
    state = yaml.safe_load(echo.stdout.split("---")[0])
    positions = dict(zip(state["name"], state["position"]))
    return link_transform(urdf, "world", TIP, positions)[:3, 3], positions


def wait_for_move_group(env, launch):
    def up():
        assert launch.running(), launch.output()[-3000:]
        listed = subprocess.run(["rostopic", "list"], env=env, capture_output=True, text=True,
                                timeout=30, check=False).stdout.split()
        return "/px100/move_group/status" in listed and "/px100/place/status" in listed
    headless.wait_until(up, START_LIMIT, "move_group's actions")


def check_steps(steps, env):
    urdf_text = subprocess.run(["rosparam", "get", "/px100/robot_description"], env=env,
                               capture_output=True, text=True, timeout=30, check=True).stdout
    urdf = parse_urdf(yaml.safe_load(urdf_text))
    assert steps["robot"]["groups"] == ["interbotix_arm", "interbotix_gripper"]
    assert steps["robot"]["eef"] == TIP
    assert steps["sleep"]["ok"]
    np.testing.assert_allclose(steps["sleep"]["joints"], [0.0, -1.88, 1.5, 0.8], atol=0.02)
    assert steps["pose"]["ok"]
    reached, positions = true_gripper(env, urdf)
    error = np.linalg.norm(reached - np.array(steps["pose"]["target"]))
    assert error < 0.01, f"the gripper is {error * 1000:.1f} mm from the target ({positions})"
    assert not steps["in_box"]["ok"] and steps["in_box"]["code"] == PLANNING_FAILED
    assert steps["in_box"]["objects"] == ["block"]
    assert not steps["far"]["ok"] and steps["far"]["code"] == PLANNING_FAILED
    return error


def test_xsarm_moveit_with_fake_controllers(ros_env, results_dir):
    env = dict(ros_env)
    env.pop("DISPLAY", None)
    with headless.roslaunch(["interbotix_xsarm_moveit", "xsarm_moveit.launch", "robot_model:=px100",
                             "dof:=4", "use_fake:=true", "use_moveit_rviz:=false"], env,
                            os.path.join(results_dir, "xsarm_moveit.log")) as launch:
        wait_for_move_group(env, launch)
        steps = run_mover(env, os.path.join(results_dir, "mover.log"))
        error = check_steps(steps, env)
    print(f"fake: gripper {error * 1000:.2f} mm from the pose target")


def test_xsarm_moveit_in_the_simulation(ros_env, results_dir):
    """Interbotix's world starts paused: unpaused as their README says, then the same
    mover through the simulator's trajectory controllers."""
    env = dict(ros_env)
    env.pop("DISPLAY", None)
    with headless.roslaunch(["interbotix_xsarm_moveit", "xsarm_moveit.launch", "robot_model:=px100",
                             "dof:=4", "use_gazebo:=true", "use_moveit_rviz:=false"], env,
                            os.path.join(results_dir, "xsarm_moveit.log")) as launch:
        headless.wait_until(lambda: subprocess.run(
            ["rosservice", "call", "/gazebo/unpause_physics"], env=env, capture_output=True,
            timeout=30, check=False).returncode == 0, START_LIMIT, "the simulator to unpause")
        wait_for_move_group(env, launch)
        steps = run_mover(env, os.path.join(results_dir, "mover.log"))
        error = check_steps(steps, env)
    print(f"simulation: gripper {error * 1000:.2f} mm from the pose target")

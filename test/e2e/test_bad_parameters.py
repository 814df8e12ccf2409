"""Nodes started with bad private parameters, as users start them (``rosrun`` with
``_name:=value``, ``roslaunch`` with ``name:=value``), stop at once with one line naming the
parameter, the value as given and what is expected; no traceback. roslaunch hands its
arguments over as text unless they look like an int, a float with a dot or true/false, so
``1e9``, ``nan`` and ``maybe`` reach the nodes as strings (node_params converts them).

The cases share one master (``shared_master``: each case's parameters are deleted after it);
roslaunch, finding a master on its port, uses it instead of starting one, as it does for a
user who runs roscore first."""
import os
import subprocess

import pytest

import headless

# Long enough for roslaunch to start a master and the simulator to import pybullet on a
# busy 2-core machine; a case that passes ends as soon as its line is there.
LAUNCH_TIMEOUT = 60


def rosrun(env, *arguments):
    return subprocess.run(["rosrun", *arguments], env=env, capture_output=True, text=True,
                          timeout=LAUNCH_TIMEOUT, check=False, stdin=subprocess.DEVNULL)


def assert_named(output, *parts):
    for part in parts:
        assert part in output, output[-3000:]
    assert "Traceback" not in output, output[-3000:]


@pytest.mark.parametrize("parameter, value, says", [
    ("speed", "-1.0", "~speed: -1.0 is not positive; expected the wheels' ground speed"),
    ("leg_time", "fast", "~leg_time: 'fast' is not a number; expected seconds > 0"),
])
def test_flip_names_a_bad_setting(shared_master, parameter, value, says):
    result = rosrun(shared_master, "diff_drive", "flip", f"_{parameter}:={value}")
    assert result.returncode == 2, result.stdout + result.stderr
    assert_named(result.stdout + result.stderr, says)


def test_mover_names_a_bad_waypoint(shared_master):
    result = rosrun(shared_master, "arm_move", "mover", "_waypoints:=[[0.1, 0.2]]")
    assert result.returncode == 1, result.stdout + result.stderr
    assert_named(result.stdout + result.stderr, "~waypoints[0] must be [x, y, z, gripper_open]")


# ids without ':=' or spaces: the test's name becomes ROS_HOME's folder and so part of
# the __log:= argument roslaunch gives each node
@pytest.mark.parametrize("argument, says", [
    pytest.param("real_time_factor:=abc",
                 "~real_time_factor: 'abc' is not a number; expected 0 (as fast", id="rtf-abc"),
    pytest.param("real_time_factor:=nan", "~real_time_factor: 'nan' is not a finite number",
                 id="rtf-nan"),
    pytest.param("real_time_factor:=-1",
                 "~real_time_factor: -1 is neither 0 nor at least 0.001", id="rtf-negative"),
    pytest.param("seed:=abc", "~seed: 'abc' is not a whole number; expected a whole number >= 0",
                 id="seed-abc"),
    pytest.param("seed:=-5", "~seed: -5 is negative; expected a whole number >= 0",
                 id="seed-negative"),
    pytest.param("paused:=maybe",
                 "~paused: 'maybe' is not true or false; expected true or false", id="paused-maybe"),
    pytest.param("gui:=maybe", "~gui: 'maybe' is not true or false", id="gui-maybe"),
    pytest.param("extra_gazebo_args:=--seed=x", "gzserver --seed: 'x' is not a whole number",
                 id="gzserver-seed-x"),
])
def test_simulator_stops_naming_a_bad_launch_argument(shared_master, results_dir, argument,
                                                      says):
    """``roslaunch gazebo_ros empty_world.launch <argument>``: the simulator ends with one
    fatal line (roslaunch itself goes on, as the launch file does not require it)."""
    log = os.path.join(results_dir, "roslaunch.txt")
    arguments = ["gazebo_ros", "empty_world.launch", argument]
    if not argument.startswith("gui:="):
        arguments.append("gui:=false")
    with headless.roslaunch(arguments, shared_master, log) as launch:
        headless.wait_until(lambda: "process has died" in launch.output()
                            or not launch.running(), LAUNCH_TIMEOUT, "the simulator to stop")
        output = launch.output()
    assert_named(output, f"sim_bridge cannot start: {says}", "exit code 1")


def test_simulator_takes_a_huge_real_time_factor_as_fast_as_it_can(shared_master, results_dir):
    """1e9 (text to roslaunch) is read as a number; the machine cannot keep up with it, so
    the simulator simply runs unpaced."""
    log = os.path.join(results_dir, "roslaunch.txt")
    with headless.roslaunch(["gazebo_ros", "empty_world.launch", "gui:=false",
                             "real_time_factor:=1e9"], shared_master, log) as launch:
        headless.wait_until(lambda: "sim_bridge ready" in launch.output()
                            or "process has died" in launch.output(),
                            LAUNCH_TIMEOUT, "the simulator to start")
        output = launch.output()
    assert_named(output, "sim_bridge ready (real_time_factor 1e+09, running)")


@pytest.mark.parametrize("argument, says", [
    ("_ik_timeout:=abc", "~ik_timeout: 'abc' is not a number; expected s > 0 compute_ik"),
    ("_pitch_step_degrees:=0", "~pitch_step_degrees: 0 is not positive"),
])
def test_mover_names_a_bad_setting(shared_master, argument, says):
    result = rosrun(shared_master, "arm_move", "mover", argument)
    assert result.returncode == 1, result.stdout + result.stderr
    assert_named(result.stdout + result.stderr, f"mover: {says}")


@pytest.mark.parametrize("package, node, argument, says", [
    ("my_rb1_ros", "rotate_service", "_control_rate:=abc",
     "~control_rate: 'abc' is not a number; expected the control loop's rate"),
    ("my_rb1_ros", "rotate_service", "_odom_timeout:=-2",
     "~odom_timeout: -2 is not positive; expected wall seconds > 0"),
    ("my_rb1_ros", "rotate_service", "_max_degrees:=90.5",
     "~max_degrees: 90.5 is not a whole number"),
    ("teleop_twist_keyboard", "teleop_twist_keyboard.py", "_repeat_rate:=0",
     "~repeat_rate: 0 is not positive; expected how often the command is republished"),
])
def test_node_stops_naming_a_bad_parameter(shared_master, package, node, argument, says):
    result = rosrun(shared_master, package, node, argument)
    assert result.returncode == 1, result.stdout + result.stderr
    assert_named(result.stdout + result.stderr, says)

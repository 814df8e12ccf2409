"""A student's own workspace, written for Gazebo, built and run here unchanged.

test/fixtures/course_ws is written as course packages are (``$(find gazebo_ros)``,
``pkg="gazebo_ros" type="spawn_model"``, ``$(find xacro)/xacro``, CMakeLists that find
gazebo_ros, gazebo_msgs and xacro, a C++ rotate service, a Python node importing tf and
gazebo_msgs). It is copied to a temporary folder and built with catkin_make on top of this
workspace, as a student overlays theirs; then the student's commands run and what they do is
checked in the simulator's ground truth."""
import math
import os
import shutil
import subprocess
import termios

import pytest
import yaml
from tf.transformations import euler_from_quaternion

import headless

FIXTURE = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                       "fixtures", "course_ws")
MODEL = "course_robot"
SPAWN = (-0.4, -1.35)  # spawn.launch's default x, y
WALL_FACE_X = 1.9  # course.world's wall: centre x 2.0, 0.2 m thick
LASER_X = 0.2  # the laser's offset ahead of base_link


@pytest.fixture(scope="module")
def overlay(tmp_path_factory):
    """The fixture workspace built with catkin_make; its environment (sourced devel)."""
    workspace = tmp_path_factory.mktemp("course_ws")
    shutil.copytree(os.path.join(FIXTURE, "src"), workspace / "src")
    build = subprocess.run(["catkin_make", "-C", str(workspace),
                            "-DPYTHON_EXECUTABLE=/usr/bin/python3"],
                           cwd=workspace, capture_output=True, text=True, timeout=600,
                           check=False)
    assert build.returncode == 0, build.stdout[-3000:] + build.stderr[-3000:]
    sourced = subprocess.run(["bash", "-c", "source devel/setup.bash && env -0"],
                             cwd=workspace, capture_output=True, text=True, check=True)
    environment = dict(line.split("=", 1) for line in sourced.stdout.split("\0") if "=" in line)
    return workspace, environment


def test_the_cmake_files_find_the_gazebo_stack_and_the_cpp_node_builds(overlay):
    workspace, _ = overlay
    assert os.access(workspace / "devel" / "lib" / "course_robot_ros" / "rotate_service",
                     os.X_OK)


def true_pose(env):
    """(x, y, yaw in degrees) as the simulator knows it (gazebo_msgs' GetModelState)."""
    call = subprocess.run(["rosservice", "call", "/gazebo/get_model_state",
                           f"{{model_name: '{MODEL}', relative_entity_name: 'world'}}"],
                          env=env, capture_output=True, text=True, timeout=30, check=True)
    pose = yaml.safe_load(call.stdout)["pose"]
    q = pose["orientation"]
    yaw = euler_from_quaternion([q["x"], q["y"], q["z"], q["w"]])[2]
    return pose["position"]["x"], pose["position"]["y"], math.degrees(yaw)


def wrap_degrees(angle):
    return (angle + 180.0) % 360.0 - 180.0


def test_the_students_commands_spawn_scan_rotate_and_teleop(overlay, ros_env, results_dir):
    _, overlay_env = overlay
    env = dict(overlay_env, ROS_MASTER_URI=ros_env["ROS_MASTER_URI"],
               ROS_HOME=ros_env["ROS_HOME"])
    env.pop("DISPLAY", None)
    with headless.roslaunch(["course_robot_gazebo", "spawn.launch"], env,
                            os.path.join(results_dir, "spawn.log")) as launch:
        headless.wait_until(lambda: "Successfully spawned entity" in launch.output()
                            or not launch.running(), 90, "the robot to be spawned")
        assert launch.running(), launch.output()[-3000:]

        # the world's model:// include found through the package's exported model path
        world = subprocess.run(["rosservice", "call", "/gazebo/get_world_properties"],
                               env=env, capture_output=True, text=True, timeout=30, check=True)
        assert "start_marker" in yaml.safe_load(world.stdout)["model_names"]

        # the student's Python node: gazebo_msgs' service and tf.transformations
        probe = subprocess.run(["rosrun", "course_robot_ros", "true_pose.py"], env=env,
                               capture_output=True, text=True, timeout=60, check=True)
        x, y, yaw = (float(v) for v in probe.stdout.split())
        truth = true_pose(env)
        assert (x, y, yaw) == pytest.approx(truth, abs=1e-3)
        assert (x, y) == pytest.approx(SPAWN, abs=0.01) and abs(yaw) < 0.5

        # the laser's middle beam sees the wall ahead
        scan = subprocess.run(["rostopic", "echo", "-n1", "/scan/ranges"], env=env,
                              capture_output=True, text=True, timeout=60, check=True)
        ranges = [float(v) for v in scan.stdout.split("---")[0].strip().strip("[]").split(",")]
        middle = ranges[len(ranges) // 2]
        assert middle == pytest.approx(WALL_FACE_X - (x + LASER_X), abs=0.03)

        # the C++ rotate service, built by catkin_make, turns the robot by what is asked
        with headless.roslaunch(["course_robot_ros", "rotate_service.launch"], env,
                                os.path.join(results_dir, "rotate.log")) as service:
            # a C++ node's log reaches a pipe only when its buffer fills: ask the master
            headless.wait_until(lambda: subprocess.run(
                ["rosservice", "info", "/rotate_robot"], env=env, capture_output=True,
                timeout=30, check=False).returncode == 0 or not service.running(), 60,
                "the C++ rotate service")
            # -90 first: a wrong turn direction (the diff drive's wheels swapped) sends the
            # closed loop away from the goal until its 20 s timeout
            for degrees in (-90, 90):
                before = true_pose(env)[2]
                call = subprocess.run(["rosservice", "call", "/rotate_robot",
                                       f"degrees: {degrees}"], env=env, capture_output=True,
                                      text=True, timeout=120, check=False)
                assert f'result: "success: rotated {degrees} degrees"' in call.stdout, \
                    call.stdout
                turned = wrap_degrees(settled_yaw(env) - before)
                assert turned == pytest.approx(degrees, abs=5.0)

        # teleop_twist_keyboard in a terminal: 'i' drives forward, 'k' stops, Ctrl-C quits
        start = true_pose(env)
        heading = math.radians(start[2])
        master, slave = os.openpty()
        settings = termios.tcgetattr(slave)
        teleop = subprocess.Popen(["rosrun", "teleop_twist_keyboard", "teleop_twist_keyboard.py",
                                   "_speed:=0.3"], env=env, stdin=slave, stdout=slave,
                                  stderr=slave)
        try:
            headless.wait_until(lambda: "/teleop_twist_keyboard" in subprocess.run(
                ["rosnode", "list"], env=env, capture_output=True, text=True, timeout=30,
                check=False).stdout, 30, "teleop_twist_keyboard to be up")

            def ahead():
                x1, y1, _ = true_pose(env)
                return (x1 - start[0]) * math.cos(heading) + (y1 - start[1]) * math.sin(heading)

            os.write(master, b"i")
            headless.wait_until(lambda: ahead() > 0.15, 60, "the robot to drive 0.15 m ahead")
            os.write(master, b"k")
            os.write(master, b"\x03")
            teleop.wait(timeout=20)
        finally:
            if teleop.poll() is None:
                teleop.kill()
        assert teleop.returncode == 0
        assert termios.tcgetattr(slave) == settings
        os.close(master)
        os.close(slave)


def settled_yaw(env, tolerance=0.05, timeout=20.0):
    """The true yaw once it stops changing (the robot has come to rest)."""
    samples = [true_pose(env)[2]]

    def still():
        samples.append(true_pose(env)[2])
        return abs(wrap_degrees(samples[-1] - samples[-2])) < tolerance

    headless.wait_until(still, timeout, "the robot to stop turning", interval=0.3)
    return samples[-1]


def test_what_robot_packages_find_and_start_is_there(overlay, ros_env, results_dir):
    """course_robot_description's CMakeLists finds rviz and robot_state_publisher (Debian's
    librviz-dev, librobot-state-publisher-dev); course_robot_control: a C++ node whose
    CMakeLists finds controller_manager and joint_state_controller (not roscpp) links and runs; its launch file loads $(find joint_state_controller)'s yaml and
    starts tf's and tf2_ros's static_transform_publisher, topic_tools' relay and nodelet."""
    workspace, overlay_env = overlay
    assert os.access(workspace / "devel" / "lib" / "course_robot_control" / "hardware_hello",
                     os.X_OK)
    env = dict(overlay_env, ROS_MASTER_URI=ros_env["ROS_MASTER_URI"],
               ROS_HOME=ros_env["ROS_HOME"])

    def run(*command):
        return subprocess.run(list(command), env=env, capture_output=True, text=True,
                              timeout=30, check=False)

    with headless.roslaunch(["course_robot_control", "extras.launch"], env,
                            os.path.join(results_dir, "extras.log")) as launch:
        # the C++ node's latched message, through topic_tools' relay
        relayed = headless.wait_until(
            lambda: run("rostopic", "echo", "-n", "1", "/status").stdout, 60,
            "hardware_hello's status relayed on /status")
        assert "hardware up" in relayed
        kind = run("rosparam", "get", "/joint_state_controller/type").stdout.strip()
        assert kind == "joint_state_controller/JointStateController"
        assert run("rosparam", "get", "/joint_state_controller/publish_rate").stdout.strip() \
            == "50"
        # tf's publisher repeats on /tf every 100 ms; tf2_ros's is latched on /tf_static
        tf = run("rostopic", "echo", "-n", "1", "/tf").stdout
        assert "child_frame_id: \"camera_link\"" in tf, tf
        tf_static = run("rostopic", "echo", "-n", "1", "/tf_static").stdout
        assert "child_frame_id: \"imu_link\"" in tf_static, tf_static
        assert "/nodelet_manager" in run("rosnode", "list").stdout
        assert launch.running(), launch.output()[-3000:]

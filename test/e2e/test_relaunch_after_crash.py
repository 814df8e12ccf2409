"""A simulator that crashed is relaunched on the same roscore, as every ROS user does.

A killed node never unregisters: the master keeps the dead simulator's /gazebo services
until a new simulator registers them again. spawn_model took that stale registration for
the live service ('unable to connect to service: Connection refused') and died, and with it
a launch that marks it required. Now it probes the service as rospy.wait_for_service does,
so a stale registration is "not up yet" until its own timeout.

The RB1 warehouse as the course starts it: the simulator SIGKILLed (a crash, the OOM
killer), the launch stopped with Ctrl-C, the same command again: the robot is at its start
pose in the simulator's ground truth within 10 s, /odom and /scan flow, and the rotate
service started before the crash turns the robot again.
"""
import math
import os
import signal
import socket
import subprocess
import time
import xmlrpc.client

import rosgraph
import rospy.core
import yaml
from tf.transformations import euler_from_quaternion

import headless

WAREHOUSE = ["my_rb1_gazebo", "my_rb1_robot_warehouse.launch"]
START = (-0.434, -1.323)   # m: the launch's default spawn position (the taped square's centre)
SPAWN_LIMIT = 90           # s (wall): the first start, rviz-free, on a busy machine
RELAUNCH_LIMIT = 10        # s (wall): the bound from the second roslaunch to the robot
TOPIC_LIMIT = 30           # s (wall): a message on /odom or /scan
# the /gazebo services the workspace's clients call (spawn_model and its -wait, -J and
# -unpause, the grader's probes, the rotate service's tests, controller spawners' worlds)
SPAWN_SERVICES = ("/gazebo/spawn_urdf_model", "/gazebo/spawn_sdf_model",
                  "/gazebo/get_model_state", "/gazebo/unpause_physics",
                  "/gazebo/pause_physics", "/gazebo/set_model_configuration",
                  "/gazebo/get_world_properties", "/gazebo/get_model_properties",
                  "/gazebo/get_physics_properties", "/gazebo/get_link_state",
                  "/gazebo/set_model_state", "/gazebo/delete_model")


def master_of(env):
    return rosgraph.Master("/e2e_crash_check", master_uri=env["ROS_MASTER_URI"])


def simulator_pid(env) -> int:
    uri = master_of(env).lookupNode("/gazebo")
    code, _, pid = xmlrpc.client.ServerProxy(uri).getPid("/e2e_crash_check")
    assert code == 1
    return pid


def gone(pid: int) -> bool:
    """The process ended (a zombie not yet reaped by roslaunch counts as ended)."""
    try:
        with open(f"/proc/{pid}/stat") as stream:
            return stream.read().rsplit(")", 1)[1].split()[0] == "Z"
    except FileNotFoundError:
        return True


def refuses_connections(env, service: str) -> bool:
    """The master still lists ``service`` and its address refuses a connection."""
    uri = master_of(env).lookupService(service)
    try:
        socket.create_connection(rospy.core.parse_rosrpc_uri(uri), timeout=1.0).close()
        return False
    except ConnectionRefusedError:
        return True


def run(env, *command, timeout=60):
    return subprocess.run(list(command), env=env, capture_output=True, text=True,
                          timeout=timeout, check=False)


def true_pose(env):
    """(x, y, yaw) of my_rb1 in the simulator's ground truth."""
    answer = run(env, "rosservice", "call", "/gazebo/get_model_state", "model_name: 'my_rb1'")
    assert answer.returncode == 0, answer.stderr
    pose = yaml.safe_load(answer.stdout)["pose"]
    q = pose["orientation"]
    return (pose["position"]["x"], pose["position"]["y"],
            euler_from_quaternion((q["x"], q["y"], q["z"], q["w"]))[2])


def test_a_killed_simulator_relaunches_on_the_same_master(master, results_dir):
    with headless.roslaunch(["my_rb1_ros", "rotate_service.launch"], master,
                            os.path.join(results_dir, "rotate_service.log")) as service:
        with headless.roslaunch(WAREHOUSE, master,
                                os.path.join(results_dir, "first.log")) as first:
            headless.wait_until(lambda: "spawned model 'my_rb1'" in first.output(),
                                SPAWN_LIMIT, "the RB1 in the first simulator")
            headless.wait_until(lambda: "Service Ready" in service.output(), SPAWN_LIMIT,
                                "rotate_service to say Service Ready")
            pid = simulator_pid(master)
            os.kill(pid, signal.SIGKILL)
            # the leader thread turns zombie before its other threads have let the sockets go
            headless.wait_until(lambda: gone(pid) and refuses_connections(master, SPAWN_SERVICES[0]),
                                10, "the killed simulator to end")
            # what the relaunch meets: every service of the dead simulator still listed
            for name in SPAWN_SERVICES:
                assert refuses_connections(master, name), name
            # a spawn against the stale registration waits, then names the cause
            waited = run(master, "rosrun", "gazebo_ros", "spawn_model", "-urdf", "-param",
                         "robot_description", "-model", "late", "-timeout", "2")
            assert waited.returncode == 1
            assert "service /gazebo/spawn_urdf_model not available after 2 s" in waited.stderr
            assert "Connection refused" not in waited.stdout + waited.stderr
        started = time.monotonic()
        with headless.roslaunch(WAREHOUSE, master,
                                os.path.join(results_dir, "second.log")) as second:
            headless.wait_until(lambda: "spawned model 'my_rb1'" in second.output(),
                                RELAUNCH_LIMIT, "the RB1 in the relaunched simulator")
            print(f"relaunch: robot spawned {time.monotonic() - started:.2f} s after roslaunch")
            assert "Connection refused" not in second.output()
            x, y, yaw = true_pose(master)
            assert math.hypot(x - START[0], y - START[1]) < 0.02, (x, y)
            for topic in ("/odom", "/scan"):
                echo = run(master, "rostopic", "echo", "-n", "1", topic, timeout=TOPIC_LIMIT)
                assert echo.returncode == 0 and "header" in echo.stdout, (topic, echo.stderr)
            call = run(master, "rosservice", "call", "/rotate_robot", "degrees: 90",
                       timeout=120)
            assert call.returncode == 0, call.stderr
            assert "success" in call.stdout, call.stdout
            turned = math.degrees(math.remainder(true_pose(master)[2] - yaw, 2 * math.pi))
            assert abs(turned - 90.0) < 2.0, turned
            # spawn_model's later calls (-wait: get_world_properties, -unpause) reach the
            # new simulator, in a namespace of its own so that nothing above hears it
            more = run(master, "rosrun", "gazebo_ros", "spawn_model", "-urdf", "-param",
                       "robot_description", "-model", "second", "-robot_namespace", "second",
                       "-x", "1.5", "-y", "-1.3", "-wait", "my_rb1", "-unpause",
                       "-timeout", "10")
            assert more.returncode == 0, more.stdout + more.stderr

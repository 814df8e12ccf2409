#!/usr/bin/env python3
"""Starts and stops the simulator (``rosrun gazebo_ros gzserver``, as fast as it runs) N
times under the master in ROS_MASTER_URI, as roslaunch stops it: SIGINT to its process.
Each cycle spawns a robot with a laser and a drive plugin, then stops the simulator in
one of four states: running, paused, paused then unpaused, or with service calls in
flight. Prints one line per cycle: ``cycle <i> <state> <seconds from SIGINT to exit>
<exit status>``; a simulator still running after HANG_LIMIT seconds is killed and
reported with ``hung`` in place of the seconds.

Usage: stop_cycles.py N ROBOT_URDF"""
import signal
import subprocess
import sys
import threading
import time

import rospy
from gazebo_msgs.srv import GetWorldProperties, SpawnModel
from geometry_msgs.msg import Pose
from std_srvs.srv import Empty

STATES = ("running", "paused", "unpaused", "calls in flight")
HANG_LIMIT = 10.0      # s after SIGINT before a simulator counts as hung
START_LIMIT = 60.0     # s for the simulator's services to appear
CALLS_BEFORE_STOP = 3  # world-properties calls answered before SIGINT, in the flight state


def calls_in_flight(stop):
    """Calls /gazebo/get_world_properties until ``stop`` is set or the simulator goes."""
    ask = rospy.ServiceProxy("/gazebo/get_world_properties", GetWorldProperties)
    answered = 0
    while not stop.is_set():
        try:
            ask()
            answered += 1
        except (rospy.ServiceException, rospy.ROSException):
            return answered
    return answered


def cycle(index, robot):
    state = STATES[index % len(STATES)]
    simulator = subprocess.Popen(["rosrun", "gazebo_ros", "gzserver", "_real_time_factor:=0"],
                                 stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    rospy.wait_for_service("/gazebo/spawn_urdf_model", timeout=START_LIMIT)
    answer = rospy.ServiceProxy("/gazebo/spawn_urdf_model", SpawnModel)(
        model_name="robot", model_xml=robot, robot_namespace="", initial_pose=Pose(),
        reference_frame="")
    if not answer.success:
        raise SystemExit(f"cycle {index}: spawn refused: {answer.status_message}")
    if state in ("paused", "unpaused"):
        rospy.ServiceProxy("/gazebo/pause_physics", Empty)()
    if state == "unpaused":
        rospy.ServiceProxy("/gazebo/unpause_physics", Empty)()
    stop = threading.Event()
    caller = None
    if state == "calls in flight":
        caller = threading.Thread(target=calls_in_flight, args=(stop,), daemon=True)
        caller.start()
        ask = rospy.ServiceProxy("/gazebo/get_world_properties", GetWorldProperties)
        for _ in range(CALLS_BEFORE_STOP):
            ask()
    began = time.monotonic()
    simulator.send_signal(signal.SIGINT)
    try:
        status = simulator.wait(timeout=HANG_LIMIT)
        took = f"{time.monotonic() - began:.2f}"
    except subprocess.TimeoutExpired:
        simulator.kill()
        status, took = simulator.wait(), "hung"
    stop.set()
    if caller is not None:
        caller.join(HANG_LIMIT)
    print(f"cycle {index} {state.replace(' ', '_')} {took} {status}", flush=True)


def main():
    count, robot_file = int(sys.argv[1]), sys.argv[2]
    with open(robot_file) as stream:
        robot = stream.read()
    rospy.init_node("stop_cycles", anonymous=True, disable_signals=True)
    for index in range(count):
        cycle(index, robot)


if __name__ == "__main__":
    main()

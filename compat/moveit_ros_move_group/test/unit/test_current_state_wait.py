"""move_group's current state waits for a joint_states message no older than a request, as
MoveIt's CurrentStateMonitor::waitForCurrentState (current_state_monitor.cpp:272-292 on
noetic-devel): the oldest stamp among the joints heard so far must reach the request's time
(a joint never heard does not count, unless none was: :95-114); after the wait, false."""
import threading
import time

import rospy
from sensor_msgs.msg import JointState

from moveit_ros_move_group.state_monitor import CurrentState

JOINTS = ["a", "b", "c"]
SHORT_WAIT = 0.05      # s: a wait that must run out
LONG_WAIT = 5.0        # s: a wait that must not (the message comes far sooner)


def message(stamp, names=("a", "b")):
    state = JointState(name=list(names), position=[0.1] * len(names))
    state.header.stamp = rospy.Time.from_sec(stamp)
    return state


def test_a_state_older_than_the_request_is_waited_for_and_a_newer_one_ends_the_wait():
    current = CurrentState(dict.fromkeys(JOINTS, 0.0))
    current.update(message(10.0))
    assert not current.wait_for(10.5, JOINTS, SHORT_WAIT)
    threading.Timer(0.1, current.update, [message(11.0)]).start()
    began = time.monotonic()
    assert current.wait_for(10.5, JOINTS, LONG_WAIT)     # "c" was never heard: not waited for
    assert time.monotonic() - began < LONG_WAIT / 2


def test_one_joint_left_behind_keeps_the_state_old():
    current = CurrentState(dict.fromkeys(JOINTS, 0.0))
    current.update(message(10.0))
    current.update(message(11.0, names=("a",)))
    assert not current.wait_for(10.5, JOINTS, SHORT_WAIT)


def test_nothing_heard_or_no_time_is_no_current_state():
    current = CurrentState(dict.fromkeys(JOINTS, 0.0))
    assert not current.wait_for(10.0, JOINTS, SHORT_WAIT)
    current.update(message(11.0))
    began = time.monotonic()
    assert not current.wait_for(0.0, JOINTS, LONG_WAIT)   # an unset time answers at once
    assert time.monotonic() - began < LONG_WAIT / 2

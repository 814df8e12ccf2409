"""``rosrun rqt_robot_steering rqt_robot_steering``: the steering window as a ROS node.

Joins :mod:`robot_steering.widget` (Qt) to rospy: reads the private parameters
(``~default_topic``, ``~default_vx_max``, ``~default_vx_min``, ``~default_vw_max``,
``~default_vw_min``), publishes ``geometry_msgs/Twist`` with a queue of 10 as the rqt plugin
does, and is named as rqt's Python plugins' node is (``rqt_gui_py_node_<pid>``; ``__name:=``
renames it). Without a master it stops at once with a message; Ctrl-C, ``rosnode kill`` or
closing the window ends it. rqt's own command-line options (``--force-discover`` and the
like) are accepted and have no effect.

Test hook: when the environment variable ``ROBOT_STEERING_STATE_FILE`` names a file, the
window writes what it shows there as JSON after every change and every 100 ms tick (see
:meth:`robot_steering.widget.SteeringWidget.state`): the slider values and labels, the
ranges, the topic, how many Twists it published, and where its widgets are on the screen, so
that a test can move them with real mouse and keyboard input.
"""
from __future__ import annotations

import argparse
import json
import os
import signal
import sys
import traceback
from typing import List, Optional

import rosgraph
import rospy
from geometry_msgs.msg import Twist

from robot_steering.steering import read_settings

STATE_FILE_VARIABLE = "ROBOT_STEERING_STATE_FILE"
QUEUE_SIZE = 10
SHUTDOWN_POLL_MS = 200


class TopicPublisher:
    """A Twist publisher on one topic, for :class:`~robot_steering.widget.SteeringWidget`."""

    def __init__(self, topic: str):
        self._publisher = rospy.Publisher(topic, Twist, queue_size=QUEUE_SIZE)

    def publish(self, twist: Twist) -> None:
        try:
            self._publisher.publish(twist)
        except rospy.ROSException as error:  # the node is shutting down
            rospy.logdebug("not published: %s", error)

    def unregister(self) -> None:
        self._publisher.unregister()


class StateFile:
    """Writes the window's state as JSON to ``path``, replacing the file in one step."""

    def __init__(self, path: str):
        self.path = path

    def write(self, state: dict) -> None:
        partial = f"{self.path}.{os.getpid()}.partial"
        with open(partial, "w", encoding="utf-8") as stream:
            json.dump(state, stream)
        os.replace(partial, self.path)


def parse_arguments(argv: List[str]) -> List[str]:
    """Handles ``--help``; returns the other arguments (rqt's and Qt's options)."""
    parser = argparse.ArgumentParser(
        prog="rqt_robot_steering",
        description="A window with two sliders that publishes geometry_msgs/Twist: the "
                    "linear velocity (vertical) and the angular velocity (horizontal).",
        epilog="Private parameters: _default_topic:=/cmd_vel, _default_vx_max:=1.0, "
               "_default_vx_min:=-1.0, _default_vw_max:=3.0, _default_vw_min:=-3.0. "
               "Keys: W/S faster/slower, A/D left/right (Shift: by 0.1), X/Z zero, Space stop.")
    _, others = parser.parse_known_args(argv)
    return others


def master_online() -> bool:
    try:
        return rosgraph.Master("/rqt_robot_steering").is_online()
    except Exception:  # noqa: BLE001  (no ROS_MASTER_URI, a malformed one...)
        return False


def main(argv: Optional[List[str]] = None) -> int:
    argv = list(sys.argv if argv is None else argv)
    others = parse_arguments(rospy.myargv(argv)[1:])
    if not master_online():
        uri = os.environ.get("ROS_MASTER_URI", "(ROS_MASTER_URI is not set)")
        print(f"rqt_robot_steering: no ROS master at {uri}; start roscore (or a launch "
              "file) first, then run this again", file=sys.stderr)
        return 1

    # Qt first: a missing display ends here with Qt's own message, before the node exists
    from python_qt_binding.QtCore import QTimer
    from python_qt_binding.QtWidgets import QApplication

    from robot_steering.widget import SteeringWidget

    app = QApplication([argv[0], *others])
    rospy.init_node(f"rqt_gui_py_node_{os.getpid()}", argv=argv, disable_signals=True)
    if others:
        rospy.loginfo("options with no effect here (this is not rqt): %s", " ".join(others))
    _keep_running_on_errors()

    settings, warnings = read_settings(rospy.get_param)
    for warning in warnings:
        rospy.logwarn(warning)
    rospy.loginfo("publishing geometry_msgs/Twist on %s; linear %.2f .. %.2f m/s, "
                  "angular %.2f .. %.2f rad/s", settings.topic or "(no topic)",
                  settings.vx_min, settings.vx_max, settings.vw_min, settings.vw_max)

    widget = SteeringWidget(settings, TopicPublisher)
    state_path = os.environ.get(STATE_FILE_VARIABLE)
    if state_path:
        state_file = StateFile(state_path)
        widget.updated.connect(lambda: state_file.write(widget.state()))
    widget.show()

    for number in (signal.SIGINT, signal.SIGTERM):
        signal.signal(number, lambda *_: app.quit())
    watch = QTimer()  # also gives Python the chance to run the signal handlers
    watch.timeout.connect(lambda: rospy.is_shutdown() and app.quit())
    watch.start(SHUTDOWN_POLL_MS)

    try:
        app.exec_()
    finally:
        watch.stop()
        widget.shutdown()
        rospy.signal_shutdown("window closed")
    return 0


def _keep_running_on_errors() -> None:
    """PyQt5 aborts the process on an exception in a slot unless sys.excepthook is set:
    log it instead, and keep the window."""
    def log(kind, value, trace):
        rospy.logerr("".join(traceback.format_exception(kind, value, trace)))

    sys.excepthook = log

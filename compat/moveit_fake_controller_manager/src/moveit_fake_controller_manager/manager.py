"""``moveit_fake_controller_manager/MoveItFakeControllerManager``: execution without a
robot. Each controller of ``controller_list`` (``name``, ``joints``, ``type``: interpolate
(the default), via points or last point) "executes" its part of a trajectory by publishing
joint states on move_group's ``~fake_controller_joint_states`` (latched): interpolate
publishes the positions between the points at ``~fake_interpolating_controller_rate``
(10 Hz), via points each point at its time, last point the final point at once. A config
package's joint_state_publisher takes that topic as a source and publishes /joint_states.
``initial`` (a list of ``group`` and ``pose``, an SRDF group state) is published once at
start.

A controller runs in a thread of its own and can be cancelled; times follow ROS time
(simulated time when ``use_sim_time`` is set)."""
from __future__ import annotations

import threading
from dataclasses import dataclass
from typing import Dict, List, Optional, Sequence

import numpy as np
import rospy
from sensor_msgs.msg import JointState

PLUGIN = "moveit_fake_controller_manager/MoveItFakeControllerManager"
TYPES = ("interpolate", "via points", "last point")
DEFAULT_RATE = 10.0          # Hz, fake_interpolating_controller_rate's default


class ControllerConfigError(ValueError):
    """A controller_list entry that cannot be used; the message names it."""


@dataclass
class FakeController:
    name: str
    joints: List[str]
    kind: str = "interpolate"


class Run:
    """One controller executing one trajectory part."""

    def __init__(self, thread: threading.Thread, cancel: threading.Event):
        self.thread, self.cancel = thread, cancel
        self.succeeded = False

    def done(self) -> bool:
        return not self.thread.is_alive()

    def stop(self) -> None:
        self.cancel.set()


class FakeControllerManager:
    def __init__(self, entries: Sequence[dict], rate: float = DEFAULT_RATE,
                 publisher: Optional[rospy.Publisher] = None):
        self.controllers: Dict[str, FakeController] = {}
        for index, entry in enumerate(entries or []):
            if not isinstance(entry, dict) or not entry.get("name") or not entry.get("joints"):
                raise ControllerConfigError(f"controller_list entry {index + 1} needs a name "
                                            f"and joints: {entry}")
            kind = str(entry.get("type", "interpolate"))
            if kind not in TYPES:
                rospy.logwarn("fake controller '%s': type '%s' is not one of %s; interpolating",
                              entry["name"], kind, ", ".join(TYPES))
                kind = "interpolate"
            self.controllers[entry["name"]] = FakeController(
                str(entry["name"]), [str(j) for j in entry["joints"]], kind)
        self.rate = rate if rate > 0 else DEFAULT_RATE
        self.publisher = publisher or rospy.Publisher("~fake_controller_joint_states",
                                                      JointState, queue_size=100, latch=True)

    def publish(self, names: Sequence[str], positions: Sequence[float]) -> None:
        message = JointState(name=list(names), position=[float(p) for p in positions])
        message.header.stamp = rospy.Time.now()
        self.publisher.publish(message)

    def joints_of(self, name: str) -> List[str]:
        return self.controllers[name].joints

    def start(self, name: str, joints: Sequence[str], trajectory) -> Run:
        """Executes ``trajectory`` (a JointTrajectory of ``joints``) on controller ``name``."""
        controller = self.controllers[name]
        cancel = threading.Event()
        run = Run(None, cancel)

        def execute():
            run.succeeded = self._execute(controller, list(joints), trajectory, cancel)
        run.thread = threading.Thread(target=execute, name=f"fake_{name}", daemon=True)
        run.thread.start()
        return run

    def _execute(self, controller, joints, trajectory, cancel) -> bool:
        points = trajectory.points
        if not points:
            return True
        positions = np.array([p.positions for p in points], dtype=float)
        times = np.array([p.time_from_start.to_sec() for p in points])
        began = rospy.get_time()
        if controller.kind == "last point":
            self.publish(joints, positions[-1])
            return True
        if controller.kind == "via points":
            for t, q in zip(times, positions):
                if not self._wait_until(began + t, cancel):
                    return False
                self.publish(joints, q)
            return True
        period = 1.0 / self.rate
        clock = 0.0
        while clock < times[-1]:
            if not self._wait_until(began + clock, cancel):
                return False
            self.publish(joints, [np.interp(clock, times, positions[:, i])
                                  for i in range(len(joints))])
            clock += period
        if not self._wait_until(began + times[-1], cancel):
            return False
        self.publish(joints, positions[-1])
        return True

    @staticmethod
    def _wait_until(when: float, cancel: threading.Event) -> bool:
        """Sleeps in ROS time until ``when``; False when cancelled (or ROS shuts down)."""
        while rospy.get_time() < when:
            if cancel.is_set() or rospy.is_shutdown():
                return False
            rospy.sleep(min(0.01, max(0.0, when - rospy.get_time())))
        return not cancel.is_set()

"""The robot's current joint positions, from ``joint_states`` (MoveIt's
CurrentStateMonitor): the latest position of every joint any message named, and the stamp
of the message that brought it, so that a request can wait for a state newer than itself
(PlanningSceneMonitor::waitForCurrentRobotState, planning_scene_monitor.cpp:910-944 on
noetic-devel)."""
from __future__ import annotations

import math
import threading
from typing import Dict, Iterable

STATE_WAIT = 1.0     # s: waitForCurrentRobotState's default wait (planning_scene_monitor.h:394)


class CurrentState:
    """Thread-safe store of the latest joint positions; ``update`` takes a JointState."""

    def __init__(self, defaults: Dict[str, float]):
        self._positions = dict(defaults)
        self._stamps: Dict[str, float] = {}
        self._lock = threading.Condition()
        self.received = threading.Event()

    def update(self, message) -> None:
        if len(message.name) != len(message.position):
            return     # a malformed message (names without positions) changes nothing
        stamp = message.header.stamp.to_sec()
        with self._lock:
            for name, value in zip(message.name, message.position):
                if name in self._positions and math.isfinite(value):
                    self._positions[name] = float(value)
                    self._stamps[name] = stamp
            self._lock.notify_all()
        self.received.set()

    def wait_for(self, since: float, joints: Iterable[str], wait: float = STATE_WAIT) -> bool:
        """True once each of ``joints`` heard so far has been heard in a message stamped at
        or after ``since`` (s); False after ``wait`` s of waiting (CurrentStateMonitor::
        waitForCurrentState, current_state_monitor.cpp:272-292): the caller goes on with the
        state it has, as move_group does after its warning."""
        if since <= 0.0:
            return False       # an unset time: MoveIt's wait answers false at once (:912)
        with self._lock:
            return self._lock.wait_for(lambda: self._oldest(joints) >= since, timeout=wait)

    def _oldest(self, joints: Iterable[str]) -> float:
        """The oldest stamp among ``joints`` heard so far (those never heard do not count),
        0 when none was (CurrentStateMonitor::getCurrentStateTimeHelper, :95-114)."""
        heard = [self._stamps[j] for j in joints if j in self._stamps]
        return min(heard) if heard else 0.0

    def positions(self) -> Dict[str, float]:
        with self._lock:
            return dict(self._positions)

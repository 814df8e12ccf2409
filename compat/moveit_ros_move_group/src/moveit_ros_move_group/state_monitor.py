"""The robot's current joint positions, from ``joint_states`` (MoveIt's
CurrentStateMonitor): the latest position of every joint any message named."""
from __future__ import annotations

import threading
from typing import Dict

import math


class CurrentState:
    """Thread-safe store of the latest joint positions; ``update`` takes a JointState."""

    def __init__(self, defaults: Dict[str, float]):
        self._positions = dict(defaults)
        self._lock = threading.Lock()
        self.received = threading.Event()

    def update(self, message) -> None:
        if len(message.name) != len(message.position):
            return     # a malformed message (names without positions) changes nothing
        with self._lock:
            for name, value in zip(message.name, message.position):
                if name in self._positions and math.isfinite(value):
                    self._positions[name] = float(value)
        self.received.set()

    def positions(self) -> Dict[str, float]:
        with self._lock:
            return dict(self._positions)

"""A Bus without ROS: what plugins publish goes straight to what subscribed in the same
process. For scripts that drive a :class:`sim_bridge.world.World` directly (pictures,
experiments) with the same plugins and messages as the ROS node, but no master."""
from __future__ import annotations

from typing import Any, Callable, Dict, List

from sim_bridge.plugins.base import Bus


class _Publisher:
    def __init__(self, bus: "LocalBus", topic: str):
        self._bus, self._topic = bus, topic

    def publish(self, message: Any) -> None:
        self._bus.publish(self._topic, message)

    def unregister(self) -> None:
        pass

    shutdown = unregister


class LocalBus(Bus):
    """Topics as lists of callbacks; services, actions and transforms are ignored."""

    def __init__(self, params: Dict[str, Any] = None):
        self._subscribers: Dict[str, List[Callable[[Any], None]]] = {}
        self._params = dict(params or {})

    def publish(self, topic: str, message: Any) -> None:
        """Delivers ``message`` to every subscriber of ``topic`` (a resolved name)."""
        for callback in list(self._subscribers.get(topic, ())):
            callback(message)

    def publisher(self, topic, msg_class, queue_size=10, latch=False):
        return _Publisher(self, topic)

    def subscriber(self, topic, msg_class, callback):
        self._subscribers.setdefault(topic, []).append(callback)
        return _Publisher(self, topic)

    def service(self, name, srv_class, handler):
        return _Publisher(self, name)

    def action_server(self, name, action_class, on_goal, on_cancel):
        return _Publisher(self, name)

    def send_transforms(self, transforms) -> None:
        pass

    def get_param(self, name, default=None):
        return self._params.get(name, default)

    def info(self, text: str) -> None:
        print(text)

    def warn(self, text: str) -> None:
        print("warning:", text)

    def warn_throttled(self, key: str, period: float, text: str) -> None:
        self.warn(text)

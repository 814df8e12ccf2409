"""What every emulated ros_control controller is: built from its parameters (the dict under
``<namespace>/<name>`` on the parameter server), started, updated each control period with
simulated time, stopped, closed."""
from __future__ import annotations

from typing import Any, List, Mapping, Optional, Tuple

from sim_bridge.plugins.base import PluginError


class Controller:
    # the hardware interface its joints must have, or None (reads only)
    interface: Optional[str] = None

    def __init__(self, name: str, params: Mapping[str, Any], hardware, io):
        self.name = name
        self.params = params
        self.hardware = hardware
        self.io = io
        self.joints: List[str] = []

    # --- parameters ------------------------------------------------------------------------
    def required(self, key: str):
        if key not in self.params:
            raise PluginError(f"controller '{self.name}' needs parameter "
                              f"'{self.io.param_path(self.name, key)}'")
        return self.params[key]

    def number(self, key: str, default: float) -> float:
        value = self.params.get(key, default)
        try:
            return float(value)
        except (TypeError, ValueError):
            raise PluginError(f"controller '{self.name}': parameter '{key}' = {value!r} is not "
                              "a number") from None

    def claim(self, joints: List[str]) -> None:
        """Checks that the joints exist with this controller's interface, and keeps them."""
        for joint in joints:
            handle = self.hardware.joints.get(joint)
            if handle is None:
                raise PluginError(f"controller '{self.name}': joint '{joint}' has no "
                                  "transmission in the robot description")
            if self.interface is not None and handle.interface != self.interface:
                raise PluginError(f"controller '{self.name}' needs joint '{joint}' to have a "
                                  f"{self.interface.capitalize()}JointInterface; its "
                                  f"transmission gives {handle.interface.capitalize()}"
                                  "JointInterface")
        self.joints = list(joints)

    def claimed(self) -> List[Tuple[str, List[str]]]:
        """(interface, joints) for each hardware interface it commands joints through, as
        list_controllers reports them; one, or none for a controller that only reads."""
        return [(self.interface, list(self.joints))] if self.interface else []

    # --- life cycle -------------------------------------------------------------------------
    def start(self, now_ns: int) -> None:
        pass

    def stop(self, now_ns: int) -> None:
        pass

    def update(self, now_ns: int, dt: float) -> None:
        pass

    def close(self) -> None:
        pass

"""A PID loop with ros_control's gain names (p, i, d, i_clamp / i_clamp_min / i_clamp_max)."""
from __future__ import annotations

from typing import Mapping

from sim_bridge.plugins.base import PluginError


class Pid:
    def __init__(self, gains: Mapping, where: str):
        if not isinstance(gains, Mapping) or "p" not in gains:
            raise PluginError(f"{where} needs PID gains (at least p) on the parameter server")
        try:
            self.p = float(gains.get("p", 0.0))
            self.i = float(gains.get("i", 0.0))
            self.d = float(gains.get("d", 0.0))
            clamp = float(gains.get("i_clamp", 0.0))
            self.i_min = float(gains.get("i_clamp_min", -clamp))
            self.i_max = float(gains.get("i_clamp_max", clamp))
        except (TypeError, ValueError):
            raise PluginError(f"{where}: PID gains must be numbers, got {dict(gains)}") from None
        self.integral = 0.0

    def reset(self) -> None:
        self.integral = 0.0

    def command(self, error: float, error_rate: float, dt: float) -> float:
        self.integral = min(max(self.integral + self.i * error * dt, self.i_min), self.i_max)
        return self.p * error + self.integral + self.d * error_rate

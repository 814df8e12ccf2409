"""control_toolbox's Pid (noetic-devel de05a5c src/pid.cpp), the PID of ros_control's
``pid``, ``gains/<joint>`` namespaces.

Gains as Pid::init reads them (pid.cpp:106-155): ``p`` required ("No p gain specified for
pid"); ``i``, ``d`` 0; ``i_clamp`` 0 gives i_max = |i_clamp|, i_min = -|i_clamp|;
``i_clamp_min`` / ``i_clamp_max`` override them with their signs forced; ``antiwindup``
false. A value of another type takes its default, as roscpp's ``param`` does (an int is a
double; ``antiwindup`` must be a bool). ``publish_state`` is not read.

The command as Pid::computeCommand computes it (pid.cpp:331-394): the integral of the error
grows without bound and only the i-term is clamped to [i_min, i_max]; with ``antiwindup``
the integral itself is clamped to [i_min/i, i_max/i]. A NaN or infinite error (or error
rate) or a zero period gives 0. :meth:`compute` is computeCommand(error, dt), the derivative
from the error's difference (pid.cpp:305-324); :meth:`command` takes it given.
"""
from __future__ import annotations

import math
from typing import Mapping

from sim_bridge.plugins.base import PluginError


def _number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


class Pid:
    def __init__(self, gains: Mapping, where: str):
        if not isinstance(gains, Mapping) or not _number(gains.get("p")):  # pid.cpp:113-119
            raise PluginError(f"{where}: No p gain specified for pid (a number under 'p' is "
                              "required; i, d, i_clamp are optional)")

        def param(key, default):  # nh.param(key, value, default)
            value = gains.get(key, default)
            return float(value) if _number(value) else default

        self.p = float(gains["p"])
        self.i = param("i", 0.0)  # pid.cpp:121-122
        self.d = param("d", 0.0)
        clamp = param("i_clamp", 0.0)  # pid.cpp:125-128
        self.i_max, self.i_min = abs(clamp), -abs(clamp)
        if "i_clamp_min" in gains:  # pid.cpp:129-133
            self.i_min = -abs(param("i_clamp_min", self.i_min))
        if "i_clamp_max" in gains:  # pid.cpp:134-138
            self.i_max = abs(param("i_clamp_max", self.i_max))
        antiwindup = gains.get("antiwindup", False)  # pid.cpp:139
        self.antiwindup = antiwindup if isinstance(antiwindup, bool) else False
        self.reset()

    def reset(self) -> None:
        """Pid::reset (pid.cpp:197-211): the last error counts as 0 for the next derivative."""
        self.p_error_last = 0.0
        self.i_error = 0.0
        self.d_error = 0.0
        self.valid_p_error_last = True

    def compute(self, error: float, dt: float) -> float:
        """computeCommand(error, dt) (pid.cpp:305-324)."""
        if dt == 0 or not math.isfinite(error):
            return 0.0
        error_dot = self.d_error
        if dt > 0:
            if self.valid_p_error_last:
                error_dot = (error - self.p_error_last) / dt
            self.p_error_last = error
            self.valid_p_error_last = True
        return self.command(error, error_dot, dt)

    def command(self, error: float, error_dot: float, dt: float) -> float:
        """computeCommand(error, error_dot, dt) (pid.cpp:331-394)."""
        self.d_error = error_dot
        if dt == 0 or not (math.isfinite(error) and math.isfinite(error_dot)):
            return 0.0
        self.i_error += dt * error
        if self.antiwindup and self.i != 0:  # pid.cpp:349-354
            low, high = sorted((self.i_min / self.i, self.i_max / self.i))
            self.i_error = min(max(self.i_error, low), high)
        i_term = self.i * self.i_error
        if not self.antiwindup:  # pid.cpp:359-363
            i_term = min(max(i_term, self.i_min), self.i_max)
        return self.p * error + i_term + self.d * error_dot

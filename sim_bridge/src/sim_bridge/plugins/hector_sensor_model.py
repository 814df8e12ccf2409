"""hector_gazebo_plugins' error model and update timer, shared by its IMU and GPS.

**Error model** (hector's ``SensorModel``), per axis, its parameters named ``<prefix>Offset``,
``<prefix>Drift``, ``<prefix>DriftFrequency``, ``<prefix>GaussianNoise``,
``<prefix>ScaleError`` (``offset``, ``drift``... when the prefix is empty); three numbers
each for a vector model, one for a scalar one. Defaults: offset 0, drift 0, drift
frequency 1/3600 Hz (a time constant of an hour), Gaussian noise 0, scale error 1.

- a reading is ``value * scaleError + error``, where ``error = offset + drift_now + n``,
  ``n`` Gaussian with the noise's standard deviation, drawn anew each update;
- ``drift_now`` starts (at load and at every reset) as a Gaussian draw with standard
  deviation ``drift``, and each update of ``dt`` seconds becomes
  ``exp(-dt f) drift_now + dt w``, ``w`` Gaussian with standard deviation
  ``sqrt(2 f) drift`` (hector's discretisation, scaled by dt as hector does, not by
  sqrt(dt));
- the *bias* is ``offset + drift_now`` (hector's ``getCurrentBias``).

This is hector's model itself, not a simplification; the random numbers come from the
model's generator (``context.rng``, seeded from the world's seed), so a seed repeats a run.
hector's dynamic_reconfigure servers for these parameters are not offered.

**Update timer** (hector's ``UpdateTimer``, hector_gazebo melodic-devel de947fb
hector_gazebo_plugins/include/hector_gazebo_plugins/update_timer.h): ``updateRate`` (Hz,
:56-60) or ``updatePeriod`` (it wins, :62-71), and ``updateOffset`` (:73-82). The last two
are read as Gazebo 9+ reads them, through ``sdf::Time``: two whole numbers, seconds and
nanoseconds (sdformat sdf9 include/sdf/Types.hh:185-191), so ``0 250000000`` is 0.25 s and
``0.25`` is 0 s (the seconds stop at the dot, the nanoseconds are not read): an update at
every step, as in Gazebo (a warning says so). A period of 0 runs every step; otherwise an
update falls on the steps at ``updateOffset + k period`` of simulated time (within half a
step, :141-156), not at a period after the previous one. ``dt`` is the time since the
previous update, 0 for the first after loading or a reset (:132-139).
"""
from __future__ import annotations

import math
import re
from typing import Optional, Union

import numpy as np

from sim_bridge.plugins.base import Plugin, PluginError
from sim_bridge.plugins.body_state import vector3

DEFAULT_DRIFT_FREQUENCY = 1.0 / 3600.0


class SensorModel:
    """hector's SensorModel for a vector (``size`` 3) or a scalar (``size`` 1)."""

    def __init__(self, plugin: Plugin, prefix: str, size: int):
        self.rng = plugin.context.rng
        self.size = size

        def name(suffix: str) -> str:
            return prefix + suffix if prefix else suffix[0].lower() + suffix[1:]

        def read(suffix: str, default: float) -> np.ndarray:
            tag = name(suffix)
            if size == 3:
                return vector3(plugin, tag, (default,) * 3)
            return np.array([plugin.number(tag, default)])

        self.offset = read("Offset", 0.0)
        self.drift = read("Drift", 0.0)
        self.drift_frequency = read("DriftFrequency", DEFAULT_DRIFT_FREQUENCY)
        self.gaussian_noise = read("GaussianNoise", 0.0)
        self.scale_error = read("ScaleError", 1.0)
        if np.any(self.drift_frequency < 0):
            raise PluginError(f"plugin '{plugin.spec.name}' ({plugin.spec.filename}): "
                              f"<{name('DriftFrequency')}> must not be negative")
        self.current_drift = np.zeros(size)
        self.current_error = np.zeros(size)
        self.reset()

    def _gauss(self, sigma: np.ndarray) -> np.ndarray:
        if not np.any(sigma):
            return np.zeros(self.size)  # no draw: other plugins' numbers stay as they were
        return self.rng.normal(0.0, np.abs(sigma))

    def reset(self, value: Optional[Union[float, np.ndarray]] = None) -> None:
        """A new drift drawn (hector's ``reset()``), or set to ``value`` (``reset(value)``)."""
        if value is None:
            self.current_drift = self._gauss(self.drift)
        else:
            self.current_drift = np.broadcast_to(np.asarray(value, float), (self.size,)).copy()
        self.current_error = np.zeros(self.size)

    def update(self, dt: float) -> np.ndarray:
        self.current_drift = (np.exp(-dt * self.drift_frequency) * self.current_drift
                              + dt * self._gauss(np.sqrt(2.0 * self.drift_frequency) * self.drift))
        self.current_error = self.offset + self.current_drift + self._gauss(self.gaussian_noise)
        return self.current_error

    def __call__(self, value: np.ndarray, dt: float) -> np.ndarray:
        return np.asarray(value, float) * self.scale_error + self.update(dt)

    @property
    def bias(self) -> np.ndarray:
        return self.current_drift + self.offset


_WHOLE = re.compile(r"\s*([+-]?\d+)")


def sdf_time(text: str) -> float:
    """Seconds of an ``sdf::Time`` read from ``text`` as ``_in >> sec >> nsec`` reads it
    (sdformat sdf9 include/sdf/Types.hh:185-191): each a whole number; where one cannot be
    read it and what follows stay 0."""
    seconds = _WHOLE.match(text)
    if seconds is None:
        return 0.0
    nanoseconds = _WHOLE.match(text, seconds.end())
    return int(seconds.group(1)) + (int(nanoseconds.group(1)) * 1e-9 if nanoseconds else 0.0)


class UpdateTimer:
    """hector's UpdateTimer (see the module's notes)."""

    def __init__(self, plugin: Plugin, default_rate: float = 0.0):
        rate = plugin.number("updateRate", default_rate)
        self.period = 1.0 / rate if rate > 0 else 0.0
        if plugin.spec.text("updatePeriod") is not None:
            self.period = max(self._time(plugin, "updatePeriod"), 0.0)
        self.offset = 0.0
        if plugin.spec.text("updateOffset") is not None:
            self.offset = self._time(plugin, "updateOffset")
        self.step = plugin.context.step_size
        self._last_ns: Optional[int] = None
        self._previous_step_ns: Optional[int] = None

    @staticmethod
    def _time(plugin: Plugin, tag: str) -> float:
        """``<tag>`` as the sdf::Time hector reads (update_timer.h:62-82), with a warning
        when the text is not two whole numbers, seconds and nanoseconds."""
        text = plugin.spec.text(tag) or ""
        value = sdf_time(text)
        if not re.fullmatch(r"\s*[+-]?\d+(\s+[+-]?\d+)?\s*", text):
            plugin.context.bus.warn(
                f"model '{plugin.context.model_name}': plugin '{plugin.spec.name}' "
                f"({plugin.spec.filename}): <{tag}> '{text}' is read as Gazebo reads it, an "
                f"sdf::Time of whole seconds and nanoseconds: {value:g} s"
                + (" (an update at every step)" if tag == "updatePeriod" and value == 0 else "")
                + "; write '<seconds> <nanoseconds>' (0 250000000 is 0.25 s) or <updateRate>")
        return value

    def due(self, now_ns: int) -> bool:
        if self._previous_step_ns is not None and now_ns > self._previous_step_ns:
            self.step = (now_ns - self._previous_step_ns) / 1e9  # the step size may change
        self._previous_step_ns = now_ns
        if self.period == 0:
            return True
        fraction = math.fmod(now_ns / 1e9 - self.offset + self.step / 2.0, self.period)
        return 0.0 <= fraction < self.step

    def elapsed(self, now_ns: int) -> float:
        """Seconds since the last update (0 before the first), and marks this one."""
        dt = 0.0 if self._last_ns is None else (now_ns - self._last_ns) / 1e9
        self._last_ns = now_ns
        return dt

    def reset(self) -> None:
        self._last_ns = None

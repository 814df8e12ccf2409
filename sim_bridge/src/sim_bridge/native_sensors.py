"""A robot's sensors as Gazebo's C++ sensors read them (compat/gazebo_dev's ContactSensor,
RaySensor and ImuSensor, found through SensorManager or sensors::get_sensor), for the
backend of :mod:`sim_bridge.native_plugins`.

Every ``<sensor>`` of a robot's ``<gazebo reference>`` blocks is one, with or without a
plugin of its own: a robot's C++ plugin reads plugin-less sensors, as Kobuki's reads its
bumpers, cliff rays and gyro. Each is measured by the code of the sensor plugin sim_bridge
emulates for it, without its ROS side: contacts as ``libgazebo_ros_bumper.so``'s
(:mod:`sim_bridge.plugins.bumper`: scoped collision names, world axes, the normal pointing
at the sensor's collision), ranges as ``libgazebo_ros_laser.so``'s
(:mod:`sim_bridge.plugins.laser`: one horizontal plane, +inf where nothing is hit, the
sensor's noise), the IMU as ``libgazebo_ros_imu_sensor.so``'s (:mod:`sim_bridge.plugins.imu`:
rate and specific force in the sensor's axes, its orientation in the world's, which the C++
side makes relative to the orientation at load, as Gazebo's ImuSensor).

A sensor measures when a plugin asks, once per step (a second reading within the step is
the first); Gazebo's refresh at their ``<update_rate>``. The IMU's acceleration is the
change of velocity between two such readings. A sensor whose description the emulated
plugin would refuse is named in one warning and left out (its plugin then finds no sensor
of that name, as under Gazebo a sensor that failed to load)."""
from __future__ import annotations

import dataclasses
from typing import TYPE_CHECKING, Dict, List, Optional, Tuple

from sim_bridge.gazebo_tags import PluginSpec
from sim_bridge.plugins.base import Bus, PluginError
from sim_bridge.plugins.bumper import Bumper
from sim_bridge.plugins.imu import ImuSensor
from sim_bridge.plugins.laser import Laser

if TYPE_CHECKING:
    from sim_bridge.world import World

# the emulated plugin whose measurement each sensor type takes
READERS = {"contact": Bumper, "ray": Laser, "gpu_ray": Laser, "imu": ImuSensor}


class _Dropped:
    """A publisher nobody hears."""

    def publish(self, _message) -> None:
        pass


class _QuietBus(Bus):
    """The sensors' bus: no ROS side; the world's warnings."""

    def __init__(self, bus: Bus):
        self.bus = bus

    def publisher(self, topic, msg_class, queue_size=10, latch=False):
        return _Dropped()

    def listened(self, publisher=None) -> bool:
        return False

    def info(self, text: str) -> None:
        self.bus.debug(text)

    def warn(self, text: str) -> None:
        self.bus.warn(text)

    def warn_throttled(self, key: str, period: float, text: str) -> None:
        self.bus.warn_throttled(key, period, text)

    def debug(self, text: str) -> None:
        self.bus.debug(text)


@dataclasses.dataclass
class SensorReader:
    name: str
    type: str
    link: str  # Gazebo's link (after lumping)
    update_rate: float
    always_on: bool
    reader: object  # the emulated plugin that measures
    measured_ns: int = -1
    value: object = None


class NativeSensors:
    """The sensors of the world's robots, made when a model's C++ plugins first ask."""

    def __init__(self, world: "World"):
        self.world = world
        self._models: Dict[str, Dict[str, SensorReader]] = {}

    def of(self, model_name: str) -> Dict[str, SensorReader]:
        made = self._models.get(model_name)
        if made is None:
            made = self._models[model_name] = self._make(model_name)
        return made

    def forget(self, model_name: str) -> None:
        self._models.pop(model_name, None)

    def _make(self, model_name: str) -> Dict[str, SensorReader]:
        model = self.world.model(model_name)
        if model.tags is None or model.context is None:
            return {}
        context = dataclasses.replace(model.context, bus=_QuietBus(self.world.bus))
        readers: Dict[str, SensorReader] = {}
        for sensor in model.tags.sensors:
            kind = READERS.get(sensor.type)
            link = model.structure.body_of.get(sensor.link, sensor.link)
            if kind is None:  # named, and reads nothing
                readers[sensor.name] = SensorReader(sensor.name, sensor.type, link,
                                                    _update_rate(sensor), _always_on(sensor),
                                                    None)
                continue
            # the IMU plugin's frame is its messages' only; the laser's topic never opened
            spec = PluginSpec(sensor.name, "", {"frameName": sensor.link}, sensor.element)
            try:
                reader = kind(context, spec, sensor)
            except PluginError as error:
                self.world.bus.warn(f"model '{model_name}': sensor '{sensor.name}' cannot be "
                                    f"read by Gazebo C++ plugins: {error}")
                continue
            readers[sensor.name] = SensorReader(sensor.name, sensor.type, link,
                                                _update_rate(sensor), _always_on(sensor), reader)
        return readers

    def _measured(self, model_name: str, sensor: str, measure):
        reader = self.of(model_name)[sensor]
        now = self.world.now_ns
        if reader.measured_ns != now:
            reader.value = measure(reader.reader, now)
            reader.measured_ns = now
        return reader.value

    def contacts(self, model_name: str, sensor: str) -> List[Tuple]:
        """(collision1, collision2, positions, normals, depths, forces, torques), the
        vectors flat."""
        def measure(bumper: Bumper, _now: int):
            found = []
            for state in bumper.contacts():
                found.append((state.collision1_name, state.collision2_name,
                              _flat(state.contact_positions), _flat(state.contact_normals),
                              list(state.depths), _flat([w.force for w in state.wrenches]),
                              _flat([w.torque for w in state.wrenches])))
            return found
        return self._measured(model_name, sensor, measure)

    def ranges(self, model_name: str, sensor: str) -> List[float]:
        return self._measured(model_name, sensor,
                              lambda laser, _now: laser.measure().tolist())

    def imu(self, model_name: str, sensor: str) -> List[float]:
        """[wx wy wz ax ay az qx qy qz qw]."""
        def measure(imu: ImuSensor, now: int):
            # the emulated plugin's own update (its publishing side is not used)
            imu._measure(now)
            _, orientation, specific_force, body_rate = imu._measured
            return [*map(float, body_rate), *map(float, specific_force),
                    *map(float, orientation)]
        return self._measured(model_name, sensor, measure)


def _flat(vectors) -> List[float]:
    return [value for v in vectors for value in (v.x, v.y, v.z)]


def _always_on(sensor) -> bool:
    """sdformat's bool: true or 1 (false when absent)."""
    return (sensor.element.findtext("always_on") or "").strip().lower() in ("true", "1")


def _update_rate(sensor) -> float:
    try:
        return float((sensor.element.findtext("update_rate") or "0").strip())
    except ValueError:
        return 0.0

"""``libhector_gazebo_ros_gps.so``: hector_gazebo_plugins' GNSS receiver, a model plugin:
a link's world position as sensor_msgs/NavSatFix and its velocity as
geometry_msgs/Vector3Stamped, through hector's error model (hector_sensor_model.py).

Parameters as hector_gazebo_plugins (melodic-devel) reads them:

| parameter | default (error models: three numbers each, m and m/s) |
|---|---|
| bodyName | the model's canonical link (its URDF root) |
| frameId | ``/world`` (both messages' header) |
| topicName, velocityTopicName | ``fix``, ``fix_velocity`` |
| referenceLatitude, referenceLongitude | 49.9, 8.9 (degrees) |
| referenceHeading | 0 (degrees, clockwise from north: the world's x axis is its direction) |
| referenceAltitude | 0 (m) |
| status, service | 0 (STATUS_FIX), 0 (no service bits) |
| offset, drift, driftFrequency, gaussianNoise, scaleError | position error: 0, 0, 1/3600, 0, 1 |
| velocityOffset, velocityDrift, velocityDriftFrequency... | velocity error, the same defaults |
| updateRate, updatePeriod, updateOffset | 4 Hz, aligned to multiples of the period |
| robotNamespace | |

Geodesy, hector's flat earth around the reference (WGS84: a = 6378137 m,
f = 1/298.257223563, e² = 2f - f²), with φ0 the reference latitude and ψ the heading:

    R_N = a (1 - e²) / (1 - e² sin² φ0)^(3/2)      (meridian radius)
    R_E = a cos φ0 / (1 - e² sin² φ0)^(1/2)        (radius of the parallel)
    latitude  = φ0 + ( cos ψ x + sin ψ y) / R_N        (degrees)
    longitude = λ0 - (-sin ψ x + cos ψ y) / R_E        (degrees)
    altitude  = h0 + z

so with heading 0 the world's x points north and y west. The velocity is turned the same
way: (cos ψ vx + sin ψ vy, -sin ψ vx + cos ψ vy, vz). x, y, z and v are the link frame's
origin after the error model; the velocity error's drift is integrated into the position
error's drift (hector's "offset in velocity integrates into position"). Covariance:
DIAGONAL_KNOWN, drift² + gaussianNoise² per axis.

Not emulated: useWorldSphericalCoordinates (the world's ``<spherical_coordinates>``; a
warning, and the reference parameters are used), the ``<topicName>/set_reference_geopose``
service (hector_gazebo_plugins/SetReferenceGeoPose) and the dynamic_reconfigure servers.
"""
from __future__ import annotations

import math

from geometry_msgs.msg import Vector3Stamped
from sensor_msgs.msg import NavSatFix

from sim_bridge.plugins.base import Plugin, PluginError, stamp
from sim_bridge.plugins.body_state import body_link, link_state
from sim_bridge.plugins.hector_sensor_model import SensorModel, UpdateTimer

EQUATORIAL_RADIUS = 6378137.0
FLATTENING = 1.0 / 298.257223563
ECCENTRICITY2 = 2 * FLATTENING - FLATTENING * FLATTENING
DEFAULT_LATITUDE, DEFAULT_LONGITUDE = 49.9, 8.9
DEFAULT_UPDATE_RATE = 4.0


def earth_radii(latitude_degrees: float):
    """(north, east) radii in metres at a latitude, as hector computes them."""
    s = math.sin(math.radians(latitude_degrees))
    temp = 1.0 / (1.0 - ECCENTRICITY2 * s * s)
    prime_vertical = EQUATORIAL_RADIUS * math.sqrt(temp)
    return (prime_vertical * (1 - ECCENTRICITY2) * temp,
            prime_vertical * math.cos(math.radians(latitude_degrees)))


class HectorGps(Plugin):
    def __init__(self, context, spec):
        super().__init__(context, spec)
        self.body = body_link(self, "bodyName", context.robot.model.root())
        self.frame_id = self.param("frameId", "/world")
        fix_topic = self.param("topicName", "fix")
        velocity_topic = self.param("velocityTopicName", "fix_velocity")
        for tag, value in (("topicName", fix_topic), ("velocityTopicName", velocity_topic)):
            if not value:
                raise PluginError(f"plugin '{spec.name}' ({spec.filename}): <{tag}> is empty; "
                                  "name a topic or leave the tag out")
        self.latitude = self.number("referenceLatitude", DEFAULT_LATITUDE)
        self.longitude = self.number("referenceLongitude", DEFAULT_LONGITUDE)
        self.heading = math.radians(self.number("referenceHeading", 0.0))
        self.altitude = self.number("referenceAltitude", 0.0)
        if not -90.0 < self.latitude < 90.0:
            raise PluginError(f"plugin '{spec.name}': <referenceLatitude> {self.latitude} is "
                              "not strictly between -90 and 90 degrees")
        if self.flag("useWorldSphericalCoordinates", False):
            context.bus.warn(f"model '{context.model_name}': plugin '{spec.name}' "
                             f"({spec.filename}): useWorldSphericalCoordinates is not emulated "
                             "(sim_bridge reads no <spherical_coordinates>); the plugin's "
                             "reference latitude, longitude, heading and altitude are used")
        self.status = self._integer("status", 0, -128, 127)
        self.service = self._integer("service", 0, 0, 65535)
        self.position_model = SensorModel(self, "", 3)
        self.velocity_model = SensorModel(self, "velocity", 3)
        self.radius_north, self.radius_east = earth_radii(self.latitude)
        self.timer = UpdateTimer(self, DEFAULT_UPDATE_RATE)
        self.fix_output = context.bus.publisher(self.topic(fix_topic), NavSatFix, queue_size=10)
        self.velocity_output = context.bus.publisher(self.topic(velocity_topic), Vector3Stamped,
                                                     queue_size=10)

    def _integer(self, tag: str, default: int, low: int, high: int) -> int:
        value = self.number(tag, default)
        if value != int(value) or not low <= value <= high:
            return self.unreadable(tag, f"{value:g}", f"a whole number from {low} to {high}",
                                   default)
        return int(value)

    def after_step(self, now_ns: int) -> None:
        if not self.timer.due(now_ns):
            return
        dt = self.timer.elapsed(now_ns)
        true_position, _, true_velocity, _ = link_state(self.context, self.body)
        velocity = self.velocity_model(true_velocity, dt)
        x, y, z = self.position_model(true_position, dt)
        self.position_model.current_drift = (self.position_model.current_drift
                                             + dt * self.velocity_model.current_drift)
        c, s = math.cos(self.heading), math.sin(self.heading)
        fix = NavSatFix()
        fix.header.stamp = stamp(now_ns)
        fix.header.frame_id = self.frame_id
        fix.status.status = self.status
        fix.status.service = self.service
        fix.latitude = self.latitude + math.degrees((c * x + s * y) / self.radius_north)
        fix.longitude = self.longitude - math.degrees((-s * x + c * y) / self.radius_east)
        fix.altitude = self.altitude + float(z)
        variance = self.position_model.drift ** 2 + self.position_model.gaussian_noise ** 2
        fix.position_covariance = [float(variance[0]), 0.0, 0.0, 0.0, float(variance[1]), 0.0,
                                   0.0, 0.0, float(variance[2])]
        fix.position_covariance_type = NavSatFix.COVARIANCE_TYPE_DIAGONAL_KNOWN
        moving = Vector3Stamped()
        moving.header = fix.header
        moving.vector.x = float(c * velocity[0] + s * velocity[1])
        moving.vector.y = float(-s * velocity[0] + c * velocity[1])
        moving.vector.z = float(velocity[2])
        self.fix_output.publish(fix)
        self.velocity_output.publish(moving)

    def reset(self, now_ns: int) -> None:
        self.timer.reset()
        self.position_model.reset()
        self.velocity_model.reset()

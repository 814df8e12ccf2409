"""What the model plugins that sense one link share (``libgazebo_ros_imu.so``,
``libhector_gazebo_ros_imu.so``, ``libhector_gazebo_ros_gps.so``): finding the link their
``<bodyName>`` names, reading its frame's world state, three-number parameters, and
quaternion arithmetic in ROS's (x, y, z, w) order.

A link on a fixed joint (an ``imu_link`` under ``base_link``) is a link of its own in
pybullet (sim_bridge loads URDFs without merging fixed links), so its frame's pose and
motion are read directly: where the sensor is and how it moves, lever arm included.
"""
from __future__ import annotations

import math
from typing import Optional, Sequence, Tuple

import numpy as np
import pybullet as pb

from sim_bridge.plugins.base import Plugin, PluginError

Quat = Tuple[float, float, float, float]
IDENTITY: Quat = (0.0, 0.0, 0.0, 1.0)


def body_link(plugin: Plugin, tag: str = "bodyName", default: Optional[str] = None) -> str:
    """The link ``<tag>`` names (``default`` when absent; required when that is None).

    Accepts ``model::link`` with this model's name, as Gazebo's scoped names."""
    spec, context = plugin.spec, plugin.context
    name = spec.text(tag)
    if name is None:
        name = default
    if not name:
        raise PluginError(f"plugin '{spec.name}' ({spec.filename}) needs <{tag}>, the name of "
                          f"a link of model '{context.model_name}'")
    links = context.robot.link_index
    model, _, plain = name.rpartition("::")
    if name not in links and model == context.model_name and plain in links:
        name = plain
    if name not in links:
        raise PluginError(f"plugin '{spec.name}' ({spec.filename}): <{tag}> names link "
                          f"'{name}', which model '{context.model_name}' does not have "
                          f"(its links: {', '.join(sorted(links))})")
    return name


def link_state(context, link: str) -> Tuple[np.ndarray, Quat, np.ndarray, np.ndarray]:
    """(position, orientation, velocity of the frame's origin, angular velocity) of a URDF
    link's frame, world axes (pybullet reports its centre of mass's velocity)."""
    robot = context.robot
    index = robot.link_index[link]
    if index == -1:
        position, orientation = robot.base_pose()
        linear, angular = robot.base_twist()
        return np.asarray(position, float), tuple(orientation), linear, angular
    state = pb.getLinkState(robot.id, index, computeLinkVelocity=1, computeForwardKinematics=1,
                            physicsClientId=context.client)
    (cx, cy, cz), frame, (vx, vy, vz), angular = state[0], state[4], state[6], state[7]
    wx, wy, wz = angular
    rx, ry, rz = frame[0] - cx, frame[1] - cy, frame[2] - cz  # from the centre of mass
    # v + w x r, written out: np.cross costs tens of microseconds, every step
    linear = np.array((vx + wy * rz - wz * ry, vy + wz * rx - wx * rz, vz + wx * ry - wy * rx))
    return np.array(frame, float), tuple(state[5]), linear, np.array(angular, float)


def vector3(plugin: Plugin, tag: str, default: Sequence[float] = (0.0, 0.0, 0.0)) -> np.ndarray:
    """A parameter of three numbers (``x y z``, or ``roll pitch yaw``)."""
    text = plugin.spec.text(tag)
    if text is None or text == "":
        return np.asarray(default, dtype=float)
    try:
        values = [float(v) for v in text.split()]
    except ValueError:
        values = []
    if len(values) != 3 or not all(math.isfinite(v) for v in values):
        values = plugin.unreadable(tag, text, "three numbers (x y z)", tuple(default))
    return np.asarray(values, dtype=float)


# --- quaternions, (x, y, z, w) -----------------------------------------------------------
def q_multiply(a: Sequence[float], b: Sequence[float]) -> Quat:
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz)


def q_inverse(q: Sequence[float]) -> Quat:
    x, y, z, w = q
    norm2 = x * x + y * y + z * z + w * w
    return (-x / norm2, -y / norm2, -z / norm2, w / norm2)


def q_normalized(q: Sequence[float]) -> Quat:
    norm = math.sqrt(sum(c * c for c in q))
    if norm == 0.0 or not math.isfinite(norm):
        return IDENTITY
    return tuple(float(c) / norm for c in q)  # type: ignore[return-value]


def q_from_wxyz(w: float, x: float, y: float, z: float) -> Quat:
    return (x, y, z, w)


def to_sensor(q: Sequence[float], v: Sequence[float]) -> Tuple[float, float, float]:
    """``R(q)ᵀ v`` for a unit quaternion (x, y, z, w): a world vector in the sensor's axes.
    Written out in floats: numpy's 4x4 matrix and product cost 10 us of gazebo_ros_imu's 23
    a message (it runs every step at updateRate 0, TurtleBot3's)."""
    x, y, z, w = q
    vx, vy, vz = (float(c) for c in v)
    xx, yy, zz = x * x, y * y, z * z
    xy, xz, yz, xw, yw, zw = x * y, x * z, y * z, x * w, y * w, z * w
    return ((1.0 - 2.0 * (yy + zz)) * vx + 2.0 * (xy + zw) * vy + 2.0 * (xz - yw) * vz,
            2.0 * (xy - zw) * vx + (1.0 - 2.0 * (xx + zz)) * vy + 2.0 * (yz + xw) * vz,
            2.0 * (xz + yw) * vx + 2.0 * (yz - xw) * vy + (1.0 - 2.0 * (xx + yy)) * vz)

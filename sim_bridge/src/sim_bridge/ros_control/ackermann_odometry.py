"""ackermann_steering_controller's odometry, as ros_controllers noetic-devel (678b92a)
computes it: ``ackermann_steering_controller/src/odometry.cpp`` ("odometry.cpp" below).
Pure maths: no pybullet, no ROS.

It is diff_drive_controller's odometry with one rear wheel and a steering angle in place of
the two sides: the same time keeping, rolling means, exact-arc integration and open loop
(odometry.cpp:49-71, :112-171 do what diff_drive_controller's odometry.cpp:48-72, :112-172
do), so those are :class:`~sim_bridge.ros_control.diff_drive_odometry.Odometry`'s,
shared. What differs is :meth:`AckermannOdometry.update`: the bicycle model.
"""
from __future__ import annotations

import math

from sim_bridge.ros_control.diff_drive_odometry import Odometry


class AckermannOdometry(Odometry):
    """odometry.cpp's Odometry: its pose and the rear wheel's previous position start at 0
    when it is made, and :meth:`init` keeps them (odometry.cpp:49-71)."""

    def __init__(self, window: int):
        super().__init__(window)
        self.separation_h = self.radius = 0.0
        self._rear_old = 0.0

    def set_wheel_params(self, separation_h: float, radius: float) -> None:
        """setWheelParams (odometry.cpp:124-128): the distance between the rear axle and the
        steering joint, and the rear wheel's radius (both with their multipliers)."""
        self.separation_h, self.radius = separation_h, radius

    def update(self, rear_wheel_position: float, steer_position: float, now_ns: int) -> bool:
        """odometry.cpp:73-110: the rear wheel's travel since the last update (its position,
        rad, times the radius) is the step forward; the turn is that step times
        tan(steering angle) over the separation, the bicycle model. Integrated first; a
        velocity estimate only when at least 0.1 ms has passed."""
        rear = rear_wheel_position * self.radius
        linear = rear - self._rear_old
        self._rear_old = rear
        angular = math.tan(steer_position) * linear / self.separation_h
        return self._advance(linear, angular, now_ns)

"""The ``/rotate_robot`` service: turn the RB1 in place by a number of degrees.

Closed loop on ``odom`` (yaw accumulated, so full turns count), publishing ``cmd_vel``;
the speed falls near the goal; after stopping, the robot settles and the error is checked
again, so it ends within the tolerance. The robot is stopped on success, on every failure,
and when the node shuts down. Settings are private parameters (config/rotate_service.yaml).

Answers: ``success: rotated -90 degrees (final error 0.3 degrees)``, or ``failure: ...``
for: no odometry within ``~odom_timeout``; a robot that does not turn while commanded
(blocked); a rotation that outlasts its time (scaled to the angle); a request while
another runs (rejected; the first one goes on); more than ``~max_degrees``.
"""
from __future__ import annotations

import math
import threading
import time
from dataclasses import dataclass

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry

from my_rb1_ros.rotation import RotationGains, YawAccumulator, angular_speed, time_allowed
from my_rb1_ros.srv import Rotate, RotateResponse


@dataclass
class Config:
    """Private parameters, read once; units in the names' comments of the yaml."""

    max_angular_speed: float = 0.8
    min_angular_speed: float = 0.05
    gain: float = 1.5
    tolerance_degrees: float = 0.3
    control_rate: float = 50.0
    odom_timeout: float = 5.0
    stall_seconds: float = 2.0
    stall_degrees: float = 2.0
    settle_speed: float = 0.01
    settle_seconds: float = 1.0
    time_slack: float = 2.0
    time_margin: float = 5.0
    max_degrees: int = 3600

    @classmethod
    def from_parameters(cls) -> "Config":
        return cls(**{name: type(default)(rospy.get_param("~" + name, default))
                      for name, default in cls().__dict__.items()})

    @property
    def gains(self) -> RotationGains:
        return RotationGains(self.gain, self.max_angular_speed, self.min_angular_speed,
                             math.radians(self.tolerance_degrees))


class RotationFailed(Exception):
    """Why a rotation stopped short; the text goes into the answer."""


class RotateService:
    def __init__(self, config: Config):
        self.config = config
        self.yaw = YawAccumulator()
        self.yaw_rate = 0.0
        self.odom_stamp = None  # wall time of the latest odometry
        self._busy = threading.Lock()
        self._odom_lock = threading.Lock()

    def start(self) -> None:
        self.command = rospy.Publisher("cmd_vel", Twist, queue_size=1)
        rospy.Subscriber("odom", Odometry, self._on_odometry, queue_size=10)
        rospy.on_shutdown(self.stop_robot)
        self.service = rospy.Service("/rotate_robot", Rotate, self._serve)
        rospy.loginfo("Service Ready")

    def _on_odometry(self, message: Odometry) -> None:
        q = message.pose.pose.orientation
        yaw = math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))
        with self._odom_lock:
            self.yaw.update(yaw)
            self.yaw_rate = message.twist.twist.angular.z
            self.odom_stamp = time.monotonic()

    def current_yaw(self):
        with self._odom_lock:
            return self.yaw.total, self.yaw_rate, self.odom_stamp

    def stop_robot(self) -> None:
        self.command.publish(Twist())

    def _turn(self, speed: float) -> None:
        twist = Twist()
        twist.angular.z = speed
        self.command.publish(twist)

    # --- the service --------------------------------------------------------------------
    def _serve(self, request) -> RotateResponse:
        rospy.loginfo(f"Service Requested: rotate {request.degrees} degrees")
        if abs(request.degrees) > self.config.max_degrees:
            result = (f"failure: {request.degrees} degrees is beyond the limit of "
                      f"+-{self.config.max_degrees}; the robot did not move")
        elif not self._busy.acquire(blocking=False):
            result = ("failure: another rotation is running; this request is rejected "
                      "(the first one goes on)")
        else:
            try:
                result = self._rotate(request.degrees)
            except RotationFailed as failure:
                result = f"failure: {failure}"
            finally:
                self.stop_robot()
                self._busy.release()
        rospy.loginfo(f"Service Completed: {result}")
        return RotateResponse(result)

    def _wait_for_odometry(self) -> float:
        deadline = time.monotonic() + self.config.odom_timeout
        while not rospy.is_shutdown():
            total, _, stamp = self.current_yaw()
            if stamp is not None and time.monotonic() - stamp < self.config.odom_timeout:
                return total
            if time.monotonic() > deadline:
                raise RotationFailed(f"no odometry on {rospy.resolve_name('odom')} within "
                                     f"{self.config.odom_timeout:g} s; the robot did not move")
            time.sleep(0.05)
        raise RotationFailed("the node is shutting down")

    def _rotate(self, degrees: int) -> str:
        config, gains = self.config, self.config.gains
        start = self._wait_for_odometry()
        if degrees == 0:
            return "success: rotated 0 degrees (final error 0.0 degrees)"
        target = start + math.radians(degrees)
        rate = rospy.Rate(config.control_rate)
        began = rospy.get_time()
        deadline = began + time_allowed(math.radians(degrees), gains, config.time_margin,
                                        config.time_slack)
        progress_yaw, progress_time = start, began
        while not rospy.is_shutdown():
            total, _, stamp = self.current_yaw()
            now = rospy.get_time()
            if time.monotonic() - stamp > config.odom_timeout:
                raise RotationFailed(f"odometry stopped for {config.odom_timeout:g} s "
                                     f"after {math.degrees(total - start):.1f} degrees")
            error = target - total
            speed = angular_speed(error, gains)
            if speed == 0.0:
                final_error = self._settle(target)
                if abs(final_error) <= gains.tolerance:
                    return (f"success: rotated {degrees} degrees (final error "
                            f"{abs(math.degrees(final_error)):.1f} degrees)")
                continue  # it drifted out while stopping: turn again
            if abs(total - progress_yaw) >= math.radians(config.stall_degrees):
                progress_yaw, progress_time = total, now
            elif now - progress_time > config.stall_seconds:
                raise RotationFailed(
                    f"the robot does not turn (blocked?): {math.degrees(total - start):.1f} of "
                    f"{degrees} degrees done, no progress for {config.stall_seconds:g} s")
            if now > deadline:
                raise RotationFailed(f"timed out after {now - began:.1f} s with "
                                     f"{math.degrees(error):.1f} degrees to go")
            self._turn(speed)
            rate.sleep()
        raise RotationFailed("the node is shutting down")

    def _settle(self, target: float) -> float:
        """Stops, waits until the robot is still (or settle_seconds), returns the error."""
        self.stop_robot()
        until = rospy.get_time() + self.config.settle_seconds
        rate = rospy.Rate(self.config.control_rate)
        while not rospy.is_shutdown() and rospy.get_time() < until:
            _, yaw_rate, _ = self.current_yaw()
            if abs(yaw_rate) < self.config.settle_speed:
                break
            rate.sleep()
        total, _, _ = self.current_yaw()
        return target - total


def main() -> None:
    rospy.init_node("rotate_service")
    service = RotateService(Config.from_parameters())
    service.start()
    rospy.spin()

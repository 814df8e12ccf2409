"""``diff_drive_controller/DiffDriveController``: two sides of velocity-controlled wheel
joints, as ros_controllers noetic-devel (678b92a) ``diff_drive_controller/src/
diff_drive_controller.cpp`` (DDC below) runs them.

Parameters, read once when the controller is loaded (DDC:147-164, :197-283): ``left_wheel``,
``right_wheel`` (a joint or a list of joints, as many on each side; required),
``wheel_separation`` and ``wheel_radius`` (from the URDF when not given: the distance between
the two first wheel joints' origins, the left wheel link's first collision's radius),
``wheel_separation_multiplier`` (1), ``wheel_radius_multiplier`` (overrides the two)
or ``left_wheel_radius_multiplier`` and ``right_wheel_radius_multiplier`` (1),
``publish_rate`` (50 Hz), ``open_loop`` (false), ``velocity_rolling_window_size`` (10),
``cmd_vel_timeout`` (0.5 s), ``allow_multiple_cmd_vel_publishers`` (true), ``base_frame_id``
(base_link), ``odom_frame_id`` (odom), ``enable_odom_tf`` (true),
``pose_covariance_diagonal``, ``twist_covariance_diagonal`` (6 doubles each; zeros when absent),
``linear/x/...`` and ``angular/z/...`` limits (see :class:`SpeedLimiter`), ``publish_cmd``
(false), ``publish_wheel_joint_controller_state`` (false).

Topics under the controller's name: ``cmd_vel`` (in), ``odom``, ``cmd_vel_out`` and
``wheel_joint_controller_state`` (out), and ``/tf``. Odometry and limits:
:mod:`.diff_drive_odometry`. dynamic_reconfigure (DDC:358-386) is not emulated.
"""
from __future__ import annotations

import math

from control_msgs.msg import JointTrajectoryControllerState
from geometry_msgs.msg import TransformStamped, Twist, TwistStamped
from nav_msgs.msg import Odometry as OdometryMessage

from sim_bridge.plugins.base import PluginError, stamp
from sim_bridge.poses import quaternion_from_rpy
from sim_bridge.ros_control.controller_base import Controller
from sim_bridge.ros_control.diff_drive_odometry import (DEFAULT_ROLLING_WINDOW, Odometry,
                                                        SpeedLimiter)

# DDC:147-164, :199
DEFAULT_PUBLISH_RATE = 50.0
DEFAULT_CMD_VEL_TIMEOUT = 0.5
# the realtime publishers' queues (DDC:307, :313, :707)
QUEUE_SIZE = 100
# what Noetic's messages say (DDC:539-540, :547, :563)
TOO_MANY_PUBLISHERS = "Detected {} publishers. Only 1 publisher is allowed. Going to brake."
NAN_COMMAND = "Received NaN in velocity command. Ignoring."
NOT_RUNNING = "Can't accept new commands. Controller is not running."
# ROS_*_THROTTLE periods of those messages (s)
MESSAGE_THROTTLE = 1.0
# a load that throws (ros_control noetic-devel 633c374 controller_manager.cpp:326-333)
INIT_EXCEPTION = "Exception thrown while initializing controller '{}'"
# x, y, z, roll, pitch, yaw: the diagonal of a 6 x 6 covariance
COVARIANCE_ENTRIES = 6


def _joint_list(value, what: str, name: str):
    """getWheelNames (DDC:567-618): a string, or a non-empty list of strings."""
    joints = value if isinstance(value, list) else [value]
    if not joints or not all(isinstance(j, str) for j in joints):
        raise PluginError(f"controller '{name}': '{what}' must name a joint or a list of joints")
    return joints


class DiffDriveController(Controller):
    interface = "velocity"
    # what a NaN command is answered with (DDC:547); the ackermann controller's differs
    nan_warning = NAN_COMMAND

    def __init__(self, name, params, hardware, io):
        super().__init__(name, params, hardware, io)
        self.left = _joint_list(self.required("left_wheel"), "left_wheel", name)
        self.right = _joint_list(self.required("right_wheel"), "right_wheel", name)
        if len(self.left) != len(self.right):  # DDC:182-188
            raise PluginError(f"controller '{name}': #left wheels ({len(self.left)}) != "
                              f"#right wheels ({len(self.right)}).")
        self.claim(self.left + self.right)
        model = io.robot.model
        separation = self.params.get("wheel_separation")
        radius = self.params.get("wheel_radius")
        if separation is None:  # DDC:661-674: the joints' origins, each in its parent
            left = model.joints[self.left[0]].origin.xyz
            right = model.joints[self.right[0]].origin.xyz
            separation = math.dist(left, right)
        if radius is None:
            radius = self._radius_from_urdf(model, model.joints[self.left[0]].child)
        separation_multiplier = self.number("wheel_separation_multiplier", 1.0)
        # DDC:210-222: the common multiplier, when set, overrides both sides'
        if "wheel_radius_multiplier" in self.params:
            left_multiplier = right_multiplier = self.number("wheel_radius_multiplier", 1.0)
        else:
            left_multiplier = self.number("left_wheel_radius_multiplier", 1.0)
            right_multiplier = self.number("right_wheel_radius_multiplier", 1.0)
        self.separation = float(separation) * separation_multiplier
        self.left_radius = float(radius) * left_multiplier
        self.right_radius = float(radius) * right_multiplier
        rate = self.number("publish_rate", DEFAULT_PUBLISH_RATE)
        if rate <= 0:
            raise PluginError(f"controller '{name}': publish_rate must be above 0 Hz")
        self.publish_period_ns = int(round(1e9 / rate))
        self.open_loop = bool(self.params.get("open_loop", False))
        self.odometry = Odometry(int(self.number("velocity_rolling_window_size",
                                                 DEFAULT_ROLLING_WINDOW)))
        self.odometry.set_wheel_params(self.separation, self.left_radius, self.right_radius)
        self.timeout_ns = int(self.number("cmd_vel_timeout", DEFAULT_CMD_VEL_TIMEOUT) * 1e9)
        self.allow_multiple_publishers = bool(self.params.get(
            "allow_multiple_cmd_vel_publishers", True))
        # as written, no tf_prefix (DDC:245-249, 708-709, 732-733)
        self.base_frame = str(self.params.get("base_frame_id", "base_link"))
        self.odom_frame = str(self.params.get("odom_frame_id", "odom"))
        self.publish_tf = bool(self.params.get("enable_odom_tf", True))
        self.pose_covariance = self._diagonal("pose_covariance_diagonal")
        self.twist_covariance = self._diagonal("twist_covariance_diagonal")
        self.limiter_linear = self._limiter("linear", "x")
        self.limiter_angular = self._limiter("angular", "z")
        self.publish_cmd = bool(self.params.get("publish_cmd", False))
        self.publish_wheel_state = bool(self.params.get(
            "publish_wheel_joint_controller_state", False))
        bus = io.bus
        self.topic = io.topic(f"{name}/cmd_vel")
        self.odom_out = bus.publisher(io.topic(f"{name}/odom"), OdometryMessage,
                                      queue_size=QUEUE_SIZE)
        self.cmd_out = (bus.publisher(io.topic(f"{name}/cmd_vel_out"), TwistStamped,
                                      queue_size=QUEUE_SIZE) if self.publish_cmd else None)
        self.wheel_state_out = None
        if self.publish_wheel_state:  # DDC:311-342
            self.wheel_state_out = bus.publisher(
                io.topic(f"{name}/wheel_joint_controller_state"), JointTrajectoryControllerState,
                queue_size=QUEUE_SIZE)
            self._wheel_state = self._empty_wheel_state()
            self._previous_velocities = [0.0] * len(self.joints)
            self._previous_desired = [0.0, 0.0]  # left, right
        self._subscription = bus.subscriber(self.topic, Twist, self._on_command)
        self.running = False
        # the command buffer: (linear, angular) and when it came (None: never; -1: stamped
        # by the next update, simulated time); it is kept across a stop and a start
        self.command = (0.0, 0.0)
        self._commanded_ns = None
        # the last two limited commands (last0_cmd_, last1_cmd_): the limiter's memory and
        # the open-loop odometry's twist
        self._last0 = (0.0, 0.0)
        self._last1 = (0.0, 0.0)
        self._last_publish_ns = 0
        self._previous_update_ns = 0

    # --- parameters ---------------------------------------------------------------------
    @staticmethod
    def _radius_from_urdf(model, link: str) -> float:
        """getWheelRadius (DDC:128-143): the link's first collision, a cylinder or a sphere."""
        collisions = model.links[link].collisions
        if collisions and collisions[0].geometry.kind in ("cylinder", "sphere"):
            return collisions[0].geometry.radius
        raise PluginError(f"Wheel link {link} is NOT modeled as a cylinder or sphere! (its "
                          "first <collision>); give wheel_radius")

    def _diagonal(self, key: str):
        """setOdomPubFields (DDC:689-728) as Noetic's released build runs it: its ROS_ASSERTs
        on the list's type and size are compiled out (NDEBUG), so the first six entries are
        read through XmlRpcValue, which makes an absent list or missing entries 0.0 and
        throws on anything but a double (ros_comm noetic-devel 845f746 utilities/xmlrpcpp/
        src/XmlRpcValue.cpp:81-118, include/xmlrpcpp/XmlRpcValue.h:93, :106): an int, a
        string or a scalar fails the load (controller_manager.cpp:323-333)."""
        values = self.params.get(key, [])
        if not isinstance(values, list):
            raise PluginError(f"{INIT_EXCEPTION.format(self.name)}: '{key}' is not a list "
                              f"(XmlRpc type error)")
        values = values[:COVARIANCE_ENTRIES]
        values += [0.0] * (COVARIANCE_ENTRIES - len(values))
        matrix = [0.0] * (COVARIANCE_ENTRIES * COVARIANCE_ENTRIES)
        for i, value in enumerate(values):
            if not isinstance(value, float):  # a double in XmlRpc; bool and int are not
                raise PluginError(f"{INIT_EXCEPTION.format(self.name)}: '{key}' entry {i} is "
                                  f"{value!r}, not a double (XmlRpc type error)")
            matrix[i * (COVARIANCE_ENTRIES + 1)] = value
        return matrix

    def _limiter(self, group: str, axis: str) -> SpeedLimiter:
        """DDC:255-273: each minimum defaults to minus its maximum, each maximum to
        SpeedLimiter's 0 (speed_limiter.h:61-71): a limit switched on without its bounds
        holds the command at 0."""
        section = self.params.get(group, {}).get(axis, {})

        def number(key, default):
            value = section.get(key, default)
            try:
                return float(value)
            except (TypeError, ValueError):
                raise PluginError(f"controller '{self.name}': parameter '{group}/{axis}/{key}' "
                                  f"= {value!r} is not a number") from None

        max_velocity = number("max_velocity", 0.0)
        max_acceleration = number("max_acceleration", 0.0)
        max_jerk = number("max_jerk", 0.0)
        return SpeedLimiter(
            has_velocity_limits=bool(section.get("has_velocity_limits", False)),
            has_acceleration_limits=bool(section.get("has_acceleration_limits", False)),
            has_jerk_limits=bool(section.get("has_jerk_limits", False)),
            min_velocity=number("min_velocity", -max_velocity), max_velocity=max_velocity,
            min_acceleration=number("min_acceleration", -max_acceleration),
            max_acceleration=max_acceleration,
            min_jerk=number("min_jerk", -max_jerk), max_jerk=max_jerk)

    def _empty_wheel_state(self) -> JointTrajectoryControllerState:
        state = JointTrajectoryControllerState()
        state.joint_names = self.left + self.right
        for point in (state.desired, state.actual, state.error):
            for field in ("positions", "velocities", "accelerations", "effort"):
                setattr(point, field, [0.0] * len(self.joints))
        return state

    # --- cmd_vel ------------------------------------------------------------------------
    def _on_command(self, message: Twist):
        """cmdVelCallback (DDC:532-565)."""
        if not self.running:
            self.io.bus.warn(f"{self.name}: {NOT_RUNNING}")
            return
        publishers = getattr(self._subscription, "get_num_connections", None)
        count = publishers() if publishers is not None else 1
        if not self.allow_multiple_publishers and count > 1:
            self.io.bus.warn_throttled(f"{self.topic}:publishers", MESSAGE_THROTTLE,
                                       f"{self.name}: {TOO_MANY_PUBLISHERS.format(count)}")
            self._brake()
            return
        linear, angular = message.linear.x, message.angular.z
        if not (math.isfinite(linear) and math.isfinite(angular)):
            self.io.bus.warn_throttled(f"{self.topic}:nan", MESSAGE_THROTTLE, self.nan_warning)
            return
        self.command = (linear, angular)
        self._commanded_ns = -1

    def _brake(self) -> None:
        """DDC:522-530: the wheels' commands 0 (the next update sets them again)."""
        for joint in self.joints:
            self.hardware.joints[joint].command = 0.0

    # --- life cycle ---------------------------------------------------------------------
    def start(self, now_ns):
        """starting (DDC:506-515): brake, the publishing clock from now, the odometry's
        means start over (its pose is kept)."""
        self._brake()
        self._last_publish_ns = now_ns
        self._previous_update_ns = now_ns
        self.odometry.init(now_ns)
        self.running = True

    def stop(self, now_ns):
        self._brake()
        self.running = False

    def update(self, now_ns, dt):
        """update (DDC:391-504): odometry from the wheels (or the last command), published
        when a period has passed; then the command, braked when older than the timeout,
        limited, to the wheels."""
        if self._commanded_ns == -1:
            self._commanded_ns = now_ns
        if self.open_loop:
            self.odometry.update_open_loop(*self._last0, now_ns)
        else:
            left = [self.hardware.state(j)[0] for j in self.left]
            right = [self.hardware.state(j)[0] for j in self.right]
            if any(math.isnan(p) for p in left + right):  # DDC:416-417: the whole update
                return
            self.odometry.update(sum(left) / len(left), sum(right) / len(right), now_ns)
        # DDC:430-432: strictly after a period since the last, which moves on by one period
        if self._last_publish_ns + self.publish_period_ns < now_ns:
            self._last_publish_ns += self.publish_period_ns
            self._publish(now_ns)
        linear, angular = self.command
        if self._commanded_ns is None or now_ns - self._commanded_ns > self.timeout_ns:
            linear = angular = 0.0
        linear = self.limiter_linear.limit(linear, self._last0[0], self._last1[0], dt)
        angular = self.limiter_angular.limit(angular, self._last0[1], self._last1[1], dt)
        self._last1, self._last0 = self._last0, (linear, angular)
        if self.cmd_out is not None:  # DDC:483-489
            message = TwistStamped()
            message.header.stamp = stamp(now_ns)
            message.twist.linear.x, message.twist.angular.z = linear, angular
            self.cmd_out.publish(message)
        left_speed = (linear - angular * self.separation / 2.0) / self.left_radius
        right_speed = (linear + angular * self.separation / 2.0) / self.right_radius
        for joint in self.left:
            self.hardware.joints[joint].command = left_speed
        for joint in self.right:
            self.hardware.joints[joint].command = right_speed
        if self.wheel_state_out is not None:
            self._publish_wheel_state(now_ns, dt, left_speed, right_speed)
        self._previous_update_ns = now_ns

    # --- publishing ---------------------------------------------------------------------
    def _publish(self, now_ns):
        odometry = self.odometry
        message = OdometryMessage()
        message.header.stamp = stamp(now_ns)
        message.header.frame_id = self.odom_frame
        message.child_frame_id = self.base_frame
        message.pose.pose.position.x, message.pose.pose.position.y = odometry.x, odometry.y
        q = message.pose.pose.orientation
        q.x, q.y, q.z, q.w = quaternion_from_rpy(0.0, 0.0, odometry.heading)
        message.twist.twist.linear.x = odometry.linear
        message.twist.twist.angular.z = odometry.angular
        message.pose.covariance = self.pose_covariance
        message.twist.covariance = self.twist_covariance
        self.odom_out.publish(message)
        if self.publish_tf:
            transform = TransformStamped()
            transform.header = message.header
            transform.child_frame_id = self.base_frame
            transform.transform.translation.x = odometry.x
            transform.transform.translation.y = odometry.y
            transform.transform.rotation = message.pose.pose.orientation
            self.io.bus.send_transforms([transform])

    def _publish_wheel_state(self, now_ns, dt, left_desired, right_desired):
        """publishWheelData (DDC:765-834), its formulas as they are: the desired velocities
        are the limited command's, desired positions their sum times the period, desired
        "accelerations" their change *times* the period, actual accelerations the
        velocities' change over the time since the last update."""
        state = self._wheel_state
        state.header.stamp = stamp(now_ns)
        count = len(self.left)
        elapsed = (now_ns - self._previous_update_ns) * 1e-9
        for i in range(count):
            for k, joint, desired, side in ((i, self.left[i], left_desired, 0),
                                            (i + count, self.right[i], right_desired, 1)):
                position, velocity, effort = (float(v) for v in self.hardware.state(joint))
                state.actual.positions[k] = position
                state.actual.velocities[k] = velocity
                state.actual.accelerations[k] = ((velocity - self._previous_velocities[k])
                                                 / elapsed if elapsed else math.nan)
                state.actual.effort[k] = effort
                state.desired.positions[k] += desired * dt
                state.desired.velocities[k] = desired
                state.desired.accelerations[k] = (desired - self._previous_desired[side]) * dt
                state.desired.effort[k] = math.nan
                for field in ("positions", "velocities", "accelerations", "effort"):
                    getattr(state.error, field)[k] = (getattr(state.desired, field)[k]
                                                      - getattr(state.actual, field)[k])
                self._previous_velocities[k] = velocity
            # DDC:828-829: within the loop, so a second wheel pair sees this pair's desired
            self._previous_desired = [left_desired, right_desired]
        self.wheel_state_out.publish(state)
        self._wheel_state = _copy_state(state)

    def close(self):
        self._subscription.unregister()
        self.odom_out.unregister()
        for publisher in (self.cmd_out, self.wheel_state_out):
            if publisher is not None:
                publisher.unregister()


def _copy_state(state: JointTrajectoryControllerState) -> JointTrajectoryControllerState:
    """A fresh message carrying ``state``'s values on: one published is never changed."""
    copy = JointTrajectoryControllerState()
    copy.joint_names = list(state.joint_names)
    for field in ("desired", "actual", "error"):
        source, target = getattr(state, field), getattr(copy, field)
        for values in ("positions", "velocities", "accelerations", "effort"):
            setattr(target, values, list(getattr(source, values)))
    return copy

"""``ackermann_steering_controller/AckermannSteeringController``: one velocity-controlled rear
wheel joint and one position-controlled steering joint, as ros_controllers noetic-devel
(678b92a) ``ackermann_steering_controller/src/ackermann_steering_controller.cpp`` (ASC below)
runs them.

Parameters, read once when the controller is loaded (ASC:108-123, :125-257): ``rear_wheel``
(rear_wheel_joint) on the VelocityJointInterface, ``front_steer`` (front_steer_joint) on the
PositionJointInterface, ``publish_rate`` (50 Hz), ``open_loop`` (false),
``wheel_separation_h`` and ``wheel_radius`` (from the URDF when not given: the distance along
x between the two joints' origins, the rear wheel link's first collision's cylinder radius),
``wheel_separation_h_multiplier``, ``wheel_radius_multiplier``, ``steer_pos_multiplier`` (1;
the odometry's only), ``velocity_rolling_window_size`` (10), ``cmd_vel_timeout`` (0.5 s),
``allow_multiple_cmd_vel_publishers`` (true), ``base_frame_id`` (base_link),
``odom_frame_id`` (odom), ``enable_odom_tf`` (true), ``pose_covariance_diagonal``,
``twist_covariance_diagonal``, ``linear/x/...`` and ``angular/z/...`` limits (diff drive's
speed limiter, which Noetic's ackermann controller includes: ASC header :45, :167-168).
Noetic's has no ``publish_cmd`` and no dynamic_reconfigure.

``cmd_vel``'s ``angular.z`` is the steering angle (rad) the steering joint is set to, not a
turn rate (ASC:335): the robot turns at linear.x * tan(angular.z) / wheel_separation_h, on
a circle of wheel_separation_h / tan(angular.z) about its rear axle. The rear wheel turns at
linear.x / wheel_radius as given, without the multiplier (ASC:333).

Topics under the controller's name: ``cmd_vel`` (in), ``odom`` (out), and ``/tf``.
Odometry: :mod:`.ackermann_odometry`.
"""
from __future__ import annotations

import math

from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry as OdometryMessage

from sim_bridge.plugins.base import PluginError
from sim_bridge.ros_control.ackermann_odometry import AckermannOdometry
from sim_bridge.ros_control.controller_base import Controller
from sim_bridge.ros_control.diff_drive_controller import (DEFAULT_CMD_VEL_TIMEOUT,
                                                          DEFAULT_PUBLISH_RATE, INIT_EXCEPTION,
                                                          QUEUE_SIZE, DiffDriveController)
from sim_bridge.ros_control.diff_drive_odometry import DEFAULT_ROLLING_WINDOW

# ASC:143, :147: the joints' names when the parameters are absent
DEFAULT_REAR_WHEEL = "rear_wheel_joint"
DEFAULT_FRONT_STEER = "front_steer_joint"
# ASC:113-115 (and the publish rate, timeout and rolling window, ASC:116, :153, :172, as
# diff_drive_controller's, imported from there)
DEFAULT_MULTIPLIER = 1.0
# the interfaces the handles come from (ASC:129-135, :246, :250), as ResourceManager::getHandle
# names them when it throws (ros_control noetic-devel 633c374 hardware_interface/include/
# hardware_interface/internal/resource_manager.h:113-121)
INTERFACE_TYPES = {"velocity": "hardware_interface::VelocityJointInterface",
                   "position": "hardware_interface::PositionJointInterface"}
# what a NaN command would do here: Noetic takes it (ASC:363-379, no check) and sends NaN
# to both joints, which ruins the physics; sim_bridge ignores it, saying so
NAN_COMMAND = ("Received NaN in velocity command. Ignoring. (Noetic's ackermann controller "
               "would send it to the joints)")


class AckermannSteeringController(Controller):
    # the rear wheel's interface; the steering joint's is PositionJointInterface: see
    # claimed() (a MultiInterfaceController<PositionJointInterface, VelocityJointInterface>,
    # ASC header :64-67)
    interface = "velocity"

    # the same code upstream: ASC:197-216 read the limits as DDC:255-273 do, and ASC:468-507
    # the covariance diagonals as DDC:689-728 do (their ROS_ASSERTs compiled out alike)
    _limiter = DiffDriveController._limiter
    _diagonal = DiffDriveController._diagonal
    # and odom and its transform published as DDC:358-389 do (ASC:283-308, the message's
    # constant fields as setOdomPubFields sets them, :486-512)
    _publish = DiffDriveController._publish
    # and cmd_vel taken as DDC:532-565 takes it (cmdVelCallback, ASC:363-390: the publishers'
    # count, the brake, the command kept with its time), angular.z meaning the steering angle
    _on_command = DiffDriveController._on_command
    nan_warning = NAN_COMMAND

    def __init__(self, name, params, hardware, io):
        super().__init__(name, params, hardware, io)
        self.rear = self._name("rear_wheel", DEFAULT_REAR_WHEEL)
        self.steer = self._name("front_steer", DEFAULT_FRONT_STEER)
        rate = self.number("publish_rate", DEFAULT_PUBLISH_RATE)
        if rate <= 0:
            raise PluginError(f"controller '{name}': publish_rate must be above 0 Hz")
        self.publish_period_ns = int(round(1e9 / rate))
        self.open_loop = bool(self.params.get("open_loop", False))
        separation_multiplier = self.number("wheel_separation_h_multiplier", DEFAULT_MULTIPLIER)
        radius_multiplier = self.number("wheel_radius_multiplier", DEFAULT_MULTIPLIER)
        self.steer_multiplier = self.number("steer_pos_multiplier", DEFAULT_MULTIPLIER)
        self.odometry = AckermannOdometry(int(self.number("velocity_rolling_window_size",
                                                          DEFAULT_ROLLING_WINDOW)))
        self.timeout_ns = int(self.number("cmd_vel_timeout", DEFAULT_CMD_VEL_TIMEOUT) * 1e9)
        self.allow_multiple_publishers = bool(self.params.get(
            "allow_multiple_cmd_vel_publishers", True))
        # as written, no tf_prefix (ASC:188-195, :487-488, :511-512)
        self.base_frame = str(self.params.get("base_frame_id", "base_link"))
        self.odom_frame = str(self.params.get("odom_frame_id", "odom"))
        self.publish_tf = bool(self.params.get("enable_odom_tf", True))
        self.limiter_linear = self._limiter("linear", "x")
        self.limiter_angular = self._limiter("angular", "z")
        # ASC:218-229: what is not given comes from the robot's description
        separation, radius = self._geometry()
        self.separation_h = separation
        self.radius = radius
        # ASC:231-238: the multipliers are the odometry's; the command uses the radius as is
        self.odometry.set_wheel_params(separation * separation_multiplier,
                                       radius * radius_multiplier)
        self.pose_covariance = self._diagonal("pose_covariance_diagonal")
        self.twist_covariance = self._diagonal("twist_covariance_diagonal")
        # ASC:242-250: the handles last; each throws when its interface lacks the joint
        self._handle(self.rear, "velocity")
        self._handle(self.steer, "position")
        self.joints = [self.rear, self.steer]
        io.bus.info(f"{name}: rear wheel '{self.rear}', front steer '{self.steer}', wheel "
                    f"separation h {separation} m x {separation_multiplier}, wheel radius "
                    f"{radius} m x {radius_multiplier}, steer x {self.steer_multiplier}, "
                    f"publish rate {rate} Hz, cmd_vel_timeout {self.timeout_ns * 1e-9} s, "
                    f"open_loop {self.open_loop}, frames {self.odom_frame} -> "
                    f"{self.base_frame}, tf {self.publish_tf}")
        bus = io.bus
        self.topic = io.topic(f"{name}/cmd_vel")
        self.odom_out = bus.publisher(io.topic(f"{name}/odom"), OdometryMessage,
                                      queue_size=QUEUE_SIZE)
        self._subscription = bus.subscriber(self.topic, Twist, self._on_command)
        self.running = False
        # the command buffer (ASC:115-123): (linear, steering angle) and when it came (None:
        # never, time 0; -1: stamped by the next update, simulated time)
        self.command = (0.0, 0.0)
        self._commanded_ns = None
        # last0_cmd_, last1_cmd_: the limiter's memory and the open-loop odometry's twist
        self._last0 = (0.0, 0.0)
        self._last1 = (0.0, 0.0)
        self._last_publish_ns = 0

    # --- parameters ---------------------------------------------------------------------
    def _name(self, key: str, default: str) -> str:
        """controller_nh.param(key, std::string) (ASC:143-148): a value that is not a string
        is not read (getParam fails on it), and the default stands."""
        value = self.params.get(key, default)
        return value if isinstance(value, str) else default

    def _geometry(self):
        """setOdomParamsFromUrdf (ASC:393-466) for what the parameters leave out: the
        separation is |x| between the rear wheel's and the steering joint's origins, each
        in its parent link as written; the radius the rear wheel link's first collision's,
        which must be a cylinder (getWheelRadius, isCylinder: ASC:58-104)."""
        # :219-220: getParam(double) reads an int or a double; anything else is not given
        separation, radius = (self.params.get(key) if _is_number(self.params.get(key)) else None
                              for key in ("wheel_separation_h", "wheel_radius"))
        if separation is not None and radius is not None:  # :399-403: no URDF needed
            return float(separation), float(radius)
        joints = self.io.robot.model.joints
        # :417-435; Noetic checks the joints only when it looks the separation up: with the
        # separation given and the rear wheel missing, it dereferences a null joint (:457)
        # and the simulator dies. Here that load is refused with the same words.
        for joint in (self.rear, self.steer) if separation is None else (self.rear,):
            if joint not in joints:
                raise PluginError(f"controller '{self.name}': {joint} couldn't be retrieved "
                                  "from model description (Failed to initialize the "
                                  "controller)")
        if separation is None:  # :447-449
            separation = abs(joints[self.rear].origin.xyz[0] - joints[self.steer].origin.xyz[0])
        if radius is None:  # :454-463
            radius = self._radius_from_urdf(joints[self.rear].child)
        return float(separation), float(radius)

    def _radius_from_urdf(self, link: str) -> float:
        """getWheelRadius (ASC:94-104): the link's first collision, a cylinder only."""
        collisions = self.io.robot.model.links[link].collisions
        if not collisions:  # isCylinder (ASC:66-70)
            why = (f"Link {link} does not have collision description. Add collision "
                   "description for link to urdf.")
        elif collisions[0].geometry.kind != "cylinder":  # :78-82
            why = f"Link {link} does not have cylinder geometry"
        else:
            return collisions[0].geometry.radius
        raise PluginError(f"controller '{self.name}': {why}; Wheel link {link} is NOT modeled "
                          f"as a cylinder!; Couldn't retrieve {self.rear} wheel radius (give "
                          "wheel_radius)")

    def _handle(self, joint: str, interface: str) -> None:
        """getHandle on the controller's share of the robot (ASC:246, :250): a joint whose
        transmission gives it another interface, or none, is not there; the exception fails
        the load (ros_control 633c374 controller_manager.cpp:323-333)."""
        handle = self.hardware.joints.get(joint)
        if handle is None or handle.interface != interface:
            raise PluginError(f"{INIT_EXCEPTION.format(self.name)}.\nCould not find resource "
                              f"'{joint}' in '{INTERFACE_TYPES[interface]}'.")

    def claimed(self):
        """As populateClaimedResources lists a MultiInterfaceController's claims: one entry
        per interface, in the template's order (ros_control 633c374 controller_interface/
        include/controller_interface/internal/robothw_interfaces.h:123-143)."""
        return [("position", [self.steer]), ("velocity", [self.rear])]

    # --- cmd_vel ------------------------------------------------------------------------
    def _brake(self) -> None:
        """brake (ASC:354-361): the rear wheel still, the steering straight."""
        self.hardware.joints[self.rear].command = 0.0
        self.hardware.joints[self.steer].command = 0.0

    # --- life cycle ---------------------------------------------------------------------
    def start(self, now_ns):
        """starting (ASC:339-347): brake, the publishing clock from now, the odometry's
        means start over (its pose is kept)."""
        self._brake()
        self._last_publish_ns = now_ns
        self.odometry.init(now_ns)
        self.running = True

    def stop(self, now_ns):
        """stopping (ASC:349-352)."""
        self._brake()
        self.running = False

    def update(self, now_ns, dt):
        """update (ASC:259-337): odometry from the rear wheel and the steering angle (or the
        last command), published when a period has passed; then the command, braked when
        older than the timeout, limited, to the joints."""
        if self._commanded_ns == -1:
            self._commanded_ns = now_ns
        if self.open_loop:  # :262-265: the steering angle taken as the turn rate, as written
            self.odometry.update_open_loop(*self._last0, now_ns)
        else:
            wheel = float(self.hardware.state(self.rear)[0])
            steer = float(self.hardware.state(self.steer)[0])
            if math.isnan(wheel) or math.isnan(steer):  # :271-272: the whole update
                return
            self.odometry.update(wheel, steer * self.steer_multiplier, now_ns)
        # :280-282: strictly after a period since the last, which moves on by one period
        if self._last_publish_ns + self.publish_period_ns < now_ns:
            self._last_publish_ns += self.publish_period_ns
            self._publish(now_ns)
        linear, angle = self.command
        commanded_ns = 0 if self._commanded_ns is None else self._commanded_ns
        if now_ns - commanded_ns > self.timeout_ns:  # :313-321
            linear = angle = 0.0
        linear = self.limiter_linear.limit(linear, self._last0[0], self._last1[0], dt)
        angle = self.limiter_angular.limit(angle, self._last0[1], self._last1[1], dt)
        self._last1, self._last0 = self._last0, (linear, angle)
        self.hardware.joints[self.rear].command = linear / self.radius  # :333-334
        self.hardware.joints[self.steer].command = angle  # :335

    def close(self):
        self._subscription.unregister()
        self.odom_out.unregister()


def _is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)

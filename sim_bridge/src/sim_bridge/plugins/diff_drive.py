"""``libgazebo_ros_diff_drive.so``: two driven wheels, cmd_vel in, odometry and TF out.

Parameters, names and defaults as gazebo_ros (noetic) reads them:

leftJoint (left_joint), rightJoint (right_joint), wheelSeparation (0.34 m),
wheelDiameter (0.15 m), wheelTorque (5 N m), wheelAcceleration (m/s^2 at the wheel's rim, as
gazebo_ros reads it; 0 or false: no limit; Noetic's ramp from the measured wheel speeds, see
``_wheel_velocities``),
commandTopic (cmd_vel), odometryTopic (odom), odometryFrame (odom),
robotBaseFrame (base_footprint), publishWheelTF (false), publishOdomTF (true),
publishWheelJointState (false: true publishes the wheels' names and positions on
joint_states), publishTf (true: false advertises no odometry topic and publishes neither the
odometry nor its TF; the wheels' TF and joint states go out all the same, as Noetic's:
gazebo_plugins/src/gazebo_ros_diff_drive.cpp:167-171, :272-274),
odometrySource (exactly ``world`` or ``encoder``, case counting; any other text is world with
a warning, as Noetic's map lookup: gazebo_plugins/src/gazebo_ros_diff_drive.cpp:104-107),
updateRate (100 Hz: how often the odometry goes out, and the update slots at which the
last cmd_vel reaches the wheels, :class:`UpdateSlots`), robotNamespace.

The wheels' speeds are Noetic's ``GazeboRosDiffDrive::getWheelVelocities``: the joint
``<leftJoint>`` names turns at (v - w s/2)/r, the one ``<rightJoint>`` names at
(v + w s/2)/r, whatever else the file says. Noetic reads no ``<legacyMode>``: Kinetic's
plugin swapped the two speeds when it was true; Melodic dropped the tag (gazebo_plugins
2.8), so a Kinetic-era package that swapped its joints' names and wrote
``<legacyMode>true</legacyMode>`` turns clockwise for +w on Noetic's Gazebo, and here
(sim_bridge.plugins.RETIRED_TAGS: the tag is a --verbose note, never acted on).

Differences from Gazebo, on purpose: encoder odometry's twist keeps the sign of v; a
``cmd_vel`` with NaN or inf is ignored with a throttled warning instead of spinning the
wheels at NaN.
"""
from __future__ import annotations

import pybullet as pb
from geometry_msgs.msg import TransformStamped
from nav_msgs.msg import Odometry
from sensor_msgs.msg import JointState

from sim_bridge.drive_kinematics import body_twist, integrate
from sim_bridge.plugins.base import Rate, UpdateSlots, stamp
from sim_bridge.plugins.drive_base import DriveBase, covariance
from sim_bridge.poses import quaternion_from_rpy

# gazebo_ros's odometry covariance: x, y and yaw known well, z, roll, pitch not at all
# (gazebo_plugins/src/gazebo_ros_diff_drive.cpp:461-467); nothing sets the twist's: all 0
POSE_COVARIANCE = covariance(1e-5, 1e-5, 1e-3)
TWIST_COVARIANCE = [0.0] * 36
# the left wheel's index in the (left, right) pairs used here (Noetic's enum numbers RIGHT
# first, gazebo_plugins/src/gazebo_ros_diff_drive.cpp:70-73)
LEFT = 0
# m/s at the rim: a wheel this close to its target skips the acceleration ramp for both
# (gazebo_plugins/src/gazebo_ros_diff_drive.cpp:285-286)
WITHIN_TARGET = 0.01


class DiffDrive(DriveBase):
    ABSENT_NAMESPACE_IS_MODEL = EMPTY_NAMESPACE_IS_MODEL = True  # gazebo_plugins' GazeboRos

    def __init__(self, context, spec):
        super().__init__(context, spec, spec.text("commandTopic", "cmd_vel"), None)
        odometry_topic = self.param("odometryTopic", "odom")
        self.left_joint = self.joint("leftJoint", "left_joint")
        self.right_joint = self.joint("rightJoint", "right_joint")
        self.separation, self.radius = self.wheel_geometry(0.34, 0.15)
        self.torque = self.number("wheelTorque", 5.0)
        # m/s^2 at the rim, as gazebo_ros compares it with the joint's speed times the radius
        self.acceleration = self.number("wheelAcceleration", 0.0, false_value=0.0)
        # read through GazeboRos::getParameterBoolean: another text than true, false, 1 or 0
        # keeps the default (gazebo_plugins/src/gazebo_ros_diff_drive.cpp:96-98,
        # gazebo_plugins/src/gazebo_ros_utils.cpp:92-123)
        self.publish_wheel_tf = self.gazebo_ros_flag("publishWheelTF", False)
        self.publish_odom_tf = self.gazebo_ros_flag("publishOdomTF", True)
        self.publish_joint_state = self.gazebo_ros_flag("publishWheelJointState", False)
        # sdformat's Get<bool> (gazebo_plugins/src/gazebo_ros_diff_drive.cpp:118-124): false
        # advertises no odometry topic (:167-171) and skips publishOdometry, the odom TF
        # with it (:272); the wheels' TF and joint states do not depend on it (:273-274)
        self.publish_tf = self.flag("publishTf", True)
        self.publish_odom_tf = self.publish_odom_tf and self.publish_tf
        if self.publish_tf:
            self.odom_out = context.bus.publisher(self.topic(odometry_topic), Odometry,
                                                  queue_size=1)
        # Noetic looks the text up, case counting, in {"encoder", "world"}; another text
        # warns and keeps world (gazebo_plugins/src/gazebo_ros_diff_drive.cpp:104-107,
        # gazebo_plugins/include/gazebo_plugins/gazebo_ros_utils.h:281-293)
        source = self.param("odometrySource", "world")
        if source not in ("world", "encoder"):
            source = self.unreadable("odometrySource", source,
                                     "'world' or 'encoder' (case counts)", "world")
        self.encoder = source == "encoder"
        update_rate = self.number("updateRate", 100.0)
        self.rate = Rate(update_rate)  # the odometry, TF and joint states
        self.slots = UpdateSlots(update_rate)  # the wheels' commands
        self.joints_out = (context.bus.publisher(self.topic("joint_states"), JointState,
                                                 queue_size=1)
                           if self.publish_joint_state else None)
        self.applied = (None, None)
        # Noetic's wheel_speed_instr_, m/s at the rim: set to 0 at load only
        # (gazebo_plugins/src/gazebo_ros_diff_drive.cpp:140-141)
        self.instructed = [0.0, 0.0]
        self._reset_odometry()
        self._last_ns = None
        self._joints = [context.robot.joint_index[self.left_joint],
                        context.robot.joint_index[self.right_joint]]

    def _reset_odometry(self) -> None:
        self.pose = (0.0, 0.0, 0.0)  # encoder odometry: x, y, yaw since spawn or reset
        self.encoder_twist = (0.0, 0.0)

    # --- the step -------------------------------------------------------------------------
    def quiet_until_ns(self, now_ns: int, step_ns: int) -> int:
        # the wheels' slots before the step (its start), the odometry's rate after it (its
        # end); encoder odometry integrates the wheels at every step
        if self.encoder:
            return now_ns
        return min(self.slots.quiet_until_ns(now_ns) + step_ns, self.rate.quiet_until_ns())

    def before_step(self, now_ns: int) -> None:
        """Noetic's rate branch (gazebo_plugins/src/gazebo_ros_diff_drive.cpp:271-308): at
        each update slot the last command becomes the wheels' target; between slots the
        joint motors keep what they were given, so a command waits up to 1/updateRate."""
        seconds = self.slots.due(now_ns)
        if seconds is None:
            return
        self._set_motors(self._wheel_velocities(seconds))

    def _set_motors(self, velocities) -> None:
        """(left, right) joint speed targets, rad/s, at the motors' wheelTorque."""
        if velocities != self.applied:
            pb.setJointMotorControlArray(
                self.context.robot.id, self._joints, pb.VELOCITY_CONTROL,
                targetVelocities=list(velocities), forces=[self.torque, self.torque],
                physicsClientId=self.context.client)
            self.applied = velocities

    def _wheel_velocities(self, seconds: float):
        """(left, right) joint speeds to set, rad/s, as Noetic's UpdateChild works them out
        in m/s at the rim (gazebo_plugins/src/gazebo_ros_diff_drive.cpp:277-306,
        getWheelVelocities :324-333): without wheelAcceleration, or while either wheel's
        measured rim speed is within WITHIN_TARGET of its target, the targets themselves;
        otherwise each wheel's instructed speed (kept between slots, never reset) moves by
        the target's difference from the measured speed, at most wheelAcceleration times
        the seconds since the last update."""
        linear, angular = self.command
        targets = (linear - angular * self.separation / 2.0,
                   linear + angular * self.separation / 2.0)
        states = self.context.robot.joint_states([self.left_joint, self.right_joint])
        measured = [state[1] * self.radius for state in states]
        if self.acceleration == 0 or any(abs(target - speed) < WITHIN_TARGET
                                         for target, speed in zip(targets, measured)):
            return tuple(target / self.radius for target in targets)
        step = self.acceleration * seconds
        for side, (target, speed) in enumerate(zip(targets, measured)):
            # the left wheel ramps up when its target is at or above the measured speed, the
            # right when strictly above (:291, :296); at equality both add 0
            up = target >= speed if side == LEFT else target > speed
            change = min(target - speed, step) if up else max(target - speed, -step)
            self.instructed[side] += change
        return tuple(speed / self.radius for speed in self.instructed)

    def after_step(self, now_ns: int) -> None:
        if self.encoder:
            self._integrate_encoders(now_ns)
        if not self.rate.due(now_ns):
            return
        time = stamp(now_ns)
        transforms = []
        if self.publish_tf and self.odometry_listened(self.publish_odom_tf):
            odometry = self._odometry(now_ns)
            self.odom_out.publish(odometry)
            if self.publish_odom_tf:
                transforms.append(self.odometry_transform(odometry))
        if self.publish_wheel_tf:
            transforms.extend(self._wheel_transforms(time))
        if transforms:
            self.context.bus.send_transforms(transforms)
        if self.joints_out is not None:
            # gazebo_plugins/src/gazebo_ros_diff_drive.cpp:199-218: names and positions only
            states = self.context.robot.joint_states([self.left_joint, self.right_joint])
            message = JointState()
            message.header.stamp = time
            message.name = [self.left_joint, self.right_joint]
            message.position = [s[0] for s in states]
            self.joints_out.publish(message)

    def _integrate_encoders(self, now_ns: int) -> None:
        if self._last_ns is None:
            self._last_ns = now_ns
            return
        dt = (now_ns - self._last_ns) / 1e9
        self._last_ns = now_ns
        states = self.context.robot.joint_states([self.left_joint, self.right_joint])
        linear, angular = body_twist(states[0][1], states[1][1], self.separation, self.radius)
        self.pose = integrate(*self.pose, linear, angular, dt)
        self.encoder_twist = (linear, angular)

    def _odometry(self, now_ns: int):
        if self.encoder:
            x, y, yaw = self.pose
            linear, angular = self.encoder_twist
            return self.odometry_message(now_ns, (x, y, 0.0), quaternion_from_rpy(0.0, 0.0, yaw),
                                         (linear, 0.0, angular), POSE_COVARIANCE,
                                         TWIST_COVARIANCE)
        return self.odometry_message(now_ns, *self.world_odometry(), POSE_COVARIANCE,
                                     TWIST_COVARIANCE)

    def _wheel_transforms(self, time):
        """Noetic's publishWheelTF (gazebo_plugins/src/gazebo_ros_diff_drive.cpp:220-241):
        the frame is named after the joint's parent link as Gazebo has it, after sdformat
        lumped the fixed joints (base_link fixed under base_footprint is base_footprint),
        and the pose is the wheel link's RelativePose, which is relative to the model (the
        root link's frame), not to that parent."""
        robot = self.context.robot
        structure = self.context.structure
        model_inverse = pb.invertTransform(*robot.base_pose())
        transforms = []
        for joint_name in (self.left_joint, self.right_joint):
            joint = robot.model.joints[joint_name]
            parent = structure.body_of.get(joint.parent, joint.parent) if structure \
                else joint.parent
            child = robot.link_pose(joint.child)
            position, orientation = pb.multiplyTransforms(*model_inverse, *child)
            transform = TransformStamped()
            transform.header.stamp = time
            transform.header.frame_id = self.frame(parent)
            transform.child_frame_id = self.frame(joint.child)
            transform.transform.translation.x, transform.transform.translation.y, \
                transform.transform.translation.z = position
            rotation = transform.transform.rotation
            rotation.x, rotation.y, rotation.z, rotation.w = orientation
            transforms.append(transform)
        return transforms

    def reset(self, now_ns: int) -> None:
        """Noetic's Reset (gazebo_plugins/src/gazebo_ros_diff_drive.cpp:183-197): the
        command and the encoder pose to 0, the update slots from now; the instructed speeds
        stay. The motors are stopped at once rather than at the next slot, as the world's
        reset leaves the model at rest (what Gazebo's own Joint::Reset does to a motor's
        target is not read here: gazebo-classic's source is not on this machine)."""
        super().reset(now_ns)
        self._set_motors((0.0, 0.0))
        self._reset_odometry()
        self._last_ns = None
        self.rate.reset(now_ns)
        self.slots.restart(now_ns)

"""``libgazebo_ros_diff_drive.so``: two driven wheels, cmd_vel in, odometry and TF out.

Parameters, names and defaults as gazebo_ros (noetic) reads them:

leftJoint (left_joint), rightJoint (right_joint), wheelSeparation (0.34 m),
wheelDiameter (0.15 m), wheelTorque (5 N m), wheelAcceleration (m/s^2 at the wheel's rim, as
gazebo_ros reads it; 0 or false: no limit),
commandTopic (cmd_vel), odometryTopic (odom), odometryFrame (odom),
robotBaseFrame (base_footprint), publishWheelTF (false), publishOdomTF (true),
publishWheelJointState (false: true publishes the wheels' names and positions on
joint_states), publishTf (true: false advertises no odometry topic and publishes neither the
odometry nor its TF; the wheels' TF and joint states go out all the same, as Noetic's:
gazebo_plugins/src/gazebo_ros_diff_drive.cpp:167-171, :272-274),
odometrySource (exactly ``world`` or ``encoder``, case counting; any other text is world with
a warning, as Noetic's map lookup: gazebo_plugins/src/gazebo_ros_diff_drive.cpp:104-107),
updateRate (100 Hz), robotNamespace.

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

from sim_bridge.drive_kinematics import body_twist, integrate, limit_change, wheel_speeds
from sim_bridge.plugins.base import PluginError, Rate, stamp
from sim_bridge.plugins.drive_base import DriveBase, covariance
from sim_bridge.poses import quaternion_from_rpy

# gazebo_ros's odometry covariance: x, y and yaw known well, z, roll, pitch not at all
# (gazebo_plugins/src/gazebo_ros_diff_drive.cpp:461-467); nothing sets the twist's: all 0
POSE_COVARIANCE = covariance(1e-5, 1e-5, 1e-3)
TWIST_COVARIANCE = [0.0] * 36


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
        self.rate = Rate(self.number("updateRate", 100.0))
        self.joints_out = (context.bus.publisher(self.topic("joint_states"), JointState,
                                                 queue_size=1)
                           if self.publish_joint_state else None)
        self.applied = (None, None)
        self.wheel_target = [0.0, 0.0]
        self._reset_odometry()
        self._last_ns = None
        self._joints = [context.robot.joint_index[self.left_joint],
                        context.robot.joint_index[self.right_joint]]

    def _reset_odometry(self) -> None:
        self.pose = (0.0, 0.0, 0.0)  # encoder odometry: x, y, yaw since spawn or reset
        self.encoder_twist = (0.0, 0.0)

    # --- the step -------------------------------------------------------------------------
    def before_step(self, now_ns: int) -> None:
        targets = wheel_speeds(*self.command, self.separation, self.radius)  # (left, right)
        max_change = self.acceleration / self.radius * self.context.step_size  # rad/s per step
        for side in (0, 1):
            self.wheel_target[side] = limit_change(self.wheel_target[side], targets[side],
                                                   max_change)
        if tuple(self.wheel_target) != self.applied:
            pb.setJointMotorControlArray(
                self.context.robot.id, self._joints, pb.VELOCITY_CONTROL,
                targetVelocities=list(self.wheel_target), forces=[self.torque, self.torque],
                physicsClientId=self.context.client)
            self.applied = tuple(self.wheel_target)

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
        robot = self.context.robot
        transforms = []
        for joint_name in (self.left_joint, self.right_joint):
            joint = robot.model.joints[joint_name]
            parent = robot.link_pose(joint.parent)
            child = robot.link_pose(joint.child)
            inverse = pb.invertTransform(*parent)
            position, orientation = pb.multiplyTransforms(*inverse, *child)
            transform = TransformStamped()
            transform.header.stamp = time
            transform.header.frame_id = self.frame(joint.parent)
            transform.child_frame_id = self.frame(joint.child)
            transform.transform.translation.x, transform.transform.translation.y, \
                transform.transform.translation.z = position
            rotation = transform.transform.rotation
            rotation.x, rotation.y, rotation.z, rotation.w = orientation
            transforms.append(transform)
        return transforms

    def reset(self, now_ns: int) -> None:
        super().reset(now_ns)
        self.wheel_target = [0.0, 0.0]
        self._reset_odometry()
        self._last_ns = None
        self.rate.reset(now_ns)

"""``libgazebo_ros_planar_move.so``: moves the model in the plane as commanded, holonomic.

As Noetic's plugin (gazebo_ros_pkgs noetic-devel f9e1a46,
gazebo_plugins/src/gazebo_ros_planar_move.cpp). Parameters: commandTopic (cmd_vel),
odometryTopic (odom), odometryFrame (odom), robotBaseFrame (base_footprint), odometryRate
(20 Hz; 0 or less: no odometry at all), cmdTimeout (-1: none; 0 or more: seconds after
which the last command is zeroed), robotNamespace. Nothing else: no ``publishOdometryTf``
(the odometry always goes on /tf too) and no ``covariance_*`` tags (the covariance is
hard-coded); written, they are named as tags the plugin does not read.

Every step linear.x, linear.y and angular.z of the command (body frame) set the model's
velocity, and its vertical velocity to 0 (a model in the air sinks by g dt² a step instead of
falling). The odometry is the true pose with z 0, its twist the change of the pose since the
last publication. A reset of the world changes nothing in the plugin, as Noetic's has no
Reset.
"""
from __future__ import annotations

import math

import pybullet as pb

from sim_bridge.plugins.base import gazebo_seconds
from sim_bridge.plugins.drive_base import DriveBase, covariance
from sim_bridge.poses import yaw_from_quaternion

# gazebo_plugins/src/gazebo_ros_planar_move.cpp:292-297: the pose's, whatever the file says;
# the twist's is never set (all 0)
POSE_COVARIANCE = covariance(1e-5, 1e-5, 1e-3)
TWIST_COVARIANCE = [0.0] * 36


class PlanarMove(DriveBase):
    def __init__(self, context, spec):
        super().__init__(context, spec, spec.text("commandTopic", "cmd_vel"),
                         spec.text("odometryTopic", "odom"))
        # gazebo_plugins/src/gazebo_ros_planar_move.cpp:106-116, used at :212-220
        self.odometry_rate = self.number("odometryRate", 20.0)
        # gazebo_plugins/src/gazebo_ros_planar_move.cpp:117-127, used at :189-197
        self.timeout = self.number("cmdTimeout", -1.0)
        self.sideways = 0.0
        self._commanded_ns = None
        # the time and (x, y, yaw) of the last publication, the load's until the first
        # (gazebo_plugins/src/gazebo_ros_planar_move.cpp:129-138); set at the first step
        self._last_ns = None
        self._last_pose = None

    def _on_command(self, message) -> None:
        if self.finite_command(linear_x=message.linear.x, linear_y=message.linear.y,
                               angular_z=message.angular.z):
            self.command = (message.linear.x, message.angular.z)
            self.sideways = message.linear.y
            self._commanded_ns = -1  # stamped by the next step (simulated time)

    def _planar_pose(self):
        (x, y, _), orientation = self.context.robot.base_pose()
        return x, y, yaw_from_quaternion(orientation)

    def before_step(self, now_ns: int) -> None:
        if self._last_ns is None:
            self._last_ns, self._last_pose = now_ns, self._planar_pose()
        if self._commanded_ns == -1:
            self._commanded_ns = now_ns
        # gazebo_plugins/src/gazebo_ros_planar_move.cpp:189-197: a timeout of 0 or more is
        # active; a command older than it is zeroed (and stays so until the next one)
        if self.timeout >= 0 and (self._commanded_ns is None or
                                  now_ns - self._commanded_ns > self.timeout * 1e9):
            self.command, self.sideways = (0.0, 0.0), 0.0
        forward, turn = self.command
        sideways = self.sideways
        robot = self.context.robot
        _, orientation = robot.base_pose()
        yaw = yaw_from_quaternion(orientation)
        world_x = forward * math.cos(yaw) - sideways * math.sin(yaw)
        world_y = forward * math.sin(yaw) + sideways * math.cos(yaw)
        # gazebo_plugins/src/gazebo_ros_planar_move.cpp:204-208: the vertical velocity is
        # set to 0 every update, as the rates about x and y
        pb.resetBaseVelocity(robot.id, [world_x, world_y, 0.0], [0.0, 0.0, turn],
                             physicsClientId=self.context.client)

    def after_step(self, now_ns: int) -> None:
        # gazebo_plugins/src/gazebo_ros_planar_move.cpp:212-229: only with a rate above 0,
        # once more than a period has passed since the last publication, which becomes now
        if self.odometry_rate <= 0 or self._last_ns is None:
            return
        step_time = gazebo_seconds(now_ns - self._last_ns)
        if not step_time > 1.0 / self.odometry_rate:
            return
        last_pose, pose = self._last_pose, self._planar_pose()
        self._last_ns, self._last_pose = now_ns, pose
        if self.odometry_listened(True):
            self._publish(now_ns, step_time, last_pose, pose)

    def _publish(self, now_ns: int, step_time: float, last_pose, pose) -> None:
        """gazebo_plugins/src/gazebo_ros_planar_move.cpp:261-329."""
        position, orientation = self.context.robot.base_pose()
        x, y, yaw = pose
        last_x, last_y, last_yaw = last_pose
        # :300-302, :319-322: the world's change of position over the time, turned into
        # the body by the current yaw
        world_vx, world_vy = (x - last_x) / step_time, (y - last_y) / step_time
        forward = math.cos(yaw) * world_vx + math.sin(yaw) * world_vy
        sideways = math.cos(yaw) * world_vy - math.sin(yaw) * world_vx
        # :303-316: the command when it turns faster than π per period, else the change
        # of yaw unwrapped to within π of the last
        turn = self.command[1]
        if turn > math.pi / step_time:
            rate = turn
        else:
            while yaw < last_yaw - math.pi:
                yaw += 2 * math.pi
            while yaw > last_yaw + math.pi:
                yaw -= 2 * math.pi
            rate = (yaw - last_yaw) / step_time
        # :285-286: position.z is never set (0); the transform (:276-282) has the true z
        odometry = self.odometry_message(now_ns, (position[0], position[1], 0.0), orientation,
                                         (forward, sideways, rate), POSE_COVARIANCE,
                                         TWIST_COVARIANCE)
        transform = self.odometry_transform(odometry)
        transform.transform.translation.z = position[2]
        # :279-282: sent every time, before the message; no tag turns it off
        self.context.bus.send_transforms([transform])
        self.odom_out.publish(odometry)

    def reset(self, now_ns: int) -> None:
        """Noetic's plugin has no Reset (gazebo_plugins/include/gazebo_plugins/
        gazebo_ros_planar_move.h:47-56 declares none, so ModelPlugin's empty one runs): the last command stays and moves the model on from the
        reset pose, and the next odometry's twist is the change from the last published pose
        (before the reset) over the time since."""

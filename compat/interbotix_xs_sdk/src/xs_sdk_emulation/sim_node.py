"""The ``xs_sdk_sim`` node: the driver's services, command topics and joint states in the
robot's namespace, on :class:`SimulatedMotors` (interbotix_ros_core noetic 172841f,
``interbotix_xs_sdk/scripts/xs_sdk_sim``): ``torque_enable``, ``reboot_motors``,
``get_robot_info``, ``set_operating_modes``, ``set_motor_pid_gains``,
``set_motor_registers``, ``get_motor_registers``; ``commands/joint_group``,
``commands/joint_single``, ``commands/joint_trajectory``; the motor config's joint state
topic at 20 Hz. Parameters ``~motor_configs`` and ``~mode_configs`` (file paths, as
``xsarm_control.launch`` sets them); the joints' limits from ``/<robot_name>/robot_description``.

``~simulator`` (false): drive the simulated arm's position controllers instead of fake joints
(``simulator_joints``), waiting ``~simulator_timeout`` (30 s) for them.

A request the driver cannot serve (an unknown joint or group, a wrong number of commands, a
non-finite command) is refused with a message naming it, and the node goes on."""
from __future__ import annotations

import sys
import threading
from dataclasses import dataclass
from typing import Optional

import rospy
from interbotix_xs_msgs.msg import JointGroupCommand, JointSingleCommand, JointTrajectoryCommand
from interbotix_xs_msgs.srv import (MotorGains, MotorGainsResponse, OperatingModes,
                                    OperatingModesResponse, Reboot, RebootResponse,
                                    RegisterValues, RegisterValuesResponse, RobotInfo,
                                    RobotInfoResponse, TorqueEnable, TorqueEnableResponse)
from node_params import ParameterError, parameter, positive, read
from sensor_msgs.msg import JointState

from xs_sdk_emulation import configs
from xs_sdk_emulation.simulated_motors import TIMER_HZ, CommandError, SimulatedMotors
from xs_sdk_emulation.simulator_joints import SimulatorJoints, SimulatorUnavailable

LOG = "[xs_sdk] "


@dataclass(frozen=True)
class Settings:
    """The workspace's own parameters (upstream's simulated driver drives no simulator)."""
    simulator: bool = parameter(False, expected="true to drive the simulated arm's position "
                                                "controllers, false for fake joints")
    simulator_timeout: float = parameter(30.0, positive,
                                         expected="s > 0 to wait for the simulator's controllers")


def joint_limits(description_key: str):
    """joint -> (lower, upper, velocity) of robot_description's joints with limits, or None
    when the parameter is not there (upstream then answers without limits)."""
    if not rospy.has_param(description_key):
        rospy.logwarn(LOG + "%s is not set: get_robot_info answers without joint limits",
                      description_key)
        return None
    from urdf_parser_py.urdf import URDF
    model = URDF.from_xml_string(rospy.get_param(description_key))
    return {joint.name: (joint.limit.lower, joint.limit.upper, joint.limit.velocity)
            for joint in model.joints if joint.limit is not None}


class XsSdkSim:
    """Serves the motors; construct after ``rospy.init_node`` (in the robot's namespace)."""

    def __init__(self, motors: SimulatedMotors, limits,
                 simulator: Optional[SimulatorJoints] = None):
        self.motors, self.limits, self.simulator = motors, limits, simulator
        self.trajectory_running = threading.Event()
        self.services = [
            rospy.Service("torque_enable", TorqueEnable, self._torque_enable),
            rospy.Service("reboot_motors", Reboot, self._reboot),
            rospy.Service("get_robot_info", RobotInfo, self._robot_info),
            rospy.Service("set_operating_modes", OperatingModes, self._operating_modes),
            rospy.Service("set_motor_pid_gains", MotorGains, self._pid_gains),
            rospy.Service("set_motor_registers", RegisterValues, self._set_registers),
            rospy.Service("get_motor_registers", RegisterValues, self._get_registers)]
        self.subscribers = [
            rospy.Subscriber("commands/joint_group", JointGroupCommand, self._group),
            rospy.Subscriber("commands/joint_single", JointSingleCommand, self._single),
            rospy.Subscriber("commands/joint_trajectory", JointTrajectoryCommand,
                             self._trajectory, queue_size=1)]
        # on the simulated arm the simulator's joint_state_controller publishes the states
        self.states = None if simulator else rospy.Publisher(
            motors.config.joint_state_topic, JointState, queue_size=1)
        self.timer = rospy.Timer(rospy.Duration(1.0 / TIMER_HZ), self._tick)

    def _tick(self, _event) -> None:
        names, positions = self.motors.tick()
        if self.simulator is not None:
            self.simulator.send(names, positions)
            return
        self.states.publish(JointState(name=names, position=positions,
                                       header=rospy.Header(stamp=rospy.Time.now())))

    # --- services: an error is the service's error, with the driver's words ----------------
    @staticmethod
    def _served(handler, request):
        try:
            return handler(request)
        except CommandError as error:
            rospy.logwarn(LOG + "%s", error)
            raise rospy.ServiceException(str(error)) from None

    def _torque_enable(self, request):
        def serve(req):
            self.motors.joints(req.cmd_type, req.name)
            rospy.loginfo(LOG + "The '%s' %s was torqued %s.", req.name,
                          "group" if req.cmd_type == "group" else "joint",
                          "on" if req.enable else "off")
            return TorqueEnableResponse()
        return self._served(serve, request)

    def _reboot(self, request):
        def serve(req):
            self.motors.joints(req.cmd_type, req.name)
            rospy.loginfo(LOG + "The '%s' %s was rebooted.", req.name,
                          "group" if req.cmd_type == "group" else "joint")
            return RebootResponse()
        return self._served(serve, request)

    def _robot_info(self, request):
        return self._served(lambda req: RobotInfoResponse(
            **self.motors.robot_info(req.cmd_type, req.name, self.limits)), request)

    def _operating_modes(self, request):
        def serve(req):
            self.motors.set_operating_modes(req.cmd_type, req.name, req.mode, req.profile_type,
                                            req.profile_velocity, req.profile_acceleration)
            rospy.loginfo(LOG + "The operating mode for the '%s' %s was changed to %s.",
                          req.name, "group" if req.cmd_type == "group" else "joint", req.mode)
            return OperatingModesResponse()
        return self._served(serve, request)

    def _pid_gains(self, request):
        def serve(req):   # no motor firmware to write them to (as upstream's simulator)
            self.motors.joints(req.cmd_type, req.name)
            return MotorGainsResponse()
        return self._served(serve, request)

    def _set_registers(self, request):
        def serve(req):
            self.motors.set_register(req.cmd_type, req.name, req.reg, req.value)
            return RegisterValuesResponse()
        return self._served(serve, request)

    def _get_registers(self, request):
        return self._served(lambda req: RegisterValuesResponse(
            values=self.motors.get_register(req.cmd_type, req.name, req.reg)), request)

    # --- commands: a bad one is logged and dropped ------------------------------------------
    def _group(self, message) -> None:
        try:
            self.motors.write_group(message.name, list(message.cmd))
        except CommandError as error:
            rospy.logerr(LOG + "%s", error)

    def _single(self, message) -> None:
        try:
            self.motors.write_joint(message.name, message.cmd)
        except CommandError as error:
            rospy.logerr(LOG + "%s", error)

    def _trajectory(self, message) -> None:
        """Each point after the first at its time_from_start, in this callback (as
        upstream's), in the mode of the group or joint: positions, velocities or efforts."""
        if self.trajectory_running.is_set():
            rospy.logwarn(LOG + "Trajectory rejected since joints are still moving.")
            return
        points = message.traj.points
        if len(points) < 2:
            rospy.logwarn(LOG + "Trajectory has fewer than 2 points. Aborting...")
            return
        try:
            mode = self.motors.mode_of(message.cmd_type, message.name).mode
        except CommandError as error:
            rospy.logerr(LOG + "%s", error)
            return
        field = ("positions" if "position" in mode else
                 "velocities" if mode == "velocity" else "effort")
        self.trajectory_running.set()
        try:
            start = rospy.Time.now()
            for number, point in enumerate(points[1:], start=1):
                values = list(getattr(point, field))
                if message.cmd_type == "group":
                    self.motors.write_group(message.name, values)
                else:
                    self.motors.write_joint(message.name, values[0])
                if number < len(points) - 1:
                    rospy.sleep(point.time_from_start - (rospy.Time.now() - start))
        except CommandError as error:
            rospy.logerr(LOG + "trajectory for '%s' stopped at a point: %s", message.name, error)
        except IndexError:
            rospy.logerr(LOG + "trajectory for '%s' stopped at a point that has no %s",
                         message.name, field)
        finally:
            self.trajectory_running.clear()


def main() -> None:
    rospy.init_node("xs_sdk_sim")
    try:
        config = configs.read(rospy.get_param("~motor_configs"), rospy.get_param("~mode_configs", ""))
    except KeyError as error:
        rospy.logfatal(LOG + "the parameter ~%s is not set (xsarm_control.launch sets it to "
                       "the robot's motor config). Shutting down...", error.args[0])
        sys.exit(1)
    except configs.ConfigError as error:
        rospy.logfatal(LOG + "%s. Shutting down...", error)
        sys.exit(1)
    rospy.loginfo(LOG + "Loaded motor configs from '%s'.", rospy.get_param("~motor_configs"))
    try:
        settings = read(Settings)
    except ParameterError as error:
        rospy.logfatal(LOG + "%s. Shutting down...", error)
        sys.exit(1)
    robot_name = rospy.get_namespace().strip("/")
    limits = joint_limits(f"/{robot_name}/robot_description")
    simulator, motors = None, SimulatedMotors(config)
    if settings.simulator:
        try:
            simulator = SimulatorJoints(config, settings.simulator_timeout)
        except (SimulatorUnavailable, rospy.ROSException) as error:
            rospy.logfatal(LOG + "%s. Shutting down...", error)
            sys.exit(1)
        fingers = {g.left_finger: limits[g.left_finger][:2] for g in config.grippers.values()
                   if limits and g.left_finger in limits}
        motors = SimulatedMotors(config, finger_limits=fingers,
                                 state_order=simulator.state_order)
    XsSdkSim(motors, limits, simulator)
    rospy.loginfo(LOG + "InterbotixRobotXS is up (%s: %s)",
                  "the simulated arm's position controllers" if simulator else "fake joints",
                  ", ".join(config.joint_order))
    rospy.spin()

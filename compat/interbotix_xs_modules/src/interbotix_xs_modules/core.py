"""``InterbotixRobotXSCore``: the X-series driver's services and command topics under
``/<robot_name>/``, and its joint states (upstream's ``core.py``, noetic af96d28). The
driver must answer within 5 s (``set_operating_modes``), else the program ends saying so,
as upstream's; the first joint states are awaited 10 s at most (upstream waits for ever)."""
import copy
import sys
import threading
import time

import rospy
from interbotix_xs_msgs.msg import JointGroupCommand, JointSingleCommand, JointTrajectoryCommand
from interbotix_xs_msgs.srv import (MotorGains, OperatingModes, Reboot, RegisterValues,
                                    RobotInfo, TorqueEnable)
from sensor_msgs.msg import JointState
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

DRIVER_WAIT = 5.0           # s: upstream's wait for set_operating_modes (core.py l. 30)
JOINT_STATES_WAIT = 10.0    # s (wall)
SERVICES = (("set_operating_modes", OperatingModes), ("set_motor_pid_gains", MotorGains),
            ("set_motor_registers", RegisterValues), ("get_motor_registers", RegisterValues),
            ("get_robot_info", RobotInfo), ("torque_enable", TorqueEnable),
            ("reboot_motors", Reboot))


class InterbotixRobotXSCore:
    """The driver of robot ``robot_name`` (default: ``robot_model``); ``init_node`` starts
    the node ``<robot_name>_robot_manipulation``."""

    def __init__(self, robot_model, robot_name=None, init_node=True,
                 joint_state_topic="joint_states"):
        self.joint_states = None
        self.js_mutex = threading.Lock()
        self.robot_name = robot_model if robot_name is None else robot_name
        if init_node:
            rospy.init_node(self.robot_name + "_robot_manipulation")
        prefix = "/" + self.robot_name + "/"
        try:
            rospy.wait_for_service(prefix + SERVICES[0][0], timeout=DRIVER_WAIT)
            for name, _ in SERVICES[1:]:
                rospy.wait_for_service(prefix + name, timeout=DRIVER_WAIT)
        except rospy.exceptions.ROSException as error:
            print(str(error.args[0]))
            print(f"The robot '{self.robot_name}' is not discoverable. Did you enter the "
                  "correct robot_name parameter? Is the xs_sdk node running? Quitting...")
            sys.exit(1)
        proxies = {name: rospy.ServiceProxy(prefix + name, kind) for name, kind in SERVICES}
        self.srv_set_op_modes = proxies["set_operating_modes"]
        self.srv_set_pids = proxies["set_motor_pid_gains"]
        self.srv_set_reg = proxies["set_motor_registers"]
        self.srv_get_reg = proxies["get_motor_registers"]
        self.srv_get_info = proxies["get_robot_info"]
        self.srv_torque = proxies["torque_enable"]
        self.srv_reboot = proxies["reboot_motors"]
        self.pub_group = rospy.Publisher(prefix + "commands/joint_group", JointGroupCommand,
                                         queue_size=1)
        self.pub_single = rospy.Publisher(prefix + "commands/joint_single", JointSingleCommand,
                                          queue_size=1)
        self.pub_traj = rospy.Publisher(prefix + "commands/joint_trajectory",
                                        JointTrajectoryCommand, queue_size=1)
        self.sub_joint_states = rospy.Subscriber(prefix + joint_state_topic, JointState,
                                                 self.joint_state_cb)
        deadline = time.monotonic() + JOINT_STATES_WAIT
        while self.joint_states is None and not rospy.is_shutdown():
            if time.monotonic() > deadline:
                print(f"No joint states on {prefix + joint_state_topic} within "
                      f"{JOINT_STATES_WAIT:g} s: is the xs_sdk node publishing? Quitting...")
                sys.exit(1)
            time.sleep(0.01)
        self.js_index_map = dict(zip(self.joint_states.name, range(len(self.joint_states.name))))
        rospy.sleep(0.5)    # upstream's (l. 59): the publishers' connections settle
        print(f"Robot Name: {self.robot_name}\nRobot Model: {robot_model}")
        print("Initialized InterbotixRobotXSCore!\n")

    def robot_set_operating_modes(self, cmd_type, name, mode, profile_type="velocity",
                                  profile_velocity=0, profile_acceleration=0):
        self.srv_set_op_modes(cmd_type, name, mode, profile_type, profile_velocity,
                              profile_acceleration)

    def robot_set_motor_pid_gains(self, cmd_type, name, kp_pos, ki_pos=0, kd_pos=0, k1=0, k2=0,
                                  kp_vel=100, ki_vel=1920):
        self.srv_set_pids(cmd_type, name, kp_pos, ki_pos, kd_pos, k1, k2, kp_vel, ki_vel)

    def robot_set_motor_registers(self, cmd_type, name, reg, value):
        self.srv_set_reg(cmd_type, name, reg, value)

    def robot_get_motor_registers(self, cmd_type, name, reg):
        return self.srv_get_reg(cmd_type=cmd_type, name=name, reg=reg)

    def robot_get_robot_info(self, cmd_type, name):
        return self.srv_get_info(cmd_type, name)

    def robot_torque_enable(self, cmd_type, name, enable):
        self.srv_torque(cmd_type, name, enable)

    def robot_reboot_motors(self, cmd_type, name, enable, smart_reboot=False):
        self.srv_reboot(cmd_type, name, enable, smart_reboot)

    def robot_write_commands(self, group_name, commands):
        self.pub_group.publish(JointGroupCommand(group_name, commands))

    def robot_write_joint_command(self, joint_name, command):
        self.pub_single.publish(JointSingleCommand(joint_name, command))

    def robot_write_trajectory(self, cmd_type, name, type, raw_traj):  # pylint: disable=redefined-builtin
        """``raw_traj``: a list of {time_from_start: values}; ``type``: position or velocity."""
        trajectory = JointTrajectory()
        for point in raw_traj:
            for seconds, values in point.items():
                message = JointTrajectoryPoint(time_from_start=rospy.Duration.from_sec(seconds))
                if type == "position":
                    message.positions = values
                elif type == "velocity":
                    message.velocities = values
                trajectory.points.append(message)
        self.pub_traj.publish(JointTrajectoryCommand(cmd_type, name, trajectory))

    def robot_get_joint_states(self):
        with self.js_mutex:
            return copy.deepcopy(self.joint_states)

    def robot_get_single_joint_state(self, name):
        states = self.robot_get_joint_states()
        index = states.name.index(name)
        return {"position": states.position[index], "velocity": states.velocity[index],
                "effort": states.effort[index]}

    def joint_state_cb(self, msg):
        with self.js_mutex:
            self.joint_states = msg

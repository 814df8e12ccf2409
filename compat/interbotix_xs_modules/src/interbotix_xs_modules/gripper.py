"""The X-series gripper driven by PWM (upstream's ``gripper.py``, noetic af96d28): ``open``
and ``close`` send +-effort, effort = lower + pressure * (upper - lower) (150 and 350 by
default, pressure 0.5: 250; l. 27, 36), and a 50 Hz timer (l. 40) sends 0 once the left
finger reaches its limit from robot_description."""
import rospy
from interbotix_xs_msgs.msg import JointSingleCommand

from interbotix_xs_modules.core import InterbotixRobotXSCore

STATE_PERIOD = 0.02     # s: upstream's gripper_state timer (gripper.py l. 40)


class InterbotixGripperXS:  # pylint: disable=too-few-public-methods
    """A standalone gripper with its own core."""

    def __init__(self, robot_model, gripper_name, robot_name=None, gripper_pressure=0.5,
                 gripper_pressure_lower_limit=150, gripper_pressure_upper_limit=350,
                 init_node=True):
        self.dxl = InterbotixRobotXSCore(robot_model, robot_name, init_node)
        self.gripper = InterbotixGripperXSInterface(self.dxl, gripper_name, gripper_pressure,
                                                    gripper_pressure_lower_limit,
                                                    gripper_pressure_upper_limit)


class InterbotixGripperXSInterface:
    def __init__(self, core, gripper_name, gripper_pressure=0.5, gripper_pressure_lower_limit=150,
                 gripper_pressure_upper_limit=350):
        self.core = core
        info = self.core.srv_get_info("single", gripper_name)
        if info.mode not in ("current", "pwm"):
            rospy.logerr("Please set the gripper's 'operating mode' to 'pwm' or 'current'.")
        self.gripper_moving = False
        self.gripper_command = JointSingleCommand(name=gripper_name)
        self.gripper_pressure_lower_limit = gripper_pressure_lower_limit
        self.gripper_pressure_upper_limit = gripper_pressure_upper_limit
        self.gripper_value = gripper_pressure_lower_limit + gripper_pressure * (
            gripper_pressure_upper_limit - gripper_pressure_lower_limit)
        self.left_finger_index = self.core.js_index_map[info.joint_names[0]]
        self.left_finger_lower_limit = info.joint_lower_limits[0]
        self.left_finger_upper_limit = info.joint_upper_limits[0]
        self.timer = rospy.Timer(rospy.Duration(STATE_PERIOD), self.gripper_state)
        print(f"Gripper Name: {gripper_name}\nGripper Pressure: {gripper_pressure * 100:.0f}%")
        print("Initialized InterbotixGripperXSInterface!\n")

    def _left_finger(self):
        with self.core.js_mutex:
            return self.core.joint_states.position[self.left_finger_index]

    def _beyond_limit(self, position):
        return ((self.gripper_command.cmd > 0 and position >= self.left_finger_upper_limit) or
                (self.gripper_command.cmd < 0 and position <= self.left_finger_lower_limit))

    def gripper_state(self, _event):
        """Stops the fingers at their limit."""
        if self.gripper_moving and self._beyond_limit(self._left_finger()):
            self.gripper_command.cmd = 0
            self.core.pub_single.publish(self.gripper_command)
            self.gripper_moving = False

    def gripper_controller(self, effort, delay):
        self.gripper_command.cmd = effort
        position = self._left_finger()
        if ((effort > 0 and position < self.left_finger_upper_limit) or
                (effort < 0 and position > self.left_finger_lower_limit)):
            self.core.pub_single.publish(self.gripper_command)
            self.gripper_moving = True
            rospy.sleep(delay)

    def set_pressure(self, pressure):
        self.gripper_value = self.gripper_pressure_lower_limit + pressure * (
            self.gripper_pressure_upper_limit - self.gripper_pressure_lower_limit)

    def open(self, delay=1.0):
        self.gripper_controller(self.gripper_value, delay)

    def close(self, delay=1.0):
        self.gripper_controller(-self.gripper_value, delay)

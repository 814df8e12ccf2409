"""The driver on the simulated arm: ``xs_sdk_sim`` with ``~simulator`` true sends each 20 Hz
tick's joint positions (the motors' profiles, as with fake joints) to the simulator's
per-joint position controllers, those ``xsarm_gazebo.launch use_position_controllers:=true``
loads (``<joint>_controller``: Interbotix's ``<robot_model>_position_controllers.yaml``), and
the joint states are the simulator's (its joint_state_controller publishes them). A gripper's
horn angle becomes its fingers' positions through the linkage, and stops where a finger
would leave its joint limits, as the real gripper stops at its end stops (the fake joints,
like upstream's simulated driver, leave that to interbotix_xs_modules' gripper timer).

Interbotix's simulated driver drives no simulator (its ``use_sim`` means fake joints); this
is the workspace's way of running a script on Interbotix's Python API against the physics."""
from __future__ import annotations

import time
from typing import List, Sequence

import rospy
from controller_manager_msgs.srv import ListControllers
from sensor_msgs.msg import JointState
from std_msgs.msg import Float64

from xs_sdk_emulation.configs import MotorConfig

POLL = 0.1    # s (wall) between looks at the controller manager


class SimulatorUnavailable(RuntimeError):
    """The simulator's controllers did not come; the message names what is missing."""


def controlled_joints(config: MotorConfig) -> List[str]:
    """The simulator's joints the driver commands: the arm's motors and the grippers'
    fingers (a gripper's horn is no joint the simulator actuates)."""
    joints = [name for name in config.joint_order if name not in config.grippers]
    for gripper in config.grippers.values():
        joints += [gripper.left_finger, gripper.right_finger]
    return joints


class SimulatorJoints:
    """Position commands to ``<joint>_controller/command`` in the driver's namespace."""

    def __init__(self, config: MotorConfig, timeout: float):
        self.joints = controlled_joints(config)
        wanted = {f"{joint}_controller" for joint in self.joints}
        service = "controller_manager/list_controllers"
        deadline = time.monotonic() + timeout
        running: set = set()
        while not wanted <= running:
            if time.monotonic() > deadline:
                raise SimulatorUnavailable(
                    f"the simulator's position controllers {', '.join(sorted(wanted - running))} "
                    f"are not running in {rospy.get_namespace()} after {timeout:g} s (start the "
                    "arm with xsarm_gazebo.launch use_position_controllers:=true)")
            try:
                rospy.wait_for_service(service, timeout=max(POLL, deadline - time.monotonic()))
                answer = rospy.ServiceProxy(service, ListControllers)()
                running = {c.name for c in answer.controller if c.state == "running"}
            except (rospy.ROSException, rospy.ServiceException):
                pass
            if not wanted <= running:
                time.sleep(POLL)
        self.commands = {joint: rospy.Publisher(f"{joint}_controller/command", Float64,
                                                queue_size=1) for joint in self.joints}
        self.state_order = rospy.wait_for_message(config.joint_state_topic, JointState,
                                                  timeout=timeout).name

    def send(self, names: Sequence[str], positions: Sequence[float]) -> None:
        for name, position in zip(names, positions):
            publisher = self.commands.get(name)
            if publisher is not None:
                publisher.publish(Float64(position))

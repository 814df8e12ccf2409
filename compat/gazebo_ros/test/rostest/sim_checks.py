"""Helpers for sim_bridge's rostest nodes: ground truth from the simulator, driving, waiting."""
import math

import rospy
from geometry_msgs.msg import Twist
from std_srvs.srv import Empty

from sim_bridge.poses import yaw_from_quaternion
from gazebo_msgs.srv import GetModelState, GetWorldProperties
from sim_bridge.testing import TIMEOUT, wait_until  # noqa: F401 (the tests import them from here)


class Simulator:
    """The /gazebo interface, as a test uses it."""

    def __init__(self):
        for name in ("get_model_state", "get_world_properties", "pause_physics",
                     "unpause_physics"):
            rospy.wait_for_service(f"/gazebo/{name}", timeout=TIMEOUT)
        self.get_state = rospy.ServiceProxy("/gazebo/get_model_state", GetModelState)
        self.properties = rospy.ServiceProxy("/gazebo/get_world_properties", GetWorldProperties)
        self.pause = rospy.ServiceProxy("/gazebo/pause_physics", Empty)
        self.unpause = rospy.ServiceProxy("/gazebo/unpause_physics", Empty)

    def wait_for_model(self, name):
        wait_until(lambda: name in self.properties().model_names, f"model '{name}' to be spawned")

    def sim_time(self):
        return self.properties().sim_time

    def truth(self, model):
        """(x, y, yaw) of the model in the world, from the simulator."""
        state = self.get_state(model, "")
        assert state.success, state.status_message
        p = state.pose.position
        q = state.pose.orientation
        return p.x, p.y, yaw_from_quaternion((q.x, q.y, q.z, q.w))

    def wait_sim_time(self, target):
        wait_until(lambda: self.sim_time() >= target, f"simulated time {target:.2f} s",
                   interval=0.001)


def drive(simulator, publisher, linear, angular, duration):
    """Commands a twist for ``duration`` simulated seconds, bracketed by pauses, and stops.
    Starts from rest. Returns (elapsed simulated time, truth before, truth after)."""
    publisher.publish(Twist())
    simulator.wait_sim_time(simulator.sim_time() + 1.0)
    simulator.pause()
    start_time = simulator.sim_time()
    before = simulator.truth("diff_bot")
    command = Twist()
    command.linear.x, command.angular.z = linear, angular
    publisher.publish(command)
    simulator.unpause()
    simulator.wait_sim_time(start_time + duration)
    simulator.pause()
    elapsed = simulator.sim_time() - start_time
    after = simulator.truth("diff_bot")
    publisher.publish(Twist())
    simulator.unpause()
    return elapsed, before, after


def angle_difference(a, b):
    return math.atan2(math.sin(a - b), math.cos(a - b))

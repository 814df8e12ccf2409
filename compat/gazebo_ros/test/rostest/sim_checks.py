"""Helpers for sim_bridge's rostest nodes: ground truth from the simulator, driving, waiting."""
import math

from geometry_msgs.msg import Twist

# the tests import them from here
from sim_bridge.testing import TIMEOUT, Simulator, wait_until  # noqa: F401


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

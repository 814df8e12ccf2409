"""Helpers for the RB1 rostests: the simulator's truth about the RB1, waits with timeouts."""
import math
import threading

import rospy

from gazebo_msgs.msg import ModelStates
from sim_bridge.poses import rpy_from_quaternion
from gazebo_msgs.srv import GetModelState, GetWorldProperties
from sim_bridge.testing import TIMEOUT, service_proxy, wait_until  # noqa: F401 (the tests import them from here)

ROBOT = "my_rb1"
# my_rb1_robot_warehouse.launch's default spawn: the centre of the taped start square of the
# course's warehouse (rb1_base_gazebo: inside x -0.896 to 0.028, y -1.712 to -0.933)
START = (-0.434, -1.323)
SQUARE_X = (-0.896, 0.028)
SQUARE_Y = (-1.712, -0.933)


class Truth:
    """Where the RB1 really is, and its yaw accumulated from /gazebo/model_states (so full
    turns count)."""

    def __init__(self):
        self.get_state = service_proxy("/gazebo/get_model_state", GetModelState)
        self.properties = service_proxy("/gazebo/get_world_properties", GetWorldProperties)
        wait_until(lambda: ROBOT in self.properties().model_names, "the RB1 to be spawned")
        self._lock = threading.Lock()
        self.total_yaw = None
        self._last_yaw = None
        rospy.Subscriber("/gazebo/model_states", ModelStates, self._on_states, queue_size=100)
        wait_until(lambda: self.total_yaw is not None, "/gazebo/model_states")

    def _on_states(self, message):
        if ROBOT not in message.name:
            return
        q = message.pose[message.name.index(ROBOT)].orientation
        yaw = rpy_from_quaternion((q.x, q.y, q.z, q.w))[2]
        with self._lock:
            if self._last_yaw is None:
                self.total_yaw = yaw
            else:
                self.total_yaw += math.atan2(math.sin(yaw - self._last_yaw),
                                             math.cos(yaw - self._last_yaw))
            self._last_yaw = yaw

    def accumulated_yaw(self):
        with self._lock:
            return self.total_yaw

    def pose(self):
        """(x, y, roll, pitch, yaw) in the world."""
        state = self.get_state(ROBOT, "")
        p, q = state.pose.position, state.pose.orientation
        return (p.x, p.y, *rpy_from_quaternion((q.x, q.y, q.z, q.w)))

    def sim_time(self):
        return self.properties().sim_time

    def wait_sim_time(self, target):
        wait_until(lambda: self.sim_time() >= target, f"simulated time {target:.2f} s",
                   interval=0.005)

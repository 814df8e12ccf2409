"""For tests that run against sim_bridge (its own rostests and other packages'): waiting
on a condition with a timeout, in wall-clock time, instead of sleeping a fixed time, and the
/gazebo interface as a test uses it (ground truth, simulated time, pause)."""
from __future__ import annotations

import time

import rospy
from gazebo_msgs.srv import GetModelState, GetWorldProperties
from std_srvs.srv import Empty

from sim_bridge.poses import yaw_from_quaternion

TIMEOUT = 60.0  # wall seconds any one wait may take


def wait_until(condition, what: str, timeout: float = TIMEOUT, interval: float = 0.01) -> None:
    """Polls ``condition`` until it is true; AssertionError naming ``what`` after ``timeout``."""
    end = time.monotonic() + timeout
    while not rospy.is_shutdown():
        if condition():
            return
        if time.monotonic() > end:
            raise AssertionError(f"timed out after {timeout:.0f} s waiting for {what}")
        time.sleep(interval)


def service_proxy(name: str, service_class, timeout: float = TIMEOUT) -> rospy.ServiceProxy:
    """A proxy for ``name`` once the service is there (the simulator advertises its
    services one after another: one being up says nothing of the next)."""
    rospy.wait_for_service(name, timeout=timeout)
    return rospy.ServiceProxy(name, service_class)


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

    def pose(self, model):
        """The model's pose (geometry_msgs/Pose) in the world, from the simulator."""
        state = self.get_state(model, "")
        assert state.success, state.status_message
        return state.pose

    def truth(self, model):
        """(x, y, yaw) of the model in the world, from the simulator."""
        pose = self.pose(model)
        q = pose.orientation
        return pose.position.x, pose.position.y, yaw_from_quaternion((q.x, q.y, q.z, q.w))

    def wait_sim_time(self, target):
        wait_until(lambda: self.sim_time() >= target, f"simulated time {target:.2f} s",
                   interval=0.001)

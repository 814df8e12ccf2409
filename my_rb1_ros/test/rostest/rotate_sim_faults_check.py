#!/usr/bin/env python3
"""rostest node: /rotate_robot when simulated time stops (physics paused) or the robot is
teleported (reset_simulation during a turn). The answer is a failure that names the cause,
within the service's wall-clock bound for the pause; the next request turns the robot by
what it asks, in the simulator's truth."""
import math
import os
import sys
import threading
import time
import unittest

import rospy
import rostest
from std_srvs.srv import Empty

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rb1_checks import TIMEOUT, Truth, service_proxy, wait_until  # noqa: E402

from my_rb1_ros.srv import Rotate  # noqa: E402

# The service's own settings (config/rotate_service.yaml), read as it reads them.
SERVICE = "/rotate_service/"
# Wall seconds a failure may take beyond odom_timeout: the guards' poll and a loaded machine.
LATENESS = 1.5
ANGLE_TOLERANCE = 1.0  # degrees, as rotate.test
COASTING = 0.5  # simulated seconds after an answer for whatever motion remains
# The reset comes in the middle of the turn, when the robot faces well away from where it
# was spawned, so that being put back there is a jump odometry cannot mistake for turning.
MID_TURN = 90.0  # degrees turned in the rotation
AWAY_FROM_SPAWN = 45.0  # degrees between the heading and the spawn heading


def wrapped_degrees(radians):
    return math.degrees(math.atan2(math.sin(radians), math.cos(radians)))


class RotateWhenTheSimulatorMisbehaves(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("rotate_sim_faults_check")
        cls.truth = Truth()
        cls.pause = service_proxy("/gazebo/pause_physics", Empty)
        cls.unpause = service_proxy("/gazebo/unpause_physics", Empty)
        cls.reset = service_proxy("/gazebo/reset_simulation", Empty)
        rospy.wait_for_service("/rotate_robot", timeout=TIMEOUT)
        cls.rotate = rospy.ServiceProxy("/rotate_robot", Rotate)
        cls.odom_timeout = rospy.get_param(SERVICE + "odom_timeout")
        cls.truth.wait_sim_time(1.0)  # settled on its wheels
        cls.spawn_yaw = cls.truth.pose()[4]  # where a reset puts it back

    def tearDown(self):
        self.unpause()  # whatever happened, the next test has a running simulator

    def assert_rotation_works(self, degrees):
        before = self.truth.accumulated_yaw()
        answer = self.rotate(degrees).result
        self.truth.wait_sim_time(self.truth.sim_time() + COASTING)
        turned = math.degrees(self.truth.accumulated_yaw() - before)
        self.assertTrue(answer.startswith(f"success: rotated {degrees} degrees"), answer)
        self.assertAlmostEqual(turned, degrees, delta=ANGLE_TOLERANCE)
        rospy.loginfo(f"after the failure: rotate {degrees} turned {turned:.2f} degrees "
                      f"in truth ({answer})")

    def test_1_paused_physics_fails_in_wall_time_then_rotation_works(self):
        self.pause()
        x0, y0, _, _, yaw0 = self.truth.pose()
        started = time.monotonic()
        answer = self.rotate(90).result
        waited = time.monotonic() - started
        rospy.loginfo(f"paused: the call failed after {waited:.2f} s wall: {answer}")
        self.assertTrue(answer.startswith("failure"), answer)
        self.assertIn("physics paused", answer)
        self.assertGreaterEqual(waited, self.odom_timeout)
        self.assertLess(waited, self.odom_timeout + LATENESS)
        x1, y1, _, _, yaw1 = self.truth.pose()  # paused: nothing could move
        self.assertLess(math.hypot(x1 - x0, y1 - y0), 1e-6)
        self.assertLess(abs(wrapped_degrees(yaw1 - yaw0)), 1e-4)
        self.unpause()
        self.assert_rotation_works(90)

    def test_2_reset_during_a_full_turn_fails_naming_the_jump_then_rotation_works(self):
        first = {}
        before = self.truth.accumulated_yaw()
        worker = threading.Thread(target=lambda: first.update(answer=self.rotate(360).result))
        worker.start()
        wait_until(lambda: (abs(math.degrees(self.truth.accumulated_yaw() - before)) > MID_TURN
                            and abs(wrapped_degrees(self.truth.pose()[4] - self.spawn_yaw))
                            > AWAY_FROM_SPAWN),
                   "the robot to be half way and facing away from where it was spawned",
                   interval=0.001)
        turned = math.degrees(self.truth.accumulated_yaw() - before)
        self.reset()
        rospy.loginfo(f"reset after about {turned:.1f} degrees turned in truth")
        worker.join(TIMEOUT)
        self.assertFalse(worker.is_alive(), "the rotation did not answer")
        answer = first["answer"]
        rospy.loginfo(f"reset during rotate 360: {answer}")
        self.assertTrue(answer.startswith("failure"), answer)
        self.assertIn("odometry jumped", answer)
        self.assertIn("reset", answer)
        self.truth.wait_sim_time(self.truth.sim_time() + COASTING)
        self.assert_rotation_works(90)


if __name__ == "__main__":
    rostest.rosrun("my_rb1_ros", "rotate_sim_faults", RotateWhenTheSimulatorMisbehaves)

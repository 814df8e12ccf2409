#!/usr/bin/env python3
"""rostest node: teleop_twist_keyboard in a pseudo-terminal. Keys typed produce the expected
Twist messages; Ctrl-C ends it with a zero twist and the terminal's settings restored."""
import os
import subprocess
import termios
import unittest

import rospy
import rostest
from geometry_msgs.msg import Twist

from sim_bridge.testing import wait_until


class TeleopTerminal(unittest.TestCase):
    def test_keys_and_terminal(self):
        rospy.init_node("teleop_terminal_check")
        received = []
        rospy.Subscriber("/cmd_vel", Twist, received.append, queue_size=100)
        master, slave = os.openpty()
        before = termios.tcgetattr(slave)
        teleop = subprocess.Popen(["rosrun", "teleop_twist_keyboard", "teleop_twist_keyboard.py"],
                                  stdin=slave, stdout=slave, stderr=slave)
        try:
            wait_until(lambda: received, "the first command on /cmd_vel")

            def press(key, linear, angular):
                os.write(master, key.encode())
                wait_until(lambda: received and
                           abs(received[-1].linear.x - linear) < 1e-9 and
                           abs(received[-1].angular.z - angular) < 1e-9,
                           f"linear {linear}, angular {angular} after '{key}'", timeout=10)

            press("i", 0.5, 0.0)
            press("j", 0.0, 1.0)
            press("k", 0.0, 0.0)
            press("i", 0.5, 0.0)
            press("q", 0.55, 0.0)
            os.write(master, b"\x03")  # Ctrl-C
            teleop.wait(timeout=10)
        finally:
            if teleop.poll() is None:
                teleop.kill()
        self.assertEqual(teleop.returncode, 0)
        self.assertEqual(received[-1].linear.x, 0.0)
        self.assertEqual(termios.tcgetattr(slave), before)
        os.close(master)
        os.close(slave)


if __name__ == "__main__":
    rostest.rosrun("teleop_twist_keyboard", "teleop_terminal", TeleopTerminal)

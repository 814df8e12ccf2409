#!/usr/bin/env python3
"""rostest node: turtle_teleop_key in a pseudo-terminal, as tutorials/teleop_turtle_key.cpp
(ros/ros_tutorials noetic-devel db63288) behaves: it prints its three lines (:209-211),
publishes on turtle1/cmd_vel only for the arrow keys (:230-265), scaled by scale_linear and
scale_angular read beside the node, not under it (:175-176; the .test sets
/scale_linear 0.5, and /teleop_turtle/scale_linear 9 that must not count), quits on q
(:252-254) or Ctrl-C (:181-187) with the terminal's settings restored."""
import os
import select
import subprocess
import termios
import unittest

import rospy
import rostest
from geometry_msgs.msg import Twist

from sim_bridge.testing import wait_until

WAIT = 30.0  # s (wall)
UP, DOWN, RIGHT, LEFT = b"\x1b[A", b"\x1b[B", b"\x1b[C", b"\x1b[D"


class Terminal:
    """turtle_teleop_key on a pseudo-terminal: what it printed, keys typed to it."""

    def __init__(self):
        self.master, self.slave = os.openpty()
        self.before = termios.tcgetattr(self.slave)
        # in a session of its own whose controlling terminal is this one, so that Ctrl-C
        # typed here interrupts it as in a real terminal (setsid execs rosrun, rosrun the node)
        self.process = subprocess.Popen(
            ["setsid", "--ctty", "rosrun", "turtlesim", "turtle_teleop_key"],
            stdin=self.slave, stdout=self.slave, stderr=self.slave)
        self.output = b""

    def read(self):
        while select.select([self.master], [], [], 0)[0]:
            try:
                self.output += os.read(self.master, 4096)
            except OSError:  # the other side closed
                break
        return self.output.decode("utf-8", "replace")

    def type(self, keys):
        os.write(self.master, keys)

    def settings(self):
        return termios.tcgetattr(self.slave)

    def close(self):
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()
        os.close(self.master)
        os.close(self.slave)


class TeleopKey(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("turtlesim_teleop_key_check")
        cls.received = []
        rospy.Subscriber("/turtle1/cmd_vel", Twist, cls.received.append, queue_size=100)

    def start(self):
        terminal = Terminal()
        self.addCleanup(terminal.close)
        wait_until(lambda: "'q' to quit." in terminal.read(), "the teleop's help", WAIT)
        wait_until(lambda: terminal.settings()[3] & termios.ECHO == 0,
                   "the terminal in key mode", WAIT)
        return terminal

    def press(self, terminal, keys, linear, angular):
        count = len(self.received)
        terminal.type(keys)
        wait_until(lambda: len(self.received) > count, f"a Twist after {keys!r}", 10)
        twist = self.received[-1]
        self.assertEqual((twist.linear.x, twist.angular.z), (linear, angular))
        self.assertEqual((twist.linear.y, twist.linear.z, twist.angular.x, twist.angular.y),
                         (0.0,) * 4)

    def test_arrow_keys_then_q(self):
        terminal = self.start()
        self.assertIn("Reading from keyboard\r\n---------------------------\r\n"
                      "Use arrow keys to move the turtle. 'q' to quit.", terminal.read())
        # the first key again until this check's subscriber is connected (upstream
        # publishes only on a key: one pressed before the connection is lost)
        for _ in range(10):
            terminal.type(UP)
            try:
                wait_until(lambda: self.received, "a Twist after the up arrow", 2.0)
                break
            except AssertionError:
                continue
        self.press(terminal, UP, 0.5, 0.0)  # /scale_linear 0.5; ~scale_linear 9 not read
        self.press(terminal, LEFT, 0.0, 2.0)  # scale_angular unset: 2.0
        self.press(terminal, DOWN, -0.5, 0.0)
        self.press(terminal, RIGHT, 0.0, -2.0)
        count = len(self.received)
        terminal.type(b"xw [\x1b")  # no Twist for other keys
        self.press(terminal, b"A", 0.5, 0.0)  # the last byte of the up arrow's sequence
        self.assertEqual(len(self.received), count + 1)
        terminal.type(b"q")
        self.assertEqual(terminal.process.wait(timeout=WAIT), 0)
        self.assertEqual(terminal.settings(), terminal.before)
        self.assertNotIn("xw", terminal.read())  # keys were not echoed

    def test_ctrl_c_quits_and_restores_the_terminal(self):
        terminal = self.start()
        terminal.type(b"\x03")
        self.assertEqual(terminal.process.wait(timeout=WAIT), 0)
        self.assertEqual(terminal.settings(), terminal.before)


if __name__ == "__main__":
    rostest.rosrun("turtlesim", "turtlesim_teleop_key", TeleopKey)

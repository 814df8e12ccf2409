#!/usr/bin/env python3
"""rostest node: /clock comes every step unless use_clock_frequency sets a rate, as gazebo_ros
publishes it (a student's ros::Rate(1000) in simulated time then wakes every 1 ms step, not
every 4 ms: an open-loop turn timed that way went 2.5 times too far). A rospy.Rate(1000)
loop's count is no measure of it: rospy's Rate catches up in bursts when it falls behind,
and a Python subscriber on a loaded 2-core machine misses /clock messages (measured: 354
turns a simulated second at every step, 595 at 250 Hz, with a test suite beside it)."""
import time
import unittest

import rospy
import rostest
from rosgraph_msgs.msg import Clock

MESSAGES = 300
TIMEOUT = 60.0  # s (wall)


class ClockRate(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("clock_rate_check")

    def test_the_clock_period(self):
        expected = float(rospy.get_param("~period"))  # s of simulated time
        times = []
        subscriber = rospy.Subscriber("/clock", Clock,
                                      lambda message: times.append(message.clock.to_sec()),
                                      queue_size=None)
        limit = time.monotonic() + TIMEOUT  # wall time: simulated time runs ahead of it
        while len(times) < MESSAGES and time.monotonic() < limit:
            time.sleep(0.01)
        subscriber.unregister()
        self.assertGreaterEqual(len(times), MESSAGES, "too few /clock messages")
        gaps = [b - a for a, b in zip(times, times[1:]) if b > a]
        # the shortest gap is the publishing period: a Python subscriber misses some messages
        # (the publisher's queue of 10 drops the oldest while a burst of steps holds the
        # interpreter, as roscpp's queue does in Gazebo), so longer gaps say nothing
        self.assertAlmostEqual(min(gaps), expected, delta=1e-6)


if __name__ == "__main__":
    rostest.rosrun("gazebo_ros", "clock_rate", ClockRate)

#!/usr/bin/env python3
"""rostest node beside the flip routine: for 60 s of simulated time after its first command,
the robot's true pose (/gazebo/model_states) must show at least 4 flips (the body's up axis
changing sign) and 4 reversals of its travel along its starting line, no point more than
0.5 m from that line sideways, and no command with a nonzero angular velocity."""
import math
import threading
import unittest

import rospy
import rostest
from geometry_msgs.msg import Twist

from diff_drive.flip import FlipCounter, up_axis_z
from gazebo_msgs.msg import ModelStates
from sim_bridge.poses import yaw_from_quaternion
from sim_bridge.testing import wait_until

ROBOT = "ddrive"
DURATION = 60.0       # s of simulated time
MIN_FLIPS = 4
MIN_REVERSALS = 4
MAX_SIDEWAYS = 0.5    # m from the starting line
MOVING = 0.3          # m/s along the line: slower samples do not count for the direction
SAMPLE = 0.1          # s of simulated time between the poses compared for the direction


class FlipRoutine(unittest.TestCase):
    def setUp(self):
        rospy.init_node("flip_check")
        self.lock = threading.Lock()
        self.commands = []       # (sim time, linear.x, angular as a tuple)
        self.poses = []          # (sim time, x, y, up z)
        rospy.Subscriber("/diff/cmd_vel", Twist, self.on_command, queue_size=100)
        rospy.Subscriber("/gazebo/model_states", ModelStates, self.on_states, queue_size=100)

    def on_command(self, twist):
        with self.lock:
            self.commands.append((rospy.get_time(), twist.linear.x,
                                  (twist.angular.x, twist.angular.y, twist.angular.z)))

    def on_states(self, states):
        if ROBOT not in states.name or not self.commands:
            return
        pose = states.pose[states.name.index(ROBOT)]
        q = pose.orientation
        with self.lock:
            if not self.poses:  # the body's x axis, on the ground plane
                self.start_heading = yaw_from_quaternion((q.x, q.y, q.z, q.w))
            self.poses.append((rospy.get_time(), pose.position.x, pose.position.y,
                               up_axis_z(q.x, q.y, q.z, q.w)))

    def test_flips_reverses_and_keeps_to_its_line(self):
        wait_until(lambda: self.commands, "the flip routine's first command")
        with self.lock:
            first = self.commands[0][0]
        # 60 s of simulated time at several times real time; the wall-clock limit is generous
        wait_until(lambda: self.poses and self.poses[-1][0] >= first + DURATION,
                   "60 s of simulated flipping", timeout=150.0)
        with self.lock:
            poses = [p for p in self.poses if p[0] <= first + DURATION]
            commands = [c for c in self.commands if c[0] <= first + DURATION]

        turning = [c for c in commands if any(a != 0.0 for a in c[2])]
        self.assertEqual(turning, [], "commands with a nonzero angular velocity")
        self.assertGreater(len({math.copysign(1, c[1]) for c in commands}), 1,
                           "the routine never reversed its command")

        counter = FlipCounter()
        for pose in poses:
            counter.update(pose[3])

        # the starting line: through the first pose, along the robot's heading there
        t0, x0, y0, _ = poses[0]
        ux, uy = math.cos(self.start_heading), math.sin(self.start_heading)
        along = [(p[0], (p[1] - x0) * ux + (p[2] - y0) * uy) for p in poses]
        sideways = max(abs(-(p[1] - x0) * uy + (p[2] - y0) * ux) for p in poses)

        directions, last = [], None
        for t, s in along:
            if last is None or t - last[0] >= SAMPLE:
                if last is not None:
                    speed = (s - last[1]) / (t - last[0])
                    if abs(speed) > MOVING:
                        directions.append(speed > 0)
                last = (t, s)
        reversals = sum(1 for a, b in zip(directions, directions[1:]) if a != b)

        summary = (f"{counter.flips} flips, {reversals} reversals, {sideways:.2f} m sideways "
                   f"at most, {len(poses)} poses over {poses[-1][0] - t0:.1f} s, "
                   f"travel {min(s for _, s in along):.2f}..{max(s for _, s in along):.2f} m")
        rospy.loginfo("flip_check: %s", summary)
        self.assertGreater(poses[-1][0] - t0, DURATION - 1.0, summary)
        self.assertGreaterEqual(counter.flips, MIN_FLIPS, summary)
        self.assertGreaterEqual(reversals, MIN_REVERSALS, summary)
        self.assertLess(sideways, MAX_SIDEWAYS, summary)


if __name__ == "__main__":
    rostest.rosrun("diff_drive", "flip_routine", FlipRoutine)

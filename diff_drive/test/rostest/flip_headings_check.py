#!/usr/bin/env python3
"""rostest node beside the flip routines of several robots (parameter ~robots: model name
and command topic of each). For 60 s of simulated time from the first true pose seen after
each robot's first command, its true pose (/gazebo/model_states) must show at least 4 flips (the body's up axis
changing sign) and 4 reversals of its travel along its starting line, no point more than
0.2 m from that line sideways, its heading within 5 degrees of the line's whenever it lies
flat, and no command with a nonzero angular velocity. The same limits at every heading:
the simulator's friction must not depend on which way the robot faces."""
import math
import threading
import unittest

import rospy
import rostest
from geometry_msgs.msg import Twist
from tf.transformations import quaternion_matrix

from diff_drive.flip import FlipCounter, FlipSettings, load_defaults, packaged_settings_path
from gazebo_msgs.msg import ModelStates
from sim_bridge.testing import wait_until

DURATION = 60.0             # s of simulated time
MIN_FLIPS = 4
MIN_REVERSALS = 4
MAX_SIDEWAYS = 0.2          # m from the starting line
MAX_DRIFT = math.radians(5.0)
FLAT = 0.7                  # |up z| above which the body lies flat and has a heading
MOVING = 0.3                # m/s along the line: slower samples do not count for the direction
SAMPLE = 0.1                # s of simulated time between the poses compared for the direction


def axes(q):
    """(forward x, forward y, up z) of the body, from its orientation quaternion."""
    matrix = quaternion_matrix((q.x, q.y, q.z, q.w))
    return matrix[0][0], matrix[1][0], matrix[2][2]


def line_offset(angle):
    """``angle`` folded onto (-pi/2, pi/2]: a flip turns the body's x axis around, and the
    line is the same line either way."""
    return (angle + math.pi / 2) % math.pi - math.pi / 2


class Robot:
    """What one robot's commands and true poses were."""

    def __init__(self, model, commands):
        self.model = model
        self.lock = threading.Lock()
        self.commands = []  # (sim time, linear.x, angular as a tuple)
        self.poses = []     # (sim time, x, y, forward x, forward y, up z)
        rospy.Subscriber(commands, Twist, self.on_command, queue_size=100)

    def on_command(self, twist):
        with self.lock:
            self.commands.append((rospy.get_time(), twist.linear.x,
                                  (twist.angular.x, twist.angular.y, twist.angular.z)))

    def on_pose(self, stamp, pose):
        with self.lock:
            if self.commands:
                self.poses.append((stamp, pose.position.x, pose.position.y)
                                  + axes(pose.orientation))

    def done(self):
        with self.lock:
            return bool(self.poses and self.poses[-1][0] >= self.poses[0][0] + DURATION)

    def judge(self, case):
        with self.lock:
            # from the first pose (the state topic's first message may come a little
            # after the first command on a loaded machine)
            first = self.poses[0][0]
            poses = [p for p in self.poses if p[0] <= first + DURATION]
            commands = [c for c in self.commands if c[0] <= first + DURATION]
        turning = [c for c in commands if any(a != 0.0 for a in c[2])]
        case.assertEqual(turning, [], f"{self.model}: commands with an angular velocity")
        case.assertGreater(len({math.copysign(1, c[1]) for c in commands}), 1,
                           f"{self.model}: the routine never reversed its command")

        counter = FlipCounter()
        for pose in poses:
            counter.update(pose[5])
        # the starting line: through the first pose, along the robot's heading where it
        # first lies flat (the first pose may be mid-flip, pointing up)
        t0, x0, y0 = poses[0][:3]
        fx, fy = next(p[3:5] for p in poses if abs(p[5]) > FLAT)
        heading = math.atan2(fy, fx)
        ux, uy = math.cos(heading), math.sin(heading)
        along = [(p[0], (p[1] - x0) * ux + (p[2] - y0) * uy) for p in poses]
        sideways = max(abs(-(p[1] - x0) * uy + (p[2] - y0) * ux) for p in poses)
        drift = max(abs(line_offset(math.atan2(p[4], p[3]) - heading))
                    for p in poses if abs(p[5]) > FLAT)

        directions, last = [], None
        for t, s in along:
            if last is None or t - last[0] >= SAMPLE:
                if last is not None:
                    speed = (s - last[1]) / (t - last[0])
                    if abs(speed) > MOVING:
                        directions.append(speed > 0)
                last = (t, s)
        reversals = sum(1 for a, b in zip(directions, directions[1:]) if a != b)
        # when the commanded reversals reached this node, against the routine's own schedule
        # (legs of leg_time): each reversal's delay from the first one's, less whole legs.
        # The simulator's share of the timing; the first command is no reference (it may
        # have been published before this node was connected).
        leg_time = FlipSettings.from_mapping(load_defaults(packaged_settings_path()),
                                             "flip.yaml").leg_time
        switches = [t for (t, v, _), (_, before, _) in zip(commands[1:], commands)
                    if v != before]
        late = [t - switches[0] - round((t - switches[0]) / leg_time) * leg_time
                for t in switches]
        summary = (f"{self.model} heading {math.degrees(heading):.0f} deg: {counter.flips} "
                   f"flips, {reversals} reversals, {sideways:.3f} m sideways and "
                   f"{math.degrees(drift):.1f} deg off the line at most, {len(poses)} poses "
                   f"over {poses[-1][0] - t0:.1f} s, travel "
                   f"{min(s for _, s in along):.2f}..{max(s for _, s in along):.2f} m, "
                   f"reversals received {1000 * min(late):+.0f}..{1000 * max(late):+.0f} ms "
                   f"from the first one's schedule")
        rospy.loginfo("flip_headings_check: %s", summary)
        case.assertGreater(poses[-1][0] - t0, DURATION - 1.0, summary)
        case.assertGreaterEqual(counter.flips, MIN_FLIPS, summary)
        case.assertGreaterEqual(reversals, MIN_REVERSALS, summary)
        case.assertLess(sideways, MAX_SIDEWAYS, summary)
        case.assertLess(drift, MAX_DRIFT, summary)


class FlipAtEveryHeading(unittest.TestCase):
    def setUp(self):
        rospy.init_node("flip_headings_check")
        self.robots = {entry["model"]: Robot(entry["model"], entry["commands"])
                       for entry in rospy.get_param("~robots")}
        rospy.Subscriber("/gazebo/model_states", ModelStates, self.on_states, queue_size=100)

    def on_states(self, states):
        stamp = rospy.get_time()
        for name, pose in zip(states.name, states.pose):
            if name in self.robots:
                self.robots[name].on_pose(stamp, pose)

    def test_each_robot_flips_along_its_line(self):
        # 60 s of simulated time for four robots: about 35 s at twice real time, 70 s at real time
        wait_until(lambda: all(r.done() for r in self.robots.values()),
                   "60 s of simulated flipping by every robot", timeout=200.0)
        for robot in self.robots.values():
            robot.judge(self)


if __name__ == "__main__":
    rostest.rosrun("diff_drive", "flip_headings", FlipAtEveryHeading)

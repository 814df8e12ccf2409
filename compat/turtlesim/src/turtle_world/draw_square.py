"""``rosrun turtlesim draw_square``: turtle1 drives squares of 2 m sides.

As turtlesim 0.10.2's tutorials/draw_square.cpp (ros/ros_tutorials noetic-devel, db63288):
node ``draw_square`` (:152) calls ``reset`` once (:156-160), then every 0.016 s (:157, ROS
time) drives turtle1 through four states: forward at 1.0 m/s to a goal 2 m ahead, stop,
turn at 0.4 rad/s to the heading pi/2 further, stop, and again (:89-148). It reads
``turtle1/pose`` and publishes ``turtle1/cmd_vel`` (queues of 1, :154-155).

:class:`SquareDriver` is that state machine without ROS.
"""
from __future__ import annotations

import math
from typing import List, Optional, Tuple

import rospy
from geometry_msgs.msg import Twist
from std_srvs.srv import Empty
from turtlesim.msg import Pose

from turtle_world.world import f32

PI = 3.141592  # draw_square.cpp:22 (its own, shorter than turtlesim's)
PERIOD = 0.016  # s (:157)
FORWARD_SPEED = 1.0  # m/s (:98)
TURN_SPEED = 0.4  # rad/s (:111)
SIDE = 2.0  # m (:77-78, :126-127)
FORWARD, STOP_FORWARD, TURN, STOP_TURN = "forward", "stop_forward", "turn", "stop_turn"


class SquareDriver:
    """The tutorial's state machine (draw_square.cpp:7-148). The goal is kept in a Pose's
    32-bit floats, as upstream's."""

    def __init__(self):
        self.state = FORWARD
        self.goal: Optional[Tuple[float, float, float]] = None

    def _set_goal(self, x: float, y: float, theta: float, log: List[str]) -> None:
        self.goal = (f32(x), f32(y), f32(theta))
        log.append("New goal [%f %f, %f]" % self.goal)  # :41

    def _ahead(self, pose, log: List[str]) -> None:
        """The next corner: SIDE metres along the heading (:77-79, :126-128)."""
        self._set_goal(math.cos(pose.theta) * SIDE + pose.x,
                       math.sin(pose.theta) * SIDE + pose.y, pose.theta, log)

    def _reached(self, pose) -> bool:  # :29-32
        x, y, theta = self.goal
        return abs(pose.x - x) < 0.1 and abs(pose.y - y) < 0.1 and abs(pose.theta - theta) < 0.01

    @staticmethod
    def _stopped(pose) -> bool:  # :34-37 (signed: turning backwards counts as stopped)
        return pose.angular_velocity < 0.0001 and pose.linear_velocity < 0.0001

    def step(self, pose) -> Tuple[Optional[Tuple[float, float]], List[str]]:
        """One timer tick with the latest pose (None before the first): the (linear.x,
        angular.z) to publish or None, and the lines to log (:115-148)."""
        log: List[str] = []
        if pose is None:
            return None, log
        if self.goal is None:  # :122-130
            self.state = FORWARD
            self._ahead(pose, log)
        if self.state == FORWARD:  # :89-100
            if self._reached(pose):
                self.state = STOP_FORWARD
                return (0.0, 0.0), log
            return (FORWARD_SPEED, 0.0), log
        if self.state == TURN:  # :102-113
            if self._reached(pose):
                self.state = STOP_TURN
                return (0.0, 0.0), log
            return (0.0, TURN_SPEED), log
        if not self._stopped(pose):  # :52-86: both stop states wait for a standstill
            return (0.0, 0.0), log
        log.append("Reached goal")
        if self.state == STOP_FORWARD:
            self.state = TURN
            theta = f32(math.fmod(pose.theta + PI / 2.0, 2 * PI))
            if theta >= PI:  # :60-62
                theta -= 2 * PI
            self._set_goal(pose.x, pose.y, theta, log)
        else:
            self.state = FORWARD
            self._ahead(pose, log)
        return None, log


def main() -> int:
    rospy.init_node("draw_square")
    latest: List[Optional[Pose]] = [None]
    rospy.Subscriber("turtle1/pose", Pose, lambda pose: latest.__setitem__(0, pose),
                     queue_size=1)
    publisher = rospy.Publisher("turtle1/cmd_vel", Twist, queue_size=1)
    try:
        rospy.ServiceProxy("reset", Empty)()
    except (rospy.ServiceException, rospy.ROSException) as error:
        rospy.logwarn("could not reset turtlesim (%s); drawing from where turtle1 is", error)
    driver = SquareDriver()

    def tick(_event):
        move, log = driver.step(latest[0])
        for line in log:
            rospy.loginfo(line)
        if move is not None:
            twist = Twist()
            twist.linear.x, twist.angular.z = move
            publisher.publish(twist)

    rospy.Timer(rospy.Duration(PERIOD), tick)
    rospy.spin()
    return 0

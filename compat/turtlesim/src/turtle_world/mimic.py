"""``rosrun turtlesim mimic``: one turtle does what another does.

As turtlesim 0.10.2's tutorials/mimic.cpp (ros/ros_tutorials noetic-devel, db63288): node
``turtle_mimic`` (:35) reads ``input/pose`` and publishes on ``output/cmd_vel`` (queues of
1, :19-22) a Twist with linear.x = the pose's linear_velocity and angular.z = its
angular_velocity (:27-30). ``input`` and ``output`` are namespaces (node handles, :19-20),
which roscpp remaps as names: the roslaunch tutorial's ``<remap from="input"
to="turtlesim1/turtle1"/>`` moves both topics under them. rospy remaps whole names only, so
the namespaces are resolved (and remapped) here first.
"""
from __future__ import annotations

import rospy
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose


def mirror(pose: Pose) -> Twist:
    """The command that makes another turtle move as this pose says this one does."""
    twist = Twist()
    twist.linear.x = pose.linear_velocity
    twist.angular.z = pose.angular_velocity
    return twist


def main() -> int:
    rospy.init_node("turtle_mimic")
    publisher = rospy.Publisher(rospy.resolve_name("output") + "/cmd_vel", Twist, queue_size=1)
    rospy.Subscriber(rospy.resolve_name("input") + "/pose", Pose,
                     lambda pose: publisher.publish(mirror(pose)), queue_size=1)
    rospy.spin()
    return 0

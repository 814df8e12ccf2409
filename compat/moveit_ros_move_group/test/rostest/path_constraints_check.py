#!/usr/bin/env python3
"""rostest node: MoveIt's tutorial case through move_group. moveit_commander's
set_path_constraints with an OrientationConstraint on the tool (the tutorial's 0.1 rad on
each axis, 10 s of planning time) reaches the request: every waypoint of the plan to a pose
goal keeps the tool's orientation (urdf_tools' forward kinematics, tf's intrinsic XYZ Euler
angles), the executed plan puts the tool on the goal (/joint_states); after
clear_path_constraints the plan back is the unconstrained straight line, which turns the
tool beyond the tolerance."""
import sys
import unittest

import numpy as np
import rospy
import rostest
from geometry_msgs.msg import Pose
from moveit_msgs.msg import Constraints, OrientationConstraint
from sensor_msgs.msg import JointState
from tf.transformations import euler_from_matrix, quaternion_from_matrix

import moveit_commander
from urdf_tools import parse_urdf
from urdf_tools.kinematics import link_transform

TIMEOUT = 30.0
GROUP = "manipulator"
BASE, TIP = "base_link", "tool0"
READY = {"shoulder_pan_joint": 0.0, "shoulder_lift_joint": 0.4, "elbow_joint": 0.8,
         "wrist_1_joint": 0.3, "wrist_2_joint": 0.5, "wrist_3_joint": 0.0}   # the SRDF's
# move_group_interface_tutorial.cpp (moveit_tutorials noetic-devel): its tolerances and time
TOLERANCE = 0.1
PLANNING_TIME = 10.0
GOAL_SHIFT = (-0.2, -0.4, 0.1)     # m: reached only by turning the wrist on the way
METRES, RADIANS = 0.001, 0.01      # how close the executed goal must be


def wait_until(condition, timeout=TIMEOUT, what="a condition"):
    deadline = rospy.get_time() + timeout
    while not rospy.is_shutdown():
        value = condition()
        if value:
            return value
        if rospy.get_time() > deadline:
            raise AssertionError(f"timed out after {timeout:.0f} s waiting for {what}")
        rospy.sleep(0.02)
    raise AssertionError("shut down")


class PathConstraints(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        moveit_commander.roscpp_initialize(sys.argv)
        rospy.init_node("path_constraints_check")
        cls.urdf = parse_urdf(rospy.get_param("/robot_description"))
        cls.joints = {}
        rospy.Subscriber("/joint_states", JointState, cls._on_joints)
        wait_until(lambda: cls.joints and all(abs(cls.joints.get(j, 9) - v) < 1e-6
                                              for j, v in READY.items()),
                   what="joint_states at the 'ready' state")
        cls.group = moveit_commander.MoveGroupCommander(GROUP, wait_for_servers=TIMEOUT)

    @classmethod
    def _on_joints(cls, message):
        cls.joints = dict(zip(message.name, message.position))

    def tool(self, positions):
        return link_transform(self.urdf, BASE, TIP, positions)

    def errors(self, begin, trajectory):
        names = trajectory.joint_trajectory.joint_names
        rotations = []
        for point in trajectory.joint_trajectory.points:
            relative = np.eye(4)
            tool = self.tool(dict(zip(names, point.positions)))
            relative[:3, :3] = begin[:3, :3].T @ tool[:3, :3]
            rotations.append(np.abs(euler_from_matrix(relative, "rxyz")).max())
        return rotations

    def test_the_tutorials_orientation_constraint(self):
        begin = self.tool(READY)
        constraint = OrientationConstraint(link_name=TIP, weight=1.0,
                                           absolute_x_axis_tolerance=TOLERANCE,
                                           absolute_y_axis_tolerance=TOLERANCE,
                                           absolute_z_axis_tolerance=TOLERANCE)
        constraint.header.frame_id = BASE
        (constraint.orientation.x, constraint.orientation.y, constraint.orientation.z,
         constraint.orientation.w) = quaternion_from_matrix(begin)
        self.group.set_path_constraints(Constraints(orientation_constraints=[constraint]))
        self.assertEqual(len(self.group.get_path_constraints().orientation_constraints), 1)
        self.group.set_planning_time(PLANNING_TIME)
        target = Pose(orientation=constraint.orientation)
        target.position.x, target.position.y, target.position.z = \
            np.array(begin[:3, 3]) + GOAL_SHIFT
        self.group.set_pose_target(target)
        success, trajectory, _, code = self.group.plan()
        self.assertTrue(success, code)
        errors = self.errors(begin, trajectory)
        self.assertGreater(len(errors), 2)
        self.assertLess(max(errors), TOLERANCE, errors)
        self.assertTrue(self.group.execute(trajectory, wait=True))
        goal = np.array(begin)
        goal[:3, 3] += GOAL_SHIFT
        wait_until(lambda: np.linalg.norm(self.tool(self.joints)[:3, 3] - goal[:3, 3]) <= METRES,
                   what="the tool at the goal")
        turned = begin[:3, :3].T @ self.tool(self.joints)[:3, :3]
        self.assertLess(np.arccos(min(1.0, (np.trace(turned) - 1) / 2)), RADIANS)

        # cleared: the plan back to 'ready' is the straight joint-space line, which does not
        # keep the orientation
        self.group.clear_path_constraints()
        self.assertEqual(self.group.get_path_constraints(), Constraints())
        self.group.clear_pose_targets()
        self.group.set_joint_value_target(READY)
        success, trajectory, _, code = self.group.plan()
        self.assertTrue(success, code)
        self.assertGreater(max(self.errors(begin, trajectory)), TOLERANCE)


if __name__ == "__main__":
    rostest.rosrun("moveit_ros_move_group", "path_constraints", PathConstraints)

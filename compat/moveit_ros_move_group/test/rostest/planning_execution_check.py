#!/usr/bin/env python3
"""rostest node: move_group plans (plan only: the robot stays) and executes on fake
controllers (the robot arrives: /joint_states and TF); the scene from collision_object and
apply_planning_scene; MoveIt's codes for a goal in a box, a bad scene message, a trajectory
that does not start where the robot is; pick and place refused; a Cartesian path lands
where asked; check_state_validity names the contacts."""
import math
import unittest

import actionlib
from actionlib.action_client import CommState
import numpy as np
import rospy
import rostest
import tf2_ros
from geometry_msgs.msg import Pose
from moveit_msgs.msg import (CollisionObject, Constraints, ExecuteTrajectoryAction,
                             ExecuteTrajectoryGoal, JointConstraint, MoveGroupAction,
                             MoveGroupGoal, MoveItErrorCodes as Codes, PickupAction, PickupGoal,
                             PlanningScene, PositionConstraint, RobotTrajectory)
from moveit_msgs.srv import (ApplyPlanningScene, GetCartesianPath, GetCartesianPathRequest,
                             GetPlanningScene, GetStateValidity, GetStateValidityRequest)
from sensor_msgs.msg import JointState
from shape_msgs.msg import SolidPrimitive
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

TIMEOUT = 30.0
ARM = ["waist", "shoulder", "elbow", "wrist_angle"]
TIP = "px100/ee_gripper_link"


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


def joint_goal(positions, plan_only):
    goal = MoveGroupGoal()
    goal.request.group_name = "interbotix_arm"
    goal.request.allowed_planning_time = 5.0
    goal.request.max_velocity_scaling_factor = 1.0
    goal.request.max_acceleration_scaling_factor = 1.0
    goal.request.goal_constraints = [Constraints(joint_constraints=[
        JointConstraint(joint_name=j, position=p, tolerance_above=1e-4, tolerance_below=1e-4,
                        weight=1.0) for j, p in zip(ARM, positions)])]
    goal.planning_options.plan_only = plan_only
    return goal


def box(name, xyz, size):
    message = CollisionObject(id=name, operation=CollisionObject.ADD)
    message.header.frame_id = "world"
    message.pose.position.x, message.pose.position.y, message.pose.position.z = xyz
    message.pose.orientation.w = 1.0
    message.primitives = [SolidPrimitive(type=SolidPrimitive.BOX, dimensions=list(size))]
    message.primitive_poses = [Pose()]
    message.primitive_poses[0].orientation.w = 1.0
    return message


class PlanningExecution(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("planning_execution_check")
        cls.joints = {}
        rospy.Subscriber("/joint_states", JointState, lambda m: cls.joints.update(
            zip(m.name, m.position)), queue_size=10)
        cls.buffer = tf2_ros.Buffer()
        cls.listener = tf2_ros.TransformListener(cls.buffer)
        # ActionClient, not SimpleActionClient: rospy's SimpleActionClient drops the
        # transitions of a goal refused before send_goal has stored its handle (pickup's
        # answer comes within a millisecond) and waits for ever; the handle has them
        cls.move = actionlib.ActionClient("/move_group", MoveGroupAction)
        cls.execute = actionlib.ActionClient("/execute_trajectory", ExecuteTrajectoryAction)
        cls.pickup = actionlib.ActionClient("/pickup", PickupAction)
        for client in (cls.move, cls.execute, cls.pickup):
            assert client.wait_for_server(rospy.Duration(TIMEOUT)), client.ns
        cls.objects = rospy.Publisher("/collision_object", CollisionObject, queue_size=10)
        cls.get_scene = rospy.ServiceProxy("/get_planning_scene", GetPlanningScene)
        cls.apply_scene = rospy.ServiceProxy("/apply_planning_scene", ApplyPlanningScene)
        cls.cartesian = rospy.ServiceProxy("/compute_cartesian_path", GetCartesianPath)
        cls.validity = rospy.ServiceProxy("/check_state_validity", GetStateValidity)
        wait_until(lambda: set(ARM) <= set(cls.joints), what="/joint_states")

    def run_goal(self, goal, client=None):
        """The goal's result once it is done; its handle is ``self.handle``."""
        self.handle = (client or self.move).send_goal(goal)
        wait_until(lambda: self.handle.get_comm_state() == CommState.DONE, what="the result")
        return self.handle.get_result()

    def arm(self):
        return [self.joints[j] for j in ARM]

    def test_0_every_initial_group_state_is_published(self):
        """The fake controllers' initial states of both groups reach /joint_states (one
        latched message: a later one would hide the first)."""
        wait_until(lambda: abs(self.joints.get("left_finger", 0.0) - 0.037) < 1e-6,
                   what="the gripper's initial Open state")
        np.testing.assert_allclose(self.arm(), [0.0, -1.88, 1.5, 0.8], atol=1e-9)   # Sleep

    def test_1_plan_only_leaves_the_robot_and_execution_moves_it(self):
        before = self.arm()
        target = [0.5, -0.3, 0.4, 0.2]
        result = self.run_goal(joint_goal(target, plan_only=True))
        self.assertEqual(result.error_code.val, Codes.SUCCESS)
        points = result.planned_trajectory.joint_trajectory.points
        np.testing.assert_allclose(points[-1].positions, target, atol=1e-4)
        rospy.sleep(0.3)
        np.testing.assert_allclose(self.arm(), before, atol=1e-6)
        result = self.run_goal(joint_goal(target, plan_only=False))
        self.assertEqual(result.error_code.val, Codes.SUCCESS)
        wait_until(lambda: np.allclose(self.arm(), target, atol=0.01), 5, "the arm at the goal")
        # TF agrees: the wrist turned by the goal's wrist_angle
        rotation = wait_until(lambda: self._wrist(target[3]), 5, "TF of the goal")
        self.assertTrue(rotation)

    def _wrist(self, angle):
        try:
            q = self.buffer.lookup_transform("px100/forearm_link", "px100/gripper_link",
                                             rospy.Time(0)).transform.rotation
        except tf2_ros.TransformException:
            return False
        return abs(2 * math.atan2(q.y, q.w) - angle) < 0.01

    def test_2_the_scene_a_goal_in_a_box_and_a_bad_scene_message(self):
        self.objects.publish(box("crate", (0.2, 0.0, 0.05), (0.08, 0.08, 0.08)))
        wait_until(lambda: [o.id for o in self.get_scene().scene.world.collision_objects]
                   == ["crate"], what="the crate in the scene")
        goal = MoveGroupGoal()
        goal.request.group_name = "interbotix_arm"
        goal.request.allowed_planning_time = 2.0
        constraint = PositionConstraint(link_name=TIP, weight=1.0)
        constraint.header.frame_id = "world"
        constraint.constraint_region.primitives = [
            SolidPrimitive(type=SolidPrimitive.SPHERE, dimensions=[1e-4])]
        inside = Pose()
        inside.position.x, inside.position.z, inside.orientation.w = 0.2, 0.05, 1.0
        constraint.constraint_region.primitive_poses = [inside]
        goal.request.goal_constraints = [Constraints(position_constraints=[constraint])]
        goal.planning_options.plan_only = True
        self.assertEqual(self.run_goal(goal).error_code.val, Codes.PLANNING_FAILED)
        bad = PlanningScene(is_diff=True)
        bad.world.collision_objects = [box("flat", (0, 0, 0), (0.1, 0.0, 0.1))]
        self.assertFalse(self.apply_scene(bad).success)
        removal = PlanningScene(is_diff=True)
        removal.world.collision_objects = [CollisionObject(id="crate",
                                                           operation=CollisionObject.REMOVE)]
        self.assertTrue(self.apply_scene(removal).success)
        self.assertEqual(self.get_scene().scene.world.collision_objects, [])

    def test_3_a_trajectory_away_from_the_robot_is_refused(self):
        trajectory = RobotTrajectory(joint_trajectory=JointTrajectory(joint_names=ARM, points=[
            JointTrajectoryPoint(positions=[1.0, 0.0, 0.0, 0.0],
                                 time_from_start=rospy.Duration(0)),
            JointTrajectoryPoint(positions=[1.1, 0.0, 0.0, 0.0],
                                 time_from_start=rospy.Duration(1))]))
        result = self.run_goal(ExecuteTrajectoryGoal(trajectory=trajectory), self.execute)
        self.assertEqual(result.error_code.val, Codes.CONTROL_FAILED)

    def test_4_pick_and_place_are_refused_saying_so(self):
        result = self.run_goal(PickupGoal(target_name="crate", group_name="interbotix_arm"),
                               self.pickup)
        self.assertEqual(result.error_code.val, Codes.FAILURE)
        self.assertIn("not provided", self.handle.get_goal_status_text())

    def test_5_a_cartesian_path_and_state_validity(self):
        start = self.buffer.lookup_transform("world", TIP, rospy.Time(0)).transform.translation
        request = GetCartesianPathRequest(group_name="interbotix_arm", max_step=0.005,
                                          avoid_collisions=True)
        request.header.frame_id = "world"
        waypoint = Pose()
        waypoint.position.x, waypoint.position.y = start.x, start.y
        waypoint.position.z = start.z - 0.04
        waypoint.orientation.w = 1.0
        request.waypoints = [waypoint]
        answer = self.cartesian(request)
        self.assertEqual(answer.error_code.val, Codes.SUCCESS)
        self.assertAlmostEqual(answer.fraction, 1.0)
        self.assertGreater(len(answer.solution.joint_trajectory.points), 5)
        folded = GetStateValidityRequest(group_name="interbotix_arm")
        folded.robot_state.joint_state = JointState(name=["shoulder", "elbow", "wrist_angle"],
                                                    position=[-1.9, 1.6, 2.1])
        verdict = self.validity(folded)
        self.assertFalse(verdict.valid)
        self.assertIn("px100/base_link", {c.contact_body_1 for c in verdict.contacts} |
                      {c.contact_body_2 for c in verdict.contacts})


if __name__ == "__main__":
    rostest.rosrun("moveit_ros_move_group", "planning_execution", PlanningExecution)

#!/usr/bin/env python3
"""rostest node for pick_place.test (fake MoveIt, config/waypoints.yaml): one follow picks
the block and sets it down at the drop-off place, as move_group's planning scene holds it
(fake controllers have no physics: the scene is what there is): the block was attached to
the gripper on the way, and ends detached, on the table, within 3 mm of the place. Picked
up again, a reset (which opens the gripper) lets go of it."""
import threading
import unittest

import rospy
import rostest
from geometry_msgs.msg import Point, Pose, Quaternion
from moveit_msgs.msg import MoveItErrorCodes as Codes, PlanningScene, PlanningSceneComponents
from moveit_msgs.srv import GetPlanningScene

from arm_move.srv import Follow, Reset, Step

DROP_OFF = (0.17, -0.02)       # in px100/base_link, as the last waypoints of the yaml
RESTING = 0.0235               # the block's centre set down 3.5 mm above the table
BOX_ON_TABLE = Pose(Point(0.16, -0.17, 0.025), Quaternion(0, 0, 0, 1))


class PickAndPlace(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("pick_place_check")

    def test_1_the_block_ends_at_the_drop_off_place(self):
        attached, lock = [], threading.Lock()

        def on_scene(scene):
            with lock:
                attached.extend(a.object.id for a in scene.robot_state.attached_collision_objects)
        rospy.Subscriber("move_group/monitored_planning_scene", PlanningScene, on_scene)
        for name in ("reset", "follow"):
            rospy.wait_for_service(name, timeout=90)
        waypoints = rospy.get_param("mover/waypoints")
        self.assertEqual(waypoints[-2][:2], list(DROP_OFF))
        answer = rospy.ServiceProxy("reset", Reset)(BOX_ON_TABLE, False)
        self.assertEqual(answer.error_code.val, Codes.SUCCESS, answer.message)
        answer = rospy.ServiceProxy("follow", Follow)(False)
        self.assertEqual(answer.error_code.val, Codes.SUCCESS, answer.message)
        scene = self.scene()
        self.assertNotIn("pick_object", [a.object.id for a in
                                         scene.robot_state.attached_collision_objects])
        block = [o for o in scene.world.collision_objects if o.id == "pick_object"][0]
        p = block.pose.position      # its one box sits at the object's pose
        distance = ((p.x - DROP_OFF[0]) ** 2 + (p.y - DROP_OFF[1]) ** 2) ** 0.5
        rospy.loginfo("pick_place_check: block at (%.4f, %.4f, %.4f), %.4f m from the drop-off",
                      p.x, p.y, p.z, distance)
        self.assertLess(distance, 0.003)
        self.assertAlmostEqual(p.z, RESTING, delta=0.002)
        with lock:
            self.assertIn("pick_object", attached)      # carried, not pushed

    def test_2_reset_lets_go_of_a_held_block(self):
        grasp = rospy.ServiceProxy("step", Step)(Point(DROP_OFF[0], DROP_OFF[1], 0.045), False)
        self.assertEqual(grasp.error_code.val, Codes.SUCCESS, grasp.message)
        self.assertIn("pick_object", [a.object.id for a in
                                      self.scene().robot_state.attached_collision_objects])
        answer = rospy.ServiceProxy("reset", Reset)(BOX_ON_TABLE, False)
        self.assertEqual(answer.error_code.val, Codes.SUCCESS, answer.message)
        scene = self.scene()
        self.assertEqual(scene.robot_state.attached_collision_objects, [])
        self.assertIn("pick_object", [o.id for o in scene.world.collision_objects])

    @staticmethod
    def scene():
        return rospy.ServiceProxy("get_planning_scene", GetPlanningScene)(
            PlanningSceneComponents(components=PlanningSceneComponents.WORLD_OBJECT_GEOMETRY |
                                    PlanningSceneComponents.ROBOT_STATE_ATTACHED_OBJECTS)).scene


if __name__ == "__main__":
    rostest.rosrun("arm_move", "pick_place", PickAndPlace)

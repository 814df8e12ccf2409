#!/usr/bin/env python3
"""rostest node for pick_place.test (fake MoveIt, config/waypoints.yaml): one follow picks
the block and sets it down at the drop-off place, as move_group's planning scene holds it
(fake controllers have no physics: the scene is what there is): the block was attached to
the gripper on the way, and ends detached, on the table, within 3 mm of the place."""
import threading
import unittest

import rospy
import rostest
from geometry_msgs.msg import Point, Pose, Quaternion
from moveit_msgs.msg import MoveItErrorCodes as Codes, PlanningScene, PlanningSceneComponents
from moveit_msgs.srv import GetPlanningScene

from arm_move.srv import Follow, Reset

DROP_OFF = (0.17, -0.02)       # in px100/base_link, as the last waypoints of the yaml
RESTING = 0.0235               # the block's centre set down 3.5 mm above the table
BOX_ON_TABLE = Pose(Point(0.16, -0.17, 0.025), Quaternion(0, 0, 0, 1))


class PickAndPlace(unittest.TestCase):
    def test_the_block_ends_at_the_drop_off_place(self):
        rospy.init_node("pick_place_check")
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
        scene = rospy.ServiceProxy("get_planning_scene", GetPlanningScene)(
            PlanningSceneComponents(components=PlanningSceneComponents.WORLD_OBJECT_GEOMETRY |
                                    PlanningSceneComponents.ROBOT_STATE_ATTACHED_OBJECTS)).scene
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


if __name__ == "__main__":
    rostest.rosrun("arm_move", "pick_place", PickAndPlace)

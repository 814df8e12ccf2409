#!/usr/bin/env python3
"""rostest node for pick_place_sim.test (physics): the README's cycle (config/waypoints.yaml,
follow once) ``~runs`` times in a row on one simulator (make test: once; make soak: three
times, pick_place_sim.test's ``runs`` argument). Each time the block ends, in the
simulator's ground truth, within 2 cm of the drop-off place, upright (its z axis within
10 degrees of the vertical) and resting on the table; between runs a hand (this test)
puts it back where the world starts it, in the simulation and in the mover's planning
scene. Before the mover stopped closing an already closed gripper again, it fell out at
the top of the lift and ended 11.5 cm away, by the place it was picked from."""
import math
import os
import unittest

import rospkg
import rospy
import rostest
import yaml
from gazebo_msgs.msg import ModelState
from gazebo_msgs.srv import GetModelState, SetModelState
from geometry_msgs.msg import Point, Pose, PoseStamped, Quaternion
from moveit_commander import PlanningSceneInterface
from moveit_msgs.msg import MoveItErrorCodes as Codes
from tf.transformations import quaternion_from_euler

from arm_move.srv import Follow, Reset
from sim_bridge.testing import service_proxy, wait_until

BLOCK = "pick_object"
RUNS = 3                        # ~runs' default (make soak's)
DROP_OFF = (0.17, -0.02)        # in px100/base_link (= the world's frame), the yaml's
PLACED = 0.02                   # m: the "within 2 cm of the drop-off"
UPRIGHT = math.radians(10.0)    # the block's z axis from the vertical
RESTING = (0.02, 0.003)         # its centre's height on the table (half of 0.04) and slack
BOX_ON_TABLE = Pose(Point(0.16, -0.17, 0.025), Quaternion(0, 0, 0, 1))


class PickAndPlaceInTheSimulation(unittest.TestCase):
    def test_each_run_lands_the_block_at_the_drop_off(self):
        rospy.init_node("pick_place_sim_check")
        runs = int(rospy.get_param("~runs", RUNS))
        reset = service_proxy("reset", Reset, timeout=120)
        follow = service_proxy("follow", Follow, timeout=120)
        get = service_proxy("/gazebo/get_model_state", GetModelState)
        put = service_proxy("/gazebo/set_model_state", SetModelState)
        scene = PlanningSceneInterface(ns=rospy.get_namespace())
        with open(os.path.join(rospkg.RosPack().get_path("arm_move"), "config", "scene.yaml"),
                  encoding="utf-8") as stream:
            block = yaml.safe_load(stream)[BLOCK]
        self.assertEqual(rospy.get_param("mover/waypoints")[-2][:2], list(DROP_OFF))
        landed = []
        for run in range(runs):
            answer = reset(BOX_ON_TABLE, False)
            self.assertEqual(answer.error_code.val, Codes.SUCCESS, answer.message)
            answer = follow(False)
            self.assertEqual(answer.error_code.val, Codes.SUCCESS, answer.message)
            pose = self.settled(get)
            p, q = pose.position, pose.orientation
            distance = math.hypot(p.x - DROP_OFF[0], p.y - DROP_OFF[1])
            tilt = math.acos(max(-1.0, min(1.0, 1.0 - 2.0 * (q.x ** 2 + q.y ** 2))))
            rospy.loginfo("pick_place_sim_check: run %d: block at (%.4f, %.4f, %.4f), %.4f m "
                          "from the drop-off, tilted %.1f deg", run + 1, p.x, p.y, p.z,
                          distance, math.degrees(tilt))
            landed.append((round(distance, 4), round(math.degrees(tilt), 1)))
            self.assertLess(distance, PLACED, landed)
            self.assertLess(tilt, UPRIGHT, landed)
            self.assertAlmostEqual(p.z, RESTING[0], delta=RESTING[1])
            if run < RUNS - 1:
                self.put_back(put, scene, block)

    @staticmethod
    def settled(get):
        """The block's true pose once it has stopped moving (the gripper let go of it)."""
        last = []

        def still():
            state = get(BLOCK, "")
            speed = state.twist.linear
            last[:] = [state.pose]
            return math.sqrt(speed.x ** 2 + speed.y ** 2 + speed.z ** 2) < 1e-3
        wait_until(still, "the block to come to rest", timeout=10.0)
        return last[0]

    @staticmethod
    def put_back(put, scene, block):
        """The block where the world starts it: in the simulation and in the planning scene
        (a millimetre above the table there, as config/scene.yaml has it)."""
        x, y, z = block["position"]
        orientation = Quaternion(*quaternion_from_euler(0.0, 0.0, block["yaw"]))
        answer = put(ModelState(model_name=BLOCK, reference_frame="world",
                                pose=Pose(Point(x, y, block["size"][2] / 2), orientation)))
        assert answer.success, answer.status_message
        stamped = PoseStamped()
        stamped.header.frame_id = "px100/base_link"
        stamped.pose = Pose(Point(x, y, z), orientation)
        scene.add_box(BLOCK, stamped, block["size"])
        wait_until(lambda: abs(scene.get_object_poses([BLOCK])[BLOCK].position.y - y) < 1e-6,
                   "the block back in the planning scene", timeout=5.0)


if __name__ == "__main__":
    rostest.rosrun("arm_move", "pick_place_sim", PickAndPlaceInTheSimulation)

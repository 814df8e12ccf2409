#!/usr/bin/env python3
"""rostest node: the sensor robot's camera, depth camera and sonar, read through ROS, against
the world: a red crate whose near face is 1.75 m ahead of the origin (0.5 m wide), a wall
whose face is 0.95 m to the left."""
import math
import os
import sys
import unittest

import numpy as np
import rospy
import rostest
from sensor_msgs.msg import CameraInfo, Image, PointCloud2, Range

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sim_checks import TIMEOUT, Simulator  # noqa: E402

HALF = 0.15                  # m: the robot's half size; the cameras sit on its front face
CRATE_FACE_X, CRATE_HALF_WIDTH = 1.75, 0.25
WALL_FACE_Y = 0.95


def message(topic, kind):
    return rospy.wait_for_message(topic, kind, timeout=TIMEOUT)


def is_red(pixel):
    return pixel[0] > 120 and pixel[1] < 60 and pixel[2] < 60


class Sensors(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("sensors_check")
        cls.sim = Simulator()
        cls.sim.wait_for_model("sensor_bot")
        cls.sim.wait_sim_time(cls.sim.sim_time() + 0.5)  # settled on the floor
        cls.x, cls.y, cls.yaw = cls.sim.truth("sensor_bot")

    def test_the_camera_sees_the_crate_where_the_intrinsics_put_it(self):
        info = message("/front_camera/camera_info", CameraInfo)
        image = message("/front_camera/image_raw", Image)
        self.assertEqual((image.encoding, image.width, image.height), ("rgb8", 320, 240))
        self.assertEqual(image.header.frame_id, "camera_optical")
        pixels = np.frombuffer(image.data, np.uint8).reshape(240, 320, 3)
        row = pixels[120]
        self.assertTrue(is_red(row[160]), f"centre pixel {row[160]}")
        red = [i for i in range(320) if is_red(row[i])]
        focal, distance = info.K[0], CRATE_FACE_X - (self.x + HALF)
        for edge, expected in ((min(red), 160 - focal * CRATE_HALF_WIDTH / distance),
                               (max(red) + 1, 160 + focal * CRATE_HALF_WIDTH / distance)):
            self.assertLess(abs(edge - expected), 2.0, f"edge {edge}, expected {expected:.1f}")

    def test_the_depth_camera_measures_the_crates_face(self):
        depth = message("/kinect/depth/image_raw", Image)
        self.assertEqual(depth.encoding, "32FC1")
        metres = np.frombuffer(depth.data, np.float32).reshape(120, 160)
        expected = CRATE_FACE_X - (self.x + HALF)
        self.assertAlmostEqual(float(metres[60, 80]), expected, delta=0.01)
        cloud = message("/kinect/points", PointCloud2)
        self.assertEqual(cloud.header.frame_id, "depth_optical")
        points = np.frombuffer(cloud.data, np.dtype({"names": ["x", "y", "z"],
                                                     "formats": ["<f4"] * 3,
                                                     "offsets": [0, 4, 8],
                                                     "itemsize": cloud.point_step}))
        centre = points.reshape(cloud.height, cloud.width)[60, 80]
        # the optical frame's z is ahead: the point in the world is the crate's near face
        world_x = self.x + HALF + math.cos(self.yaw) * float(centre["z"])
        self.assertAlmostEqual(world_x, CRATE_FACE_X, delta=0.01)
        self.assertLess(abs(float(centre["x"])), 0.01)

    def test_the_sonar_reads_the_wall(self):
        reading = message("/sonar/left", Range)
        self.assertEqual(reading.header.frame_id, "sonar")
        self.assertAlmostEqual(reading.range, WALL_FACE_Y - (self.y + HALF), delta=0.02)
        self.assertAlmostEqual(reading.range, 0.8, delta=0.02)


if __name__ == "__main__":
    rostest.rosrun("gazebo_ros", "sensors", Sensors)

"""Each arm's kinematics as Modern Robotics writes them: the space-frame screw axes ``Slist``
(one column a joint) and ``M``, the pose of ``<robot_name>/ee_gripper_link`` in
``<robot_name>/base_link`` with every joint at zero. Interbotix's published numbers
(interbotix_ros_toolboxes noetic af96d28, ``mr_descriptions.py``); those of the arms this
workspace describes, checked against the description's own kinematics
(``test/unit/test_mr_descriptions.py``)."""
import numpy as np


class px100:  # pylint: disable=invalid-name,too-few-public-methods
    """PincherX 100: waist, shoulder, elbow, wrist_angle."""
    Slist = np.array([[0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.0931, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.1931, 0.0, 0.035],
                      [0.0, 1.0, 0.0, -0.1931, 0.0, 0.135]]).T
    M = np.array([[1.0, 0.0, 0.0, 0.248575],
                  [0.0, 1.0, 0.0, 0.0],
                  [0.0, 0.0, 1.0, 0.1931],
                  [0.0, 0.0, 0.0, 1.0]])


class wx200:  # pylint: disable=invalid-name,too-few-public-methods
    """WidowX 200: waist, shoulder, elbow, wrist_angle, wrist_rotate."""
    Slist = np.array([[0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.11065, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.31065, 0.0, 0.05],
                      [0.0, 1.0, 0.0, -0.31065, 0.0, 0.25],
                      [1.0, 0.0, 0.0, 0.0, 0.31065, 0.0]]).T
    M = np.array([[1.0, 0.0, 0.0, 0.408575],
                  [0.0, 1.0, 0.0, 0.0],
                  [0.0, 0.0, 1.0, 0.31065],
                  [0.0, 0.0, 0.0, 1.0]])

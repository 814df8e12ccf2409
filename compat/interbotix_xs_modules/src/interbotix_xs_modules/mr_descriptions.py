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


class px150:  # pylint: disable=invalid-name,too-few-public-methods
    """PincherX 150: waist, shoulder, elbow, wrist_angle, wrist_rotate."""
    Slist = np.array([[0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.10457, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.25457, 0.0, 0.05],
                      [0.0, 1.0, 0.0, -0.25457, 0.0, 0.2],
                      [1.0, 0.0, 0.0, 0.0, 0.25457, 0.0]]).T
    M = np.array([[1.0, 0.0, 0.0, 0.358575],
                  [0.0, 1.0, 0.0, 0.0],
                  [0.0, 0.0, 1.0, 0.25457],
                  [0.0, 0.0, 0.0, 1.0]])


class rx150:  # pylint: disable=invalid-name,too-few-public-methods
    """ReactorX 150: waist, shoulder, elbow, wrist_angle, wrist_rotate."""
    Slist = np.array([[0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.10457, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.25457, 0.0, 0.05],
                      [0.0, 1.0, 0.0, -0.25457, 0.0, 0.2],
                      [1.0, 0.0, 0.0, 0.0, 0.25457, 0.0]]).T
    M = np.array([[1.0, 0.0, 0.0, 0.358575],
                  [0.0, 1.0, 0.0, 0.0],
                  [0.0, 0.0, 1.0, 0.25457],
                  [0.0, 0.0, 0.0, 1.0]])


class rx200:  # pylint: disable=invalid-name,too-few-public-methods
    """ReactorX 200: waist, shoulder, elbow, wrist_angle, wrist_rotate."""
    Slist = np.array([[0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.10457, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.30457, 0.0, 0.05],
                      [0.0, 1.0, 0.0, -0.30457, 0.0, 0.25],
                      [1.0, 0.0, 0.0, 0.0, 0.30457, 0.0]]).T
    M = np.array([[1.0, 0.0, 0.0, 0.408575],
                  [0.0, 1.0, 0.0, 0.0],
                  [0.0, 0.0, 1.0, 0.30457],
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


class wx250:  # pylint: disable=invalid-name,too-few-public-methods
    """WidowX 250: waist, shoulder, elbow, wrist_angle, wrist_rotate."""
    Slist = np.array([[0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.11065, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.36065, 0.0, 0.04975],
                      [0.0, 1.0, 0.0, -0.36065, 0.0, 0.29975],
                      [1.0, 0.0, 0.0, 0.0, 0.36065, 0.0]]).T
    M = np.array([[1.0, 0.0, 0.0, 0.458325],
                  [0.0, 1.0, 0.0, 0.0],
                  [0.0, 0.0, 1.0, 0.36065],
                  [0.0, 0.0, 0.0, 1.0]])


class wx250s:  # pylint: disable=invalid-name,too-few-public-methods
    """WidowX 250 6DOF: waist, shoulder, elbow, forearm_roll, wrist_angle, wrist_rotate."""
    Slist = np.array([[0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.11065, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.36065, 0.0, 0.04975],
                      [1.0, 0.0, 0.0, 0.0, 0.36065, 0.0],
                      [0.0, 1.0, 0.0, -0.36065, 0.0, 0.29975],
                      [1.0, 0.0, 0.0, 0.0, 0.36065, 0.0]]).T
    M = np.array([[1.0, 0.0, 0.0, 0.458325],
                  [0.0, 1.0, 0.0, 0.0],
                  [0.0, 0.0, 1.0, 0.36065],
                  [0.0, 0.0, 0.0, 1.0]])


class vx250:  # pylint: disable=invalid-name,too-few-public-methods
    """ViperX 250: waist, shoulder, elbow, wrist_angle, wrist_rotate."""
    Slist = np.array([[0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.12705, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.37705, 0.0, 0.06],
                      [0.0, 1.0, 0.0, -0.37705, 0.0, 0.31],
                      [1.0, 0.0, 0.0, 0.0, 0.37705, 0.0]]).T
    M = np.array([[1.0, 0.0, 0.0, 0.468575],
                  [0.0, 1.0, 0.0, 0.0],
                  [0.0, 0.0, 1.0, 0.37705],
                  [0.0, 0.0, 0.0, 1.0]])


class vx300:  # pylint: disable=invalid-name,too-few-public-methods
    """ViperX 300: waist, shoulder, elbow, wrist_angle, wrist_rotate."""
    Slist = np.array([[0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.12705, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.42705, 0.0, 0.05955],
                      [0.0, 1.0, 0.0, -0.42705, 0.0, 0.35955],
                      [1.0, 0.0, 0.0, 0.0, 0.42705, 0.0]]).T
    M = np.array([[1.0, 0.0, 0.0, 0.536494],
                  [0.0, 1.0, 0.0, 0.0],
                  [0.0, 0.0, 1.0, 0.42705],
                  [0.0, 0.0, 0.0, 1.0]])


class vx300s:  # pylint: disable=invalid-name,too-few-public-methods
    """ViperX 300 6DOF: waist, shoulder, elbow, forearm_roll, wrist_angle, wrist_rotate."""
    Slist = np.array([[0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.12705, 0.0, 0.0],
                      [0.0, 1.0, 0.0, -0.42705, 0.0, 0.05955],
                      [1.0, 0.0, 0.0, 0.0, 0.42705, 0.0],
                      [0.0, 1.0, 0.0, -0.42705, 0.0, 0.35955],
                      [1.0, 0.0, 0.0, 0.0, 0.42705, 0.0]]).T
    M = np.array([[1.0, 0.0, 0.0, 0.536494],
                  [0.0, 1.0, 0.0, 0.0],
                  [0.0, 0.0, 1.0, 0.42705],
                  [0.0, 0.0, 0.0, 1.0]])

"""Euler angles and homogeneous transforms as Interbotix's modules use them: static x-y-z
(roll about x, then pitch about y, then yaw about z, fixed axes: tf's ``sxyz``), through
tf.transformations as upstream's ``angle_manipulation.py`` does."""
import math

import numpy as np
from geometry_msgs.msg import Quaternion, QuaternionStamped
from tf.transformations import euler_from_matrix, euler_matrix


def transInv(T):  # pylint: disable=invalid-name
    """The inverse of a homogeneous transform."""
    rotation, position = np.asarray(T)[:3, :3], np.asarray(T)[:3, 3]
    inverse = np.identity(4)
    inverse[:3, :3] = rotation.T
    inverse[:3, 3] = -rotation.T @ position
    return inverse


def yawToRotationMatrix(yaw):  # pylint: disable=invalid-name
    """The 2 x 2 rotation by ``yaw`` in the plane."""
    return np.array([[math.cos(yaw), -math.sin(yaw)], [math.sin(yaw), math.cos(yaw)]])


def eulerAnglesToRotationMatrix(theta):  # pylint: disable=invalid-name
    """[roll, pitch, yaw] -> 3 x 3 rotation (sxyz)."""
    return euler_matrix(theta[0], theta[1], theta[2], axes="sxyz")[:3, :3]


def rotationMatrixToEulerAngles(R):  # pylint: disable=invalid-name
    """3 x 3 rotation -> [roll, pitch, yaw] (sxyz)."""
    return list(euler_from_matrix(R, axes="sxyz"))


def poseToTransformationMatrix(pose):  # pylint: disable=invalid-name
    """[x, y, z, roll, pitch, yaw] -> 4 x 4 transform."""
    matrix = np.identity(4)
    matrix[:3, :3] = eulerAnglesToRotationMatrix(pose[3:])
    matrix[:3, 3] = pose[:3]
    return matrix


def quaternion_is_valid(quat, tol=10e-3):
    """A Quaternion (or QuaternionStamped) of unit length within ``tol``."""
    if isinstance(quat, QuaternionStamped):
        quat = quat.quaternion
    if not isinstance(quat, Quaternion):
        raise TypeError("quaternion_is_valid must be given a Quaternion or QuaternionStamped "
                        f"message. Was given {type(quat)}.")
    return abs(quat.w ** 2 + quat.x ** 2 + quat.y ** 2 + quat.z ** 2 - 1.0) < tol

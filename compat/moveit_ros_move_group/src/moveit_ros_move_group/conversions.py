"""moveit_msgs and geometry_msgs to numbers and back: poses as 4x4 matrices
(tf.transformations), robot states as positions by joint. No master needed."""
from __future__ import annotations

import logging
from typing import Dict, Iterable, Mapping

import numpy as np
from geometry_msgs.msg import Pose
from moveit_msgs.msg import RobotState
from sensor_msgs.msg import JointState
from tf.transformations import quaternion_matrix

from moveit_core.planning_scene import matrix_pose  # noqa: F401  (one Pose builder)

LOG = logging.getLogger("rosout.move_group")


class MessageError(ValueError):
    """A request field that cannot be used; the message names it."""


def pose_matrix(pose: Pose, what: str = "pose") -> np.ndarray:
    position, orientation = pose.position, pose.orientation
    quaternion = np.array([orientation.x, orientation.y, orientation.z, orientation.w])
    values = np.concatenate([[position.x, position.y, position.z], quaternion])
    if not np.all(np.isfinite(values)):
        raise MessageError(f"{what} holds a value that is not finite: {values.tolist()}")
    norm = np.linalg.norm(quaternion)
    if norm < 1e-6:
        raise MessageError(f"{what} has a zero quaternion (orientation all 0: w = 1 is "
                           "the identity)")
    matrix = quaternion_matrix(quaternion / norm)
    matrix[:3, 3] = values[:3]
    return matrix


def state_positions(state: RobotState, current: Mapping[str, float]) -> Dict[str, float]:
    """The positions a RobotState message gives, over ``current`` (MoveIt applies a message
    to the current state: the joints it names replace theirs). A joint state whose names and
    positions differ in number changes nothing, with MoveIt's error (conversions.cpp l. 57-61
    on noetic-devel), and the request goes on from ``current``: compute_ik, compute_fk,
    compute_cartesian_path and check_state_validity ignore the conversion's failure there
    (kinematics_service_capability.cpp l. 80, 201, cartesian_path_service_capability.cpp
    l. 86, state_validation_service_capability.cpp l. 60). A non-finite position is refused
    (MessageError): MoveIt would plan from it."""
    names, positions = state.joint_state.name, state.joint_state.position
    if len(names) != len(positions):
        LOG.error("Different number of names and positions in JointState message: %d, %d",
                  len(names), len(positions))
        return dict(current)
    merged = dict(current)
    for name, value in zip(names, positions):
        if not np.isfinite(value):
            raise MessageError(f"robot_state.joint_state: joint '{name}' is at {value}")
        merged[name] = float(value)
    return merged


def robot_state(positions: Mapping[str, float], joints: Iterable[str]) -> RobotState:
    """A RobotState message of ``joints`` (every single-dof joint of the model, in order)."""
    state = RobotState()
    state.joint_state = JointState()
    state.joint_state.name = list(joints)
    state.joint_state.position = [float(positions.get(j, 0.0)) for j in state.joint_state.name]
    return state

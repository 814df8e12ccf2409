"""move_group's Cartesian path capability (MoveIt's MoveGroupCartesianPathService,
``compute_cartesian_path``, with noetic-devel's CartesianInterpolator since "New
implementation of computeCartesianPath", moveit 9af1839): the link moved along straight
lines through the waypoints (positions interpolated, orientations slerped), a step at most
``max_step`` metres, each step solved by the group's IK from the previous one. Between two
solved steps the joint-space midpoint must put the link on the line's midpoint within
CartesianPrecision (1 mm, 0.01 rad; by position only for a group solved by position only,
see _Segment); where it does not, the interval is halved (the
midpoint's pose solved by IK from the joint-space midpoint) down to ``max_resolution`` of
the segment (validateAndImproveInterval). The path stops at the first step that has no
solution, cannot be refined, collides (with ``avoid_collisions``) or breaks the request's
``path_constraints`` (each solution is checked against them, as the capability's
isStateValid callback, cartesian_path_service_capability.cpp:55-61, 132-146 on noetic-devel).
``fraction`` is the
share of the waypoints reached; the error code is SUCCESS even when it is below 1, as
MoveIt's."""
from __future__ import annotations

import math
from typing import Dict, List, Optional

import numpy as np
import rospy
from moveit_msgs.msg import MoveItErrorCodes as Codes
from moveit_msgs.srv import GetCartesianPathResponse
from tf.transformations import quaternion_from_matrix, quaternion_matrix, quaternion_slerp

from moveit_core.kinematic_constraints import ConstraintError, ConstraintSet
from moveit_core.planning_scene import SceneError, pose_matrix
from moveit_core.robot_model import RobotModelError
from moveit_core.time_parameterization import joint_trajectory, limits_of, time_path
from moveit_kinematics.kdl_solver import SEED_ITERATIONS
from moveit_ros_move_group.conversions import MessageError, robot_state, state_positions

# CartesianPrecision's defaults (cartesian_interpolator.h:50-55 at moveit 9af1839), which the
# capability passes (cartesian_path_service_capability.cpp at moveit ed01b06)
PRECISION_TRANSLATIONAL = 0.001   # m: the joint-space midpoint's link from the line's
PRECISION_ROTATIONAL = 0.01       # rad
MAX_RESOLUTION = 1e-5             # the shortest interval refined, a share of the segment
ROTATION_STEP = 3.5        # a step turns at most max_step x this (rad per m), as MoveIt's


def _steps(a: np.ndarray, b: np.ndarray, max_step: float) -> int:
    translation = np.linalg.norm(b[:3, 3] - a[:3, 3])
    difference = a[:3, :3].T @ b[:3, :3]
    angle = math.acos(max(-1.0, min(1.0, (np.trace(difference) - 1) / 2)))
    return int(math.floor(max(translation / max_step, angle / (ROTATION_STEP * max_step)))) + 1


def _between(a: np.ndarray, b: np.ndarray, share: float) -> np.ndarray:
    pose = np.eye(4)
    qa, qb = quaternion_from_matrix(a), quaternion_from_matrix(b)
    pose[:3, :3] = quaternion_matrix(quaternion_slerp(qa, qb, share))[:3, :3]
    pose[:3, 3] = a[:3, 3] + (b[:3, 3] - a[:3, 3]) * share
    return pose


def _angle(a: np.ndarray, b: np.ndarray) -> float:
    """The rotation between two poses' orientations (Eigen's angularDistance)."""
    difference = a[:3, :3].T @ b[:3, :3]
    return math.acos(max(-1.0, min(1.0, (np.trace(difference) - 1) / 2)))


class _Segment:
    """One straight segment's steps: IK from the previous state, each interval refined
    until its joint-space midpoint is on the line (validateAndImproveInterval)."""

    def __init__(self, solver, scene, state, link, base_inverse, group, avoid_collisions,
                 constraints: Optional[ConstraintSet]):
        self.solver, self.scene, self.state, self.link = solver, scene, state, link
        self.base_inverse, self.group = base_inverse, group
        self.avoid_collisions, self.constraints = avoid_collisions, constraints
        self.why = ""          # why the segment stopped, for the log
        # A group solved by position only (kinematics.yaml's position_only_ik, as
        # Interbotix's 4- and 5-joint arms are) does not hold the line's orientation: its
        # midpoints are checked by position only. MoveIt checks the rotation regardless,
        # so there such a path stops at its first step.
        settings = getattr(solver, "settings", None)
        self.rotational = math.inf if getattr(settings, "position_only_ik", False) \
            else PRECISION_ROTATIONAL

    def solve(self, pose: np.ndarray, seed: np.ndarray) -> Optional[np.ndarray]:
        solution = self.solver.inverse(self.base_inverse @ pose, seed, None, SEED_ITERATIONS)
        if solution is None:
            self.why = "no IK solution"
            return None
        q = np.array(solution)
        if self.avoid_collisions:
            touching = self.scene.contacts(self._complete(q), self.group)
            if touching:
                self.why = f"in collision ({touching})"
                return None
        if self.constraints is not None:
            broken = self.constraints.decide(self._complete(q))
            if broken:
                self.why = f"breaks the path constraints ({broken})"
                return None
        return q

    def _complete(self, q: np.ndarray) -> Dict[str, float]:
        return dict(self.state, **dict(zip(self.solver.joints, q)))

    def refine(self, start_q, end_q, start_pose, end_pose, width: float,
               out: List[np.ndarray]) -> bool:
        """Appends to ``out`` the states from ``start_q`` (excluded) to ``end_q`` (included)
        that keep the link on the line; False when the interval cannot be refined."""
        middle_q = (start_q + end_q) / 2
        reached = self.scene.model.link_poses(self._complete(middle_q))[self.link]
        wanted = _between(start_pose, end_pose, 0.5)
        if np.linalg.norm(reached[:3, 3] - wanted[:3, 3]) <= PRECISION_TRANSLATIONAL and \
                _angle(reached, wanted) <= self.rotational:
            out.append(end_q)
            return True
        if width < MAX_RESOLUTION:
            self.why = "the link leaves the straight line (a jump the interval cannot refine)"
            return False
        middle = self.solve(wanted, middle_q)
        if middle is None:
            return False
        return (self.refine(start_q, middle, start_pose, wanted, width / 2, out) and
                self.refine(middle, end_q, wanted, end_pose, width / 2, out))


def compute_cartesian_path(context, monitor, request) -> GetCartesianPathResponse:
    response = GetCartesianPathResponse(fraction=-1.0)
    scene = monitor.snapshot()
    try:
        solver = context.solver(request.group_name)
    except RobotModelError as error:
        rospy.logerr("compute_cartesian_path: %s", error)
        response.error_code.val = Codes.INVALID_GROUP_NAME \
            if request.group_name not in context.model.groups else Codes.NO_IK_SOLUTION
        return response
    if not request.max_step > 0:
        rospy.logerr("compute_cartesian_path: max_step %s must be > 0", request.max_step)
        response.error_code.val = Codes.FAILURE
        return response
    link = request.link_name or solver.tip
    if link != solver.tip:
        rospy.logerr("compute_cartesian_path: group '%s' moves its tip '%s', not '%s'",
                     request.group_name, solver.tip, link)
        response.error_code.val = Codes.INVALID_LINK_NAME
        return response
    try:
        state = state_positions(request.start_state, scene.positions)
        poses = scene.model.link_poses(state)
        frame = scene.frame_pose(request.header.frame_id, poses)
        targets = [frame @ pose_matrix(p, f"waypoint {i + 1}")
                   for i, p in enumerate(request.waypoints)]
    except (MessageError, SceneError) as error:
        rospy.logerr("compute_cartesian_path: %s", error)
        response.error_code.val = Codes.FRAME_TRANSFORM_FAILURE \
            if "frame" in str(error) else Codes.INVALID_ROBOT_STATE
        return response
    try:
        constraints = ConstraintSet(scene, request.path_constraints)
    except (ConstraintError, SceneError) as error:
        rospy.logerr("compute_cartesian_path: path constraints: %s", error)
        response.error_code.val = Codes.FAILURE
        return response
    rospy.loginfo("Attempting to follow %d waypoints for link '%s' using a step of %f m "
                  "(in global reference frame)", len(targets), link, request.max_step)
    segment = _Segment(solver, scene, state, link, np.linalg.inv(poses[solver.base]),
                       request.group_name, request.avoid_collisions,
                       None if constraints.empty else constraints)
    current = poses[link]
    path: List[np.ndarray] = [np.array([state[j] for j in solver.joints])]
    reached = 0.0
    for index, target in enumerate(targets):
        count = _steps(current, target, request.max_step)
        done, previous_pose = 0, current
        for step in range(1, count + 1):
            pose = _between(current, target, step / count)
            q = segment.solve(pose, path[-1])
            if q is None or not segment.refine(path[-1], q, previous_pose, pose, 1.0 / count,
                                               path):
                break
            done, previous_pose = step, pose
        reached = (index + done / count) / len(targets)
        if done < count:
            rospy.loginfo("compute_cartesian_path: stopped at waypoint %d, step %d of %d: %s",
                          index + 1, done + 1, count, segment.why)
            break
        current = target
    else:
        reached = 1.0 if targets else 0.0
    joints = solver.joints
    velocity, acceleration = limits_of(scene.model, joints)
    timed = time_path(path, velocity, acceleration)
    response.start_state = robot_state(scene.model.complete(state),
                                       [j for j in scene.model.joint_order
                                        if j in scene.model.bounds])
    response.solution.joint_trajectory = joint_trajectory(timed, joints)
    response.fraction = reached
    response.error_code.val = Codes.SUCCESS
    rospy.loginfo("Computed Cartesian path with %d points (followed %f%% of requested "
                  "trajectory)", len(path), reached * 100.0)
    return response

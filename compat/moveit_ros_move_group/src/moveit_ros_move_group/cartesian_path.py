"""move_group's Cartesian path capability (MoveIt's MoveGroupCartesianPathService,
``compute_cartesian_path``): the link moved along straight lines through the waypoints
(positions interpolated, orientations slerped), a step at most ``max_step`` metres, each
step solved by the group's IK from the previous one; the path stops at the first step that
has no solution, jumps (the joint-space midpoint of two steps puts the link more than
1 mm off the line's midpoint, as MoveIt 1.1.16's precision check) or collides (with
``avoid_collisions``). ``fraction`` is the share of the waypoints reached; the error code
is SUCCESS even when it is below 1, as MoveIt's."""
from __future__ import annotations

import math
from typing import List

import numpy as np
import rospy
from moveit_msgs.msg import MoveItErrorCodes as Codes
from moveit_msgs.srv import GetCartesianPathResponse
from tf.transformations import quaternion_from_matrix, quaternion_matrix, quaternion_slerp

from moveit_core.planning_scene import SceneError, pose_matrix
from moveit_core.robot_model import RobotModelError
from moveit_core.time_parameterization import joint_trajectory, limits_of, time_path
from moveit_kinematics.kdl_solver import SEED_ITERATIONS
from moveit_ros_move_group.conversions import MessageError, robot_state, state_positions

PRECISION = 0.001          # m: a joint-space midpoint's link within this of the line's
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
    group = request.group_name
    base_inverse = np.linalg.inv(poses[solver.base])
    current = poses[link]
    joints = solver.joints
    path: List[np.ndarray] = [np.array([state[j] for j in joints])]
    reached = 0.0
    for index, target in enumerate(targets):
        count = _steps(current, target, request.max_step)
        done = 0
        for step in range(1, count + 1):
            pose = _between(current, target, step / count)
            solution = solver.inverse(base_inverse @ pose, path[-1], None, SEED_ITERATIONS)
            if solution is None:
                break
            q = np.array(solution)
            middle = dict(state, **dict(zip(joints, (path[-1] + q) / 2)))
            wanted = _between(current, target, (step - 0.5) / count)[:3, 3]
            if np.linalg.norm(scene.model.link_poses(middle)[link][:3, 3] - wanted) > PRECISION:
                break      # a jump (the solver changed branch): MoveIt cuts here too
            if request.avoid_collisions and scene.contacts(dict(state, **dict(zip(joints, q))),
                                                           group):
                break
            path.append(q)
            done = step
        reached = (index + done / count) / len(targets)
        if done < count:
            break
        current = target
    else:
        reached = 1.0 if targets else 0.0
    velocity, acceleration = limits_of(scene.model, joints)
    timed = time_path(path, velocity, acceleration)
    response.start_state = robot_state(scene.model.complete(state),
                                       [j for j in scene.model.joint_order
                                        if j in scene.model.bounds])
    response.solution.joint_trajectory = joint_trajectory(timed, joints)
    response.fraction = reached
    response.error_code.val = Codes.SUCCESS
    return response

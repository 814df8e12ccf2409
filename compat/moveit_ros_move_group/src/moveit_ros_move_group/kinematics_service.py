"""move_group's kinematics capability (MoveIt's MoveGroupKinematicsService): ``compute_fk``
and ``compute_ik``, each a function of the request and the context, so tested without a
master.

compute_fk: the poses of ``fk_link_names`` in ``header.frame_id`` (a link of the robot or
the model frame; empty: the model frame) for ``robot_state`` applied to the current state;
a link the robot lacks is left out and the answer is INVALID_LINK_NAME, as MoveIt's.
compute_ik: the group's solver from the seed (``robot_state`` over the current state)
within ``timeout`` (0: the solver's ``kinematics_solver_timeout``); the solution holds
every joint of the robot, the group's changed. With ``avoid_collisions`` a solution must
be free in the planning scene (the robot, attached objects, the world; the allowed
collision matrix applies), as MoveIt's collision-aware IK: when none is found within the
timeout the answer is NO_IK_SOLUTION, and the log names what the last solution touched.
"""
from __future__ import annotations

import logging

import numpy as np
from moveit_msgs.msg import MoveItErrorCodes
from moveit_msgs.srv import GetPositionFKResponse, GetPositionIKResponse
from geometry_msgs.msg import PoseStamped

from moveit_core.robot_model import RobotModelError
from moveit_ros_move_group.context import MoveGroupContext
from moveit_ros_move_group.conversions import (MessageError, matrix_pose, pose_matrix,
                                               robot_state, state_positions)

# rospy shows the rosout.* loggers on the console and /rosout
LOG = logging.getLogger("rosout.move_group")


def compute_fk(context: MoveGroupContext, request) -> GetPositionFKResponse:
    response = GetPositionFKResponse()
    try:
        positions = state_positions(request.robot_state, context.state.positions())
    except MessageError as error:
        LOG.error("compute_fk: %s", error)
        response.error_code.val = MoveItErrorCodes.INVALID_ROBOT_STATE
        return response
    frame = request.header.frame_id
    try:
        reference = context.frame_pose(frame, positions)
    except KeyError:
        LOG.error("compute_fk: frame '%s' is neither a link of the robot nor its model frame "
                  "'%s'", frame, context.model.model_frame)
        response.error_code.val = MoveItErrorCodes.FRAME_TRANSFORM_FAILURE
        return response
    poses = context.model.link_poses(positions)
    inverse = np.linalg.inv(reference)
    response.error_code.val = MoveItErrorCodes.SUCCESS
    for link in request.fk_link_names:
        if link not in poses:
            LOG.error("compute_fk: the robot has no link '%s'", link)
            response.error_code.val = MoveItErrorCodes.INVALID_LINK_NAME
            continue
        stamped = PoseStamped()
        stamped.header.frame_id = frame or context.model.model_frame
        stamped.header.stamp = request.header.stamp
        stamped.pose = matrix_pose(inverse @ poses[link])
        response.pose_stamped.append(stamped)
        response.fk_link_names.append(link)
    return response


def compute_ik(context: MoveGroupContext, request, monitor=None) -> GetPositionIKResponse:
    """``monitor``: move_group's scene monitor, for ``avoid_collisions``."""
    response = GetPositionIKResponse()
    ik = request.ik_request
    code = MoveItErrorCodes()
    try:
        solver = context.solver(ik.group_name)
    except RobotModelError as error:
        LOG.error("compute_ik: %s", error)
        unknown = ik.group_name not in context.model.groups
        response.error_code.val = (code.INVALID_GROUP_NAME if unknown else code.NO_IK_SOLUTION)
        return response
    link = ik.ik_link_name or solver.tip
    if link != solver.tip:
        LOG.error("compute_ik: group '%s' solves for its tip '%s', not '%s'", ik.group_name,
                  solver.tip, link)
        response.error_code.val = code.INVALID_LINK_NAME
        return response
    try:
        seed = state_positions(ik.robot_state, context.state.positions())
        target = pose_matrix(ik.pose_stamped.pose, "ik_request.pose_stamped.pose")
    except MessageError as error:
        LOG.error("compute_ik: %s", error)
        response.error_code.val = code.INVALID_ROBOT_STATE if "robot_state" in str(error) \
            else code.INVALID_GOAL_CONSTRAINTS
        return response
    try:
        frame = context.frame_pose(ik.pose_stamped.header.frame_id, seed)
    except KeyError:
        LOG.error("compute_ik: frame '%s' is neither a link of the robot nor its model frame",
                  ik.pose_stamped.header.frame_id)
        response.error_code.val = code.FRAME_TRANSFORM_FAILURE
        return response
    base = context.frame_pose(solver.base, seed)
    in_base = np.linalg.inv(base) @ frame @ target
    timeout = ik.timeout.to_sec()
    accept, touched = None, []
    if ik.avoid_collisions and monitor is not None:
        scene = monitor.snapshot()

        def accept(solution):
            hit = scene.contacts(dict(seed, **solver.state(solution)), ik.group_name)
            touched[:] = hit
            return not hit
    solution = solver.inverse(in_base, [seed.get(j, 0.0) for j in solver.joints],
                              timeout if timeout > 0 else None, accept=accept)
    if solution is None:
        if touched:
            LOG.info("compute_ik: no collision-free solution for group '%s' (the last one "
                     "found: %s touches %s)", ik.group_name, *touched[0])
        response.error_code.val = code.NO_IK_SOLUTION
        return response
    seed.update(solver.state(solution))
    full = context.model.complete(seed)
    response.solution = robot_state(full, [j for j in context.model.joint_order
                                           if j in context.model.bounds])
    response.error_code.val = code.SUCCESS
    return response


"""move_group's scene capabilities (MoveIt's MoveGroupGetPlanningSceneService,
ApplyPlanningSceneService, MoveGroupStateValidationService, ClearOctomapService):
functions of the request and the scene monitor, tested without a master."""
from __future__ import annotations

import rospy
from moveit_msgs.msg import ContactInformation, ConstraintEvalResult
from moveit_msgs.srv import (ApplyPlanningSceneResponse, GetPlanningSceneResponse,
                             GetStateValidityResponse)
from std_srvs.srv import EmptyResponse

from moveit_core.planning_scene import SceneError
from moveit_planners_ompl.goals import GoalError, satisfied
from moveit_ros_move_group.conversions import MessageError, state_positions


def get_planning_scene(monitor, request) -> GetPlanningSceneResponse:
    with monitor.lock:
        monitor.scene.set_state(monitor.current.positions())
        return GetPlanningSceneResponse(scene=monitor.scene.to_msg(request.components.components))


def apply_planning_scene(monitor, request) -> ApplyPlanningSceneResponse:
    try:
        monitor.apply(request.scene)
    except SceneError as error:
        rospy.logerr("apply_planning_scene: %s (nothing applied)", error)
        return ApplyPlanningSceneResponse(success=False)
    return ApplyPlanningSceneResponse(success=True)


def check_state_validity(monitor, request) -> GetStateValidityResponse:
    """The state (the request's over the current) against the scene for the group (every
    link when it names none) and the constraints."""
    response = GetStateValidityResponse(valid=True)
    scene = monitor.snapshot()
    try:
        positions = state_positions(request.robot_state, scene.positions)
    except MessageError as error:
        rospy.logerr("check_state_validity: %s", error)
        response.valid = False
        return response
    group = request.group_name or None
    if group is not None and group not in scene.model.groups:
        rospy.logerr("check_state_validity: no group '%s'", group)
        response.valid = False
        return response
    for a, b in scene.contacts(positions, group, first_only=False):
        response.valid = False
        response.contacts.append(ContactInformation(
            contact_body_1=a, contact_body_2=b,
            body_type_1=_body_type(scene, a), body_type_2=_body_type(scene, b)))
    outside = scene.model.within_bounds(positions)
    if outside:
        response.valid = False
        rospy.loginfo("check_state_validity: outside the bounds: %s", "; ".join(outside))
    constraints = request.constraints
    if constraints.joint_constraints or constraints.position_constraints or \
            constraints.orientation_constraints:
        try:
            broken = satisfied(scene, positions, constraints)
        except GoalError as error:
            broken = str(error)
        response.constraint_result.append(ConstraintEvalResult(result=broken is None))
        if broken is not None:
            response.valid = False
    return response


def _body_type(scene, name: str) -> int:
    if name in scene.attached:
        return ContactInformation.ROBOT_ATTACHED
    if name in scene.objects:
        return ContactInformation.WORLD_OBJECT
    return ContactInformation.ROBOT_LINK


def clear_octomap(_monitor, _request) -> EmptyResponse:
    """No sensors feed this move_group an octomap: there is nothing to clear."""
    return EmptyResponse()

"""What move_group checks where a request enters it, before anything plans or moves: one
module that every capability uses. A request that fails a check is refused with MoveIt's
error code and a message naming the cause (the field by its path, the trajectory point, the
joint, its limit and the value); nothing raises.

- :func:`non_finite`: the first NaN or infinite float of any message, by its field path
  (``goal_constraints[0].position_constraints[0].constraint_region.primitive_poses[0]
  .position.x is nan``); a float of a JointState or JointTrajectory array names its joint.
- :func:`check_plan_request` (the ``move_group`` action, ``plan_kinematic_path``): goal
  constraints holding a non-finite value are INVALID_GOAL_CONSTRAINTS, start state positions
  holding one INVALID_ROBOT_STATE (the codes MoveIt's pipeline gives an unusable goal or
  start); path constraints holding one START_STATE_VIOLATES_PATH_CONSTRAINTS, what MoveIt
  ends with (a comparison with NaN is false: no state satisfies them, not even one that
  FixStartStatePathConstraints plans to). What the planner does not read is not checked
  (trajectory constraints, workspace bounds; a start state's velocities and efforts, which
  a driver may publish as NaN and a client copy from joint_states); a non-finite scaling
  factor means 1, as MoveIt's time parameterization reads it.
- :func:`check_trajectory` (``execute_trajectory``): a trajectory holding a non-finite value,
  or a point outside a joint's position limits, is INVALID_MOTION_PLAN; a point whose
  positions (velocities, accelerations, efforts) do not match the joint names is
  CONTROL_FAILED, as MoveIt's TrajectoryExecutionManager::validate refuses it ("Wrong
  trajectory: #joints != #positions", trajectory_execution_manager.cpp, noetic-devel
  7c0343f0, l. 742-747: the ExecuteTrajectory capability answers the refusal
  CONTROL_FAILED). MoveIt itself sends a trajectory outside the limits to the controllers,
  which refuse or saturate it; here it is refused before anything moves. The first point
  may lie outside a joint's limits by as much as ``start_state_max_bounds_error``: a plan
  from a start that far out begins there (FixStartStateBounds prefixes the start as given:
  fix_start_state_bounds.cpp l. 197) and moveit_commander executes plans through ``execute_trajectory``.
No ROS master is needed."""
from __future__ import annotations

import math
from typing import List, Mapping, Optional, Sequence

import genpy
from moveit_msgs.msg import MoveItErrorCodes as Codes
from sensor_msgs.msg import JointState

FLOATS = ("float32", "float64")
# rad (m): a point this far outside its limits is still inside (rounding of a limit that a
# client computed), past the first point
BOUNDS_MARGIN = 1e-9


class Refused(ValueError):
    """A request move_group will not act on: ``code`` is MoveIt's error code, the message
    names the cause."""

    def __init__(self, code: int, message: str):
        super().__init__(message)
        self.code = code
        self.message = message


def non_finite(message: genpy.Message, path: str = "") -> Optional[str]:
    """The first float field of ``message`` (nested messages and arrays included) that is
    NaN or infinite, as ``'<path>.<field>[<i>] is <value>'``; None when all are finite."""
    return _walk(message, path, None)


def _joint_names(message, inherited: Optional[Sequence[str]]) -> Optional[Sequence[str]]:
    """The joint names that index a message's float arrays: a JointTrajectory's
    ``joint_names`` (for its points), a JointState's ``name``."""
    names = getattr(message, "joint_names", None)
    if isinstance(names, (list, tuple)):
        return names
    if hasattr(message, "position") and isinstance(getattr(message, "name", None),
                                                   (list, tuple)):
        return message.name
    return inherited


def _walk(message, path: str, names: Optional[Sequence[str]]) -> Optional[str]:
    names = _joint_names(message, names)
    for slot, kind in zip(message.__slots__, message._slot_types):
        value = getattr(message, slot)
        here = f"{path}.{slot}" if path else slot
        array = kind.endswith("]")
        base = kind.split("[", 1)[0]
        if base in FLOATS:
            for index, number in enumerate(value if array else [value]):
                if not math.isfinite(number):
                    where = here
                    if array:
                        where = f"{here}[{index}]"
                        if names is not None and index < len(names):
                            where += f" (joint '{names[index]}')"
                    return f"{where} is {number}"
        elif array and value and isinstance(value[0], genpy.Message):
            for index, item in enumerate(value):
                found = _walk(item, f"{here}[{index}]", names)
                if found:
                    return found
        elif isinstance(value, genpy.Message):
            found = _walk(value, here, names)
            if found:
                return found
    return None


def check_plan_request(request, where: str = "request") -> None:
    """Raises :class:`Refused` for a MotionPlanRequest holding a non-finite value in what
    the planner reads: its goal or path constraints or its start state's positions."""
    for index, constraints in enumerate(request.goal_constraints):
        found = non_finite(constraints, f"{where}.goal_constraints[{index}]")
        if found:
            raise Refused(Codes.INVALID_GOAL_CONSTRAINTS,
                          f"{_joint_of(constraints, found)}{found}: goal constraints must be "
                          "finite numbers (nothing was planned)")
    found = non_finite(request.path_constraints, f"{where}.path_constraints")
    if found:
        raise Refused(Codes.START_STATE_VIOLATES_PATH_CONSTRAINTS,
                      f"{_joint_of(request.path_constraints, found)}{found}: path constraints "
                      "must be finite numbers (nothing was planned)")
    state = request.start_state.joint_state
    found = non_finite(JointState(name=state.name, position=state.position),
                       f"{where}.start_state.joint_state")
    if found:
        raise Refused(Codes.INVALID_ROBOT_STATE,
                      f"{found}: a start state must be finite numbers (nothing was planned)")


def _joint_of(constraints, found: str) -> str:
    """'joint 'elbow': ' when the non-finite value is in a joint constraint."""
    marker = ".joint_constraints["
    if marker not in found:
        return ""
    index = int(found.split(marker, 1)[1].split("]", 1)[0])
    return f"joint '{constraints.joint_constraints[index].joint_name}': "


def check_trajectory(trajectory, bounds: Mapping, start_margin: float,
                     where: str = "trajectory") -> None:
    """Raises :class:`Refused` for a RobotTrajectory that must not reach the controllers
    (``bounds``: the model's Bounds by joint; joints it lacks are left to the controllers'
    assignment, which refuses them)."""
    found = non_finite(trajectory, where)
    if found:
        raise Refused(Codes.INVALID_MOTION_PLAN,
                      f"{found}: a trajectory must hold finite numbers (nothing was executed)")
    joints: List[str] = list(trajectory.joint_trajectory.joint_names)
    twice = sorted({j for j in joints if joints.count(j) > 1})
    if twice:
        raise Refused(Codes.CONTROL_FAILED, f"{where}.joint_trajectory.joint_names name "
                      f"{twice} more than once (nothing was executed)")
    for index, point in enumerate(trajectory.joint_trajectory.points):
        at = f"{where}.joint_trajectory.points[{index}]"
        for field in ("positions", "velocities", "accelerations", "effort"):
            values = getattr(point, field)
            if len(values) != len(joints) and (field == "positions" or values):
                raise Refused(Codes.CONTROL_FAILED,
                              f"{at} has {len(values)} {field} for {len(joints)} joints "
                              f"{joints} (nothing was executed)")
        margin = start_margin if index == 0 else BOUNDS_MARGIN
        for joint, value in zip(joints, point.positions):
            limits = bounds.get(joint)
            if limits is not None and limits.bounded and not limits.contains(value, margin):
                raise Refused(Codes.INVALID_MOTION_PLAN,
                              f"{at}: joint '{joint}' at {value:.4f} is outside its limits "
                              f"{limits.lower:.4f} to {limits.upper:.4f}"
                              + (f" (by more than start_state_max_bounds_error {margin})"
                                 if index == 0 and margin > 0 else "")
                              + " (nothing was executed)")

"""Goal constraints (moveit_msgs/Constraints) as MoveIt's constraint samplers read them:
joint constraints give one joint-space goal, each constrained joint drawn uniformly from
its tolerance band within its bounds (JointConstraintSampler::sample,
moveit_core/constraint_samplers/src/default_constraint_samplers.cpp l. 184-186 on
noetic-devel: so a goal equal to the start is never the start itself to the last bit, and
a path to it has a segment of non-zero length, as a controller needs strictly increasing
times); a position constraint on a link (a sphere or box region, as
moveit_commander writes for a pose or position target), with or without an orientation
constraint, is sampled by the group's IK solver from random seeds; each sample must lie
within the bounds, satisfy every constraint of the set (and the request's path
constraints, which MoveIt merges into each goal set) and be collision-free.
:func:`satisfied` checks a state against a constraint set with MoveIt's evaluation
(:mod:`moveit_core.kinematic_constraints`: intrinsic XYZ Euler angles for orientations)."""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import Dict, List, Mapping, Optional, Tuple

import numpy as np
from geometry_msgs.msg import Pose
from moveit_msgs.msg import Constraints, MoveItErrorCodes
from tf.transformations import random_rotation_matrix

from moveit_core.kinematic_constraints import ConstraintError, ConstraintSet
from moveit_core.planning_scene import PlanningScene, SceneError, pose_matrix

GOAL_SAMPLES = 4            # valid IK goals gathered for a search (one for a straight line)
# IK attempts for one goal set, within the planning time: MoveIt's max_goal_sampling_attempts
# (planning_context_manager.cpp l. 241, noetic-devel: 1000). An unreachable pose so takes the
# planning time (or 1000 solver timeouts) to be refused, as in MoveIt; a reachable one found
# on a narrow branch (a 6-axis arm's singular wrist) is found
MAX_IK_TRIES = 1000


class GoalError(ValueError):
    """Goal constraints that cannot be used: ``code`` is MoveIt's error code."""

    def __init__(self, code: int, message: str):
        super().__init__(message)
        self.code = code


@dataclass
class Goals:
    states: List[Dict[str, float]] = field(default_factory=list)
    ik_solutions: int = 0            # IK answers found, valid or not
    collisions: List[Tuple[str, str]] = field(default_factory=list)
    violations: List[str] = field(default_factory=list)   # of the path constraints


def _region_center(constraint, scene: PlanningScene, poses) -> np.ndarray:
    """Where a position constraint wants its link point, in the model frame."""
    region = constraint.constraint_region
    if not region.primitive_poses:
        raise GoalError(MoveItErrorCodes.INVALID_GOAL_CONSTRAINTS,
                        f"position constraint on '{constraint.link_name}' has no region")
    frame = _frame(scene, constraint.header.frame_id, poses)
    return (frame @ pose_matrix(region.primitive_poses[0], "region pose"))[:3, 3]


def _frame(scene: PlanningScene, frame: str, poses) -> np.ndarray:
    try:
        return scene.frame_pose(frame, poses)
    except SceneError as error:
        raise GoalError(MoveItErrorCodes.FRAME_TRANSFORM_FAILURE, str(error)) from error


def satisfied(scene: PlanningScene, positions: Mapping[str, float], constraints: Constraints,
              poses=None) -> Optional[str]:
    """None when ``positions`` satisfy the set; else which constraint they break. Links a
    goal names must exist (INVALID_LINK_NAME); the evaluation is MoveIt's
    (:mod:`moveit_core.kinematic_constraints`)."""
    for constraint in list(constraints.position_constraints) + \
            list(constraints.orientation_constraints):
        if constraint.link_name not in scene.model.urdf.links:
            raise GoalError(MoveItErrorCodes.INVALID_LINK_NAME,
                            f"a goal constraint on '{constraint.link_name}', which the robot "
                            "lacks")
    for joint in constraints.joint_constraints:
        if joint.joint_name not in positions:
            return f"joint '{joint.joint_name}' has no position"
    try:
        return ConstraintSet(scene, constraints).decide(positions, poses)
    except ConstraintError as error:
        raise GoalError(error.code, str(error)) from error


def joint_goal(scene: PlanningScene, group: str, start: Mapping[str, float],
               constraints: Constraints, rng: np.random.Generator) -> Dict[str, float]:
    goal = dict(start)
    variables = scene.model.group(group).variables
    for joint in constraints.joint_constraints:
        name = joint.joint_name
        if name not in scene.model.bounds:
            raise GoalError(MoveItErrorCodes.INVALID_GOAL_CONSTRAINTS,
                            f"joint constraint on '{name}', which the robot lacks")
        if not math.isfinite(joint.position):
            raise GoalError(MoveItErrorCodes.INVALID_GOAL_CONSTRAINTS,
                            f"joint constraint on '{name}': position {joint.position}")
        bounds = scene.model.bounds[name]
        low = max(joint.position - joint.tolerance_below, bounds.lower)
        high = min(joint.position + joint.tolerance_above, bounds.upper)
        if low > high + 1e-12:
            raise GoalError(MoveItErrorCodes.INVALID_GOAL_CONSTRAINTS,
                            f"joint '{name}' goal {joint.position:.4f} is outside its bounds "
                            f"{bounds.lower:.4f} to {bounds.upper:.4f}")
        goal[name] = float(rng.uniform(low, high)) if high > low else low
        if name not in variables:
            raise GoalError(MoveItErrorCodes.INVALID_GOAL_CONSTRAINTS,
                            f"joint '{name}' is not in group '{group}'")
    return goal


def pose_goals(scene: PlanningScene, group: str, start: Mapping[str, float],
               constraints: Constraints, solver, deadline: float, rng: np.random.Generator,
               wanted: int = GOAL_SAMPLES, path: Optional[ConstraintSet] = None) -> Goals:
    """Goal states of a position (and orientation) constraint, sampled by IK; with
    ``path``, only states that satisfy the path constraints too (MoveIt merges them into
    each goal set: model_based_planning_context.cpp:597-611, mergeConstraints)."""
    if solver is None:
        raise GoalError(MoveItErrorCodes.PLANNING_FAILED,
                        f"group '{group}' has no kinematics solver: a pose goal cannot be "
                        "sampled (give robot_description_kinematics an entry for it)")
    links = {c.link_name for c in constraints.position_constraints} | \
        {c.link_name for c in constraints.orientation_constraints}
    if len(links) != 1:
        raise GoalError(MoveItErrorCodes.INVALID_GOAL_CONSTRAINTS,
                        f"pose constraints on {sorted(links)}: one link per goal")
    link = links.pop()
    poses = scene.model.link_poses(start)
    if link not in poses:
        raise GoalError(MoveItErrorCodes.INVALID_LINK_NAME,
                        f"a pose goal for '{link}', which the robot lacks")
    offset = _fixed_offset(scene.model, solver.tip, link)
    base = poses[solver.base]
    position = constraints.position_constraints[0] if constraints.position_constraints else None
    orientation = constraints.orientation_constraints[0] \
        if constraints.orientation_constraints else None
    center = _region_center(position, scene, poses) if position is not None else None
    target_rotation = None
    if orientation is not None:
        frame = _frame(scene, orientation.header.frame_id, poses)
        target_rotation = (frame @ pose_matrix(Pose(orientation=orientation.orientation),
                                               "orientation"))[:3, :3]
    goals = Goals()
    seed = [start[j] for j in solver.joints]
    for attempt in range(MAX_IK_TRIES):
        if len(goals.states) >= wanted or (attempt > 0 and time.monotonic() > deadline):
            break
        target = np.eye(4)
        target[:3, :3] = target_rotation if target_rotation is not None else \
            random_rotation_matrix(rng.random(3))[:3, :3]
        if center is not None:
            target[:3, 3] = center
        else:   # an orientation alone: a position the link can have
            sample = {j: rng.uniform(*_range(scene.model.bounds[j])) for j in solver.joints}
            target[:3, 3] = scene.model.link_poses(dict(start, **sample))[link][:3, 3]
        tip_target = target @ np.linalg.inv(offset)
        solution = solver.inverse(np.linalg.inv(base) @ tip_target, seed)
        seed = [rng.uniform(*_range(scene.model.bounds[j])) for j in solver.joints]
        if solution is None:
            continue
        goals.ik_solutions += 1
        state = dict(start, **solver.state(solution))
        if satisfied(scene, state, constraints) is not None:
            continue
        broken = path.decide(state) if path is not None else None
        if broken is not None:
            goals.violations.append(broken)
            continue
        hit = scene.contacts(state, group)
        if hit:
            goals.collisions += hit
            continue
        goals.states.append(state)
    return goals


def _range(bounds) -> Tuple[float, float]:
    return (bounds.lower, bounds.upper) if bounds.bounded else (-math.pi, math.pi)


def fixed_offset(model, tip: str, link: str) -> Optional[np.ndarray]:
    """The pose of ``link`` in the solver tip's frame when fixed joints join them, else None."""
    if link == tip:
        return np.eye(4)
    poses = model.link_poses(model.default_positions())
    for a, b in ((tip, link), (link, tip)):
        try:
            chain = model.urdf.chain(a, b)
        except ValueError:
            continue
        if all(j.type == "fixed" for j in chain):
            return np.linalg.inv(poses[tip]) @ poses[link]
    return None


def _fixed_offset(model, tip: str, link: str) -> np.ndarray:
    """:func:`fixed_offset`, a goal's link that does not move rigidly with the tip refused."""
    offset = fixed_offset(model, tip, link)
    if offset is None:
        raise GoalError(MoveItErrorCodes.INVALID_LINK_NAME,
                        f"the group's IK solves for '{tip}'; '{link}' does not move rigidly with it")
    return offset
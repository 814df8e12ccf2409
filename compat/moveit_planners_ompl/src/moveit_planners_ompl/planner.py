"""MoveIt's planning pipeline with OMPL (``ompl_interface/OMPLPlanner`` and the default
request adapters), in Python on PyPI's OMPL: a MotionPlanRequest and a planning scene in,
MoveIt's error code and a timed RobotTrajectory of the group out.

In order, as the pipeline runs:
- the group must exist (INVALID_GROUP_NAME) and there must be goal constraints
  (INVALID_GOAL_CONSTRAINTS);
- the start is the scene's state with the request's ``start_state`` over it;
  FixStartStateBounds: a joint outside its bounds by no more than
  ``start_state_max_bounds_error`` is moved onto them (farther: START_STATE_INVALID);
  FixStartStateCollision: a start in collision is jiggled (``jiggle_fraction`` of each
  joint's range, 100 tries) to a free state nearby, else START_STATE_IN_COLLISION;
- path constraints (:mod:`moveit_core.kinematic_constraints`, MoveIt's evaluation): a start
  that breaks them is first planned onto them without them and the request planned from
  there, the two paths joined (FixStartStatePathConstraints; when nothing reaches them,
  START_STATE_VIOLATES_PATH_CONSTRAINTS); they are merged into every goal set (goal states
  that break them are not used: when none is left, PLANNING_FAILED naming them), every
  state checked while planning and every waypoint returned keeps them, and the search
  grows towards states their constraint sampler draws (:mod:`constrained`);
- each goal constraint set (alternatives) gives goal states (:mod:`goals`): a joint goal
  outside the bounds is INVALID_GOAL_CONSTRAINTS; a pose goal no IK reaches, or goals whose
  every state collides, are PLANNING_FAILED, as MoveIt's OMPL context answers every solve
  that fails (the message says which: users' tests assert -1 for both);
- the straight joint-space line to the nearest goal when it is free, else the group's OMPL
  planner (``ompl_planning.yaml``) within ``allowed_planning_time`` (PLANNING_FAILED when
  it finds nothing), its path simplified and interpolated;
- the whole path checked again four times more finely than motions were checked while
  planning; where that finds a collision the planning resolution stepped over, the search
  runs again at the finer resolution while time is left (else INVALID_MOTION_PLAN);
- AddTimeParameterization: times within the joint limits and the request's scaling.
Continuous joints are planned within [-pi, pi]. Collision checks use the group's moving
links (:meth:`PlanningScene.contacts`); motions are checked every
``longest_valid_segment_fraction`` of the space's extent, as MoveIt's OMPL interface does.
"""
from __future__ import annotations

import logging
import math
import time
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence

import numpy as np
from moveit_msgs.msg import MoveItErrorCodes as Codes
from ompl import base as ob
from ompl import geometric as og
from ompl import util as ou

from moveit_core.kinematic_constraints import ConstraintError, ConstraintSet
from moveit_core.planning_scene import PlanningScene
from moveit_core.robot_model import RobotModelError
from moveit_core.time_parameterization import Timed, limits_of, time_path
from moveit_planners_ompl.constrained import (ConstrainedSampler, planner_range, rrt_connect,
                                              shortcut)
from moveit_planners_ompl.goals import GOAL_SAMPLES, GoalError, Goals, joint_goal, pose_goals
from moveit_planners_ompl.planner_configs import PlannerConfigs

# rospy shows the rosout.* loggers on the console and /rosout
LOG = logging.getLogger("rosout.move_group")
ou.setLogLevel(ou.LOG_WARN)

DEFAULT_PLANNING_TIME = 1.0      # s, for a request that allows none (MoveIt's)
JIGGLE_TRIES = 100               # FixStartStateCollision's max_sampling_attempts
GOAL_SHARE = 0.5                 # of the planning time IK goal sampling may take
MAX_SEED = 2 ** 32 - 1           # OMPL's seeds are unsigned 32-bit; 0 would be its own
# the found path is checked again this many times more finely than motions were checked
# while planning: a thin object a planning step jumped over is found there
FINAL_CHECK_DIVISOR = 4


@dataclass(frozen=True)
class AdapterSettings:
    """The request adapters' parameters (move_group's namespace; Setup-Assistant values)."""

    start_state_max_bounds_error: float = 0.1
    jiggle_fraction: float = 0.05


@dataclass
class PlanResult:
    code: int
    message: str
    start: Dict[str, float] = field(default_factory=dict)
    joints: List[str] = field(default_factory=list)
    timed: Optional[Timed] = None
    planning_time: float = 0.0

    @property
    def ok(self) -> bool:
        return self.code == Codes.SUCCESS


class OmplPlanner:
    """Plans for every group of a scene's robot (``solvers(group)``: the group's IK solver
    or None)."""

    def __init__(self, configs: PlannerConfigs, solvers, adapters: AdapterSettings = AdapterSettings(),
                 seed: int = 1):
        self.configs, self.solvers, self.adapters = configs, solvers, adapters
        self.seed = seed
        self._plans = 0

    def plan(self, scene: PlanningScene, request) -> PlanResult:
        began = time.monotonic()
        try:
            result = self._plan(scene, request, began)
        except GoalError as error:
            result = PlanResult(error.code, str(error))
        result.planning_time = time.monotonic() - began
        if not result.ok:
            LOG.warning("planning for group '%s' failed (%d): %s", request.group_name,
                        result.code, result.message)
        return result

    # --- the pipeline --------------------------------------------------------------------

    def _plan(self, scene: PlanningScene, request, began: float) -> PlanResult:
        group_name = request.group_name
        if not group_name:
            return PlanResult(Codes.INVALID_GROUP_NAME, "the request names no group")
        try:
            group = scene.model.group(group_name)
        except RobotModelError as error:
            return PlanResult(Codes.INVALID_GROUP_NAME, str(error))
        joints = list(group.variables)
        goals_given = [c for c in request.goal_constraints
                       if c.joint_constraints or c.position_constraints or
                       c.orientation_constraints]
        if not goals_given:
            return PlanResult(Codes.INVALID_GOAL_CONSTRAINTS, "the request has no goal "
                              "constraints")
        allowed = request.allowed_planning_time if request.allowed_planning_time > 0 \
            else DEFAULT_PLANNING_TIME
        self._plans += 1
        seed = (self.seed + self._plans) % MAX_SEED or 1
        rng = np.random.default_rng(seed)
        start = self._start(scene, request, joints)
        if isinstance(start, PlanResult):
            return start
        prefix, start = start
        try:
            path_set = ConstraintSet(scene, request.path_constraints)
        except ConstraintError as error:
            return PlanResult(error.code, f"path_constraints: {error}", prefix)
        path_set = None if path_set.empty else path_set
        broken = path_set.decide(start) if path_set is not None else None
        if broken is None:
            dense = self._path(scene, request, joints, start, goals_given, path_set, began,
                               allowed, rng, seed)
        else:
            dense = self._to_path_constraints(scene, request, joints, start, goals_given,
                                              path_set, broken, allowed, rng, seed)
        if isinstance(dense, PlanResult):
            dense.start = prefix
            return dense
        # the start as given leads the path whenever FixStartStateBounds moved it into its
        # bounds, by however little (moveit noetic-devel 7c0343f0, moveit_ros/planning/
        # planning_request_adapter_plugins/src/fix_start_state_bounds.cpp:145-152, 197); the
        # waypoints carry no velocities (the scene's current state is positions only unless
        # copy_dynamics is enabled), so IPTP mirrors the first segment
        positions = ([np.array([prefix[j] for j in joints])]
                     if any(prefix[j] != start[j] for j in joints) else []) + dense
        velocity, acceleration = limits_of(scene.model, joints)
        timed = time_path(positions, velocity, acceleration,
                          request.max_velocity_scaling_factor,
                          request.max_acceleration_scaling_factor)
        return PlanResult(Codes.SUCCESS, f"planned: {len(dense)} waypoints, "
                          f"{timed.times[-1]:.2f} s", prefix, joints, timed)

    def _to_path_constraints(self, scene, request, joints, start, goals_given, path_set,
                             broken, allowed, rng, seed):
        """FixStartStatePathConstraints (fix_start_state_path_constraints.cpp:70-128 on
        noetic-devel): a start that breaks the path constraints is first moved, by a plan
        without them, to a state that satisfies them; the request is planned from there and
        the two paths joined. Each plan has the request's planning time; when the first
        finds nothing the answer is START_STATE_VIOLATES_PATH_CONSTRAINTS."""
        LOG.info("Path constraints not satisfied for start state (%s); planning to path "
                 "constraints", broken)
        try:
            first = self._path(scene, request, joints, start, [request.path_constraints], None,
                               time.monotonic(), allowed, rng, seed)
        except GoalError as error:   # the path constraints are no goal one can sample
            first = PlanResult(error.code, str(error))
        if isinstance(first, PlanResult):
            LOG.warning("Unable to plan to path constraints: %s", first.message)
            return PlanResult(Codes.START_STATE_VIOLATES_PATH_CONSTRAINTS,
                              f"the start state breaks the path constraints ({broken}) and no "
                              f"plan reaches them: {first.message}")
        LOG.info("Planned to path constraints. Resuming original planning request.")
        reached = dict(start, **dict(zip(joints, (float(v) for v in first[-1]))))
        second = self._path(scene, request, joints, reached, goals_given, path_set,
                            time.monotonic(), allowed, rng, seed)
        if isinstance(second, PlanResult):
            return second
        return first + second[1:]

    def _path(self, scene, request, joints, start, goals_given, path_set, began, allowed, rng,
              seed):
        """The dense joint-space path from ``start`` to one of the goal sets (or a failed
        PlanResult): goal states, the straight line when it is valid, else the search; every
        state checked keeps the path constraints ``path_set`` (None: none) and is free."""
        group_name = request.group_name
        deadline = began + allowed
        # one goal first (IK from the start: most often the straight line reaches it), more
        # for the search when the line is blocked
        goals = self._goals(scene, group_name, start, goals_given,
                            began + allowed * GOAL_SHARE, rng, wanted=1, path=path_set)
        if isinstance(goals, PlanResult):
            return goals
        planning = self.configs.group(group_name, request.planner_id)
        lows, highs = self._space_bounds(scene, joints)
        goal_vectors = [np.clip([g[j] for j in joints], lows, highs) for g in goals]
        start_vector = np.clip([start[j] for j in joints], lows, highs)
        resolution = planning.longest_valid_segment_fraction * float(np.linalg.norm(highs - lows))

        def keeps(vector) -> bool:
            return path_set is None or \
                path_set.decide(dict(start, **dict(zip(joints, vector)))) is None

        def valid(vector) -> bool:
            return keeps(vector) and \
                not scene.contacts(dict(start, **dict(zip(joints, vector))), group_name)

        def motion_free(a, b, step) -> bool:
            states, order = _motion_states(a, b, step)
            if path_set is not None and not all(keeps(states[k]) for k in order):
                return False
            return scene.first_collision(start, joints, states, group_name, order) is None

        order = np.argsort([np.linalg.norm(g - start_vector) for g in goal_vectors])
        path = None
        fine = resolution / FINAL_CHECK_DIVISOR
        for index in order:   # the straight line first (checked as finely as a found path)
            line = [start_vector, goal_vectors[index]]
            if motion_free(*line, fine) and all(keeps(state) for state in
                                                _interpolate(line, resolution)):
                path = line
                break
        if path is None and len(goals) < GOAL_SAMPLES and any(
                c.position_constraints or c.orientation_constraints for c in goals_given):
            more = self._goals(scene, group_name, start, goals_given,
                               began + allowed * GOAL_SHARE, rng, path=path_set)
            if not isinstance(more, PlanResult):
                goal_vectors += [np.clip([g[j] for j in joints], lows, highs) for g in more]
        while path is None:
            seconds = max(0.05, deadline - time.monotonic())
            if path_set is None:
                path = self._search(joints, lows, highs, start_vector, goal_vectors, planning,
                                    resolution, valid, seconds, seed)
            else:
                path = self._constrained_search(scene, group_name, joints, start, lows, highs,
                                                start_vector, goal_vectors, planning,
                                                resolution, path_set, motion_free, seconds, rng)
            if isinstance(path, PlanResult):
                return path
            dense = _interpolate(path, resolution)
            if all(motion_free(a, b, fine) for a, b in zip(path, path[1:])) and \
                    all(keeps(state) for state in dense):
                return dense
            # a corner the planning resolution stepped over: search again checking motions
            # as finely as the final check, while time is left
            if time.monotonic() >= deadline or resolution <= fine:
                return PlanResult(Codes.INVALID_MOTION_PLAN, "the planned path collides or "
                                  "breaks the path constraints between the states the "
                                  "planner checked")
            resolution, path = fine, None
        return _interpolate(path, resolution)

    def _constrained_search(self, scene, group, joints, start, lows, highs, start_vector,
                            goal_vectors, planning, resolution, path_set, motion_free, seconds,
                            rng):
        """RRTConnect growing towards states the path constraints' sampler draws
        (:mod:`constrained`), its path shortcut; a PlanResult when time runs out."""
        deadline = time.monotonic() + seconds
        sampler = ConstrainedSampler(path_set, scene.model, joints, start, lows, highs,
                                     self._solver(group), rng)
        step = planner_range(planning.parameters, lows, highs)
        path = rrt_connect(start_vector, goal_vectors, sampler.sample,
                           lambda a, b: motion_free(a, b, resolution), step, deadline)
        if path is None:
            return PlanResult(Codes.PLANNING_FAILED, f"RRTConnect under path constraints found "
                              f"no path within {seconds:.2f} s ({sampler.constrained} "
                              f"constrained and {sampler.uniform} uniform samples)")
        # OMPL's simplifySolution gets what is left of the planning time, at most a quarter
        # of it (as _search)
        return shortcut(path, lambda a, b: motion_free(a, b, resolution), rng,
                        time.monotonic() + max(0.01, min(seconds / 4,
                                                         deadline - time.monotonic())))

    def _start(self, scene: PlanningScene, request, joints: Sequence[str]):
        """(the start as given, the start planned from) or a failed PlanResult."""
        given = dict(scene.positions)
        state = request.start_state.joint_state
        if len(state.name) != len(state.position):
            return PlanResult(Codes.INVALID_ROBOT_STATE, f"start_state has {len(state.name)} "
                              f"joint names and {len(state.position)} positions")
        for name, value in zip(state.name, state.position):
            if name in scene.model.bounds:
                if not math.isfinite(value):
                    return PlanResult(Codes.INVALID_ROBOT_STATE,
                                      f"start_state: joint '{name}' at {value}")
                given[name] = float(value)
        start = dict(given)
        for joint in joints:
            bounds = scene.model.bounds[joint]
            if not bounds.bounded:
                start[joint] = math.remainder(start[joint], 2 * math.pi)
                continue
            if not bounds.contains(start[joint]):
                if not bounds.contains(start[joint], self.adapters.start_state_max_bounds_error):
                    return PlanResult(Codes.START_STATE_INVALID,
                                      f"the start has {scene.model.within_bounds({joint: start[joint]})[0]}"
                                      f", beyond start_state_max_bounds_error "
                                      f"({self.adapters.start_state_max_bounds_error})", given)
                start[joint] = bounds.clamp(start[joint])
        hit = scene.contacts(start, request.group_name)
        if hit:
            freed = self._jiggle(scene, request.group_name, start, joints)
            if freed is None:
                return PlanResult(Codes.START_STATE_IN_COLLISION,
                                  f"the start state collides: {hit[0][0]} touches {hit[0][1]}",
                                  given)
            start = freed
        return given, start

    def _jiggle(self, scene, group, start, joints):
        rng = np.random.default_rng(len(joints))
        for _ in range(JIGGLE_TRIES):
            trial = dict(start)
            for joint in joints:
                lower, upper = self._bounds(scene, joint)
                reach = (upper - lower) * self.adapters.jiggle_fraction
                trial[joint] = float(np.clip(trial[joint] + rng.uniform(-reach, reach), lower,
                                             upper))
            if not scene.contacts(trial, group):
                return trial
        return None

    def _goals(self, scene, group, start, sets, deadline, rng, wanted=GOAL_SAMPLES, path=None):
        """Goal states of the sets; with ``path`` (a ConstraintSet) only those keeping the
        path constraints (merged into each goal set, as MoveIt does)."""
        states, found = [], Goals()
        for constraints in sets:
            if constraints.joint_constraints and not (constraints.position_constraints or
                                                      constraints.orientation_constraints):
                goal = joint_goal(scene, group, start, constraints, rng)
                broken = path.decide(goal) if path is not None else None
                hit = scene.contacts(goal, group) if broken is None else []
                if broken is not None:
                    found.violations.append(broken)
                elif hit:
                    found.collisions += hit
                else:
                    states.append(goal)
                continue
            sampled = pose_goals(scene, group, start, constraints,
                                 self._solver(group), deadline, rng, wanted, path)
            found.ik_solutions += sampled.ik_solutions
            found.collisions += sampled.collisions
            found.violations += sampled.violations
            states += sampled.states
        if states:
            return states
        if found.violations:
            # the merged goal sets cannot be sampled: OMPL's goal tree stays empty and the
            # solve fails (PLANNING_FAILED, as every failed solve here)
            return PlanResult(Codes.PLANNING_FAILED, "every goal state breaks the path "
                              f"constraints ({found.violations[0]})")
        if found.collisions:
            a, b = found.collisions[0]
            return PlanResult(Codes.PLANNING_FAILED, f"every goal state collides ({a} "
                              f"touches {b})")
        return PlanResult(Codes.PLANNING_FAILED, "no IK solution reaches the goal within the "
                          "joint bounds" + ("" if not found.ik_solutions else
                                            " and its constraints"))

    def _solver(self, group):
        try:
            return self.solvers(group)
        except RobotModelError:
            return None

    @staticmethod
    def _bounds(scene, joint):
        bounds = scene.model.bounds[joint]
        return (bounds.lower, bounds.upper) if bounds.bounded else (-math.pi, math.pi)

    def _space_bounds(self, scene, joints):
        ranges = [self._bounds(scene, j) for j in joints]
        return np.array([r[0] for r in ranges]), np.array([r[1] for r in ranges])

    def _search(self, joints, lows, highs, start, goals, planning, resolution, valid,
                seconds, seed):
        ou.setLogLevel(ou.LOG_NONE)
        ou.RNG.setSeed(seed)
        ou.setLogLevel(ou.LOG_WARN)
        count = len(joints)
        space = ob.RealVectorStateSpace(count)
        bounds = ob.RealVectorBounds(count)
        for i in range(count):
            bounds.setLow(i, float(lows[i]))
            bounds.setHigh(i, float(highs[i]))
        space.setBounds(bounds)
        # OMPL checks motions every fraction of the space's extent (its diagonal here)
        space.setLongestValidSegmentFraction(resolution / float(np.linalg.norm(highs - lows)))
        setup = og.SimpleSetup(space)
        information = setup.getSpaceInformation()
        setup.setStateValidityChecker(lambda s: valid([s[i] for i in range(count)]))
        start_state = space.allocState()
        for i in range(count):
            start_state[i] = float(start[i])
        setup.addStartState(start_state)
        goal_states = ob.GoalStates(information)
        for goal in goals:
            state = space.allocState()
            for i in range(count):
                state[i] = float(goal[i])
            goal_states.addState(state)
        setup.setGoal(goal_states)
        setup.setPlanner(self.configs.make(planning, information))
        setup.solve(seconds)
        if not setup.haveExactSolutionPath():
            return PlanResult(Codes.PLANNING_FAILED, f"{planning.planner} found no path within "
                              f"{seconds:.2f} s")
        setup.simplifySolution(max(0.01, seconds / 4))
        solution = setup.getSolutionPath()
        return [np.array([solution.getState(k)[i] for i in range(count)])
                for k in range(solution.getStateCount())]


def _interpolate(path: Sequence[np.ndarray], resolution: float) -> List[np.ndarray]:
    """The path's states no farther apart than ``resolution`` (Euclidean, joint space)."""
    dense = [np.asarray(path[0], dtype=float)]
    for a, b in zip(path, path[1:]):
        steps = max(1, int(math.ceil(np.linalg.norm(b - a) / resolution)))
        for k in range(1, steps + 1):
            dense.append(a + (b - a) * (k / steps))
    return dense


def _motion_states(a, b, resolution):
    """The states of the straight motion from a to b, ``resolution`` apart (a first, b
    last), and the order to check them in: b, then from the ends inwards by halving, as
    OMPL's discrete motion validator does (a, the motion's start, is not checked)."""
    steps = max(1, int(math.ceil(np.linalg.norm(b - a) / resolution)))
    states = a + np.outer(np.arange(steps + 1) / steps, b - a)
    order = [steps]
    pending = [(0, steps)]
    while pending:
        low, high = pending.pop(0)
        if high - low < 2:
            continue
        middle = (low + high) // 2
        order.append(middle)
        pending += [(low, middle), (middle, high)]
    return states, order

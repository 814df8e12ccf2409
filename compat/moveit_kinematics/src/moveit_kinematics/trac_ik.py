"""``trac_ik_kinematics_plugin/TRAC_IKKinematicsPlugin`` under its name, on this package's KDL
solver (TRAC-IK is not packaged by Debian).

TRAC-IK's parameters, read as its MoveIt plugin reads them (lookupParam in the plugin's
initialize; traclabs/trac_ik, trac_ik_kinematics_plugin/src/trac_ik_kinematics_plugin.cpp):
``solve_type`` (default ``Speed``), ``epsilon`` (default 1e-5) and ``position_only_ik``. The
solve types, as TRAC_IK::runSolver and CartToJnt define them (trac_ik_lib/src/trac_ik.cpp):

- ``Speed``: the first solution found (from the seed, then from random seeds) is the answer.
- ``Distance``: the search runs for the whole timeout, collecting every distinct solution
  (two are the same when each joint differs by less than :data:`SAME_SOLUTION`, TRAC-IK's
  myEqual); each revolute joint is moved by whole turns to within half a turn of the seed,
  then into its bounds (normalize_seed); the answer is the one with the least sum of squared
  joint differences to the seed (JointErr).
- ``Manipulation1`` / ``Manipulation2``: the same search, each solution's revolute joints
  moved to within half a turn of the middle of their bounds (normalize_limits); the answer
  has the largest ``penalty * measure``: measure the product of the Jacobian's singular values
  (Manipulation1) or the smallest over the largest (Manipulation2), penalty
  ``max(0, 1 - exp(-prod_i (q_i - lower_i)(upper_i - q_i) / range_i^2))`` over bounded joints
  (manipPenalty, manipValue1, manipValue2).
- any other name: a warning, and ``Speed`` (the plugin's own fallback).
- a solution callback (collision-aware IK) is asked about the chosen solution; when it refuses
  it, the search starts again from a random seed while time is left (the plugin's loop).

Not honoured: TRAC-IK runs two solvers side by side, KDL's Newton-Raphson with joint limits
and an SQP on NLopt, and takes whichever answers; here only the KDL-style descent of
:class:`~moveit_kinematics.kdl_solver.KdlSolver` runs, so the Speed answer's time and the
number of solutions found within a timeout differ from TRAC-IK's. TRAC-IK checks ``epsilon``
on each component of the error twist; here it bounds the position error's norm and the
rotation error's norm. ``Manipulation3`` (a ROS 2 addition) is not a Noetic solve type.
"""
from __future__ import annotations

import logging
import math
import time
from dataclasses import dataclass
from typing import Callable, List, Mapping, Optional, Sequence

import numpy as np

from moveit_core.robot_model import RobotModel
from moveit_kinematics.kdl_solver import MAX_ITERATIONS, KdlSolver, SolverSettings, kdl_frame

# rospy shows the rosout.* loggers on the console and /rosout
LOG = logging.getLogger("rosout.moveit_kinematics")

TRAC_IK_PLUGIN = "trac_ik_kinematics_plugin/TRAC_IKKinematicsPlugin"
SPEED, DISTANCE = "Speed", "Distance"
MANIPULATION1, MANIPULATION2 = "Manipulation1", "Manipulation2"
SOLVE_TYPES = (SPEED, DISTANCE, MANIPULATION1, MANIPULATION2)
DEFAULT_SOLVE_TYPE = SPEED       # trac_ik_kinematics_plugin.cpp: lookupParam("solve_type", ..., "Speed")
DEFAULT_EPSILON = 1e-5           # trac_ik_kinematics_plugin.cpp: lookupParam("epsilon", ..., 1e-5)
SAME_SOLUTION = 1e-4             # rad: TRAC_IK::myEqual's tolerance (trac_ik.hpp)


@dataclass(frozen=True)
class TracIkSettings:
    """TRAC-IK's own entries of a group's ``robot_description_kinematics``."""

    solve_type: str = DEFAULT_SOLVE_TYPE
    epsilon: float = DEFAULT_EPSILON

    @staticmethod
    def from_parameters(values: Mapping) -> "TracIkSettings":
        return TracIkSettings(str(values.get("solve_type", DEFAULT_SOLVE_TYPE)),
                              float(values.get("epsilon", DEFAULT_EPSILON)))


def _turned_near(value: float, target: float) -> float:
    """``value`` moved by whole turns to within half a turn of ``target``."""
    return target + math.remainder(value - target, 2 * math.pi)


class TracIkSolver(KdlSolver):
    """TRAC-IK's solve types over the KDL descent (see the module's docstring)."""

    def __init__(self, model: RobotModel, group: str, settings: SolverSettings = SolverSettings(),
                 trac_ik: TracIkSettings = TracIkSettings(), seed: Optional[int] = None):
        super().__init__(model, group, settings, seed)
        self.solve_type = trac_ik.solve_type
        if self.solve_type not in SOLVE_TYPES:
            LOG.warning("group '%s': %s is not a valid solve_type; setting to default: %s",
                        group, self.solve_type, SPEED)
            self.solve_type = SPEED
        self.position_tolerance = self.orientation_tolerance = trac_ik.epsilon
        LOG.info("group '%s': TRAC-IK solve type %s, epsilon %g (on the KDL descent)", group,
                 self.solve_type, trac_ik.epsilon)

    def inverse(self, target: np.ndarray, seed: Sequence[float],
                timeout: Optional[float] = None,
                seed_iterations: int = MAX_ITERATIONS,
                accept: Optional[Callable[[List[float]], bool]] = None
                ) -> Optional[List[float]]:
        timeout = self.settings.kinematics_solver_timeout if not timeout else timeout
        if self.solve_type == SPEED:
            return super().inverse(target, seed, timeout, seed_iterations, accept)
        deadline = time.monotonic() + timeout
        start = [b.clamp(v) for b, v in zip(self.bounds, seed)]
        while time.monotonic() < deadline:
            best = self._best(target, seed, start, deadline, seed_iterations)
            if best is not None and (accept is None or accept(best)):
                return best
            start = self._random_seed(seed)
        return None

    def _best(self, target: np.ndarray, seed: Sequence[float], start: Sequence[float],
              deadline: float, seed_iterations: int) -> Optional[List[float]]:
        """One CartToJnt of TRAC-IK: every distinct solution until ``deadline``, the best by
        the solve type's measure."""
        goal = kdl_frame(target)
        found: List[np.ndarray] = []
        solution = self._attempt(goal, start, seed_iterations)
        while True:
            if solution is not None:
                normalized = self._normalized(solution, seed)
                if normalized is not None and not any(
                        np.all(np.abs(normalized - other) < SAME_SOLUTION) for other in found):
                    found.append(normalized)
            if time.monotonic() >= deadline:
                break
            solution = self._attempt(goal, self._random_seed(seed), give_up_stalled=True)
        if not found:
            return None
        if self.solve_type == DISTANCE:
            chosen = min(found, key=lambda q: self.joint_error(seed, q))
        else:
            chosen = max(found, key=self.manipulability)
        return chosen.tolist()

    def _normalized(self, solution: Sequence[float], seed: Sequence[float]
                    ) -> Optional[np.ndarray]:
        """normalize_seed (Distance) or normalize_limits (Manipulation): revolute joints near
        the seed or the middle of their bounds, then into the bounds; None when a joint cannot
        be put within its bounds."""
        values = []
        for value, bounds, turns, near in zip(solution, self.bounds, self.turns, seed):
            if turns:
                if self.solve_type != DISTANCE and bounds.bounded:
                    near = (bounds.lower + bounds.upper) / 2.0
                value = _turned_near(value, near)
                if bounds.bounded:
                    if value > bounds.upper:
                        value -= 2 * math.pi
                    elif value < bounds.lower:
                        value += 2 * math.pi
            if not bounds.contains(value):
                return None
            values.append(value)
        return np.array(values)

    def _random_seed(self, seed: Sequence[float]) -> List[float]:
        """TRAC-IK's restart: uniform within a bounded joint's limits, within a turn either
        side of the seed for a continuous one."""
        return [self._random.uniform(b.lower, b.upper) if b.bounded else
                self._random.uniform(s - 2 * math.pi, s + 2 * math.pi)
                for b, s in zip(self.bounds, seed)]

    @staticmethod
    def joint_error(seed: Sequence[float], solution: Sequence[float]) -> float:
        """TRAC_IK::JointErr: the sum of squared joint differences."""
        return float(np.sum((np.asarray(seed, dtype=float) - np.asarray(solution)) ** 2))

    def manipulability(self, solution: Sequence[float]) -> float:
        """penalty * measure of the solve type (manipPenalty, manipValue1 / manipValue2)."""
        singular = np.linalg.svd(self._jacobian_at(self._array(list(solution))),
                                 compute_uv=False)
        measure = float(np.prod(singular)) if self.solve_type == MANIPULATION1 else \
            float(singular.min() / singular.max())
        return self.limits_penalty(solution) * measure

    def limits_penalty(self, solution: Sequence[float]) -> float:
        """TRAC_IK::manipPenalty: near 0 close to a bound, near 1 in the middle of the
        bounds (continuous joints do not count)."""
        product = 1.0
        for value, bounds in zip(solution, self.bounds):
            if not bounds.bounded:
                continue
            span = bounds.upper - bounds.lower
            product *= (value - bounds.lower) * (bounds.upper - value) / (span * span)
        return max(0.0, 1.0 - math.exp(-product))

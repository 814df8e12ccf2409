"""Inverse and forward kinematics of a chain group on Orocos KDL (Debian's python3-pykdl),
the library behind MoveIt's default ``kdl_kinematics_plugin/KDLKinematicsPlugin``.

As that plugin does: the group must be a chain; the solver starts from the seed, then from
random states within the joint bounds, until a solution is found or the timeout passes.
Each attempt is the plugin's loop: KDL's forward kinematics and Jacobian of the chain, a
damped least-squares step on the weighted error (``position_only_ik`` weighs the
orientation by 0, as a 4-joint arm cannot take every orientation; ``orientation_vs_position``
weighs it otherwise), the joints clipped to their bounds after every step. (KDL's own
weighted solver, ChainIkSolverPos_LMA, takes its weights as an Eigen matrix, which Debian's
PyKDL crashes on beside NumPy 2.) Configs naming MoveIt's other built-in solvers (LMA, the
cached and service plugins: SOLVER_NAMES) get this solver; which solver a group gets is
:mod:`moveit_kinematics.solvers`' choice (C++ plugins through pluginlib, TRAC-IK on
:mod:`moveit_kinematics.trac_ik`).

The URDF is turned into a KDL chain as kdl_parser turns it (a segment per joint: the joint
at its origin, its axis in the parent's frame). No ROS here.
"""
from __future__ import annotations

import math
import random
import time
from dataclasses import dataclass
from typing import Callable, Dict, List, Mapping, Optional, Sequence

import numpy as np
import PyKDL as kdl

from moveit_core.robot_model import RobotModel, RobotModelError
from urdf_tools import Joint
from urdf_tools.kinematics import rpy_matrix

# the plugins a kinematics.yaml names that this solver answers for
KDL_PLUGIN = "kdl_kinematics_plugin/KDLKinematicsPlugin"
SOLVER_NAMES = (KDL_PLUGIN, "lma_kinematics_plugin/LMAKinematicsPlugin",
                "cached_ik_kinematics_plugin/CachedKDLKinematicsPlugin",
                "srv_kinematics_plugin/SrvKinematicsPlugin")
MAX_ITERATIONS = 30       # steps of one attempt before a restart from a random state
SEED_ITERATIONS = 150     # steps from the seed for a step along a path (near a singularity
                          # the descent is slow; a random restart would change branch)
POSITION_TOLERANCE = 1e-5  # m: an attempt has converged when the tip is this close
ORIENTATION_TOLERANCE = 1e-4   # rad, when orientation counts
DAMPING = 1e-6             # damped least squares: keeps steps finite near singularities
MAX_STEP = 0.5             # rad (or m): the largest change of a joint in one step
# an attempt from a random state is given up (and another random state tried) when its
# weighted error has not shrunk to STALL_SHRINK of what it was STALL_STEPS steps before:
# most failing attempts are stuck against a joint limit, and a converging one shrinks its
# error far faster (on the px100's random reachable poses: mean time per solution 17.6 ms
# to 4.0, 95th percentile 101 to 27 ms)
STALL_STEPS = 3
STALL_SHRINK = 0.9
# an attempt this close (weighted error) is near a solution, where a singularity (a wrist's
# two axes aligned) slows the descent to a crawl: it is not given up as stalled, and runs
# up to SEED_ITERATIONS steps (a UR-type arm's random reachable pose with wrist_2 at 3e-4
# rad was otherwise given up from every random start)
NEAR = 1e-3


@dataclass(frozen=True)
class SolverSettings:
    """A group's entry of ``robot_description_kinematics`` (MoveIt's names and defaults)."""

    kinematics_solver: str = KDL_PLUGIN
    kinematics_solver_search_resolution: float = 0.005
    kinematics_solver_timeout: float = 0.005
    position_only_ik: bool = False
    orientation_vs_position: float = 1.0

    @staticmethod
    def from_parameters(values: Mapping) -> "SolverSettings":
        known = SolverSettings.__dataclass_fields__
        settings = SolverSettings(**{k: values[k] for k in known if k in values})
        return settings


def kdl_frame(matrix: np.ndarray) -> kdl.Frame:
    rotation = kdl.Rotation(*[float(v) for v in np.asarray(matrix)[:3, :3].reshape(-1)])
    return kdl.Frame(rotation, kdl.Vector(*[float(v) for v in np.asarray(matrix)[:3, 3]]))


def frame_matrix(frame: kdl.Frame) -> np.ndarray:
    matrix = np.eye(4)
    for i in range(3):
        for j in range(3):
            matrix[i, j] = frame.M[i, j]
        matrix[i, 3] = frame.p[i]
    return matrix


def _segment(joint: Joint) -> kdl.Segment:
    """kdl_parser's conversion of one URDF joint and its child link."""
    origin = np.eye(4)
    origin[:3, :3] = rpy_matrix(*joint.origin.rpy)
    origin[:3, 3] = joint.origin.xyz
    frame = kdl_frame(origin)
    axis = frame.M * kdl.Vector(*joint.axis)
    if joint.type in ("revolute", "continuous"):
        kdl_joint = kdl.Joint(joint.name, frame.p, axis, kdl.Joint.RotAxis)
    elif joint.type == "prismatic":
        kdl_joint = kdl.Joint(joint.name, frame.p, axis, kdl.Joint.TransAxis)
    else:
        kdl_joint = kdl.Joint(joint.name, kdl.Joint.Fixed)
    return kdl.Segment(joint.child, kdl_joint, frame)


class KdlSolver:
    """IK and FK of one chain group of ``model``."""

    def __init__(self, model: RobotModel, group: str, settings: SolverSettings = SolverSettings(),
                 seed: Optional[int] = None):
        self.model, self.settings = model, settings
        self.group = model.group(group)
        if not self.group.is_chain:
            raise RobotModelError(f"group '{group}' is not a chain: the KDL solver needs one "
                                  f"(its joints: {', '.join(self.group.joints)})")
        self.base, self.tip = self.group.base_link, self.group.tip_link
        self.chain = kdl.Chain()
        self.joints: List[str] = []
        for joint in model.urdf.chain(self.base, self.tip):
            self.chain.addSegment(_segment(joint))
            if joint.type != "fixed":
                if joint.name not in self.group.variables:
                    raise RobotModelError(f"group '{group}': joint '{joint.name}' on the "
                                          "chain is a mimic or passive joint, which this "
                                          "solver cannot move")
                self.joints.append(joint.name)
        self.bounds = [model.bounds[j] for j in self.joints]
        # whole turns move a revolute joint's solution into its bounds, not a prismatic one's
        self.turns = [model.urdf.joints[j].type != "prismatic" for j in self.joints]
        self.weight = 0.0 if settings.position_only_ik else settings.orientation_vs_position
        self.lower = np.array([b.lower if b.bounded else -np.inf for b in self.bounds])
        self.upper = np.array([b.upper if b.bounded else np.inf for b in self.bounds])
        self._jacobian_solver = kdl.ChainJntToJacSolver(self.chain)
        self._jacobian = kdl.Jacobian(len(self.joints))
        self._fk = kdl.ChainFkSolverPos_recursive(self.chain)
        self._random = random.Random(seed)
        # when an attempt has converged (TRAC-IK's solver sets its epsilon here)
        self.position_tolerance, self.orientation_tolerance = \
            POSITION_TOLERANCE, ORIENTATION_TOLERANCE

    def forward(self, positions: Sequence[float]) -> np.ndarray:
        """The tip's pose in the base link's frame (4x4) for the chain's joints."""
        frame = kdl.Frame()
        self._fk.JntToCart(self._array(positions), frame)
        return frame_matrix(frame)

    def inverse(self, target: np.ndarray, seed: Sequence[float],
                timeout: Optional[float] = None,
                seed_iterations: int = MAX_ITERATIONS,
                accept: Optional[Callable[[List[float]], bool]] = None
                ) -> Optional[List[float]]:
        """Joint positions (the chain's joints, in order) putting the tip at ``target``
        (4x4, in the base link's frame; its rotation ignored with position_only_ik); None
        when no solution was found within ``timeout`` s (the settings' when None).
        ``seed_iterations``: the descent from the seed (a caller stepping along a path gives
        it SEED_ITERATIONS, to stay on the seed's branch near a singularity). ``accept``:
        MoveIt's solution callback (collision-aware IK): a solution it refuses counts as
        none, and the search goes on from random seeds."""
        timeout = self.settings.kinematics_solver_timeout if not timeout else timeout
        deadline = time.monotonic() + timeout
        goal = kdl_frame(target)
        start = [b.clamp(v) for b, v in zip(self.bounds, seed)]
        solution = self._attempt(goal, start, seed_iterations)
        while solution is None or (accept is not None and not accept(solution)):
            if time.monotonic() >= deadline:
                return None
            start = [self._random.uniform(*self._range(b)) for b in self.bounds]
            solution = self._attempt(goal, start, give_up_stalled=True)
        return solution

    def _attempt(self, goal: kdl.Frame, start: Sequence[float],
                 iterations: int = MAX_ITERATIONS, give_up_stalled: bool = False
                 ) -> Optional[List[float]]:
        """One descent from ``start``: the joints when the tip converged on ``goal``
        (``give_up_stalled``: None as soon as the error stops shrinking, see STALL_STEPS)."""
        q = np.array(start, dtype=float)
        frame = kdl.Frame()
        weights = np.array([1.0, 1.0, 1.0, self.weight, self.weight, self.weight])
        errors: List[float] = []
        damping = DAMPING * np.eye(6)
        array = kdl.JntArray(len(self.joints))
        step_count, budget = 0, iterations
        while step_count < budget:
            step_count += 1
            self._array(q.tolist(), array)
            self._fk.JntToCart(array, frame)
            twist = kdl.diff(frame, goal)          # in the base frame: (velocity, rotation)
            values = [twist[i] for i in range(6)]
            if math.hypot(*values[:3]) < self.position_tolerance and (
                    self.weight == 0.0 or
                    math.hypot(*values[3:]) < self.orientation_tolerance):
                positions = [_into_bounds(b, v, turns)
                             for b, v, turns in zip(self.bounds, q, self.turns)]
                return None if any(v is None for v in positions) else positions
            weighted = np.array(values) * weights
            errors.append(float(np.linalg.norm(weighted)))
            if errors[-1] < NEAR:
                budget = max(budget, SEED_ITERATIONS)
            elif give_up_stalled and len(errors) > STALL_STEPS and \
                    errors[-1] > STALL_SHRINK * errors[-1 - STALL_STEPS]:
                return None
            jacobian = self._jacobian_at(array) * weights[:, None]
            step = jacobian.T @ np.linalg.solve(jacobian @ jacobian.T + damping, weighted)
            # a joint at a bound that the step pushes further out stays there: the step is
            # solved again by the other joints (else the clip below throws its share away and
            # a solution near the bounds is approached ever more slowly, or not at all)
            blocked = ((q <= self.lower) & (step < 0)) | ((q >= self.upper) & (step > 0))
            if np.any(blocked) and not np.all(blocked):
                free = jacobian * ~blocked[None, :]
                step = free.T @ np.linalg.solve(free @ free.T + damping, weighted)
            largest = np.max(np.abs(step))
            if largest > MAX_STEP:
                step *= MAX_STEP / largest
            q = np.clip(q + step, self.lower, self.upper)
        return None

    def _jacobian_at(self, array: kdl.JntArray) -> np.ndarray:
        """The chain's 6 x n Jacobian at ``array`` (KDL's, in the base frame)."""
        self._jacobian_solver.JntToJac(array, self._jacobian)
        return np.array([[self._jacobian[r, c] for c in range(len(self.joints))]
                         for r in range(6)])

    @staticmethod
    def _range(bounds) -> tuple:
        return (bounds.lower, bounds.upper) if bounds.bounded else (-math.pi, math.pi)

    def _array(self, values: Sequence[float], into: Optional[kdl.JntArray] = None
               ) -> kdl.JntArray:
        """``values`` as a JntArray (``into``, when given: reused in a loop)."""
        array = into if into is not None else kdl.JntArray(len(self.joints))
        for i, value in enumerate(values):
            array[i] = float(value)
        return array

    def state(self, positions: Sequence[float]) -> Dict[str, float]:
        return dict(zip(self.joints, positions))


def _into_bounds(bounds, value: float, turns: bool) -> Optional[float]:
    """``value`` moved by whole turns (``turns``: a revolute joint) into the bounds; None
    when no turn of it is within them (a continuous joint: wrapped to [-pi, pi])."""
    if not math.isfinite(value):
        return None
    if bounds.contains(value):
        return math.remainder(value, 2 * math.pi) if not bounds.bounded else value
    if not turns:
        return None
    turned = value - 2 * math.pi * math.floor((value - bounds.lower) / (2 * math.pi))
    return turned if bounds.contains(turned) else None

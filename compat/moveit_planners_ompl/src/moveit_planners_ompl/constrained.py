"""Planning under path constraints, as MoveIt's OMPL interface does it (noetic-devel,
moveit_planners/ompl/ompl_interface): in joint space, every state the planner keeps or
checks along a motion must satisfy the path constraints besides being collision-free
(detail/state_validity_checker.cpp: ``path_constraints->decide(state)`` in isValid), and
the states the planner grows towards are drawn by a constraint sampler instead of
uniformly (model_based_planning_context.cpp:206-253, allocPathConstrainedSampler;
detail/constrained_sampler.cpp: three tries of the constraint sampler, then a uniform
state; moveit_core/constraint_samplers/src/default_constraint_samplers.cpp):

- joint constraints alone: JointConstraintSampler, each constrained joint uniform in its
  tolerance band within its bounds, the others uniform within theirs;
- position and/or orientation constraints on one link: IKConstraintSampler, a pose drawn
  inside the region (a uniform point of one of its shapes) with the target orientation
  turned by uniform angles within the tolerances (XYZ Euler or rotation vector, as the
  constraint's parameterization: samplePose, l. 424-540), or an orientation alone at the
  link position of a random state; IK from a random seed; kept when the whole set holds
  (joint constraints included) and the state is within bounds. MoveIt's planning context
  gives each try ``max_state_sampling_attempts`` (4) poses.

PyPI's OMPL binding cannot install a state sampler allocator in a state space (no
``setStateSamplerAllocator``), so the tree search with such a sampler is the algorithm of
OMPL's RRTConnect (ompl/geometric/planners/rrt/src/RRTConnect.cpp: two trees, growth by at
most ``range`` towards a sample, the other tree connecting greedily) written here, over the
same validity checks; its path is shortened by OMPL's reduceVertices shortcutting (random
pairs joined by a valid straight motion). This is used for every request with path
constraints, whichever planner_id the request names.
"""
from __future__ import annotations

import time
from typing import Callable, List, Optional, Sequence

import numpy as np
from tf.transformations import euler_matrix, quaternion_matrix, random_quaternion, rotation_matrix

from moveit_core.kinematic_constraints import ConstraintSet
from moveit_msgs.msg import OrientationConstraint as OrientationMsg

from moveit_planners_ompl.goals import fixed_offset

# model_based_planning_context.h / planning_context_manager.cpp (noetic-devel):
# max_state_sampling_attempts defaults to 4 poses per try of the constraint sampler
MAX_STATE_SAMPLING_ATTEMPTS = 4
# constrained_sampler.cpp sampleUniform: three tries of the constraint sampler, then uniform
CONSTRAINED_TRIES = 3
# OMPL's SelfConfig::configurePlannerRange: range 0 means this fraction of the space's extent
# (ompl/tools/config/MagicConstants.h, MAX_MOTION_LENGTH_AS_SPACE_EXTENT_FRACTION)
RANGE_EXTENT_FRACTION = 0.2
# rejection sampling of a point inside a sphere, cylinder or mesh (bodies::samplePointInside
# takes max_attempts tries, the sampler's)
REGION_TRIES = 100
# PathSimplifier::reduceVertices: stop after this many failed shortcuts in a row (its
# default maxEmptySteps is 0, meaning the path's vertex count; we bound it the same way)
SHORTCUT_EMPTY_STEPS_MIN = 10

ADVANCED, REACHED, TRAPPED = range(3)


class ConstrainedSampler:
    """States of the group that satisfy ``constraints`` (as well as they can be drawn),
    else uniform states within ``lows``/``highs``."""

    def __init__(self, constraints: ConstraintSet, model, joints: Sequence[str],
                 start: dict, lows: np.ndarray, highs: np.ndarray, solver,
                 rng: np.random.Generator):
        self.constraints, self.model, self.joints = constraints, model, list(joints)
        self.start, self.lows, self.highs, self.solver, self.rng = \
            start, lows, highs, solver, rng
        self.bands = {}
        for name, target, below, above, _continuous in constraints.joints:
            if name in self.joints:
                index = self.joints.index(name)
                self.bands[index] = (max(lows[index], target - below),
                                     min(highs[index], target + above))
        links = {c[0] for c in constraints.positions} | {c[0] for c in constraints.orientations}
        self.link = links.pop() if len(links) == 1 and solver is not None else None
        self.position = next((c for c in constraints.positions if c[0] == self.link), None)
        self.orientation = next((c for c in constraints.orientations if c[0] == self.link), None)
        self.offset = None
        if self.link is not None:
            self.offset = fixed_offset(model, solver.tip, self.link)
            if self.offset is None:   # the link does not move with the solver's tip
                self.link = None
        self.constrained = 0
        self.uniform = 0

    def uniform_state(self) -> np.ndarray:
        return self.rng.uniform(self.lows, self.highs)

    def sample(self) -> np.ndarray:
        for _ in range(CONSTRAINED_TRIES):
            state = self._constrained()
            if state is not None:
                self.constrained += 1
                return state
        self.uniform += 1
        return self.uniform_state()

    def _constrained(self) -> Optional[np.ndarray]:
        if self.link is None:
            if not self.bands:
                return None
            state = self.uniform_state()
            for index, (low, high) in self.bands.items():
                state[index] = self.rng.uniform(low, high) if high > low else low
            return state if self._holds(state) else None
        for _ in range(MAX_STATE_SAMPLING_ATTEMPTS):
            pose = self._pose()
            if pose is None:
                continue
            poses = self.model.link_poses(self.start)
            base = poses[self.solver.base]
            seed = [self.rng.uniform(low, high) for low, high in
                    (self._range(j) for j in self.solver.joints)]
            solution = self.solver.inverse(np.linalg.inv(base) @ pose @ np.linalg.inv(self.offset),
                                           seed)
            if solution is None:
                continue
            values = dict(self.start, **self.solver.state(solution))
            state = np.array([values[j] for j in self.joints])
            if np.all(state >= self.lows) and np.all(state <= self.highs) and self._holds(state):
                return state
        return None

    def _range(self, joint):
        index = self.joints.index(joint)
        return self.lows[index], self.highs[index]

    def _holds(self, state: np.ndarray) -> bool:
        return self.constraints.decide(dict(self.start, **dict(zip(self.joints, state)))) is None

    def _pose(self) -> Optional[np.ndarray]:
        """A pose for the constrained link (samplePose, default_constraint_samplers.cpp:424-540)."""
        poses = None
        target = np.eye(4)
        if self.position is not None:
            _link, frame, offset, regions = self.position
            first = int(self.rng.integers(len(regions)))
            point = None
            for k in range(len(regions)):
                region = regions[(first + k) % len(regions)]
                local = region.sample(self.rng, REGION_TRIES)
                if local is not None:
                    poses = self.model.link_poses(self.start)
                    point = (self.constraints.frame(frame, poses) @ region.pose @
                             np.append(local, 1.0))[:3]
                    break
            if point is None:
                return None
            target[:3, 3] = point
        else:
            random_state = dict(self.start, **dict(zip(self.joints, self.uniform_state())))
            target[:3, 3] = self.model.link_poses(random_state)[self.link][:3, 3]
        if self.orientation is not None:
            _link, frame, rotation, tolerances, parameterization = self.orientation
            # uniform in (-tolerance, tolerance), one epsilon inside (l. 478-486)
            angles = 2.0 * (self.rng.random(3) - 0.5) * (tolerances - np.finfo(float).eps)
            if parameterization == OrientationMsg.ROTATION_VECTOR:
                norm = float(np.linalg.norm(angles))
                turn = rotation_matrix(norm, angles / norm)[:3, :3] if norm > 0 else np.eye(3)
            else:   # Rx * Ry * Rz: intrinsic XYZ (l. 492-494)
                turn = euler_matrix(angles[0], angles[1], angles[2], "rxyz")[:3, :3]
            poses = poses if poses is not None else self.model.link_poses(self.start)
            target[:3, :3] = self.constraints.frame(frame, poses)[:3, :3] @ rotation @ turn
        else:
            target[:3, :3] = quaternion_matrix(random_quaternion(self.rng.random(3)))[:3, :3]
        if self.position is not None:
            # the region holds the offset point: the link's origin sits behind it (l. 534-537)
            target[:3, 3] -= target[:3, :3] @ self.position[2][:3]
        return target




class Tree:
    """One of RRTConnect's trees: states and each one's parent index."""

    def __init__(self, roots: Sequence[np.ndarray]):
        self.states = np.array(roots, dtype=float)
        self.parents = [-1] * len(roots)

    def add(self, state: np.ndarray, parent: int) -> int:
        self.states = np.vstack([self.states, state])
        self.parents.append(parent)
        return len(self.parents) - 1

    def nearest(self, state: np.ndarray) -> int:
        return int(np.argmin(np.linalg.norm(self.states - state, axis=1)))

    def branch(self, index: int) -> List[np.ndarray]:
        """The states from ``index`` back to its root."""
        found = []
        while index >= 0:
            found.append(self.states[index])
            index = self.parents[index]
        return found


def rrt_connect(start: np.ndarray, goals: Sequence[np.ndarray], sample: Callable[[], np.ndarray],
                motion_valid: Callable[[np.ndarray, np.ndarray], bool], step: float,
                deadline: float) -> Optional[List[np.ndarray]]:
    """A path from ``start`` to one of ``goals`` (all valid states) whose motions
    ``motion_valid`` accepts, growing by at most ``step``; None when ``deadline`` passes."""
    trees = [Tree([start]), Tree(goals)]
    grow_start = True

    def grow(tree: Tree, toward: np.ndarray, backwards: bool):
        near = tree.nearest(toward)
        origin = tree.states[near]
        distance = float(np.linalg.norm(toward - origin))
        reach = distance <= step
        target = toward if reach else origin + (toward - origin) * (step / distance)
        # the goal tree's motions run towards its roots (RRTConnect checks them that way)
        valid = motion_valid(target, origin) if backwards else motion_valid(origin, target)
        if not valid:
            return TRAPPED, -1
        return (REACHED if reach else ADVANCED), tree.add(target, near)

    while time.monotonic() < deadline:
        tree, other = (trees[0], trees[1]) if grow_start else (trees[1], trees[0])
        sampled = sample()
        state, added = grow(tree, sampled, not grow_start)
        if state != TRAPPED:
            toward = tree.states[added]
            connect = ADVANCED
            while connect == ADVANCED and time.monotonic() < deadline:
                connect, reached = grow(other, toward, grow_start)
            if connect == REACHED:
                start_tree_index, goal_tree_index = (added, reached) if grow_start else \
                    (reached, added)
                first = trees[0].branch(start_tree_index)[::-1]
                second = trees[1].branch(goal_tree_index)
                return first + second[1:]
        grow_start = not grow_start
    return None


def shortcut(path: List[np.ndarray], motion_valid, rng: np.random.Generator,
             deadline: float) -> List[np.ndarray]:
    """Vertices dropped where a straight valid motion joins two non-adjacent ones
    (PathSimplifier::reduceVertices)."""
    path = list(path)
    empty_steps = max(SHORTCUT_EMPTY_STEPS_MIN, len(path))
    failures = 0
    while len(path) > 2 and failures < empty_steps and time.monotonic() < deadline:
        i = int(rng.integers(len(path)))
        j = int(rng.integers(len(path)))
        i, j = min(i, j), max(i, j)
        if j - i < 2:
            failures += 1
            continue
        if motion_valid(path[i], path[j]):
            path = path[:i + 1] + path[j:]
            failures = 0
        else:
            failures += 1
    return path


def planner_range(parameters, lows: np.ndarray, highs: np.ndarray) -> float:
    """The configured ``range``, or OMPL's default: a fifth of the space's extent."""
    try:
        value = float(parameters.get("range", 0.0))
    except (TypeError, ValueError):
        value = 0.0
    return value if value > 0 else RANGE_EXTENT_FRACTION * float(np.linalg.norm(highs - lows))

"""Planning for the arm: a position target to a timed joint trajectory, or a MoveIt error
code saying why not.

In order: the target must be finite and above the floor (else INVALID_GOAL_CONSTRAINTS);
the start must be within limits and not touch anything (INVALID_ROBOT_STATE,
START_STATE_IN_COLLISION); inverse kinematics over a fan of gripper pitches, the preferred
one first, must give solutions within limits (NO_IK_SOLUTION) of which some are free with
``goal_margin`` to spare, so that the next start is clear (GOAL_IN_COLLISION);
RRTConnect (OMPL) searches joint space from the start to any of the best free solutions
within the time allowed (TIMED_OUT, PLANNING_FAILED) unless a straight line is free; every
motion is checked densely (all states no more than ``resolution`` apart in every joint,
in batches); the path is shortened greedily; then each straight segment gets a trapezoidal speed profile within the joint
speed and acceleration limits. The random numbers are OMPL's, seeded per plan from
``seed``: the same request from the same state gives the same path.
"""
from __future__ import annotations

import math
import time
from collections import Counter
from dataclasses import dataclass, field
from typing import List, Mapping, Optional, Sequence

import numpy as np
from ompl import base as ob
from ompl import geometric as og
from ompl import util as ou

from arm_move.collision import ArmCollisionModel, Scene
from arm_move.kinematics import ArmKinematics
from arm_move.msg import MoveItErrorCodes as Codes
from node_params import Check, between, non_negative, parameter, positive, read

ou.setLogLevel(ou.LOG_WARN)


# OMPL's random seed: OMPL takes unsigned numbers; 0 asks it for a seed of its own (the
# paths would no longer repeat), and 32 bits are what every platform's OMPL keeps.
MAX_SEED = 2 ** 32 - 1


@dataclass(frozen=True)
class PlannerSettings:
    """From config/mover.yaml (units in its comments), read with node_params."""

    planning_time: float = parameter(1.0, positive,
                                     expected="seconds > 0 the search may take")
    resolution_degrees: float = parameter(
        1.0, positive, expected="degrees > 0 between the states a motion is checked at")
    pitch_step_degrees: float = parameter(
        5.0, positive, expected="degrees > 0 between the gripper pitches IK tries")
    preferred_pitch_degrees: float = parameter(
        90.0, between(-180.0, 180.0),
        expected="the gripper pitch IK tries first, degrees in [-180, 180] (90: down)")
    goal_count: int = parameter(6, positive,
                                expected="a whole number > 0 of IK solutions to aim at")
    velocity_scaling: float = parameter(
        0.5, Check(lambda value: 0 < value <= 1, "is not in (0, 1]"),
        expected="a fraction in (0, 1] of the joints' speed limit")
    acceleration: float = parameter(6.0, positive, expected="rad/s^2 > 0, every arm joint")
    sample_period: float = parameter(0.05, positive,
                                     expected="seconds > 0 between trajectory points")
    seed: int = parameter(1, between(1, MAX_SEED),
                          expected=f"OMPL's seed, a whole number from 1 to {MAX_SEED}")
    goal_margin: float = parameter(
        0.003, non_negative, expected="metres >= 0 goals keep beyond the padding")


@dataclass(frozen=True)
class CollisionSettings:
    """The collision model's settings, from config/mover.yaml too."""

    collision_padding: float = parameter(
        0.005, non_negative, expected="metres >= 0 the arm keeps from everything")
    attached_contact_tolerance: float = parameter(
        0.001, non_negative, expected="metres >= 0 a held object may sink into its support")


@dataclass
class Plan:
    """What planning gave: a MoveIt code and message; on success the path (joint vertices)
    and the timed trajectory (times, positions, velocities)."""

    code: int
    message: str
    path: List[np.ndarray] = field(default_factory=list)
    times: List[float] = field(default_factory=list)
    positions: List[np.ndarray] = field(default_factory=list)
    velocities: List[np.ndarray] = field(default_factory=list)
    planning_seconds: float = 0.0

    @property
    def ok(self) -> bool:
        return self.code == Codes.SUCCESS


class _BatchMotionValidator(ob.MotionValidator):
    """OMPL asks whether a straight motion is free; this checks all its states at once."""

    def __init__(self, information, planner: "ArmPlanner", finger: float, scene: Scene):
        super().__init__(information)
        self._planner, self._finger, self._scene = planner, finger, scene

    def checkMotion(self, first, second, *_):
        a = np.array([first[i] for i in range(4)])
        b = np.array([second[i] for i in range(4)])
        return self._planner.motion_free(a, b, self._finger, self._scene)


class ArmPlanner:
    def __init__(self, kinematics: ArmKinematics, model: ArmCollisionModel,
                 settings: PlannerSettings = PlannerSettings()):
        self.k = kinematics
        self.model = model
        self.settings = settings
        self.resolution = math.radians(settings.resolution_degrees)
        self._plans = 0

    # --- checks ------------------------------------------------------------------------
    def interpolate(self, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        """States from a to b (both included), no joint moving more than the resolution
        between two."""
        count = max(1, int(math.ceil(np.max(np.abs(b - a)) / self.resolution)))
        return a + np.linspace(0.0, 1.0, count + 1)[:, None] * (b - a)

    def motion_free(self, a: np.ndarray, b: np.ndarray, finger: float, scene: Scene) -> bool:
        return bool(np.all(self.model.valid(self.interpolate(a, b), finger, scene)))

    def path_free(self, path: Sequence[np.ndarray], finger: float, scene: Scene) -> bool:
        return all(self.motion_free(a, b, finger, scene) for a, b in zip(path, path[1:]))

    def pitches(self) -> List[float]:
        """The gripper pitches IK tries, the preferred first, then alternately either side."""
        step = math.radians(self.settings.pitch_step_degrees)
        preferred = math.radians(self.settings.preferred_pitch_degrees)
        fan = [preferred]
        for i in range(1, int(math.ceil(math.pi / step)) + 1):
            fan += [preferred + i * step, preferred - i * step]
        return [p for p in fan if -math.pi <= p - preferred <= math.pi]

    # --- planning ----------------------------------------------------------------------
    def plan_to_position(self, start: Sequence[float], finger: float,
                         target: Sequence[float], scene: Scene) -> Plan:
        began = time.perf_counter()
        plan = self._plan_to_position(np.asarray(start, float), finger, target, scene)
        plan.planning_seconds = time.perf_counter() - began
        return plan

    def plan_to_joints(self, start: Sequence[float], finger: float, goal: Sequence[float],
                       scene: Scene) -> Plan:
        began = time.perf_counter()
        start, goal = np.asarray(start, float), np.asarray(goal, float)
        plan = self._check_start(start, finger, scene)
        if plan is None:
            if not np.all(np.isfinite(goal)) or not self.k.within_limits(goal):
                plan = Plan(Codes.INVALID_GOAL_CONSTRAINTS, f"goal {goal.round(3).tolist()} is "
                            "outside the joint limits")
            else:
                hit = self.model.collision(goal, finger, scene, self.settings.goal_margin)
                plan = Plan(Codes.GOAL_IN_COLLISION, f"the goal touches {hit}") if hit \
                    else self._search(start, [goal], finger, scene)
        plan.planning_seconds = time.perf_counter() - began
        return plan

    def _check_start(self, start: np.ndarray, finger: float, scene: Scene) -> Optional[Plan]:
        if not np.all(np.isfinite(start)) or not self.k.within_limits(start, slack=0.02):
            return Plan(Codes.INVALID_ROBOT_STATE, f"the arm's state {start.round(3).tolist()} "
                        "is outside its joint limits")
        # the arm where it really is: true shapes (no padding), since a controller that holds
        # a goal may sag into the padding a little
        hit = self.model.collision(start, finger, scene, -self.model.padding)
        if hit:
            return Plan(Codes.START_STATE_IN_COLLISION, f"the arm already touches {hit}")
        return None

    def _plan_to_position(self, start, finger, target, scene) -> Plan:
        target = np.asarray(target, dtype=float)
        if target.shape != (3,) or not np.all(np.isfinite(target)):
            return Plan(Codes.INVALID_GOAL_CONSTRAINTS, f"target {target.tolist()} is not a "
                        "finite position")
        if target[2] < scene.floor_z:
            return Plan(Codes.INVALID_GOAL_CONSTRAINTS, f"target z {target[2]:.3f} m is below "
                        f"the floor (z {scene.floor_z:.3f} m)")
        inside = scene.containing(target)
        if inside:
            return Plan(Codes.GOAL_IN_COLLISION, f"target {target.round(3).tolist()} is inside "
                        f"{inside}")
        plan = self._check_start(start, finger, scene)
        if plan is not None:
            return plan
        goals = self.ranked_goals(start, finger, target, scene)
        if isinstance(goals, Plan):
            return goals
        plan = self._search(start, goals, finger, scene)
        if plan.ok:
            plan.message = f"planned: {self.describe_goal(plan.path[-1], target)}"
        return plan

    # --- choosing among IK solutions -----------------------------------------------------
    @property
    def travel_weights(self) -> np.ndarray:
        """Per arm joint, how far one radian of it moves the gripper point at Home (m/rad):
        a joint's travel weighs as much as the motion it causes at the gripper."""
        home = self.k.named_poses["home"]
        shoulder, elbow, wrist, grip, _ = self.k.planar_points(home)
        return np.array([abs(grip[0]), np.linalg.norm(grip - shoulder),
                         np.linalg.norm(grip - elbow), np.linalg.norm(grip - wrist)])

    def travel(self, start: np.ndarray, goals: np.ndarray) -> np.ndarray:
        """Weighted joint travel (m) from the start to each goal (no joint wraps: the waist
        stops at +-180 degrees)."""
        return np.abs(np.atleast_2d(goals) - start) @ self.travel_weights

    @staticmethod
    def faces(waist: np.ndarray, target: Sequence[float]) -> np.ndarray:
        """Whether waist angles face the target: within 90 degrees of its bearing (every
        angle faces a target straight above the waist)."""
        if math.hypot(target[0], target[1]) < 1e-9:
            return np.ones(np.shape(waist), bool)
        bearing = math.atan2(target[1], target[0])
        off = np.arctan2(np.sin(waist - bearing), np.cos(waist - bearing))
        return np.abs(off) <= math.pi / 2

    def ranked_goals(self, start: np.ndarray, finger: float, target: np.ndarray, scene: Scene):
        """The free IK solutions the search may end at, best first, or a Plan saying why
        there are none. Best: a waist facing the target whenever such a solution is free
        (reaching back over the base is for targets that cannot be reached otherwise),
        then the preferred gripper pitch (straight down grasps and sets objects down
        squarely), then the least weighted joint travel from the start."""
        candidates, ranks = [], []
        for rank, pitch in enumerate(self.pitches()):
            for q in self.k.ik(target, pitch):
                candidates.append(q)
                ranks.append(rank)
        if not candidates:
            return Plan(Codes.NO_IK_SOLUTION, f"no joint solution within the limits puts the "
                        f"gripper at {target.round(3).tolist()} (out of reach)")
        goals, ranks = np.array(candidates), np.array(ranks)
        free = self.model.valid(goals, finger, scene, self.settings.goal_margin)
        if not free.any():
            hits = Counter(self.model.collision(q, finger, scene, self.settings.goal_margin)
                           for q in goals[:12])
            what = ", ".join(f"{name}" for name, _ in hits.most_common())
            return Plan(Codes.GOAL_IN_COLLISION, f"every joint solution for "
                        f"{target.round(3).tolist()} touches something ({what})")
        facing = self.faces(goals[:, 0], target)
        keep = free & facing if np.any(free & facing) else free
        goals, ranks = goals[keep], ranks[keep]
        order = np.lexsort((self.travel(start, goals), ranks))
        return [goals[i] for i in order[:self.settings.goal_count]]

    def describe_goal(self, q: np.ndarray, target: Sequence[float]) -> str:
        """The chosen solution in words: waist (facing the target or reaching back), the
        gripper's pitch, the joints."""
        facing = bool(self.faces(np.array([q[0]]), target)[0])
        pitch = math.degrees(q[1] + q[2] + q[3])
        return (f"waist {q[0]:.2f} rad ({'faces the target' if facing else 'reaches back over the base'}), "
                f"gripper pitch {pitch:.0f} deg, joints {np.round(q, 3).tolist()}")

    def _search(self, start: np.ndarray, goals: List[np.ndarray], finger: float,
                scene: Scene) -> Plan:
        settings = self.settings
        for goal in goals:  # the straight line first: most requests need nothing else
            if self.motion_free(start, goal, finger, scene):
                return self._timed([start, goal])
        # every plan starts from the same seed (OMPL logs that sampling has started before)
        ou.setLogLevel(ou.LOG_NONE)
        ou.RNG.setSeed(settings.seed)
        ou.setLogLevel(ou.LOG_WARN)
        space = ob.RealVectorStateSpace(4)
        bounds = ob.RealVectorBounds(4)
        for i, (low, high) in enumerate(zip(self.k.lower, self.k.upper)):
            bounds.setLow(i, low)
            bounds.setHigh(i, high)
        space.setBounds(bounds)
        setup = og.SimpleSetup(space)
        information = setup.getSpaceInformation()
        model = self.model
        setup.setStateValidityChecker(
            lambda state: bool(model.valid(np.array([[state[i] for i in range(4)]]),
                                           finger, scene)[0]))
        validator = _BatchMotionValidator(information, self, finger, scene)
        information.setMotionValidator(validator)
        start_state = space.allocState()
        for i in range(4):
            start_state[i] = float(np.clip(start[i], self.k.lower[i], self.k.upper[i]))
        setup.addStartState(start_state)
        goal_states = ob.GoalStates(information)
        for goal in goals:
            state = space.allocState()
            for i in range(4):
                state[i] = float(goal[i])
            goal_states.addState(state)
        setup.setGoal(goal_states)
        setup.setPlanner(og.RRTConnect(information))
        status = setup.solve(settings.planning_time)
        if not setup.haveExactSolutionPath():
            if "TIMEOUT" in str(status).upper() or "timeout" in str(status).lower():
                return Plan(Codes.TIMED_OUT, f"no path within {settings.planning_time} s")
            return Plan(Codes.PLANNING_FAILED, f"the planner found no path ({status})")
        solution = setup.getSolutionPath()
        path = [np.array([solution.getState(j)[i] for i in range(4)])
                for j in range(solution.getStateCount())]
        path[0] = start
        path = self.shortcut(path, finger, scene)
        if not self.path_free(path, finger, scene):
            return Plan(Codes.INVALID_MOTION_PLAN, "the shortened path failed the dense check")
        return self._timed(path)

    def shortcut(self, path: List[np.ndarray], finger: float, scene: Scene) -> List[np.ndarray]:
        """Shortens a path greedily: from each kept vertex, straight to the farthest vertex
        it can reach freely. Deterministic (unlike a time-limited random shortcutter)."""
        kept, i = [path[0]], 0
        while i < len(path) - 1:
            j = len(path) - 1
            while j > i + 1 and not self.motion_free(path[i], path[j], finger, scene):
                j -= 1
            kept.append(path[j])
            i = j
        return kept

    # --- timing ------------------------------------------------------------------------
    def _timed(self, path: List[np.ndarray]) -> Plan:
        """Each straight segment with a trapezoidal profile (rest to rest), sampled every
        ``sample_period``: no joint faster than velocity_scaling x the limit."""
        settings = self.settings
        speed = self.k.max_speed * settings.velocity_scaling
        accel = settings.acceleration
        plan = Plan(Codes.SUCCESS, "planned", path=path)
        clock = 0.0
        plan.times.append(0.0)
        plan.positions.append(path[0].copy())
        plan.velocities.append(np.zeros(4))
        for a, b in zip(path, path[1:]):
            delta = b - a
            length = float(np.max(np.abs(delta)))
            if length < 1e-9:
                continue
            direction = delta / length
            ramp = speed / accel
            if length < speed * ramp:  # never reaches full speed: a triangle
                ramp = math.sqrt(length / accel)
                top, cruise = accel * ramp, 0.0
            else:
                top, cruise = speed, (length - speed * ramp) / speed
            duration = 2 * ramp + cruise
            samples = max(2, int(math.ceil(duration / settings.sample_period)))
            for t in np.linspace(0.0, duration, samples + 1)[1:]:
                if t < ramp:
                    s, v = 0.5 * accel * t * t, accel * t
                elif t < ramp + cruise:
                    s, v = 0.5 * top * ramp + top * (t - ramp), top
                else:
                    left = duration - t
                    s, v = length - 0.5 * accel * left * left, accel * left
                plan.times.append(clock + float(t))
                plan.positions.append(a + direction * s)
                plan.velocities.append(direction * v)
            plan.positions[-1] = b.copy()
            plan.velocities[-1] = np.zeros(4)
            clock += duration
        return plan


def settings_from(cls, values: Mapping, prefix: str = ""):
    """A settings dataclass (fields declared with node_params) from a mapping: known keys
    only, converted and checked; the rest keep their defaults. node_params.ParameterError
    (a ValueError) names ``prefix + key``, the value and what is expected."""
    return read(cls, values, prefix)


def planner_from_config(robot: Mapping, settings: Mapping, prefix: str = "") -> ArmPlanner:
    """The planner for a robot yaml (config/px100.yaml) and the mover's settings
    (config/mover.yaml and private parameters, named ``prefix + key`` in errors; unknown
    keys are ignored)."""
    kinematics = ArmKinematics.from_config(robot)
    collision = settings_from(CollisionSettings, settings, prefix)
    model = ArmCollisionModel(kinematics, robot["links"], robot["finger"],
                              collision.collision_padding,
                              robot.get("self_collision_pairs"),  # none: from the geometry
                              collision.attached_contact_tolerance)
    return ArmPlanner(kinematics, model, settings_from(PlannerSettings, settings, prefix))


def random_reachable_targets(planner: ArmPlanner, scene: Scene, count: int, finger: float,
                             seed: int = 7) -> List[np.ndarray]:
    """Gripper points of random free configurations: reachable and collision-free by
    construction (the planner may choose another configuration for each)."""
    rng = np.random.default_rng(seed)
    targets = []
    while len(targets) < count:
        q = rng.uniform(planner.k.lower, planner.k.upper)
        point = planner.k.gripper_point(q)
        if planner.model.collision(q, finger, scene) is None and scene.containing(point) is None:
            targets.append(point)
    return targets

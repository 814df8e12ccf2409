"""trac_ik_kinematics_plugin/TRAC_IKKinematicsPlugin on the KDL descent: each solve_type's
defining property (traclabs/trac_ik trac_ik_lib/src/trac_ik.cpp, runSolver and CartToJnt), on
the six-axis arm (its up to 8 closed-form branches give Distance and Manipulation a choice).
Every answer is checked by forward kinematics apart from KDL (urdf_tools); the solutions the
choice is measured against are found by Speed from many random seeds."""
import contextlib
import logging
import math
import os
import time

import numpy as np
import pytest

from moveit_core import robot_model
from moveit_kinematics.kdl_solver import SolverSettings
from moveit_kinematics.solvers import load_solver
from moveit_kinematics.trac_ik import (DEFAULT_EPSILON, DEFAULT_SOLVE_TYPE, TRAC_IK_PLUGIN,
                                       TracIkSettings, TracIkSolver)
from urdf_tools.kinematics import link_transform

DATA = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))), "moveit_core", "test", "data")
TARGETS = 3              # random reachable poses per solve type
REFERENCE_SEEDS = 40     # Speed solves giving the solutions a choice is compared with
SEARCH_TIME = 0.3        # s: Distance and Manipulation search for the whole of it
SPEED_TIMEOUT = 2.0      # s: Speed returns long before it
REACHED = 1e-4           # m: a solution's tool within this of the target (epsilon is 1e-5)
# relative: the same branch found twice differs by the descent's tolerance (about 1e-5 rad a
# joint), two branches by far more
SAME = 1e-3
# the limits penalty of a joint near its bound changes by percents with such a difference
SAME_MANIPULABILITY = 0.05


def load():
    with open(os.path.join(DATA, "six_axis_arm.urdf"), encoding="utf-8") as urdf, \
            open(os.path.join(DATA, "six_axis_arm.srdf"), encoding="utf-8") as srdf:
        return robot_model.load(urdf.read(), srdf.read())


MODEL = load()


def solver(solve_type, seed=3):
    return TracIkSolver(MODEL, "manipulator", SolverSettings(kinematics_solver=TRAC_IK_PLUGIN),
                        TracIkSettings(solve_type=solve_type), seed=seed)


def truth(solver_, positions):
    return link_transform(MODEL.urdf, solver_.base, solver_.tip, solver_.state(positions))


def random_state(rng, solver_):
    return [rng.uniform(max(b.lower, -math.pi), min(b.upper, math.pi)) for b in solver_.bounds]


def reached(solver_, solution, target):
    assert solution is not None
    assert all(b.contains(v) for b, v in zip(solver_.bounds, solution))
    return np.linalg.norm(truth(solver_, solution)[:3, 3] - target[:3, 3]) < REACHED


def reference_solutions(target, chooser):
    """Solutions found by Speed from random seeds, put where ``chooser`` would put them."""
    speed = solver("Speed", seed=11)
    rng = np.random.default_rng(5)
    found = []
    for _ in range(REFERENCE_SEEDS):
        solution = speed.inverse(target, random_state(rng, speed), SPEED_TIMEOUT)
        if solution is not None:
            found.append(solution)
    assert len(found) > REFERENCE_SEEDS // 2
    return found


def test_trac_iks_parameters_and_defaults():
    assert TracIkSettings.from_parameters({}) == TracIkSettings("Speed", 1e-5)
    assert (DEFAULT_SOLVE_TYPE, DEFAULT_EPSILON) == ("Speed", 1e-5)
    settings = TracIkSettings.from_parameters({"solve_type": "Distance", "epsilon": 1e-4,
                                               "kinematics_solver": TRAC_IK_PLUGIN})
    assert settings == TracIkSettings("Distance", 1e-4)
    chosen = solver("Distance")
    assert chosen.position_tolerance == chosen.orientation_tolerance == DEFAULT_EPSILON


def test_an_unknown_solve_type_is_speed_with_trac_iks_warning(caplog):
    with caplog.at_level(logging.WARNING, logger="rosout.moveit_kinematics"):
        chosen = solver("Manip1")
    assert chosen.solve_type == "Speed"
    assert "Manip1 is not a valid solve_type; setting to default: Speed" in caplog.text


def test_move_group_gets_trac_ik_under_its_name(caplog):
    with caplog.at_level(logging.INFO, logger="rosout.moveit_kinematics"):
        chosen = load_solver(MODEL, "manipulator",
                             {"kinematics_solver": TRAC_IK_PLUGIN, "solve_type": "Manipulation2"},
                             "", "")
    assert isinstance(chosen, TracIkSolver) and chosen.solve_type == "Manipulation2"
    assert f"group 'manipulator': kinematics solver '{TRAC_IK_PLUGIN}' loaded" in caplog.text


def test_speed_answers_with_the_first_solution():
    speed = solver("Speed")
    rng = np.random.default_rng(1)
    for _ in range(TARGETS):
        state = random_state(rng, speed)
        target = truth(speed, state)
        started = time.monotonic()
        solution = speed.inverse(target, state, SPEED_TIMEOUT)
        # the seed is a solution: the descent from it is the first, at once
        assert time.monotonic() - started < SPEED_TIMEOUT / 4
        assert reached(speed, solution, target)
        np.testing.assert_allclose(solution, state, atol=1e-3)


@contextlib.contextmanager
def measured(solver_, measure):
    """The values ``solver_.<measure>`` gives while the block runs (the solver compares the
    solutions it found by it)."""
    original = getattr(solver_, measure)
    values = []

    def recording(*args):
        values.append(original(*args))
        return values[-1]
    setattr(solver_, measure, recording)
    try:
        yield values
    finally:
        delattr(solver_, measure)


def test_distance_answers_with_the_solution_nearest_the_seed():
    distance = solver("Distance")
    rng = np.random.default_rng(2)
    differs = 0
    for _ in range(TARGETS):
        target = truth(distance, random_state(rng, distance))
        seed = random_state(rng, distance)
        started = time.monotonic()
        with measured(distance, "joint_error") as compared:
            solution = distance.inverse(target, seed, SEARCH_TIME)
        # it searches for the whole timeout, as TRAC-IK's Distance does
        assert time.monotonic() - started >= SEARCH_TIME
        assert reached(distance, solution, target)
        mine = distance.joint_error(seed, solution)
        # the nearest of the solutions the search found (how many it finds in the time depends
        # on the machine's load, as TRAC-IK's does)
        assert mine == pytest.approx(min(compared)), (mine, sorted(compared)[:3])
        others = [distance.joint_error(seed, distance._normalized(q, seed))
                  for q in reference_solutions(target, distance)
                  if distance._normalized(q, seed) is not None]
        differs += mine < max(others) * (1 - SAME)
    assert differs   # there was a choice to make


@pytest.mark.parametrize("solve_type", ["Manipulation1", "Manipulation2"])
def test_manipulation_answers_with_the_most_manipulable_solution(solve_type):
    manip = solver(solve_type)
    rng = np.random.default_rng(4)
    differs = 0
    for _ in range(TARGETS):
        target = truth(manip, random_state(rng, manip))
        seed = random_state(rng, manip)
        with measured(manip, "manipulability") as compared:
            solution = manip.inverse(target, seed, SEARCH_TIME)
        assert reached(manip, solution, target)
        mine = manip.manipulability(solution)
        # the most manipulable of the solutions the search found in the time
        assert mine == pytest.approx(max(compared)), (mine, sorted(compared)[-3:])
        others = [manip.manipulability(manip._normalized(q, seed))
                  for q in reference_solutions(target, manip)
                  if manip._normalized(q, seed) is not None]
        differs += mine > min(others) * (1 + SAME_MANIPULABILITY)
    assert differs


def test_the_manipulability_measures_are_trac_iks():
    manip1, manip2 = solver("Manipulation1"), solver("Manipulation2")
    middle = [(b.lower + b.upper) / 2 for b in manip1.bounds]
    # manipPenalty: 1 - exp(-prod (q - lower)(upper - q) / range^2), 1/4 a joint at the middle
    assert manip1.limits_penalty(middle) == pytest.approx(1 - math.exp(-0.25 ** 6))
    near_bound = list(middle)
    near_bound[0] = manip1.bounds[0].upper
    assert manip1.limits_penalty(near_bound) == 0.0
    state = [0.1, 0.4, 0.8, 0.3, 0.5, 0.2]
    jacobian = np.array(_jacobian(manip1, state))
    singular = np.linalg.svd(jacobian, compute_uv=False)
    penalty = manip1.limits_penalty(state)
    assert manip1.manipulability(state) == pytest.approx(penalty * np.prod(singular), rel=1e-5)
    assert manip2.manipulability(state) == pytest.approx(
        penalty * singular.min() / singular.max(), rel=1e-5)


def _jacobian(solver_, state, step=1e-7):
    """The geometric Jacobian by finite differences of urdf_tools' FK (apart from KDL)."""
    base = truth(solver_, state)
    columns = []
    for i in range(len(state)):
        moved = list(state)
        moved[i] += step
        other = truth(solver_, moved)
        linear = (other[:3, 3] - base[:3, 3]) / step
        turn = other[:3, :3] @ base[:3, :3].T
        angular = np.array([turn[2, 1] - turn[1, 2], turn[0, 2] - turn[2, 0],
                            turn[1, 0] - turn[0, 1]]) / (2 * step)
        columns.append(np.concatenate([linear, angular]))
    return np.array(columns).T


def test_a_refused_solution_is_not_the_answer():
    """The solution callback: Speed searches on from random seeds; Distance's one search
    used the whole timeout, so a refused best leaves none (the plugin's loop)."""
    speed, distance = solver("Speed"), solver("Distance")
    rng = np.random.default_rng(6)
    state = random_state(rng, speed)
    target = truth(speed, state)
    wanted = speed.inverse(target, state, SPEED_TIMEOUT,
                           accept=lambda q: abs(q[0] - state[0]) > 0.5)
    assert wanted is not None and abs(wanted[0] - state[0]) > 0.5
    assert reached(speed, wanted, target)
    assert distance.inverse(target, state, SEARCH_TIME, accept=lambda q: False) is None

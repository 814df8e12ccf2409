"""Iterative parabolic time parameterization: speeds and accelerations (finite differences
of the result) within the limits times the scaling factors, at rest at both ends, the path's
positions kept; MoveIt's reading of the scaling factors."""
import numpy as np
import pytest

from moveit_core.time_parameterization import TimingError, scaling, time_path


def path(count=40, seed=0):
    rng = np.random.default_rng(seed)
    return np.cumsum(rng.uniform(-0.05, 0.05, (count, 3)), axis=0)


@pytest.mark.parametrize("velocity_scaling, acceleration_scaling", [(1.0, 1.0), (0.3, 0.1)])
def test_speeds_and_accelerations_within_the_scaled_limits(velocity_scaling,
                                                           acceleration_scaling):
    q = path()
    vmax, amax = np.array([2.0, 1.0, 3.0]), np.array([5.0, 2.0, 4.0])
    timed = time_path(q, vmax, amax, velocity_scaling, acceleration_scaling)
    np.testing.assert_array_equal(timed.positions, q)
    dt = np.diff(timed.times)
    assert np.all(dt > 0)
    speeds = np.diff(q, axis=0) / dt[:, None]
    assert np.all(np.abs(speeds) <= vmax * velocity_scaling + 1e-9)
    # acceleration at each inner waypoint from the segments either side
    inner = (speeds[1:] - speeds[:-1]) * 2 / (dt[1:] + dt[:-1])[:, None]
    assert np.all(np.abs(inner) <= amax * acceleration_scaling + 1e-9)
    np.testing.assert_array_equal(timed.velocities[[0, -1]], 0.0)
    assert np.all(np.abs(timed.velocities) <= vmax * velocity_scaling + 1e-9)


def test_joints_without_limits_get_moveits_defaults():
    q = np.array([[0.0], [1.0], [2.0]])
    timed = time_path(q, [None], [None])
    speeds = np.diff(q[:, 0]) / np.diff(timed.times)
    assert np.all(speeds <= 1.0 + 1e-9)


def test_scaling_factors_as_moveit_reads_them():
    assert [scaling(v) for v in (0.0, 0.5, 1.0, 1.5, -1.0)] == [1.0, 0.5, 1.0, 1.0, 1.0]


def test_one_waypoint_and_bad_paths():
    assert time_path([[0.3, 0.1]], [1, 1], [1, 1]).times.tolist() == [0.0]
    with pytest.raises(TimingError):
        time_path([[0.0, float("nan")]], [1, 1], [1, 1])


@pytest.mark.parametrize("points", [66, 3, 2])
@pytest.mark.parametrize("distance, vmax, amax", [(2.0, 2.35, 5.0), (0.011, 1.0, 0.01),
                                                  (0.001, 2.35, 5.0)])
def test_a_straight_path_takes_the_trapezoids_time(distance, vmax, amax, points):
    """Waypoints on a line, dense (as a planner interpolates them) or only the two ends (a
    goal a millimetre away: the two-point path took 3.8e9 s, which no Duration holds):
    rest to rest in the time of the ideal trapezoid (or triangle) within 1 %."""
    q = np.linspace(0.0, distance, points)[:, None]
    ramp = vmax / amax
    ideal = distance / vmax + ramp if vmax * ramp < distance else 2 * np.sqrt(distance / amax)
    assert time_path(q, [vmax], [amax]).times[-1] == pytest.approx(ideal, rel=0.01)

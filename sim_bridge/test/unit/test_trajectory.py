"""sim_bridge.trajectory: the interpolation the JointTrajectoryController uses."""
import numpy as np
import pytest

from sim_bridge.trajectory import Trajectory, Waypoint


def point(t, p, v=None, a=None):
    arrays = [None if x is None else np.array(x, dtype=float) for x in (p, v, a)]
    return Waypoint(t, *arrays)


def test_linear_between_positions():
    trajectory = Trajectory(point(0.0, [0.0]), [point(2.0, [1.0]), point(3.0, [0.0])])
    assert trajectory.sample(1.0)[0] == pytest.approx([0.5])
    assert trajectory.sample(1.0)[1] == pytest.approx([0.5])
    assert trajectory.sample(2.5)[0] == pytest.approx([0.5])
    assert trajectory.sample(10.0)[0] == pytest.approx([0.0])  # holds the last point


def test_cubic_meets_positions_and_velocities_at_both_ends():
    trajectory = Trajectory(point(0.0, [0.0], [0.0]), [point(1.0, [1.0], [0.0])])
    for t, position, velocity in ((0.0, 0.0, 0.0), (0.5, 0.5, 1.5), (1.0, 1.0, 0.0)):
        p, v, _ = trajectory.sample(t)
        assert p == pytest.approx([position]) and v == pytest.approx([velocity])


def test_quintic_meets_accelerations_too():
    trajectory = Trajectory(point(0.0, [0.0], [0.0], [0.0]), [point(2.0, [1.0], [0.0], [0.0])])
    p, v, a = trajectory.sample(1.0)
    assert p == pytest.approx([0.5]) and a == pytest.approx([0.0], abs=1e-12)
    p, v, a = trajectory.sample(2.0)
    assert (p, v, a) == (pytest.approx([1.0]), pytest.approx([0.0]), pytest.approx([0.0]))


def test_points_before_the_start_are_dropped():
    trajectory = Trajectory(point(5.0, [0.0]), [point(4.0, [9.0]), point(6.0, [1.0])])
    assert trajectory.sample(5.5)[0] == pytest.approx([0.5])

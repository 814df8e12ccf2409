"""Iterative parabolic time parameterization as Noetic's MoveIt runs it (moveit noetic-devel
7c0343f0, moveit_core/trajectory_processing/src/iterative_time_parameterization.cpp). The
expected segment times below are what that file's algorithm gives for the same paths and
limits: its loops were compiled as a stand-alone harness outside this repository and agree
with this module to 1e-14 on these and random paths of 1-6 joints."""
import numpy as np
import pytest

from moveit_core.time_parameterization import TimingError, scaling, time_path

PATH = np.array([[0.0, 0.5, -0.2], [0.1, 0.45, -0.1], [0.25, 0.3, 0.05], [0.3, 0.1, 0.3],
                 [0.28, -0.1, 0.4], [0.2, -0.2, 0.35], [0.0, -0.25, 0.2], [-0.1, -0.2, 0.0]])
VMAX, AMAX = [2.0, 1.0, 3.0], [5.0, 0.5, 4.0]
# the harness's segment times for PATH, without and with a start velocity
HARNESS = [0.5676095018079185, 0.4400000000000003, 0.366561230252443, 0.45000000000000023,
           0.4600000000000003, 0.40446644110000024, 0.48666666666666697]
HARNESS_FROM_VELOCITY = [0.45760950180791843, 0.4500000000000003, 0.37656123025244304,
                         0.45000000000000023, 0.4600000000000003, 0.40446644110000024,
                         0.48666666666666697]


def test_segment_times_are_noetics():
    timed = time_path(PATH, VMAX, AMAX)
    np.testing.assert_allclose(np.diff(timed.times), HARNESS, rtol=1e-12)
    np.testing.assert_array_equal(timed.positions, PATH)
    # speeds within the limits (applyVelocityConstraints is exact); at rest at both ends
    speeds = np.diff(PATH, axis=0) / np.diff(timed.times)[:, None]
    assert np.all(np.abs(speeds) <= np.array(VMAX) + 1e-12)
    np.testing.assert_array_equal(timed.velocities[[0, -1]], 0.0)


def test_a_known_start_velocity_is_where_the_first_segment_starts():
    start = [0.2, -0.1, 0.0]
    timed = time_path(PATH, VMAX, AMAX, start_velocity=start)
    np.testing.assert_allclose(np.diff(timed.times), HARNESS_FROM_VELOCITY, rtol=1e-12)
    np.testing.assert_allclose(timed.velocities[0], start)
    np.testing.assert_array_equal(timed.accelerations[0], 0.0)


def test_moveits_own_test_a_straight_line_in_under_three_seconds():
    """moveit_core/trajectory_processing/test/test_time_parameterization.cpp,
    TestIterativeParabolic: 11 waypoints from 0 to 2 rad on the PR2's r_shoulder_pan_joint
    (2.088 rad/s in its URDF, no acceleration limit: 1 rad/s^2) take under 3 s."""
    q = np.array([i * 2.0 / 10 for i in range(10)] + [2.0])[:, None]
    duration = time_path(q, [2.088], [None]).times[-1]
    assert duration < 3.0
    assert duration == pytest.approx(2.849341663191666, rel=1e-12)


def test_a_gripper_starting_a_hair_off_its_path_opens_in_seconds():
    """Interbotix's px100 gripper (1 m/s, 0.01 m/s^2 in its 4dof_joint_limits.yaml) opened
    from a simulated start 8 um off the fingers' line (the start FixStartStateBounds
    prefixes): 202 waypoints. The earlier ramp-and-stretch timing gave 52 s (73 s as
    planned in the simulation), longer than any caller waited; Noetic's IPTP gives 3.7 s."""
    fingers = np.linspace(0.015, 0.037, 201)
    q = np.vstack([[0.01499234, -0.01499484], np.column_stack([fingers, -fingers])])
    duration = time_path(q, [1.0, 1.0], [0.01, 0.01]).times[-1]
    assert duration == pytest.approx(3.6969334357984183, rel=1e-9)


def test_a_millimetre_between_two_waypoints_takes_milliseconds():
    """A goal a millimetre away (the arm already nearly there): 0.02 s, as the harness gives
    (an earlier timing gave 3.8e9 s, which no Duration holds)."""
    duration = time_path([[0.0], [0.001]], [2.35], [5.0]).times[-1]
    assert duration == pytest.approx(0.020425531914893616, rel=1e-12)


def test_scaling_factors_scale_a_joints_limits_not_the_defaults():
    """iptp:131-135: a joint's own limit is scaled; the 1 rad/s of a joint without one is
    not (a metre at 0.25 scaling: 4 s limited to 1 rad/s, 1 s unlimited)."""
    q = [[0.0], [1.0]]
    assert time_path(q, [1.0], [100.0], velocity_scaling=0.25).times[-1] == 4.0
    assert time_path(q, [None], [100.0], velocity_scaling=0.25).times[-1] == 1.0


def test_scaling_factors_as_moveit_reads_them():
    assert [scaling(v) for v in (0.0, 0.5, 1.0, 1.5, -1.0)] == [1.0, 0.5, 1.0, 1.0, 1.0]


def test_one_waypoint_and_bad_paths():
    assert time_path([[0.3, 0.1]], [1, 1], [1, 1]).times.tolist() == [0.0]
    with pytest.raises(TimingError):
        time_path([[0.0, float("nan")]], [1, 1], [1, 1])


def test_repeated_waypoints_take_no_time():
    """MoveIt's TestRepeatedPoint (for its spline parameterization; IPTP the same): three
    equal waypoints, no time."""
    assert time_path([[1.0], [1.0], [1.0]], [1.0], [1.0]).times[-1] < 0.001

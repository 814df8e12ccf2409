"""What the simulator's loop asks at every step, made cheaper for issue 36, still answers
as before: the drive plugins' update slots (gazebo_plugins' rate branch,
gazebo_ros_diff_drive.cpp:269-271, :307 on gazebo_ros_pkgs noetic-devel f9e1a46) fire at
the same steps as the float comparison they are defined by, and the physics thread's
queue runs every job handed to it, in order."""
import threading

import pytest

from sim_bridge.plugins.base import UpdateSlots, gazebo_seconds

# step sizes (ns): Gazebo's 1 ms, pybullet's 1/240 s rounded as World keeps it, 0.1 ms, 3 ms
STEPS_NS = (1_000_000, 4_166_667, 100_000, 3_000_000)
RATES_HZ = (0.0, 1.0, 7.0, 20.0, 30.0, 50.0, 100.0, 240.0, 333.0, 1000.0, 2000.0)
SIMULATED_NS = 3_000_000_000


def reference_slots(rate_hz, step_ns):
    """The steps at which the branch runs: Noetic's ``seconds_since_last_update >
    update_period_`` in common::Time::Double() seconds, last_update_time_ moved on by one
    period (whole nanoseconds) each time; the first step is the load's time."""
    period = 1.0 / rate_hz if rate_hz > 0 else 0.0
    period_ns = int(round(period * 1e9))
    fired, last = [], None
    for now in range(step_ns, SIMULATED_NS, step_ns):
        if last is None:
            last = now
        seconds = gazebo_seconds(now - last)
        if seconds > period:
            last += period_ns
            fired.append((now, seconds))
    return fired


@pytest.mark.parametrize("step_ns", STEPS_NS)
@pytest.mark.parametrize("rate_hz", RATES_HZ)
def test_update_slots_fire_where_the_float_comparison_says(rate_hz, step_ns):
    slots = UpdateSlots(rate_hz)
    fired = []
    for now in range(step_ns, SIMULATED_NS, step_ns):
        seconds = slots.due(now)
        if seconds is not None:
            fired.append((now, seconds))
    assert fired == reference_slots(rate_hz, step_ns)


def test_the_physics_queue_serves_every_job_in_order_from_other_threads():
    from sim_bridge.ros_node import PhysicsThread
    physics = PhysicsThread()
    done = []
    posters = [threading.Thread(target=lambda k=k: [physics.post(
        lambda k=k, i=i: done.append((k, i))) for i in range(200)]) for k in range(4)]
    for poster in posters:
        poster.start()
    for poster in posters:
        poster.join(timeout=30)
    physics.serve()
    assert sorted(done) == [(k, i) for k in range(4) for i in range(200)]
    for k in range(4):  # each thread's jobs in the order it posted them
        assert [i for kk, i in done if kk == k] == list(range(200))
    physics.serve()  # nothing left: returns at once
    assert len(done) == 800


def test_the_old_imus_frame_change_is_tfs_matrix_transposed():
    """gazebo_ros_imu's world -> sensor turn, written out in floats, against
    tf.transformations' rotation matrix of the same unit quaternion, transposed."""
    import numpy as np
    from tf.transformations import quaternion_matrix

    from sim_bridge.plugins.body_state import to_sensor
    rng = np.random.default_rng(36)
    for _ in range(200):
        q = rng.normal(size=4)
        q /= np.linalg.norm(q)
        v = rng.normal(scale=10.0, size=3)
        expected = quaternion_matrix(q)[:3, :3].T @ v
        assert to_sensor(tuple(q), v) == pytest.approx(tuple(expected), abs=1e-12)

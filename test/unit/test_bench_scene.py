"""tools/bench.py's physics alone (BareScene), what make bench compares the simulator with:
its robot drives the circle the ROS run's robot drives (a robot left standing costs the
physics less, and made the ROS overhead look larger than it is), and paced, it keeps real
time."""
import math
import os
import sys
import time

import pybullet as pb
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))), "tools"))
import bench  # noqa: E402  (tools/ is not a package)


@pytest.fixture(scope="module")
def scene():
    scene = bench.BareScene()
    yield scene
    scene.close()


def _pose(scene):
    world = scene.world
    position, orientation = pb.getBasePositionAndOrientation(
        world.models["rb1_class"].robot.id, physicsClientId=world.client)
    return position, pb.getEulerFromQuaternion(orientation)[2]


def test_the_bare_robot_drives_the_circle(scene):
    """0.3 m/s and 0.5 rad/s (RosProbe.circle): over a simulated second, the ground truth
    turns by about 0.5 rad and moves by about 0.3 m, as the ROS run's robot."""
    start, start_yaw = _pose(scene)
    started_ns = scene.world.now_ns
    while scene.world.now_ns - started_ns < 1_000_000_000:
        scene.rate(0.01)
    end, end_yaw = _pose(scene)
    seconds = (scene.world.now_ns - started_ns) / 1e9
    turned = math.remainder(end_yaw - start_yaw, math.tau)
    assert turned / seconds == pytest.approx(0.5, rel=0.15)
    assert math.dist(start[:2], end[:2]) / seconds == pytest.approx(0.3, rel=0.15)


def test_paced_bare_scene_keeps_real_time(scene):
    started_ns, wall = scene.world.now_ns, time.monotonic()
    cpu = scene.paced_cpu(0.3)
    simulated = (scene.world.now_ns - started_ns) / 1e9
    assert simulated == pytest.approx(time.monotonic() - wall, abs=0.05)
    assert 0.0 < cpu < 100.0

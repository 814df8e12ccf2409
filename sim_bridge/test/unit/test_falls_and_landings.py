"""A robot dropped from 1 m (launch files spawn at ``-z 1``): in the air nothing turns it, as
no torque acts on it; it lands where it fell, facing as it fell, whatever fraction of a step
its wheels touch down at. Before the tyre load cap, the one-step impact load (8-53 kN a
wheel) drove the next step's tyre friction: a 24 kg robot rested up to 13 cm off and 10
degrees tilted on landing, 43 cm and 5 degrees off its heading without its drive plugin."""
import math
import os

import numpy as np
import pytest

from sim_bridge.poses import rpy_from_quaternion
from sim_bridge.tyre_friction import LOAD_CAP_SHARE
from urdf_tools.xacro_loader import expand
from world_fixtures import DATA, run

G = 9.8
FALL = 0.40         # s: before the first contact from 1 m (touchdown at sqrt(2/g) = 0.452 s)
SETTLE = 1.5        # s after the drop starts
# touchdown at 17 points within a 1 ms step: 1.000 to 1.004 m in 0.25 mm steps
HEIGHTS = [1.0 + 0.00025 * i for i in range(17)]


def angle_between(first, second):
    """Degrees of rotation between two (x, y, z, w) quaternions."""
    dot = abs(float(np.dot(first, second)))
    return math.degrees(2 * math.acos(min(1.0, dot)))


@pytest.mark.parametrize("robot", ["diff_bot", "skid_bot", "burger_like", "heavy_bot"])
def test_nothing_turns_a_falling_robot(world, robot):
    world.spawn_urdf("r", expand(os.path.join(DATA, f"{robot}.urdf.xacro")), (0, 0, 1.0))
    start = world.pose("r")
    run(world, FALL)
    (x, y, z), orientation = world.pose("r")
    assert angle_between(start[1], orientation) < 0.01
    assert math.hypot(x - start[0][0], y - start[0][1]) < 1e-6
    assert z == pytest.approx(start[0][2] - G * FALL ** 2 / 2, abs=G * world.step_size * FALL)


@pytest.mark.parametrize("drive", ["true", "false"])
@pytest.mark.parametrize("height", HEIGHTS)
def test_a_dropped_robot_rests_where_it_fell_facing_as_it_fell(world, drive, height):
    world.spawn_urdf("r", expand(os.path.join(DATA, "heavy_bot.urdf.xacro"), {"drive": drive}),
                     (0, 0, height))
    tilt = 0.0
    for _ in range(int(round(SETTLE / 0.01))):
        run(world, 0.01)
        roll, pitch, _ = rpy_from_quaternion(world.pose("r")[1])
        tilt = max(tilt, math.degrees(max(abs(roll), abs(pitch))))
    (x, y, _), orientation = world.pose("r")
    roll, pitch, yaw = (math.degrees(a) for a in rpy_from_quaternion(orientation))
    assert math.hypot(x, y) < 0.01, (x, y)
    assert abs(roll) < 1.0 and abs(pitch) < 1.0  # level, as spawned
    assert abs(yaw) < 1.0  # free wheels: up to 0.8 (pybullet's contact order), 0.3 driven
    assert tilt < 3.0


def test_the_friction_of_an_impact_is_bounded_by_the_weight_share(world):
    world.spawn_urdf("r", expand(os.path.join(DATA, "heavy_bot.urdf.xacro")), (0, 0, 0.03))
    run(world, 0.2)
    friction = world.model("r").friction
    share = friction.mass * G / len(friction.tyres)
    assert friction.load_cap == pytest.approx(LOAD_CAP_SHARE * share)

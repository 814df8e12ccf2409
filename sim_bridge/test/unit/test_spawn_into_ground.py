"""A robot spawned with its collision shapes below the ground (packages that spawn at -z 0
with wheels under their base link) is set on the ground, as Gazebo lifts it, instead of
being shot into the air by the penetration's correction."""
import pytest

from sim_bridge.poses import rpy_from_quaternion

from world_fixtures import run


def test_a_robot_spawned_into_the_ground_rests_on_it(world, diff_bot_xml):
    world.spawn_urdf("resting", diff_bot_xml(), (0.0, 0.0, 0.0))
    run(world, 1.0)
    (_, _, resting_z), _ = world.pose("resting")
    world.delete("resting")

    world.spawn_urdf("sunk", diff_bot_xml(), (0.0, 0.0, -0.1))
    highest = -1.0
    for _ in range(20):  # 2 s, watched every 0.1 s
        run(world, 0.1)
        highest = max(highest, world.pose("sunk")[0][2])
    (x, y, z), orientation = world.pose("sunk")
    roll, pitch, _ = rpy_from_quaternion(orientation)
    assert highest < resting_z + 0.2
    assert z == pytest.approx(resting_z, abs=0.005)
    assert (x, y) == pytest.approx((0.0, 0.0), abs=0.01)
    assert abs(roll) < 0.01 and abs(pitch) < 0.01


def test_reset_puts_it_back_on_the_ground_not_into_it(world, diff_bot_xml):
    world.spawn_urdf("sunk", diff_bot_xml(), (0.0, 0.0, -0.1))
    run(world, 0.5)
    world.reset()
    run(world, 0.5)
    assert abs(world.pose("sunk")[0][2]) < 0.01

"""A robot written as TurtleBot3 burger's package writes its gazebo tags (wheelAcceleration 1,
wheelTorque 10, a 360-beam laser, the older IMU plugin) drives and turns as commanded, in the
simulator's ground truth, and its sensors publish."""
import math
import os

import pytest
from geometry_msgs.msg import Twist

from sim_bridge.poses import yaw_from_quaternion
from urdf_tools.xacro_loader import expand

from world_fixtures import DATA, run


@pytest.fixture
def burger(world):
    world.spawn_urdf("burger", expand(os.path.join(DATA, "burger_like.urdf.xacro"), {}),
                     (0.0, 0.0, 0.0))
    run(world, 0.5)
    return world


def command(bus, linear, angular):
    twist = Twist()
    twist.linear.x, twist.angular.z = linear, angular
    bus.subscriptions["/cmd_vel"](twist)


def test_it_drives_a_metre_at_0_2_m_s_for_5_s(burger, bus):
    (x0, y0, _), _ = burger.pose("burger")
    command(bus, 0.2, 0.0)
    run(burger, 5.0)
    command(bus, 0.0, 0.0)
    run(burger, 1.0)  # comes to rest
    (x1, y1, _), _ = burger.pose("burger")
    assert math.hypot(x1 - x0, y1 - y0) == pytest.approx(1.0, rel=0.02)
    assert abs(y1 - y0) < 0.02


def turn_for(world, seconds, last_yaw):
    """(angle turned, final yaw), summed every 0.1 s of simulated time."""
    turned = 0.0
    for _ in range(int(round(seconds / 0.1))):
        run(world, 0.1)
        yaw = yaw_from_quaternion(world.pose("burger")[1])
        turned += math.atan2(math.sin(yaw - last_yaw), math.cos(yaw - last_yaw))
        last_yaw = yaw
    return turned, last_yaw


def test_it_turns_2_rad_at_0_5_rad_s_for_4_s(burger, bus):
    command(bus, 0.0, 0.5)
    turning, yaw = turn_for(burger, 4.0, yaw_from_quaternion(burger.pose("burger")[1]))
    command(bus, 0.0, 0.0)
    coasting, _ = turn_for(burger, 1.0, yaw)
    assert turning + coasting == pytest.approx(2.0, rel=0.03)


def test_its_laser_and_imu_publish(burger, bus):
    scan = bus.last("/scan")
    assert len(scan.ranges) == 360 and scan.header.frame_id == "base_scan"
    assert bus.last("/imu").header.frame_id == "imu_link"
    assert not [w for w in bus.warnings if "not loaded" in w or "not emulated by" in w
                and "plugin" in w]

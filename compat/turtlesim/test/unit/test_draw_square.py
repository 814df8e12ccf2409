"""turtle_world.draw_square's state machine driving this package's turtle model: squares of
2 m, as tutorials/draw_square.cpp (ros_tutorials noetic-devel db63288, :22-163: 1 m/s,
0.4 rad/s, goals within 0.1 m and 0.01 rad, PI 3.141592) draws them; and mimic's Twist
(tutorials/mimic.cpp:17-31)."""
import math
from types import SimpleNamespace

import pytest
from turtlesim.msg import Pose

from turtle_world.draw_square import PI, SquareDriver
from turtle_world.mimic import mirror
from turtle_world.world import DT, World, f32


def as_pose(step):
    return SimpleNamespace(**dict(zip(
        ("x", "y", "theta", "linear_velocity", "angular_velocity"),
        (f32(value) for value in step.pose))))


def test_draws_a_square_of_two_metre_sides():
    world = World()
    world.reset()
    turtle = world.turtles["turtle1"]
    driver, pose, now, goals = SquareDriver(), None, 0.0, []
    world.tick(now)
    while len(goals) < 5 and now < 60.0:
        move, log = driver.step(pose)
        goals += [line for line in log if line.startswith("New goal")]
        if move is not None:
            turtle.command(move[0], 0.0, move[1], now)
        now += DT
        pose = as_pose(world.tick(now)[0][1])
    centre = world.centre()[0]
    corners = [tuple(float(v) for v in g[len("New goal ["):-1].replace(",", "").split())
               for g in goals]
    assert len(corners) == 5
    assert corners[0] == pytest.approx((centre + 2.0, centre, 0.0), abs=1e-5)
    assert corners[1][:2] == pytest.approx((centre + 2.0, centre), abs=0.1)
    assert corners[1][2] == pytest.approx(PI / 2, abs=0.01)  # the next heading
    assert corners[2][:2] == pytest.approx((centre + 2.0, centre + 2.0), abs=0.2)
    assert corners[4][:2] == pytest.approx((centre, centre + 2.0), abs=0.3)


def test_waits_for_a_pose_and_stops_before_turning():
    driver = SquareDriver()
    assert driver.step(None) == (None, [])
    standing = SimpleNamespace(x=1.0, y=1.0, theta=0.0, linear_velocity=0.0,
                               angular_velocity=0.0)
    move, log = driver.step(standing)
    assert move == (1.0, 0.0) and log == ["New goal [3.000000 1.000000, 0.000000]"]
    there = SimpleNamespace(x=2.95, y=1.0, theta=0.0, linear_velocity=1.0,
                            angular_velocity=0.0)
    assert driver.step(there) == ((0.0, 0.0), [])
    assert driver.step(there) == ((0.0, 0.0), [])  # still moving: stop again
    there.linear_velocity = 0.0
    move, log = driver.step(there)
    assert move is None
    assert log[0] == "Reached goal" and log[1].startswith("New goal [2.950000 1.000000, 1.5707")
    assert driver.step(there)[0] == (0.0, 0.4)


def test_a_goal_heading_past_pi_is_wrapped():
    driver = SquareDriver()
    driver.state, driver.goal = "stop_forward", (0.0, 0.0, 0.0)
    driver.step(SimpleNamespace(x=0.0, y=0.0, theta=3.0, linear_velocity=0.0,
                                angular_velocity=0.0))
    assert driver.goal[2] == pytest.approx(f32(math.fmod(3.0 + PI / 2, 2 * PI)) - 2 * PI)


def test_mimic_sends_what_the_pose_says():
    twist = mirror(Pose(x=1.0, y=2.0, theta=3.0, linear_velocity=1.5, angular_velocity=-0.5))
    assert (twist.linear.x, twist.linear.y, twist.linear.z) == (1.5, 0.0, 0.0)
    assert (twist.angular.x, twist.angular.y, twist.angular.z) == (0.0, 0.0, -0.5)

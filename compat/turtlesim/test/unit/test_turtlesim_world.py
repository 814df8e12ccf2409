"""turtle_world.world: the window's size, spawn naming, kill, reset, the update clock and the
background parameters, as turtlesim 0.10.2's turtle_frame.cpp (ros_tutorials noetic-devel
db63288)."""
import math
import random

import pytest

from turtle_world.world import (DEFAULT_BACKGROUND, LOOKS, METER, World, background_colour,
                                f32, pixel_under, spawn_problem, teleport_problem)


def test_the_world_is_499_pixels_of_45_square():
    world = World()
    assert METER == 45.0  # turtle_frame.cpp:101: the turtle images' height
    assert world.width == world.height == f32(499 / 45)  # turtle_frame.cpp:112-113
    assert world.width == pytest.approx(11.088889, abs=1e-6)
    assert world.centre() == pytest.approx((5.544444, 5.544444), abs=1e-6)


def test_reset_starts_over_with_turtle1_in_the_middle():
    world = World()
    world.spawn("", 1.0, 1.0, 0.0)
    world.spawn("other", 2.0, 2.0, 1.0)
    assert world.reset() == "turtle1"
    assert list(world.turtles) == ["turtle1"] and world.id_counter == 1
    turtle = world.turtles["turtle1"]
    assert (turtle.x, world.height - turtle.y, turtle.orient) == pytest.approx(
        (*world.centre(), 0.0), abs=1e-6)


def test_empty_names_count_up_and_skip_names_taken():
    world = World()
    assert world.spawn("", 1, 1, 0) == "turtle1"
    assert world.spawn("turtle3", 1, 1, 0) == "turtle3"
    assert world.spawn("", 1, 1, 0) == "turtle2"
    assert world.spawn("", 1, 1, 0) == "turtle4"  # turtle3 is taken
    assert world.kill("turtle4")
    assert world.spawn("", 1, 1, 0) == "turtle5"  # the counter does not go back
    world.reset()
    assert world.spawn("", 1, 1, 0) == "turtle2"


def test_a_name_taken_is_refused():
    world = World()
    world.spawn("leo", 1, 1, 0)
    assert world.spawn("leo", 2, 2, 0) is None
    assert world.turtles["leo"].x == 1.0


def test_kill_of_an_unknown_name_fails():
    world = World()
    assert not world.kill("nobody")


def test_spawn_takes_y_up_in_floats():
    world = World()
    world.spawn("a", 1.1, 2.2, 0.3)
    turtle = world.turtles["a"]
    assert turtle.x == f32(1.1) and turtle.orient == f32(0.3)
    assert turtle.y == f32(world.height - f32(2.2))  # QPointF(x, height - y), floats


def test_looks_are_picked_at_random():
    world = World(random.Random(1))
    looks = {world.turtles[world.spawn("", 1, 1, 0)].look for _ in range(40)}
    assert looks == set(range(LOOKS))


def test_the_first_tick_only_starts_the_clock_then_turtles_update_by_name():
    world = World()
    world.spawn("b", 1, 1, 0)
    world.spawn("a", 2, 2, 0)
    world.turtles["a"].command(1.0, 0.0, 0.0, now=0.0)
    assert world.tick(0.0) == [] and world.turtles["a"].x == 2.0
    steps = world.tick(0.016)
    assert [name for name, _ in steps] == ["a", "b"]
    assert steps[0][1].pose[0] == pytest.approx(2.016)


def test_pixel_under_rounds_as_qpointf_topoint():
    assert pixel_under((0.0, 0.0)) == (0, 0)
    assert pixel_under((1.0, 2.0)) == (45, 90)
    assert pixel_under((0.5 / 45, 1.49 / 45)) == (1, 1)  # half away from zero
    world = World()
    assert pixel_under((world.width, world.height)) == (499, 499)


def params(**values):
    return lambda name, default: values.get(name.lstrip("~"), default)


def test_background_defaults():
    assert DEFAULT_BACKGROUND == (69, 86, 255)  # turtle_frame.cpp:38-40
    assert background_colour(params()) == ((69, 86, 255), [])


def test_background_from_the_parameters_rounded_as_roscpp():
    colour, warnings = background_colour(params(background_r=10, background_g=100.5,
                                                background_b=200.4))
    assert colour == (10, 101, 200) and warnings == []


@pytest.mark.parametrize("value, says", [
    ("red", "is not a number"), (300, "is not between 0 and 255"), (-1, "is not between"),
    (True, "is a boolean")])
def test_a_bad_background_channel_is_named_and_keeps_its_default(value, says):
    colour, warnings = background_colour(params(background_g=value))
    assert colour == (69, 86, 255)
    assert len(warnings) == 1
    assert warnings[0].startswith("~background_g: ") and says in warnings[0]
    assert warnings[0].endswith("; using 86")


def test_spawn_requests_that_cannot_be_served_are_named():
    assert spawn_problem("", 1.0, 2.0, 0.0) is None
    assert spawn_problem("leo/one", 1.0, 2.0, 0.0) is None
    assert "'my turtle' is not a legal ROS name" in spawn_problem("my turtle", 1, 2, 0)
    assert spawn_problem("", math.nan, 2.0, 0.0) == "x is nan; give a finite number"
    assert teleport_problem(linear=1.0, angular=math.inf) == \
        "angular is inf; give a finite number"

"""turtle_world.turtle: one turtle's motion, pen and teleports as turtlesim 0.10.2's
turtle.cpp (ros_tutorials noetic-devel db63288) does them."""
import math

import pytest

from turtle_world.turtle import (COMMAND_TIMEOUT, DEFAULT_PEN, PI, WALL_WARNING, Pen,
                                 Segment, Turtle, wrap)
from turtle_world.world import DT, World

W = H = World().width  # 11.0888... m


def run(turtle, ticks, start=0.0):
    """``ticks`` updates, one DT of wall time apart from ``start``; the last Step."""
    step = None
    for tick in range(1, ticks + 1):
        step = turtle.update(DT, start + tick * DT, W, H)
    return step


def test_upstream_constants():
    assert PI == 3.14159265  # turtle.h:51
    assert DEFAULT_PEN == Pen(179, 184, 255, 3)  # turtle.cpp:35-37, :53
    assert COMMAND_TIMEOUT == 1.0  # turtle.cpp:148
    assert DT == 0.016  # turtle_frame.cpp:59, :255
    assert WALL_WARNING % (-0.5, 3.0) == \
        "Oh no! I hit the wall! (Clamping from [x=-0.500000, y=3.000000])"


def test_forward_command_moves_v_dt_per_tick():
    turtle = Turtle(5.0, 5.0, 0.0)
    turtle.command(1.0, 0.0, 0.0, now=0.0)
    xs = [run(turtle, 1, start=k * DT).pose[0] for k in range(10)]
    steps = [b - a for a, b in zip([5.0] + xs, xs)]
    assert steps == pytest.approx([1.0 * DT] * 10, abs=1e-12)
    x, y, theta, linear, angular = run(turtle, 1, start=10 * DT).pose
    assert (y, theta, linear, angular) == pytest.approx((H - 5.0, 0.0, 1.0, 0.0))


def test_heading_turns_first_then_the_turtle_moves_along_it():
    turtle = Turtle(5.0, 5.0, 0.0)
    turtle.command(2.0, 0.0, 1.0, now=0.0)
    step = run(turtle, 1)
    assert turtle.orient == pytest.approx(DT)
    # along the new heading; canvas y points down, so the pose's y grows
    assert turtle.x == pytest.approx(5.0 + math.cos(DT) * 2.0 * DT)
    assert turtle.y == pytest.approx(5.0 - math.sin(DT) * 2.0 * DT)
    assert step.pose[1] == pytest.approx(H - turtle.y)
    assert step.pose[3:] == pytest.approx((2.0, 1.0))


def test_sideways_command_moves_left_and_reports_the_speed():
    turtle = Turtle(5.0, 5.0, 0.0)
    turtle.command(3.0, 4.0, 0.0, now=0.0)
    step = run(turtle, 1)
    assert step.pose[0] == pytest.approx(5.0 + 3.0 * DT)
    assert step.pose[1] == pytest.approx(H - 5.0 + 4.0 * DT)  # linear.y is to the left
    assert step.pose[3] == pytest.approx(5.0)  # hypot(3, 4)


def test_turning_past_pi_wraps_and_draws_nothing():
    turtle = Turtle(5.0, 5.0, 0.0)
    turtle.command(0.0, 0.0, 4.0, now=0.0)
    step = run(turtle, 50)  # 3.2 rad in 0.8 s, past PI
    assert step.pose[2] == pytest.approx(50 * DT * 4.0 - 2 * PI, abs=1e-9)
    assert step.pose[:2] == pytest.approx((5.0, H - 5.0))
    assert step.motion_line is None and step.modified  # turned in place: nothing drawn


@pytest.mark.parametrize("orient, wrapped", [
    (0.0, 0.0), (PI, -PI), (-PI, -PI), (1.5 * PI, -0.5 * PI), (-1.5 * PI, 0.5 * PI),
    (7.0, 7.0 - 2 * PI), (math.pi, math.pi - 2 * PI)])
def test_wrap_keeps_heading_within_minus_pi_and_pi(orient, wrapped):
    assert wrap(orient) == pytest.approx(wrapped, abs=1e-12)
    assert -PI <= wrap(orient) < PI


def test_a_wall_clamps_and_says_where_from():
    turtle = Turtle(0.005, 5.0, 0.0)
    turtle.command(-1.0, 0.0, 0.0, now=0.0)
    step = run(turtle, 1)
    assert step.clamped_from == pytest.approx((0.005 - DT, 5.0))
    assert (turtle.x, step.pose[0]) == (0.0, 0.0)
    step = run(turtle, 1, start=DT)
    assert step.clamped_from == pytest.approx((-DT, 5.0))
    assert step.motion_line is None  # pushed against the wall, it stays where it was


def test_the_far_walls_are_the_canvas_size():
    turtle = Turtle(W - 0.001, 0.001, math.pi / 4)
    turtle.command(1.0, 0.0, 0.0, now=0.0)
    step = run(turtle, 1)
    assert step.clamped_from is not None
    assert (turtle.x, turtle.y) == (W, 0.0)
    assert step.pose[:2] == pytest.approx((W, H))


def test_a_command_lasts_one_second_of_wall_time():
    turtle = Turtle(5.0, 5.0, 0.0)
    turtle.command(1.0, 0.0, 0.5, now=10.0)
    assert turtle.update(DT, 11.0, W, H).pose[3:] == (1.0, 0.5)
    step = turtle.update(DT, 11.0001, W, H)
    assert step.pose[3:] == (0.0, 0.0)
    assert turtle.update(DT, 11.01, W, H).pose[3:] == (0.0, 0.0)


def test_a_turtle_never_commanded_stands_still():
    turtle = Turtle(5.0, 5.0, 1.0)
    step = turtle.update(DT, 0.0, W, H)
    assert step.pose == pytest.approx((5.0, H - 5.0, 1.0, 0.0, 0.0))
    assert not step.modified and step.motion_line is None


def test_the_pen_draws_from_the_new_position_back_to_the_old():
    turtle = Turtle(5.0, 5.0, 0.0)
    turtle.command(1.0, 0.0, 0.0, now=0.0)
    step = run(turtle, 1)
    assert step.motion_line == Segment(DEFAULT_PEN, (5.0 + DT, 5.0), (5.0, 5.0))
    assert step.sensor == (5.0 + DT, 5.0)
    assert step.teleport_lines == ()


def test_set_pen_colour_width_and_off():
    turtle = Turtle(5.0, 5.0, 0.0)
    turtle.set_pen(255, 0, 0, 5, 0)
    assert turtle.pen == Pen(255, 0, 0, 5) and turtle.pen_on
    turtle.set_pen(0, 255, 0, 0, 0)  # width 0: a new QPen's, one pixel
    assert turtle.pen == Pen(0, 255, 0, 1)
    turtle.set_pen(1, 2, 3, 9, 1)  # off: the pen is lifted and stays as it was
    assert turtle.pen == Pen(0, 255, 0, 1) and not turtle.pen_on
    turtle.command(1.0, 0.0, 0.0, now=0.0)
    step = run(turtle, 1)
    assert step.motion_line is None and step.modified
    turtle.set_pen(9, 9, 9, 2, 0)  # any set_pen without off puts it down again
    assert turtle.pen_on and run(turtle, 1, start=DT).motion_line.pen == Pen(9, 9, 9, 2)


def test_teleport_absolute_waits_for_the_update_and_draws_the_jump():
    turtle = Turtle(5.0, 5.0, 0.0)
    turtle.teleport_absolute(1.0, 2.0, 0.5)
    assert (turtle.x, turtle.y) == (5.0, 5.0)  # queued
    step = run(turtle, 1)
    assert step.pose == pytest.approx((1.0, 2.0, 0.5, 0.0, 0.0))
    assert step.teleport_lines == (Segment(DEFAULT_PEN, (1.0, H - 2.0), (5.0, 5.0)),)
    assert step.modified and step.clamped_from is None
    assert turtle.teleports == []


def test_teleport_absolute_above_the_top_stops_at_it_without_a_warning():
    turtle = Turtle(5.0, 5.0, 0.0)
    turtle.teleport_absolute(3.0, 20.0, 0.0)
    step = run(turtle, 1)
    assert step.clamped_from is None  # the y flip keeps >= 0 (turtle.cpp:134)
    assert step.pose[:2] == pytest.approx((3.0, H))


@pytest.mark.parametrize("x, y, clamped", [(-1.0, 3.0, (0.0, 3.0)), (3.0, -2.0, (3.0, 0.0)),
                                           (15.0, 3.0, (W, 3.0))])
def test_teleport_absolute_off_the_canvas_is_clamped_with_the_warning(x, y, clamped):
    turtle = Turtle(5.0, 5.0, 0.0)
    turtle.teleport_absolute(x, y, 0.0)
    step = run(turtle, 1)
    assert step.clamped_from == pytest.approx((x, H - y))
    assert step.pose[:2] == pytest.approx(clamped)
    # the jump is drawn to where the request put it, then back along the clamp
    assert step.teleport_lines[0].start == pytest.approx((x, H - y))
    assert step.motion_line.start == pytest.approx((clamped[0], H - clamped[1]))


def test_teleport_relative_turns_then_moves_along_the_new_heading():
    turtle = Turtle(5.0, 5.0, 0.0)
    turtle.teleport_relative(1.0, math.pi / 2)
    step = run(turtle, 1)
    assert step.pose == pytest.approx((5.0, H - 5.0 + 1.0, math.pi / 2, 0.0, 0.0))


def test_teleports_are_done_in_order_and_wrapped_after():
    turtle = Turtle(5.0, 5.0, 3.0)
    turtle.teleport_relative(0.0, 1.0)
    turtle.teleport_relative(2.0, 0.0)
    turtle.teleport_absolute(4.0, 4.0, 1.0)
    turtle.teleport_relative(1.0, 0.0)
    step = run(turtle, 1)
    assert len(step.teleport_lines) == 4
    assert step.pose[:3] == pytest.approx((4.0 + math.cos(1.0), 4.0 + math.sin(1.0), 1.0))
    # a relative turn past PI is wrapped by the motion step that follows
    turtle.teleport_relative(0.0, 3.0)
    assert run(turtle, 1, start=DT).pose[2] == pytest.approx(wrap(4.0))


def test_teleport_with_the_pen_off_draws_nothing():
    turtle = Turtle(5.0, 5.0, 0.0)
    turtle.set_pen(0, 0, 0, 0, 1)
    turtle.teleport_absolute(1.0, 1.0, 0.0)
    step = run(turtle, 1)
    assert step.teleport_lines == () and step.modified

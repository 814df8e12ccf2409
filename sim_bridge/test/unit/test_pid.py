"""sim_bridge.ros_control.pid against control_toolbox's Pid (noetic-devel de05a5c
src/pid.cpp), the PID of every ``pid``, ``gains/<joint>`` and ``pid_gains`` in ros_control:
the gains as Pid::init reads them (pid.cpp:106-155) and the command as
Pid::computeCommand computes it (pid.cpp:305-394). Pure maths: no simulator."""
import math

import pytest

from sim_bridge.plugins.base import PluginError
from sim_bridge.ros_control.pid import Pid

DT = 0.01


def hold(pid, error, seconds, error_dot=0.0):
    """The command after ``seconds`` of a constant error (computeCommand(e, ė, dt))."""
    command = None
    for _ in range(int(round(seconds / DT))):
        command = pid.command(error, error_dot, DT)
    return command


def test_without_antiwindup_the_integral_winds_up_and_only_the_i_term_is_clamped():
    """antiwindup false (the default, pid.cpp:139): i_error += dt·e without bound (:347), the
    i-term is clamped to [i_min, i_max] (:359-363). After 5 s at +1 the integral is 5: a
    second of -1 leaves the i-term at its clamp +1; it unwinds after 5 s more. Before, the
    integral itself was clamped (antiwindup's behaviour) and the term read -1 after 1 s."""
    pid = Pid({"p": 0.0, "i": 1.0, "i_clamp": 1.0}, "test")
    assert hold(pid, 1.0, 5.0) == pytest.approx(1.0)
    assert hold(pid, -1.0, 1.0) == pytest.approx(1.0)  # was -1
    assert hold(pid, -1.0, 3.5) == pytest.approx(0.5)
    assert hold(pid, -1.0, 2.0) == pytest.approx(-1.0)


def test_with_antiwindup_the_integral_itself_is_clamped():
    """antiwindup true: i_error is clamped to [i_min/i, i_max/i] (pid.cpp:349-354), so the
    term unwinds as soon as the error turns: i = 2, i_clamp 1, the integral stops at 0.5."""
    pid = Pid({"p": 0.0, "i": 2.0, "i_clamp": 1.0, "antiwindup": True}, "test")
    assert hold(pid, 1.0, 5.0) == pytest.approx(1.0)
    assert hold(pid, -1.0, 0.25) == pytest.approx(0.5)
    assert hold(pid, -1.0, 0.25) == pytest.approx(0.0, abs=1e-12)


def test_i_clamp_defaults_to_zero_so_without_it_there_is_no_integral_action():
    """i_clamp 0 (pid.cpp:125-128) clamps the i-term to [0, 0]: an ``i`` alone does nothing."""
    pid = Pid({"p": 1.0, "i": 5.0}, "test")
    assert hold(pid, 0.5, 2.0) == pytest.approx(0.5)


def test_i_clamp_min_and_max_have_their_signs_forced():
    """i_clamp_min becomes -|x|, i_clamp_max +|x| (pid.cpp:129-138); each overrides i_clamp.
    Before, they were taken as given (here: an inverted clamp)."""
    pid = Pid({"p": 0.0, "i": 1.0, "i_clamp": 3.0, "i_clamp_min": 0.5, "i_clamp_max": -2.0},
              "test")
    assert hold(pid, 1.0, 5.0) == pytest.approx(2.0)
    assert hold(pid, -1.0, 20.0) == pytest.approx(-0.5)


def test_a_nan_or_inf_error_or_a_zero_period_commands_nothing():
    """computeCommand returns 0 for dt = 0 or an error or error rate that is NaN or inf
    (pid.cpp:308-309, :340-341), and the integral is left as it was."""
    pid = Pid({"p": 2.0, "i": 1.0, "i_clamp": 10.0}, "test")
    hold(pid, 1.0, 1.0)
    for error, error_dot, dt in ((math.nan, 0.0, DT), (math.inf, 0.0, DT), (1.0, math.nan, DT),
                                 (1.0, 0.0, 0.0)):
        assert pid.command(error, error_dot, dt) == 0.0
    for error, dt in ((math.nan, DT), (-math.inf, DT), (1.0, 0.0)):
        assert pid.compute(error, dt) == 0.0
    assert pid.command(0.0, 0.0, DT) == pytest.approx(1.0)  # the integral kept: 1 s of 1


def test_the_error_form_takes_the_derivative_from_the_error_difference():
    """computeCommand(e, dt): ė = (e - e_last)/dt (pid.cpp:311-321); after reset() the last
    error counts as 0 (reset() sets valid_p_error_last_ true, :197-201)."""
    pid = Pid({"p": 0.0, "d": 1.0}, "test")
    pid.reset()
    assert pid.compute(0.5, DT) == pytest.approx(50.0)
    assert pid.compute(0.6, DT) == pytest.approx(10.0)
    assert pid.compute(0.6, DT) == pytest.approx(0.0)


@pytest.mark.parametrize("gains", [{}, {"i": 1.0}, {"p": "ten"}, {"p": True}, "p: 1"])
def test_without_a_number_for_p_the_pid_is_refused(gains):
    """Only p is required (pid.cpp:113-119): "No p gain specified for pid"."""
    with pytest.raises(PluginError, match="No p gain specified for pid"):
        Pid(gains, "controller 'c'")


def test_gains_that_are_not_numbers_take_their_defaults():
    """nh.param falls back to the default when the value has another type (pid.cpp:121-139):
    an int is a double, a string is not, antiwindup must be a bool."""
    pid = Pid({"p": 2, "i": "five", "d": 1, "i_clamp": 2, "antiwindup": 1}, "test")
    assert (pid.p, pid.i, pid.d, pid.i_min, pid.i_max, pid.antiwindup) == \
        (2.0, 0.0, 1.0, -2.0, 2.0, False)

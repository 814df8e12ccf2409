"""The command's numeric options are refused by argparse, before anything runs, when they
cannot be a limit or a count: 0, a negative number, NaN, infinity or no number at all; the
message names the option and the value given. The batch's runner refuses them too when
called directly (a NaN limit compares false with everything, so ``limit <= 0`` let it by)."""
import math

import pytest

from course_grader import batch, cli

SECONDS = ("--scenario-limit", "--limit")
COUNTS = ("--scenario-jobs", "--jobs")


def refusal(capsys, option, value):
    """argparse's exit status and message for ``grade rb1 PATH OPTION=VALUE`` (the ``=`` form:
    argparse takes ``-inf`` after a space for another option)."""
    with pytest.raises(SystemExit) as refused:
        cli.parse_args(["rb1", "PATH", f"{option}={value}"])
    return refused.value.code, capsys.readouterr().err


@pytest.mark.parametrize("option", SECONDS)
@pytest.mark.parametrize("value", ["0", "-3", "nan", "NaN", "inf", "-inf", "1e999", "soon", ""])
def test_a_limit_that_is_not_a_positive_number_is_refused(capsys, option, value):
    code, err = refusal(capsys, option, value)
    assert code == 2
    assert f"argument {option}: must be a positive number of seconds, got {value}" in err


@pytest.mark.parametrize("option", COUNTS)
@pytest.mark.parametrize("value", ["0", "-1", "2.5", "nan", "two"])
def test_a_count_that_is_not_at_least_one_is_refused(capsys, option, value):
    code, err = refusal(capsys, option, value)
    assert code == 2
    assert f"argument {option}: must be a whole number of at least 1, got {value}" in err


def test_a_negative_number_after_a_space_is_refused_by_value(capsys):
    code, err = refusal_spaced(capsys, "--scenario-limit", "-3")
    assert code == 2 and "--scenario-limit: must be a positive number of seconds, got -3" in err


def refusal_spaced(capsys, option, value):
    with pytest.raises(SystemExit) as refused:
        cli.parse_args(["rb1", "PATH", option, value])
    return refused.value.code, capsys.readouterr().err


@pytest.mark.parametrize("option", SECONDS)
def test_a_positive_limit_is_taken(option):
    args = cli.parse_args(["rb1", "PATH", option, "0.5"])
    assert getattr(args, option[2:].replace("-", "_")) == 0.5


@pytest.mark.parametrize("option", COUNTS)
def test_a_count_of_one_or_more_is_taken(option):
    args = cli.parse_args(["rb1", "PATH", option, "3"])
    assert getattr(args, option[2:].replace("-", "_")) == 3


def test_the_runner_refuses_a_nan_or_infinite_limit():
    for limit in (math.nan, math.inf, -1.0):
        with pytest.raises(batch.BatchError, match="--limit .*: must be a positive number"):
            batch.Runner(1, limit, 1.0)

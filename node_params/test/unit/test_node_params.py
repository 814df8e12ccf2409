"""The typed parameter reader, fed what roslaunch and rosparam hand a node (no master):
text for numbers, roslaunch's own conversions, YAML lists, and values that must be refused
with the parameter, the value and the expectation named."""
from __future__ import annotations

import math
import os
import subprocess
import sys
from dataclasses import dataclass
from typing import Any, List, Optional

import pytest

from node_params import (Given, ParameterError, at_least, given_from, non_negative, one_of,
                         parameter, positive, read, zero_or_at_least)

RTF_EXPECTED = "0 (as fast as it can) or a positive number of simulated seconds per wall second"


@dataclass(frozen=True)
class Settings:
    real_time_factor: float = parameter(1.0, zero_or_at_least(0.001), expected=RTF_EXPECTED)
    seed: int = parameter(0, non_negative, expected="a whole number >= 0")
    paused: bool = parameter(False, expected="true or false")
    world_name: str = parameter("", expected="a world file")
    mode: str = parameter("fast", one_of("fast", "slow"), expected="fast or slow")
    gains: List[float] = parameter(default_factory=lambda: [1.0, 2.0], expected="numbers")
    limit: Optional[float] = parameter(None, positive, expected="a positive number or none")
    offset: float = parameter(0.0, allow_nonfinite=True, expected="any number, inf included")


def launch_value(text: str) -> Any:
    """What roslaunch makes of ``name:=text`` passed on to ``<param value=...>``: its own
    conversion (roslaunch.loader.convert_value with type auto), run in a child process so
    that this test needs no ROS on its own path."""
    code = ("import sys, roslaunch.loader as l; "
            "print(repr(l.convert_value(sys.argv[1], 'auto')))")
    result = subprocess.run([sys.executable, "-c", code, text], capture_output=True,
                            text=True, check=False, env=dict(os.environ))
    if result.returncode != 0:
        pytest.skip("roslaunch is not importable here")
    return eval(result.stdout)  # noqa: S307 - repr of a str/int/float/bool we printed


def from_params(**params):
    return read(Settings, lambda name, default: params.get(name.lstrip("~"), default))


def test_unset_parameters_keep_the_defaults():
    assert from_params() == Settings()


@pytest.mark.parametrize("text, expected", [
    ("1e9", 1e9), ("0.5", 0.5), ("0", 0.0), ("2", 2.0), (" 0.25 ", 0.25)])
def test_numbers_as_roslaunch_hands_them_over(text, expected):
    assert from_params(real_time_factor=launch_value(text)).real_time_factor == expected


@pytest.mark.parametrize("text, problem", [
    ("abc", "'abc' is not a number"),
    ("nan", "'nan' is not a finite number"),
    ("inf", "'inf' is not a finite number"),
    ("-1", "-1 is neither 0 nor at least 0.001"),
    ("true", "True is a boolean, not a number"),
    ("", "'' is not a number"),
])
def test_bad_numbers_name_parameter_value_and_expectation(text, problem):
    with pytest.raises(ParameterError) as raised:
        from_params(real_time_factor=launch_value(text))
    assert str(raised.value) == f"~real_time_factor: {problem}; expected {RTF_EXPECTED}"
    assert isinstance(raised.value, ValueError)


def test_nan_from_yaml_is_refused_too():
    with pytest.raises(ParameterError, match=r"~real_time_factor: nan is not a finite"):
        from_params(real_time_factor=float("nan"))


def test_nonfinite_allowed_where_declared():
    assert from_params(offset="inf").offset == math.inf
    assert from_params(offset=float("-inf")).offset == -math.inf


@pytest.mark.parametrize("given, expected", [
    (3, 3), ("7", 7), (2.0, 2), ("1e3", 1000), (" 12 ", 12)])
def test_whole_numbers(given, expected):
    seed = from_params(seed=given).seed
    assert seed == expected and type(seed) is int


@pytest.mark.parametrize("given, problem", [
    ("abc", "'abc' is not a whole number"),
    (2.5, "2.5 is not a whole number"),
    ("nan", "'nan' is not a whole number"),
    (-5, "-5 is negative"),
    (True, "True is a boolean, not a whole number"),
])
def test_bad_whole_numbers(given, problem):
    with pytest.raises(ParameterError) as raised:
        from_params(seed=given)
    assert str(raised.value) == f"~seed: {problem}; expected a whole number >= 0"


@pytest.mark.parametrize("given, expected", [
    (True, True), (False, False), ("true", True), ("FALSE", False), ("Yes", True),
    ("no", False), ("1", True), ("0", False), (1, True), (0, False), (" on ", True)])
def test_booleans(given, expected):
    assert from_params(paused=given).paused is expected


@pytest.mark.parametrize("given", ["maybe", 2, 0.5, "", [True]])
def test_bad_booleans_are_refused_not_guessed(given):
    with pytest.raises(ParameterError) as raised:
        from_params(paused=given)
    assert str(raised.value) == f"~paused: {given!r} is not true or false; expected true or false"


def test_text_gets_back_what_roslaunch_made_a_number():
    assert from_params(world_name=launch_value("12")).world_name == "12"
    with pytest.raises(ParameterError, match=r"~world_name: \['a'\] is not text"):
        from_params(world_name=["a"])


def test_choices():
    assert from_params(mode="slow").mode == "slow"
    with pytest.raises(ParameterError, match=r"~mode: 'medium' is not one of 'fast', 'slow'"):
        from_params(mode="medium")


def test_lists_from_yaml_text_and_their_items_named():
    assert from_params(gains="[3, 4.5]").gains == [3.0, 4.5]
    assert from_params(gains=(1, 2)).gains == [1.0, 2.0]
    with pytest.raises(ParameterError) as raised:
        from_params(gains=[1.0, "x"])
    assert str(raised.value) == "~gains[1]: 'x' is not a number; expected numbers"
    with pytest.raises(ParameterError, match=r"~gains: 'not: \[a list' is not a list"):
        from_params(gains="not: [a list")


def test_optional():
    assert from_params(limit=None).limit is None
    assert from_params(limit="2").limit == 2.0
    with pytest.raises(ParameterError, match=r"~limit: -2.0 is not positive"):
        from_params(limit=-2.0)


def test_precedence_and_labels_of_overrides_and_defaults():
    config = read(Settings, {"seed": 5}, overrides={"paused": True},
                  defaults={"seed": 9, "mode": "slow"})
    assert (config.seed, config.paused, config.mode) == (5, True, "slow")
    with pytest.raises(ParameterError, match=r"^gzserver --seed: 'x' is not a whole number"):
        read(Settings, {}, overrides={"seed": Given("x", "gzserver --seed")})
    with pytest.raises(ParameterError, match=r"^flip.yaml: mode: 'x' is not one of"):
        read(Settings, {}, defaults=given_from({"mode": "x"}, "flip.yaml"))


def test_a_mapping_source_is_named_with_the_prefix():
    with pytest.raises(ParameterError, match=r"^~seed: -1 is negative"):
        read(Settings, {"seed": -1})
    with pytest.raises(ParameterError, match=r"^seed: -1 is negative"):
        read(Settings, {"seed": -1}, prefix="")


def test_a_parameter_without_default_must_be_set():
    @dataclass
    class Needed:
        speed: float = parameter(expected="m/s")

    assert read(Needed, {"speed": "2"}).speed == 2.0
    with pytest.raises(ParameterError) as raised:
        read(Needed, {})
    assert str(raised.value) == "~speed is not set; expected m/s"


def test_caller_mistakes_are_type_errors_not_parameter_errors():
    @dataclass
    class Undeclared:
        rate: float = 1.0

    with pytest.raises(TypeError, match="Undeclared.rate"):
        read(Undeclared, {})
    with pytest.raises(TypeError, match="no parameters"):
        read(Settings, {}, overrides={"sed": 1})
    with pytest.raises(TypeError, match="expected"):
        parameter(1.0, expected="")


def test_at_least_names_its_bound():
    @dataclass
    class Rate:
        rate: float = parameter(10.0, at_least(1.0), expected="Hz, 1 or more")

    with pytest.raises(ParameterError, match=r"~rate: '0.5' is less than 1; expected Hz"):
        read(Rate, {"rate": "0.5"})

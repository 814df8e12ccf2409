"""The ME495 homework 3 course file and the grader's hooks for a course that names its
scenarios (no master): items and points, commands as typed, one way to measure each
scenario, malformed scenario sections named; RB1 keeps its built-in scenarios."""
import textwrap

import pytest

from course_grader import course as course_file
from course_grader import grader
from course_grader.course import CourseError


@pytest.fixture(scope="module")
def hw3():
    return course_file.load("me495_hw3")


def test_items_points_and_scenarios(hw3):
    points = {item.id: item.points for item in hw3.items}
    assert points == {"layout": 0.5, "xacro_yaml_gazebo": 1.0, "world_contents": 1.0,
                      "ddrive_paused": 0.5, "flips": 2.0, "arm_test": 1.5,
                      "step_floor_error": 1.5, "step_reachable": 2.0}
    assert hw3.total_points == pytest.approx(10.0)
    assert hw3.packages == ["diff_drive", "arm_move"]
    assert hw3.scenarios() == ["layout", "world", "flip", "arm_test", "step"]


def test_commands_are_what_the_student_types(hw3):
    typed = {key: " ".join(["roslaunch", *hw3.commands[key], *hw3.command_args[key]])
             for key in hw3.commands}
    assert typed == {"ddrive_paused": "roslaunch diff_drive ddrive.launch paused:=true",
                     "ddrive_flip": "roslaunch diff_drive ddrive.launch flip:=true",
                     "arm": "roslaunch arm_move arm.launch"}
    assert hw3.headless_args == {"gui": "false", "rviz": "false"}


def test_every_scenario_has_one_way_to_measure_that_loads(hw3):
    import importlib
    for scenario in hw3.scenarios():
        spec = grader.scenario_spec(hw3, scenario)
        target = spec.probe or spec.runner
        module, _, function = target.partition(":")
        assert callable(getattr(importlib.import_module(module), function)), target
        assert bool(spec.commands) == bool(spec.probe), scenario


def test_rb1_keeps_its_built_in_scenarios():
    rb1 = course_file.load("rb1")
    assert rb1.scenario_specs == {} and rb1.headless_args == {"gui": "false"}
    assert all(args == [] for args in rb1.command_args.values())
    rotate = grader.scenario_spec(rb1, "rotate")
    assert rotate.commands == ("warehouse", "rotate") and rotate.probe == "rotate"
    assert rotate.ready == {"warehouse": "/odom"} and not rotate.display
    assert grader.scenario_spec(rb1, "display").display


BASE = """
name: bad
title: bad
packages: [p]
limits: {build: 1}
commands: {go: [p, go.launch]}
items: [{id: a, task: 1, title: a, guide: "Do a.", points: 1, scenario: s}]
"""


@pytest.mark.parametrize("scenarios, message", [
    ("scenarios: {other: {runner: 'm:f'}}", "scenario 's' .* not under 'scenarios'"),
    ("scenarios: {s: {commands: [go], probe: 'm:f', runner: 'm:g'}}", "exactly one of"),
    ("scenarios: {s: {probe: 'm:f'}}", "probe but no commands"),
    ("scenarios: {s: {commands: [went], probe: 'm:f'}}", r"unknown commands \['went'\]"),
    ("scenarios: {s: {runner: 'm:f', colour: red}}", "unknown keys"),
])
def test_malformed_scenarios_are_named(tmp_path, scenarios, message):
    path = tmp_path / "bad.yaml"
    path.write_text(textwrap.dedent(BASE) + scenarios + "\n")
    with pytest.raises(CourseError, match=message):
        course_file.parse(str(path))


def test_a_runner_that_cannot_be_loaded_is_a_course_error():
    with pytest.raises(CourseError, match="no_such_module:run"):
        grader.call_named("course_grader.no_such_module:run")

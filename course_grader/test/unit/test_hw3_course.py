"""The ME495 homework 3 course file and the grader's hooks for a course that names its
scenarios (no master): items and points, commands as typed, one way to measure each
scenario, malformed scenario sections named; RB1 keeps its built-in scenarios."""
import textwrap

import pytest

from course_grader import course as course_file
from course_grader import grader
from course_grader.course import CourseError
from course_grader.results import Check, Report, judge


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


def item_of(course, item_id):
    return next(item for item in course.items if item.id == item_id)


def test_checks_beyond_the_assignments_sentences_are_notes(hw3):
    layout = judge(item_of(hw3, "layout"), [
        Check("diff_drive's folders", True, "diff_drive has config, urdf, ..."),
        Check("a node in nodes/", False, "no file in diff_drive/nodes that rosrun can run"),
        Check("diff_drive's files", True, "x"), Check("arm_move's files", True, "y")])
    assert layout.awarded == pytest.approx(0.5)
    assert any("not scored" in note and "nodes" in note for note in layout.beyond)
    description = judge(item_of(hw3, "xacro_yaml_gazebo"), [
        Check("a xacro reads a yaml", True, "x"), Check("a .gazebo file the xacro includes",
                                                        True, "y"),
        Check("the robot's xacro expands", True, "z"),
        Check("the diff drive plugin", False, "no libgazebo_ros_diff_drive.so"),
        Check("every drawn link has collision and inertial", False, "wheel lacks inertial")])
    assert description.awarded == pytest.approx(1.0)
    assert len([n for n in description.beyond if "not scored" in n]) == 2


@pytest.mark.parametrize("flips, share", [(5, 1.0), (4, 1.0), (3, 0.75), (2, 0.5), (0, 0.0)])
def test_flips_counted_score_on_the_scale(hw3, flips, share):
    flipped = judge(item_of(hw3, "flips"), [
        Check("flips over", flips >= 4, f"flipped {flips} times", max(0, 4 - flips)),
        Check("keeps driving", True, "travelled 5 m")])
    assert flipped.awarded == pytest.approx(2.0 * (share + 1.0) / 2)


@pytest.mark.parametrize("error, share", [(0.0002, 1.0), (0.01, 1.0), (0.03, 0.5),
                                          (0.05, 0.0), (0.2, 0.0)])
def test_the_gripper_distance_scores_on_the_scale(hw3, error, share):
    reached = judge(item_of(hw3, "step_reachable"), [
        Check("answers SUCCESS", True, "code 1"),
        Check("the gripper ends at the target", error <= 0.01, f"{error} m", error)])
    assert reached.awarded == pytest.approx(2.0 * (share + 1.0) / 2)


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


def broken_runner(course, scenario, context):
    """A runner with a bug of the grader's own."""
    return {"checks": {"a": [context.missing_attribute]}}


def test_an_exception_out_of_a_runner_is_the_platforms_fault(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text(textwrap.dedent(BASE) +
                    "scenarios: {s: {runner: 'test_hw3_course:broken_runner'}}\n")
    course = course_file.parse(str(path))
    context = grader.RunnerContext({}, str(tmp_path), None, str(tmp_path / "log"))
    (result,) = grader.runner_results(course, "s", context)
    assert result.awarded == 0.0 and result.mark == "platform"
    assert "AttributeError" in result.platform and "test_hw3_course.py" in result.platform
    report = Report(course, "x", [result])
    assert report.incomplete and report.possible == 0.0

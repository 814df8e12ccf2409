"""course_grader as a teaching assistant runs it: `rosrun course_grader grade rb1 PATH` on
a copy of the workspace's own RB1 solution (full marks, 10 of 10: it spawns on the taped
square of the course's warehouse, rb1_base_gazebo), its report showing rviz's screenshot
and plots of the measured motion; and, with --only display, a copy whose display.launch
marks the slider node required="true" (the grader pauses that node, never stops it: full
marks, the launch kept running). Copies with one fault each (a rotate service that answers
without turning among them) are graded by test_course_grader_faults.py, from the table in
rb1_fault_fixtures.py."""
import json
import os
import shutil
import sys
import xml.etree.ElementTree as ET

import pytest

import headless

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from grading import grade  # noqa: E402  (beside this file, not a package)
from rb1_fault_fixtures import copy_solution  # noqa: E402

FULL_MARKS = 10.0         # the RB1 guide's points in all (course_grader/config/rb1.yaml)
# rviz's screenshot of our RB1 in display.rviz's view: its dark grey body (rb1_body, 0.15
# grey, shaded and seen through) covers about 55,000 pixels, the view's background
# (110, 120, 135) most of the rest of the 3D view; neither comes near these in a blank or
# robot-less picture
BODY_COLOUR, BODY_PIXELS = "rgb(60,64,72)", 20000
BACKGROUND_COLOUR, BACKGROUND_PIXELS = "rgb(110,120,135)", 100000
PLOT_POINTS = 20          # a plot of measured motion draws at least this many samples
SVG = "{http://www.w3.org/2000/svg}"
SLIDER_NODE = 'type="joint_state_publisher_gui"/>'


@pytest.fixture(scope="module")
def graded_solution(repo, tmp_path_factory):
    folder = tmp_path_factory.mktemp("grade_solution")
    submission = copy_solution(repo, str(folder / "submission"))
    results = os.path.join(repo, "test_results", "e2e", "course_grader", "solution")
    shutil.rmtree(results, ignore_errors=True)
    return (submission,) + grade("rb1", submission, results, "--scenario-jobs", "2") \
        + (results,)


def test_our_solution_gets_full_marks(graded_solution):
    submission, items, stdout, seconds, _ = graded_solution
    print(f"grading our RB1 solution took {seconds:.0f} s")
    for item in items.values():
        assert item["awarded"] == item["points"], item
    assert sum(item["awarded"] for item in items.values()) == FULL_MARKS
    # the note says the course's warehouse is the world loaded (its models by name)
    assert any(note.startswith("the course's warehouse") and note.endswith("is loaded")
               for note in items["spawn_in_start_square"]["notes"]), items
    assert "grade: report written:" in stdout
    # odometry use judged by behaviour: the robot geared down still turned the angle asked
    odometry = items["rotate_uses_odom"]
    assert "turns by odometry" in odometry["evidence"] and not odometry["mark"], odometry


def test_build_is_overlaid_on_the_platform_only(graded_solution, repo):
    submission, items, stdout, _, _ = graded_solution
    assert "catkin_make: ok" in stdout
    assert "resolves to" not in stdout      # every my_rb1_* package is the submission's


def plotted_points(path):
    """The points of every polyline of an SVG plot."""
    root = ET.parse(path).getroot()
    return sum(len(line.get("points").split()) for line in root.iter(f"{SVG}polyline"))


def test_the_report_shows_rviz_and_the_measured_motion(graded_solution):
    *_, out = graded_solution
    picture = os.path.join(out, "display.png")
    assert os.path.isfile(picture), "no rviz screenshot"
    assert not headless.uniform(picture)
    body = headless.pixels_near(picture, BODY_COLOUR, "10%")
    background = headless.pixels_near(picture, BACKGROUND_COLOUR, "5%")
    print(f"display.png: {body} body-coloured pixels, {background} of the view's background")
    assert body > BODY_PIXELS and background > BACKGROUND_PIXELS
    for plot in ("drive.svg", "rotate.svg"):
        points = plotted_points(os.path.join(out, plot))
        print(f"{plot}: {points} points")
        assert points >= PLOT_POINTS, plot
    with open(os.path.join(out, "report.md"), encoding="utf-8") as stream:
        text = stream.read()
    for embedded in ("](display.png)", "](drive.svg)", "](rotate.svg)"):
        assert embedded in text
    with open(os.path.join(out, "report.json"), encoding="utf-8") as stream:
        listed = [f["file"] for f in json.load(stream)["figures"] if f["file"]]
    assert sorted(listed) == ["display.png", "drive.svg", "rotate.svg"]


def test_a_required_slider_node_is_paused_not_stopped(repo, tmp_path):
    submission = copy_solution(repo, str(tmp_path / "submission"))
    launch = os.path.join(submission, "my_rb1_description", "launch", "display.launch")
    with open(launch, encoding="utf-8") as stream:
        text = stream.read()
    assert text.count(SLIDER_NODE) == 1, "the line the fixture changes is no longer there"
    with open(launch, "w", encoding="utf-8") as stream:
        stream.write(text.replace(SLIDER_NODE, SLIDER_NODE[:-2] + ' required="true"/>'))
    out = os.path.join(repo, "test_results", "e2e", "course_grader", "required_sliders")
    shutil.rmtree(out, ignore_errors=True)
    items, _, seconds = grade("rb1", submission, out, "--only", "display")
    print(f"grading display with a required slider node took {seconds:.0f} s")
    assert set(items) == {"display_links_tf", "wheel_joints_move"}
    for item in items.values():
        assert item["awarded"] == item["points"], item
    wheels = items["wheel_joints_move"]
    assert "/joint_state_publisher_gui" in wheels["evidence"]
    assert any("paused (SIGSTOP)" in note and "resumed" in note for note in wheels["notes"])
    with open(os.path.join(out, "logs", "display", "display.log"), encoding="utf-8") as log:
        launch_log = log.read()
    # a slider node shut down by the grader complains on its way out, and a required one
    # that ends takes the launch with it
    for sign in ("closed topic", "process has died", "process has finished",
                 "Initiating shutdown"):
        assert sign not in launch_log, sign

"""course_grader as a teaching assistant runs it: `rosrun course_grader grade rb1 PATH` on
a copy of the workspace's own RB1 solution (full marks, 10 of 10: it spawns on the taped
square of the course's warehouse, rb1_base_gazebo), and on a copy whose rotate service
answers success at once without turning (it loses exactly task 4's 'turns by the requested
degrees' and 'answers success when done')."""
import json
import os
import shutil
import subprocess
import time

import pytest

RB1_PACKAGES = ("my_rb1_description", "my_rb1_gazebo", "my_rb1_ros")
GRADE_TIMEOUT = 600       # s: the whole grading of one submission, bounded
# the one line changed in the faulty fixture: the service answers without turning
TURN_LINE = "            return self._turn_by(degrees, start, watch)\n"
LIE_LINE = "            return f\"success: rotated {degrees} degrees\"\n"
ROTATE_FAULT_ITEMS = {"rotate_degrees", "rotate_answers_success"}
FULL_MARKS = 10.0         # the RB1 guide's points in all (course_grader/config/rb1.yaml)


def copy_solution(repo, folder):
    os.makedirs(folder)
    for package in RB1_PACKAGES:
        shutil.copytree(os.path.join(repo, package), os.path.join(folder, package),
                        ignore=shutil.ignore_patterns("__pycache__", "test"))
    return folder


def grade(ros_env, submission, out):
    started = time.monotonic()
    done = subprocess.run(["rosrun", "course_grader", "grade", "rb1", submission, "--out", out],
                          env=ros_env, capture_output=True, text=True, timeout=GRADE_TIMEOUT,
                          check=False)
    seconds = time.monotonic() - started
    with open(os.path.join(out, "grade.log"), "w", encoding="utf-8") as log:
        log.write(done.stdout + done.stderr)
    assert done.returncode == 0, done.stdout + done.stderr
    with open(os.path.join(out, "report.json"), encoding="utf-8") as stream:
        report = json.load(stream)
    assert os.path.isfile(os.path.join(out, "report.md"))
    return {item["id"]: item for item in report["items"]}, done.stdout, seconds


@pytest.fixture(scope="module")
def graded_solution(repo, tmp_path_factory):
    folder = tmp_path_factory.mktemp("grade_solution")
    submission = copy_solution(repo, str(folder / "submission"))
    results = os.path.join(repo, "test_results", "e2e", "course_grader", "solution")
    shutil.rmtree(results, ignore_errors=True)
    return (submission,) + grade(os.environ.copy(), submission, results)


def test_our_solution_gets_full_marks(graded_solution):
    submission, items, stdout, seconds = graded_solution
    print(f"grading our RB1 solution took {seconds:.0f} s")
    for item in items.values():
        assert item["awarded"] == item["points"], item
    assert sum(item["awarded"] for item in items.values()) == FULL_MARKS
    assert "grade: report written:" in stdout


def test_build_is_overlaid_on_the_platform_only(graded_solution, repo):
    submission, items, stdout, _ = graded_solution
    assert "catkin_make: ok" in stdout
    assert "resolves to" not in stdout      # every my_rb1_* package is the submission's


def test_a_service_that_does_not_turn_loses_exactly_its_two_items(repo, tmp_path,
                                                                  graded_solution):
    submission = copy_solution(repo, str(tmp_path / "submission"))
    node = os.path.join(submission, "my_rb1_ros", "src", "my_rb1_ros", "rotate_service.py")
    with open(node, encoding="utf-8") as stream:
        lines = stream.readlines()
    assert lines.count(TURN_LINE) == 1, "the line the fixture changes is no longer there"
    lines[lines.index(TURN_LINE)] = LIE_LINE
    with open(node, "w", encoding="utf-8") as stream:
        stream.writelines(lines)
    results = os.path.join(repo, "test_results", "e2e", "course_grader", "rotate_lies")
    shutil.rmtree(results, ignore_errors=True)
    faulty, _, _ = grade(os.environ.copy(), submission, results)
    ours = graded_solution[1]
    lost = {item_id for item_id, item in faulty.items()
            if item["awarded"] < ours[item_id]["awarded"]}
    assert lost == ROTATE_FAULT_ITEMS, {i: faulty[i]["evidence"] for i in faulty}
    assert "turned +0.0" in faulty["rotate_degrees"]["evidence"] or \
        "turned -0.0" in faulty["rotate_degrees"]["evidence"], faulty["rotate_degrees"]

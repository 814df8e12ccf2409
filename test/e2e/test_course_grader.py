"""course_grader as a teaching assistant runs it: `rosrun course_grader grade rb1 PATH` on
a copy of the workspace's own RB1 solution (full marks, 10 of 10: it spawns on the taped
square of the course's warehouse, rb1_base_gazebo). Copies with one fault each (a rotate
service that answers without turning among them) are graded by
test_course_grader_faults.py, from the table in rb1_fault_fixtures.py."""
import json
import os
import shutil
import subprocess
import sys
import time

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rb1_fault_fixtures import copy_solution  # noqa: E402  (beside this file, not a package)

GRADE_TIMEOUT = 600       # s: the whole grading of one submission, bounded
FULL_MARKS = 10.0         # the RB1 guide's points in all (course_grader/config/rb1.yaml)


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
    # the note says the course's warehouse is the world loaded (its models by name)
    assert any(note.startswith("the course's warehouse") and note.endswith("is loaded")
               for note in items["spawn_in_start_square"]["notes"]), items
    assert "grade: report written:" in stdout


def test_build_is_overlaid_on_the_platform_only(graded_solution, repo):
    submission, items, stdout, _ = graded_solution
    assert "catkin_make: ok" in stdout
    assert "resolves to" not in stdout      # every my_rb1_* package is the submission's

"""course_grader on faulty RB1 submissions (test/e2e/rb1_fault_fixtures.py): each fixture is
a copy of our solution with one fault, graded as a teaching assistant runs it,
``rosrun course_grader grade rb1 PATH --out DIR --only <the scenarios its fault touches>``;
the items it loses must be exactly the table's (our solution, the baseline, scores full
marks: test_course_grader.py), each with the figure measured. The C++ rotate service scores full marks; the submission that does
not build scores 0 everywhere with its build error as the evidence; the hanging node is killed
at the scenario limit and the scenario after it is graded as usual."""
import json
import os
import shutil
import subprocess
import sys
import time

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import rb1_fault_fixtures as fixtures  # noqa: E402  (beside this file, not a package)

GRADE_TIMEOUT = 600       # s: the whole grading of one submission, bounded
STOP_LIMIT_SLACK = 15.0   # s past limit + stop within which a killed scenario must have ended
RESULTS = ("test_results", "e2e", "course_grader")


def grade(submission, out, scenarios, scenario_limit=None):
    shutil.rmtree(out, ignore_errors=True)
    command = ["rosrun", "course_grader", "grade", "rb1", submission, "--out", out,
               "--only", *scenarios]
    if scenario_limit is not None:
        command += ["--scenario-limit", str(scenario_limit)]
    started = time.monotonic()
    done = subprocess.run(command, capture_output=True, text=True, timeout=GRADE_TIMEOUT,
                          check=False)
    seconds = time.monotonic() - started
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "grade.log"), "w", encoding="utf-8") as log:
        log.write(done.stdout + done.stderr)
    assert done.returncode == 0, done.stdout + done.stderr
    with open(os.path.join(out, "report.json"), encoding="utf-8") as stream:
        report = json.load(stream)
    return {item["id"]: item for item in report["items"]}, seconds


def lost(items):
    return {item_id for item_id, item in items.items() if item["awarded"] < item["points"]}


def evidence(items):
    return "\n".join(f"  {i}: {item['awarded']:g}/{item['points']:g}  {item['evidence']}"
                     for i, item in sorted(items.items()))


@pytest.mark.parametrize("name", list(fixtures.FAULTS))
def test_a_fault_loses_exactly_its_items(name, repo, tmp_path):
    fault = fixtures.FAULTS[name]
    submission = fixtures.make_fixture(repo, name, str(tmp_path / "submission"))
    out = os.path.join(repo, *RESULTS, f"fault_{name}")
    items, seconds = grade(submission, out, fault.scenarios, fault.scenario_limit)
    print(f"{name}: {fault.what}; graded --only {' '.join(fault.scenarios)} in {seconds:.0f} s")
    print(evidence(items))
    assert set(items) == {i for i in fixtures.ALL_ITEMS
                          if any(i in scenario_items(s) for s in fault.scenarios)}
    assert lost(items) == set(fault.lost), evidence(items)
    CHECKS.get(name, lambda items, out: None)(items, out)


def scenario_items(scenario):
    from course_grader import course as course_file
    return {item.id for item in course_file.load("rb1").items_of(scenario)}


# --- what each fault's evidence must show -------------------------------------------------


def _laser(items, out):
    assert "laser roll 0.0 deg (guide 180)" in items["display_links_tf"]["evidence"]


def _spawn(items, out):
    assert "at (0.0" in items["spawn_in_start_square"]["evidence"] or \
        "at (-0.0" in items["spawn_in_start_square"]["evidence"], items["spawn_in_start_square"]


def _wheels(items, out):
    text = items["display_links_tf"]["evidence"]
    assert "right_wheel at (0.05, -0.2, -0.15) m" in text and "left_wheel at (0.05, 0.2" in text


def _mass(items, out):
    assert "29 kg in all (guide 25)" in items["display_links_tf"]["evidence"]


def _by_time(items, out):
    assert "is not among the subscribers of /odom" in items["rotate_uses_odom"]["evidence"]


def _early(items, out):
    text = items["rotate_degrees"]["evidence"]
    assert "turned +0.0" in text or "turned -0.0" in text, text


def _wraps(items, out):
    text = items["rotate_degrees"]["evidence"]
    assert "asked -90 deg, turned -9" in text or "asked -90 deg, turned -8" in text, text
    assert "asked +270 deg, turned -9" in text or "asked +270 deg, turned -8" in text, text


def _radians(items, out):
    assert "failure" in items["rotate_answers_success"]["evidence"]


def _no_success(items, out):
    assert "answer 'rotated -90 degrees" in items["rotate_answers_success"]["evidence"]


def _no_build(items, out):
    for item in items.values():
        assert item["awarded"] == 0
        assert "catkin_make failed" in item["evidence"], item
        assert "Cannot locate message [in32]" in item["evidence"], item


def _hangs(items, out):
    limit = fixtures.FAULTS["node_hangs"].scenario_limit
    rotate = items["rotate_degrees"]
    assert "did not finish within" in rotate["evidence"], rotate
    from course_grader import course as course_file
    stop = course_file.load("rb1").limits["stop"]
    assert limit <= rotate["seconds"] <= limit + stop + STOP_LIMIT_SLACK, rotate["seconds"]
    left = [pid for pid in os.listdir("/proc") if pid.isdigit() and _cmdline_has(pid, out)]
    assert not left, f"processes of the hung scenario still running: {left}"


def _cmdline_has(pid, text):
    try:
        with open(f"/proc/{pid}/cmdline", "rb") as stream:
            return text.encode() in stream.read()
    except OSError:
        return False


CHECKS = {"laser_not_upside_down": _laser, "spawned_outside_square": _spawn,
          "wheels_misplaced": _wheels, "mass_not_25kg": _mass, "rotate_by_time": _by_time,
          "answers_before_turning": _early, "turn_wraps_at_180": _wraps,
          "degrees_as_radians": _radians, "no_success_message": _no_success,
          "does_not_build": _no_build, "node_hangs": _hangs}

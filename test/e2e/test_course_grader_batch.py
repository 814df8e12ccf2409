"""course_grader's batch as a teaching assistant runs it: six fault fixtures (rb1_fault_fixtures)
graded by one command, `rosrun course_grader grade rb1 DIR/* --jobs 2 --only ... --csv ...`:
it finishes, and the CSV's scores are the one-at-a-time scores the fixture table gives (each
fixture loses exactly its fault's items). One fixture's rotate service hangs and ignores
SIGINT and SIGTERM: its scenario is killed at the scenario limit and it keeps its other
items, while the others, graded beside it, are unaffected; one does not build (0 on every
item graded). No process of the batch is left running afterwards."""
import csv
import os
import shutil
import subprocess
import time

import pytest
from course_grader import course as course_file

from rb1_fault_fixtures import FAULTS, make_fixture

# Six fixtures the rotate scenario alone grades (each scenario run costs every submission its
# time; the guide's turns take about 35 s on two busy cores): three faults of the rotate
# service that turn less than asked, the C++ service (full marks), a hang and a build failure
FIXTURES = ("answers_before_turning", "no_success_message", "turn_wraps_at_180",
            "cpp_rotate_service", "does_not_build", "node_hangs")
ONLY = ("rotate",)
# s: each scenario's limit in this batch. The hanging fixture's rotate scenario is stopped at
# it; the others' took at most 37 s on two busy cores
SCENARIO_LIMIT = 60.0
BATCH_TIMEOUT = 900       # s: the whole command, bounded
JOBS = 2
MARKER = "COURSE_GRADER_BATCH="


def batch_processes():
    """Processes carrying any batch's marker (the test holds /tmp/sim.lock: no other batch)."""
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/environ", "rb") as environ:
                if any(v.startswith(MARKER.encode()) for v in environ.read().split(b"\0")):
                    found.append(int(entry))
        except OSError:
            continue
    return found


@pytest.fixture(scope="module")
def batch_run(repo, tmp_path_factory):
    folder = tmp_path_factory.mktemp("batch")
    submissions = [make_fixture(repo, name, str(folder / "submissions" / name))
                   for name in FIXTURES]
    out = os.path.join(repo, "test_results", "e2e", "course_grader", "batch")
    shutil.rmtree(out, ignore_errors=True)
    csv_path = os.path.join(out, "scores.csv")
    command = ["rosrun", "course_grader", "grade", "rb1", *submissions, "--jobs", str(JOBS),
               "--only", *ONLY, "--scenario-limit", str(SCENARIO_LIMIT), "--out", out,
               "--csv", csv_path]
    started = time.monotonic()
    done = subprocess.run(command, capture_output=True, text=True, timeout=BATCH_TIMEOUT,
                          check=False)
    seconds = time.monotonic() - started
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "batch.log"), "w", encoding="utf-8") as log:
        log.write(done.stdout + done.stderr)
    assert done.returncode == 0, done.stdout + done.stderr
    with open(csv_path, encoding="utf-8", newline="") as stream:
        rows = {row["name"]: row for row in csv.DictReader(stream)}
    return rows, done.stdout, seconds


def expected_scores(course_items, name):
    """The one-at-a-time scores the fixture table gives: every item of the scenarios run at
    full points but the fault's lost items, 0."""
    lost = FAULTS[name].lost
    return {item.id: 0.0 if item.id in lost else item.points
            for item in course_items if item.scenario in ONLY}


def test_six_fixtures_in_one_batch_score_as_one_at_a_time(batch_run):
    rows, stdout, seconds = batch_run
    items = course_file.load("rb1").items
    print(f"batch of {len(FIXTURES)} with --jobs {JOBS}: {seconds:.0f} s; each: " +
          ", ".join(f"{name} {float(rows[name]['seconds']):.0f} s" for name in FIXTURES))
    assert sorted(rows) == sorted(FIXTURES)
    for name in FIXTURES:
        row = rows[name]
        awarded = {item.id: float(row[item.id]) for item in items if row[item.id] != ""}
        assert awarded == expected_scores(items, name), (name, row)
        assert row["status"] == "graded", row
        assert float(row["total"]) == pytest.approx(sum(awarded.values()))
    # items of scenarios not run are empty cells, not zeros
    assert all(rows[name][item.id] == "" for name in FIXTURES for item in items
               if item.scenario not in ONLY)
    # in parallel: the batch took less than its submissions one after the other
    assert seconds < sum(float(rows[name]["seconds"]) for name in FIXTURES)


def test_the_hung_and_the_unbuilt_are_explained_and_nothing_is_left_running(batch_run, repo):
    rows, stdout, _ = batch_run
    hung = rows["node_hangs"]
    assert float(hung["seconds"]) >= SCENARIO_LIMIT, hung
    assert f"{hung['name']}: " in stdout
    report = os.path.join(repo, "test_results", "e2e", "course_grader", "batch", "node_hangs",
                          "report.md")
    with open(report, encoding="utf-8") as stream:
        assert "the checks did not finish within" in stream.read()
    with open(os.path.join(repo, "test_results", "e2e", "course_grader", "batch",
                           "does_not_build", "report.md"), encoding="utf-8") as stream:
        assert "catkin_make failed" in stream.read()
    assert batch_processes() == []

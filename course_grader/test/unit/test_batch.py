"""course_grader.batch without a master: shards cover every path exactly once, folder
names, the CSV's columns and rows, options passed on to each child, and the child runner:
a hung child (and the process it started in a session of its own) is killed at its limit
and reported, while a sibling running beside it is graded."""
import csv
import json
import os
import subprocess
import sys
import textwrap
import time

import pytest
import yaml

from course_grader import batch, cli
from course_grader import course as course_file
from course_grader import report
from course_grader.results import Check, Report, judge

EXAMPLE = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))), "examples", "grade-matrix.yml")
PATHS = ["subs/zoe", "subs/adam/", "subs/mia", "other/adam", "subs/bob", "subs/carl",
         "subs/dina", "./subs/eve"]
HUNG_LIMIT = 3.0     # s: the runner's limit in the test; the sibling ends well within it
STOP_TIMEOUT = 5.0   # s: the longest the runner may take to see a killed process gone


@pytest.fixture(scope="module")
def rb1():
    return course_file.load("rb1")


@pytest.mark.parametrize("count", [1, 2, 3, 5, 8, 11])
def test_shards_cover_every_path_exactly_once(count):
    shards = [batch.select_shard(PATHS, index, count) for index in range(1, count + 1)]
    every = [path for shard in shards for path in shard]
    assert sorted(every) == batch.ordered(PATHS)
    assert len(every) == len(set(every)) == len(set(os.path.normpath(p) for p in PATHS))
    # the same shards whatever order the shell gave the paths in
    assert shards == [batch.select_shard(list(reversed(PATHS)), index, count)
                      for index in range(1, count + 1)]


def test_shard_option_is_one_based_and_checked():
    assert batch.parse_shard("2/4") == (2, 4)
    assert batch.select_shard(["a", "b", "c", "d", "e"], 2, 2) == ["b", "d"]
    for bad in ("0/3", "4/3", "1/0", "a/b", "3", "1/2/3"):
        with pytest.raises(batch.BatchError, match="--shard"):
            batch.parse_shard(bad)


def test_folder_names_are_unique_and_do_not_depend_on_the_shard():
    names = batch.names(PATHS)
    assert len(set(names.values())) == len(names) == len(batch.ordered(PATHS))
    assert names["other/adam"] == "adam" and names["subs/adam"] == "adam-2"
    assert names["subs/eve"] == "eve"


def test_limit_comes_from_the_course_limits(rb1):
    per_scenario = rb1.limits["scenario"] + rb1.limits["stop"]
    assert batch.submission_limit(rb1) == rb1.limits["build"] + 5 * per_scenario
    assert batch.submission_limit(rb1, ["rotate"]) == rb1.limits["build"] + per_scenario


def test_only_batch_options_stay_with_the_batch(rb1):
    parser = cli.build_parser()
    args = parser.parse_args(["rb1", "a", "b", "--only", "rotate", "scan", "--jobs", "2",
                              "--shard", "1/2", "--csv", "s.csv", "--out", "o", "--limit", "9"])
    assert batch.wanted(args)
    assert batch.forwarded_options(parser, args) == ["--only", "rotate", "scan"]
    command = batch.child_command(rb1, "a", "o/a", batch.forwarded_options(parser, args))
    assert command[1:] == ["-m", "course_grader", "rb1", "a", "--out", "o/a",
                           "--only", "rotate", "scan"]
    one = parser.parse_args(["rb1", "a", "--only", "rotate"])
    assert not batch.wanted(one)            # one path: today's command, unchanged
    assert batch.wanted(parser.parse_args(["rb1", "a", "--shard", "1/3"]))


def test_bad_jobs_and_limit_are_named():
    with pytest.raises(batch.BatchError, match="--jobs 0"):
        batch.Runner(0, 10.0, 1.0)
    with pytest.raises(batch.BatchError, match="--limit"):
        batch.Runner(1, 0.0, 1.0)


def rows(path):
    with open(path, encoding="utf-8", newline="") as stream:
        return list(csv.reader(stream))


def test_csv_columns_and_rows(rb1, tmp_path):
    ids = [item.id for item in rb1.items]
    full = batch.Outcome("subs/a", "a", "graded", {i: item.points for i, item in
                                                   zip(ids, rb1.items)}, rb1.total_points, 41.26)
    only = batch.Outcome("subs/b", "b", "graded", {"rotate_degrees": 1.6, "rotate_uses_odom": 1.0,
                                                   "rotate_answers_success": 0.0}, 4.0, 15.0,
                         marks={"rotate_degrees": "review"})
    killed = batch.Outcome("subs/c", "c", expected={"scan_readable": 0.75}, seconds=950.0)
    killed.zero("killed", "still running after ...")
    path = str(tmp_path / "out" / "scores.csv")
    batch.write_csv(path, rb1, [full, only, killed])
    header, *body = rows(path)
    assert header == ["path", "name", *ids, "total", "possible", "seconds", "status", "review",
                      "platform", "reason"]
    assert body[0] == ["subs/a", "a", "2.25", "0.75", "1.5", "0.75", "0.75", "2", "1", "1",
                       "10", "10", "41.3", "graded", "", "", ""]
    assert body[1][2:7] == ["", "", "", "", ""]          # not graded (--only): empty, not 0
    assert body[1][7:12] == ["1.6", "1", "0", "2.6", "4"]
    assert body[1][13:16] == ["graded", "rotate_degrees", ""]   # marked for review
    assert body[2][2:10] == ["", "", "", "", "0", "", "", ""]
    assert body[2][10:] == ["0", "0.75", "950.0", "killed", "", "", "still running after ..."]


def test_the_class_distribution_flags_an_item_nobody_passes(rb1):
    full = {item.id: item.points for item in rb1.items}
    outcomes = [batch.Outcome(f"s/{n}", n, "graded", dict(full, spawn_in_start_square=0.0,
                                                         rotate_degrees=points), 10.0)
                for n, points in (("a", 2.0), ("b", 1.5), ("c", 0.0))]
    outcomes[1].marks = {"rotate_degrees": "review"}
    table = batch.distribution(rb1, outcomes).splitlines()
    (rotate,) = [line for line in table if line.startswith("rotate_degrees")]
    assert rotate.split()[1:8] == ["2", "1", "1", "1", "1.17", "1", "0"]
    (spawn,) = [line for line in table if line.startswith("spawn_in_start_square")]
    assert spawn.split()[2:5] == ["0", "0", "3"] and "nobody has full marks" in spawn


def test_an_item_the_platform_kept_from_grading_is_no_zero_of_the_class(rb1):
    """A submission whose build stopped at a package the platform lacks has every item
    marked platform: counted apart, not among the class's no-marks, not in the mean."""
    full = {item.id: item.points for item in rb1.items}
    outcomes = [batch.Outcome("s/a", "a", "graded", dict(full), 10.0),
                batch.Outcome("s/b", "b", "graded", dict(full, rotate_degrees=1.0), 10.0),
                batch.Outcome("s/c", "c", "incomplete", {i: 0.0 for i in full}, 2.0)]
    outcomes[2].marks = {i: "platform" for i in full}
    table = batch.distribution(rb1, outcomes).splitlines()
    (rotate,) = [line for line in table if line.startswith("rotate_degrees")]
    assert rotate.split()[1:8] == ["2", "1", "1", "0", "1.50", "0", "1"]
    only = [batch.Outcome("s/c", "c", "incomplete", {i: 0.0 for i in full}, 2.0)]
    only[0].marks = {i: "platform" for i in full}
    (rotate,) = [line for line in batch.distribution(rb1, only).splitlines()
                 if line.startswith("rotate_degrees")]
    assert rotate.split()[1:8] == ["2", "0", "0", "0", "-", "0", "1"]


def test_outcome_read_from_the_child(rb1, tmp_path):
    out = tmp_path / "a"
    results = [judge(item, [Check("c", index != 0, "m")]) for index, item in enumerate(rb1.items)]
    report.write(Report(rb1, "/s/a", results, seconds=30.0), str(out))
    log = tmp_path / "grade.log"
    log.write_text("grade: staged\nTraceback (most recent call last):\nKeyError: 'x'\n")
    graded = batch.Outcome("s/a", "a")
    batch.read_outcome(graded, str(out), 0, str(log))
    assert graded.status == "graded"
    assert graded.total == pytest.approx(rb1.total_points - rb1.items[0].points)
    assert graded.awarded[rb1.items[0].id] == 0.0
    expected = {item.id: item.points for item in rb1.items}
    crashed = batch.Outcome("s/a", "a", expected=expected)
    batch.read_outcome(crashed, str(out), 1, str(log))
    assert crashed.status == "crashed" and crashed.total == 0
    assert crashed.awarded == {item.id: 0.0 for item in rb1.items}
    assert crashed.possible == pytest.approx(rb1.total_points)
    assert "exit status 1" in crashed.reason and "KeyError: 'x'" in crashed.reason
    refused = batch.Outcome("s/a", "a")
    batch.read_outcome(refused, str(out), batch.REFUSED_STATUS, str(log))
    assert refused.status == "refused" and "KeyError" in refused.reason


# A child that starts a process in a session of its own (as the grader starts roscore and
# roslaunch), says so in a file, and then waits forever.
HUNG = textwrap.dedent("""
    import os, subprocess, sys, threading
    sleeper = subprocess.Popen([sys.executable, "-c", "import threading; threading.Event().wait()"],
                               start_new_session=True)
    with open(sys.argv[1], "w") as ready:
        ready.write(str(sleeper.pid))
    threading.Event().wait()
""")
# A child that waits (bounded) until the hung one is running beside it, then writes a report.
SIBLING = textwrap.dedent("""
    import json, os, sys, time
    ready, out = sys.argv[1], sys.argv[2]
    deadline = time.monotonic() + float(sys.argv[3])
    while not os.path.exists(ready) and time.monotonic() < deadline:
        time.sleep(0.05)
    with open(os.path.join(out, "report.json"), "w") as report:
        json.dump({"possible": 1.0, "items": [{"id": "scan_readable", "awarded": 0.75}],
                   "ran_beside_the_hung_one": os.path.exists(ready)}, report)
""")


def alive(pid):
    try:
        with open(f"/proc/{pid}/stat", encoding="utf-8") as stat:
            return stat.read().rsplit(")", 1)[1].split()[0] not in ("Z", "X")
    except OSError:
        return False


def dies(pid, limit=5.0):
    """Whether ``pid`` is gone within ``limit`` s: a process SIGKILLed a moment ago may
    still be exiting (seen once in the unit tier, the machine busy)."""
    deadline = time.monotonic() + limit
    while alive(pid):
        if time.monotonic() > deadline:
            return False
        time.sleep(0.02)
    return True


def test_a_hung_child_is_killed_with_what_it_started_and_its_sibling_is_graded(tmp_path):
    ready = str(tmp_path / "hung_ready")
    hung_out, sibling_out = str(tmp_path / "hung"), str(tmp_path / "sibling")
    env = dict(os.environ)
    tasks = [(batch.Outcome("subs/hung", "hung", expected={"scan_readable": 0.75}),
              [sys.executable, "-c", HUNG, ready],
              hung_out, env),
             (batch.Outcome("subs/sibling", "sibling"),
              [sys.executable, "-c", SIBLING, ready, sibling_out, str(HUNG_LIMIT)],
              sibling_out, env)]
    lines = []
    runner = batch.Runner(2, HUNG_LIMIT, STOP_TIMEOUT, lines.append)
    hung, sibling = runner.run(tasks)
    assert hung.status == "killed" and hung.awarded == {"scan_readable": 0.0}, hung
    assert f"limit of {HUNG_LIMIT:.0f} s" in hung.reason and "1 process(es)" in hung.reason
    assert hung.seconds >= HUNG_LIMIT
    with open(ready, encoding="utf-8") as stream:
        grandchild = int(stream.read())
    assert dies(grandchild), "the process the hung child started in its own session lives"
    assert not batch.marked(f"{runner.tag}-0") and not batch.marked(f"{runner.tag}-1")
    assert sibling.status == "graded" and sibling.total == 0.75, sibling
    with open(os.path.join(sibling_out, "report.json"), encoding="utf-8") as stream:
        assert json.load(stream)["ran_beside_the_hung_one"]
    assert sibling.seconds < HUNG_LIMIT
    assert any("hung: 0 of 0.75, killed" in line for line in lines), lines


def test_the_example_workflow_shards_cover_one_to_n():
    with open(EXAMPLE, encoding="utf-8") as stream:
        workflow = yaml.safe_load(stream)
    grade = workflow["jobs"]["grade"]
    shards = grade["strategy"]["matrix"]["shard"]
    count = int(workflow["env"]["SHARDS"])
    assert shards == list(range(1, count + 1))
    assert grade["strategy"]["fail-fast"] is False   # one shard's trouble stops no other
    run = " ".join(step.get("run", "") for step in grade["steps"])
    assert "--shard ${{ matrix.shard }}/${{ env.SHARDS }}" in run and "--csv" in run
    assert workflow["jobs"]["scores"]["needs"] == "grade"


def test_the_example_workflow_joins_the_shards_csvs(rb1, tmp_path):
    with open(EXAMPLE, encoding="utf-8") as stream:
        workflow = yaml.safe_load(stream)
    join = next(step["run"] for step in workflow["jobs"]["scores"]["steps"] if "run" in step)
    outcomes = [batch.Outcome(f"submissions/s{n}", f"s{n}", "graded", {"scan_readable": 0.75},
                              0.75, 9.0) for n in range(3)]
    for shard, part in ((1, outcomes[:2]), (2, outcomes[2:])):
        batch.write_csv(str(tmp_path / "grades" / f"grades-{shard}" / f"scores-{shard}.csv"),
                        rb1, part)
    subprocess.run(["bash", "-c", join], cwd=tmp_path, check=True)
    header, *body = rows(str(tmp_path / "scores.csv"))
    assert header == batch.csv_header(rb1)
    assert [row[1] for row in body] == ["s0", "s1", "s2"]

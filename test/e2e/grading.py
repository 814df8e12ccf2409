"""The grader run as a teaching assistant runs it, for the workspace-level tests:
``rosrun course_grader grade COURSE SUBMISSION --out OUT [options]``, bounded in time, its
output kept as OUT/grade.log, and the items of its report.json by id; and a class at once
(``grade_batch``: several submissions, its CSV's rows and each one's report)."""
import csv
import json
import os
import shutil
import subprocess
import time

GRADE_TIMEOUT = 600       # s: the whole grading of one submission, bounded
BATCH_TIMEOUT = 900       # s: one batch command, bounded


def grade(course, submission, out, *options):
    """Grades ``submission`` into ``out`` (asserting the grader graded it and wrote both
    reports); (items by id, the grader's stdout, seconds it took)."""
    started = time.monotonic()
    done = subprocess.run(["rosrun", "course_grader", "grade", course, submission,
                           "--out", out, *options], capture_output=True, text=True,
                          timeout=GRADE_TIMEOUT, check=False)
    seconds = time.monotonic() - started
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "grade.log"), "w", encoding="utf-8") as log:
        log.write(done.stdout + done.stderr)
    assert done.returncode == 0, done.stdout + done.stderr
    with open(os.path.join(out, "report.json"), encoding="utf-8") as stream:
        report = json.load(stream)
    assert os.path.isfile(os.path.join(out, "report.md"))
    return {item["id"]: item for item in report["items"]}, done.stdout, seconds


class Batch:
    """One batch command (``grade COURSE SUBMISSIONS... --out OUT --csv OUT/scores.csv
    [options]``) run to its end: its stdout, wall seconds, the CSV's rows and each
    submission's report items, by the submission's folder name."""

    def __init__(self, course, submissions, out, *options, timeout=BATCH_TIMEOUT):
        shutil.rmtree(out, ignore_errors=True)
        csv_path = os.path.join(out, "scores.csv")
        started = time.monotonic()
        done = subprocess.run(["rosrun", "course_grader", "grade", course, *submissions,
                               "--out", out, "--csv", csv_path, *options],
                              capture_output=True, text=True, timeout=timeout,
                              check=False)
        self.seconds = time.monotonic() - started
        self.out, self.stdout = out, done.stdout
        os.makedirs(out, exist_ok=True)
        with open(os.path.join(out, "batch.log"), "w", encoding="utf-8") as log:
            log.write(done.stdout + done.stderr)
        assert done.returncode == 0, done.stdout + done.stderr
        with open(csv_path, encoding="utf-8", newline="") as stream:
            self.rows = {row["name"]: row for row in csv.DictReader(stream)}

    def items(self, name):
        with open(os.path.join(self.out, name, "report.json"), encoding="utf-8") as stream:
            return {item["id"]: item for item in json.load(stream)["items"]}

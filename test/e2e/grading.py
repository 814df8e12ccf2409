"""The grader run as a teaching assistant runs it, for the workspace-level tests:
``rosrun course_grader grade COURSE SUBMISSION --out OUT [options]``, bounded in time, its
output kept as OUT/grade.log, and the items of its report.json by id."""
import json
import os
import subprocess
import time

GRADE_TIMEOUT = 600       # s: the whole grading of one submission, bounded


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

"""ME495 homework 3's own test, run as the homework says: ``catkin_make run_tests`` in the
submission's workspace runs arm_move's ``arm.test`` (a rostest: it starts its own master on
a free port), and its JUnit result says whether it passed. Only arm_move's tests are run
(the ``run_tests_arm_move`` target), so the other packages' tests cost nothing here."""
from __future__ import annotations

import glob
import os
import subprocess
import time
import xml.etree.ElementTree as ET
from typing import Dict, List, Optional, Tuple

from course_grader.probe_tools import check

LOG_TAIL = 15    # lines of the run's log kept to explain a failure


def junit_counts(path: str) -> Tuple[int, int]:
    """(tests, failures + errors) of a JUnit file (a <testsuite> or <testsuites>)."""
    root = ET.parse(path).getroot()
    suites = [root] if root.tag == "testsuite" else list(root.iter("testsuite"))
    tests = sum(int(s.get("tests", 0)) for s in suites)
    bad = sum(int(s.get("failures", 0)) + int(s.get("errors", 0)) for s in suites)
    return tests, bad


def _matching(workspace: str, package: str, test_file: str) -> List[str]:
    stem = os.path.splitext(test_file)[0]
    folder = os.path.join(workspace, "build", "test_results", package)
    return [p for p in sorted(glob.glob(os.path.join(folder, "*.xml")))
            if stem in os.path.basename(p)]


def result_files(workspace: str, package: str, test_file: str) -> List[str]:
    """The JUnit files ``run_tests`` wrote for ``test_file`` of ``package``: rostest's
    summary (``rostest-*``) when there is one, which already counts the test node's own
    cases (its ``rosunit-*`` file would count them twice)."""
    found = _matching(workspace, package, test_file)
    summaries = [p for p in found if os.path.basename(p).startswith("rostest-")]
    return summaries or found


def registered(package_dir: str, test_file: str) -> bool:
    """The package's CMakeLists registers ``test_file`` with add_rostest."""
    path = os.path.join(package_dir, "CMakeLists.txt")
    if not os.path.isfile(path):
        return False
    with open(path, encoding="utf-8", errors="replace") as stream:
        text = stream.read()
    return "add_rostest" in text and test_file in text


def judge_results(files: List[str], test_file: str, seconds: float,
                  exit_code: Optional[int]) -> Dict:
    if not files:
        how = "timed out" if exit_code is None else f"exit status {exit_code}"
        return check(f"{test_file} passes", False,
                     f"catkin_make run_tests wrote no result for {test_file} ({how})")
    tests = bad = 0
    for path in files:
        counted = junit_counts(path)
        tests, bad = tests + counted[0], bad + counted[1]
    names = ", ".join(os.path.basename(p) for p in files)
    return check(f"{test_file} passes", tests > 0 and bad == 0,
                 f"{test_file}: {tests} test(s), {bad} failed or errored ({names}) "
                 f"in {seconds:.0f} s")


def run(course, scenario: str, context) -> Dict:
    """The arm_test scenario's runner (named in config/me495_hw3.yaml)."""
    spec = course.checks[scenario]
    package, test_file = spec["package"], spec["test_file"]
    item = course.items_of(scenario)[0].id
    if package not in context.staged.found:
        return {"checks": {item: [check(f"{test_file} passes", False,
                                        f"the submission has no {package}")]}}
    package_dir = os.path.join(context.workspace, "src", package)
    checks = [check(f"{test_file} registered", registered(package_dir, test_file),
                    f"{package}/CMakeLists.txt {'registers' if registered(package_dir, test_file) else 'does not register'} "
                    f"{test_file} with add_rostest")]
    for stale in _matching(context.workspace, package, test_file):
        os.remove(stale)
    log_path = os.path.join(context.log_dir, "run_tests.log")
    env = dict(context.env, ROS_HOME=os.path.join(context.log_dir, "ros"))
    env.pop("ROS_MASTER_URI", None)
    command = ["catkin_make", "-C", context.workspace, f"run_tests_{package}",
               "-DPYTHON_EXECUTABLE=/usr/bin/python3"]
    started = time.monotonic()
    with open(log_path, "w", encoding="utf-8") as log:
        try:
            code: Optional[int] = subprocess.run(
                command, cwd=context.workspace, env=env, stdout=log, stderr=subprocess.STDOUT,
                timeout=course.limits["run_tests"], check=False).returncode
        except subprocess.TimeoutExpired:
            code = None
    seconds = time.monotonic() - started
    checks.append(judge_results(result_files(context.workspace, package, test_file), test_file,
                                seconds, code))
    with open(log_path, encoding="utf-8", errors="replace") as log:
        tail = [f"run_tests: {line.rstrip()}" for line in log.readlines()[-LOG_TAIL:]]
    return {"checks": {item: checks}, "log": {item: tail},
            "notes": {item: [f"catkin_make run_tests_{package}: "
                             f"{'timed out' if code is None else f'exit status {code}'}; "
                             f"log {log_path}"]}}

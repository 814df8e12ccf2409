"""What a scenario's stop had to kill is in the report. A process still carrying the
scenario's tag (COURSE_GRADER_SESSION) after the process groups were stopped, in a session
of its own and deaf to SIGINT and SIGTERM as a hung node is, is killed (SIGKILL) and
recorded with its pid and command line (shortened); the scenario's entry in report.json
lists it, each of its items' evidence counts it and report.md names it. Real child
processes throughout, no master: a hung 'roslaunch' and a stand-in 'roscore' (answering the
one call the grader makes before the probe) are scripts first on PATH; the probe is the real
one, left waiting by that master for /use_sim_time until the scenario's limit stops it, as
in a scenario that hangs."""
import json
import os
import re
import subprocess
import sys
import time

import pytest

from course_grader import course as course_file
from course_grader import grader, report, ros_run
from course_grader.results import Report

STOP = 2.0        # s: SIGINT to SIGKILL in these tests
STARTUP = 10.0    # s: a stand-in process to start; the probe's wait, beyond SCENARIO
SCENARIO = 3.0    # s: the scenario's limit, where the waiting probe is stopped
GONE_WITHIN = 5.0  # s: a killed process to be gone
# a node that ignores SIGINT and SIGTERM and says it is running; argv long, as a node's is
DEAF_NODE = ("import signal, sys, time\n"
             "signal.signal(signal.SIGINT, signal.SIG_IGN)\n"
             "signal.signal(signal.SIGTERM, signal.SIG_IGN)\n"
             "open(sys.argv[1], 'w').write('up')\n"
             "time.sleep(600)\n")
LONG_ARGS = [f"__remap_{index}:=/a/rather/long/topic/name/{index}" for index in range(20)]
FAKE_ROSCORE = """#!{python}
import os, sys, xmlrpc.server
port = int(sys.argv[sys.argv.index("-p") + 1])
server = xmlrpc.server.SimpleXMLRPCServer(("127.0.0.1", port), logRequests=False)
server.register_function(lambda caller: [1, "", os.getpid()], "getPid")
# /use_sim_time never set: the probe waits for it until the scenario's limit stops it
server.register_function(lambda caller, key: [1, "", False], "hasParam")
server.serve_forever()
"""
# the launch starts the deaf node in a session of its own (as roslaunch does) and waits
HUNG_ROSLAUNCH = """#!/bin/bash
setsid {python} {node} {ready} {args} &
exec sleep 600
"""
QUIET_ROSLAUNCH = """#!/bin/bash
exec sleep 600
"""


def _limits():
    return {"stop": STOP, "startup": STARTUP, "scenario": SCENARIO}


def _gone(pid, timeout=GONE_WITHIN):
    """Whether ``pid`` has ended (or is a zombie) within ``timeout``: a process sent SIGKILL
    takes a moment to go, longer on a loaded machine (once seen still running at once)."""
    deadline = time.monotonic() + timeout
    while True:
        try:
            with open(f"/proc/{pid}/stat", encoding="utf-8") as stream:
                if stream.read().rsplit(")", 1)[1].split()[0] == "Z":
                    return True
        except FileNotFoundError:
            return True
        if time.monotonic() > deadline:
            return False
        time.sleep(0.01)


def test_a_tagged_process_deaf_to_sigterm_is_killed_and_recorded(tmp_path):
    session = ros_run.Session(dict(os.environ), str(tmp_path / "logs"), _limits())
    ready = tmp_path / "ready"
    with session:
        deaf = subprocess.Popen([sys.executable, "-c", DEAF_NODE, str(ready), *LONG_ARGS],
                                env=session.env, start_new_session=True)
        # a process without the tag, beside it: not the scenario's, never killed
        untagged = subprocess.Popen([sys.executable, "-c", DEAF_NODE, str(tmp_path / "other")],
                                    start_new_session=True)
        ros_run.wait_until(lambda: ready.exists() and (tmp_path / "other").exists(),
                           STARTUP, "the children to start")
        deaf.send_signal(15)   # SIGTERM: ignored, as a hung node does
    try:
        assert [k.pid for k in session.strays] == [deaf.pid]
        command = session.strays[0].command
        assert command.startswith(f"{sys.executable} -c import signal")
        assert len(command) == ros_run.COMMAND_CHARS and command.endswith("\u2026")
        assert deaf.wait(STOP) == -9
        assert untagged.poll() is None
    finally:
        untagged.kill()
        untagged.wait()


def test_a_scenario_that_stops_cleanly_records_nothing(tmp_path):
    session = ros_run.Session(dict(os.environ), str(tmp_path / "logs"), _limits())
    with session:
        session._start("launch", ["sleep", "600"])  # pylint: disable=protected-access
    assert session.strays == []


@pytest.fixture
def rb1():
    course = course_file.load("rb1")
    course.limits.update(_limits())
    return course


def _path_with(tmp_path, launch: str) -> dict:
    """The environment with stand-in roscore and roslaunch first on PATH."""
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    node = tmp_path / "node.py"
    node.write_text(DEAF_NODE)
    for name, text in (("roscore", FAKE_ROSCORE), ("roslaunch", launch)):
        script = bin_dir / name
        script.write_text(text.format(python=sys.executable, node=node,
                                      ready=tmp_path / "node_up", args=" ".join(LONG_ARGS)))
        script.chmod(0o755)
    return dict(os.environ, PATH=f"{bin_dir}{os.pathsep}{os.environ['PATH']}")


def test_a_hung_scenario_reports_what_its_stop_killed(rb1, tmp_path):
    env = _path_with(tmp_path, HUNG_ROSLAUNCH)
    out = tmp_path / "out"
    results = grader.scenario_results(rb1, "scan", env, str(tmp_path / "logs"), str(out))
    assert (tmp_path / "node_up").exists()   # the node did run
    assert all(r.awarded == 0 for r in results)   # the scenario failed, as before
    # the probe gets what is left of the limit after the start (the screen, the launch)
    within = re.search(r"the checks did not finish within (\d+) s", results[0].evidence())
    assert within and 1 <= int(within.group(1)) <= SCENARIO, results[0].evidence()
    assert all(r.mark == "review" for r in results)    # not measured: a TA decides
    killed = results[0].killed
    assert len(killed) == 1 and "node.py" in killed[0].command
    assert _gone(killed[0].pid)
    for result in results:
        assert (f"1 process(es) still running after the scenario's stop were killed "
                f"(pid {killed[0].pid})") in result.evidence()
    written = Report(rb1, str(tmp_path), results)
    report.write(written, str(out))
    with open(out / "report.json", encoding="utf-8") as stream:
        data = json.load(stream)
    assert data["scenarios"] == [{"scenario": "scan", "seconds": round(results[0].seconds, 1),
                                  "killed": [{"pid": killed[0].pid,
                                              "command": killed[0].command}]}]
    assert "killed (pid" in data["items"][0]["evidence"]
    assert f"pid {killed[0].pid}: `{killed[0].command}`" in (out / "report.md").read_text()


def test_a_scenario_whose_launch_stops_reports_no_kill(rb1, tmp_path):
    env = _path_with(tmp_path, QUIET_ROSLAUNCH)
    results = grader.scenario_results(rb1, "scan", env, str(tmp_path / "logs"))
    assert all(r.killed == [] for r in results)
    assert "killed" not in results[0].evidence()
    data = Report(rb1, str(tmp_path), results).to_dict()
    assert data["scenarios"][0]["killed"] == []

"""One scenario's processes: a fresh ``roscore`` on a free port, the guide's launch files,
an optional virtual display, and the probe that measures; every wait bounded, every
process stopped at the end, logs kept per scenario. roslaunch starts each node in a session
of its own (setsid), so a node that ignores SIGINT and SIGTERM outlives its launch's process
group: every process the scenario starts carries the scenario's tag in its environment
(SESSION_TAG), and whatever still carries it after the stop is killed."""
from __future__ import annotations

import fcntl
import json
import os
import re
import signal
import subprocess
import time
import xml.etree.ElementTree as ET
from typing import Dict, List, Optional, Tuple

import rosgraph

from course_grader.master_port import PortReservation
from course_grader.results import Killed

PYTHON = "/usr/bin/python3"   # the system interpreter, where ROS lives
POLL = 0.1                # s between looks at a condition
LOG_LINES = 12            # lines of a launch's log kept to explain a failure
# the probe's environment variable, "1" when none of the scenario's launch files starts a
# simulator (the grader reads them with roslaunch): no simulated clock, no /gazebo
NO_SIMULATOR_ENV = "COURSE_GRADER_NO_SIMULATOR"
# held while an Xvfb starts (see Session.start_display); tools/headless.py takes it too
XVFB_START_LOCK = "/tmp/.xvfb-start.lock"
SERVICES = ("roscore", "xvfb")   # what the scenario's launches and nodes use: stopped last
SESSION_TAG = "COURSE_GRADER_SESSION"   # environment variable naming a scenario's processes
COMMAND_CHARS = 200       # characters of a killed process's command line kept for the report
# lines of a log that explain a failure
TROUBLE = re.compile(r"\berror|fatal|traceback|exception|failed|not found|process has died|"
                     r"refus|connection broke|required process", re.IGNORECASE)


class RunError(RuntimeError):
    """A scenario could not be run (master, launch or probe); the message says which."""


class ScenarioLimit(RunError):
    """The scenario's checks ran out of its time: the grader could not finish measuring (a
    hung service, or a slow machine), so its items are for a teaching assistant to review."""


def wait_until(condition, timeout: float, what: str):
    deadline = time.monotonic() + timeout
    while True:
        result = condition()
        if result:
            return result
        if time.monotonic() > deadline:
            raise RunError(f"timed out after {timeout:.0f} s waiting for {what}")
        time.sleep(POLL)


def tagged(tag: str) -> List[int]:
    """The processes whose environment holds ``SESSION_TAG=tag`` (inherited by every process
    a scenario starts, whatever session or group it moves to)."""
    wanted = f"{SESSION_TAG}={tag}".encode()
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit() or int(entry) == os.getpid():
            continue
        try:
            with open(f"/proc/{entry}/environ", "rb") as stream:
                if wanted in stream.read().split(b"\0"):
                    found.append(int(entry))
        except OSError:   # gone meanwhile, or not ours to read
            continue
    return found


def command_line(pid: int) -> str:
    """The command line of ``pid``, its arguments joined by spaces, cut to COMMAND_CHARS
    (a node's line holds every remapping); its name in brackets when it has none."""
    try:
        with open(f"/proc/{pid}/cmdline", "rb") as stream:
            words = [w.decode(errors="replace") for w in stream.read().split(b"\0") if w]
        if not words:
            with open(f"/proc/{pid}/comm", encoding="utf-8", errors="replace") as stream:
                words = [f"[{stream.read().strip()}]"]
    except OSError:   # gone meanwhile
        return "?"
    text = " ".join(words)
    return text if len(text) <= COMMAND_CHARS else text[:COMMAND_CHARS - 1] + "\u2026"


def kill_tagged(tag: str, timeout: float) -> List[Killed]:
    """SIGKILL to every process tagged ``tag`` until none is left (``timeout`` s at most);
    the ones killed, by pid, each with its command line (read before the kill)."""
    killed: Dict[int, str] = {}

    def none_left():
        for pid in tagged(tag):
            command = killed.get(pid) or command_line(pid)
            try:
                os.kill(pid, signal.SIGKILL)
                killed[pid] = command
            except ProcessLookupError:
                pass
        return not tagged(tag)
    try:
        wait_until(none_left, timeout, f"the processes tagged {tag} to end")
    except RunError:
        pass   # a process stuck in the kernel (D state): nothing more a signal can do
    return [Killed(pid, killed[pid]) for pid in sorted(killed)]


def declared_args(launch_file: str) -> List[str]:
    """The arguments a launch file lets the command line set (top-level ``<arg>`` without
    ``value``)."""
    try:
        root = ET.parse(launch_file).getroot()
    except (ET.ParseError, OSError):
        return []
    return [arg.get("name") for arg in root.findall("arg") if arg.get("value") is None]


# roslaunch's own reading of a launch file with arguments: the (package, type) of every
# node it would start, includes and if/unless resolved; printed as one JSON line
_LAUNCHED = ("import json, sys, roslaunch.config\n"
             "config = roslaunch.config.load_config_default([(sys.argv[1], sys.argv[2:])], None)\n"
             "print(json.dumps([[n.package, n.type] for n in config.nodes]))\n")
LAUNCH_READ_LIMIT = 60.0    # s (wall) roslaunch may take to read a launch file


def launched_nodes(env: Dict[str, str], launch_file: str,
                   args: List[str]) -> Optional[List[Tuple[str, str]]]:
    """The (package, type) of each node ``launch_file`` starts with ``args``, as roslaunch
    reads it in ``env`` (the submission's); None when roslaunch cannot read it."""
    if not launch_file or not os.path.isfile(launch_file):
        return None
    try:
        done = subprocess.run(["python3", "-c", _LAUNCHED, launch_file, *args], env=env,
                              capture_output=True, text=True, timeout=LAUNCH_READ_LIMIT,
                              check=False)
        return [tuple(node) for node in json.loads(done.stdout.strip().splitlines()[-1])] \
            if done.returncode == 0 and done.stdout.strip() else None
    except (OSError, subprocess.TimeoutExpired, ValueError, IndexError):
        return None


class Session:
    """Processes of one scenario; use as a context manager (everything stops on exit)."""

    def __init__(self, env: Dict[str, str], log_dir: str, limits: Dict[str, float]):
        self.log_dir = log_dir
        self.limits = limits
        os.makedirs(log_dir, exist_ok=True)
        self.reservation = PortReservation()
        self.port = self.reservation.port
        self.master_uri = f"http://127.0.0.1:{self.port}"
        self.tag = f"{os.getpid()}-{self.port}-{time.monotonic_ns()}"
        self.env = dict(env, ROS_MASTER_URI=self.master_uri, ROS_HOME=os.path.join(log_dir, "ros"),
                        ROS_LOG_DIR=os.path.join(log_dir, "ros", "log"), PYTHONUNBUFFERED="1",
                        **{SESSION_TAG: self.tag})
        self.strays: List[Killed] = []   # processes killed by their tag after the stop
        self.env.pop("DISPLAY", None)
        self.processes: List[tuple] = []   # (name, Popen, log path)

    def __enter__(self) -> "Session":
        return self

    def __exit__(self, *exc) -> None:
        self.stop()

    def _start(self, name: str, command: List[str]) -> subprocess.Popen:
        log_path = os.path.join(self.log_dir, f"{name}.log")
        log = open(log_path, "w", encoding="utf-8")  # pylint: disable=consider-using-with
        process = subprocess.Popen(command, env=self.env, stdout=log, stderr=subprocess.STDOUT,
                                   stdin=subprocess.DEVNULL, start_new_session=True)
        log.close()
        self.processes.append((name, process, log_path))
        return process

    def start_master(self) -> None:
        self._start("roscore", ["roscore", "-p", str(self.port)])
        master = rosgraph.Master("/course_grader", master_uri=self.master_uri)

        def answers():
            try:
                master.getPid()
                return True
            except Exception:  # pylint: disable=broad-except
                return False
        wait_until(answers, self.limits["startup"], f"roscore on port {self.port}")
        # the master that answers must be this scenario's: one on the port already would
        # run the guide's launch files among another run's nodes of the same names
        if master.getPid() not in tagged(self.tag):
            raise RunError(f"another run's ROS master answers on port {self.port}")

    def start_display(self) -> None:
        """A virtual screen (Xvfb) for windows the guide's launch opens (rviz, sliders).
        Xvfb picks a free display itself (``-displayfd``), but two starting at once may take
        the same one's socket (a display rviz was using broke so, beside another run's
        Xvfb): starts are serialised across processes by XVFB_START_LOCK, held until the
        server announces its number."""
        read_fd, write_fd = os.pipe()
        log_path = os.path.join(self.log_dir, "xvfb.log")
        with open(XVFB_START_LOCK, "a", encoding="utf-8") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            with open(log_path, "w", encoding="utf-8") as log:
                process = subprocess.Popen(["Xvfb", "-displayfd", str(write_fd), "-screen", "0",
                                            "1280x1024x24", "-nolisten", "tcp",
                                            # a reset when the last client leaves refuses
                                            # the next one (a node started again)
                                            "-noreset"],
                                           stdout=log, stderr=subprocess.STDOUT,
                                           pass_fds=(write_fd,), start_new_session=True)
            os.close(write_fd)
            self.processes.append(("xvfb", process, log_path))
            with os.fdopen(read_fd) as pipe:   # Xvfb writes its number once it accepts clients
                number = pipe.readline().strip()
        if not number:
            raise RunError(f"Xvfb did not start (see {log_path})")
        self.env.update(DISPLAY=f":{number}", LIBGL_ALWAYS_SOFTWARE="1")

    def launch(self, name: str, package: str, launch_file: str, args: List[str]) -> None:
        self._start(name, ["roslaunch", "--wait", package, launch_file, *args])

    def rosrun(self, name: str, package: str, node: str) -> None:
        """A node started by hand, as the submission's README says."""
        self._start(name, ["rosrun", package, node])

    def master(self) -> rosgraph.Master:
        return rosgraph.Master("/course_grader", master_uri=self.master_uri)

    def wait_for_topic(self, topic: str, timeout: float) -> None:
        def published():
            self.check_alive()
            try:
                return any(name == topic for name, _ in self.master().getPublishedTopics(""))
            except Exception:  # pylint: disable=broad-except
                return False
        wait_until(published, timeout, f"a publisher of {topic}")

    def check_alive(self) -> None:
        """Raises RunError naming the first process that has ended, with the lines of its
        log that say why (roslaunch's "process has died", a traceback's last line)."""
        for name, process, log_path in self.processes:
            if process.poll() is not None:
                why = "; ".join(line.strip() for line in self._log_trouble(log_path)[-3:])
                raise RunError(f"'{name}' ended (exit status {process.returncode}) "
                               f"before the checks" + (f": {why}" if why else "")
                               + f"; see {log_path}")

    @staticmethod
    def _log_trouble(log_path: str) -> List[str]:
        try:
            with open(log_path, encoding="utf-8", errors="replace") as log:
                return [line.rstrip() for line in log if TROUBLE.search(line)]
        except OSError:
            return []

    def probe(self, scenario: str, config_path: str, timeout: float,
              folder: str = "", env: Optional[Dict[str, str]] = None) -> Dict:
        """Runs ``python3 -m course_grader.probe`` against this master (``folder``: where it
        may write pictures for the report; ``env``: variables beside the session's); its
        JSON answer."""
        log_path = os.path.join(self.log_dir, "probe.log")
        command = [PYTHON, "-m", "course_grader.probe", scenario, config_path,
                   *([folder] if folder else [])]
        with open(log_path, "w", encoding="utf-8") as log:
            try:
                done = subprocess.run(command, env={**self.env, **(env or {})},
                                      stdout=subprocess.PIPE, stderr=log,
                                      timeout=timeout, check=False, text=True)
            except subprocess.TimeoutExpired as error:
                raise ScenarioLimit(f"the checks did not finish within {timeout:.0f} s "
                                    f"(see {log_path})") from error
        lines = [line for line in done.stdout.splitlines() if line.startswith("{")]
        if not lines:
            raise RunError(f"the checks ended without an answer (exit status "
                           f"{done.returncode}; see {log_path})")
        return json.loads(lines[-1])

    def stop(self) -> None:
        """SIGINT to the launches' and nodes' process groups, then SIGKILL; then the same to
        the virtual screen and roscore (stopped after the windows and nodes that use them,
        so that a log's "X11 connection broke" or a lost master means a fault, not the
        stop); then SIGKILL to every process still tagged with this scenario (a node in a
        session of its own that ignored the signals)."""
        services = [p for p in self.processes if p[0] in SERVICES]
        self._stop_all([p for p in self.processes if p[0] not in SERVICES])
        self._stop_all([p for p in services if p[0] != "xvfb"])
        # the screen under the start lock: a stopping Xvfb removes its socket after it has
        # freed its display number, which one starting meanwhile would take (see
        # start_display); roscore's stop need not hold other runs' screens back
        with open(XVFB_START_LOCK, "a", encoding="utf-8") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            self._stop_all([p for p in services if p[0] == "xvfb"])
        self.strays = kill_tagged(self.tag, self.limits["stop"])
        self.reservation.release()

    def _stop_all(self, processes: List[tuple]) -> None:
        for _, process, _ in reversed(processes):
            if process.poll() is None:
                try:
                    os.killpg(process.pid, signal.SIGINT)
                except ProcessLookupError:
                    pass
        deadline = time.monotonic() + self.limits["stop"]
        for _, process, _ in reversed(processes):
            try:
                process.wait(max(0.0, deadline - time.monotonic()))
            except subprocess.TimeoutExpired:
                pass
            try:
                os.killpg(process.pid, signal.SIGKILL)
            except (ProcessLookupError, PermissionError):
                pass
            process.wait()

    def trouble(self, names: Optional[List[str]] = None) -> List[str]:
        """The lines of the launches' logs that explain a failure (errors, tracebacks)."""
        found: List[str] = []
        for name, _, log_path in self.processes:
            if names is not None and name not in names:
                continue
            found += [f"{name}: {line}" for line in self._log_trouble(log_path)][-LOG_LINES:]
        return found

"""Faults of the grading platform, told from the submission's: a scenario whose logs hold a
Python traceback raised in the platform's own code (the simulator, the compat packages, the
grader), a build or a launch that stops at a package the platform lacks (CMake's "Could not
find a package configuration file", roslaunch's ``Resource not found``, of a package the
submission does not hold), or a program of the platform (rviz, the sliders, the
simulator: its command under /usr or the platform's folders) killed by a signal, as a
crash or the kernel's out-of-memory killer does. Such a scenario's lost points are not the student's:
the items are marked "platform", left out of the points possible, and the grade is
incomplete. No ROS here."""
from __future__ import annotations

import glob
import os
import re
from typing import Iterable, List, Optional, Tuple

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.realpath(__file__)))))
# the platform's code: what ships in this repository besides the course solutions
PLATFORM_DIRS = ("sim_bridge", "compat", "courses", "urdf_tools", "course_grader", ".ws")
FRAME = re.compile(r'^\s*File "([^"]+)", line (\d+)')
MISSING = re.compile(r"Resource not found: ([A-Za-z0-9_]+)")
# roslaunch's words for a node that ended on its own: "[rviz-3] process has died [pid 22396,
# exit code -11, cmd /usr/lib/rviz/rviz -d ... __name:=rviz ...]"; for a required node two
# lines, "REQUIRED process [rviz-3] has died!" then "process has died [pid 22396, ..."
# (a name holds no bracket: roslaunch colours the line, "\x1b[31m[rviz-3] process ...")
DIED = re.compile(r"(?:\[([^][]+)\] )?process has died \[pid \d+, exit code (-\d+), cmd (\S+)")
REQUIRED_DIED = re.compile(r"REQUIRED process \[([^][]+)\] has died!")
SYSTEM_DIRS = ("/usr/", "/bin/", "/lib/")
# a log this big is read from its end only
TAIL_BYTES = 2_000_000


def _is_platform(path: str) -> bool:
    path = os.path.realpath(path)
    return any(path.startswith(os.path.join(REPO, folder) + os.sep) for folder in PLATFORM_DIRS)


def signal_deaths(lines: Iterable[str]) -> List[Tuple[str, str, str]]:
    """The nodes roslaunch saw killed by a signal, in its log's order: (name, exit code,
    command), e.g. ("rviz-3", "-11", "/usr/lib/rviz/rviz"), in either of its two forms."""
    deaths, required = [], None
    for line in lines:
        required_match = REQUIRED_DIED.search(line)
        if required_match:
            required = required_match.group(1)
            continue
        match = DIED.search(line)
        if match:
            name, code, command = match.groups()
            if name or required:
                deaths.append((name or required, code, command))
            required = None
    return deaths


def killed_platform_program(lines: List[str]) -> Optional[str]:
    """The first platform program roslaunch saw killed by a signal: "rviz-3 (exit code
    -11, /usr/lib/rviz/rviz)"; None when there is none. A submission's own node that
    crashes is the submission's."""
    for name, code, command in signal_deaths(lines):
        if _is_platform(command) or os.path.realpath(command).startswith(SYSTEM_DIRS):
            return f"{name} (exit code {code}, {command})"
    return None


def _lines(path: str) -> List[str]:
    try:
        with open(path, "rb") as stream:
            stream.seek(max(0, os.path.getsize(path) - TAIL_BYTES))
            return stream.read().decode("utf-8", errors="replace").splitlines()
    except OSError:
        return []


def traceback_in_platform(lines: List[str]) -> Optional[str]:
    """The first traceback whose innermost frame is platform code: "file:line: the
    exception"; None when there is none."""
    index = 0
    while index < len(lines):
        if not lines[index].startswith("Traceback (most recent call last)"):
            index += 1
            continue
        last_frame, index = None, index + 1
        while index < len(lines) and (lines[index].startswith(" ") or not lines[index].strip()):
            match = FRAME.match(lines[index])
            if match:
                last_frame = (match.group(1), match.group(2))
            index += 1
        exception = lines[index].strip() if index < len(lines) else "(no exception line)"
        if last_frame and _is_platform(last_frame[0]):
            where = os.path.relpath(os.path.realpath(last_frame[0]), REPO)
            return f"{where}:{last_frame[1]}: {exception}"
    return None


def build_lacks(not_found: Iterable[str], submission_packages: Iterable[str]) -> Optional[str]:
    """Why a build that stopped at find_package failed for the platform: the packages it
    did not find that the submission does not hold itself (a ROS package the student's
    machine has, turtlesim say), with what to install; None when there are none."""
    absent = [name for name in not_found if name not in set(submission_packages)]
    if not absent:
        return None
    names = ", ".join(f"'{name}'" for name in absent)
    debs = " ".join(f"ros-noetic-{name.replace('_', '-')}" for name in absent)
    return (f"the grading platform has no package {names}, which the submission's build "
            f"finds (catkin_make.log: Could not find a package configuration file provided "
            f"by \"{absent[0]}\"): install it where the grader runs (on ROS Noetic: {debs}) "
            "and grade again")


def find(log_dir: str, submission_packages: Iterable[str]) -> Optional[str]:
    """Why the scenario logged in ``log_dir`` failed for the platform's fault, or None."""
    own = set(submission_packages)
    paths = sorted(glob.glob(os.path.join(log_dir, "*.log")) +
                   glob.glob(os.path.join(log_dir, "ros", "log", "**", "*.log"), recursive=True))
    for path in paths:
        lines = _lines(path)
        found = traceback_in_platform(lines)
        if found:
            return f"a traceback in the grading platform ({found}; {os.path.basename(path)})"
        killed = killed_platform_program(lines)
        if killed:
            return (f"a program of the grading platform was killed by a signal: {killed}; "
                    f"{os.path.basename(path)}")
        for line in lines:
            match = MISSING.search(line)
            if match and match.group(1) not in own:
                return (f"the grading platform has no package '{match.group(1)}' "
                        f"({os.path.basename(path)}: {line.strip()[:160]})")
    return None

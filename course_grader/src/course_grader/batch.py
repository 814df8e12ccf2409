"""Grading many submissions with one command: ``grade COURSE PATH PATH ... [--jobs N]
[--shard I/N] [--csv FILE] [--limit SECONDS]``.

Each submission is graded by its own child process (``python3 -m course_grader COURSE PATH
--out OUT/<name>``, the one-submission command), up to ``--jobs`` at a time, each with its
own temporary folder (TMPDIR), ROS_HOME and, as every grading does, its own free master
ports. A child that passes its wall limit is killed with everything it started: the
scenario's ``roscore`` and ``roslaunch`` run in sessions of their own, so a process group
is not enough; every process of a submission carries a marker in its environment
(``COURSE_GRADER_BATCH``), and the child's process tree and every marked process are
killed, never a sibling's. A crash or a kill is a row of 0 points with the reason.

``--shard I/N`` (1-based: 1 <= I <= N) grades the sorted paths I, I+N, I+2N, ..., so N
shards together grade every path exactly once (a CI matrix or a cluster's job array).

The CSV: one row per submission, columns ``path, name, <item id>... (the course file's
order), total, possible, seconds, status, reason``; an item not graded (``--only``) is an
empty cell, and a submission not graded has 0 on each item it was to be graded on; status is ``graded``, ``refused`` (the grader could not use it: exit status 2),
``crashed`` (another exit status, or no report) or ``killed`` (past the limit)."""
from __future__ import annotations

import csv
import json
import math
import os
import shutil
import signal
import subprocess
import tempfile
import time
from dataclasses import dataclass, field
from typing import Callable, Dict, List, Optional, Sequence, Tuple

from course_grader import ros_run
from course_grader.course import Course

MARKER = "COURSE_GRADER_BATCH"   # environment variable every process of a submission carries
REFUSED_STATUS = 2               # the grader's exit status for a course or path it cannot use
REASON_LINES = 3                 # last lines of a child's log quoted as a crash's reason
STATUSES = ("graded", "refused", "crashed", "killed")


class BatchError(ValueError):
    """A batch option that cannot be used (shard, jobs, limit); the message names it."""


# --- which submissions ------------------------------------------------------------------

def parse_shard(text: str) -> Tuple[int, int]:
    """``"I/N"`` as (I, N), 1 <= I <= N."""
    try:
        index, count = (int(part) for part in text.split("/"))
    except ValueError as error:
        raise BatchError(f"--shard '{text}': expected I/N with whole numbers, "
                         "e.g. 2/4 (the second of four shards)") from error
    if count < 1 or not 1 <= index <= count:
        raise BatchError(f"--shard '{text}': I must be between 1 and N (1-based), N at least 1")
    return index, count


def ordered(paths: Sequence[str]) -> List[str]:
    """The paths sorted (normalised, each once): the same order on every machine."""
    return sorted({os.path.normpath(path) for path in paths})


def select_shard(paths: Sequence[str], index: int, count: int) -> List[str]:
    """Shard ``index`` of ``count`` (1-based): every ``count``-th sorted path from the
    ``index``-th."""
    return ordered(paths)[index - 1::count]


def names(paths: Sequence[str]) -> Dict[str, str]:
    """A folder name per path (its last component), ``-2``, ``-3`` ... added in sorted order
    when two paths end alike; taken over every path before sharding, so stable across
    shards."""
    result: Dict[str, str] = {}
    used: Dict[str, int] = {}
    for path in ordered(paths):
        base = os.path.basename(os.path.abspath(path)) or "submission"
        used[base] = used.get(base, 0) + 1
        result[path] = base if used[base] == 1 else f"{base}-{used[base]}"
    return result


def submission_limit(course: Course, scenarios: Optional[Sequence[str]] = None) -> float:
    """Seconds a submission may take in all, from the course's limits: the build plus, per
    scenario run, its limit and its tear-down."""
    count = len(scenarios or course.scenarios())
    return course.limits["build"] + count * (course.limits["scenario"] + course.limits["stop"])


# --- the processes of one submission ----------------------------------------------------

def _proc_ids() -> List[int]:
    return [int(entry) for entry in os.listdir("/proc") if entry.isdigit()]


def _parent(pid: int) -> Optional[int]:
    try:
        with open(f"/proc/{pid}/stat", encoding="utf-8", errors="replace") as stat:
            # the command name (in parentheses) may hold spaces: fields follow the last ')'
            return int(stat.read().rsplit(")", 1)[1].split()[1])
    except (OSError, IndexError, ValueError):
        return None


def descendants(pid: int) -> List[int]:
    """Every living process below ``pid`` (children, grandchildren ...)."""
    children: Dict[int, List[int]] = {}
    for other in _proc_ids():
        parent = _parent(other)
        if parent is not None:
            children.setdefault(parent, []).append(other)
    found, stack = [], list(children.get(pid, []))
    while stack:
        current = stack.pop()
        found.append(current)
        stack += children.get(current, [])
    return found


def marked(value: str) -> List[int]:
    """Processes whose environment holds ``MARKER=value`` (orphans included)."""
    needle = f"{MARKER}={value}".encode()
    found = []
    for pid in _proc_ids():
        try:
            with open(f"/proc/{pid}/environ", "rb") as environ:
                if needle in environ.read().split(b"\0"):
                    found.append(pid)
        except OSError:   # gone, or another user's
            continue
    return found


def kill_all(marker: str, pid: Optional[int], timeout: float) -> int:
    """SIGKILL to every process marked ``marker`` and, when ``pid`` is given (a child not yet
    reaped, so its number cannot have been reused), to ``pid`` and its tree, until no marked
    process is left (one may fork while its parent dies: looked for again); how many were
    killed besides ``pid``."""
    killed = set()

    def sweep():
        targets = set(marked(marker))
        if pid is not None:
            targets |= set(descendants(pid)) | {pid}
        for target in targets - killed - {os.getpid()}:
            try:
                os.kill(target, signal.SIGKILL)
                killed.add(target)
            except ProcessLookupError:
                pass
        return not set(marked(marker)) - killed

    try:
        ros_run.wait_until(sweep, timeout, f"the processes marked {marker} to end")
    except ros_run.RunError:
        pass   # a process that cannot be killed (another user's): nothing more to do here
    return len(killed - {pid})


# --- one submission ---------------------------------------------------------------------

@dataclass
class Outcome:
    """One submission's row of the CSV."""

    path: str
    name: str
    status: str = "crashed"
    awarded: Dict[str, float] = field(default_factory=dict)   # item id -> points awarded
    possible: float = 0.0
    seconds: float = 0.0
    reason: str = ""
    expected: Dict[str, float] = field(default_factory=dict)  # item id -> points, items to grade
    marks: Dict[str, str] = field(default_factory=dict)  # item id -> "review" or "platform"

    def zero(self, status: str, reason: str) -> None:
        """Not graded (refused, crashed, killed): 0 on every item it was to be graded on."""
        self.status, self.reason = status, reason
        self.awarded = {item_id: 0.0 for item_id in self.expected}
        self.possible = sum(self.expected.values())

    @property
    def total(self) -> float:
        return sum(self.awarded.values())


@dataclass
class Child:
    """A running child: its process, marker, folders and deadline."""

    outcome: Outcome
    process: subprocess.Popen
    marker: str
    out: str
    tmp: str
    log_path: str
    started: float
    deadline: float


def _log_tail(path: str, count: int) -> List[str]:
    try:
        with open(path, encoding="utf-8", errors="replace") as log:
            return [line.rstrip() for line in log if line.strip()][-count:]
    except OSError:
        return []


def read_outcome(outcome: Outcome, out: str, exit_status: Optional[int], log_path: str):
    """Fills ``outcome`` from the child's exit status and its report.json."""
    report_path = os.path.join(out, "report.json")
    if exit_status == 0 and os.path.isfile(report_path):
        with open(report_path, encoding="utf-8") as stream:
            report = json.load(stream)
        outcome.status = "incomplete" if report.get("incomplete") else "graded"
        outcome.awarded = {item["id"]: float(item["awarded"]) for item in report["items"]}
        outcome.marks = {item["id"]: item["mark"] for item in report["items"]
                         if item.get("mark")}
        outcome.possible = float(report["possible"])
        return
    tail = " | ".join(_log_tail(log_path, REASON_LINES))
    if exit_status == REFUSED_STATUS:
        outcome.zero("refused", tail)
    else:
        what = "no report.json" if exit_status == 0 else f"exit status {exit_status}"
        outcome.zero("crashed", f"{what}: {tail} (log {log_path})")


class Runner:
    """Runs children, at most ``jobs`` at a time, each killed at its deadline."""

    def __init__(self, jobs: int, limit: float, stop_timeout: float,
                 progress: Callable[[str], None] = lambda line: None):
        if jobs < 1:
            raise BatchError(f"--jobs {jobs}: at least 1")
        if not (math.isfinite(limit) and limit > 0):   # NaN compares false with anything
            raise BatchError(f"--limit {limit:g}: must be a positive number of seconds")
        self.jobs, self.limit, self.stop_timeout = jobs, limit, stop_timeout
        self.progress = progress
        self.tag = f"{os.getpid()}-{time.time_ns()}"   # this batch's markers differ from another's

    def start(self, outcome: Outcome, command: List[str], out: str, env: Dict[str, str],
              index: int) -> Child:
        os.makedirs(out, exist_ok=True)
        for stale in ("report.json", "report.md"):   # a report from an earlier run is not this one's
            if os.path.exists(os.path.join(out, stale)):
                os.remove(os.path.join(out, stale))
        tmp = tempfile.mkdtemp(prefix=f"grade_batch_{outcome.name}_")
        marker = f"{self.tag}-{index}"
        child_env = dict(env, TMPDIR=tmp, ROS_HOME=os.path.join(tmp, "ros_home"),
                         **{MARKER: marker})
        log_path = os.path.join(out, "grade.log")
        with open(log_path, "w", encoding="utf-8") as log:
            process = subprocess.Popen(command, env=child_env, stdout=log,
                                       stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                       start_new_session=True)
        started = time.monotonic()
        return Child(outcome, process, marker, out, tmp, log_path, started,
                     started + self.limit)

    def finish(self, child: Child, killed: bool) -> Outcome:
        outcome = child.outcome
        if killed:
            count = kill_all(child.marker, child.process.pid, self.stop_timeout)
            child.process.wait()
            outcome.zero("killed", f"still running after its limit of {self.limit:.0f} s: "
                                   f"killed with {count} process(es) it started "
                                   f"(log {child.log_path})")
        else:
            read_outcome(outcome, child.out, child.process.returncode, child.log_path)
            strays = kill_all(child.marker, None, self.stop_timeout)   # the child is reaped
            if strays:   # a node that outlived its grading (daemonised, escaped its session)
                self.progress(f"{outcome.name}: {strays} process(es) left running were killed")
        outcome.seconds = time.monotonic() - child.started
        shutil.rmtree(child.tmp, ignore_errors=True)
        return outcome

    def run(self, tasks: List[Tuple[Outcome, List[str], str, Dict[str, str]]]) -> List[Outcome]:
        """``tasks``: (outcome, command, out folder, environment); outcomes in task order."""
        pending = list(enumerate(tasks))
        running: List[Child] = []
        done: Dict[int, Outcome] = {}
        index_of: Dict[int, int] = {}
        try:
            while pending or running:
                while pending and len(running) < self.jobs:
                    index, (outcome, command, out, env) = pending.pop(0)
                    child = self.start(outcome, command, out, env, index)
                    index_of[id(child)] = index
                    running.append(child)
                    self.progress(f"[{index + 1}/{len(tasks)}] {outcome.name}: started "
                                  f"(limit {self.limit:.0f} s)")
                for child in list(running):
                    over = time.monotonic() > child.deadline
                    if child.process.poll() is None and not over:
                        continue
                    running.remove(child)
                    index = index_of[id(child)]
                    outcome = self.finish(child, killed=child.process.poll() is None)
                    done[index] = outcome
                    self.progress(f"[{index + 1}/{len(tasks)}] {outcome.name}: "
                                  f"{outcome.total:g} of {outcome.possible:g}, {outcome.status} "
                                  f"in {outcome.seconds:.0f} s"
                                  + (f" ({outcome.reason})" if outcome.reason else ""))
                if running:
                    time.sleep(ros_run.POLL)
        finally:   # interrupted (Ctrl-C, a cancelled CI job): nothing a child started survives
            for child in running:
                alive = child.process.pid if child.process.returncode is None else None
                kill_all(child.marker, alive, self.stop_timeout)
                child.process.wait()
                shutil.rmtree(child.tmp, ignore_errors=True)
        return [done[index] for index in range(len(tasks))]


# --- the CSV ----------------------------------------------------------------------------

def _points(value: float) -> str:
    return f"{value:g}"


def csv_header(course: Course) -> List[str]:
    return ["path", "name", *[item.id for item in course.items], "total", "possible",
            "seconds", "status", "review", "platform", "reason"]


def csv_row(course: Course, outcome: Outcome) -> List[str]:
    """Points per item; ``review`` and ``platform`` list the items so marked."""
    cells = [_points(outcome.awarded[item.id]) if item.id in outcome.awarded else ""
             for item in course.items]
    marked = {mark: " ".join(item.id for item in course.items
                             if outcome.marks.get(item.id) == mark)
              for mark in ("review", "platform")}
    return [outcome.path, outcome.name, *cells, _points(outcome.total),
            _points(outcome.possible), f"{outcome.seconds:.1f}", outcome.status,
            marked["review"], marked["platform"], outcome.reason]


def write_csv(path: str, course: Course, outcomes: List[Outcome]) -> None:
    folder = os.path.dirname(os.path.abspath(path))
    os.makedirs(folder, exist_ok=True)
    with open(path, "w", encoding="utf-8", newline="") as stream:
        writer = csv.writer(stream)
        writer.writerow(csv_header(course))
        for outcome in outcomes:
            writer.writerow(csv_row(course, outcome))


# --- the command ------------------------------------------------------------------------

def wanted(args) -> bool:
    """Batch grading: several paths, or any batch option given."""
    return len(args.path) > 1 or any(getattr(args, option) is not None
                                     for option in ("jobs", "shard", "csv", "limit", "summary"))


# options the batch itself handles; every other option given is passed on to each child
BATCH_OPTIONS = {"course", "path", "out", "jobs", "shard", "csv", "limit", "summary", "help"}


def forwarded_options(parser, args) -> List[str]:
    """The command-line options given (not left at their default) that each child must also
    get, rebuilt from the parser's own list of options, so an option added to the command
    is passed on without a change here. Handles flags (``store_true``), single values and
    lists (``nargs``)."""
    forwarded: List[str] = []
    for action in parser._actions:   # pylint: disable=protected-access  (argparse's only list)
        if action.dest in BATCH_OPTIONS or not action.option_strings:
            continue
        value = getattr(args, action.dest, action.default)
        if value == action.default:
            continue
        if action.nargs == 0:
            forwarded.append(action.option_strings[0])
        elif isinstance(value, (list, tuple)):
            forwarded += [action.option_strings[0], *map(str, value)]
        else:
            forwarded += [action.option_strings[0], str(value)]
    return forwarded


def child_command(course: Course, path: str, out: str, options: List[str]) -> List[str]:
    return [ros_run.PYTHON, "-m", "course_grader", course.name, path, "--out", out, *options]


def default_jobs() -> int:
    return len(os.sched_getaffinity(0))


def main(parser, args, course: Course, out: str) -> int:
    """The batch command (cli.main hands over here); 0 once the CSV is written."""
    all_paths = ordered(args.path)
    paths = all_paths
    if args.shard is not None:
        index, count = parse_shard(args.shard)
        paths = select_shard(all_paths, index, count)
        print(f"grade: shard {index}/{count}: {len(paths)} of {len(all_paths)} submissions",
              flush=True)
    folder_names = names(all_paths)
    limit = args.limit if args.limit is not None else submission_limit(course, args.only)
    runner = Runner(args.jobs if args.jobs is not None else default_jobs(), limit,
                    course.limits["stop"],
                    progress=lambda line: print(f"grade: {line}", flush=True))
    options = forwarded_options(parser, args)
    scenarios = args.only or course.scenarios()
    expected = {item.id: item.points for item in course.items if item.scenario in scenarios}
    tasks = []
    for path in paths:
        sub_out = os.path.join(out, folder_names[path])
        tasks.append((Outcome(path, folder_names[path], expected=dict(expected)),
                      child_command(course, path, sub_out, options), sub_out, dict(os.environ)))
    print(f"grade: {len(tasks)} submissions, {runner.jobs} at a time, each within "
          f"{limit:.0f} s; reports under {out}", flush=True)
    started = time.monotonic()
    outcomes = runner.run(tasks)
    csv_path = args.csv or os.path.join(out, "scores.csv")
    write_csv(csv_path, course, outcomes)
    print()
    print(summary(outcomes))
    print()
    if args.summary:
        print(distribution(course, outcomes))
        print()
    print(f"grade: scores written: {csv_path}")
    print(f"grade: {len(outcomes)} submissions in {time.monotonic() - started:.0f} s")
    return 0


def distribution(course: Course, outcomes: List[Outcome]) -> str:
    """The class per item: how many got full, part and no marks, the mean, and how many
    are marked review or platform. An item the platform kept from being graded (marked
    platform) is no score of the student's: it is counted apart, not as a 0. An item that
    nobody passes is flagged: the grader's fault until shown otherwise."""
    rows = []
    for item in course.items:
        graded = [o for o in outcomes if item.id in o.awarded]
        marks = [o.marks.get(item.id) for o in graded]
        scores = [o.awarded[item.id] for o in graded if o.marks.get(item.id) != "platform"]
        if not graded:
            continue
        full = sum(score >= item.points for score in scores)
        none = sum(score == 0 for score in scores)
        mean = f"{sum(scores) / len(scores):.2f}" if scores else "-"
        flag = "  <- nobody has full marks: check the rubric" if full == 0 and \
            len(scores) > 1 else ""
        rows.append((item.id, f"{_points(item.points)}", f"{full}", f"{len(scores) - full - none}",
                     f"{none}", mean, f"{marks.count('review')}", f"{marks.count('platform')}",
                     flag))
    header = ("item", "points", "full", "part", "none", "mean", "review", "platform", "")
    widths = [max(len(str(row[i])) for row in rows + [header]) for i in range(8)]
    lines = ["  ".join(f"{cell:<{w}}" for cell, w in zip(header, widths)).rstrip()]
    lines += ["  ".join(f"{cell:<{w}}" for cell, w in zip(row, widths)).rstrip() + row[8]
              for row in rows]
    return "\n".join(lines)


def summary(outcomes: List[Outcome]) -> str:
    """One line per submission: name, points, status, seconds."""
    width = max([len("submission")] + [len(o.name) for o in outcomes])
    lines = [f"{'submission':<{width}}  awarded  possible  seconds  status",
             f"{'-' * width}  -------  --------  -------  -------"]
    lines += [f"{o.name:<{width}}  {_points(o.total):>7}  {_points(o.possible):>8}  "
              f"{o.seconds:>7.0f}  {o.status}" for o in outcomes]
    return "\n".join(lines)

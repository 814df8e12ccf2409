"""A course's grading guide read from ``config/<course>.yaml``: its packages, commands,
items with their points, the checks' numbers and the time limits. A course may also name
its scenarios (``scenarios:``): which commands each runs, and the function that measures it
(a probe in the simulation's process, or a runner in the grader's for checks that need no
simulation); without that section the grader's built-in RB1 scenarios apply."""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Any, Dict, List, Tuple

import yaml

from course_grader import rubric as rubric_file
from course_grader.rubric import Rubric

CONFIG_DIR = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))), "config")


class CourseError(ValueError):
    """A course name or file that cannot be used; the message names it and why."""


@dataclass(frozen=True)
class Item:
    """One graded item of the guide: points for one thing the student must show, scored
    by its rubric (the guide's sentence, notes, deductions, scale)."""

    id: str
    task: int
    title: str
    points: float
    scenario: str
    rubric: Rubric = Rubric()


@dataclass(frozen=True)
class ScenarioSpec:
    """How one scenario runs: its commands (keys of ``commands``) in order, a topic per
    command that shows it is up before the next is typed, and ``module:function`` of the
    probe (run against the scenario's master) or of the runner (no simulation: files,
    builds). ``display``: the scenario grades windows (rviz, the sliders): its commands run
    as typed, without the headless arguments (every scenario has a virtual screen)."""

    commands: Tuple[str, ...] = ()
    ready: Dict[str, str] = field(default_factory=dict)
    probe: str = ""
    runner: str = ""
    display: bool = False
    # a world its launch file starts paused is unpaused before the probe, as the assignment
    # tells students ("press play"); false where starting paused is what is graded
    unpause: bool = True
    # the probe can measure a run whose launch files start no simulator (MoveIt's fake
    # controllers): the grader reads them (roslaunch) to tell it so
    without_simulator: bool = False


# the report's pictures when the course file has no ``report`` section: the rviz screenshot
# (window title waited for; s (wall) for it to show and settle; s between screenshots;
# screenshots in a row alike; fraction of the pixels that may change between alike ones,
# rviz's frame-rate text) and the samples at most per plotted series
DEFAULT_REPORT = {"screenshot": {"window": "RViz", "timeout": 30.0, "interval": 0.5,
                                 "settle": 2, "change": 0.002},
                  "plot_points": 500}

# the launch arguments given when a launch file declares them: no windows (no DISPLAY is
# given, so the simulator is headless either way)
DEFAULT_HEADLESS_ARGS = {"gui": "false"}


# The RB1 course's built-in scenarios (its file names none): which of the guide's commands
# each scenario runs, in order
SCENARIO_COMMANDS = {"display": ["display"], "spawn": ["warehouse"], "drive": ["warehouse"],
                     "scan": ["warehouse"], "rotate": ["warehouse", "rotate"]}
# a topic that shows a command's launch is up before the next command is typed
READY_TOPIC = {"warehouse": "/odom"}


@dataclass
class Course:
    name: str
    title: str
    packages: List[str]
    commands: Dict[str, Tuple[str, str]]
    items: List[Item]
    limits: Dict[str, float]
    checks: Dict[str, Dict[str, Any]]
    urdf: Dict[str, Any]
    source: str = ""
    # arguments after the launch file in a command ("flip:=true"), by command
    command_args: Dict[str, List[str]] = field(default_factory=dict)
    scenario_specs: Dict[str, ScenarioSpec] = field(default_factory=dict)
    headless_args: Dict[str, str] = field(default_factory=lambda: dict(DEFAULT_HEADLESS_ARGS))
    report: Dict[str, Any] = field(default_factory=lambda: _report_settings({}))
    # scenarios started first when several run at once (--scenario-jobs): the long ones, so
    # that the short ones run beside them instead of after them
    long_scenarios: List[str] = field(default_factory=list)
    # an argument of a command that a submission's launch file may not declare -> (package,
    # a word of the node's name): the node that starts that part by hand instead
    by_hand: Dict[str, Tuple[str, str]] = field(default_factory=dict)
    # arguments that select the real robot ("use_actual:=true"): a README's command line
    # with one of them is not how the grader runs the submission (it has no robot)
    real_robot_args: List[str] = field(default_factory=list)
    # commands that are to put the robot in the world: one whose launch file starts no
    # spawner is followed by the README's launch line that does
    robot_commands: List[str] = field(default_factory=list)

    @property
    def total_points(self) -> float:
        return sum(item.points for item in self.items)

    def scenarios(self) -> List[str]:
        """Scenario names in the order their first item appears in the guide."""
        seen: List[str] = []
        for item in self.items:
            if item.scenario not in seen:
                seen.append(item.scenario)
        return seen

    def items_of(self, scenario: str) -> List[Item]:
        return [item for item in self.items if item.scenario == scenario]

    def start_order(self, scenarios: List[str]) -> List[str]:
        """``scenarios`` in the order to start them: ``long_scenarios`` first (in their
        order), then the rest in the order given."""
        long = [s for s in self.long_scenarios if s in scenarios]
        return long + [s for s in scenarios if s not in long]


def available() -> List[str]:
    return sorted(os.path.splitext(name)[0] for name in os.listdir(CONFIG_DIR)
                  if name.endswith(".yaml"))


def scenario_summary() -> str:
    """Each known course with its scenarios, for the command's help ("rb1: display spawn
    ..."); a course file that cannot be read says so instead of failing the help."""
    parts = []
    for name in available():
        try:
            parts.append(f"{name}: {' '.join(load(name).scenarios())}")
        except CourseError as error:
            parts.append(f"{name}: unreadable ({error})")
    return "; ".join(parts)


def load(name: str) -> Course:
    """The course called ``name`` (``config/<name>.yaml``)."""
    path = os.path.join(CONFIG_DIR, f"{name}.yaml")
    if not os.path.isfile(path):
        raise CourseError(f"no course '{name}': known courses are {', '.join(available())} "
                          f"(files in {CONFIG_DIR})")
    return parse(path)


def parse(path: str) -> Course:
    with open(path, encoding="utf-8") as stream:
        data = yaml.safe_load(stream)
    try:
        items = [Item(id=str(i["id"]), task=int(i["task"]), title=str(i["title"]),
                      points=float(i["points"]), scenario=str(i["scenario"]),
                      rubric=rubric_file.parse(i, f"item '{i.get('id')}'"))
                 for i in data["items"]]
        course = Course(name=str(data["name"]), title=str(data["title"]),
                        packages=[str(p) for p in data["packages"]],
                        commands={k: (str(v[0]), str(v[1])) for k, v in data["commands"].items()},
                        items=items, limits={k: float(v) for k, v in data["limits"].items()},
                        checks=dict(data.get("checks", {})), urdf=dict(data.get("urdf", {})),
                        source=path,
                        command_args={k: [str(a) for a in v[2:]]
                                      for k, v in data["commands"].items()},
                        scenario_specs=_scenario_specs(data.get("scenarios", {})),
                        headless_args={str(k): str(v).lower() if isinstance(v, bool) else str(v)
                                       for k, v in data.get("headless_args",
                                                            DEFAULT_HEADLESS_ARGS).items()},
                        report=_report_settings(data.get("report", {})),
                        long_scenarios=[str(s) for s in data.get("long_scenarios", [])],
                        by_hand={str(k): (str(v[0]), str(v[1]))
                                 for k, v in data.get("by_hand", {}).items()},
                        real_robot_args=[str(a) for a in data.get("real_robot_args", [])],
                        robot_commands=[str(c) for c in data.get("robot_commands", [])])
    except (KeyError, TypeError, ValueError, IndexError) as error:
        raise CourseError(f"{path}: malformed course file ({type(error).__name__}: {error})") \
            from error
    ids = [item.id for item in items]
    if len(set(ids)) != len(ids):
        raise CourseError(f"{path}: item ids repeat: {ids}")
    unquoted = [item.id for item in items if not item.rubric.guide]
    if unquoted:  # an item scores what the guide's sentence says, so it quotes it
        raise CourseError(f"{path}: items {unquoted} quote no sentence of the guide "
                          "('guide:')")
    for item in items:
        taken = sum(d.points for d in item.rubric.deductions)
        if taken > item.points:
            raise CourseError(f"{path}: item '{item.id}' declares deductions of {taken:g} "
                              f"points, more than its {item.points:g}")
    _check_scenarios(course, path)
    unknown = [s for s in course.long_scenarios if s not in course.scenarios()]
    if unknown:
        raise CourseError(f"{path}: long_scenarios names {unknown}, not scenarios of the "
                          f"course's items ({', '.join(course.scenarios())})")
    return course


def _report_settings(data: Dict[str, Any]) -> Dict[str, Any]:
    """The course file's ``report`` section over DEFAULT_REPORT."""
    unknown = set(data) - set(DEFAULT_REPORT)
    if unknown:
        raise ValueError(f"'report' has unknown keys {sorted(unknown)}")
    screenshot = dict(DEFAULT_REPORT["screenshot"], **data.get("screenshot", {}))
    unknown = set(screenshot) - set(DEFAULT_REPORT["screenshot"])
    if unknown:
        raise ValueError(f"'report: screenshot' has unknown keys {sorted(unknown)}")
    points = int(data.get("plot_points", DEFAULT_REPORT["plot_points"]))
    if points < 2:
        raise ValueError(f"'report: plot_points' is {points}: a plot needs at least 2")
    return {"screenshot": screenshot, "plot_points": points}


def _scenario_specs(data: Dict[str, Any]) -> Dict[str, ScenarioSpec]:
    specs = {}
    for name, spec in data.items():
        unknown = set(spec) - {"commands", "ready", "probe", "runner", "display", "unpause",
                               "without_simulator"}
        if unknown:
            raise ValueError(f"scenario '{name}' has unknown keys {sorted(unknown)}")
        specs[str(name)] = ScenarioSpec(
            commands=tuple(str(c) for c in spec.get("commands", [])),
            ready={str(k): str(v) for k, v in spec.get("ready", {}).items()},
            probe=str(spec.get("probe", "")), runner=str(spec.get("runner", "")),
            display=bool(spec.get("display", False)), unpause=bool(spec.get("unpause", True)),
            without_simulator=bool(spec.get("without_simulator", False)))
    return specs


def scenario_spec(course: Course, scenario: str) -> ScenarioSpec:
    """How ``scenario`` runs: the course file's own, or the built-in RB1 scenarios."""
    if course.scenario_specs:
        return course.scenario_specs[scenario]
    commands = SCENARIO_COMMANDS[scenario]
    return ScenarioSpec(commands=tuple(commands),
                        ready={k: t for k, t in READY_TOPIC.items() if k in commands},
                        probe=scenario, display=scenario == "display")


def _check_scenarios(course: Course, path: str) -> None:
    """A course that names its scenarios names every item's, each with one way to measure
    it, and only commands it defines."""
    if not course.scenario_specs:
        return
    for scenario in course.scenarios():
        spec = course.scenario_specs.get(scenario)
        if spec is None:
            raise CourseError(f"{path}: scenario '{scenario}' (of its items) is not under "
                              "'scenarios'")
        if bool(spec.probe) == bool(spec.runner):
            raise CourseError(f"{path}: scenario '{scenario}' needs exactly one of 'probe' "
                              "(in the simulation) and 'runner' (no simulation)")
        if spec.probe and not spec.commands:
            raise CourseError(f"{path}: scenario '{scenario}' has a probe but no commands")
        unknown = [c for c in spec.commands if c not in course.commands]
        if unknown:
            raise CourseError(f"{path}: scenario '{scenario}' runs unknown commands {unknown}")

"""Grades one submission: stage and build it on the platform alone, then run each scenario
of the guide in a fresh simulation (own master, own time limit), judge its items from the
probe's ground-truth measurements, and add task 1's URDF checks as evidence."""
from __future__ import annotations

import importlib
import os
import tempfile
import time
import traceback
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from typing import Callable, Dict, List, Optional, Tuple

from course_grader import (instructions, layout_checks, platform_faults, plots, ros_run,
                           screenshot, submission, urdf_checks)
from course_grader.course import Course, CourseError, ScenarioSpec, scenario_spec
from course_grader.results import Check, Figure, ItemResult, Report, failed_item, judge
from urdf_tools import UrdfError

PACKAGE_DIR = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
REPO = os.path.dirname(PACKAGE_DIR)
PLATFORM_SETUP = os.path.join(REPO, ".ws", "platform", "devel", "setup.bash")
# the node that puts a robot into the world (gazebo_ros's spawn_model), as roslaunch reads it
SPAWNER = ("gazebo_ros", "spawn_model")
# the simulator's node (gazebo_ros's empty_world.launch starts it): a scenario whose launch
# files start none runs without one (MoveIt's fake controllers), and its probe is told so
SIMULATOR = ("gazebo_ros", "gzserver")
RERUN_SUFFIX = "-rerun"   # a scenario run again after a platform fault logs in <its logs>-rerun


def _launch_path(env: Dict[str, str], package: str, launch_file: str) -> str:
    """The submission's launch file (empty when its package is not found)."""
    found = submission.sourced_find(env, package)
    return os.path.join(found, "launch", launch_file) if found else ""


def _headless_args(declared: List[str], headless: Dict[str, str]) -> List[str]:
    """The course's headless arguments (gui:=false) that the launch file declares
    (headless either way: no DISPLAY)."""
    return [f"{name}:={value}" for name, value in headless.items() if name in declared]


@dataclass
class CommandPlan:
    """A guide's command as it runs for this submission: the arguments its launch file
    declares (``declared``), the guide's that it passes, and for each it does not, the node
    that starts that part by hand (or none); the arguments its README types beyond the
    guide's (``readme_args``, those the launch file declares); what was done, in words for
    the report."""

    args: List[str]
    by_hand: List[Tuple[str, str]]     # (package, node)
    notes: List[str]
    declared: List[str]
    readme_args: List[str] = field(default_factory=list)
    # launch files the README runs after this one to put the robot in the world, when this
    # one does not: (package, launch file, the README's arguments, the arguments it declares)
    then: List[Tuple[str, str, List[str], List[str]]] = field(default_factory=list)
    # whether the launch file starts a simulator, as roslaunch reads it (None: unread)
    simulator: Optional[bool] = None

    def command_line(self, headless: List[str]) -> List[str]:
        """What follows the launch file: the headless arguments (a README's ``gui:=true``
        does not open a window where the scenario has no screen), the README's, the
        guide's last (roslaunch takes an argument's last value)."""
        names = {instructions.arg_name(arg) for arg in headless}
        return headless + [a for a in self.readme_args
                           if instructions.arg_name(a) not in names] + self.args


def plan_command(course: Course, key: str, env: Dict[str, str], readmes: List[str],
                 read_simulator: bool = False) -> CommandPlan:
    """Never an argument the submission's launch file does not declare: the guide's
    ``flip:=true`` goes to a launch file with a ``flip`` argument; otherwise the part it
    starts is started by hand (course ``by_hand``), as the submission's README says.
    ``read_simulator``: whether the launch file starts a simulator is read (roslaunch's
    reading, about 0.7 s) into ``simulator``."""
    package, launch_file = course.commands[key]
    path = _launch_path(env, package, launch_file)
    plan = CommandPlan([], [], [], ros_run.declared_args(path))
    read: Dict[Tuple[str, ...], Optional[List[Tuple[str, str]]]] = {}

    def launched() -> Optional[List[Tuple[str, str]]]:
        """The nodes the launch file starts with the arguments passed so far, as roslaunch
        reads them (0.7 s a reading: once per set of arguments)."""
        args = tuple(plan.readme_args + plan.args)
        if args not in read:
            read[args] = ros_run.launched_nodes(env, path, list(args))
        return read[args]

    typed = instructions.readme_args(readmes, package, launch_file,
                                     course.command_args.get(key, []), course.real_robot_args)
    plan.readme_args = [a for a in typed if instructions.arg_name(a) in plan.declared]
    if plan.readme_args:
        plan.notes.append(f"run with the arguments the README types: roslaunch {package} "
                          f"{launch_file} {' '.join(plan.readme_args)}")
    for arg in course.command_args.get(key, []):
        name = instructions.arg_name(arg)
        if name in plan.declared:
            plan.args.append(arg)
            continue
        not_passed = f"{launch_file} declares no '{name}' argument, so '{arg}' was not passed"
        hand = course.by_hand.get(name)
        if hand is None:
            plan.notes.append(not_passed)
            continue
        hand_package, word = hand
        # a launch file that starts the part itself needs no second one by hand (two flip
        # routines fight over cmd_vel)
        own = [kind for pkg, kind in launched() or [] if pkg == hand_package and word in kind]
        if own:
            plan.notes.append(f"{not_passed}; {launch_file} starts {hand_package}/{own[0]} "
                              "itself, so nothing was started by hand")
            continue
        found = submission.sourced_find(env, hand_package)
        node = instructions.node_started_by_hand(
            readmes, hand_package, word,
            layout_checks.runnable_nodes(found) + layout_checks.built_nodes(found)
            if found else [])
        if node:
            plan.by_hand.append((hand_package, node))
            plan.notes.append(f"{not_passed}; the grader ran 'rosrun {hand_package} {node}' "
                              "after it, as the submission's README (or its node's name) says")
        else:
            plan.notes.append(f"{not_passed}, and no node of {hand_package} named for "
                              f"'{word}' was found to run by hand")
    if read_simulator:
        nodes = launched()
        plan.simulator = None if nodes is None else SIMULATOR in nodes
    if key in course.robot_commands and launched() is not None and SPAWNER not in launched():
        _spawn_as_the_readme_goes_on(plan, env, path, readmes)
    return plan


def _spawn_as_the_readme_goes_on(plan: CommandPlan, env: Dict[str, str], path: str,
                                 readmes: List[str]) -> None:
    """A command that is to put the robot in the world (course ``robot_commands``), for a
    launch file that starts no spawner: the README's ``roslaunch`` line whose launch file
    does start one runs after it, as the README tells its user to go on (the world in one
    launch file, the robot in another)."""
    spawner = "/".join(SPAWNER)
    for words in instructions.commands(readmes):
        if words[0] != "roslaunch":
            continue
        other = _launch_path(env, words[1], words[2])
        args = [w for w in words[3:] if ":=" in w]
        if other and other != path and SPAWNER in (ros_run.launched_nodes(env, other, args) or []):
            plan.then.append((words[1], words[2], args, ros_run.declared_args(other)))
            plan.notes.append(f"{os.path.basename(path)} starts no {spawner}: the robot was "
                              f"spawned by 'roslaunch {' '.join(words[1:])}' after it, as the "
                              "submission's README goes on")
            return
    plan.notes.append(f"{os.path.basename(path)} starts no {spawner}, and no launch file the "
                      "README runs does: no robot was spawned")


def call_named(target: str, *args):
    """Calls ``module:function`` (a course file names its measuring functions so)."""
    module_name, _, function = target.partition(":")
    try:
        named = getattr(importlib.import_module(module_name), function)
    except (ImportError, AttributeError) as error:
        raise CourseError(f"the course names '{target}', which cannot be loaded: {error}") \
            from error
    return named(*args)     # what it raises is its own (not a course file's error)


def scenario_results(course: Course, scenario: str, env: Dict[str, str],
                     log_dir: str, out: str = "", readmes: Tuple[str, ...] = (),
                     packages: Tuple[str, ...] = ()) -> List[ItemResult]:
    """``scenario_run`` with the platform's faults told from the submission's
    (``packages``: the submission's own). A run the platform failed (a crash of rviz or of
    the simulator, say) is run once more, as a teaching assistant would, its logs beside
    the first's; the second run's results stand, saying so."""
    results = _platform_faults(scenario_run(course, scenario, env, log_dir, out, readmes),
                               log_dir, packages)
    fault = next((r.platform for r in results if r.platform), "")
    if not fault:
        return results
    rerun_dir = f"{log_dir}{RERUN_SUFFIX}"
    results = _platform_faults(scenario_run(course, scenario, env, rerun_dir, out, readmes),
                               rerun_dir, packages)
    for result in results:
        result.notes.append(f"run twice: the first run failed for the platform ({fault}; "
                            f"logs in {log_dir}); this is the second run's (logs in "
                            f"{rerun_dir})")
    return results


def scenario_run(course: Course, scenario: str, env: Dict[str, str],
                 log_dir: str, out: str = "", readmes: Tuple[str, ...] = ()
                 ) -> List[ItemResult]:
    """Runs ``scenario`` in a fresh simulation; one result per item it judges, with the
    pictures the probe wrote and the plots of its samples (in ``out``, the report's
    folder, when given)."""
    items = course.items_of(scenario)
    spec = scenario_spec(course, scenario)
    started = time.monotonic()
    limit = course.limits["scenario"]
    names = []
    said: List[str] = []      # how the commands were run, when not as the guide types them
    simulators: List[Optional[bool]] = []   # per command: whether it starts a simulator
    session = ros_run.Session(env, log_dir, course.limits)
    try:
        with session:
            session.start_master()
            # every scenario has a screen, as the student's machine has: a launch file
            # that opens rviz or a GUI whatever its arguments is not failed for want of one
            session.start_display()

            def headless(declared: List[str]) -> List[str]:
                return [] if spec.display else _headless_args(declared, course.headless_args)
            for key in spec.commands:
                package, launch_file = course.commands[key]
                names.append(key)
                # a scenario that grades windows (rviz, the sliders) and pictures them runs
                # the command as typed; the others with the headless arguments the launch
                # file declares (gui:=false), as a student on a slow machine would
                plan = plan_command(course, key, env, list(readmes), spec.without_simulator)
                said += plan.notes
                simulators.append(plan.simulator)
                session.launch(key, package, launch_file,
                               plan.command_line(headless(plan.declared)))
                for then_package, then_file, then_args, then_declared in plan.then:
                    names.append(f"{key}_{os.path.splitext(then_file)[0]}")
                    session.launch(names[-1], then_package, then_file,
                                   then_args + headless(then_declared))
                for hand_package, node in plan.by_hand:
                    names.append(f"{key}_{node}")
                    session.rosrun(names[-1], hand_package, node)
                if key in spec.ready and key != spec.commands[-1]:
                    session.wait_for_topic(spec.ready[key], course.limits["startup"])
            remaining = limit - (time.monotonic() - started)
            no_simulator = bool(simulators) and all(s is False for s in simulators)
            answer = session.probe(scenario, course.source, max(1.0, remaining), out,
                                   {ros_run.NO_SIMULATOR_ENV: "1"} if no_simulator else {})
            session.check_alive()
            trouble = session.trouble(names)
    except ros_run.RunError as error:
        trouble = _trouble_after(log_dir, names)
        seconds = time.monotonic() - started
        results = [failed_item(item, str(error), trouble, seconds, said) for item in items]
        if isinstance(error, ros_run.ScenarioLimit):   # not measured: a TA decides
            for result in results:
                result.review.append(f"the grader could not finish measuring: {error}")
        return _with_killed(session, _not_pictured(spec, results, str(error)))
    seconds = time.monotonic() - started
    if "error" in answer:
        return _with_killed(session, _not_pictured(spec, [
            failed_item(item, answer["error"], trouble, seconds, said) for item in items],
            answer["error"]))
    checks, notes = answer.get("checks", {}), answer.get("notes", {})
    results = [judge(item, [Check.from_dict(c) for c in checks.get(item.id, [])],
                     said + notes.get(item.id, []), trouble, seconds) for item in items]
    if out:
        add_figures(results, answer, out)
    return _with_killed(session, results)


def _platform_faults(results: List[ItemResult], log_dir: str,
                     packages: Tuple[str, ...]) -> List[ItemResult]:
    """A scenario that lost points for a fault of the platform (its logs show it, see
    platform_faults): those items are marked "platform", not the student's loss."""
    if all(r.passed for r in results):
        return results
    fault = platform_faults.find(log_dir, packages)
    if fault:
        for result in results:
            if not result.passed:
                result.platform = fault
    return results


def _with_killed(session: ros_run.Session, results: List[ItemResult]) -> List[ItemResult]:
    """Each item of the scenario names the processes its stop had to kill by their tag (a
    node that outlived its launch), so the report shows what was killed; not scored."""
    for result in results:
        result.killed = list(session.strays)
    return results


def _not_pictured(spec: ScenarioSpec, results: List[ItemResult],
                  reason: str) -> List[ItemResult]:
    """A scenario with a screen that failed: its first item says why it has no picture."""
    if spec.display and results:
        results[0].figures.append(Figure("rviz screenshot", missing=(
            f"none: the scenario failed before or while it was measured ({reason})")))
    return results


def add_figures(results: List[ItemResult], answer: Dict, out: str) -> None:
    """The probe's pictures (``figures``: files it wrote into ``out``, or why none) and a
    plot of each of its ``samples`` (written into ``out``), under the items they show."""
    by_id = {r.item.id: r for r in results}
    for item_id, figures in answer.get("figures", {}).items():
        if item_id in by_id:
            by_id[item_id].figures += [Figure.from_dict(f) for f in figures]
    for kind, data in answer.get("samples", {}).items():
        target = by_id.get(data.get("item")) or results[0]
        target.figures.append(plots.draw(kind, data, out))


@dataclass
class RunnerContext:
    """What a runner (a scenario without a simulation) may use: the submission's sourced
    environment, its catkin workspace, what was staged, and a folder for its logs."""

    env: Dict[str, str]
    workspace: str
    staged: submission.Staged
    log_dir: str


def runner_results(course: Course, scenario: str, context: RunnerContext) -> List[ItemResult]:
    """Runs the course's runner for ``scenario`` in this process; one result per item."""
    items = course.items_of(scenario)
    started = time.monotonic()
    os.makedirs(context.log_dir, exist_ok=True)
    try:
        answer = call_named(scenario_spec(course, scenario).runner, course, scenario, context)
    except CourseError:
        raise
    except Exception as error:  # pylint: disable=broad-except
        # a runner answers with checks whatever the submission holds: an exception out of
        # it is the grader's own fault, marked "platform" (nothing scored against the student)
        where = traceback.extract_tb(error.__traceback__)[-1]
        fault = (f"the grader's {scenario} runner raised {type(error).__name__}: {error} "
                 f"({os.path.basename(where.filename)}:{where.lineno})")
        results = [failed_item(item, fault, [], time.monotonic() - started) for item in items]
        for result in results:
            result.platform = fault
        return results
    seconds = time.monotonic() - started
    if "error" in answer:
        return [failed_item(item, answer["error"], answer.get("log", []), seconds)
                for item in items]
    checks, notes, logs = answer.get("checks", {}), answer.get("notes", {}), answer.get("log", {})
    return [judge(item, [Check.from_dict(c) for c in checks.get(item.id, [])],
                  notes.get(item.id, []), logs.get(item.id, []), seconds) for item in items]


def _trouble_after(log_dir: str, names: List[str]) -> List[str]:
    lines: List[str] = []
    for name in names + ["probe"]:
        path = os.path.join(log_dir, f"{name}.log")
        if os.path.isfile(path):
            with open(path, encoding="utf-8", errors="replace") as log:
                lines += [f"{name}: {line.rstrip()}" for line in log
                          if ros_run.TROUBLE.search(line)][-ros_run.LOG_LINES:]
    return lines


def no_screenshot(course: Course, wanted: List[str]) -> List[Figure]:
    """Why the report will have no rviz screenshot, when that is known before anything runs:
    no scenario of the course opens rviz, or the one that does is not among ``wanted``."""
    shown = [s for s in course.scenarios() if scenario_spec(course, s).display]
    if not shown:
        headless = " ".join(f"{k}:={v}" for k, v in course.headless_args.items())
        return [Figure("rviz screenshot", missing=(
            "none: no scenario of this course opens rviz; its launch files run without a "
            f"screen ({headless} where they declare them)"))]
    if not set(shown) & set(wanted):
        return [Figure("rviz screenshot", missing=(
            f"none: the scenario that opens rviz ({', '.join(shown)}) was not run (--only)"))]
    return []


def _forget_pictures(out: str) -> None:
    """Removes the pictures an earlier grading left in ``out`` (a report names only its
    own)."""
    for name in [screenshot.REPORT_FILE] + [f"{kind}.svg" for kind in plots.KINDS]:
        try:
            os.remove(os.path.join(out, name))
        except FileNotFoundError:
            pass


def add_urdf_evidence(course: Course, results: List[ItemResult], description_dir: Optional[str]):
    """Task 1's URDF checks: names, placements and the total mass scored under the display
    item, the wheel joints' type under the wheel item, sizes, inertia and friction as notes."""
    by_id = {r.item.id: r for r in results}
    display, wheels = by_id.get("display_links_tf"), by_id.get("wheel_joints_move")
    path = urdf_checks.find_urdf(description_dir, course.urdf["file"]) if description_dir else None
    try:
        if path is None:
            raise UrdfError(f"no URDF in my_rb1_description (looked for {course.urdf['file']})")
        model = urdf_checks.read(path)
    except (UrdfError, OSError, RuntimeError) as error:
        for result in (display, wheels):
            if result is not None:
                result.checks.append(Check("URDF readable", False, str(error)))
                result.rescore()
        return
    if display is not None:
        display.checks += [*urdf_checks.names(model, course.urdf),
                           *urdf_checks.placements(model, course.urdf),
                           urdf_checks.total_mass(model, course.urdf)]
        display.notes += [f"{'pass' if c.passed else 'FAIL'}: {c.evidence}"
                          for c in urdf_checks.supporting(model, course.urdf)]
    if wheels is not None:
        wheels.checks.append(urdf_checks.wheel_joints(model, course.urdf))
    for result in (display, wheels):
        if result is not None:
            result.rescore()


def grade(course: Course, path: str, out: str, platform_setup: str = PLATFORM_SETUP,
          progress: Callable[[str], None] = lambda line: None,
          scenarios: Optional[List[str]] = None, scenario_jobs: int = 1) -> Report:
    """Grades the submission at ``path`` into ``out``; ``scenario_jobs`` scenarios at once."""
    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix=f"grade_{course.name}_ws_") as workspace:
        return _grade_in(course, path, out, platform_setup, progress, scenarios, workspace,
                         started, scenario_jobs)


def _grade_in(course, path, out, platform_setup, progress, scenarios, workspace, started,
              scenario_jobs):
    """``grade`` with the submission's catkin workspace in ``workspace``: a temporary folder
    outside any source space (inside the repository, say under test_results/, the workspace's
    own build would find the copied my_rb1_* packages twice)."""
    staged = submission.stage(path, course.packages, workspace)
    report = Report(course, os.path.abspath(path), [])
    if staged.revision:
        report.notes.append(f"git commit graded: {staged.revision}")
    if staged.missing:
        report.notes.append(f"packages not found in the submission: {', '.join(staged.missing)}")
    progress(f"staged {', '.join(staged.found) or 'nothing'} in {workspace}")
    platform_env = submission.sourced(platform_setup, submission.clean_environment(dict(os.environ)))
    os.makedirs(out, exist_ok=True)
    built = submission.build(workspace, platform_env, course.limits["build"],
                             os.path.join(out, "catkin_make.log"))
    report.build = built.summary
    progress(built.summary)
    wanted = scenarios or course.scenarios()
    _forget_pictures(out)
    report.figures += no_screenshot(course, wanted)
    if not built.ok:
        report.results = [failed_item(item, built.summary, built.log_tail)
                          for item in course.items if item.scenario in wanted]
        # a package the platform lacks is not the student's loss: the items are marked
        # "platform" (left out of the points possible) and the report says what to install
        lacks = platform_faults.build_lacks(built.not_found, staged.found)
        for result in report.results:
            result.platform = lacks or ""
        report.seconds = time.monotonic() - started
        return report
    env = submission.sourced(os.path.join(workspace, "devel", "setup.bash"),
                             submission.clean_environment(platform_env))
    foreign = submission.resolves_inside(env, list(staged.found), workspace)
    if foreign:
        report.notes += foreign
    # what the submission's READMEs tell its user to type (a node started by hand)
    readmes = tuple(instructions.readme_texts([staged.root, *staged.found.values()]))

    def run(scenario: str) -> List[ItemResult]:
        items = course.items_of(scenario)
        spec = scenario_spec(course, scenario)
        if not spec.runner:
            needed = {course.commands[key][0] for key in spec.commands}
            absent = sorted(needed & set(staged.missing))
            if absent:
                return [failed_item(item, f"the submission has no {', '.join(absent)}")
                        for item in items]
        progress(f"scenario {scenario}: {', '.join(i.id for i in items)}")
        log_dir = os.path.join(out, "logs", scenario)
        if spec.runner:
            results = runner_results(course, scenario,
                                     RunnerContext(env, workspace, staged, log_dir))
        else:
            results = scenario_results(course, scenario, env, log_dir, out, readmes,
                                       tuple(staged.found))
        progress(f"scenario {scenario}: {sum(r.awarded for r in results):g} of "
                 f"{sum(r.item.points for r in results):g} in {results[0].seconds:.0f} s")
        return results

    # each scenario has its own master, ports, logs and pictures: they may run side by side;
    # the long ones start first (the report keeps the course's order: sorted below)
    with ThreadPoolExecutor(max_workers=max(1, scenario_jobs)) as pool:
        for results in pool.map(run, course.start_order(list(wanted))):
            report.results += results
    if course.urdf:
        add_urdf_evidence(course, report.results, staged.found.get("my_rb1_description") and
                          os.path.join(workspace, "src", "my_rb1_description"))
    order = {item.id: index for index, item in enumerate(course.items)}
    report.results.sort(key=lambda r: order[r.item.id])
    report.seconds = time.monotonic() - started
    return report

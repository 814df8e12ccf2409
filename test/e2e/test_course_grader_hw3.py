"""course_grader's second course as a teaching assistant runs it: `rosrun course_grader grade
me495_hw3 PATH` on a copy of the workspace's own diff_drive and arm_move (full marks), and,
with `--only`, on two copies with one fault each of the kinds students make: ddrive.launch
without a `paused` argument loses exactly 'ddrive.launch paused:=true starts paused'; a step
service that answers SUCCESS without planning or moving (so it accepts a target in the
floor) loses exactly the two step items, judged on the simulator's gripper point. The
report plots the flips from the true orientation and says why it has no rviz screenshot.
The three gradings run at once, as separate commands (a teaching assistant's terminals)."""
import os
import re
import shutil
import xml.etree.ElementTree as ET
from concurrent.futures import ThreadPoolExecutor

import pytest
from grading import grade
from hw3_fixtures import make_fixture

PAUSED_ARG = re.compile(r'\s*<arg name="paused" default=[^>]*/>\n')
PAUSED_VALUE = '<arg name="paused" value="$(arg paused)"/>'
# the line of arm_move's mover the step fixture answers before: success, nothing planned
STEP_LINE = "        target = (request.position.x, request.position.y, request.position.z)\n"
STEP_LIE = "        return Codes.SUCCESS, \"step: done\"\n"
FLIP_POINTS = 100         # the flip plot draws at least this many samples of its 20 s
SVG = "{http://www.w3.org/2000/svg}"


def without_paused(submission):
    """ddrive.launch without its ``paused`` argument (the simulator's given false)."""
    launch = os.path.join(submission, "diff_drive", "launch", "ddrive.launch")
    with open(launch, encoding="utf-8") as stream:
        text = stream.read()
    assert len(PAUSED_ARG.findall(text)) == 1 and PAUSED_VALUE in text, \
        "the lines the fixture changes are no longer there"
    text = PAUSED_ARG.sub("\n", text).replace(PAUSED_VALUE, '<arg name="paused" value="false"/>')
    with open(launch, "w", encoding="utf-8") as stream:
        stream.write(text)


def step_lies(submission):
    """The mover's step service answers SUCCESS before planning or moving."""
    mover = os.path.join(submission, "arm_move", "src", "arm_move", "mover.py")
    with open(mover, encoding="utf-8") as stream:
        lines = stream.readlines()
    assert lines.count(STEP_LINE) == 1, "the line the fixture changes is no longer there"
    lines.insert(lines.index(STEP_LINE), STEP_LIE)
    with open(mover, "w", encoding="utf-8") as stream:
        stream.writelines(lines)


# name: (results folder, the fault made in the copy or None, grade's options)
GRADINGS = {"solution": ("solution", None, ("--scenario-jobs", "2")),
            "no_paused": ("no_paused", without_paused, ("--only", "world")),
            "step_lies": ("step_lies", step_lies, ("--only", "step"))}


@pytest.fixture(scope="module")
def gradings(repo, tmp_path_factory):
    """The three gradings at once, each its own command with its own masters and folders (our
    solution's flip scenario takes 25 s at real time, the faulty copies' scenarios 8 s each,
    mostly waiting): name -> a future of (items by id, stdout, seconds, results folder). A
    grading that fails fails the tests that use it."""
    jobs = {}
    for name, (folder, fault, options) in GRADINGS.items():
        submission = make_fixture(repo, None, str(tmp_path_factory.mktemp("hw3") / name))
        if fault is not None:
            fault(submission)
        results = os.path.join(repo, "test_results", "e2e", "course_grader_hw3", folder)
        shutil.rmtree(results, ignore_errors=True)
        jobs[name] = (submission, results, options)
    with ThreadPoolExecutor(max_workers=len(jobs)) as pool:
        yield {name: pool.submit(lambda s, r, o: grade("me495_hw3", s, r, *o) + (r,), *job)
               for name, job in jobs.items()}


@pytest.fixture(scope="module")
def graded_solution(gradings):
    return gradings["solution"].result()


def test_our_solution_gets_full_marks(graded_solution):
    items, stdout, seconds, _ = graded_solution
    print(f"grading our hw3 solution took {seconds:.0f} s")
    assert set(items) == {"layout", "xacro_yaml_gazebo", "world_contents", "ddrive_paused",
                          "flips", "arm_test", "step_floor_error", "step_reachable"}
    for item in items.values():
        assert item["awarded"] == item["points"], (item["id"], item["evidence"])
    assert "catkin_make: ok" in stdout and "resolves to" not in stdout
    assert "grade: 10 of 10 points" in stdout
    # the figures come from the simulator's truth, not from the student's nodes
    assert "from its true orientation" in items["flips"]["evidence"]
    assert "true gripper point" in items["step_reachable"]["evidence"]


def test_a_launch_file_without_paused_loses_exactly_that_item(gradings, graded_solution):
    faulty = gradings["no_paused"].result()[0]
    ours = graded_solution[0]
    assert set(faulty) == {"world_contents", "ddrive_paused"}
    lost = {i for i, item in faulty.items() if item["awarded"] < ours[i]["awarded"]}
    assert lost == {"ddrive_paused"}, {i: faulty[i]["evidence"] for i in faulty}
    assert "does not declare an argument 'paused'" in faulty["ddrive_paused"]["evidence"]


def test_a_step_service_that_always_succeeds_loses_exactly_the_step_items(gradings,
                                                                           graded_solution):
    faulty = gradings["step_lies"].result()[0]
    ours = graded_solution[0]
    assert set(faulty) == {"step_floor_error", "step_reachable"}
    lost = {i for i, item in faulty.items() if item["awarded"] < ours[i]["awarded"]}
    assert lost == {"step_floor_error", "step_reachable"}, \
        {i: faulty[i]["evidence"] for i in faulty}
    assert "answered code 1" in faulty["step_floor_error"]["evidence"]
    assert "mm from the target" in faulty["step_reachable"]["evidence"]


def test_the_report_plots_the_flips_and_says_why_there_is_no_screenshot(graded_solution):
    items, _, _, out = graded_solution
    root = ET.parse(os.path.join(out, "flip.svg")).getroot()
    points = sum(len(line.get("points").split()) for line in root.iter(f"{SVG}polyline"))
    titles = [t.text for t in root.iter(f"{SVG}text")]
    flips = int(items["flips"]["evidence"].split("flipped ")[1].split()[0])
    print(f"flip.svg: {points} points, {flips} flips")
    assert points >= FLIP_POINTS
    assert f"flip: the body's up axis, {flips} flips" in titles
    # each flip is marked by its number above the plot
    assert all(str(n) in titles for n in range(1, flips + 1))
    with open(os.path.join(out, "report.md"), encoding="utf-8") as stream:
        text = stream.read()
    assert "](flip.svg)" in text
    assert "rviz screenshot: none: no scenario of this course opens rviz" in text
    assert not os.path.exists(os.path.join(out, "display.png"))

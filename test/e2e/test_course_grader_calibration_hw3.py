"""course_grader on ME495 homework 3 submissions that are correct by the assignment but
written unlike ours (hw3_fixtures): graded as a teaching assistant grades a class, ``rosrun
course_grader grade me495_hw3 DIR/* --jobs 2 --only <scenarios> --summary``, each must get
full marks on what its batch grades, the report saying what the grader did to run it as
its README says (unpaused a paused world, started the flip node by hand) and how it read
the world (models by their uri)."""
import os

import pytest
from course_grader import course as course_file
from grading import Batch

from hw3_fixtures import CORRECT_BY_THE_ASSIGNMENT, make_fixture

JOBS = 2
# name: (scenarios graded, fixtures); every fixture once
BATCHES = {
    "files_and_world": (("layout", "world"),
                        ("xacro_named_otherwise", "world_models_named_otherwise",
                         "yaml_loaded_the_old_way")),
    "flip": (("layout", "flip"), ("paused_flip_by_hand", "flip_started_by_the_launch")),
    "arm": (("layout", "arm_test", "step"), ("arm_move_written_otherwise",
                                              "arm_readme_says_use_fake")),
}
# graded by make soak (test/soak/test_course_grader_hw3_soak.py, which checks their reports'
# notes too), to keep make test within its 15 minutes: two flip fixtures are one round of two
# jobs (44 s on a fresh clone), four were two; the two left here are the flip node started
# by hand in a paused world and by the student's launch, the two ways the others combine
SOAK_ONLY = ("nodes_not_executable", "flip_node_found_by_name", "robot_in_its_own_launch")
# what the report of a flip fixture graded by make soak must say about how it was run
SOAK_NOTES = {
    "flip_node_found_by_name": ("flips", "'rosrun diff_drive flipper'"),
    "robot_in_its_own_launch": ("flips", "the robot was spawned by 'roslaunch diff_drive "
                                         "robot.launch' after it"),
}
RESULTS = os.path.join("test_results", "e2e", "course_grader", "calibration_hw3")


class CalibrationBatch(Batch):
    def __init__(self, repo, folder, name):
        self.scenarios, fixtures = BATCHES[name]
        submissions = [make_fixture(repo, f, os.path.join(folder, f)) for f in fixtures]
        super().__init__("me495_hw3", submissions, os.path.join(repo, RESULTS, name),
                         "--jobs", str(JOBS), "--only", *self.scenarios, "--summary")


@pytest.fixture(scope="module")
def batches(repo, tmp_path_factory):
    folder = tmp_path_factory.mktemp("hw3_calibration")
    return {name: CalibrationBatch(repo, str(folder / name), name) for name in BATCHES}


def batch_of(fixture):
    return next(name for name, (_, fixtures) in BATCHES.items() if fixture in fixtures)


def notes(item):
    return item["notes"] + item["beyond_the_guide"]


def test_every_fixture_is_graded_once():
    placed = [f for _, fixtures in BATCHES.values() for f in fixtures]
    assert sorted(placed + list(SOAK_ONLY)) == sorted(CORRECT_BY_THE_ASSIGNMENT)


@pytest.mark.parametrize("fixture", [f for f in CORRECT_BY_THE_ASSIGNMENT if f not in SOAK_ONLY])
def test_a_submission_correct_by_the_assignment_gets_full_marks(batches, fixture):
    batch = batches[batch_of(fixture)]
    hw3 = course_file.load("me495_hw3")
    graded = [item for item in hw3.items if item.scenario in batch.scenarios]
    items = batch.items(fixture)
    evidence = "\n".join(f"  {i}: {item['awarded']:g}/{item['points']:g}  {item['evidence']}"
                         for i, item in sorted(items.items()))
    print(f"{fixture}: {CORRECT_BY_THE_ASSIGNMENT[fixture].what}\n{evidence}")
    assert {i: items[i]["awarded"] for i in items} == \
        CORRECT_BY_THE_ASSIGNMENT[fixture].expected(graded), evidence
    assert batch.rows[fixture]["status"] == "graded"


def test_the_report_says_how_the_submission_was_run(batches):
    flip = batches["flip"]
    paused = flip.items("paused_flip_by_hand")["flips"]
    assert any("the world started paused" in n for n in notes(paused)), notes(paused)
    assert any("'rosrun diff_drive flip'" in n for n in notes(paused)), notes(paused)
    by_launch = flip.items("flip_started_by_the_launch")["flips"]
    assert any("ddrive.launch starts diff_drive/flip itself, so nothing was started by hand"
               in n for n in notes(by_launch)), notes(by_launch)
    fake = batches["arm"].items("arm_readme_says_use_fake")["step_floor_error"]
    assert any("roslaunch arm_move arm.launch use_fake:=true" in n for n in notes(fake)), \
        notes(fake)
    world = batches["files_and_world"].items("world_models_named_otherwise")["world_contents"]
    assert "wall_north_1 (model://jersey_barrier)" in world["evidence"], world["evidence"]


def test_the_summary_gives_the_class_per_item(batches):
    out = batches["flip"].stdout
    assert "item" in out and "full  part  none  mean" in out
    assert "flips" in out and "nobody has full marks" not in out

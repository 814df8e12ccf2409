"""make soak: the ME495 homework 3 calibration fixtures that make test leaves out
(test/e2e/test_course_grader_calibration_hw3.py's SOAK_ONLY), each graded alone as a
teaching assistant grades one, ``rosrun course_grader grade me495_hw3 PATH --only <its
scenarios>``: full marks on what it is graded on, and the report saying how it was run
(SOAK_NOTES)."""
import os
import sys

import pytest

E2E = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "e2e")
sys.path.insert(0, E2E)
from grading import grade  # noqa: E402  (in test/e2e, not a package)
from hw3_fixtures import CORRECT_BY_THE_ASSIGNMENT, make_fixture  # noqa: E402
from test_course_grader_calibration_hw3 import SOAK_NOTES, SOAK_ONLY, notes  # noqa: E402

RESULTS = ("test_results", "soak", "course_grader", "calibration_hw3")


@pytest.mark.parametrize("name", SOAK_ONLY)
def test_a_submission_correct_by_the_assignment_gets_full_marks(name, repo, tmp_path):
    from course_grader import course as course_file
    fixture = CORRECT_BY_THE_ASSIGNMENT[name]
    submission = make_fixture(repo, name, str(tmp_path / name))
    items, _, seconds = grade("me495_hw3", submission, os.path.join(repo, *RESULTS, name),
                              "--only", *fixture.scenarios)
    print(f"{name}: {fixture.what}; {seconds:.0f} s")
    graded = [item for item in course_file.load("me495_hw3").items if item.id in items]
    assert {i: items[i]["awarded"] for i in items} == fixture.expected(graded), items
    if name in SOAK_NOTES:
        item, said = SOAK_NOTES[name]
        assert any(said in n for n in notes(items[item])), notes(items[item])

"""make soak: course_grader on faulty RB1 submissions (test/e2e/rb1_fault_fixtures.py) one at
a time. make test grades the same fixtures in batches (test/e2e/test_course_grader_faults.py)
and holds them to the table; this run shows the table is what one-at-a-time grading gives.
Each fixture is a copy of our solution with one fault, graded as a teaching assistant runs it,
``rosrun course_grader grade rb1 PATH --out DIR --only <the scenarios its fault touches>``;
the items it loses must be exactly the table's (our solution, the baseline, scores full
marks: test_course_grader.py), each with the figure measured. The C++ rotate service scores full marks; the submission that does
not build scores 0 everywhere with its build error as the evidence; the hanging node is killed
at the scenario limit and the scenario after it is graded as usual."""
import os
import shutil
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                "e2e"))
import rb1_fault_fixtures as fixtures  # noqa: E402  (in test/e2e, not a package)
from grading import grade  # noqa: E402

RESULTS = ("test_results", "soak", "course_grader")


def grade_fixture(submission, out, scenarios, scenario_limit=None):
    shutil.rmtree(out, ignore_errors=True)
    options = ["--only", *scenarios]
    if scenario_limit is not None:
        options += ["--scenario-limit", str(scenario_limit)]
    items, _, seconds = grade("rb1", submission, out, *options)
    return items, seconds


def evidence(items):
    return "\n".join(f"  {i}: {item['awarded']:g}/{item['points']:g}  {item['evidence']}"
                     for i, item in sorted(items.items()))


@pytest.mark.parametrize("name", list(fixtures.ALL_FIXTURES))
def test_a_fault_gets_exactly_its_points(name, repo, tmp_path):
    fault = fixtures.ALL_FIXTURES[name]
    submission = fixtures.make_fixture(repo, name, str(tmp_path / "submission"))
    out = os.path.join(repo, *RESULTS, f"fault_{name}")
    items, seconds = grade_fixture(submission, out, fault.scenarios, fault.scenario_limit)
    print(f"{name}: {fault.what}; graded --only {' '.join(fault.scenarios)} in {seconds:.0f} s")
    print(evidence(items))
    assert set(items) == {i for i in fixtures.ALL_ITEMS
                          if any(i in scenario_items(s) for s in fault.scenarios)}
    from course_grader import course as course_file
    graded = [item for item in course_file.load("rb1").items if item.id in items]
    for item in graded:
        slack = fixtures.SCALED_SLACK if item.rubric.scale else 0.0
        assert items[item.id]["awarded"] == pytest.approx(
            fault.expected(graded)[item.id], abs=slack + 1e-9), evidence(items)
    fixtures.check_evidence(name, items, fault.scenario_limit)
    if name == "node_hangs":
        assert not fixtures.processes_mentioning(out), "processes of the hung scenario left"


def scenario_items(scenario):
    from course_grader import course as course_file
    return {item.id for item in course_file.load("rb1").items_of(scenario)}

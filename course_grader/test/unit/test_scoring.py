"""course_grader without a master: the course file, all-or-nothing judging, totals, the
table and the Markdown/JSON reports, and the ground-truth figures (unwrapping, when a turn
stopped, stillness, answering success when done)."""
import json
import math

import pytest

from course_grader import course as course_file
from course_grader import report
from course_grader.measures import Rotation, inside, is_still, stop_time, tilt_degrees, unwrap
from course_grader.results import Check, Report, failed_item, judge


@pytest.fixture(scope="module")
def rb1():
    return course_file.load("rb1")


def test_rb1_items_and_points_are_the_guides(rb1):
    points = {item.id: item.points for item in rb1.items}
    assert points == {"display_links_tf": 2.25, "wheel_joints_move": 0.75,
                      "spawn_in_start_square": 1.5, "cmd_vel_moves": 0.75, "scan_readable": 0.75,
                      "rotate_degrees": 2.0, "rotate_uses_odom": 1.0,
                      "rotate_answers_success": 1.0}
    assert rb1.total_points == pytest.approx(10.0)
    assert rb1.scenarios() == ["display", "spawn", "drive", "scan", "rotate"]
    assert [i.task for i in rb1.items_of("rotate")] == [4, 4, 4]


def test_long_scenarios_start_first_and_the_rest_keep_the_course_order(rb1):
    assert rb1.start_order(rb1.scenarios()) == ["rotate", "display", "spawn", "drive", "scan"]
    assert rb1.start_order(["spawn", "display"]) == ["spawn", "display"]   # --only, no rotate
    hw3 = course_file.load("me495_hw3")
    assert hw3.start_order(hw3.scenarios())[0] == "flip"


def test_a_long_scenario_that_is_no_scenario_is_named(tmp_path):
    with open(course_file.load("rb1").source, encoding="utf-8") as stream:
        text = stream.read()
    path = tmp_path / "rb1_typo.yaml"
    path.write_text(text.replace("long_scenarios: [rotate]", "long_scenarios: [rotat]"))
    with pytest.raises(course_file.CourseError, match=r"long_scenarios names \['rotat'\]"):
        course_file.parse(str(path))


def test_unknown_course_names_the_known_ones():
    with pytest.raises(course_file.CourseError, match="no course 'rb2'.*rb1"):
        course_file.load("rb2")


def test_malformed_course_file_is_named(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text("name: bad\nitems: [{id: a}]\n")
    with pytest.raises(course_file.CourseError, match="bad.yaml: malformed"):
        course_file.parse(str(path))


def test_an_item_scores_all_or_nothing(rb1):
    item = rb1.items[0]
    assert judge(item, [Check("a", True, "x"), Check("b", True, "y")]).awarded == item.points
    failed = judge(item, [Check("a", True, "x"), Check("b", False, "y")], log=["boom"])
    assert failed.awarded == 0 and failed.log == ["boom"] and failed.evidence() == "x; y"
    assert judge(item, []).awarded == 0          # nothing measured is no points
    assert judge(item, [Check("a", True, "x")], log=["noise"]).log == []


def sample_report(rb1):
    results = [judge(item, [Check("c", True, f"{item.id} measured")]) for item in rb1.items]
    results[2] = failed_item(rb1.items[2], "roslaunch ended (exit status 1)",
                             ["warehouse: [ERROR] Resource not found: rb1_base_gazebo"])
    return Report(rb1, "/tmp/submission", results, build="catkin_make: ok", seconds=42.0)


def test_totals_table_and_reports(rb1, tmp_path):
    graded = sample_report(rb1)
    assert graded.awarded == pytest.approx(8.5) and graded.possible == pytest.approx(10.0)
    text = report.table(graded)
    assert "2. spawned inside the taped starting square" in text
    assert "total" in text and "8.5" in text
    assert "| warehouse: [ERROR] Resource not found: rb1_base_gazebo" in text
    md_path, json_path = report.write(graded, str(tmp_path))
    data = json.loads(open(json_path, encoding="utf-8").read())
    assert data["awarded"] == 8.5 and data["possible"] == 10.0
    spawn = [i for i in data["items"] if i["id"] == "spawn_in_start_square"][0]
    assert spawn["awarded"] == 0 and "exit status 1" in spawn["evidence"]
    assert "**8.5 of 10**" in open(md_path, encoding="utf-8").read()


def test_numpy_bools_become_json_bools():
    import numpy as np
    assert json.dumps(Check("a", np.bool_(True), 1.5).__dict__) == \
        '{"name": "a", "passed": true, "evidence": "1.5"}'


def test_unwrap_counts_across_the_seam():
    yaw = None
    for raw in (3.0, -3.0, -2.0):
        yaw = unwrap(yaw, raw)
    assert yaw == pytest.approx(-2.0 + 2 * math.pi)
    assert unwrap(None, 1.0) == 1.0


def test_stillness_and_stop_time():
    turning = [(t / 10, 0.1 * t) for t in range(20)] + [(2.0 + t / 10, 1.9) for t in range(10)]
    assert stop_time(turning, math.radians(0.5)) == pytest.approx(1.9)
    assert is_still(turning, window=0.5, speed=0.02)
    assert not is_still(turning[:20], window=0.5, speed=0.02)
    assert not is_still(turning[:2], window=0.5, speed=0.02)   # too short to tell


def test_success_only_counts_when_the_turn_is_done():
    done = Rotation(90, 89.8, "success: rotated 90", answered_at=10.2, stopped_at=10.0)
    assert done.turned_ok(5) and done.answered_when_done(5, 0.25)
    early = Rotation(90, 89.8, "success", answered_at=8.0, stopped_at=10.0)
    assert not early.answered_when_done(5, 0.25)        # answered while turning
    lied = Rotation(90, 0.1, "success: rotated 90", answered_at=1.0, stopped_at=0.0)
    assert not lied.turned_ok(5) and not lied.answered_when_done(5, 0.25)
    assert not Rotation(90, 90, "failure: blocked", 5, 4).answered_when_done(5, 0.25)


def test_square_and_tilt():
    assert inside(-0.4, (-0.896, 0.028)) and not inside(-5.0, (-0.896, 0.028))
    assert tilt_degrees(0, 0, 0, 1) == pytest.approx(0)
    half = math.sqrt(0.5)
    assert tilt_degrees(half, 0, 0, half) == pytest.approx(90)

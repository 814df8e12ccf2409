"""course_grader without a master: the course file, judging by the rubric (parts, scales,
notes, deductions, review), totals, the table and the Markdown/JSON reports, and the
ground-truth figures (unwrapping, when a turn stopped, stillness, answering success when
done)."""
import json
import math

import pytest

from course_grader import course as course_file
from course_grader import report
from course_grader.measures import (Rotation, distance_outside, inside, is_still, stop_time,
                                    tilt_degrees, unwrap)
from course_grader.results import Check, Report, failed_item, judge
from course_grader.rubric import Deduction, Rubric, Scale


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


def test_an_items_checks_are_its_parts(rb1):
    item = rb1.items[0]
    assert judge(item, [Check("a", True, "x"), Check("b", True, "y")]).awarded == item.points
    failed = judge(item, [Check("a", True, "x"), Check("b", False, "y")], log=["boom"])
    assert failed.awarded == pytest.approx(item.points / 2)
    assert failed.log == ["boom"] and failed.evidence() == "x; y"
    assert judge(item, []).awarded == 0          # nothing measured is no points
    assert judge(item, [Check("a", True, "x")], log=["noise"]).log == []


def test_every_item_quotes_the_guide_and_a_file_without_one_is_refused(rb1, tmp_path):
    assert all(item.rubric.guide for item in rb1.items)
    assert rb1.items[0].rubric.guide == ("You can visualize all the robot links correctly, as "
                                         "well as the TFs.")
    with open(rb1.source, encoding="utf-8") as stream:
        text = stream.read()
    path = tmp_path / "unquoted.yaml"
    path.write_text(text.replace('    guide: "The service answers success when done."\n', ""))
    with pytest.raises(course_file.CourseError, match=r"\['rotate_answers_success'\] quote no"):
        course_file.parse(str(path))


def item_with(rubric, points=2.0):
    return course_file.Item("x", 1, "x", points, "s", rubric)


def test_a_scale_scores_an_error_linearly_and_marks_figures_near_its_bounds():
    scale = Scale(5.0, 30.0, "deg")
    assert [scale.share(v) for v in (0, 5, -5, 17.5, 30, 45)] == [1, 1, 1, 0.5, 0, 0]
    assert scale.share(6.2) == pytest.approx(23.8 / 25)
    assert [scale.near_bound(v) for v in (0, 3.9, 4.5, 6.0, 6.1, 23.9, 24, 36, 37)] == [
        False, False, True, True, False, False, True, True, False]
    square = Scale(0.0, 0.3, "m")          # a bound of 0: only just outside is near it
    assert not square.near_bound(0.0) and square.near_bound(0.05) and not square.near_bound(0.1)
    with pytest.raises(ValueError):
        Scale(5.0, 5.0)


def test_a_scaled_item_scores_each_part_and_asks_for_review_near_a_bound():
    item = item_with(Rubric("Turns as asked.", scale=Scale(5.0, 30.0, "deg")))
    result = judge(item, [Check("rotate -90", False, "turned -95.8", 5.8),
                          Check("rotate +270", True, "turned 270.1", 0.1),
                          Check("rotate +360", True, "turned 359", 1.0)])
    assert result.awarded == pytest.approx(2.0 * (24.2 / 25 + 1 + 1) / 3, abs=1e-4)
    assert result.mark == "review" and "rotate -90: 5.8 deg" in result.review[0]
    clear = judge(item, [Check("rotate -90", False, "turned -96.2", 6.2)])   # 24% past 5
    assert clear.mark == "" and clear.awarded == pytest.approx(2.0 * 23.8 / 25, abs=1e-4)


def test_notes_score_nothing_and_deductions_take_their_points():
    rubric = Rubric("Shows the links.", notes=("joint names",),
                    deductions=(Deduction("total mass", 0.5, "25 kg (guide, task 1)"),))
    item = item_with(rubric)
    result = judge(item, [Check("link names", True, "7 links"),
                          Check("joint names", False, "joints not named as the guide"),
                          Check("total mass", False, "26 kg in all")])
    assert result.parts == [("link names", 1.0)]
    assert result.awarded == pytest.approx(1.5)
    assert result.deducted == [("25 kg (guide, task 1)", 0.5, "26 kg in all")]
    assert result.beyond == ["FAIL (not scored: beyond the guide's sentence): joints not named "
                             "as the guide"]
    text = report.table(Report(course_file.load("rb1"), "/s", [result]))
    assert "deducted 0.5: 25 kg (guide, task 1): 26 kg in all" in text
    only_failed_deduction = judge(item, [Check("total mass", False, "99 kg")])
    assert only_failed_deduction.awarded == 0        # no part measured: nothing, not -0.5


def test_the_rb1_rubric_takes_joint_names_mass_and_tilt_as_notes(rb1):
    display = next(i for i in rb1.items if i.id == "display_links_tf")
    result = judge(display, [Check("TF of every link as the URDF", True, "7 of 7"),
                             Check("link names", True, "7 links"),
                             Check("joint names", False, "base_link_to_left_wheel ..."),
                             Check("total mass", False, "26 kg in all (guide 25)")])
    assert result.awarded == display.points
    spawn = next(i for i in rb1.items if i.id == "spawn_in_start_square")
    tilted = judge(spawn, [Check("inside the start square", True, "inside", 0.0),
                           Check("standing", False, "tilted 5.7 deg (at most 5)")])
    assert tilted.awarded == spawn.points and tilted.mark == ""
    near = judge(spawn, [Check("inside the start square", False, "0.15 m outside", 0.15)])
    assert near.awarded == pytest.approx(0.75)


def test_a_report_shows_a_partial_score_and_its_review_mark(rb1, tmp_path):
    rotate = next(i for i in rb1.items if i.id == "rotate_degrees")
    result = judge(rotate, [Check("rotate -90", False, "asked -90 deg, turned -95.8", 5.8)])
    graded = Report(rb1, "/s", [result])
    assert "1.936 review" in report.table(graded)
    md_path, json_path = report.write(graded, str(tmp_path))
    item = json.loads(open(json_path, encoding="utf-8").read())["items"][0]
    assert item["mark"] == "review" and item["awarded"] == pytest.approx(1.936)
    assert item["guide"] == "The robot rotates for the specified amount of degrees."
    markdown = open(md_path, encoding="utf-8").read()
    assert "| 1.936 review |" in markdown and "**review**: rotate -90" in markdown


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
        '{"name": "a", "passed": true, "evidence": "1.5", "value": null, "review": ""}'


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


def test_success_counts_when_answered_once_the_robot_stopped():
    done = Rotation(90, 89.8, "success: rotated 90", answered_at=10.2, stopped_at=10.0)
    assert done.turned_ok(5) and done.answered_when_done(0.25, 30)
    early = Rotation(90, 89.8, "success", answered_at=8.0, stopped_at=10.0)
    assert not early.answered_when_done(0.25, 30)        # answered while turning
    short = Rotation(-90, -96.2, "success: rotated -90", answered_at=5.0, stopped_at=4.9)
    assert not short.turned_ok(5) and short.answered_when_done(0.25, 30)  # done, if not closely
    lied = Rotation(90, 0.1, "success: rotated 90", answered_at=1.0, stopped_at=0.0)
    assert not lied.answered_when_done(0.25, 30)         # not done at all
    assert not Rotation(90, 90, "failure: blocked", 5, 4).answered_when_done(0.25, 30)


def test_square_and_tilt():
    assert inside(-0.4, (-0.896, 0.028)) and not inside(-5.0, (-0.896, 0.028))
    assert distance_outside(-0.4, -1.0, (-0.896, 0.028), (-1.712, -0.933)) == 0.0
    assert distance_outside(0.328, -0.533, (-0.896, 0.028), (-1.712, -0.933)) == \
        pytest.approx(0.5)
    assert tilt_degrees(0, 0, 0, 1) == pytest.approx(0)
    half = math.sqrt(0.5)
    assert tilt_degrees(half, 0, 0, half) == pytest.approx(90)

"""A scenario that failed for the platform's fault is told from one the submission failed:
a traceback raised in the platform's code, or a package the platform lacks, marks the lost
items "platform"; they leave the points possible and the grade is incomplete."""
import os

from course_grader import course as course_file
from course_grader import grader, platform_faults, report
from course_grader.results import Check, Report, judge

SIM = os.path.join(platform_faults.REPO, "sim_bridge", "src", "sim_bridge", "world.py")


def traceback(*frames, exception="RuntimeError: boom"):
    return "\n".join(["[ERROR] something went wrong", "Traceback (most recent call last):",
                      *(f'  File "{path}", line {line}, in f\n    code()' for path, line in frames),
                      exception, "[INFO] shutting down"]) + "\n"


def test_a_traceback_raised_in_the_platform_is_the_platforms(tmp_path):
    (tmp_path / "warehouse.log").write_text(
        traceback(("/tmp/student/rotate.py", 3), (SIM, 120), exception="KeyError: 'base'"))
    found = platform_faults.find(str(tmp_path), ["my_rb1_ros"])
    assert "sim_bridge/src/sim_bridge/world.py:120: KeyError: 'base'" in found
    assert "warehouse.log" in found


def test_a_traceback_in_the_students_code_is_theirs(tmp_path):
    (tmp_path / "rotate.log").write_text(
        traceback((SIM, 10), ("/tmp/student/src/my_rb1_ros/rotate.py", 42)))
    assert platform_faults.find(str(tmp_path), ["my_rb1_ros"]) is None


def test_a_package_the_platform_lacks_is_the_platforms(tmp_path):
    (tmp_path / "warehouse.log").write_text(
        "[ERROR] Resource not found: my_rb1_gazebo\n")     # the student's own: theirs
    assert platform_faults.find(str(tmp_path), ["my_rb1_gazebo"]) is None
    (tmp_path / "warehouse.log").write_text("RLException: [x.launch] ... \n"
                                            "Resource not found: husky_gazebo\n")
    assert "no package 'husky_gazebo'" in platform_faults.find(str(tmp_path), ["my_rb1_gazebo"])


def test_platform_items_leave_the_points_possible_and_the_grade_is_incomplete(tmp_path):
    rb1 = course_file.load("rb1")
    (tmp_path / "probe.log").write_text(traceback((SIM, 7)))
    rotate = [judge(item, [Check("c", False, "no answer")]) for item in rb1.items_of("rotate")]
    scan = judge(rb1.items_of("scan")[0], [Check("c", True, "a scan")])
    grader._platform_faults(rotate, str(tmp_path), ("my_rb1_ros",))
    graded = Report(rb1, "/s", rotate + [scan])
    assert all(r.mark == "platform" for r in rotate)
    assert graded.possible == scan.item.points and graded.incomplete
    assert "incomplete" in report.table(graded)
    assert "platform: a traceback in the grading platform" in report.table(graded)
    untouched = [judge(item, [Check("c", True, "ok")]) for item in rb1.items_of("rotate")]
    grader._platform_faults(untouched, str(tmp_path), ())
    assert not any(r.platform for r in untouched)       # nothing lost: nothing to excuse

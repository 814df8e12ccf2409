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


def test_a_platform_program_killed_by_a_signal_is_the_platforms(tmp_path):
    """rviz crashing under the virtual screen (a required node: its launch ends) is not the
    student's; their own node killed by a signal, or rviz ending with a status, is."""
    died = "[rviz-3] process has died [pid 22396, exit code {code}, cmd {cmd} -d x.rviz]\n"
    (tmp_path / "display.log").write_text(died.format(code=-11, cmd="/usr/lib/rviz/rviz"))
    found = platform_faults.find(str(tmp_path), ["my_rb1_description"])
    assert "killed by a signal: rviz-3 (exit code -11, /usr/lib/rviz/rviz)" in found
    student = "/tmp/ws/src/my_rb1_ros/nodes/rotate_service"
    (tmp_path / "display.log").write_text(died.format(code=-11, cmd=student))
    assert platform_faults.find(str(tmp_path), ["my_rb1_ros"]) is None
    (tmp_path / "display.log").write_text(died.format(code=1, cmd="/usr/lib/rviz/rviz"))
    assert platform_faults.find(str(tmp_path), ["my_rb1_description"]) is None


def test_a_required_platform_program_killed_by_a_signal_is_the_platforms(tmp_path):
    """roslaunch words a required node's death on two lines (the last CI run's rviz, killed
    by glibc's heap check under software rendering, as display.launch files mark it)."""
    died = ("\x1b[31m" + "=" * 80 + "REQUIRED process [rviz-4] has died!\n"
            "process has died [pid 18738, exit code {code}, cmd {cmd} -d x.rviz __name:=rviz]."
            "\nInitiating shutdown!\n")
    (tmp_path / "display.log").write_text(died.format(code=-6, cmd="/usr/lib/rviz/rviz"))
    found = platform_faults.find(str(tmp_path), ["my_rb1_description"])
    assert "killed by a signal: rviz-4 (exit code -6, /usr/lib/rviz/rviz)" in found
    student = "/tmp/ws/src/my_rb1_ros/nodes/rotate_service"
    (tmp_path / "display.log").write_text(died.format(code=-6, cmd=student))
    assert platform_faults.find(str(tmp_path), ["my_rb1_ros"]) is None
    (tmp_path / "display.log").write_text(died.format(code=1, cmd="/usr/lib/rviz/rviz"))
    assert platform_faults.find(str(tmp_path), ["my_rb1_description"]) is None


def test_a_scenario_the_platform_failed_is_run_once_more(tmp_path, monkeypatch):
    """The second run's results stand, saying that the first run failed and where its logs
    are; a run that failed for the submission's fault is not repeated."""
    rb1 = course_file.load("rb1")
    runs = []

    def run(course, scenario, env, log_dir, out="", readmes=()):
        runs.append(log_dir)
        os.makedirs(log_dir, exist_ok=True)
        if len(runs) == 1:
            with open(os.path.join(log_dir, "display.log"), "w", encoding="utf-8") as log:
                log.write("[rviz-3] process has died [pid 1, exit code -6, cmd /usr/bin/rviz]\n")
            return [judge(item, [Check("c", False, "ended")]) for item in rb1.items_of(scenario)]
        return [judge(item, [Check("c", True, "ok")]) for item in rb1.items_of(scenario)]
    monkeypatch.setattr(grader, "scenario_run", run)
    results = grader.scenario_results(rb1, "display", {}, str(tmp_path / "display"))
    assert runs == [str(tmp_path / "display"), str(tmp_path / "display") + grader.RERUN_SUFFIX]
    assert all(r.passed and not r.platform for r in results)
    assert all("run twice: the first run failed for the platform" in r.notes[-1]
               for r in results)
    runs.clear()
    grader.scenario_results(rb1, "display", {}, str(tmp_path / "again"))
    assert len(runs) == 2          # the first run of this folder failed again for the platform
    student = tmp_path / "student"
    runs.clear()
    monkeypatch.setattr(grader, "scenario_run", lambda course, scenario, env, log_dir, *a: (
        runs.append(log_dir) or [judge(i, [Check("c", False, "wrong")])
                                 for i in rb1.items_of(scenario)]))
    grader.scenario_results(rb1, "display", {}, str(student))
    assert len(runs) == 1


# CMake's words (3.25, Debian bookworm) for catkin COMPONENTS it did not find, wrapped as
# CMake wraps them, and for find_package(X REQUIRED)
CATKIN_COMPONENT = """-- Could NOT find turtle_actionlib (missing: turtle_actionlib_DIR)
-- Could not find the required component 'turtle_actionlib'. The following CMake error indicates that you either need to install the package with the same name or change your environment so that it can be found.
CMake Error at /usr/share/catkin/cmake/catkinConfig.cmake:83 (find_package):
  Could not find a package configuration file provided by
  "turtle_actionlib" with any of the following names:

    turtle_actionlibConfig.cmake
    turtle_actionlib-config.cmake
"""
DIRECT = """CMake Error at CMakeLists.txt:12 (find_package):
  By not providing "Findmy_msgs.cmake" in CMAKE_MODULE_PATH this project has
  asked CMake to find a package configuration file provided by "my_msgs", but
  CMake did not find one.
"""


def test_a_build_stopped_at_a_package_the_platform_lacks_is_the_platforms():
    """Issue 31: a submission whose CMakeLists.txt finds turtle_actionlib (the student's machine
    has it) is not the student's 0: the platform lacks it, named with what to install."""
    from course_grader.submission import packages_not_found
    lines = (CATKIN_COMPONENT + DIRECT + CATKIN_COMPONENT).splitlines()
    assert packages_not_found(lines) == ["turtle_actionlib", "my_msgs"]
    lacks = platform_faults.build_lacks(["turtle_actionlib", "my_msgs"],
                                        ["diff_drive", "my_msgs"])
    assert "no package 'turtle_actionlib', which the submission's build finds" in lacks
    assert "install it where the grader runs (on ROS Noetic: ros-noetic-turtle-actionlib)" in lacks
    # a package of the submission's own that did not build is the submission's
    assert platform_faults.build_lacks(["my_msgs"], ["my_msgs"]) is None
    assert platform_faults.build_lacks([], ["diff_drive"]) is None

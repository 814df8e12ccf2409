"""ME495 homework 3's checks that need no master: the layout and the xacro + yaml +
.gazebo checks on copies of the workspace's own diff_drive and arm_move (each fault of the
kinds students make fails the check it belongs to, naming it), arm.test's JUnit result,
flips counted from the up axis, travel and rest, and the step request filled whatever its
field layout."""
import os
import shutil

import numpy as np
import pytest

from course_grader import course as course_file
from course_grader import hw3_tests, instructions, layout_checks
from course_grader.hw3_measures import FlipCount, planar_travel, still_points
from course_grader.hw3_probe import fill_request, response_code

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
URDF_NO_INERTIAL = """<robot name="r">
  <link name="body"><visual><geometry><box size="1 1 1"/></geometry></visual>
    <collision><geometry><box size="1 1 1"/></geometry></collision></link>
  <gazebo><plugin name="d" filename="libgazebo_ros_diff_drive.so"/></gazebo>
</robot>"""


@pytest.fixture(scope="module")
def spec():
    return course_file.load("me495_hw3").checks["layout"]


@pytest.fixture
def packages(tmp_path):
    for name in ("diff_drive", "arm_move"):
        shutil.copytree(os.path.join(REPO, name), tmp_path / name,
                        ignore=shutil.ignore_patterns("__pycache__", "doc"))
    return str(tmp_path / "diff_drive"), str(tmp_path / "arm_move")


def expand_with_xacro(path):
    return layout_checks.expand_in(dict(os.environ), 30.0)(path)


def failed(checks):
    return [c["evidence"] for c in checks if not c["passed"]]


def test_our_packages_pass(packages, spec):
    ddrive, arm = packages
    assert failed(layout_checks.layout(ddrive, arm, spec)) == []
    checks = layout_checks.description(ddrive, spec, "ddrive.launch", expand_with_xacro)
    assert len(checks) == 4 and failed(checks) == []
    assert layout_checks.robot_xacro(ddrive, "ddrive.launch").endswith("ddrive.urdf.xacro")


def test_missing_folder_node_and_files_are_named(packages, spec):
    ddrive, arm = packages
    shutil.rmtree(os.path.join(ddrive, "worlds"))
    for node in os.listdir(os.path.join(ddrive, "nodes")):
        os.chmod(os.path.join(ddrive, "nodes", node), 0o644)
    cmake = os.path.join(ddrive, "CMakeLists.txt")
    with open(cmake, encoding="utf-8") as stream:
        text = stream.read()
    with open(cmake, "w", encoding="utf-8") as stream:
        stream.write(text.replace("catkin_install_python", "# catkin_install_python"))
    os.remove(os.path.join(ddrive, "launch", "ddrive_rviz.launch"))
    os.remove(os.path.join(arm, "test", "arm.test"))
    reasons = failed(layout_checks.layout(ddrive, arm, spec))
    assert reasons == ["diff_drive lacks the folder(s) worlds",
                       "no file in diff_drive/nodes that rosrun can run (executable, or "
                       "installed by catkin_install_python)",
                       "diff_drive lacks launch/ddrive_rviz.launch",
                       "arm_move lacks test/arm.test"]
    assert failed(layout_checks.layout(None, None, spec)) == [
        "the submission has no diff_drive", "the submission has no arm_move"]


def test_a_node_without_the_executable_bit_runs_through_catkins_relay(packages, spec):
    ddrive, _ = packages
    with open(os.path.join(ddrive, "CMakeLists.txt"), "w", encoding="utf-8") as stream:
        stream.write("cmake_minimum_required(VERSION 3.0.2)\nproject(diff_drive)\n"
                     "catkin_install_python(\n  PROGRAMS\n    nodes/flip  # the flip routine\n"
                     "  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})\n")
    for node in os.listdir(os.path.join(ddrive, "nodes")):
        os.chmod(os.path.join(ddrive, "nodes", node), 0o644)
    assert layout_checks.runnable_nodes(ddrive) == ["flip"]
    assert failed(layout_checks.layout(ddrive, None, spec)) == ["the submission has no arm_move"]


def test_a_cpp_node_is_found_by_its_target_name(packages):
    ddrive, _ = packages
    with open(os.path.join(ddrive, "CMakeLists.txt"), "w", encoding="utf-8") as stream:
        stream.write("cmake_minimum_required(VERSION 3.0.2)\nproject(diff_drive)\n"
                     "# add_executable(old_flip src/old.cpp)\n"
                     "add_executable(${PROJECT_NAME}_flipper src/flipper.cpp)\n"
                     "add_executable( drive_square src/square.cpp src/util.cpp)\n"
                     "target_link_libraries(drive_square ${catkin_LIBRARIES})\n")
    assert layout_checks.built_nodes(ddrive) == ["diff_drive_flipper", "drive_square"]
    found = instructions.node_started_by_hand([], "diff_drive", "flip",
                                              layout_checks.built_nodes(ddrive))
    assert found == "diff_drive_flipper"
    os.remove(os.path.join(ddrive, "CMakeLists.txt"))
    assert layout_checks.built_nodes(ddrive) == []


def test_numbers_written_into_the_xacro_fail_the_yaml_check(packages, spec):
    ddrive, _ = packages
    path = os.path.join(ddrive, "urdf", "ddrive.urdf.xacro")
    with open(path, encoding="utf-8") as stream:
        text = stream.read()
    with open(path, "w", encoding="utf-8") as stream:
        stream.write(text.replace("load_yaml(", "dict("))
    checks = layout_checks.description(ddrive, spec, "ddrive.launch", lambda p: URDF_NO_INERTIAL)
    assert failed(checks)[0].startswith("load_yaml in none")


def test_gazebo_parts_not_in_a_gazebo_file_fail(packages, spec):
    ddrive, _ = packages
    os.rename(os.path.join(ddrive, "urdf", "ddrive.gazebo"),
              os.path.join(ddrive, "urdf", "ddrive_sim.xml"))
    reasons = failed(layout_checks.description(ddrive, spec, "ddrive.launch",
                                               lambda p: URDF_NO_INERTIAL))
    assert ".gazebo: none; included by none" in reasons


def test_a_drawn_link_without_inertial_and_a_xacro_that_fails(packages, spec):
    ddrive, _ = packages
    reasons = failed(layout_checks.description(ddrive, spec, "ddrive.launch",
                                               lambda p: URDF_NO_INERTIAL))
    assert reasons == ["without collision or inertial: body"]

    def broken(path):
        raise layout_checks.UrdfError("xacro ddrive.urdf.xacro failed: name 'x' is not defined")
    reasons = failed(layout_checks.description(ddrive, spec, "ddrive.launch", broken))
    assert reasons == ["xacro ddrive.urdf.xacro failed: name 'x' is not defined"]


JUNIT = """<?xml version="1.0"?>
<testsuite name="arm" tests="{tests}" failures="{failures}" errors="0"/>"""


def test_arm_test_result_files_and_registration(tmp_path, packages):
    folder = tmp_path / "build" / "test_results" / "arm_move"
    folder.mkdir(parents=True)
    (folder / "rostest-test_arm.xml").write_text(JUNIT.format(tests=1, failures=0))
    (folder / "rosunit-arm.xml").write_text(JUNIT.format(tests=1, failures=0))
    files = hw3_tests.result_files(str(tmp_path), "arm_move", "arm.test")
    assert [os.path.basename(f) for f in files] == ["rostest-test_arm.xml"]
    assert hw3_tests.judge_results(files, "arm.test", 9.0, 0)["passed"]
    (folder / "rostest-test_arm.xml").write_text(JUNIT.format(tests=1, failures=1))
    assert not hw3_tests.judge_results(files, "arm.test", 9.0, 0)["passed"]
    none = hw3_tests.judge_results([], "arm.test", 9.0, None)
    assert not none["passed"] and "timed out" in none["evidence"]
    assert hw3_tests.registered(packages[1], "arm.test")
    assert not hw3_tests.registered(packages[0], "arm.test")


def test_flips_counted_from_the_up_axis_with_a_dead_band():
    counter = FlipCount(dead_band=0.2)
    for up_z in [1.0, 0.5, 0.1, -0.1, 0.15, -0.9, -1.0, -0.1, 0.1, -0.15, 1.0, 0.0]:
        counter.update(up_z)
    assert counter.flips == 2     # the wobbles inside +-0.2 are not flips


def test_travel_and_rest():
    assert planar_travel([(0, 0), (3, 4), (3, 0)]) == pytest.approx(9.0)
    point = np.array([0.1, 0.0, 0.2])
    resting = [(t / 10, point) for t in range(10)]
    assert still_points(resting, window=0.5, speed=0.002)
    assert not still_points(resting[:3], window=0.5, speed=0.002)     # too short to tell
    moving = [(t / 10, point + [0.01 * t, 0, 0]) for t in range(10)]
    assert not still_points(moving, window=0.5, speed=0.002)


class Message:
    """A stand-in for a generated message class: slots and their types."""

    def __init__(self, **fields):
        self.__slots__ = list(fields)
        self._slot_types = [kind for kind, _ in fields.values()]
        for name, (_, value) in fields.items():
            setattr(self, name, value)


def point():
    return Message(x=("float64", 0.0), y=("float64", 0.0), z=("float64", 0.0))


def test_step_requests_of_several_layouts_are_filled():
    ours = Message(position=("geometry_msgs/Point", point()), gripper_open=("bool", False))
    assert fill_request(ours, (0.1, 0.2, 0.3), True) == ["position (position)",
                                                         "gripper_open (gripper)"]
    assert (ours.position.x, ours.position.y, ours.position.z, ours.gripper_open) == \
        (0.1, 0.2, 0.3, True)
    pose = Message(position=("geometry_msgs/Point", point()),
                   orientation=("geometry_msgs/Quaternion",
                                Message(x=("float64", 0.0), y=("float64", 0.0),
                                        z=("float64", 0.0), w=("float64", 0.0))))
    nested = Message(pose=("geometry_msgs/Pose", pose), close_gripper=("bool", True))
    fill_request(nested, (0.1, 0.2, 0.3), True)
    assert nested.pose.position.z == 0.3 and nested.pose.orientation.w == 1.0
    assert nested.close_gripper is False
    flat = Message(x=("float64", 0.0), y=("float64", 0.0), z=("float64", 0.0))
    assert fill_request(flat, (0.1, 0.2, 0.3), True) == ["x, y, z (position)"]
    with pytest.raises(Exception, match="no position field"):
        fill_request(Message(name=("string", "")), (0, 0, 0), True)


def test_the_error_code_is_read_from_the_response():
    codes = Message(val=("int32", -16))
    assert response_code(Message(error_code=("arm_move/MoveItErrorCodes", codes),
                                 message=("string", "below"))) == -16
    assert response_code(Message(message=("string", ""), code=("int32", 1))) == 1
    assert response_code(Message(message=("string", "ok"))) is None


def test_the_layout_runner_through_the_graders_hook(tmp_path):
    """grader.runner_results runs the course file's runner and judges its items: our
    packages score both layout items; without arm_move, the layout item loses that part."""
    from course_grader import grader
    from course_grader.submission import Staged
    hw3 = course_file.load("me495_hw3")
    src = tmp_path / "src"
    for name in ("diff_drive", "arm_move"):
        shutil.copytree(os.path.join(REPO, name), src / name,
                        ignore=shutil.ignore_patterns("__pycache__", "doc"))
    staged = Staged(str(tmp_path), {n: str(src / n) for n in ("diff_drive", "arm_move")})
    context = grader.RunnerContext(dict(os.environ), str(tmp_path), staged, str(tmp_path / "log"))
    awarded = {r.item.id: r.awarded for r in grader.runner_results(hw3, "layout", context)}
    assert awarded == {"layout": 0.5, "xacro_yaml_gazebo": 1.0}
    staged = Staged(str(tmp_path), {"diff_drive": str(src / "diff_drive")}, ["arm_move"])
    context = grader.RunnerContext(dict(os.environ), str(tmp_path), staged, str(tmp_path / "log"))
    results = {r.item.id: r for r in grader.runner_results(hw3, "layout", context)}
    # the layout's parts: diff_drive's folders, files, and arm_move: two of three (the node
    # in nodes/ is a note)
    assert results["layout"].awarded == pytest.approx(0.3333, abs=1e-4)
    assert results["xacro_yaml_gazebo"].awarded == 1.0
    assert "the submission has no arm_move" in results["layout"].evidence()


def test_a_world_names_its_included_models_by_uri(tmp_path):
    from course_grader.hw3_measures import included_models
    (tmp_path / "a.world").write_text(
        "<sdf version='1.6'><world name='w'>"
        "<include><uri>model://jersey_barrier</uri><name>wall_1</name></include>"
        "<include><uri>model://sun</uri></include>"
        "<model name='crate'><static>true</static></model></world></sdf>")
    (tmp_path / "broken.world").write_text("<sdf><world>")
    assert included_models(str(tmp_path)) == {"wall_1": "model://jersey_barrier"}

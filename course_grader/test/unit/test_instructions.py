"""What a submission's README tells its user to type, and the guide's command planned for a
submission whose launch file does not declare the guide's argument: the argument is not
passed, the node the README runs is started by hand instead, and the report says so."""
import os

from course_grader import course as course_file
from course_grader import grader, instructions

README = """# diff_drive

Start the world (it starts paused: hit play in Gazebo):

```
roslaunch diff_drive ddrive.launch
rosrun diff_drive flipper   # flips the robot
```

Or `rosrun diff_drive flipper _speed:=3` with a faster speed.
"""


def test_the_commands_a_readme_gives():
    assert instructions.commands([README]) == [
        ["roslaunch", "diff_drive", "ddrive.launch"], ["rosrun", "diff_drive", "flipper"],
        ["rosrun", "diff_drive", "flipper", "_speed:=3"]]


def test_the_node_started_by_hand_is_the_readmes_else_the_one_named_so():
    assert instructions.node_started_by_hand([README], "diff_drive", "flip", []) == "flipper"
    assert instructions.node_started_by_hand([], "diff_drive", "flip",
                                             ["drive", "flip_node"]) == "flip_node"
    assert instructions.node_started_by_hand([], "diff_drive", "flip", ["drive"]) is None


def test_readmes_are_read_from_the_folders_given(tmp_path):
    (tmp_path / "README.md").write_text(README)
    (tmp_path / "notes.md").write_text("rosrun diff_drive other")
    assert instructions.readme_texts([str(tmp_path), "", str(tmp_path / "none")]) == [README]


def flipper_package(folder):
    """A diff_drive package in ``folder`` with a runnable nodes/flipper and a launch/ folder."""
    package = folder / "diff_drive"
    (package / "launch").mkdir(parents=True)
    (package / "nodes").mkdir()
    (package / "nodes" / "flipper").write_text("#!/usr/bin/env python3\n")
    os.chmod(package / "nodes" / "flipper", 0o755)
    return package


def test_an_argument_the_launch_file_does_not_declare_is_not_passed(tmp_path, monkeypatch):
    hw3 = course_file.load("me495_hw3")
    package = flipper_package(tmp_path)
    (package / "launch" / "ddrive.launch").write_text(
        '<launch><arg name="paused" default="true"/><arg name="gui" default="true"/></launch>')
    monkeypatch.setattr(grader.submission, "sourced_find", lambda env, name: str(package))
    plan = grader.plan_command(hw3, "ddrive_flip", {}, [README])
    assert plan.args == [] and plan.by_hand == [("diff_drive", "flipper")]
    assert "declares no 'flip' argument" in plan.notes[0]
    assert "rosrun diff_drive flipper" in plan.notes[0]
    (package / "launch" / "ddrive.launch").write_text(
        '<launch><arg name="flip" default="false"/>'
        '<node name="spawn" pkg="gazebo_ros" type="spawn_model" args="-model r"/></launch>')
    plan = grader.plan_command(hw3, "ddrive_flip", {}, [README])
    assert plan.args == ["flip:=true"] and plan.by_hand == [] and plan.notes == []


def test_a_part_the_launch_file_starts_itself_is_not_started_again_by_hand(tmp_path,
                                                                           monkeypatch):
    """Issue 31: ddrive.launch without a flip argument that starts the flip node itself (its
    README says roslaunch runs the flip): a second flip node by hand would fight it over
    cmd_vel. roslaunch's own reading decides, includes and if= resolved."""
    hw3 = course_file.load("me495_hw3")
    package = flipper_package(tmp_path)
    (package / "launch" / "robot.launch").write_text(
        '<launch><arg name="drive"/><node if="$(arg drive)" name="f" pkg="diff_drive" '
        'type="flipper"/></launch>')
    launch = package / "launch" / "ddrive.launch"
    include = f'<include file="{package}/launch/robot.launch"><arg name="drive" value="%s"/>' \
              '</include>'
    monkeypatch.setattr(grader.submission, "sourced_find", lambda env, name: str(package))
    env = dict(os.environ)
    launch.write_text(f'<launch><arg name="paused" default="true"/>{include % "true"}</launch>')
    plan = grader.plan_command(hw3, "ddrive_flip", env, [README])
    assert plan.by_hand == []
    assert "ddrive.launch starts diff_drive/flipper itself" in plan.notes[0]
    # the same launch file with the node switched off: started by hand, as the README says
    launch.write_text(f'<launch><arg name="paused" default="true"/>{include % "false"}</launch>')
    plan = grader.plan_command(hw3, "ddrive_flip", env, [README])
    assert plan.by_hand == [("diff_drive", "flipper")]


ARM_README = """# arm_move

```
roslaunch arm_move arm.launch use_actual:=true   # on the robot
roslaunch arm_move arm.launch use_fake:=true     # in simulation
```
"""


def test_a_launch_file_runs_with_the_arguments_its_readme_types():
    """Issue 31: an arm README that says use_fake:=true is run so (the line that selects
    the real robot passed over); a plain line among others runs plain; a line that sets
    the guide's argument otherwise is passed over, one that types it comes first."""
    real = ["use_actual:=true", "use_sim:=false"]
    assert instructions.readme_args([ARM_README], "arm_move", "arm.launch", [], real) == \
        ["use_fake:=true"]
    assert instructions.readme_args([ARM_README], "arm_move", "other.launch", [], real) == []
    shown = "roslaunch pkg display.launch\nroslaunch pkg display.launch gui:=false\n"
    assert instructions.readme_args([shown], "pkg", "display.launch", []) == []
    flip = ("roslaunch d ddrive.launch paused:=true\nroslaunch d ddrive.launch flip:=false x:=1\n"
            "roslaunch d ddrive.launch rviz:=true flip:=true\n")
    assert instructions.readme_args([flip], "d", "ddrive.launch", ["flip:=true"]) == \
        ["rviz:=true"]
    assert instructions.readme_args([flip], "d", "ddrive.launch", ["paused:=true"]) == []


def test_the_readmes_arguments_are_passed_when_declared_headless_and_guide_winning(
        tmp_path, monkeypatch):
    hw3 = course_file.load("me495_hw3")
    launch = tmp_path / "arm_move" / "launch"
    launch.mkdir(parents=True)
    (launch / "arm.launch").write_text(
        '<launch><arg name="use_fake" default="false"/><arg name="gui" default="true"/>'
        '</launch>')
    monkeypatch.setattr(grader.submission, "sourced_find",
                        lambda env, name: str(tmp_path / name))
    readme = ARM_README + "\n`roslaunch arm_move arm.launch use_fake:=true gui:=true rate:=2`\n"
    plan = grader.plan_command(hw3, "arm", {}, [readme])
    assert plan.readme_args == ["use_fake:=true"]
    assert plan.notes == ["run with the arguments the README types: roslaunch arm_move "
                          "arm.launch use_fake:=true"]
    # a README's gui:=true does not open a window where the scenario has none
    plan.readme_args.append("gui:=true")
    assert plan.command_line(["gui:=false"]) == ["gui:=false", "use_fake:=true"]


def test_a_world_without_its_robot_is_followed_by_the_readmes_robot_launch(tmp_path,
                                                                           monkeypatch):
    """Issue 31: ddrive.launch that opens the world only, its robot spawned by another
    launch file the README names next: that one runs after it (roslaunch's reading says
    which starts gazebo_ros/spawn_model); with no such line the report says no robot came."""
    hw3 = course_file.load("me495_hw3")
    package = flipper_package(tmp_path)
    (package / "launch" / "ddrive.launch").write_text(
        '<launch><arg name="paused" default="false"/><arg name="flip" default="false"/>'
        '</launch>')
    (package / "launch" / "robot.launch").write_text(
        '<launch><arg name="gui" default="true"/><node name="spawn" pkg="gazebo_ros" '
        'type="spawn_model" args="-urdf -param robot_description -model r"/></launch>')
    (package / "launch" / "view.launch").write_text(
        '<launch><node name="rviz" pkg="rviz" type="rviz"/></launch>')
    monkeypatch.setattr(grader.submission, "sourced_find", lambda env, name: str(package))
    readme = ("roslaunch diff_drive ddrive.launch\nroslaunch diff_drive view.launch\n"
              "roslaunch diff_drive robot.launch x:=1\n")
    plan = grader.plan_command(hw3, "ddrive_flip", dict(os.environ), [readme])
    assert plan.args == ["flip:=true"]
    assert plan.then == [("diff_drive", "robot.launch", ["x:=1"], ["gui"])]
    assert ("ddrive.launch starts no gazebo_ros/spawn_model: the robot was spawned by "
            "'roslaunch diff_drive robot.launch x:=1' after it") in plan.notes[-1]
    plan = grader.plan_command(hw3, "ddrive_flip", dict(os.environ),
                               ["roslaunch diff_drive view.launch"])
    assert plan.then == [] and "no robot was spawned" in plan.notes[-1]
    # the arm's command is not one that puts the robot in the world
    assert grader.plan_command(hw3, "arm", dict(os.environ), [readme]).then == []


def test_a_launch_without_a_simulator_is_told_when_the_scenario_can_run_so(tmp_path,
                                                                           monkeypatch):
    """MoveIt's fake controllers start no gazebo_ros gzserver: the plan says so, read only
    where the scenario can be measured without one (hw3's step)."""
    hw3 = course_file.load("me495_hw3")
    launch = tmp_path / "arm_move" / "launch"
    launch.mkdir(parents=True)
    arm = launch / "arm.launch"
    monkeypatch.setattr(grader.submission, "sourced_find",
                        lambda env, name: str(tmp_path / name))
    env = dict(os.environ)
    arm.write_text('<launch><arg name="use_fake" default="false"/><node unless="$(arg '
                   'use_fake)" name="gazebo" pkg="gazebo_ros" type="gzserver"/></launch>')
    assert grader.plan_command(hw3, "arm", env, [ARM_README], True).simulator is False
    assert grader.plan_command(hw3, "arm", env, [], True).simulator is True
    assert grader.plan_command(hw3, "arm", env, [], False).simulator is None
    assert course_file.scenario_spec(hw3, "step").without_simulator

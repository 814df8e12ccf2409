"""ME495 homework 3 submissions correct by the assignment but unlike the workspace's own
diff_drive and arm_move, made at test time from them (edits as in fixture_edits): each
must get what a teaching assistant reading the assignment gives, which for all of these is
full marks on the items their scenarios grade, with the grader's notes saying what it did
differently (unpaused the world, started a node by hand).

- ``CORRECT_BY_THE_ASSIGNMENT``: name -> ``Fault`` (``scores`` empty: full marks;
  ``scenarios``: what to grade with ``--only``).
- ``make_fixture(repo, name, folder)``: writes fixture ``name`` (None: our own packages)
  into ``folder``."""
from __future__ import annotations

import os
from typing import Dict, Optional

from fixture_edits import Chmod, Copy, Delete, Fault, Rename, Replace, ReplaceAll, make

FILES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "hw3_fixtures")
HW3_PACKAGES = ("diff_drive", "arm_move")
LAUNCH = "diff_drive/launch/ddrive.launch"
ROBOT_LAUNCH = "diff_drive/launch/inc/ddrive_robot.launch.xml"
RVIZ_LAUNCH = "diff_drive/launch/ddrive_rviz.launch"
XACRO = "diff_drive/urdf/ddrive.urdf.xacro"
WORLD = "diff_drive/worlds/ddrive.world"
CMAKE = "diff_drive/CMakeLists.txt"
FLIP_ARG = ('  <arg name="flip" default="false" doc="Start the flip routine (nodes/flip, settings '
            'in config/flip.yaml)."/>\n')
FLIP_PASSED = '    <arg name="flip" value="$(arg flip)"/>\n'
ROBOT_INCLUDE = ('  <include file="$(find diff_drive)/launch/inc/ddrive_robot.launch.xml">\n'
                 '    <arg name="config" value="$(arg config)"/>\n'
                 '    <arg name="x" value="$(arg x)"/>\n'
                 '    <arg name="y" value="$(arg y)"/>\n'
                 '    <arg name="yaw" value="$(arg yaw)"/>\n'
                 '    <arg name="flip" value="$(arg flip)"/>\n'
                 '  </include>\n')
# ddrive.launch without a flip argument: the flip routine is started by hand
NO_FLIP_ARGUMENT = (Replace(LAUNCH, FLIP_ARG, ""),
                    Replace(LAUNCH, FLIP_PASSED, '    <arg name="flip" value="false"/>\n'))

CORRECT_BY_THE_ASSIGNMENT: Dict[str, Fault] = {
    "paused_flip_by_hand": Fault(
        "ddrive.launch starts paused by default and has no flip argument; its README says "
        "press play, then rosrun diff_drive flip",
        (Replace(LAUNCH, '<arg name="paused" default="false"', '<arg name="paused" default="true"'),
         *NO_FLIP_ARGUMENT, Copy("readme_flip_by_hand.md", "diff_drive/README.md")),
        {}, ("layout", "flip")),
    "flip_started_by_the_launch": Fault(
        "no flip argument: ddrive.launch always starts the flip node itself, as its README "
        "says (roslaunch runs the flip); nothing is to be started by hand",
        (*NO_FLIP_ARGUMENT,
         Replace(ROBOT_LAUNCH, '<node if="$(arg flip)" name="flip"', '<node name="flip"'),
         Copy("readme_flip_by_launch.md", "diff_drive/README.md")),
        {}, ("flip",)),
    "flip_node_found_by_name": Fault(
        "no flip argument, no command in the README: the node is nodes/flipper",
        (*NO_FLIP_ARGUMENT, Copy("readme_no_commands.md", "diff_drive/README.md"),
         Rename("diff_drive/nodes/flip", "diff_drive/nodes/flipper"),
         Replace(CMAKE, "nodes/flip ", "nodes/flipper "),
         Replace(ROBOT_LAUNCH, 'type="flip"', 'type="flipper"')),
        {}, ("flip",)),
    "nodes_not_executable": Fault(
        "nodes/flip without the executable bit (catkin_install_python runs it)",
        (Chmod("diff_drive/nodes/flip", 0o644),),
        {}, ("layout", "flip")),
    "xacro_named_otherwise": Fault(
        "robot.xacro, robot.gazebo.xacro and config/dimensions.yaml instead of our names",
        (Rename(XACRO, "diff_drive/urdf/robot.xacro"),
         Rename("diff_drive/urdf/ddrive.gazebo", "diff_drive/urdf/robot.gazebo.xacro"),
         Rename("diff_drive/config/ddrive.yaml", "diff_drive/config/dimensions.yaml"),
         Replace("diff_drive/urdf/robot.xacro", "urdf/ddrive.gazebo\"",
                 "urdf/robot.gazebo.xacro\""),
         ReplaceAll("diff_drive/urdf/robot.xacro", "config/ddrive.yaml", "config/dimensions.yaml"),
         ReplaceAll(ROBOT_LAUNCH, "urdf/ddrive.urdf.xacro", "urdf/robot.xacro"),
         ReplaceAll(RVIZ_LAUNCH, "urdf/ddrive.urdf.xacro", "urdf/robot.xacro"),
         ReplaceAll(RVIZ_LAUNCH, "config/ddrive.yaml", "config/dimensions.yaml"),
         ReplaceAll(LAUNCH, "config/ddrive.yaml", "config/dimensions.yaml")),
        {}, ("layout",)),
    "world_models_named_otherwise": Fault(
        "the world's barriers, boxes and asphalt included under names of the student's own "
        "(wall_*, crate_*, road): the models are Gazebo's jersey_barrier, cardboard_box and "
        "asphalt_plane by their uri",
        (ReplaceAll(WORLD, "<name>jersey_barrier_", "<name>wall_"),
         ReplaceAll(WORLD, "<name>cardboard_box_", "<name>crate_"),
         Replace(WORLD, "<name>asphalt_plane</name>", "<name>road</name>")),
        {}, ("world",)),
    "yaml_loaded_the_old_way": Fault(
        "the yaml read with Melodic's ${load_yaml(...)} instead of xacro.load_yaml",
        (Replace(XACRO, "${xacro.load_yaml(config_file)}", "${load_yaml(config_file)}"),),
        {}, ("layout",)),
    "arm_move_written_otherwise": Fault(
        "arm_move as a student writes it: one script node in the px100 namespace on "
        "moveit_commander's defaults, pose targets at a few fixed gripper pitches, the arm on "
        "Interbotix's own world (no table: the ground is z 0), no unpause (its README says "
        "press play), services answering only the error code, arm.test with its own "
        "unittest on fake MoveIt",
        (Copy("student_arm_move/CMakeLists.txt", "arm_move/CMakeLists.txt"),
         Copy("student_arm_move/package.xml", "arm_move/package.xml"),
         Copy("student_arm_move/arm.launch", "arm_move/launch/arm.launch"),
         Copy("student_arm_move/mover", "arm_move/nodes/mover"),
         Copy("student_arm_move/arm.test", "arm_move/test/arm.test"),
         Copy("student_arm_move/step_unittest.py", "arm_move/test/test_step.py"),
         *(Copy(f"student_arm_move/{srv}", f"arm_move/srv/{srv}")
           for srv in ("Step.srv", "Reset.srv", "Follow.srv")),
         *(Delete(f"arm_move/{path}") for path in (
             "setup.py", "src/arm_move/__init__.py", "src/arm_move/mover.py",
             "src/arm_move/scene.py", "config/mover.yaml", "config/scene.yaml",
             "worlds/arm_box.world"))),
        {}, ("layout", "arm_test", "step")),
    "robot_in_its_own_launch": Fault(
        "ddrive.launch opens the world only; the robot (flipping) is spawned by robot.launch, "
        "the README's second command",
        (Replace(LAUNCH, ROBOT_INCLUDE, ""),
         Copy("robot_own.launch", "diff_drive/launch/robot.launch"),
         Copy("readme_robot_own_launch.md", "diff_drive/README.md")),
        {}, ("layout", "flip")),
    "arm_readme_says_use_fake": Fault(
        "arm.launch runs the real arm by default (use_sim false); its README says "
        "roslaunch arm_move arm.launch use_fake:=true for the simulation",
        (Replace("arm_move/launch/arm.launch", '<arg name="use_sim" default="true"',
                 '<arg name="use_sim" default="false"'),
         Copy("readme_arm_use_fake.md", "arm_move/README.md")),
        {}, ("step",)),
}


def make_fixture(repo: str, name: Optional[str], folder: str) -> str:
    """Fixture ``name`` (None: our diff_drive and arm_move as they are, arm.test included:
    the grader runs it) written into ``folder``; returns ``folder``."""
    edits = CORRECT_BY_THE_ASSIGNMENT[name].edits if name is not None else ()
    return make(folder, [os.path.join(repo, p) for p in HW3_PACKAGES], edits, FILES)

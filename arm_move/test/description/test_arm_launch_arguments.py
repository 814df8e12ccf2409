"""arm.launch and arm_box.launch as the homework words them, read by roslaunch itself (no
master): ``use_sim`` chooses the simulation (arm_box.launch: Interbotix's px100 Gazebo
program with the RealSense box's world) or the real arm's driver, ``fake:=true`` MoveIt's
fake controllers; Interbotix's ``use_fake``/``use_gazebo``/``use_actual`` still work."""
import os
import subprocess
import xml.etree.ElementTree as ET

import pytest
import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
WORLD = os.path.join(HERE, "..", "..", "worlds", "arm_box.world")
SIMULATION = {"/gazebo", "/px100/controller_spawner", "/px100/urdf_spawner",
              "/unpause_physics"}
FAKE = {"/px100/joint_state_publisher"}
REAL = {"/px100/xs_hardware_interface"}
ALWAYS = {"/px100/move_group", "/px100/mover"}


def nodes(launch, *arguments):
    listed = subprocess.run(["roslaunch", "--nodes", "arm_move", launch, *arguments],
                            capture_output=True, text=True, timeout=60, check=True).stdout
    return set(listed.split())


@pytest.mark.parametrize("arguments, started, absent", [
    (("use_sim:=true",), SIMULATION, FAKE | REAL),
    (("use_sim:=true", "fake:=true"), FAKE, SIMULATION | REAL),
    (("use_sim:=false",), REAL, SIMULATION | FAKE),
    ((), SIMULATION, FAKE | REAL),                       # the simulation by default
    (("use_fake:=true",), FAKE, SIMULATION | REAL),       # Interbotix's names
    (("use_actual:=true",), REAL, SIMULATION | FAKE),
    (("use_gazebo:=true",), SIMULATION, FAKE | REAL),
])
def test_use_sim_and_fake_choose_what_runs(arguments, started, absent):
    found = nodes("arm.launch", "rviz:=false", *arguments)
    assert started | ALWAYS <= found, found
    assert not absent & found, found


def test_arm_box_launch_is_the_gazebo_program_with_the_box_world():
    assert nodes("arm_box.launch") == {"/gazebo", "/gazebo_gui", "/px100/controller_spawner",
                                       "/px100/robot_state_publisher", "/px100/urdf_spawner"}
    command = subprocess.run(["roslaunch", "--args", "/gazebo", "arm_move", "arm_box.launch"],
                             capture_output=True, text=True, timeout=60, check=True).stdout
    assert os.path.realpath(WORLD) in {os.path.realpath(word) for word in command.split()}
    # paused, as Interbotix's Gazebo program starts (gazebo_ros' -u, here the simulator's
    # ~paused parameter)
    params = yaml.safe_load(subprocess.run(
        ["roslaunch", "--dump-params", "arm_move", "arm_box.launch"], capture_output=True,
        text=True, timeout=60, check=True).stdout)
    assert params["/gazebo/paused"] is True


def test_the_world_holds_the_realsense_box_on_the_table():
    world = ET.parse(WORLD).getroot().find("world")
    box = world.find("model[@name='realsense_box']")
    size = [float(v) for v in box.find("link/collision/geometry/box/size").text.split()]
    assert size == [0.14, 0.09, 0.05]
    assert float(box.find("link/inertial/mass").text) == 0.1
    x, y, z = [float(v) for v in box.find("pose").text.split()[:3]]
    assert z == pytest.approx(0.025)        # resting on the table top (z 0 at the arm's base)

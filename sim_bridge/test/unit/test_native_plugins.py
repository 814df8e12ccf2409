"""Gazebo C++ plugins in sim_bridge (sim_bridge.native_plugins, compat/gazebo_dev): built
against the workspace's find_package(gazebo) as Gazebo's tutorials build theirs, loaded
from GAZEBO_PLUGIN_PATH, run in lockstep with the world; checked in pybullet's ground truth.

The fixtures (test/data/gazebo_plugins) are built once per run with plain CMake against the
devel space (about 6 s on two cores)."""
import os
import subprocess
import xml.etree.ElementTree as ET

import pytest

from sim_bridge.sdf_world import load_world
from sim_bridge.world import World
from world_fixtures import DATA
from recording_bus import RecordingBus

PLUGINS_SOURCE = os.path.join(DATA, "gazebo_plugins")
# Gazebo's model_push: 0.3 m/s along x, imposed before every step
PUSH_SPEED = 0.3
PUSH_SECONDS = 2.0
# friction takes mu g dt of the speed back within each step (mu 0.5: 0.5 % of 0.3 m/s at
# 1 ms), as in Gazebo, where the plugin also sets the velocity before the step
PUSH_TOLERANCE = 0.03


def devel_space():
    for prefix in os.environ.get("CMAKE_PREFIX_PATH", "").split(os.pathsep):
        if os.path.isfile(os.path.join(prefix, "share", "gazebo", "cmake", "gazeboConfig.cmake")):
            return prefix
    pytest.skip("no find_package(gazebo) config in CMAKE_PREFIX_PATH (source tools/env.bash)")


@pytest.fixture(scope="session")
def plugin_dir(tmp_path_factory):
    build = tmp_path_factory.mktemp("gazebo_plugins")
    env = dict(os.environ, PATH="/usr/bin:/bin:" + os.environ.get("PATH", ""))
    for command in (["cmake", "-S", PLUGINS_SOURCE, "-B", str(build),
                     f"-DCMAKE_PREFIX_PATH={devel_space()}"],
                    ["make", "-C", str(build), "-j2"]):
        result = subprocess.run(command, env=env, capture_output=True, text=True)
        assert result.returncode == 0, result.stdout + result.stderr
    return str(build)


@pytest.fixture
def plugin_world(plugin_dir, monkeypatch):
    monkeypatch.setenv("GAZEBO_PLUGIN_PATH", plugin_dir)
    bus = RecordingBus()
    world = World(bus)
    yield world, bus
    world.close()


def test_model_push_moves_the_box_at_the_speed_it_sets(plugin_world):
    world, bus = plugin_world
    world.load_world(load_world(os.path.join(PLUGINS_SOURCE, "model_push.world")))
    assert bus.warnings == []
    start = world.pose("box")[0]
    for _ in range(round(PUSH_SECONDS / world.step_size)):
        world.step()
    end, orientation = world.pose("box")
    travelled = end[0] - start[0]
    assert travelled == pytest.approx(PUSH_SPEED * PUSH_SECONDS, rel=PUSH_TOLERANCE)
    assert abs(end[1] - start[1]) < 1e-3 and abs(end[2] - start[2]) < 1e-3
    assert world.twist("box")[0][0] == pytest.approx(PUSH_SPEED, rel=PUSH_TOLERANCE)


def test_without_the_plugin_the_box_stays(plugin_world, tmp_path):
    """The same world naming a plugin file that is nowhere: a warning naming it and the
    loader's error, the box spawned and at rest (what moved it was the plugin). (A file
    another test loaded would be found: dlopen hands back a library the process has.)"""
    world, bus = plugin_world
    with open(os.path.join(PLUGINS_SOURCE, "model_push.world")) as stream:
        text = stream.read().replace("libmodel_push.so", "libmodel_push_elsewhere.so")
    path = tmp_path / "model_push.world"
    path.write_text(text)
    world.load_world(load_world(str(path)))
    [warning] = bus.warnings
    assert "plugin 'model_push' (libmodel_push_elsewhere.so) not loaded" in warning
    assert "cannot open shared object file" in warning and "spawned without it" in warning
    start = world.pose("box")[0]
    for _ in range(200):
        world.step()
    assert world.pose("box")[0][0] == pytest.approx(start[0], abs=1e-4)


def _box_with_plugins(*plugins):
    world = ET.fromstring(
        "<sdf version='1.6'><world name='default'><model name='crate'><pose>0 0 0.5 0 0 0</pose>"
        "<link name='link'><collision name='c'><geometry><box><size>1 1 1</size></box>"
        "</geometry></collision></link></model></world></sdf>")
    model = world.find("world/model")
    for name, filename in plugins:
        ET.SubElement(model, "plugin", name=name, filename=filename).append(
            ET.fromstring("<joint>left_wheel_joint</joint>"))
    return ET.tostring(world, encoding="unicode")


def test_a_plugin_that_throws_or_is_missing_is_named_and_the_model_spawns(plugin_world,
                                                                         tmp_path):
    world, bus = plugin_world
    path = tmp_path / "crate.world"
    path.write_text(_box_with_plugins(("thrower", "libthrowing_plugin.so"),
                                      ("absent", "libnot_there.so"),
                                      ("pusher", "libmodel_push.so")))
    world.load_world(load_world(str(path)))
    assert "crate" in world.models
    thrower, absent = bus.warnings
    assert thrower.startswith("model 'crate': plugin 'thrower' (libthrowing_plugin.so) not loaded")
    # the exception's text (gzthrow's message, with the plugin's <joint> read through sdformat)
    assert "couldn't get wheel hinge joint named left_wheel_joint in crate" in thrower
    assert absent.startswith("model 'crate': plugin 'absent' (libnot_there.so) not loaded")
    assert "libnot_there.so: cannot open shared object file" in absent
    # the plugin after them runs
    for _ in range(500):
        world.step()
    assert world.pose("crate")[0][0] > 0.1


# wheel_drive's command: 0.5 m straight, or 90 degrees on the spot, in 2 s
DRIVE_SECONDS = 2.0
DRIVE_TOLERANCE = 0.05  # the wheels' slip
SPIN_UP_SECONDS = 0.5  # spawned 0.1 m up: the fall and the wheels' start, not measured


def _driven_bot(diff_bot_xml, linear, angular):
    xml = diff_bot_xml(drive="none")
    plugin = (f"<gazebo><plugin name='wheels' filename='libwheel_drive.so'>"
              f"<leftJoint>left_wheel_joint</leftJoint><rightJoint>right_wheel_joint</rightJoint>"
              f"<wheelSeparation>0.34</wheelSeparation><wheelDiameter>0.1</wheelDiameter>"
              f"<torque>10</torque><linear>{linear}</linear><angular>{angular}</angular>"
              f"</plugin></gazebo></robot>")
    return xml.replace("</robot>", plugin)


@pytest.mark.parametrize("linear, angular", [(0.25, 0.0), (0.0, 0.7853981633974483)])
def test_wheel_motors_by_set_param_drive_the_robot(plugin_world, diff_bot_xml, linear,
                                                   angular):
    """SetParam("fmax") in Load and SetParam("vel") each step drive a URDF robot's wheels:
    0.5 m ahead, or a quarter turn, in ground truth."""
    import math
    import pybullet as pb
    from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec
    world, bus = plugin_world
    world.add_sdf_model(ModelSpec("ground", True, links=[
        LinkSpec("link", collisions=[ShapeSpec("plane")])]))
    world.spawn_urdf("bot", _driven_bot(diff_bot_xml, linear, angular), (0, 0, 0.1))
    assert not [w for w in bus.warnings if "wheel" in w]
    for _ in range(round(SPIN_UP_SECONDS / world.step_size)):  # landed, wheels up to speed
        world.step()
    start, start_orientation = world.pose("bot")
    for _ in range(round(DRIVE_SECONDS / world.step_size)):
        world.step()
    end, orientation = world.pose("bot")
    yaw = pb.getEulerFromQuaternion(orientation)[2] - pb.getEulerFromQuaternion(
        start_orientation)[2]
    travelled = math.hypot(end[0] - start[0], end[1] - start[1])
    assert travelled == pytest.approx(linear * DRIVE_SECONDS, abs=DRIVE_TOLERANCE * 0.5)
    assert yaw == pytest.approx(angular * DRIVE_SECONDS, abs=DRIVE_TOLERANCE * math.pi / 2)

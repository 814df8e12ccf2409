"""Gazebo C++ plugins in sim_bridge (sim_bridge.native_plugins, compat/gazebo_dev): built
against the workspace's find_package(gazebo) as Gazebo's tutorials build theirs, loaded
from GAZEBO_PLUGIN_PATH, run in lockstep with the world; checked in pybullet's ground truth.

The fixtures (test/data/gazebo_plugins) are built once per run with plain CMake against the
devel space (about 6 s on two cores)."""
import ctypes
import math
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


# A robot with plugin-less sensors, as Kobuki's URDF has them, and the probe plugin that
# reads them through SensorManager (test/data/gazebo_plugins/sensor_probe.cc); the ray looks
# down from ahead of the body (a ray from inside the body would meet the body)
BODY_MASS = 2.0
BODY_HALF_HEIGHT = 0.05
PROBE_YAW = 0.5  # the robot's heading at spawn (rad): the IMU's reference
PROBE_TURN = 0.3  # then turned by this much
GRAVITY = 9.8
SENSOR_TOLERANCE = 0.01  # of a force or an acceleration: the contacts' give
TINY_MASS = "<inertial><mass value='0.001'/><inertia ixx='1e-7' ixy='0' ixz='0' iyy='1e-7' " \
            "iyz='0' izz='1e-7'/></inertial>"


def _probe_bot(name, sensor_names):
    inertia = BODY_MASS * (0.3 ** 2 + 0.1 ** 2) / 12
    return f"""<robot name="{name}">
  <link name="body">
    <collision><geometry><box size="0.4 0.3 0.1"/></geometry></collision>
    <inertial><mass value="{BODY_MASS}"/>
      <inertia ixx="{inertia}" ixy="0" ixz="0" iyy="{inertia}" iyz="0" izz="{inertia}"/></inertial>
  </link>
  <link name="ray_mount">{TINY_MASS}</link>
  <joint name="ray_mount_joint" type="fixed"><parent link="body"/><child link="ray_mount"/>
    <origin xyz="0.25 0 0" rpy="0 {math.pi / 2} 0"/></joint>
  <link name="imu_link">{TINY_MASS}</link>
  <joint name="imu_joint" type="fixed"><parent link="body"/><child link="imu_link"/></joint>
  <gazebo reference="body"><sensor type="contact" name="touch">
    <contact><collision>body_collision</collision></contact></sensor></gazebo>
  <gazebo reference="ray_mount"><sensor type="ray" name="down"><ray>
    <scan><horizontal><samples>1</samples><min_angle>0</min_angle><max_angle>0</max_angle>
    </horizontal></scan><range><min>0.01</min><max>2.0</max></range></ray></sensor></gazebo>
  <gazebo reference="imu_link"><sensor type="imu" name="imu"/></gazebo>
  <gazebo><plugin name="probe" filename="libsensor_probe.so">
    <sensors>{sensor_names}</sensors></plugin></gazebo>
</robot>"""


def _probe_report(plugin_dir):
    """{sensor's scoped name: its line's words} from the probe's last update."""
    library = ctypes.CDLL(os.path.join(plugin_dir, "libsensor_probe.so"))
    library.sensor_probe_report.restype = ctypes.c_char_p
    lines = library.sensor_probe_report().decode().splitlines()
    return {line.split()[0]: line.split()[1:] for line in lines}


def _field(words, name):
    return float(words[words.index(name) + 1])


def _ground(world):
    from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec
    world.add_sdf_model(ModelSpec("ground", True, links=[
        LinkSpec("link", collisions=[ShapeSpec("plane")])]))


def test_a_robots_sensors_read_through_the_sensor_manager(plugin_world, plugin_dir):
    """Plugin-less <sensor>s found by their plain names: the contact sensor feels the
    ground under the body (the normal up, at the body; the weight), the downward ray reads
    the height of its mount, the IMU at rest reads +g up and a heading relative to the one
    it had at load."""
    import pybullet as pb
    world, bus = plugin_world
    _ground(world)
    spawn_orientation = pb.getQuaternionFromEuler((0, 0, PROBE_YAW))
    world.spawn_urdf("probe_bot", _probe_bot("probe_bot", "touch down imu"),
                     (0, 0, BODY_HALF_HEIGHT), spawn_orientation)
    assert bus.warnings == []
    for _ in range(round(SPIN_UP_SECONDS / world.step_size)):
        world.step()
    report = _probe_report(plugin_dir)
    # the <plugin>'s parent is its <model>, named, after Load too (Kobuki reads it so)
    assert report["model:"] == ["probe_bot"]
    touch = report["default::probe_bot::body::touch"]
    assert touch[:2] == ["probe_bot::body", "contact"]
    assert touch[touch.index("pair") + 1] == "probe_bot::body::body_collision"
    assert _field(touch, "points") >= 1
    assert _field(touch, "normal_z") == pytest.approx(1.0, abs=1e-3)
    assert _field(touch, "force_z") == pytest.approx(BODY_MASS * GRAVITY, rel=SENSOR_TOLERANCE)
    down = report["default::probe_bot::body::down"]  # lumped into body, as Gazebo names it
    assert down[:2] == ["probe_bot::body", "ray"]
    assert _field(down, "count") == 1
    assert (_field(down, "min"), _field(down, "max")) == (0.01, 2.0)
    mount_height = world.pose("probe_bot")[0][2]
    assert _field(down, "range0") == pytest.approx(mount_height, abs=1e-3)
    imu = report["default::probe_bot::body::imu"]
    assert _field(imu, "accel_z") == pytest.approx(GRAVITY, rel=SENSOR_TOLERANCE)
    assert _field(imu, "rate_z") == pytest.approx(0.0, abs=1e-3)
    assert _field(imu, "yaw") == pytest.approx(0.0, abs=1e-3)
    position = world.pose("probe_bot")[0]
    world.set_state("probe_bot", position,
                    pb.getQuaternionFromEuler((0, 0, PROBE_YAW + PROBE_TURN)))
    world.step()
    assert _field(_probe_report(plugin_dir)["default::probe_bot::body::imu"], "yaw") == \
        pytest.approx(PROBE_TURN, abs=1e-3)


def test_a_plain_sensor_name_two_robots_share_finds_none(plugin_world):
    """As Gazebo's SensorManager: the second robot's probe asks for 'touch', which both
    robots now have: none is found (gzerr), the plugin throws, the robot spawns; asked by
    its scoped name, the third's finds its own."""
    world, bus = plugin_world
    _ground(world)
    world.spawn_urdf("first", _probe_bot("first", "touch"), (0, 0, BODY_HALF_HEIGHT))
    world.spawn_urdf("second", _probe_bot("second", "touch"), (1, 0, BODY_HALF_HEIGHT))
    world.spawn_urdf("third", _probe_bot("third", "default::third::body::touch"),
                     (2, 0, BODY_HALF_HEIGHT))
    [warning] = bus.warnings
    assert warning.startswith("model 'second': plugin 'probe' (libsensor_probe.so) not loaded")
    assert "SensorProbe: no sensor named touch" in warning
    assert set(world.models) >= {"first", "second", "third"}


CONTACT_RATE = 100.0  # Hz: the contact sensor's <update_rate>
CONTACT_SECONDS = 1.0


def _box_with_contact_plugin():
    inertia = BODY_MASS * (0.3 ** 2 + 0.1 ** 2) / 12
    return f"""<robot name="tutorial_box">
  <link name="body">
    <collision><geometry><box size="0.4 0.3 0.1"/></geometry></collision>
    <inertial><mass value="{BODY_MASS}"/>
      <inertia ixx="{inertia}" ixy="0" ixz="0" iyy="{inertia}" iyz="0" izz="{inertia}"/></inertial>
  </link>
  <gazebo reference="body"><sensor type="contact" name="my_contact">
    <contact><collision>body_collision</collision></contact>
    <update_rate>{CONTACT_RATE}</update_rate>
    <plugin name="contact" filename="libcontact_plugin.so"/></sensor></gazebo>
</robot>"""


def test_a_sensor_plugin_hears_its_contact_sensor_at_its_rate(plugin_world, plugin_dir):
    """A sensor plugin (GZ_REGISTER_SENSOR_PLUGIN) inside a <sensor> is loaded with the
    sensor; once activated, the sensor updates at its <update_rate> in simulated time and
    calls the plugin, which reads the box's contacts with the ground."""
    world, bus = plugin_world
    _ground(world)
    world.spawn_urdf("tutorial_box", _box_with_contact_plugin(), (0, 0, BODY_HALF_HEIGHT))
    assert bus.warnings == []
    for _ in range(round(CONTACT_SECONDS / world.step_size)):
        world.step()
    library = ctypes.CDLL(os.path.join(plugin_dir, "libcontact_plugin.so"))
    library.contact_plugin_report.restype = ctypes.c_char_p
    words = library.contact_plugin_report().decode().split()
    assert int(words[1]) == pytest.approx(CONTACT_RATE * CONTACT_SECONDS, abs=1)
    assert int(words[3]) >= 1
    assert words[5] == "tutorial_box::body::body_collision"
    assert words[6].startswith("ground::")


# A car with the LIMO's layout (test/data/gazebo_plugins/ackermann_drive.cc): the base's
# origin on the rear axle, whose middle follows the commanded circle
WHEELBASE = 0.3
TRACK = 0.26
WHEEL_RADIUS = 0.05
CAR_SPEED = 0.5  # m/s
CAR_CURVATURES = (1.0, -0.8)  # 1/m: a 1 m circle to the left, a 1.25 m one to the right
CAR_SECONDS = 6.0  # three fifths of a circle or more
RADIUS_TOLERANCE = 0.10  # the issue's: the circle's radius within 10 % of 1 / curvature
STEER_TOLERANCE = 0.01  # rad: a stiff PID's offset against the tyres' pull


def _inertial(mass, x=0.0):
    inertia = mass * 0.01
    return (f"<inertial><origin xyz='{x} 0 0'/><mass value='{mass}'/><inertia ixx='{inertia}' "
            f"ixy='0' ixz='0' iyy='{inertia}' iyz='0' izz='{inertia}'/></inertial>")


def _ackermann_car(curvature):
    wheel = (f"<collision><origin rpy='{math.pi / 2} 0 0'/><geometry><cylinder "
             f"radius='{WHEEL_RADIUS}' length='0.04'/></geometry></collision>{_inertial(0.2)}")
    links, joints = [], []
    for side, y in (("left", TRACK / 2), ("right", -TRACK / 2)):
        links.append(f"<link name='{side}_rear_wheel'>{wheel}</link>")
        joints.append(f"<joint name='{side}_rear_joint' type='continuous'><parent link='base_link'/>"
                      f"<child link='{side}_rear_wheel'/><origin xyz='0 {y} 0'/>"
                      f"<axis xyz='0 1 0'/></joint>")
        links.append(f"<link name='{side}_hinge'>{_inertial(0.05)}</link>")
        joints.append(f"<joint name='{side}_steer_joint' type='revolute'><parent link='base_link'/>"
                      f"<child link='{side}_hinge'/><origin xyz='{WHEELBASE} {y} 0'/>"
                      f"<axis xyz='0 0 1'/><limit lower='-0.7' upper='0.7' effort='20' "
                      f"velocity='5'/></joint>")
        links.append(f"<link name='{side}_front_wheel'>{wheel}</link>")
        joints.append(f"<joint name='{side}_front_joint' type='continuous'><parent "
                      f"link='{side}_hinge'/><child link='{side}_front_wheel'/>"
                      f"<axis xyz='0 1 0'/></joint>")
    return f"""<robot name="car">
  <link name="base_link">
    <collision><origin xyz="{WHEELBASE / 2} 0 0.04"/><geometry><box size="0.4 0.2 0.05"/>
    </geometry></collision>{_inertial(3.0, WHEELBASE / 2)}
  </link>
  {''.join(links)}{''.join(joints)}
  <gazebo><plugin name="drive" filename="libackermann_drive.so">
    <leftSteerJoint>left_steer_joint</leftSteerJoint>
    <rightSteerJoint>right_steer_joint</rightSteerJoint>
    <leftRearJoint>left_rear_joint</leftRearJoint><rightRearJoint>right_rear_joint</rightRearJoint>
    <wheelbase>{WHEELBASE}</wheelbase><track>{TRACK}</track>
    <wheelDiameter>{2 * WHEEL_RADIUS}</wheelDiameter><torque>5</torque>
    <steerP>40</steerP><steerD>1</steerD><steerTorque>20</steerTorque>
    <linear>{CAR_SPEED}</linear><curvature>{curvature}</curvature>
  </plugin></gazebo>
</robot>"""


def _joint_position(world, model_name, joint):
    import pybullet as pb
    robot = world.model(model_name).robot
    return pb.getJointState(robot.id, robot.joint_index[joint], physicsClientId=world.client)[0]


def _fitted_circle(points):
    """The least-squares circle (Kasa's fit) through (x, y) points: its centre and radius."""
    import numpy
    xy = numpy.asarray(points)
    design = numpy.column_stack((2 * xy[:, 0], 2 * xy[:, 1], numpy.ones(len(xy))))
    (cx, cy, c), *_ = numpy.linalg.lstsq(design, (xy ** 2).sum(axis=1), rcond=None)
    return (cx, cy), math.sqrt(c + cx ** 2 + cy ** 2)


@pytest.mark.parametrize("curvature", CAR_CURVATURES)
def test_an_ackermann_plugin_follows_the_circle_of_its_curvature(plugin_world, curvature):
    """Steering hinges held at their Ackermann angles by common::PID efforts, rear wheels by
    velocity motors: the rear axle's middle runs on a circle of radius 1 / curvature (10 %),
    on the commanded side, at the commanded speed, in ground truth."""
    world, bus = plugin_world
    _ground(world)
    world.spawn_urdf("car", _ackermann_car(curvature), (0, 0, WHEEL_RADIUS + 0.005))
    assert bus.warnings == []
    for _ in range(round(SPIN_UP_SECONDS / world.step_size)):
        world.step()
    track, steps = [], round(CAR_SECONDS / world.step_size)
    for step in range(steps):
        world.step()
        if step % 100 == 0:
            track.append(world.pose("car")[0][:2])
    (cx, cy), radius = _fitted_circle(track)
    # the hinges at their Ackermann angles: what common::PID's efforts hold
    turn_radius = 1 / curvature
    for side, offset in (("left", -TRACK / 2), ("right", TRACK / 2)):
        assert _joint_position(world, "car", f"{side}_steer_joint") == pytest.approx(
            math.atan(WHEELBASE / (turn_radius + offset)), abs=STEER_TOLERANCE)
    assert radius == pytest.approx(1 / abs(curvature), rel=RADIUS_TOLERANCE)
    # the centre on the car's left for a positive curvature (REP 103: y left)
    start_x, start_y = track[0]
    assert math.copysign(1, curvature) * (cy - start_y) > 0
    arc = sum(math.dist(a, b) for a, b in zip(track, track[1:]))
    assert arc / ((len(track) - 1) * 100 * world.step_size) == pytest.approx(CAR_SPEED, rel=0.05)


def test_set_linear_vel_keeps_the_spin_and_sets_the_frames_velocity(plugin_world):
    """Model::SetLinearVel reaches World.set_twist with the angular part NaN: the model's
    spin is kept, and the velocity set is its frame origin's, not its centre of mass's
    (here 0.2 m off the origin), as Gazebo's Link::SetLinearVel sets the link frame's."""
    world, _bus = plugin_world
    nan = float("nan")
    world.spawn_urdf("spinner", f"""<robot name="spinner"><link name="body">
      <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
      {_inertial(1.0, 0.2)}</link></robot>""", (0, 0, 5))
    world.set_model_gravity("spinner", False)
    world.set_state("spinner", (0, 0, 5), (0, 0, 0, 1), (0, 0, 0), (0, 0, 1.5))
    world.set_twist("spinner", (0.4, -0.1, 0.0), (nan, nan, nan))
    linear, angular = world.twist("spinner")
    assert list(angular) == pytest.approx([0, 0, 1.5], abs=1e-9)
    assert list(linear) == pytest.approx([0.4, -0.1, 0.0], abs=1e-9)
    world.set_twist("spinner", (nan, nan, nan), (0.0, 0.0, -0.5))
    linear, angular = world.twist("spinner")
    assert list(angular) == pytest.approx([0, 0, -0.5], abs=1e-9)
    assert list(linear) == pytest.approx([0.4, -0.1, 0.0], abs=1e-9)


def test_a_plugin_finds_what_gzserver_has_loaded_and_an_unbound_symbol_is_named(
        plugin_world, plugin_dir, capfd):
    """The host's process has what gazebo_ros's API plugin brings into gzserver (roscpp,
    roslib, tf): a plugin calling tf::resolve without linking tf loads and runs (before: the
    simulator ended with 'symbol lookup error'). A symbol nothing defines is named when the
    plugin loads, and the plugin loads lazily as Gazebo loads it, so a path that never
    calls it runs."""
    world, bus = plugin_world
    path = os.path.join(plugin_dir, "scoped.world")
    with open(path, "w") as stream:
        stream.write(_box_with_plugins(("scope", "libhost_scope_plugin.so"))
                     .replace("<joint>left_wheel_joint</joint>",
                              "<prefix>robot1</prefix><frame>/base_link</frame>"))
    world.load_world(load_world(path))
    assert bus.warnings == []
    library = ctypes.CDLL(os.path.join(plugin_dir, "libhost_scope_plugin.so"))
    library.host_scope_plugin_report.restype = ctypes.c_char_p
    # tf/src/tf.cpp:159-185: a leading '/' is taken as already resolved
    assert library.host_scope_plugin_report() == b"base_link"
    log = capfd.readouterr().err
    assert "libhost_scope_plugin.so: undefined symbol: sim_bridge_test_defined_nowhere" in log
    assert "loaded as Gazebo loads it (lazily)" in log


# gzserver's command line as a launch file gives it: three words, which system_push turns
# into 0.3 m/s
SYSTEM_ARGV = ["gzserver", "-s", "libsystem_push.so"]


def _plain_box_world(tmp_path):
    """model_push's world without its model plugin: the box at rest unless pushed."""
    with open(os.path.join(PLUGINS_SOURCE, "model_push.world")) as stream:
        text = stream.read().replace('<plugin name="model_push" filename="libmodel_push.so"/>',
                                     "")
    path = tmp_path / "plain_box.world"
    path.write_text(text)
    return load_world(str(path))


def test_a_system_plugin_gets_the_command_line_and_the_world_once_created(plugin_world,
                                                                          tmp_path):
    """gzserver -s: Load(argc, argv) and Init() before the world, Events::worldCreated once
    its models are in, physics::get_world by that name (gazebo 11's gazebo_shared.cc:55-96,
    physics/World.cc:414, PhysicsIface.cc:58-79): system_push then pushes the box at 0.1
    m/s a word of its command line."""
    world, bus = plugin_world
    world.native.load_system_plugins(["libsystem_push.so"], SYSTEM_ARGV)
    world.load_world(_plain_box_world(tmp_path))
    assert bus.warnings == []
    start = world.pose("box")[0]
    for _ in range(round(PUSH_SECONDS / world.step_size)):
        world.step()
    travelled = world.pose("box")[0][0] - start[0]
    assert travelled == pytest.approx(0.1 * len(SYSTEM_ARGV) * PUSH_SECONDS, rel=PUSH_TOLERANCE)


def test_a_system_plugin_that_fails_is_named_and_the_world_runs(plugin_world, tmp_path,
                                                               monkeypatch):
    """One that throws in Init, one of another type, one that is nowhere: each named with
    Gazebo's words, none run, the world loads and steps."""
    world, bus = plugin_world
    monkeypatch.setenv("SYSTEM_PUSH_FAIL", "init")
    world.native.load_system_plugins(["libmodel_push.so", "libnot_there.so",
                                      "libsystem_push.so"], SYSTEM_ARGV)
    world.load_world(_plain_box_world(tmp_path))
    wrong_type, absent, throws = bus.warnings
    assert "detected an incorrect plugin type. Plugin filename[libmodel_push.so]" in wrong_type
    assert "libnot_there.so: cannot open shared object file" in absent
    assert ("exception in the Init function of system plugin [libsystem_push.so]: "
            "system_push was told to fail in Init" in throws)
    assert all(w.endswith("the simulator runs without it") for w in bus.warnings)
    assert world.native.count == 0
    start = world.pose("box")[0]
    for _ in range(200):
        world.step()
    assert world.pose("box")[0][0] == pytest.approx(start[0], abs=1e-4)


def test_a_system_plugin_named_in_a_model_is_refused_naming_where_it_belongs(plugin_world,
                                                                             tmp_path):
    world, bus = plugin_world
    path = tmp_path / "crate.world"
    path.write_text(_box_with_plugins(("pusher", "libsystem_push.so")))
    world.load_world(load_world(str(path)))
    [warning] = bus.warnings
    assert warning.startswith("model 'crate': plugin 'pusher' (libsystem_push.so) not loaded: "
                              "it is not a model plugin (GZ_REGISTER_MODEL_PLUGIN)")
    assert "a system plugin on gzserver's command line (-s)" in warning
    assert "crate" in world.models and world.native.count == 0

"""The World on pybullet.DIRECT: spawning, poses in link frames, the plugins' physics."""
import math

import numpy as np
import pybullet as pb
import pytest
from geometry_msgs.msg import Twist

from sim_bridge.poses import quaternion_from_rpy
from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec
from sim_bridge.world import SimError

from world_fixtures import run


def command(bus, linear, angular=0.0, topic="/cmd_vel"):
    message = Twist()
    message.linear.x, message.angular.z = linear, angular
    bus.subscriptions[topic](message)


def test_a_robot_rests_on_its_wheels_where_spawned(world, diff_bot_xml):
    world.spawn_urdf("bot", diff_bot_xml(), (1.0, 2.0, 0.0))
    run(world, 1.0)
    (x, y, z), orientation = world.pose("bot")
    # base_footprint is at the wheels' contact plane: the wheels are true cylinders
    assert (x, y) == pytest.approx((1.0, 2.0), abs=1e-3)
    assert abs(z) < 2e-4


def test_the_pose_is_the_root_link_frame_not_the_centre_of_mass(world, diff_bot_xml):
    model = world.spawn_urdf("bot", diff_bot_xml(), (0.0, 0.0, 0.5))
    position, _ = world.pose("bot")
    assert position == pytest.approx((0.0, 0.0, 0.5))
    # the body's centre (base_link) is 0.08 m above base_footprint
    base_link, _ = model.robot.link_pose("base_link")
    assert base_link == pytest.approx((0.0, 0.0, 0.58))


def test_driving_straight_matches_the_command(world, bus, diff_bot_xml):
    world.spawn_urdf("bot", diff_bot_xml(), (0, 0, 0))
    run(world, 0.5)
    start, _ = world.pose("bot")
    command(bus, 0.2)
    run(world, 5.0)
    end, _ = world.pose("bot")
    assert end[0] - start[0] == pytest.approx(1.0, rel=0.02)
    assert abs(end[1] - start[1]) < 0.005
    odometry = bus.last("/odom")
    assert odometry.header.frame_id == "odom" and odometry.child_frame_id == "base_footprint"
    assert odometry.pose.pose.position.x == pytest.approx(end[0], abs=0.01)


@pytest.mark.parametrize("source", ["world", "encoder"])
def test_odometry_nobody_hears_is_not_built_and_encoders_still_count(world, bus, diff_bot_xml,
                                                                      source):
    """No /odom or /tf listener: no message; TF alone heard: the transform; and encoder
    odometry integrated all along (its pose is the true one when someone listens again)."""
    world.spawn_urdf("bot", diff_bot_xml(odometry_source=source), (0, 0, 0))
    bus.unheard.update({"/odom", "/tf"})
    command(bus, 0.2)
    run(world, 2.0)
    assert "/odom" not in bus.published and "/tf" not in bus.published
    bus.unheard.discard("/tf")
    run(world, 0.1)
    transform = bus.last("/tf")
    assert transform.child_frame_id == "base_footprint"
    assert transform.transform.translation.x == pytest.approx(world.pose("bot")[0][0], abs=0.01)
    bus.unheard.clear()
    run(world, 0.1)
    assert bus.last("/odom").pose.pose.position.x == \
        pytest.approx(world.pose("bot")[0][0], abs=0.01)


def test_encoder_odometry_keeps_the_sign_of_v(world, bus, diff_bot_xml):
    world.spawn_urdf("bot", diff_bot_xml(odometry_source="encoder"), (0, 0, 0))
    run(world, 0.5)
    command(bus, -0.2)
    run(world, 2.0)
    odometry = bus.last("/odom")
    assert odometry.twist.twist.linear.x == pytest.approx(-0.2, rel=0.05)
    assert odometry.pose.pose.position.x == pytest.approx(world.pose("bot")[0][0], abs=0.01)


def test_nan_commands_are_ignored_with_a_warning(world, bus, diff_bot_xml):
    world.spawn_urdf("bot", diff_bot_xml(), (0, 0, 0))
    command(bus, float("nan"))
    run(world, 0.5)
    assert abs(world.pose("bot")[0][0]) < 1e-3
    assert any("must be finite" in warning for warning in bus.warnings)


def test_laser_against_analytic_geometry(world, bus, diff_bot_xml):
    # a wall across the x axis whose face is at x = 3.0; the laser sits at x = 0.15
    world.add_sdf_model(ModelSpec("wall", True, pose=(3.1, 0, 0.5, 0, 0, 0), links=[
        LinkSpec("link", collisions=[ShapeSpec("box", size=(0.2, 20.0, 1.0))])]))
    world.spawn_urdf("bot", diff_bot_xml(), (0, 0, 0))
    run(world, 0.5)
    scan = bus.last("/scan")
    angles = scan.angle_min + np.arange(len(scan.ranges)) * scan.angle_increment
    ranges = np.array(scan.ranges)
    # a ray at angle a meets the plane x = 3.0 after (3.0 - 0.15) / cos(a)
    expected = np.where(np.cos(angles) > (3.0 - 0.15) / 10.0, (3.0 - 0.15) / np.cos(angles),
                        math.inf)
    finite = np.isfinite(expected) & (np.abs(angles) < 1.2)
    np.testing.assert_allclose(ranges[finite], expected[finite], atol=0.01)
    assert math.isinf(ranges[0]) and math.isinf(ranges[-1])  # along the wall: nothing


def test_laser_noise_is_seeded(bus, diff_bot_xml):
    from sim_bridge.world import World
    from recording_bus import RecordingBus
    readings = []
    for _ in range(2):
        recording = RecordingBus()
        simulated = World(recording, seed=7, ray_threads=1)
        simulated.add_sdf_model(ModelSpec("wall", True, pose=(2.0, 0, 0.5, 0, 0, 0), links=[
            LinkSpec("link", collisions=[ShapeSpec("box", size=(0.2, 20.0, 1.0))])]))
        simulated.spawn_urdf("bot", diff_bot_xml(laser_noise="0.01"), (0, 0, 0.0))
        run(simulated, 0.2)
        readings.append(recording.last("/scan").ranges)
        simulated.close()
    assert readings[0] == readings[1]


def test_requests_that_cannot_be_done_name_the_cause(world, diff_bot_xml):
    world.spawn_urdf("bot", diff_bot_xml(), (0, 0, 0))
    with pytest.raises(SimError, match="exists already"):
        world.spawn_urdf("bot", diff_bot_xml(), (0, 0, 0))
    with pytest.raises(SimError, match="no model named 'ghost'"):
        world.delete("ghost")
    with pytest.raises(SimError, match="not finite"):
        world.set_state("bot", (float("nan"), 0, 0), (0, 0, 0, 1))
    with pytest.raises(SimError, match="no direction"):
        world.set_state("bot", (0, 0, 0), (0, 0, 0, 0))


def test_reset_puts_models_back_and_time_goes_on(world, bus, diff_bot_xml):
    world.spawn_urdf("bot", diff_bot_xml(), (0, 0, 0))
    command(bus, 0.3)
    run(world, 1.0)
    before = world.now_ns
    world.reset()
    assert world.pose("bot")[0][0] == pytest.approx(0.0, abs=1e-9)
    assert world.now_ns == before
    run(world, 0.5)  # the reset dropped the command: it stays
    assert abs(world.pose("bot")[0][0]) < 2e-3


def test_many_static_objects_are_all_solid_and_seen(world):
    # more than pybullet keeps in a compound (16) or in one body's links (127)
    for index in range(150):
        world.add_sdf_model(ModelSpec(f"box{index}", True, pose=(index * 1.0, 5.0, 0.5, 0, 0, 0),
                                      links=[LinkSpec("l", collisions=[ShapeSpec("box")])]))
    down = np.array([[0.0, 0.0, -1.0]])
    for index in (0, 127, 149):
        assert world.cast_rays((index * 1.0, 5.0, 3.0), down, 0.0, 10.0)[0] == \
            pytest.approx(2.0)
        assert pb.rayTest((index * 1.0, 5.0, 3.0), (index * 1.0, 5.0, -1.0),
                          physicsClientId=world.client)[0][0] >= 0  # solid for physics too


def test_the_model_library_loads_and_free_models_rest_where_placed(bus, tmp_path):
    from sim_bridge.sdf_world import load_world
    from sim_bridge.world import World
    world_file = tmp_path / "library.world"
    includes = "".join(
        f"<include><uri>model://{name}</uri><name>{name}</name><pose>{x} 0 0 0 0 0</pose></include>"
        for name, x in (("jersey_barrier", 0), ("cardboard_box", 3), ("construction_cone", 5)))
    world_file.write_text(
        "<sdf version='1.6'><world name='w'><include><uri>model://ground_plane</uri></include>"
        "<include><uri>model://sun</uri></include><include><uri>model://asphalt_plane</uri>"
        f"</include>{includes}</world></sdf>")
    simulated = World(bus, ray_threads=1)
    simulated.load_world(load_world(str(world_file)))
    assert set(simulated.models) == {"ground_plane", "asphalt_plane", "jersey_barrier",
                                     "cardboard_box", "construction_cone"}
    run(simulated, 1.0)
    for name, x in (("cardboard_box", 3.0), ("construction_cone", 5.0)):
        (px, py, pz), _ = simulated.pose(name)
        assert (px, py) == pytest.approx((x, 0.0), abs=0.01), name
        assert 0.0 <= pz < 0.2, name  # resting on the asphalt, not sunk or thrown
    # the barrier is solid to lasers, the model database's size: 1.143 m tall, 4.06542 m
    # long across the x axis at y = 0 (its top 2.0 - 1.143 m below the ray's start)
    down = np.array([[0.0, 0.0, -1.0]])
    assert simulated.cast_rays((1.5, 0.0, 2.0), down, 0.0, 5.0)[0] == pytest.approx(0.857, abs=0.01)
    assert simulated.cast_rays((2.0, 0.0, 2.0), down, 0.0, 5.0)[0] == pytest.approx(0.857, abs=0.01)
    assert simulated.cast_rays((2.06, 0.0, 2.0), down, 0.0, 5.0)[0] > 1.9  # past its end
    simulated.close()


def test_skid_steer_drives_straight_and_turns_in_place(world, bus):
    from urdf_tools.xacro_loader import expand
    from world_fixtures import DATA
    world.spawn_urdf("skid", expand(f"{DATA}/skid_bot.urdf.xacro"), (0, 0, 0))
    run(world, 0.5)
    command(bus, 0.3)
    run(world, 3.0)
    (x, y, _), _ = world.pose("skid")
    assert x == pytest.approx(0.9, rel=0.1)
    assert abs(y) < 0.03
    command(bus, 0.0, 1.0)
    run(world, 0.5)
    start_position, start_orientation = world.pose("skid")
    run(world, 1.0)
    end_position, end_orientation = world.pose("skid")
    from sim_bridge.poses import yaw_from_quaternion
    turned = yaw_from_quaternion(end_orientation) - yaw_from_quaternion(start_orientation)
    # counter-clockwise; slower than commanded, since the wheels slide sideways to turn
    assert turned > 0.2
    assert math.dist(start_position[:2], end_position[:2]) < 0.05  # in place
    odometry = bus.last("/odom")
    assert odometry.pose.covariance[0] == 0.0001 and odometry.pose.covariance[35] == 0.01
    assert any(t.child_frame_id == "base_footprint" for t in bus.published["/tf"])


@pytest.fixture
def gadget(world):
    from world_fixtures import DATA
    with open(f"{DATA}/gadget_bot.urdf", encoding="utf-8") as stream:
        model = world.spawn_urdf("gadget", stream.read(), (0, 0, 0.001), joints={"pan": 0.5})
    run(world, 0.5)
    return model


def test_an_unknown_plugin_warns_once_naming_it(bus, gadget):
    named = [w for w in bus.warnings if "libgazebo_ros_mystery.so" in w]
    assert len(named) == 1 and "'mystery'" in named[0]


def test_imu_at_rest_reads_gravity_upwards(bus, gadget):
    imu = bus.last("/imu")
    assert imu.header.frame_id == "base_link"
    assert imu.linear_acceleration.z == pytest.approx(9.8, abs=0.05)
    assert abs(imu.linear_acceleration.x) < 0.05 and abs(imu.angular_velocity.z) < 1e-3


def test_p3d_and_joint_states_report_the_truth(world, bus, gadget):
    truth = bus.last("/pan_truth")
    link_position, _ = gadget.robot.link_pose("pan_link")
    assert truth.header.frame_id == "world" and truth.child_frame_id == "pan_link"
    assert (truth.pose.pose.position.x, truth.pose.pose.position.y,
            truth.pose.pose.position.z) == pytest.approx(link_position, abs=2e-3)
    joints = bus.last("/joint_states")
    assert joints.name == ["pan"]
    assert joints.position[0] == pytest.approx(gadget.robot.joint_position_velocity("pan")[0])


def test_planar_move_goes_sideways_and_ignores_nan(world, bus, gadget):
    message = Twist()
    message.linear.x, message.linear.y = 0.2, 0.1
    bus.subscriptions["/cmd_vel"](message)
    start, _ = world.pose("gadget")
    run(world, 2.0)
    end, _ = world.pose("gadget")
    assert (end[0] - start[0], end[1] - start[1]) == pytest.approx((0.4, 0.2), abs=0.01)
    message.linear.y = float("nan")
    bus.subscriptions["/cmd_vel"](message)
    assert any("linear.y=nan" in w for w in bus.warnings)
    odometry = bus.last("/odom")
    assert odometry.pose.pose.position.x == pytest.approx(end[0], abs=0.01)


def test_a_link_without_gravity_floats(world):
    floating = """<robot name="balloon"><link name="body">
      <collision><geometry><sphere radius="0.1"/></geometry></collision>
      <inertial><mass value="0.5"/><inertia ixx="0.002" ixy="0" ixz="0" iyy="0.002" iyz="0"
        izz="0.002"/></inertial></link>
      <gazebo reference="body"><gravity>false</gravity></gazebo></robot>"""
    world.spawn_urdf("balloon", floating, (0, 0, 1.0))
    world.spawn_urdf("stone", floating.replace("<gravity>false</gravity>", ""), (1, 0, 1.0))
    run(world, 1.0)
    assert world.pose("balloon")[0][2] == pytest.approx(1.0, abs=1e-3)
    assert world.pose("stone")[0][2] < 0.2  # fell


def test_mesh_scenery_is_solid_and_seen(world, tmp_path):
    # a 1 m cube as an OBJ mesh, standing on the ground 3 m ahead
    corners = [(x, y, z) for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (0.0, 1.0)]
    faces = [(1, 2, 4, 3), (5, 7, 8, 6), (1, 5, 6, 2), (3, 4, 8, 7), (1, 3, 7, 5), (2, 6, 8, 4)]
    mesh = tmp_path / "cube.obj"
    mesh.write_text("".join(f"v {x} {y} {z}\n" for x, y, z in corners) +
                    "".join("f " + " ".join(map(str, f)) + "\n" for f in faces))
    world.add_sdf_model(ModelSpec("crate", True, pose=(3, 0, 0, 0, 0, 0), links=[LinkSpec(
        "link", collisions=[ShapeSpec("mesh", filename=str(mesh))])]))
    ahead = np.array([[1.0, 0.0, 0.0]])
    assert world.cast_rays((0.0, 0.0, 0.5), ahead, 0.0, 10.0)[0] == pytest.approx(2.5, abs=0.01)
    assert pb.rayTest((3, 0, 5), (3, 0, -1), physicsClientId=world.client)[0][0] >= 0


def wheel_loads(world, name):
    """The ground's normal force (N) on each wheel of robot ``name``."""
    robot = world.model(name).robot
    return [sum(contact[9] for contact in pb.getContactPoints(
                bodyA=robot.id, linkIndexA=robot.link_index[f"{side}_wheel"],
                physicsClientId=world.client))
            for side in ("left", "right")]


@pytest.mark.parametrize("heading_degrees", [0.0, 30.0, 45.0])
def test_a_robot_stands_on_both_wheels_alike_whatever_its_heading(world, diff_bot_xml,
                                                                    heading_degrees):
    # a rigid cylinder keeps one edge of its contact line; the crowned wheel its middle
    heading = quaternion_from_rpy(0.0, 0.0, math.radians(heading_degrees))
    world.spawn_urdf("bot", diff_bot_xml(), (0, 0, 0), heading)
    run(world, 1.0)
    left, right = wheel_loads(world, "bot")
    assert left > 1.0 and right > 1.0
    assert left == pytest.approx(right, rel=0.02)

"""Links by Gazebo's names, their states, model properties, physics properties, wrenches
and joint efforts, on pybullet.DIRECT: every number from mechanics (Δv = F·d/m,
Δω = τ·d/I), not from pybullet."""
import math

import numpy as np
import pybullet as pb
import pytest

from sim_bridge.poses import quaternion_from_rpy, yaw_from_quaternion
from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec
from sim_bridge.world import LinkRef, SimError

from test_model_structure import ROTOR
from world_fixtures import DATA, run

SECOND = 1_000_000_000
# the free box: 2 kg, 0.2 m cube, inertia m a²/6 about each axis
BOX_MASS = 2.0
BOX_INERTIA = BOX_MASS * 0.2 ** 2 / 6


def free_box(world, name="box", pose=(0, 0, 1, 0, 0, 0), link_pose=(0, 0, 0, 0, 0, 0),
             inertial_pose=(0, 0, 0, 0, 0, 0)):
    return world.add_sdf_model(ModelSpec(name, False, pose=pose, links=[LinkSpec(
        "link", pose=link_pose, collisions=[ShapeSpec("box", size=(0.2, 0.2, 0.2))],
        mass=BOX_MASS, inertia=(BOX_INERTIA,) * 3, inertial_pose=inertial_pose)]))


@pytest.fixture
def weightless(world):
    world.set_physics(world.step_size, world.max_update_rate, (0.0, 0.0, 0.0))
    return world


@pytest.fixture
def bot(world, diff_bot_xml):
    return world.spawn_urdf("bot", diff_bot_xml(), (0, 0, 0))


# --- names ------------------------------------------------------------------------------
def test_links_are_found_scoped_or_plain_as_gazebo_finds_them(world, bot):
    assert world.find_link("bot::left_wheel") == LinkRef("bot", "left_wheel")
    assert world.find_link("left_wheel") == LinkRef("bot", "left_wheel")
    assert world.find_link("ground::link").scoped == "ground::link"
    assert world.find_link("link") == LinkRef("ground", "link")  # the first model's


@pytest.mark.parametrize("name, words", [
    ("bot::base_link", ["lumps it into 'base_footprint'", "fixed joint 'base_joint'",
                        "preserveFixedJoint"]),
    ("laser", ["model 'bot' has no link 'laser'", "'bot::base_footprint'"]),
    ("bot", ["'bot' is a model, not a link", "bot::left_wheel"]),
    ("bot::tail", ["model 'bot' has no link 'tail'", "bot::base_footprint, bot::left_wheel"]),
    ("ghost::link", ["no model named 'ghost'", "models: ground, bot"]),
    ("nothing", ["no link named 'nothing'", "model::link"]),
])
def test_a_name_that_is_no_link_is_refused_naming_it(world, bot, name, words):
    with pytest.raises(SimError) as error:
        world.find_link(name)
    for word in words:
        assert word in str(error.value)


def test_model_properties_are_gazebos(world, bot):
    properties = world.model_properties("bot")
    assert properties.body_names == ("base_footprint", "left_wheel", "right_wheel")
    assert properties.canonical_body_name == "base_footprint"
    assert properties.joint_names == ("left_wheel_joint", "right_wheel_joint")
    assert "left_wheel_collision" in properties.geom_names
    assert not properties.is_static and properties.parent_model_name == ""
    assert properties.child_model_names == ()
    ground = world.model_properties("ground")
    assert ground.is_static and ground.body_names == ("link",)
    with pytest.raises(SimError, match="no model named 'ghost'"):
        world.model_properties("ghost")


# --- link states ------------------------------------------------------------------------
def test_link_poses_are_link_frames_and_twists_their_origins_velocity(weightless, bot):
    world = weightless
    world.set_state("bot", (1, 2, 1), quaternion_from_rpy(0, 0, 0.5), (0.3, 0, 0), (0, 0, 2.0))
    for link in ("base_footprint", "left_wheel"):
        ref = world.find_link(f"bot::{link}")
        assert world.link_pose(ref)[0] == pytest.approx(bot.robot.link_pose(link)[0])
    base = np.asarray(world.link_pose(LinkRef("bot", "base_footprint"))[0])
    wheel = np.asarray(world.link_pose(LinkRef("bot", "left_wheel"))[0])
    # a rigid motion: the wheel's origin moves at v + ω × r
    linear, angular = world.link_twist(LinkRef("bot", "left_wheel"))
    expected = np.array([0.3, 0, 0]) + np.cross([0, 0, 2.0], wheel - base)
    np.testing.assert_allclose(linear, expected, atol=1e-6)
    np.testing.assert_allclose(angular, (0, 0, 2.0), atol=1e-6)


def test_link_states_list_every_link_of_every_model(world, bot):
    names = [state[0] for state in world.link_states()]
    assert names == ["ground::link", "bot::base_footprint", "bot::left_wheel",
                     "bot::right_wheel"]
    for name, position, orientation, _, _ in world.link_states():
        expected_position, expected_orientation = world.link_pose(world.find_link(name))
        assert position == pytest.approx(expected_position)
        assert orientation == pytest.approx(expected_orientation)


def test_setting_the_canonical_link_moves_the_model(world, bot):
    heading = quaternion_from_rpy(0, 0, 1.0)
    world.set_link_state(LinkRef("bot", "base_footprint"), (2.0, 1.0, 0.0), heading)
    position, orientation = world.pose("bot")
    assert position == pytest.approx((2.0, 1.0, 0.0))
    assert yaw_from_quaternion(orientation) == pytest.approx(1.0)
    wheel, _ = world.link_pose(LinkRef("bot", "left_wheel"))
    # the wheel came along: 0.17 m to the left of the base, 0.05 m up
    assert wheel == pytest.approx((2.0 - 0.17 * math.sin(1.0), 1.0 + 0.17 * math.cos(1.0),
                                   0.05), abs=1e-6)


def test_another_link_of_a_robot_cannot_be_placed_apart(world, bot):
    with pytest.raises(SimError, match="hangs on joint 'left_wheel_joint'.*set_model_config"):
        world.set_link_state(LinkRef("bot", "left_wheel"), (0, 0, 1), (0, 0, 0, 1))


def test_a_free_bodys_model_and_link_frames_differ_by_the_links_pose(world):
    # the link 0.15 m above the model frame, its centre of mass 0.05 m further up
    free_box(world, pose=(1, 0, 0.5, 0, 0, 0), link_pose=(0, 0, 0.15, 0, 0, 0),
             inertial_pose=(0, 0, 0.05, 0, 0, 0))
    ref = LinkRef("box", "link")
    assert world.pose("box")[0] == pytest.approx((1, 0, 0.5))
    assert world.link_pose(ref)[0] == pytest.approx((1, 0, 0.65))
    world.set_link_state(ref, (3, 0, 2.15), (0, 0, 0, 1), linear=(1, 0, 0))
    assert world.pose("box")[0] == pytest.approx((3, 0, 2.0))
    assert world.twist("box")[0] == pytest.approx((1, 0, 0))
    world.reset()
    assert world.link_pose(ref)[0] == pytest.approx((1, 0, 0.65))


# --- physics properties -----------------------------------------------------------------
def test_physics_properties_are_reported_and_set(world):
    properties = world.physics_properties()
    assert properties.time_step == 0.001 and properties.gravity == (0.0, 0.0, -9.8)
    assert properties.max_update_rate == pytest.approx(1000.0)  # real time
    assert properties.ode["sor_pgs_iters"] == 50 and properties.ode["erp"] == 0.2
    world.set_physics(0.002, 250.0, (0.0, 0.0, -1.0))
    assert world.real_time_factor == pytest.approx(0.5)
    before = world.now_ns
    world.step()
    assert world.now_ns - before == 2_000_000
    assert world.physics_properties().gravity == (0.0, 0.0, -1.0)


NAN, INF = float("nan"), float("inf")


@pytest.mark.parametrize("time_step, rate, gravity, words", [
    (0.0, 1000.0, (0, 0, -9.8), "time_step 0.0 must be a positive"),
    (-0.001, 1000.0, (0, 0, -9.8), "time_step -0.001 must be a positive"),
    (NAN, 1000.0, (0, 0, -9.8), "time_step nan"),
    (INF, 1000.0, (0, 0, -9.8), "time_step inf"),
    # under half a nanosecond the step rounds to 0 ns and the clock would stand still
    (1e-12, 1000.0, (0, 0, -9.8), "time_step 1e-12 is below a nanosecond"),
    # int(round(1e300 * 1e9)) overflowed: an OverflowError, not an answer
    (1e300, 1000.0, (0, 0, -9.8), "time_step 1e\\+300 is longer than ROS time can carry"),
    (0.001, -1.0, (0, 0, -9.8), "max_update_rate -1.0"),
    (0.001, NAN, (0, 0, -9.8), "max_update_rate nan"),
    (0.001, INF, (0, 0, -9.8), "max_update_rate inf"),
    # the reported case: pacing would have slept 1e9 s before the next step
    (0.001, 1e-9, (0, 0, -9.8), "max_update_rate 1e-09 is too slow: each step would wait "
                                "1e\\+09 s"),
    (0.001, 0.5, (0, 0, -9.8), "max_update_rate 0.5 is too slow"),
    (0.001, 1000.0, (0, 0, INF), "gravity"),
    (0.001, 1000.0, (NAN, 0, -9.8), "gravity \\(nan, 0.0, -9.8\\) is not finite"),
])
def test_bad_physics_properties_are_refused_and_nothing_changes(world, time_step, rate,
                                                                 gravity, words):
    with pytest.raises(SimError, match=words):
        world.set_physics(time_step, rate, gravity)
    properties = world.physics_properties()
    assert properties.time_step == 0.001 and world.step_ns == 1_000_000
    assert properties.max_update_rate == pytest.approx(1000.0)
    assert properties.gravity == (0.0, 0.0, -9.8)


@pytest.mark.parametrize("time_step, rate, step_ns", [
    (0.001, 0.0, 1_000_000),   # 0: as fast as possible, as Gazebo
    (0.001, 1.0, 1_000_000),   # the slowest rate taken: a step a second
    (0.001, 1e9, 1_000_000),   # beyond what the machine reaches: as fast as it can
    (1e-9, 1000.0, 1),         # a nanosecond, the clock's resolution
    (3600.0, 1.0, 3_600_000_000_000),
])
def test_what_gazebo_simulates_is_taken(world, time_step, rate, step_ns):
    world.set_physics(time_step, rate, (0.0, 0.0, -1.0))
    assert world.physics_properties().max_update_rate == rate
    before = world.now_ns
    world.step()
    assert world.now_ns - before == step_ns


def test_without_gravity_a_dropped_body_floats(weightless):
    free_box(weightless)
    run(weightless, 1.0)
    assert weightless.pose("box")[0] == pytest.approx((0, 0, 1), abs=1e-9)


def test_plugins_see_the_new_gravity(world, bus):
    with open(f"{DATA}/gadget_bot.urdf", encoding="utf-8") as stream:
        world.spawn_urdf("gadget", stream.read(), (0, 0, 0.001))
    run(world, 0.3)
    assert bus.last("/imu").linear_acceleration.z == pytest.approx(9.8, abs=0.05)
    world.set_physics(world.step_size, world.max_update_rate, (0, 0, -3.0))
    run(world, 0.3)
    assert bus.last("/imu").linear_acceleration.z == pytest.approx(3.0, abs=0.05)


# --- wrenches ---------------------------------------------------------------------------
def test_a_force_for_a_while_changes_velocity_by_f_d_over_m(weightless):
    free_box(weightless)
    weightless.apply_wrench("box::link", (4.0, 0, 0), (0, 0, 0), duration_ns=SECOND // 2)
    run(weightless, 1.0)
    linear, angular = weightless.twist("box")
    assert linear == pytest.approx((4.0 * 0.5 / BOX_MASS, 0, 0), abs=1e-6)
    assert angular == pytest.approx((0, 0, 0), abs=1e-9)
    assert not weightless.forces  # over, dropped


def test_a_torque_changes_angular_velocity_by_t_d_over_i(weightless):
    free_box(weightless)
    weightless.apply_wrench("box::link", (0, 0, 0), (0, 0, 0.1), duration_ns=SECOND // 2)
    run(weightless, 1.0)
    assert weightless.twist("box")[1] == pytest.approx((0, 0, 0.05 / BOX_INERTIA), rel=1e-3)


def test_a_wrench_waits_for_its_start_time(weightless):
    free_box(weightless)
    weightless.apply_wrench("box::link", (2.0, 0, 0), (0, 0, 0), start_ns=SECOND // 2,
                            duration_ns=SECOND // 10)
    run(weightless, 0.4)
    assert weightless.twist("box")[0][0] == 0.0
    run(weightless, 0.6)
    assert weightless.twist("box")[0][0] == pytest.approx(2.0 * 0.1 / BOX_MASS, abs=1e-6)


def test_a_wrench_without_end_lasts_until_cleared(weightless):
    free_box(weightless)
    weightless.apply_wrench("box::link", (1.0, 0, 0), (0, 0, 0), duration_ns=-1)
    run(weightless, 0.5)
    assert weightless.clear_wrenches("box::link") == 1
    speed = weightless.twist("box")[0][0]
    assert speed == pytest.approx(0.5 / BOX_MASS, abs=1e-6)
    run(weightless, 0.5)
    assert weightless.twist("box")[0][0] == pytest.approx(speed, abs=1e-9)


def test_a_wrench_in_a_links_frame_turns_with_it(weightless):
    free_box(weightless, pose=(0, 0, 1, 0, 0, math.pi / 2))
    weightless.apply_wrench("box::link", (1.0, 0, 0), (0, 0, 0), reference_frame="box::link",
                            duration_ns=SECOND)
    run(weightless, 1.0)
    # the box's x axis is the world's y
    assert weightless.twist("box")[0] == pytest.approx((0, 1.0 / BOX_MASS, 0), abs=1e-6)


def test_a_force_off_the_centre_of_mass_turns_the_body(weightless):
    free_box(weightless)
    # 1 N up, 0.1 m along x from the centre: a torque of 0.1 N m about -y
    weightless.apply_wrench("box::link", (0, 0, 1.0), (0, 0, 0), reference_point=(0.1, 0, 0),
                            duration_ns=SECOND // 10)
    run(weightless, 0.1)
    linear, angular = weightless.twist("box")
    assert linear[2] == pytest.approx(0.1 / BOX_MASS, rel=1e-3)
    assert angular == pytest.approx((0, -0.1 * 0.1 / BOX_INERTIA, 0), rel=1e-3)


def test_a_wrench_on_a_robots_lumped_body_moves_the_robot(weightless, bot):
    mass = 5.0 + 2 * 0.5 + 2 * 0.1 + 0.2  # base, wheels, casters, laser
    weightless.set_state("bot", (0, 0, 1), (0, 0, 0, 1))
    weightless.apply_wrench("bot::base_footprint", (mass, 0, 0), (0, 0, 0),
                            duration_ns=SECOND // 2)
    run(weightless, 0.5)
    assert weightless.twist("bot")[0][0] == pytest.approx(0.5, rel=0.03)


@pytest.mark.parametrize("name, arguments, words", [
    ("box::nothing", {}, "model 'box' has no link 'nothing'"),
    ("ground::link", {}, "static model 'ground': forces move nothing"),
    ("box::link", {"force": (float("nan"), 0, 0)}, "the force"),
    ("box::link", {"reference_frame": "nowhere"}, "reference frame 'nowhere'"),
])
def test_wrenches_that_cannot_be_applied_are_refused(world, name, arguments, words):
    free_box(world)
    arguments = {"force": (1, 0, 0), "torque": (0, 0, 0), **arguments}
    with pytest.raises(SimError, match=words):
        world.apply_wrench(name, **arguments)
    assert not world.forces


# --- joint efforts ----------------------------------------------------------------------
@pytest.fixture
def rotor(world):
    return world.spawn_urdf("rotor", ROTOR, (0, 0, 0))


def test_an_effort_turns_a_joint_by_t_d_over_i(world, rotor):
    # the disc turns about z: I = 0.2 kg m²; 0.5 N m for 0.4 s
    world.apply_joint_effort("spin", 0.5, duration_ns=int(0.4 * SECOND))
    run(world, 0.4)
    position, velocity = rotor.robot.joint_position_velocity("spin")
    assert velocity == pytest.approx(0.5 * 0.4 / 0.2, rel=1e-3)
    assert position == pytest.approx(0.5 * (0.5 / 0.2) * 0.4 ** 2, rel=0.01)
    run(world, 0.2)  # over: the disc turns on at the same speed
    assert rotor.robot.joint_position_velocity("spin")[1] == pytest.approx(velocity, rel=1e-3)
    # the link's state says so too
    assert world.link_twist(world.find_link("rotor::disc"))[1][2] == pytest.approx(velocity)


def test_an_effort_without_end_lasts_until_cleared(world, rotor):
    world.apply_joint_effort("rotor::spin", 0.2, duration_ns=-1)
    run(world, 0.5)
    assert world.clear_joint_efforts("spin") == 1
    velocity = rotor.robot.joint_position_velocity("spin")[1]
    assert velocity == pytest.approx(0.2 * 0.5 / 0.2, rel=1e-3)
    run(world, 0.5)
    assert rotor.robot.joint_position_velocity("spin")[1] == pytest.approx(velocity, rel=1e-3)


@pytest.mark.parametrize("name, words", [
    ("fix", "joint 'rotor::fix' is fixed"),
    ("bot::base_joint", "fixed joint Gazebo lumps away"),
    ("elbow", "no joint named 'elbow'"),
])
def test_efforts_that_cannot_be_applied_are_refused(world, rotor, bot, name, words):
    with pytest.raises(SimError, match=words):
        world.apply_joint_effort(name, 1.0)


def test_deleting_a_model_ends_its_forces(world, rotor):
    world.apply_joint_effort("spin", 0.2, duration_ns=-1)
    world.delete("rotor")
    assert not world.forces
    run(world, 0.01)


# --- joint properties -------------------------------------------------------------------
def test_joint_properties_are_pybullets_joint(world, rotor):
    """get_joint_properties (gazebo_ros_api_plugin.cpp:1128-1172): position and rate of
    the joint's axis, as pybullet's joint has them; here also its own type and damping
    (Noetic answers REVOLUTE and no damping, :1152-1156)."""
    world.apply_joint_effort("spin", 0.5, duration_ns=int(0.4 * SECOND))
    run(world, 0.5)
    position, rate = pb.getJointState(rotor.robot.id, rotor.robot.joint_index["spin"],
                                      physicsClientId=world.client)[:2]
    properties = world.joint_properties("rotor::spin")
    assert properties.type == "continuous" and properties.damping == (0.0,)
    assert properties.position == (position,) and properties.rate == (rate,)
    assert rate == pytest.approx(1.0, rel=1e-3)


def test_set_joint_damping_slows_the_joint_as_damping_does(world, rotor):
    """set_joint_properties' damping (SetDamping, :1556-1557) is pybullet's joint damping:
    a torque of -d w on the disc (I = 0.2 kg m²), so w falls by exp(-d t / I): to e^-1 in
    1 s at d = 0.2 N m s. Before: no such service."""
    world.apply_joint_effort("spin", 0.5, duration_ns=int(0.4 * SECOND))
    run(world, 0.4)
    start = rotor.robot.joint_position_velocity("spin")[1]
    world.set_joint_properties("spin", damping=[0.2])
    run(world, 1.0)
    assert rotor.robot.joint_position_velocity("spin")[1] == pytest.approx(
        start * math.exp(-1.0), rel=0.02)
    assert world.joint_properties("spin").damping == (0.2,)


def test_set_joint_stops_and_motor_hold_the_joint(world, rotor):
    """hiStop and loStop (:1558-1561) are pybullet's joint limits: pushed, the continuous
    joint stops at hiStop; fmax and vel (:1572-1575) are the joint's velocity motor: it
    turns the disc at vel with at most fmax."""
    world.set_joint_properties("spin", lo_stop=[-0.2], hi_stop=[0.5])
    world.apply_joint_effort("spin", 0.5, duration_ns=int(2.0 * SECOND))
    run(world, 2.0)
    assert rotor.robot.joint_position_velocity("spin")[0] == pytest.approx(0.5, abs=0.01)
    world.set_joint_properties("spin", lo_stop=[-1e9], hi_stop=[1e9], fmax=[10.0],
                               vel=[-2.0])
    run(world, 0.5)
    assert rotor.robot.joint_position_velocity("spin")[1] == pytest.approx(-2.0, abs=0.01)


@pytest.mark.parametrize("name, arguments, words", [
    ("fix", {}, "is fixed"),
    ("spin", dict(damping=[1.0, 2.0]), "has one axis"),
    ("spin", dict(lo_stop=[1.0], hi_stop=[0.0]), "above hiStop"),
    ("spin", dict(damping=[-1.0]), "negative"),
    ("elbow", {}, "no joint named 'elbow'"),
])
def test_joint_properties_that_cannot_be_set_are_refused(world, rotor, name, arguments,
                                                          words):
    with pytest.raises(SimError, match=words):
        world.set_joint_properties(name, **arguments)


# --- link properties --------------------------------------------------------------------
# a free robot whose link 'body' lumps 'plate' (a fixed joint), and whose inertial frame is
# turned: Gazebo's Inertial keeps the body's moments in that frame (parser_urdf.cc:887-892)
LUMPED = """<robot name="lumped">
  <link name="body"><inertial><origin xyz="0.1 0 0" rpy="0 0 0.3"/><mass value="2"/>
    <inertia ixx="0.1" ixy="0.01" ixz="0" iyy="0.2" iyz="0" izz="0.3"/></inertial></link>
  <joint name="weld" type="fixed"><parent link="body"/><child link="plate"/>
    <origin xyz="0 0.5 0" rpy="0.2 0 0"/></joint>
  <link name="plate"><inertial><origin xyz="0 0 0.2"/><mass value="1"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.03"/></inertial></link>
</robot>"""


def _turn(roll, pitch, yaw):
    """URDF's fixed-axis roll, pitch, yaw as a matrix, written out (Rz Ry Rx)."""
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch),
                              math.sin(pitch), math.cos(yaw), math.sin(yaw))
    return (np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
            @ np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
            @ np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]]))


def _six(tensor):
    return (tensor[0, 0], tensor[0, 1], tensor[0, 2], tensor[1, 1], tensor[1, 2], tensor[2, 2])


def test_link_properties_lump_the_parts_by_the_parallel_axis_theorem(weightless):
    """get_link_properties (gazebo_ros_api_plugin.cpp:1174-1230) of a link that lumps a
    fixed child: the masses summed, the centre of mass their weighted mean in the link's
    frame, the inertia about it by the parallel-axis theorem, in the axes of the link's own
    inertial frame (Gazebo's Inertial, :1196-1205); com's orientation the identity
    (:1221-1224). Worked from the URDF's numbers here, not from the code under test."""
    weightless.spawn_urdf("lumped", LUMPED, (0, 0, 1))
    body_axes = _turn(0, 0, 0.3)
    body_tensor = body_axes @ np.array([[0.1, 0.01, 0], [0.01, 0.2, 0], [0, 0, 0.3]]) \
        @ body_axes.T
    body_centre = np.array([0.1, 0, 0])
    plate_axes = _turn(0.2, 0, 0)
    plate_tensor = plate_axes @ np.diag([0.01, 0.02, 0.03]) @ plate_axes.T
    plate_centre = np.array([0, 0.5, 0]) + plate_axes @ np.array([0, 0, 0.2])
    centre = (2 * body_centre + 1 * plate_centre) / 3
    tensor = np.zeros((3, 3))
    for mass, own, where in ((2, body_tensor, body_centre), (1, plate_tensor, plate_centre)):
        d = where - centre
        tensor += own + mass * (d @ d * np.eye(3) - np.outer(d, d))
    properties = weightless.link_properties("lumped::body")
    assert properties.mass == pytest.approx(3.0)
    assert properties.com == pytest.approx(tuple(centre), abs=1e-9)
    assert properties.inertia == pytest.approx(_six(body_axes.T @ tensor @ body_axes),
                                               abs=1e-9)
    assert properties.gravity_mode
    # a link alone reports its URDF inertia as written, in its inertial frame
    weightless.spawn_urdf("rotor", ROTOR, (2, 0, 0))
    disc = weightless.link_properties("rotor::disc")
    assert (disc.mass, disc.com) == (pytest.approx(2.0), pytest.approx((0, 0, 0)))
    assert disc.inertia == pytest.approx((0.1, 0, 0, 0.1, 0, 0.2), abs=1e-9)


def test_set_link_mass_halves_what_a_force_does(weightless):
    """set_link_properties' mass (SetMass, :1423) is the link's mass in pybullet: 3 N for
    1 s moves the lumped 3 kg robot at 1 m/s, at 0.5 m/s once set to 6 kg (every part
    doubled, so the centre of mass stays); the same for a free SDF box (2 kg → 4 kg)."""
    model = weightless.spawn_urdf("lumped", LUMPED, (0, 0, 1))
    box = free_box(weightless, pose=(3, 0, 1, 0, 0, 0))
    properties = weightless.link_properties("lumped::body")
    weightless.set_link_properties("lumped::body", properties.com, True, 6.0,
                                   tuple(2 * v for v in properties.inertia))
    weightless.set_link_properties("box::link", (0, 0, 0), True, 2 * BOX_MASS,
                                   (2 * BOX_INERTIA, 0, 0, 2 * BOX_INERTIA, 0,
                                    2 * BOX_INERTIA))
    weightless.apply_wrench("lumped::body", (3.0, 0, 0), (0, 0, 0), duration_ns=SECOND)
    weightless.apply_wrench("box::link", (3.0, 0, 0), (0, 0, 0), duration_ns=SECOND)
    run(weightless, 1.0)
    assert pb.getBaseVelocity(model.body, physicsClientId=weightless.client)[0][0] == \
        pytest.approx(0.5, rel=1e-3)
    assert pb.getBaseVelocity(box.body, physicsClientId=weightless.client)[0][0] == \
        pytest.approx(3.0 / (2 * BOX_MASS), rel=1e-3)
    again = weightless.link_properties("lumped::body")
    assert again.mass == pytest.approx(6.0) and again.com == pytest.approx(properties.com)
    assert again.inertia == pytest.approx(tuple(2 * v for v in properties.inertia))


def test_set_link_inertia_slows_the_joint_as_the_moment_says(world, rotor):
    """set_link_properties' moments (SetInertiaMatrix, :1422) are pybullet's: an effort of
    0.5 N m for 0.4 s turns the disc to w = t d / I, 1.0 rad/s with its izz 0.2 kg m², 0.5
    once izz is 0.4 (its mass kept). Before: no such service."""
    world.set_link_properties("rotor::disc", (0, 0, 0), True, 2.0, (0.1, 0, 0, 0.1, 0, 0.4))
    world.apply_joint_effort("spin", 0.5, duration_ns=int(0.4 * SECOND))
    run(world, 0.5)
    assert rotor.robot.joint_position_velocity("spin")[1] == pytest.approx(0.5, rel=1e-3)
    assert world.link_properties("rotor::disc").inertia == pytest.approx(
        (0.1, 0, 0, 0.1, 0, 0.4))


PENDULUM = """<robot name="pendulum"><link name="world"/>
  <link name="pivot"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0"
    iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <joint name="fix" type="fixed"><parent link="world"/><child link="pivot"/>
    <origin xyz="0 0 1"/></joint>
  <link name="arm"><inertial><origin xyz="0.5 0 0"/><mass value="1"/><inertia ixx="0.001"
    ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial></link>
  <joint name="swing" type="continuous"><parent link="pivot"/><child link="arm"/>
    <axis xyz="0 1 0"/></joint>
</robot>"""


def test_a_link_without_gravity_stays_where_it_is(world):
    """gravity_mode (SetGravityMode, :1424; get :1191): false holds the horizontal arm of a
    pendulum still for 1 s (with gravity it falls 0.5 m / (0.251 kg m^2) * 9.8 rad/s² at
    first), and a free box floats; true again and the arm swings down. pybullet has no
    switch per link: a force of m g at the centre of mass each step."""
    pendulum = world.spawn_urdf("pendulum", PENDULUM, (0, 0, 0))
    box = free_box(world, pose=(3, 0, 1, 0, 0, 0))
    arm = world.link_properties("pendulum::arm")
    world.set_link_properties("pendulum::arm", arm.com, False, arm.mass, arm.inertia)
    world.set_link_properties("box::link", (0, 0, 0), False, BOX_MASS,
                              (BOX_INERTIA, 0, 0, BOX_INERTIA, 0, BOX_INERTIA))
    assert not world.link_properties("arm").gravity_mode
    assert not world.link_properties("box::link").gravity_mode
    run(world, 1.0)
    assert pendulum.robot.joint_position_velocity("swing")[0] == pytest.approx(0, abs=1e-6)
    assert world.pose("box")[0] == pytest.approx((3, 0, 1), abs=1e-6)
    world.set_link_properties("pendulum::arm", arm.com, True, arm.mass, arm.inertia)
    run(world, 0.1)
    # at first the arm turns at 9.8 * 0.5 / 0.251 rad/s² (positive about y: down)
    assert pendulum.robot.joint_position_velocity("swing")[0] == pytest.approx(
        0.5 * 9.8 * 0.5 / 0.251 * 0.1 ** 2, rel=0.05)


@pytest.mark.parametrize("name, com, mass, inertia, words", [
    ("rotor::disc", (0, 0, 0.1), 2.0, (0.1, 0, 0, 0.1, 0, 0.2), "cannot move it"),
    ("rotor::disc", (0, 0, 0), 2.0, (0.1, 0.05, 0, 0.1, 0, 0.2), "principal axes"),
    ("rotor::disc", (0, 0, 0), 2.0, (0.1, 0, 0, 0.1, 0, -0.2), "must be positive"),
    ("rotor::disc", (0, 0, 0), 0.0, (0.1, 0, 0, 0.1, 0, 0.2), "mass 0 kg must be positive"),
    ("rotor::disc", (0, 0, 0), math.nan, (0.1, 0, 0, 0.1, 0, 0.2), "not finite"),
    ("ground::link", (0, 0, 0), 1.0, (1, 0, 0, 1, 0, 1), "static model"),
    ("rotor::wheel", (0, 0, 0), 1.0, (1, 0, 0, 1, 0, 1), "has no link 'wheel'"),
])
def test_link_properties_that_cannot_be_set_are_refused(world, rotor, name, com, mass,
                                                         inertia, words):
    """What pybullet cannot do is refused, naming why (Noetic takes them all, :1418-1424,
    and moves the centre of mass or turns the axes); nothing changes."""
    before = world.link_properties("rotor::disc")
    with pytest.raises(SimError, match=words):
        world.set_link_properties(name, com, True, mass, inertia)
    assert world.link_properties("rotor::disc") == before

"""gazebo_ros_p3d as Noetic's (gazebo_ros_pkgs noetic-devel f9e1a46,
gazebo_plugins/src/gazebo_ros_p3d.cpp): the offsets it reads are the singular
``<xyzOffset>`` / ``<rpyOffset>``, applied after the reference frame on the world's side;
the noise goes on the twist only; a link as ``<frameName>`` is applied with Noetic's own
maths. Each test checks the message that arrives, against the world's truth."""
import math

import numpy as np
import pybullet as pb
import pytest

from world_fixtures import run

SLIDE, TURN = 0.3, 0.5  # m along the hull's x, rad about its z: the two joints' positions


def probe(plugin):
    """A hull (the root) with a slider on a prismatic joint along the hull's x and a turret
    on a revolute joint about the hull's z; ``plugin``: the p3d plugin's parameters (its
    topic is ``truth``)."""
    def link(name):
        return f"""<link name="{name}"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0"
          ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>"""
    return f"""<robot name="probe">{link("hull")}{link("slider")}{link("turret")}
      <joint name="slide" type="prismatic"><parent link="hull"/><child link="slider"/>
        <axis xyz="1 0 0"/><limit lower="-5" upper="5" effort="0" velocity="10"/></joint>
      <joint name="turn" type="continuous"><parent link="hull"/><child link="turret"/>
        <axis xyz="0 0 1"/></joint>
      <gazebo><plugin name="truth" filename="libgazebo_ros_p3d.so">
        <topicName>truth</topicName>{plugin}</plugin></gazebo></robot>"""


@pytest.fixture
def weightless(world):
    world.set_physics(world.step_size, world.max_update_rate, (0.0, 0.0, 0.0))
    return world


def spawn(world, plugin, orientation=(0, 0, 0, 1)):
    world.spawn_urdf("probe", probe(plugin), (0, 0, 2), orientation,
                     joints={"slide": SLIDE, "turn": TURN})
    return world.model("probe").robot


def position(message):
    p = message.pose.pose.position
    return np.array([p.x, p.y, p.z])


def orientation(message):
    q = message.pose.pose.orientation
    return np.array([q.x, q.y, q.z, q.w])


def linear(message):
    v = message.twist.twist.linear
    return np.array([v.x, v.y, v.z])


def same_rotation(q1, q2):
    return abs(float(np.dot(q1, q2))) == pytest.approx(1.0, abs=1e-6)


YAW_90 = (0, 0, math.sin(math.pi / 4), math.cos(math.pi / 4))


def test_the_singular_offsets_move_the_pose_on_the_worlds_side(weightless, bus):
    """gazebo_plugins/src/gazebo_ros_p3d.cpp:97 and :105 read <xyzOffset> and <rpyOffset>;
    :301-304 add the position offset in world axes (p + xyzOffset) and turn the orientation
    on the world's side (q = q_rpyOffset * q). The hull, turned 90 degrees about z at
    (0, 0, 2), with offsets (1, 2, 3) and yaw 90 degrees: (1, 2, 5), facing -x (a body-frame
    offset would give (-2, 1, 5))."""
    spawn(weightless, "<bodyName>hull</bodyName><xyzOffset>1 2 3</xyzOffset>"
                      f"<rpyOffset>0 0 {math.pi / 2}</rpyOffset>", YAW_90)
    run(weightless, 0.01)
    message = bus.last("/truth")
    assert position(message) == pytest.approx((1, 2, 5), abs=1e-6)
    assert same_rotation(orientation(message), (0, 0, 1, 0))  # 180 degrees about z


def test_the_plural_offsets_are_not_read_and_named_once(weightless, bus):
    """No gazebo_plugins release reads <xyzOffsets> / <rpyOffsets>: Noetic's p3d reads the
    singular alone (gazebo_plugins/src/gazebo_ros_p3d.cpp:97, :105), so the plural changes
    nothing and the spawn names it as a tag the plugin does not read."""
    spawn(weightless, "<bodyName>hull</bodyName><xyzOffsets>1 2 3</xyzOffsets>"
                      f"<rpyOffsets>0 0 {math.pi / 2}</rpyOffsets>")
    (warning,) = [w for w in bus.warnings if "does not read" in w]
    assert "<xyzOffsets>, <rpyOffsets>" in warning and "plugin 'truth'" in warning
    run(weightless, 0.01)
    message = bus.last("/truth")
    assert position(message) == pytest.approx(weightless.pose("probe")[0], abs=1e-9)
    assert same_rotation(orientation(message), (0, 0, 0, 1))


def test_the_noise_is_on_the_twist_alone(weightless, bus):
    """gazebo_plugins/src/gazebo_ros_p3d.cpp:318-325 copy the pose as it is; :327-339 add
    N(0, gaussianNoise) to each of the twist's six values; :343-356 put gaussianNoise^2 on
    both covariance diagonals. A hull at rest: every position exact, the velocities spread
    by the noise."""
    spawn(weightless, "<bodyName>hull</bodyName><gaussianNoise>0.1</gaussianNoise>")
    messages = []
    for _ in range(400):
        weightless.step()
        messages.append(bus.last("/truth"))
    truth = weightless.pose("probe")[0]
    assert all(position(m) == pytest.approx(truth, abs=1e-6) for m in messages)
    velocities = np.array([linear(m) for m in messages])
    assert velocities.std(axis=0) == pytest.approx((0.1, 0.1, 0.1), rel=0.2)
    assert messages[-1].pose.covariance[0] == pytest.approx(0.01)
    assert messages[-1].twist.covariance[35] == pytest.approx(0.01)


def test_a_reference_links_rotation_is_taken_off_on_the_right(weightless, bus):
    """gazebo_plugins/src/gazebo_ros_p3d.cpp:291-293: relative to a link of the model,
    p = R_f^T (p - p_f) and q = q_link * q_f^-1 (ignition's `*=`: the frame's inverse on the
    right). The hull rolled 90 degrees about x, the turret turned TURN about the hull's z:
    the turret reads (0, 0, 0) and the turn about the hull's z as the world sees it, -y
    (the turn about z itself would be q_f^-1 * q_link)."""
    roll_90 = (math.sin(math.pi / 4), 0, 0, math.cos(math.pi / 4))
    spawn(weightless, "<bodyName>turret</bodyName><frameName>hull</frameName>", roll_90)
    run(weightless, 0.01)
    message = bus.last("/truth")
    assert message.header.frame_id == "hull" and message.child_frame_id == "turret"
    assert position(message) == pytest.approx((0, 0, 0), abs=1e-6)
    turned = weightless.model("probe").robot.joint_position_velocity("turn")[0]
    half = turned / 2
    assert same_rotation(orientation(message), (0, -math.sin(half), 0, math.cos(half)))


def test_a_reference_links_velocity_is_turned_by_its_rotation(weightless, bus):
    """gazebo_plugins/src/gazebo_ros_p3d.cpp:295-296: relative to a link of the model, the
    twist is R_f (v - v_f), ignition's RotateVector (not RotateVectorReverse, which :292
    uses for the position). The hull turned 90 degrees about z, the slider moving along the
    hull's x at 0.5 m/s, (0, 0.5, 0) in the world: it reads (-0.5, 0, 0) (R_f^T would give
    (0.5, 0, 0)); its position SLIDE along the hull's x."""
    robot = spawn(weightless, "<bodyName>slider</bodyName><frameName>hull</frameName>",
                  YAW_90)
    pb.resetJointState(robot.id, robot.joint_index["slide"], SLIDE, 0.5,
                       physicsClientId=weightless.client)
    weightless.step()
    message = bus.last("/truth")
    slid = robot.joint_position_velocity("slide")[0]
    assert position(message) == pytest.approx((slid, 0, 0), abs=1e-6)
    assert linear(message) == pytest.approx((-0.5, 0, 0), abs=1e-3)

"""gazebo_ros_diff_drive's switches and messages as Noetic's (gazebo_ros_pkgs noetic-devel
f9e1a46, gazebo_plugins/src/gazebo_ros_diff_drive.cpp): <publishTf> false advertises no
odometry topic and publishes no odometry (and so no odom TF), while the wheels' TF and joint
states still go out (:118-124, :167-171, :272-274); the twist's covariance is never set
(:461-467 set the pose's alone); the boolean tags read through GazeboRos::
getParameterBoolean keep their default for a text that is not true, false, 1 or 0, any case
(gazebo_plugins/src/gazebo_ros_utils.cpp:92-123); the wheels' joint_states carry names and
positions only (:199-218). Checked by what arrives on the topics, in simulated time."""
import pybullet as pb
import pytest
from geometry_msgs.msg import Twist

from world_fixtures import run

ANCHOR = "<updateRate>50</updateRate>"


def bot(diff_bot_xml, *tags, **arguments):
    xml = diff_bot_xml(**arguments)
    assert ANCHOR in xml
    return xml.replace(ANCHOR, ANCHOR + "".join(tags))


def drive(world, bus, xml, seconds=0.5):
    world.spawn_urdf("bot", xml, (0, 0, 0))
    message = Twist()
    message.linear.x, message.angular.z = 0.2, 0.5
    bus.subscriptions["/cmd_vel"](message)
    run(world, seconds)


def transforms_to(bus, child):
    return [t for t in bus.published.get("/tf", []) if t.child_frame_id == child]


def test_publish_tf_false_sends_no_odometry_but_wheel_tf_and_joint_states(world, bus,
                                                                          diff_bot_xml):
    """gazebo_plugins/src/gazebo_ros_diff_drive.cpp:167-171: the odometry topic is
    advertised only when publishTf; :272: publishOdometry (the message and the odom TF) only
    then; :273-274: the wheels' TF and joint states whatever it says. Before: the odometry
    was published and the wheels' TF suppressed."""
    drive(world, bus, bot(diff_bot_xml, "<publishTf>false</publishTf>",
                          "<publishWheelTF>true</publishWheelTF>",
                          "<publishWheelJointState>true</publishWheelJointState>"))
    assert "/odom" not in bus.advertised and "/odom" not in bus.published
    assert not transforms_to(bus, "base_footprint")
    left, right = transforms_to(bus, "left_wheel"), transforms_to(bus, "right_wheel")
    assert len(left) == len(right) == len(bus.published["/joint_states"]) >= 25  # 50 Hz
    assert world.now_ns - 20_000_000 < left[-1].header.stamp.to_nsec() <= world.now_ns
    assert world.pose("bot")[0][0] > 0.05  # the commands still drive it (:277-306)


def test_publish_tf_false_alone_sends_nothing(world, bus, diff_bot_xml):
    """gazebo_plugins/src/gazebo_ros_diff_drive.cpp:96-98 (publishWheelTF and
    publishWheelJointState default false), :167-172: no odometry, and no TF at all."""
    drive(world, bus, bot(diff_bot_xml, "<publishTf>false</publishTf>"))
    assert "/odom" not in bus.advertised and "/tf" not in bus.published


@pytest.mark.parametrize("written, sent", [("true", True), ("True", True), ("1", True),
                                           ("yes", False), ("0", False)])
def test_publish_tf_is_read_as_sdformat_reads_a_bool(world, bus, diff_bot_xml, written, sent):
    """gazebo_plugins/src/gazebo_ros_diff_drive.cpp:123 reads publishTf with
    sdf::Element::Get<bool>, not getParameterBoolean: sdformat 9 lower-cases the text and
    reads true or 1 as true, anything else as false (sdformat sdf9 include/sdf/Param.hh,
    Param::Get), with no warning."""
    drive(world, bus, bot(diff_bot_xml, f"<publishTf>{written}</publishTf>"), seconds=0.1)
    assert ("/odom" in bus.published) == sent
    assert not [w for w in bus.warnings if "publishTf" in w]


@pytest.mark.parametrize("source", ["world", "encoder"])
def test_the_twist_covariance_is_zero(world, bus, diff_bot_xml, source):
    """gazebo_plugins/src/gazebo_ros_diff_drive.cpp:461-467 set the pose's covariance
    (1e-5, 1e-5, 1e12 x3, 1e-3) and nothing sets the twist's: all 0, for both sources.
    Before: the pose's values on the twist's diagonal too."""
    drive(world, bus, diff_bot_xml(odometry_source=source), seconds=0.2)
    odometry = bus.last("/odom")
    assert list(odometry.twist.covariance) == [0.0] * 36
    assert [odometry.pose.covariance[i * 7] for i in range(6)] == \
        [1e-5, 1e-5, 1e12, 1e12, 1e12, 1e-3]


@pytest.mark.parametrize("written", ["yes", "on", "tru", ""])
def test_an_unreadable_publish_odom_tf_keeps_its_default_true(world, bus, diff_bot_xml,
                                                              written):
    """gazebo_plugins/src/gazebo_ros_utils.cpp:114-118: a text that is not true, false, 1 or
    0 (boost::iequals, any case) warns "must be either true or false" and keeps the default,
    true for publishOdomTF (gazebo_plugins/src/gazebo_ros_diff_drive.cpp:97); the odom TF is
    sent. Before: any text but 1 or true was false, silently."""
    drive(world, bus, bot(diff_bot_xml, f"<publishOdomTF>{written}</publishOdomTF>"),
          seconds=0.1)
    assert transforms_to(bus, "base_footprint")
    (warning,) = [w for w in bus.warnings if "<publishOdomTF>" in w]
    assert f"'{written}'" in warning and "True" in warning


@pytest.mark.parametrize("written, published", [("TRUE", True), ("1", True), ("False", False),
                                                ("0", False)])
def test_the_words_getparameterboolean_knows_in_any_case(world, bus, diff_bot_xml, written,
                                                         published):
    """gazebo_plugins/src/gazebo_ros_utils.cpp:106-113: true or 1, false or 0, compared
    with boost::iequals (any case), no warning."""
    drive(world, bus, bot(diff_bot_xml,
                          f"<publishWheelJointState>{written}</publishWheelJointState>"),
          seconds=0.1)
    assert ("/joint_states" in bus.published) == published
    assert not [w for w in bus.warnings if "publishWheelJointState" in w]


def test_unreadable_wheel_flags_keep_their_default_false_with_a_warning(world, bus,
                                                                        diff_bot_xml):
    """gazebo_plugins/src/gazebo_ros_diff_drive.cpp:96, :98 (defaults false) through
    gazebo_plugins/src/gazebo_ros_utils.cpp:114-118: 'Yes' keeps false and warns. Before:
    false, silently."""
    drive(world, bus, bot(diff_bot_xml, "<publishWheelTF>Yes</publishWheelTF>",
                          "<publishWheelJointState>enabled</publishWheelJointState>"),
          seconds=0.1)
    assert not transforms_to(bus, "left_wheel") and "/joint_states" not in bus.published
    assert [w for w in bus.warnings if "<publishWheelTF> 'Yes'" in w]
    assert [w for w in bus.warnings if "<publishWheelJointState> 'enabled'" in w]


def test_wheel_joint_states_carry_names_and_positions_only(world, bus, diff_bot_xml):
    """gazebo_plugins/src/gazebo_ros_diff_drive.cpp:199-218: the message's name and position
    are resized and filled (joint->Position(0)), velocity and effort left empty, stamped
    with the simulated time (:201-203). Before: velocity and effort were filled too."""
    drive(world, bus, bot(diff_bot_xml,
                          "<publishWheelJointState>true</publishWheelJointState>"), seconds=0.2)
    robot = world.model("bot").robot
    names = ["left_wheel_joint", "right_wheel_joint"]
    positions = {}
    for _ in range(40):
        world.step()
        positions[world.now_ns] = [robot.joint_position_velocity(j)[0] for j in names]
    messages = [m for m in bus.published["/joint_states"]
                if m.header.stamp.to_nsec() in positions]
    assert len(messages) == 2  # 50 Hz over the last 40 ms, stamped at steps' times
    for message in messages:
        assert message.name == names
        assert list(message.position) == positions[message.header.stamp.to_nsec()]
        assert message.position[0] != 0.0
        assert list(message.velocity) == [] and list(message.effort) == []


def test_the_wheel_tf_names_the_lumped_parent_and_gives_the_pose_in_the_model(world, bus,
                                                                            diff_bot_xml):
    """gazebo_plugins/src/gazebo_ros_diff_drive.cpp:225-231: the frame is the joint's parent
    link as Gazebo has it after lumping fixed joints (the test robot's base_link, fixed
    0.08 m above base_footprint, is lumped into base_footprint), the pose the wheel link's
    RelativePose, relative to the model (the root link base_footprint). Checked against
    pybullet's poses of the wheel and of the root link. Before: parent base_link, the pose
    relative to base_link (z -0.03 instead of 0.05)."""
    drive(world, bus, bot(diff_bot_xml, "<publishWheelTF>true</publishWheelTF>"), 0.3)
    robot = world.model("bot").robot
    model_inverse = pb.invertTransform(*robot.base_pose())
    for wheel in ("left_wheel", "right_wheel"):
        transform = transforms_to(bus, wheel)[-1]
        assert transform.header.frame_id == "base_footprint"
        position, orientation = pb.multiplyTransforms(*model_inverse, *robot.link_pose(wheel))
        translation, rotation = transform.transform.translation, transform.transform.rotation
        assert (translation.x, translation.y, translation.z) == pytest.approx(position,
                                                                              abs=1e-9)
        assert (rotation.x, rotation.y, rotation.z, rotation.w) == pytest.approx(orientation,
                                                                                 abs=1e-9)
        assert translation.z == pytest.approx(0.05, abs=1e-3)

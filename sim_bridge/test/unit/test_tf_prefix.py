"""The prefix of gazebo_plugins' frames, as Noetic's tf::getPrefixParam finds it
(gazebo_ros_pkgs noetic-devel f9e1a46, gazebo_plugins/src/gazebo_ros_utils.cpp:87): the
``tf_prefix`` parameter searched from the model's namespace up to the root; none set, no
prefix (the namespace is not one); and the diff drive's frames carry it."""
import pytest
from geometry_msgs.msg import Twist

from sim_bridge.ros_node import search_tf_prefix
from world_fixtures import run


@pytest.mark.parametrize("namespace,params,prefix", [
    ("/r1", {}, ""),                                     # a namespace is no prefix
    ("", {}, ""),
    ("/r1", {"/r1/tf_prefix": "robot1"}, "robot1"),
    ("/fleet/r1", {"/fleet/tf_prefix": "fleet"}, "fleet"),   # found further up
    ("/fleet/r1", {"/tf_prefix": "top", "/fleet/r1/tf_prefix": "own"}, "own"),  # nearest wins
    ("r2", {"/tf_prefix": "top"}, "top"),
    ("/r1", {"/r2/tf_prefix": "robot2"}, ""),            # a sibling's is not searched
])
def test_the_prefix_is_searched_from_the_namespace_up(namespace, params, prefix):
    assert search_tf_prefix(namespace, params.get) == prefix


@pytest.mark.parametrize("prefix,odom,base", [
    ("", "odom", "base_footprint"), ("r1", "r1/odom", "r1/base_footprint")])
def test_the_diff_drive_frames_carry_the_prefix_and_no_namespace(world, bus, diff_bot_xml,
                                                                 prefix, odom, base):
    world.spawn_urdf("bot", diff_bot_xml(), (0, 0, 0.06), namespace="/r1", tf_prefix=prefix)
    bus.subscriptions["/r1/cmd_vel"](Twist())
    run(world, 0.1)
    odometry = bus.last("/r1/odom")
    assert (odometry.header.frame_id, odometry.child_frame_id) == (odom, base)


@pytest.mark.parametrize("written,prefix,published", [
    ("/world", "r1", "world"),        # absolute: the slash dropped, no prefix (tf.cpp:162-166)
    ("world", "r1", "r1/world"),
    ("/world", "", "world"),
    ("chassis", "", "chassis"),
])
def test_a_frame_written_with_a_slash_is_absolute(world, bus, written, prefix, published):
    """gazebo_ros_p3d's <frameName> (its odometry's header) through tf::resolve (ros/geometry
    noetic-devel fe344b6, tf/src/tf.cpp:159-185)."""
    xml = f"""<robot name="puck">
  <link name="chassis">
    <inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
  </link>
  <gazebo><plugin name="truth" filename="libgazebo_ros_p3d.so">
    <bodyName>chassis</bodyName><topicName>truth</topicName><frameName>{written}</frameName>
    <updateRate>100</updateRate>
  </plugin></gazebo>
</robot>"""
    world.spawn_urdf("puck", xml, (0, 0, 0.5), namespace="/", tf_prefix=prefix)
    run(world, 0.05)
    assert bus.last("/truth").header.frame_id == published

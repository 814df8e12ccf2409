"""gazebo_plugins' model plugins that report one body or joint, parameter by parameter as
Noetic reads them (gazebo_ros_pkgs noetic-devel f9e1a46, gazebo_plugins/src/):
gazebo_ros_joint_state_publisher.cpp, gazebo_ros_f3d.cpp, gazebo_ros_ft_sensor.cpp,
gazebo_ros_imu.cpp: where their topics go, their frames, their rates and their messages
(sim_bridge/README.md, each plugin's table)."""
import pytest

from world_fixtures import run

ABSENT = None


def post(plugins):
    """A post fixed to the world, an arm on a revolute joint 1 m up, and ``plugins``."""
    inertia = 'ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"'
    return f"""<robot name="post"><link name="world"/>
      <joint name="anchor" type="fixed"><parent link="world"/><child link="post"/></joint>
      <link name="post"><inertial><mass value="10"/><inertia {inertia}/></inertial></link>
      <joint name="shoulder" type="revolute"><parent link="post"/><child link="arm"/>
        <origin xyz="0 0 1"/><axis xyz="0 0 1"/>
        <limit lower="-10" upper="10" effort="100" velocity="100"/></joint>
      <link name="arm"><inertial><origin xyz="0.5 0 0"/><mass value="2"/>
        <inertia {inertia}/></inertial></link>
      <gazebo>{plugins}</gazebo></robot>"""


def plugins(namespace=ABSENT, jsp=""):
    own = "" if namespace is ABSENT else f"<robotNamespace>{namespace}</robotNamespace>"
    return f"""
      <plugin name="jsp" filename="libgazebo_ros_joint_state_publisher.so">{own}
        {jsp or '<jointName>shoulder</jointName>'}</plugin>
      <plugin name="f3d" filename="libgazebo_ros_f3d.so">{own}
        <bodyName>arm</bodyName><topicName>arm_force</topicName></plugin>
      <plugin name="ft" filename="libgazebo_ros_ft_sensor.so">{own}
        <jointName>shoulder</jointName><topicName>shoulder_wrench</topicName></plugin>
      <plugin name="imu" filename="libgazebo_ros_imu.so">{own}
        <bodyName>arm</bodyName><topicName>arm_imu</topicName></plugin>"""


def stamps_ms(bus, topic):
    return [round(m.header.stamp.to_nsec() / 1e6) for m in bus.published.get(topic, [])]


# --- robotNamespace ------------------------------------------------------------------------
@pytest.mark.parametrize("own, spawned_in, jsp_under, others_under", [
    (ABSENT, "/r1", "/r1", "/r1"),     # the spawn service gives its namespace to each plugin
    (ABSENT, "", "/post", ""),         # none given: the joint state publisher the model's
    ("", "/r1", "/post", ""),          # an empty tag: the model's name; "" + "/" the top level
    ("team", "/r1", "/team", "/team"),  # a plugin's own tag is kept
])
def test_each_plugins_namespace_is_its_own_rule(world, bus, own, spawned_in, jsp_under,
                                                others_under):
    """joint_state_publisher: the model's name when absent or empty (:50-58);
    f3d (:62-64), ft_sensor (:63-65), imu (:69-71): "" when absent, the tag + "/" when
    present, so an empty tag is the top level. The spawn request's namespace goes to every
    plugin without a tag (gazebo_ros/src/gazebo_ros_api_plugin.cpp:2623-2649)."""
    world.spawn_urdf("post", post(plugins(own)), namespace=spawned_in)
    run(world, 0.02)
    assert f"{jsp_under}/joint_states" in bus.published, sorted(bus.published)
    for topic in ("arm_force", "shoulder_wrench", "arm_imu"):
        assert f"{others_under}/{topic}" in bus.published, sorted(bus.published)
    assert "/default_imu" in bus.services  # the imu's serviceName, absolute


# --- libgazebo_ros_joint_state_publisher.so ------------------------------------------------
def test_joint_states_come_a_period_and_a_step_after_the_load_without_effort(world, bus):
    """last_update_time_ is the time of the load (:85-88); a message goes out once more than
    a period has passed, and the slot moves on by one period (:132-143): 100 Hz on 1 ms steps
    is 11, 21, 31, 41 ms (before: 1, 10, 20, 30, 40 ms). The message has name, position and
    velocity, no effort (:147-167; before: effort too)."""
    world.spawn_urdf("post", post(plugins()), namespace="/")
    run(world, 0.045)
    assert stamps_ms(bus, "/joint_states") == [11, 21, 31, 41]
    message = bus.last("/joint_states")
    assert message.name == ["shoulder"] and len(message.position) == 1
    assert len(message.velocity) == 1 and list(message.effort) == []


def test_joint_states_at_update_rate_0_go_out_every_step(world, bus):
    """updateRate 0: a period of 0 (:79-83), more than 0 s has passed at every step."""
    world.spawn_urdf("post", post(plugins(jsp="<jointName>shoulder</jointName>"
                                               "<updateRate>0</updateRate>")), namespace="/")
    run(world, 0.005)
    assert stamps_ms(bus, "/joint_states") == [1, 2, 3, 4, 5]


def test_joint_names_lose_their_spaces(world, bus):
    """boost::erase_all(joint_names, " ") then split at commas (:64-67)."""
    world.spawn_urdf("post", post(plugins(jsp="<jointName> shoulder , anchor </jointName>")),
                     namespace="/")
    run(world, 0.02)
    assert bus.last("/joint_states").name == ["shoulder", "anchor"]


def test_without_joint_names_empty_joint_states_go_out(world, bus):
    """No <jointName>: Noetic's ROS_ASSERT with a string does nothing (:61-62), the list
    stays empty and empty messages go out at the rate (before: the plugin was left out);
    a warning says what to write."""
    world.spawn_urdf("post", post(plugins(jsp="<updateRate>100</updateRate>")),
                     namespace="/")
    run(world, 0.02)
    assert stamps_ms(bus, "/joint_states") == [11]
    assert bus.last("/joint_states").name == []
    assert any("no <jointName>" in w for w in bus.warnings)


def test_an_empty_name_in_the_list_leaves_the_plugin_out(world, bus):
    """"shoulder,,anchor" asks for a joint named "" (:67), which Noetic logs as fatal and
    then crashes on (:90-97, :156): here the plugin is left out, naming the text."""
    world.spawn_urdf("post", post(plugins(jsp="<jointName>shoulder,,anchor</jointName>")),
                     namespace="/")
    run(world, 0.02)
    assert "/joint_states" not in bus.published
    assert any("'shoulder,,anchor'" in w and "not loaded" in w for w in bus.warnings)


# --- libgazebo_ros_f3d.so --------------------------------------------------------------------
@pytest.mark.parametrize("frame, prefix, header", [("", "", "world"), ("", "p", "p/world"),
                                                   ("<frameName>/world</frameName>", "p",
                                                    "world"),
                                                   ("<frameName>arm</frameName>", "p", "p/arm")])
def test_the_f3d_header_is_its_frame_name_through_tf_resolve(world, bus, frame, prefix,
                                                             header):
    """frameName (world, :89-99) through tf::resolve with the tf_prefix (:112-115)."""
    xml = post(plugins()).replace("<topicName>arm_force</topicName>",
                                  f"<topicName>arm_force</topicName>{frame}")
    bus.params["/tf_prefix"] = prefix
    world.spawn_urdf("post", xml, namespace="/", tf_prefix=prefix)
    run(world, 0.002)
    assert bus.last("/arm_force").header.frame_id == header


def test_the_f3d_publishes_every_step_while_someone_listens(world, bus):
    """No rate: every world update while subscribed (:150-156), stamped with its time."""
    bus.unheard.add("/arm_force")
    world.spawn_urdf("post", post(plugins()), namespace="/")
    run(world, 0.005)
    assert "/arm_force" not in bus.published
    bus.unheard.clear()
    run(world, 0.003)
    assert stamps_ms(bus, "/arm_force") == [6, 7, 8]


@pytest.mark.parametrize("params, header", [
    ({"/tf_prefix": "top"}, "world"), ({"/tf_prefix": "top", "/r1/tf_prefix": "own"},
                                       "own/world"), ({"/r1/tf_prefix": 3}, "world")])
def test_the_f3d_and_ft_sensor_read_tf_prefix_in_their_own_namespace_only(world, bus, params,
                                                                           header):
    """Both plugins read ``tf_prefix`` with getParam on a node handle in their robotNamespace
    (gazebo_ros_f3d.cpp:110-115, gazebo_ros_ft_sensor.cpp:121-126), not by tf's
    searchParam (ros/geometry noetic-devel fe344b6 tf/include/tf/transform_listener.h:55-63)
    that gives the model its tf_prefix: a prefix set only above the robot's namespace is not
    theirs (before: the model's, top/world and top/arm), and a value that is not a string
    is not read."""
    bus.params.update(params)
    world.spawn_urdf("post", post(plugins()), namespace="/r1", tf_prefix="top")
    run(world, 0.002)
    assert bus.last("/r1/arm_force").header.frame_id == header
    assert bus.last("/r1/shoulder_wrench").header.frame_id == header.replace("world", "arm")


# --- libgazebo_ros_ft_sensor.so --------------------------------------------------------------
def test_the_ft_sensor_rate_counts_from_0_and_its_frame_is_the_child_link(world, bus):
    """updateRate: nothing until 1/rate s after the last message, the last starting at 0
    (:173-176, :228): 50 Hz is 20, 40, 60 ms (before: 1, 20, 40, 60 ms); the frame is the
    joint's child link through tf::resolve (:84, :124-126)."""
    xml = post(plugins()).replace("<topicName>shoulder_wrench</topicName>",
                                  "<topicName>shoulder_wrench</topicName>"
                                  "<updateRate>50</updateRate>")
    bus.params["/tf_prefix"] = "p"
    world.spawn_urdf("post", xml, namespace="/", tf_prefix="p")
    run(world, 0.07)
    assert stamps_ms(bus, "/shoulder_wrench") == [20, 40, 60]
    assert bus.last("/shoulder_wrench").header.frame_id == "p/arm"


def test_the_ft_sensor_waits_for_a_listener_without_losing_its_turn(world, bus):
    """The rate is checked first, then the subscribers, and the last message's time is kept
    only when one went out (:173-179, :228): a listener arriving at 35 ms gets a message at
    once (before: at the next multiple of the period, 40 ms)."""
    xml = post(plugins()).replace("<topicName>shoulder_wrench</topicName>",
                                  "<topicName>shoulder_wrench</topicName>"
                                  "<updateRate>50</updateRate>")
    bus.unheard.add("/shoulder_wrench")
    world.spawn_urdf("post", xml, namespace="/")
    run(world, 0.035)
    bus.unheard.clear()
    run(world, 0.03)
    assert stamps_ms(bus, "/shoulder_wrench") == [36, 56]


# --- libgazebo_ros_imu.so ------------------------------------------------------------------
def test_the_old_imus_service_and_frame(world, bus):
    """serviceName and topicName default to /default_imu (:73-87), frameName to bodyName as
    written (:130-136), no tf_prefix; an empty topicName advertises neither (:165-178)."""
    world.spawn_urdf("post", post(plugins()).replace("<topicName>arm_imu</topicName>", ""),
                     namespace="/", tf_prefix="p")
    run(world, 0.002)
    assert bus.last("/default_imu").header.frame_id == "arm"
    assert "/default_imu" in bus.services
    world.delete("post")
    bus.published.clear()
    bus.services.clear()
    world.spawn_urdf("post", post(plugins()).replace("<topicName>arm_imu</topicName>",
                                                     "<topicName></topicName>"),
                     namespace="/")
    run(world, 0.002)
    assert not [t for t in bus.published if "imu" in t] and not bus.services


def test_the_old_imus_rpy_offset_turns_on_the_worlds_side_and_xyz_offset_does_nothing(
        world, bus):
    """rpyOffset: rot = offset.Rot() * link.Rot() (:113-119, :256-257), the offset on the
    world's side; xyzOffset moves only a position the plugin never uses (:105-111, :252):
    the arm's frame origin, on the joint's axis, reads no acceleration while it spins,
    whatever xyzOffset says (a lever arm would read w^2 |r|)."""
    from sim_bridge.plugins.body_state import q_multiply
    from sim_bridge.poses import quaternion_from_rpy
    xml = post(plugins()).replace(
        "<topicName>arm_imu</topicName>",
        "<topicName>arm_imu</topicName><rpyOffset>0.3 0 0</rpyOffset>"
        "<xyzOffset>1 2 3</xyzOffset>")
    world.spawn_urdf("post", xml, namespace="/", joints={"shoulder": 0.5})
    world.apply_joint_effort("shoulder", 2.0, duration_ns=1_000_000_000)
    run(world, 0.2)
    imu = bus.last("/arm_imu")
    _, link = world.model("post").robot.link_pose("arm")
    expected = q_multiply(quaternion_from_rpy(0.3, 0, 0), link)
    got = (imu.orientation.x, imu.orientation.y, imu.orientation.z, imu.orientation.w)
    assert abs(sum(a * b for a, b in zip(got, expected))) == pytest.approx(1.0, abs=1e-6)
    assert abs(imu.angular_velocity.x) + abs(imu.angular_velocity.y) + \
        abs(imu.angular_velocity.z) > 0.5  # it spins
    a = imu.linear_acceleration
    assert (a.x, a.y, a.z) == pytest.approx((0, 0, 0), abs=1e-3)  # a 3.7 m lever: ~2 m/s²

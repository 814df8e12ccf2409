"""A plugin that cannot run as written is left out with a warning naming it and the cause,
and the model spawns, as Gazebo loads it; nothing the plugin opened stays behind."""
from controller_manager_msgs.srv import ListControllersRequest, LoadControllerRequest

from world_fixtures import run

BASE = """<link name="base"><inertial><mass value="1"/>
  <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
  <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link>"""


def robot(gazebo):
    return f'<robot name="r">{BASE}<gazebo>{gazebo}</gazebo></robot>'


# a list of joints where one is expected (seen in a tutorial's four-wheel robot)
JOINT_LIST = robot("""<plugin name="drive" filename="libgazebo_ros_diff_drive.so">
  <leftJoint>front_left_wheel_joint, rear_left_wheel_joint</leftJoint>
  <rightJoint>front_right_wheel_joint</rightJoint></plugin>
  <plugin name="truth" filename="libgazebo_ros_p3d.so"><bodyName>base</bodyName>
  <topicName>ground_truth</topicName><updateRate>100</updateRate></plugin>""")
NO_TRANSMISSION = robot("""<plugin name="gazebo_ros_control"
  filename="libgazebo_ros_control.so"><robotNamespace>/r</robotNamespace></plugin>""")


def test_a_plugin_naming_joints_the_model_lacks_is_skipped_and_the_rest_runs(world, bus):
    world.spawn_urdf("r", JOINT_LIST, (0, 0, 0.1))
    assert "r" in world.models
    (warning,) = [w for w in bus.warnings if "not loaded" in w]
    assert "plugin 'drive'" in warning and "front_left_wheel_joint, rear_left_wheel_joint" \
        in warning and "spawned without it" in warning
    # what the skipped plugin opened is closed (its odometry topic is never opened: Noetic's
    # reads the joints before it advertises, gazebo_plugins/src/gazebo_ros_diff_drive.cpp:111
    # and :169); the other plugin publishes
    assert "/cmd_vel" in bus.closed
    assert set(bus.advertised) - set(bus.closed) == {"/ground_truth"}
    run(world, 0.1)
    assert bus.published["/ground_truth"]


def test_ros_control_without_transmissions_serves_a_controller_manager_with_no_joint(world,
                                                                                    bus):
    """No <transmission> at all: Noetic's plugin takes the empty list (gazebo_ros_pkgs
    noetic-devel f9e1a46 gazebo_ros_control_plugin.cpp:300-304) and its controller manager
    serves no joint: a joint state controller loads, a controller naming a joint does not.
    Before: no controller manager."""
    world.spawn_urdf("r", NO_TRANSMISSION, (0, 0, 0.1))
    assert "r" in world.models
    assert any("gazebo_ros_control" in w and "<transmission>" in w for w in bus.warnings)
    bus.params.update({"/r/states": {"type": "joint_state_controller/JointStateController",
                                     "publish_rate": 50},
                       "/r/arm": {"type": "position_controllers/JointTrajectoryController",
                                  "joints": ["base"]}})
    load = bus.services["/r/controller_manager/load_controller"]
    assert load(LoadControllerRequest("states")).ok
    assert not load(LoadControllerRequest("arm")).ok
    listed = bus.services["/r/controller_manager/list_controllers"](ListControllersRequest())
    assert [c.name for c in listed.controller] == ["states"]


def test_a_deleted_model_with_a_skipped_plugin_leaves_the_world_consistent(world, bus):
    world.spawn_urdf("r", NO_TRANSMISSION, (0, 0, 0.1))
    world.delete("r")
    world.spawn_urdf("r", NO_TRANSMISSION, (0, 0, 0.1))
    run(world, 0.1)
    assert list(world.models) == ["ground", "r"]


OLD_NAMES = robot("""<plugin name="truth" filename="libgazebo_ros_p3d.so">
  <alwaysOn>true</alwaysOn><bodyName>base</bodyName><topicName>ground_truth</topicName>
  <torque>20</torque><maxVelocity>3</maxVelocity></plugin>""")


def test_parameters_a_plugin_does_not_read_are_named_once(world, bus):
    world.spawn_urdf("r", OLD_NAMES, (0, 0, 0.1))
    (warning,) = [w for w in bus.warnings if "does not read" in w]
    assert "plugin 'truth'" in warning and "<torque>, <maxVelocity>" in warning
    assert "alwaysOn" not in warning  # every gazebo_ros plugin takes it


def test_gazebo_ros_controls_own_parameters_are_read(world, bus, diff_bot_xml):
    written = '<plugin filename="libgazebo_ros_control.so" name="gazebo_ros_control"/>'
    xml = diff_bot_xml(drive="ros_control")
    assert written in xml
    xml = xml.replace(written, written[:-2] + "><legacyModeNS>true</legacyModeNS>"
                      "<robotParam>robot_description</robotParam><robotSimType>"
                      "gazebo_ros_control/DefaultRobotHWSim</robotSimType></plugin>")
    world.spawn_urdf("r", xml, (0, 0, 0))
    assert "r" in world.models
    assert not [w for w in bus.warnings if "does not read" in w or "robotSimType" in w]
    # Kinetic's legacyModeNS, which Noetic reads no more (as Interbotix's files still write
    # it): a verbose note, never a warning
    (note,) = [d for d in bus.debugs if "<legacyModeNS>" in d]
    assert "ignores <legacyModeNS>" in note and "Noetic" in note


# --- what Gazebo loads with a warning ---------------------------------------------------
def drive(bus, world, forward, seconds):
    from geometry_msgs.msg import Twist
    twist = Twist()
    twist.linear.x = forward
    bus.subscriptions["/cmd_vel"](twist)
    run(world, seconds)


def test_a_gazebo_block_for_a_link_the_robot_lacks_warns_and_the_robot_runs(world, bus,
                                                                             diff_bot_xml):
    # a robot whose camera link was commented out, its <gazebo> block left in
    xml = diff_bot_xml().replace("</robot>", """<gazebo reference="camera_link">
      <material>Gazebo/Black</material>
      <sensor name="camera" type="camera"><update_rate>30</update_rate></sensor>
    </gazebo></robot>""")
    world.spawn_urdf("bot", xml, (0, 0, 0.06))
    (warning,) = [w for w in bus.warnings if "camera_link" in w]
    assert "names no link or joint" in warning and "<sensor 'camera'>" in warning
    drive(bus, world, 0.3, 1.0)
    assert world.pose("bot")[0][0] > 0.15  # it drives: the rest of its <gazebo> tags run


def test_a_drive_parameter_gazebo_cannot_read_takes_its_default_and_the_plugin_runs(
        world, bus, diff_bot_xml):
    # <wheelAcceleration>true</wheelAcceleration>, seen in a homework robot: 0 (no limit)
    world.spawn_urdf("bot", diff_bot_xml(wheel_acceleration="true"), (0, 0, 0.06))
    (warning,) = [w for w in bus.warnings if "<wheelAcceleration>" in w]
    assert "'true' is not a number" in warning and "its default, 0" in warning
    assert not [w for w in bus.warnings if "not loaded" in w]
    drive(bus, world, 0.3, 1.0)
    assert world.pose("bot")[0][0] > 0.15


UNREADABLE = robot("""<plugin name="truth" filename="libgazebo_ros_p3d.so">
  <bodyName>base</bodyName><topicName>ground_truth</topicName><updateRate>often</updateRate>
  <xyzOffset>1 two 3</xyzOffset><gaussianNoise>nan</gaussianNoise></plugin>""")


def test_every_unreadable_value_is_named_with_the_default_used(world, bus):
    world.spawn_urdf("r", UNREADABLE, (0, 0, 0.1))
    named = {tag: w for w in bus.warnings for tag in ("updateRate", "xyzOffset", "gaussianNoise")
             if f"<{tag}>" in w}
    assert "'often' is not a number" in named["updateRate"]
    assert "'1 two 3' is not three numbers" in named["xyzOffset"]
    assert "its default, 0 0 0" in named["xyzOffset"]
    assert "'nan' is not a finite number" in named["gaussianNoise"]
    run(world, 0.1)
    message = bus.published["/ground_truth"][-1]
    assert abs(message.pose.pose.position.z - world.pose("r")[0][2]) < 1e-6  # no offset, no noise


UNREADABLE_IMU = f"""<robot name="r">{BASE}<gazebo reference="base">
  <sensor name="imu" type="imu"><update_rate>fast</update_rate>
  <plugin name="imu" filename="libgazebo_ros_imu_sensor.so"><topicName>imu</topicName>
  <frameName>base</frameName><xyzOffset>0 0</xyzOffset><rpyOffset>zero 0 0</rpyOffset></plugin></sensor></gazebo></robot>"""


def test_an_imu_with_unreadable_offsets_and_rate_runs_on_its_defaults(world, bus):
    world.spawn_urdf("r", UNREADABLE_IMU, (0, 0, 0.1))
    assert not [w for w in bus.warnings if "not loaded" in w]
    named = {tag: w for w in bus.warnings for tag in ("xyzOffset", "rpyOffset", "update_rate")
             if f"<{tag}>" in w}
    assert "'0 0' is not three numbers" in named["xyzOffset"]
    assert "'zero 0 0' is not three numbers" in named["rpyOffset"]
    assert "'fast' is not a rate in Hz" in named["update_rate"]
    run(world, 1.0)  # the sensor at every step, the plugin's default 1 Hz: a message at 1 s
    message = bus.published["/imu"][-1]
    assert abs(message.linear_acceleration.z - 9.8) < 0.2  # at rest, level: +g, no rotation

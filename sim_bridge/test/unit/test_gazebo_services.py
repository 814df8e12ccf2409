"""The /gazebo services as sim_bridge's node answers them, called on its handlers with no
master (the physics thread run inline), against Noetic's gazebo_ros_api_plugin.cpp
(gazebo_ros_pkgs noetic-devel f9e1a46, gazebo_ros/src/gazebo_ros_api_plugin.cpp): what a
request does, what it answers, and its answer when it cannot be done (sim_bridge/README.md,
the services' table)."""
import math

import pybullet as pb
import pytest
from geometry_msgs.msg import Pose
from std_srvs.srv import Empty, EmptyRequest

from gazebo_msgs.msg import LinkState, ModelState, ODEJointProperties
from gazebo_msgs.srv import (ApplyBodyWrench, ApplyBodyWrenchRequest, BodyRequest,
                             BodyRequestRequest, DeleteModel, DeleteModelRequest,
                             GetJointProperties, GetLinkProperties, GetModelProperties,
                             GetModelPropertiesRequest, GetModelState,
                             GetModelStateRequest, GetPhysicsProperties,
                             GetPhysicsPropertiesRequest, GetWorldProperties,
                             GetWorldPropertiesRequest, JointRequest, JointRequestRequest,
                             SetJointProperties, SetLinkProperties,
                             SetModelConfiguration,
                             SetModelConfigurationRequest,
                             SetModelState, SetModelStateRequest, SpawnModel,
                             SpawnModelRequest)
from sim_bridge.ros_node import Config, SimBridgeNode
from world_fixtures import run

BOX = """<robot name="box"><link name="base"><inertial><mass value="1"/><inertia ixx="0.01"
  ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial><collision><geometry>
  <box size="0.2 0.2 0.2"/></geometry></collision></link></robot>"""


class Inline:
    """The physics thread's hand-over, done at once."""

    @staticmethod
    def call(work):
        return work()

    @staticmethod
    def post(work):
        work()


@pytest.fixture
def node(world, monkeypatch):
    simulator = SimBridgeNode(Config(), world, Inline())
    # the tf_prefix is looked up at the master; there is none here
    monkeypatch.setattr(SimBridgeNode, "_tf_prefix", staticmethod(lambda namespace: ""))
    return simulator


def call(node, kind, handler, **fields):
    return node._guarded(handler, kind)(kind._request_class(**fields))


def spawn(node, name, x=0.0):
    pose = Pose()
    pose.position.x, pose.position.z, pose.orientation.w = x, 0.1, 1.0
    return call(node, SpawnModel, node._spawn_urdf, model_name=name, model_xml=BOX,
                robot_namespace="/", initial_pose=pose, reference_frame="")


def test_spawn_answers_and_a_name_in_use_is_refused(node):
    """SpawnModel: success "SpawnModel: Successfully spawned entity" (:2747); a name in use
    success false (:2692)."""
    answer = spawn(node, "a")
    assert answer.success and answer.status_message.startswith(
        "SpawnModel: Successfully spawned entity")
    again = spawn(node, "a")
    assert not again.success and again.status_message.startswith("SpawnModel: ")
    assert "exists already" in again.status_message


def test_get_model_states_header_frame_is_the_request_as_written(node):
    """res.header.frame_id = req.relative_entity_name (:970): "" stays "" (before:
    "world"); the empty name, world and map are the world's frame (:1008-1011)."""
    spawn(node, "a", x=1.0)
    for frame in ("", "world", "map"):
        answer = call(node, GetModelState, node._get_state, model_name="a",
                      relative_entity_name=frame)
        assert answer.success and answer.header.frame_id == frame
        assert answer.pose.position.x == pytest.approx(1.0, abs=1e-6)
        assert answer.status_message == "GetModelState: got properties"  # :1036


def test_get_model_state_relative_to_another_model(node):
    """model_pose - frame_pose (:1000-1002), the frame a model's name."""
    spawn(node, "a", x=1.0)
    spawn(node, "b", x=3.0)
    answer = call(node, GetModelState, node._get_state, model_name="b",
                  relative_entity_name="a")
    assert answer.success and answer.pose.position.x == pytest.approx(2.0, abs=1e-6)
    missing = call(node, GetModelState, node._get_state, model_name="b",
                   relative_entity_name="nowhere")
    assert not missing.success and missing.status_message.startswith("GetModelState: ")


@pytest.mark.parametrize("kind, handler, fields", [
    (GetModelState, "_get_state", dict(model_name="ghost")),
    (DeleteModel, "_delete", dict(model_name="ghost")),
    (GetModelProperties, "_model_properties", dict(model_name="ghost")),
    (SetModelConfiguration, "_set_configuration",
     dict(model_name="ghost", joint_names=["j"], joint_positions=[0.0])),
    (SetModelState, "_set_state", dict(model_state=ModelState(model_name="ghost"))),
    (ApplyBodyWrench, "_apply_wrench", dict(body_name="ghost::base")),
])
def test_a_model_that_does_not_exist_answers_success_false_naming_the_service(
        node, kind, handler, fields):
    """Each answers success false with its status message (:947, :828, :1054, :1809,
    :1602, :1954) and the node goes on; here the message also names the models there
    are."""
    answer = call(node, kind, getattr(node, handler), **fields)
    service = kind._type.split("/")[-1]
    assert not answer.success and answer.status_message.startswith(f"{service}: ")
    assert "ghost" in answer.status_message


def test_world_properties_list_the_models_in_the_worlds_order_rendering_enabled(node):
    """model_names in the world's order, the order they came in (:1114-1115; before:
    sorted); rendering_enabled always true (:1121-1122; before: whether pybullet's window
    is shown); sim_time the world's."""
    spawn(node, "zeta")
    spawn(node, "alpha")
    run(node.world, 0.01)
    answer = call(node, GetWorldProperties, node._world_properties)
    assert list(answer.model_names) == ["ground", "zeta", "alpha"]
    assert answer.rendering_enabled is True
    assert answer.sim_time == pytest.approx(0.01)
    assert answer.status_message == "GetWorldProperties: got properties"  # :1124


def test_a_configuration_whose_lists_differ_in_length_is_refused(node):
    """"joint name and position list have different lengths" (:1833-1838)."""
    spawn(node, "a")
    answer = call(node, SetModelConfiguration, node._set_configuration, model_name="a",
                  joint_names=["x", "y"], joint_positions=[0.0])
    assert not answer.success and "differ in length" in answer.status_message


def test_clearing_with_unknown_names_answers_empty(node):
    """clear_body_wrenches and clear_joint_forces have empty answers (:1737-1792)."""
    assert isinstance(call(node, BodyRequest, node._clear_wrenches, body_name="ghost"),
                      BodyRequest._response_class)
    assert isinstance(call(node, JointRequest, node._clear_efforts, joint_name="ghost"),
                      JointRequest._response_class)


def test_pause_unpause_and_reset_world(node):
    """pause_physics / unpause_physics (:1725-1735); reset_world puts the models back
    (:1719-1723) and time goes on here (reset_simulation sets Gazebo's to 0)."""
    spawn(node, "a")
    node._guarded(node._pause, Empty)(EmptyRequest())
    assert node.world.paused and not node.world.step()
    node._guarded(node._unpause, Empty)(EmptyRequest())
    run(node.world, 0.05)
    node.world.set_state("a", (2.0, 0.0, 0.1), (0, 0, 0, 1))
    before = node.world.now_ns
    node._guarded(node._reset, Empty)(EmptyRequest())
    assert node.world.pose("a")[0][0] == pytest.approx(0.0, abs=1e-6)
    assert node.world.now_ns == before


def test_physics_properties_report_the_step_and_gravity(node):
    """get_physics_properties (:1479-1520)."""
    answer = call(node, GetPhysicsProperties, node._get_physics)
    assert answer.success and answer.time_step == pytest.approx(0.001)
    assert (answer.gravity.x, answer.gravity.y, answer.gravity.z) == pytest.approx(
        (0, 0, -9.8))


def test_model_properties(node):
    """get_model_properties (:1042-1106): bodies, geoms, joints, is_static."""
    spawn(node, "a")
    answer = call(node, GetModelProperties, node._model_properties, model_name="a")
    assert answer.success and list(answer.body_names) == ["base"]
    assert list(answer.geom_names) == ["base_collision"] and not answer.is_static
    assert answer.status_message == "GetModelProperties: got properties"  # :1102


def test_a_model_state_without_an_orientation_is_upright(node):
    """set_model_state normalises the quaternion, and ignition's Normalize makes one of
    length 0 the identity ("eliminates invalid rotation (0, 0, 0, 0)", :1588): a ModelState
    that sets only the position, as course scripts write it, is accepted and the model
    stands upright (_pose_parts reads an unset quaternion so, for every request)."""
    spawn(node, "a")
    node.world.set_state("a", (0.0, 0.0, 0.1), (0.0, 0.0, 0.3826834, 0.9238795))
    state = ModelState(model_name="a")
    state.pose.position.x, state.pose.position.z = 2.0, 0.1
    answer = call(node, SetModelState, node._set_state, model_state=state)
    assert answer.success, answer.status_message
    assert answer.status_message == "SetModelState: set model state done"  # :1658
    position, orientation = node.world.pose("a")
    assert position[0] == pytest.approx(2.0, abs=1e-6)
    assert orientation == pytest.approx((0, 0, 0, 1), abs=1e-6)


CRATE_SDF = """<sdf version="1.6"><model name="crate"><pose>1 0 0.5 0 0 1.5707963267948966</pose>
  <link name="link"><inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy>
  <izz>0.01</izz></inertia></inertial><collision name="c"><geometry><box>
  <size>0.2 0.2 0.2</size></box></geometry></collision></link></model></sdf>"""


def _spawn_sdf_at(node, name, xml, x, yaw_quaternion_zw):
    pose = Pose()
    pose.position.x = x
    pose.orientation.z, pose.orientation.w = yaw_quaternion_zw
    return call(node, SpawnModel, node._spawn_sdf, model_name=name, model_xml=xml,
                robot_namespace="/", initial_pose=pose, reference_frame="")


def test_an_sdf_models_own_pose_is_composed_with_the_initial_pose(node):
    """spawnSDFModel hands initial_pose to updateSDFAttributes (:761), which composes the
    model's own <pose> into it: initial_pose * <pose> (:2459-2475). A crate whose <pose>
    is 1 m ahead, 0.5 m up and turned 90 degrees, spawned at x = 2 turned 90 degrees, is at
    (2, 1, 0.5) turned 180 degrees: pybullet's body says so (before: (2, 0, 0), 90
    degrees, the model's own pose dropped)."""
    half_turn = (math.sin(math.pi / 4), math.cos(math.pi / 4))
    answer = _spawn_sdf_at(node, "crate", CRATE_SDF, 2.0, half_turn)
    assert answer.success, answer.status_message
    body = node.world.models["crate"].body
    position, orientation = pb.getBasePositionAndOrientation(
        body, physicsClientId=node.world.client)
    assert position == pytest.approx((2.0, 1.0, 0.5), abs=1e-6)
    assert abs(orientation[2]) == pytest.approx(1.0, abs=1e-6)  # yaw pi


def test_an_included_models_own_pose_gives_way_to_the_spawn_pose(node, tmp_path,
                                                                 monkeypatch):
    """spawn_model -database sends <world><include>: gazebo_ros writes the composed pose
    into the include (:2459-2475), and an include's <pose> replaces the included model's
    own, so with none in the include the model is at initial_pose itself; with one, at
    initial_pose * the include's <pose>."""
    folder = tmp_path / "crate"
    folder.mkdir()
    (folder / "model.sdf").write_text(CRATE_SDF)
    monkeypatch.setenv("GAZEBO_MODEL_PATH", str(tmp_path))
    plain = ('<sdf version="1.6"><world name="default"><include><uri>model://crate</uri>'
             '</include></world></sdf>')
    placed = ('<sdf version="1.6"><world name="default"><include><uri>model://crate</uri>'
              '<pose>0 0 0.3 0 0 0</pose></include></world></sdf>')
    assert _spawn_sdf_at(node, "a", plain, 2.0, (0.0, 1.0)).success
    assert _spawn_sdf_at(node, "b", placed, -2.0, (0.0, 1.0)).success
    client = node.world.client
    a, _ = pb.getBasePositionAndOrientation(node.world.models["a"].body, physicsClientId=client)
    b, _ = pb.getBasePositionAndOrientation(node.world.models["b"].body, physicsClientId=client)
    assert a == pytest.approx((2.0, 0.0, 0.0), abs=1e-6)
    assert b == pytest.approx((-2.0, 0.0, 0.3), abs=1e-6)


def test_the_state_topics_set_as_the_services_do_and_answer_nothing(node):
    """~set_model_state and ~set_link_state (:474-490) hand each message to setModelState
    and setLinkState and drop the answer (:1663-1669, :1918-1924): the box moves where the
    message says (pybullet's body), and a message naming no model is logged, not raised,
    and changes nothing (before: no such topics)."""
    spawn(node, "a")
    body = node.world.models["a"].body
    client = node.world.client
    state = ModelState(model_name="a")
    state.pose.position.x, state.pose.position.z = 1.5, 0.1
    node.on_set_model_state(state)
    position, _ = pb.getBasePositionAndOrientation(body, physicsClientId=client)
    assert position == pytest.approx((1.5, 0.0, 0.1), abs=1e-6)
    link = LinkState(link_name="a::base", reference_frame="a")
    link.pose.position.y, link.pose.orientation.w = 0.5, 1.0
    node.on_set_link_state(link)
    position, _ = pb.getBasePositionAndOrientation(body, physicsClientId=client)
    assert position == pytest.approx((1.5, 0.5, 0.1), abs=1e-6)
    node.on_set_model_state(ModelState(model_name="ghost"))
    node.on_set_link_state(LinkState(link_name="ghost::base"))
    position, _ = pb.getBasePositionAndOrientation(body, physicsClientId=client)
    assert position == pytest.approx((1.5, 0.5, 0.1), abs=1e-6)


SENSING_BOX = """<robot name="sensing"><link name="base"><inertial><mass value="1"/><inertia
  ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial><collision><geometry>
  <box size="0.2 0.2 0.2"/></geometry></collision></link>
  <link name="mount"><inertial><mass value="0.1"/><inertia ixx="1e-4" ixy="0" ixz="0"
  iyy="1e-4" iyz="0" izz="1e-4"/></inertial></link>
  <joint name="mount_joint" type="fixed"><parent link="base"/><child link="mount"/></joint>
  <gazebo reference="mount"><sensor name="eye" type="camera"><update_rate>40</update_rate>
  </sensor></gazebo>
  <gazebo reference="base"><sensor name="imu" type="imu"/></gazebo></robot>"""


def test_performance_metrics_measure_the_real_time_factor_and_the_sensors_rates(node):
    """~performance_metrics (:410-417), relayed from Gazebo's message (:230-253): the
    real time factor, and per sensor its update rate in simulated and in wall time, fps
    for a camera and -1 for the others. Measured against the simulated time the world
    stepped over the wall time given: 2 s of steps in 1 wall second is a factor of 2; the
    camera at <update_rate> 40 is 40 Hz simulated, 80 Hz wall, on the link it is lumped
    into; the IMU without one updates every step (1000 Hz). Before: no such topic."""
    node.world.spawn_urdf("sensing", SENSING_BOX, (0.0, 0.0, 0.1))
    meter = node.performance
    assert meter.sample(node.world, 10.0) is None  # the first sample starts the span
    run(node.world, 0.5)
    assert meter.sample(node.world, 10.5) is None  # not a period yet
    run(node.world, 1.5)
    message = meter.sample(node.world, 11.0)
    assert message.real_time_factor == pytest.approx(2.0, abs=1e-9)
    assert message.header.stamp.to_nsec() == node.world.now_ns
    sensors = {sensor.name: sensor for sensor in message.sensors}
    assert set(sensors) == {"sensing::base::eye", "sensing::base::imu"}
    eye, imu = sensors["sensing::base::eye"], sensors["sensing::base::imu"]
    assert (eye.sim_update_rate, eye.real_update_rate, eye.fps) == pytest.approx((40, 80, 80))
    assert (imu.sim_update_rate, imu.real_update_rate, imu.fps) == pytest.approx(
        (1000, 2000, -1))


ROTOR_URDF = """<robot name="rotor"><link name="world"/><link name="base"><inertial><mass
  value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
  </link><joint name="fix" type="fixed"><parent link="world"/><child link="base"/>
  <origin xyz="0 0 0.5"/></joint><link name="disc"><inertial><mass value="2"/><inertia
  ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.2"/></inertial></link>
  <joint name="spin" type="continuous"><parent link="base"/><child link="disc"/>
  <axis xyz="0 0 1"/></joint></robot>"""


def test_joint_properties_services_answer_and_set(node):
    """get_joint_properties (:1128-1172) and set_joint_properties (:1531-1582): the type
    constant of the joint's own type (Noetic: REVOLUTE for all, :1152-1153), position
    and rate from pybullet; a damping set is what the next get reports; an unknown joint
    answers success false (:1146-1148, :1551-1553)."""
    node.world.spawn_urdf("rotor", ROTOR_URDF, (0.0, 0.0, 0.0))
    robot = node.world.models["rotor"].robot
    pb.resetJointState(robot.id, robot.joint_index["spin"], 0.3, 1.5,
                       physicsClientId=node.world.client)
    answer = call(node, GetJointProperties, node._get_joint_properties, joint_name="spin")
    assert answer.success and answer.type == answer.CONTINUOUS
    assert list(answer.position) == pytest.approx([0.3]) and list(answer.rate) == \
        pytest.approx([1.5])
    config = ODEJointProperties(damping=[0.4], erp=[0.5])
    answer = call(node, SetJointProperties, node._set_joint_properties, joint_name="spin",
                  ode_joint_config=config)
    assert answer.success and answer.status_message == "SetJointProperties: properties set"
    answer = call(node, GetJointProperties, node._get_joint_properties, joint_name="spin")
    assert list(answer.damping) == [0.4]
    missing = call(node, GetJointProperties, node._get_joint_properties, joint_name="elbow")
    assert not missing.success and missing.status_message.startswith("GetJointProperties: ")
    missing = call(node, SetJointProperties, node._set_joint_properties, joint_name="elbow",
                   ode_joint_config=ODEJointProperties())
    assert not missing.success and missing.status_message.startswith("SetJointProperties: ")


def test_link_properties_services_answer_and_set(node):
    """get_link_properties (:1174-1230): the rotor's disc, its mass, centre of mass (com's
    orientation the identity, :1221-1224) and inertia, "GetLinkProperties: got properties"
    (:1227); set_link_properties (:1402-1430) with the same centre of mass and twice the
    mass and moments, "SetLinkProperties: properties set" (:1427), and what the next get
    reports; a request moving the centre of mass, or an unknown link: success false."""
    node.world.spawn_urdf("rotor", ROTOR_URDF, (0.0, 0.0, 0.0))
    answer = call(node, GetLinkProperties, node._get_link_properties, link_name="rotor::disc")
    assert answer.success and answer.status_message == "GetLinkProperties: got properties"
    assert answer.gravity_mode and answer.mass == pytest.approx(2.0)
    assert (answer.com.position.x, answer.com.position.y, answer.com.position.z,
            answer.com.orientation.w) == pytest.approx((0, 0, 0, 1))
    assert (answer.ixx, answer.ixy, answer.iyy, answer.izz) == pytest.approx((0.1, 0, 0.1, 0.2))
    fields = dict(link_name="rotor::disc", com=answer.com, gravity_mode=True, mass=4.0,
                  ixx=0.2, ixy=0.0, ixz=0.0, iyy=0.2, iyz=0.0, izz=0.4)
    answer = call(node, SetLinkProperties, node._set_link_properties, **fields)
    assert answer.success and answer.status_message == "SetLinkProperties: properties set"
    answer = call(node, GetLinkProperties, node._get_link_properties, link_name="disc")
    assert (answer.mass, answer.izz) == pytest.approx((4.0, 0.4))
    moved = Pose()
    moved.position.z, moved.orientation.w = 0.1, 1.0
    refused = call(node, SetLinkProperties, node._set_link_properties,
                   **dict(fields, com=moved))
    assert not refused.success and refused.status_message.startswith("SetLinkProperties: ")
    assert "cannot move it" in refused.status_message
    missing = call(node, GetLinkProperties, node._get_link_properties, link_name="rotor::hub")
    assert not missing.success and "has no link 'hub'" in missing.status_message

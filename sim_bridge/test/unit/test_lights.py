"""The world's lights and gazebo_ros's light services (get_light_properties,
set_light_properties, delete_light; gazebo_ros_pkgs noetic-devel f9e1a46,
gazebo_ros/src/gazebo_ros_api_plugin.cpp): a world file's <light> elements and included
lights read with SDF's defaults (sdformat sdf9 66a8c21, sdf/1.6/light.sdf), then asked for,
changed and deleted through the node's handlers, without a master."""
import math

import pytest
from geometry_msgs.msg import Pose, Vector3
from std_msgs.msg import ColorRGBA

from gazebo_msgs.srv import DeleteLight, GetLightProperties, SetLightProperties, SpawnModel
from sim_bridge.ros_node import Config, SimBridgeNode
from sim_bridge.sdf_world import load_world

from test_gazebo_services import Inline, call

WORLD = """<sdf version="1.6"><world name="lit">
  <include><uri>model://sun</uri></include>
  <include><uri>model://sun</uri><name>dusk</name><pose>1 2 3 0 0 0</pose></include>
  <light name="lamp" type="point"><diffuse>0.5 0.4 0.3 1</diffuse>
    <attenuation><range>20</range><linear>0.2</linear></attenuation></light>
  <model name="floor"><static>true</static><link name="link"><collision name="c">
    <geometry><plane><normal>0 0 1</normal></plane></geometry></collision></link></model>
  <state world_name="lit"><light name="lamp"><pose>4 5 6 0 0 0</pose></light></state>
</world></sdf>"""


@pytest.fixture
def lit(tmp_path):
    path = tmp_path / "lit.world"
    path.write_text(WORLD)
    return load_world(str(path))


@pytest.fixture
def node(world, lit):
    world.load_world(lit)
    return SimBridgeNode(Config(), world, Inline())


def test_world_lights_are_read_with_sdfs_defaults(lit):
    """Every <light> of the world and every included one (model://sun), in the file's
    order, an <include>'s <name> and <pose> taking the light's place (sdformat parser.cc
    :987-1027), a <state>'s <light><pose> placing it; what a light leaves out is SDF's default (light.sdf:13-45): the lamp's
    constant attenuation 1 (:35), quadratic 0 (:38), specular 0.1 (:23), no shadows (:13).
    Before: lights were read and dropped."""
    assert [light.name for light in lit.lights] == ["sun", "dusk", "lamp"]
    sun, dusk, lamp = lit.lights
    assert (sun.type, sun.cast_shadows, sun.diffuse, sun.direction) == (
        "directional", True, (0.8, 0.8, 0.8, 1.0), (-0.5, 0.1, -0.9))
    assert sun.pose == (0, 0, 10, 0, 0, 0) and dusk.pose == (1, 2, 3, 0, 0, 0)
    # the model database's sun (osrf/gazebo_models 8163eb4, sun/model.sdf), which
    # get_light_properties reports in Gazebo
    assert (sun.attenuation_range, sun.attenuation_constant, sun.attenuation_linear,
            sun.attenuation_quadratic) == (1000.0, 0.9, 0.01, 0.001)
    assert (lamp.type, lamp.diffuse, lamp.specular, lamp.cast_shadows) == (
        "point", (0.5, 0.4, 0.3, 1.0), (0.1, 0.1, 0.1, 1.0), False)
    assert (lamp.attenuation_range, lamp.attenuation_constant, lamp.attenuation_linear,
            lamp.attenuation_quadratic) == (20.0, 1.0, 0.2, 0.0)
    assert lamp.direction == (0.0, 0.0, -1.0)  # :43
    assert lamp.pose == (4, 5, 6, 0, 0, 0)  # the world's <state> places it
    assert [model.name for model in lit.models] == ["floor"]


def test_light_properties_are_the_world_files(node):
    """get_light_properties (:1312-1344): diffuse and the three attenuation factors; success
    with no status_message, as Noetic; an unknown light: success false, the lights named."""
    answer = call(node, GetLightProperties, node._get_light_properties, light_name="lamp")
    assert answer.success and answer.status_message == ""
    assert (answer.diffuse.r, answer.diffuse.g, answer.diffuse.b, answer.diffuse.a) == \
        pytest.approx((0.5, 0.4, 0.3, 1.0))
    assert (answer.attenuation_constant, answer.attenuation_linear,
            answer.attenuation_quadratic) == pytest.approx((1.0, 0.2, 0.0))
    missing = call(node, GetLightProperties, node._get_light_properties, light_name="moon")
    assert not missing.success
    assert missing.status_message == ("GetLightProperties: there is no light named 'moon' "
                                      "(lights: sun, dusk, lamp)")


def _set(node, name, **fields):
    return call(node, SetLightProperties, node._set_light_properties, light_name=name,
                **fields)


def test_set_light_properties_writes_every_field(node):
    """set_light_properties (:1346-1400) writes all its fields into the light, those the
    request leaves at 0 too (:1366-1392); the next get reports them."""
    pose = Pose()
    pose.position.x, pose.orientation.z, pose.orientation.w = 4.0, math.sin(0.5), \
        math.cos(0.5)
    answer = _set(node, "sun", cast_shadows=False, diffuse=ColorRGBA(0.1, 0.2, 0.3, 0.4),
                  attenuation_constant=0.5, attenuation_quadratic=0.01,
                  direction=Vector3(0, 0, -1), pose=pose)
    assert answer.success
    sun = node.world.light("sun")
    assert (sun.cast_shadows, sun.specular, sun.attenuation_linear) == (
        False, (0, 0, 0, 0), 0.0)
    assert sun.pose == pytest.approx((4, 0, 0, 0, 0, 1.0))
    answer = call(node, GetLightProperties, node._get_light_properties, light_name="sun")
    assert (answer.diffuse.r, answer.diffuse.a, answer.attenuation_constant,
            answer.attenuation_linear, answer.attenuation_quadratic) == pytest.approx(
        (0.1, 0.4, 0.5, 0.0, 0.01))
    refused = _set(node, "sun", attenuation_linear=math.nan)
    assert not refused.success and "not finite" in refused.status_message
    assert node.world.light("sun").attenuation_linear == 0.0
    missing = _set(node, "moon")
    assert not missing.success and "lights: sun, dusk, lamp" in missing.status_message


def test_delete_light_removes_it(node):
    """delete_light (:886-931): "DeleteLight: <name> successfully deleted"; the light is gone
    (get answers success false); an unknown light: success false, the lights named."""
    answer = call(node, DeleteLight, node._delete_light, light_name="dusk")
    assert answer.success and answer.status_message == "DeleteLight: dusk successfully deleted"
    gone = call(node, GetLightProperties, node._get_light_properties, light_name="dusk")
    assert not gone.success and "(lights: sun, lamp)" in gone.status_message
    again = call(node, DeleteLight, node._delete_light, light_name="dusk")
    assert not again.success and again.status_message == (
        "DeleteLight: there is no light named 'dusk' (lights: sun, lamp)")


def test_spawn_sdf_model_of_a_light_adds_it(node):
    """spawn_sdf_model of an SDF whose first element is a <light> spawns a light
    (:2654-2658, :2697-2705) named by the request (:2703), at its own <pose> (no
    initial_pose for an SDF without <model>, :2427-2435); a light or model of that name
    already there: success false (:2683-2694). Before: refused, 'no <model> in it'."""
    xml = """<sdf version="1.6"><light name="x" type="spot"><pose>1 2 3 0 0 0</pose>
      <diffuse>0.2 0.3 0.4 1</diffuse></light></sdf>"""
    pose = Pose()
    pose.position.x, pose.orientation.w = 7.0, 1.0
    answer = call(node, SpawnModel, node._spawn_sdf, model_name="torch", model_xml=xml,
                  robot_namespace="", initial_pose=pose, reference_frame="")
    assert answer.success and answer.status_message.startswith(
        "SpawnModel: Successfully spawned entity")
    torch = node.world.light("torch")
    assert (torch.type, torch.pose, torch.diffuse) == ("spot", (1, 2, 3, 0, 0, 0),
                                                       (0.2, 0.3, 0.4, 1.0))
    assert "torch" not in node.world.models
    got = call(node, GetLightProperties, node._get_light_properties, light_name="torch")
    assert got.success and got.diffuse.b == pytest.approx(0.4)
    for name in ("torch", "floor"):
        again = call(node, SpawnModel, node._spawn_sdf, model_name=name, model_xml=xml,
                     robot_namespace="", initial_pose=pose, reference_frame="")
        assert not again.success and "exists already" in again.status_message

"""The <gazebo> tag reader and the SDF reader, with model:// resolution."""
import os

import pytest

from sim_bridge.gazebo_tags import read_gazebo_tags
from sim_bridge.sdf_world import SdfError, load_world, parse_model, resolve_model_uri
from urdf_tools.model import UrdfError, parse_urdf

from world_fixtures import DATA


def test_gazebo_tags_surfaces_plugins_and_sensors(diff_bot_xml):
    tags = read_gazebo_tags(parse_urdf(diff_bot_xml(), "diff_bot"))
    assert tags.surfaces["front_caster"].mu1 == 0.0
    assert tags.surfaces["base_link"].material == "Gazebo/Blue"
    assert tags.surfaces["base_link"].mu1 == 1.0  # Gazebo's default
    assert [p.filename for p in tags.plugins] == ["libgazebo_ros_diff_drive.so"]
    assert tags.plugins[0].text("wheelDiameter") == "0.1"
    (sensor,) = tags.sensors
    assert (sensor.type, sensor.link, sensor.plugins[0].text("topicName")) == \
        ("ray", "laser", "scan")


def test_a_gazebo_reference_to_no_link_is_kept_aside_with_what_it_held():
    text = ("<robot name='r'><link name='a'/><gazebo reference='b'><mu1>1</mu1>"
            "<sensor name='cam' type='camera'/></gazebo></robot>")
    tags = read_gazebo_tags(parse_urdf(text, "r.urdf"))
    assert tags.unknown_references == {"b": ["<mu1>", "<sensor 'cam'>"]}
    assert not tags.surfaces and not tags.sensors


def test_the_test_world_loads_with_its_includes():
    world = load_world(os.path.join(DATA, "test.world"))
    assert [m.name for m in world.models] == ["ground_plane", "wall", "left_post"]
    assert world.step_size == 0.001
    wall = world.models[1]
    assert wall.static and wall.pose == (2.25, 0.0, 0.5, 0.0, 0.0, 0.0)
    assert wall.links[0].collisions[0].size == (0.2, 4.0, 1.0)
    assert wall.links[0].visuals[0].rgba is not None  # Gazebo/Bricks


def test_model_uri_resolution_prefers_gazebo_model_path(tmp_path, monkeypatch):
    own = tmp_path / "ground_plane"
    own.mkdir()
    (own / "model.sdf").write_text("<sdf version='1.6'><model name='mine'/></sdf>")
    monkeypatch.setenv("GAZEBO_MODEL_PATH", str(tmp_path))
    assert resolve_model_uri("model://ground_plane", "w.world") == str(own / "model.sdf")
    monkeypatch.setenv("GAZEBO_MODEL_PATH", "")
    assert resolve_model_uri("model://ground_plane", "w.world").endswith(
        os.path.join("sim_bridge", "models", "ground_plane", "model.sdf"))


def test_an_unknown_model_uri_names_the_folders_searched(tmp_path, monkeypatch):
    monkeypatch.setenv("GAZEBO_MODEL_PATH", str(tmp_path))
    with pytest.raises(SdfError) as error:
        resolve_model_uri("model://nowhere", "my.world")
    message = str(error.value)
    assert message.startswith("my.world: cannot find 'model://nowhere'")
    assert str(tmp_path) in message and os.path.join("sim_bridge", "models") in message


@pytest.mark.parametrize("text, fault", [
    ("<sdf><model name='m'><link name='l'><collision name='c'><geometry><torus/></geometry>"
     "</collision></link></model></sdf>", "geometry <torus>"),
    ("<sdf><model name='m'><pose>1 2</pose></model></sdf>", "is not 6 numbers"),
    ("<sdf><model name='m'>", "not well-formed"),
])
def test_broken_sdf_is_named(text, fault):
    with pytest.raises(SdfError, match=fault):
        parse_model(text, "m.sdf")


JOINTED_WORLD = """<?xml version="1.0"?>
<sdf version="1.6"><world name="default">
  <model name="crate"><static>true</static><pose>2 0 0.25 0 0 0</pose>
    <link name="body"><collision name="c"><geometry><box><size>0.5 0.5 0.5</size></box>
    </geometry></collision></link></model>
  <model name="r2"><pose>0 0 0.1 0 0 0</pose>
    <link name="chassis"><collision name="c"><geometry><box><size>0.4 0.2 0.1</size></box>
    </geometry></collision></link>
    <link name="wheel"><pose>0 0.15 0 1.5707 0 0</pose><collision name="c"><geometry>
    <cylinder><radius>0.05</radius><length>0.02</length></cylinder></geometry></collision></link>
    <joint name="axle" type="revolute"><parent>chassis</parent><child>wheel</child>
    <axis><xyz>0 0 1</xyz></axis></joint></model>
</world></sdf>"""


def test_a_jointed_sdf_model_in_a_world_is_built_as_a_robot(tmp_path):
    # students add Gazebo's robots to their worlds; before, the whole world refused to load
    path = tmp_path / "ddrive.world"
    path.write_text(JOINTED_WORLD)
    warnings = []
    world = load_world(str(path), warnings.append)
    assert [m.name for m in world.models] == ["crate", "r2"]
    assert "<joint name=\"axle\" type=\"continuous\">" in world.models[1].urdf
    assert not warnings


def test_a_model_with_a_joint_sim_bridge_does_not_build_is_left_out_naming_it(tmp_path):
    path = tmp_path / "ball.world"
    path.write_text(JOINTED_WORLD.replace('type="revolute"', 'type="ball"'))
    warnings = []
    world = load_world(str(path), warnings.append)
    assert [m.name for m in world.models] == ["crate"]
    (warning,) = warnings
    assert "model 'r2' cannot be built: joint 'axle' is of type 'ball'" in warning
    assert "left out of the world" in warning
    ball = JOINTED_WORLD.replace('type="revolute"', 'type="ball"')
    model = ball.split("</model>", 1)[1].rsplit("</world>", 1)[0]
    with pytest.raises(SdfError, match="joint 'axle' is of type 'ball'"):
        parse_model(f"<sdf version='1.6'>{model}</sdf>", "spawn request")


def test_a_world_whose_xml_declaration_follows_a_blank_line_loads(tmp_path):
    # Interbotix's xsarm_gazebo.world starts with an empty line; Gazebo reads it
    path = tmp_path / "xsarm.world"
    assert JOINTED_WORLD.startswith("<?xml")
    path.write_text("\n" + JOINTED_WORLD)
    assert [m.name for m in load_world(str(path), [].append).models] == ["crate", "r2"]

"""What the simulator refuses, and what it answers, when a description asks the impossible:
include cycles and runaway nesting, numbers that are not finite, shapes of no size,
negative masses, descriptions over the size limit, lasers of too many beams, robots of too
many links, and set_model_state positions beyond what pybullet carries. Every refusal
names its cause and value, and the world goes on serving (a valid request afterwards
works, checked against its ground truth)."""
import math
import os
import re

import numpy as np
import pybullet as pb
import pytest
from world_fixtures import run

from sim_bridge import robot_body
from sim_bridge.plugins.laser import MAX_BEAMS
from sim_bridge.sdf_world import (MAX_INCLUDE_DEPTH, LinkSpec, ModelSpec, SdfError, ShapeSpec,
                                  load_world, parse_model)
from sim_bridge.world import MAX_COORDINATE, SimError
from urdf_tools.model import MAX_DESCRIPTION_BYTES, MAX_LINKS, UrdfError

BOX_LINK = """<link name="body"><inertial><mass>1</mass><inertia><ixx>0.01</ixx>
<iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
<collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
</link>"""


def write_model(folder, name, body):
    """A model folder ``name`` whose model.sdf holds ``body`` inside its <model>."""
    os.makedirs(os.path.join(folder, name))
    with open(os.path.join(folder, name, "model.sdf"), "w", encoding="utf-8") as stream:
        stream.write(f'<sdf version="1.6"><model name="{name}">{body}</model></sdf>')


def include(uri):
    return f"<include><uri>{uri}</uri></include>"


@pytest.fixture
def models(tmp_path, monkeypatch):
    """A model folder first on GAZEBO_MODEL_PATH."""
    monkeypatch.setenv("GAZEBO_MODEL_PATH", str(tmp_path))
    return str(tmp_path)


def spawn_sdf(world, text, name):
    """What spawn_sdf_model does: parse, then add."""
    spec = parse_model(text, f"model '{name}'")
    spec.name = name
    return world.add_sdf_model(spec, (0, 0, 1), (0, 0, 0, 1))


def assert_world_serves(world):
    """A valid spawn after a refusal works: the box falls onto the ground (truth: z = 0.1)."""
    spawn_sdf(world, f'<model name="ok">{BOX_LINK}</model>', "ok")
    run(world, 1.0)
    (x, y, z), _ = world.pose("ok")
    assert abs(z - 0.1) < 0.005 and abs(x) < 1e-3 and abs(y) < 1e-3


# --- item 1: includes ------------------------------------------------------------------

def test_a_model_including_itself_is_refused_naming_the_chain(world, models):
    write_model(models, "selfie", "<static>true</static>" + include("model://selfie"))
    text = f'<model name="m">{include("model://selfie")}</model>'
    with pytest.raises(SdfError) as refused:
        spawn_sdf(world, text, "m")
    message = str(refused.value)
    assert "includes itself" in message
    assert "model://selfie -> model://selfie" in message
    assert os.path.join(models, "selfie", "model.sdf") in message
    assert_world_serves(world)


def test_an_include_cycle_through_two_models_names_both(models):
    write_model(models, "a", "<static>true</static>" + include("model://b"))
    write_model(models, "b", "<static>true</static>" + include("model://a"))
    world_file = os.path.join(models, "cycle.world")
    with open(world_file, "w", encoding="utf-8") as stream:
        stream.write(f'<sdf version="1.6"><world name="w">{include("model://a")}</world></sdf>')
    # at start: the simulator's world file; an SdfError (main() reports it), no RecursionError
    with pytest.raises(SdfError, match="model://a -> model://b -> model://a"):
        load_world(world_file)


def test_include_depth_is_capped(world, models):
    # a chain of distinct models, each including the next: the limit is followed, one more
    # is refused naming the depth and the limit
    depth = MAX_INCLUDE_DEPTH + 1
    for level in range(depth):
        inner = include(f"model://level{level + 1}") if level + 1 < depth else BOX_LINK
        write_model(models, f"level{level}", "<static>true</static>" + inner)
    with pytest.raises(SdfError) as refused:
        spawn_sdf(world, f'<model name="m">{include("model://level0")}</model>', "m")
    assert f"nested {MAX_INCLUDE_DEPTH + 1} deep" in str(refused.value)
    assert f"at most {MAX_INCLUDE_DEPTH} (MAX_INCLUDE_DEPTH)" in str(refused.value)
    # the deepest allowed nesting loads, and its box is where the chain puts it
    spec = spawn_sdf(world, f'<model name="m2">{include("model://level1")}</model>', "m2").spec
    assert [link.name for link in spec.links] == ["body"]


# --- item 1: numbers --------------------------------------------------------------------

@pytest.mark.parametrize("where,text,named", [
    ("model", '<model name="m"><pose>nan 0 1 0 0 0</pose>{link}</model>',
     "model 'm' <pose> 'nan 0 1 0 0 0'"),
    ("link", '<model name="m"><link name="body"><pose>0 0 1e999 0 0 0</pose></link></model>',
     "model 'm' link 'body' <pose> '0 0 1e999 0 0 0'"),
    ("collision", '<model name="m"><link name="body"><collision name="c"><pose>0 inf 0 0 0 0'
     '</pose><geometry><sphere><radius>1</radius></sphere></geometry></collision></link>'
     '</model>', "model 'm' link 'body' collision 'c' <pose> '0 inf 0 0 0 0'"),
])
def test_a_pose_that_is_not_finite_is_refused_naming_model_link_and_value(world, where, text,
                                                                           named):
    with pytest.raises(SdfError) as refused:
        spawn_sdf(world, text.format(link=BOX_LINK), "m")
    assert named in str(refused.value) and "is not 6 finite numbers" in str(refused.value)
    assert "m" not in world.models
    assert_world_serves(world)


def test_an_include_pose_that_is_not_finite_is_refused(models):
    write_model(models, "thing", BOX_LINK)
    text = ('<model name="m"><include><uri>model://thing</uri><pose>0 0 nan 0 0 0</pose>'
            '</include></model>')
    with pytest.raises(SdfError, match=r"<include> of model://thing <pose> '0 0 nan 0 0 0'"):
        parse_model(text)


@pytest.mark.parametrize("geometry,named", [
    ("<box><size>0.2 -0.1 0.2</size></box>", "box size '0.2 -0.1 0.2' must be positive"),
    ("<box><size>0 0.1 0.2</size></box>", "box size '0 0.1 0.2' must be positive"),
    ("<cylinder><radius>-1</radius><length>1</length></cylinder>",
     "cylinder radius and length '-1 1' must be positive"),
    ("<cylinder><radius>0.1</radius><length>0</length></cylinder>",
     "cylinder radius and length '0.1 0' must be positive"),
    ("<sphere><radius>0</radius></sphere>", "sphere radius '0' must be positive"),
])
def test_a_shape_without_size_is_refused_naming_the_link_and_value(world, geometry, named):
    text = (f'<model name="m"><link name="body"><collision name="c"><geometry>{geometry}'
            '</geometry></collision></link></model>')
    with pytest.raises(SdfError) as refused:
        spawn_sdf(world, text, "m")
    assert f"model 'm' link 'body' collision 'c' {named}" in str(refused.value)
    assert_world_serves(world)


def test_a_negative_mass_is_refused_naming_the_link_and_value(world):
    text = BOX_LINK.replace("<mass>1</mass>", "<mass>-2.5</mass>")
    with pytest.raises(SdfError, match=r"model 'm' link 'body' has a negative mass "
                                       r"\(-2.5 kg\)"):
        spawn_sdf(world, f'<model name="m">{text}</model>', "m")
    assert_world_serves(world)


def test_the_urdf_path_refuses_the_same_through_urdf_tools(world, diff_bot_xml):
    xml = diff_bot_xml()
    negative_box = xml.replace('<box size="', '<box size="-', 1)
    assert negative_box != xml
    with pytest.raises(UrdfError, match="box size '-.*' must be positive"):
        world.spawn_urdf("bad", negative_box)
    negative_mass = xml.replace('<mass value="', '<mass value="-', 1)
    with pytest.raises(UrdfError, match="has a negative mass"):
        world.spawn_urdf("bad", negative_mass)
    assert "bad" not in world.models
    assert_world_serves(world)


# --- item 1: size -----------------------------------------------------------------------

def test_a_description_over_the_size_limit_is_refused_naming_the_limit(world, tmp_path,
                                                                       diff_bot_xml):
    padding = "<!--" + "x" * MAX_DESCRIPTION_BYTES + "-->"
    text = f'<model name="m">{padding}{BOX_LINK}</model>'
    with pytest.raises(SdfError) as refused:
        spawn_sdf(world, text, "m")
    assert f"at most {MAX_DESCRIPTION_BYTES}" in str(refused.value)
    assert "MAX_DESCRIPTION_BYTES" in str(refused.value)
    # a world file is measured before it is read
    big = tmp_path / "big.world"
    big.write_text(f'<sdf version="1.6"><world name="w">{padding}</world></sdf>')
    with pytest.raises(SdfError, match=f"big.world: the SDF is {big.stat().st_size} bytes"):
        load_world(str(big))
    # a URDF the same, by urdf_tools
    with pytest.raises(UrdfError, match=f"at most {MAX_DESCRIPTION_BYTES}"):
        world.spawn_urdf("bad", diff_bot_xml().replace("</robot>", padding + "</robot>"))
    assert_world_serves(world)


# --- item 2: lasers and links -----------------------------------------------------------

@pytest.mark.parametrize("samples", ["1e9", "10001", "inf", "nan", "0", "360.5"])
def test_a_laser_beyond_the_beam_limit_or_not_a_count_is_left_out_naming_it(world, bus,
                                                                            diff_bot_xml,
                                                                            samples):
    world.spawn_urdf("bot", diff_bot_xml(laser_samples=samples), (0, 0, 0))
    (warning,) = [w for w in bus.warnings if "not loaded" in w]
    assert "sensor 'laser_sensor'" in warning and "spawned without it" in warning
    if math.isfinite(float(samples)) and float(samples) > MAX_BEAMS:
        assert f"{int(float(samples))} x 1 samples" in warning
        assert f"at most {MAX_BEAMS} per sensor (MAX_BEAMS)" in warning
    else:
        assert f"'{samples}' must be a whole number" in warning
    # the robot runs without its laser (refused before it opened its topic), and its
    # odometry publishes
    run(world, 0.2)
    assert "/scan" not in bus.published
    assert bus.published["/odom"]


def test_vertical_samples_count_towards_the_beams(world, bus, diff_bot_xml):
    xml = re.sub(r"</horizontal>\s*</scan>",
                 "</horizontal><vertical><samples>51</samples></vertical></scan>",
                 diff_bot_xml(laser_samples="200"))
    assert "<vertical>" in xml
    world.spawn_urdf("bot", xml, (0, 0, 0))
    (warning,) = [w for w in bus.warnings if "not loaded" in w]
    assert "200 x 51 samples (horizontal x vertical) = 10200 beams" in warning


def test_a_laser_at_the_beam_limit_scans_the_truth(world, bus, diff_bot_xml):
    # a wall whose face is at x = 3.0 in front of the laser (at x = 0.15)
    world.add_sdf_model(ModelSpec("wall", True, pose=(3.1, 0, 0.5, 0, 0, 0), links=[
        LinkSpec("link", collisions=[ShapeSpec("box", size=(0.2, 20.0, 1.0))])]))
    world.spawn_urdf("bot", diff_bot_xml(laser_samples=str(MAX_BEAMS)), (0, 0, 0))
    run(world, 0.2)
    scan = bus.last("/scan")
    assert len(scan.ranges) == MAX_BEAMS
    (laser,) = [p for p in world.models["bot"].plugins if hasattr(p, "measure")]
    (x, _, _), _ = laser.sensor_pose()
    assert abs(scan.ranges[MAX_BEAMS // 2] - (3.0 - x)) < 0.002


def chain_urdf(links):
    parts = ['<robot name="chain">']
    for index in range(links):
        parts.append(f'<link name="l{index}"><inertial><mass value="0.1"/><inertia ixx="1e-4" '
                     'ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial></link>')
        if index:
            parts.append(f'<joint name="j{index}" type="continuous"><parent link="l{index - 1}"/>'
                         f'<child link="l{index}"/><origin xyz="0 0 0.01"/></joint>')
    return "".join(parts) + "</robot>"


def test_a_robot_of_too_many_links_is_refused_before_pybullet_sees_it(world, monkeypatch):
    # pybullet crashes (a segfault, which no test can catch) on a body of about 7000 links:
    # the refusal must come before pybullet is asked to load anything
    def must_not_load(*args, **kwargs):
        raise AssertionError("pybullet.loadURDF was called with a 10,000-link robot")
    monkeypatch.setattr(robot_body.pb, "loadURDF", must_not_load)
    with pytest.raises(UrdfError) as refused:
        world.spawn_urdf("chain", chain_urdf(10_000), (0, 0, 1))
    assert "10000 links" in str(refused.value)
    assert f"at most {MAX_LINKS} (MAX_LINKS)" in str(refused.value)
    monkeypatch.undo()
    assert "chain" not in world.models
    assert_world_serves(world)


# --- item 3: set_model_state ------------------------------------------------------------

def test_a_state_beyond_what_pybullet_carries_is_refused_naming_the_value_sent(world):
    spawn_sdf(world, f'<model name="box">{BOX_LINK}</model>', "box")
    before = world.pose("box")
    # turned by pybullet first (what the ROS adapter did), 1e300 became (inf, nan, nan)
    turned = pb.multiplyTransforms((0, 0, 0), (0, 0, 0, 1), (1e300, 0, 0), (0, 0, 0, 1))[0]
    assert math.isinf(turned[0]) and math.isnan(turned[1])
    with pytest.raises(SimError) as refused:
        world.state_in_world("world", (1e300, 0.0, 0.0), (0, 0, 0, 1), (0, 0, 0), (0, 0, 0))
    assert "(1e+300, 0.0, 0.0)" in str(refused.value)
    assert f"{MAX_COORDINATE:.3g}" in str(refused.value)
    with pytest.raises(SimError, match=r"the linear velocity \(nan, 0.0, 0.0\) is not finite"):
        world.state_in_world("", (0, 0, 0), (0, 0, 0, 1), (math.nan, 0, 0), (0, 0, 0))
    with pytest.raises(SimError, match=r"the position \(1e\+300, 0.0, 0.0\) is beyond"):
        world.set_state("box", (1e300, 0, 0), (0, 0, 0, 1))
    assert world.pose("box") == before


def test_a_state_in_a_frame_is_turned_into_the_world(world):
    spawn_sdf(world, f'<model name="box">{BOX_LINK}</model>', "box")
    spawn_sdf(world, f'<model name="other">{BOX_LINK}</model>', "other")
    yaw = pb.getQuaternionFromEuler((0, 0, math.pi / 2))
    world.set_state("box", (1.0, 2.0, 0.5), yaw)
    position, orientation, linear, _ = world.state_in_world(
        "box", (1.0, 0.0, 0.0), (0, 0, 0, 1), (0.5, 0.0, 0.0), (0, 0, 0))
    # the truth: pybullet's own transform of the same (well within single precision)
    expected, expected_orientation = pb.multiplyTransforms((1.0, 2.0, 0.5), yaw, (1, 0, 0),
                                                           (0, 0, 0, 1))
    np.testing.assert_allclose(position, expected, atol=1e-6)
    assert abs(abs(np.dot(orientation, expected_orientation)) - 1) < 1e-6
    np.testing.assert_allclose(linear, (0.0, 0.5, 0.0), atol=1e-6)
    world.set_state("other", position, orientation, linear)
    np.testing.assert_allclose(world.pose("other")[0], expected, atol=1e-6)


def test_a_urdf_written_on_one_line_longer_than_8_kb_spawns(world, diff_bot_xml):
    """pybullet's importer refused a valid URDF written on one line of more than ~8 KB
    ('Cannot load URDF file'); what sim_bridge hands it is written one element a line."""
    tags = "".join(  # 60 small fixed parts make it long enough
        f'<link name="tag_{i}"><inertial><mass value="0.001"/><inertia ixx="1e-7" ixy="0" '
        f'ixz="0" iyy="1e-7" iyz="0" izz="1e-7"/></inertial><visual><geometry><box '
        f'size="0.01 0.01 0.01"/></geometry></visual></link><joint name="tag_{i}_joint" '
        f'type="fixed"><parent link="base_link"/><child link="tag_{i}"/><origin '
        f'xyz="0 0 {0.06 + 0.001 * i}"/></joint>' for i in range(60))
    xml = diff_bot_xml().replace("</robot>", tags + "</robot>")
    one_line = " ".join(line.strip() for line in xml.splitlines() if line.strip())
    assert "\n" not in one_line and len(one_line) > 8192
    world.spawn_urdf("one_line", one_line, (0.0, 0.0, 0.1))
    assert "one_line" in world.models


def chain(links):
    """A robot of ``links`` links on fixed joints, one after the other."""
    body = "".join(f'<link name="l{i}"><inertial><mass value="0.01"/><inertia ixx="1e-6" '
                   f'ixy="0" ixz="0" iyy="1e-6" iyz="0" izz="1e-6"/></inertial></link>'
                   for i in range(links))
    body += "".join(f'<joint name="j{i}" type="fixed"><parent link="l{i}"/>'
                    f'<child link="l{i + 1}"/></joint>' for i in range(links - 1))
    return f'<robot name="chain">{body}</robot>'


def test_a_robot_of_more_links_than_pybullet_builds_is_refused_naming_the_count(world):
    # found by the spawn fuzzer: 129 links (128 joints) gave a body pybullet never built
    from urdf_tools.model import UrdfError
    with pytest.raises(UrdfError, match="129 links and 128 joints.*at most 128 links"):
        world.spawn_urdf("long", chain(129))
    assert "long" not in world.models
    world.spawn_urdf("short", chain(128))
    assert world.pose("short")[0] is not None  # 128 links: built


def test_a_name_longer_than_pybullet_takes_is_refused_before_pybullet_sees_it(world):
    # found by the spawn fuzzer: a joint named by 5000 characters crashed pybullet (SIGSEGV)
    from urdf_tools.model import UrdfError
    long_name = chain(2).replace('name="j0"', f'name="{"n" * 5000}"')
    with pytest.raises(UrdfError, match="name of 5000 characters.*at most 1024"):
        world.spawn_urdf("long", long_name)
    world.spawn_urdf("fine", chain(2).replace('name="j0"', f'name="{"n" * 1000}"'))

"""Meshes as Gazebo reads them (mesh_files.py, robot_body.prepare_urdf, sdf_world): Collada
converted and cached with its unit applied and its up_axis ignored as Gazebo does, checked in
ground truth on pybullet.DIRECT (resting heights, a falling body stopped, laser distances),
and meshes that cannot be read warned about, with a visual left out and a collision standing
in for the missing one, the model spawned all the same.

The Collada boxes (test/data): box_cm_zup.dae is 20 x 30 x 10 cm in centimetres, Z_UP,
spanning z 0..0.1 m; box_mm_yup.dae is 200 x 100 x 300 mm in millimetres, Y_UP, spanning
z -0.15..0.15 m as written (Gazebo Classic and RViz do not turn Y_UP files).
"""
import logging
import math
import os
import shutil

import numpy as np
import pybullet as pb
import pytest
from world_fixtures import DATA, run

from sim_bridge import mesh_files
from sim_bridge.mesh_files import MeshError
from sim_bridge.sdf_world import load_world, parse_model

CM_BOX = os.path.abspath(os.path.join(DATA, "box_cm_zup.dae"))
MM_BOX = os.path.abspath(os.path.join(DATA, "box_mm_yup.dae"))
REPOSITORY = os.path.abspath(os.path.join(DATA, "..", "..", ".."))
PI = repr(math.pi)
# a body at rest is within this of its true height (pybullet's contact tolerance)
HEIGHT_TOLERANCE = 0.003


@pytest.fixture(autouse=True)
def mesh_cache(tmp_path, monkeypatch):
    """Each test converts into a cache folder of its own (under ROS_HOME), and sees no
    GAZEBO_MODEL_PATH but what it sets."""
    monkeypatch.setenv("ROS_HOME", str(tmp_path / "ros_home"))
    monkeypatch.setenv("GAZEBO_MODEL_PATH", "")
    return tmp_path / "ros_home" / "sim_bridge" / "meshes"


@pytest.fixture
def conversions(monkeypatch):
    """The source files converted during the test, in order."""
    calls = []
    convert = mesh_files._convert

    def counting(path, kind, target):
        calls.append(path)
        convert(path, kind, target)
    monkeypatch.setattr(mesh_files, "_convert", counting)
    return calls


def mesh(tag, filename, rpy="0 0 0", xyz="0 0 0", scale=None):
    scale_attribute = f' scale="{scale}"' if scale else ""
    return (f'<{tag}><origin xyz="{xyz}" rpy="{rpy}"/><geometry><mesh filename="{filename}"'
            f'{scale_attribute}/></geometry></{tag}>')


def box(tag, size, xyz="0 0 0"):
    return f'<{tag}><origin xyz="{xyz}"/><geometry><box size="{size}"/></geometry></{tag}>'


def block_robot(*shapes, mass=1.0):
    """A one-link robot made of ``shapes`` (<visual> and <collision> elements)."""
    return (f'<robot name="block"><link name="body"><inertial><mass value="{mass}"/>'
            '<inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>'
            + "".join(shapes) + "</link></robot>")


def resting_height(world, name="block", seconds=1.5):
    run(world, seconds)
    position, _ = world.pose(name)
    linear, _ = world.twist(name)
    assert np.linalg.norm(linear) < 0.01, f"{name} is still moving: {linear}"
    return position[2]


def body_height(world, name):
    position, _ = pb.getBasePositionAndOrientation(world.model(name).body,
                                                   physicsClientId=world.client)
    return position[2]


# --- conversion -----------------------------------------------------------------------
def test_collada_is_converted_to_obj_in_metres_and_its_up_axis_is_left_as_gazebo_does(
        mesh_cache):
    converted = mesh_files.loadable_file(CM_BOX)
    assert converted.endswith(".obj") and converted.startswith(str(mesh_cache))
    lower, upper = mesh_files.bounds(CM_BOX)
    assert lower == pytest.approx([-0.1, -0.15, 0.0])
    assert upper == pytest.approx([0.1, 0.15, 0.1])
    assert mesh_files.collada_unit_and_up_axis(MM_BOX) == (0.001, "Y_UP")
    lower, upper = mesh_files.bounds(MM_BOX)  # not turned: 0.3 m tall as written
    assert lower == pytest.approx([-0.1, -0.05, -0.15])
    assert upper == pytest.approx([0.1, 0.05, 0.15])


def test_the_cache_is_keyed_by_the_source_file_and_outside_the_repository(
        tmp_path, mesh_cache, conversions, monkeypatch):
    source = tmp_path / "box.dae"
    shutil.copy(CM_BOX, source)
    first = mesh_files.loadable_file(str(source))
    written = os.stat(first).st_mtime_ns
    assert mesh_files.loadable_file(str(source)) == first
    assert conversions == [str(source)] and os.stat(first).st_mtime_ns == written
    assert not os.path.realpath(first).startswith(REPOSITORY + os.sep)
    # an edited file (new modification time) is converted anew, to another cache file
    os.utime(source, ns=(written + 10**9, written + 10**9))
    assert mesh_files.loadable_file(str(source)) != first
    assert conversions == [str(source)] * 2
    # without ROS_HOME: ~/.cache/sim_bridge/meshes
    monkeypatch.delenv("ROS_HOME")
    monkeypatch.delenv("XDG_CACHE_HOME", raising=False)
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    assert mesh_files.cache_folder() == str(tmp_path / "home" / ".cache" / "sim_bridge" / "meshes")


def test_obj_and_binary_stl_are_loaded_as_they_are_and_ascii_stl_is_converted(
        tmp_path, conversions):
    obj = mesh_files.loadable_file(CM_BOX)  # an OBJ: loaded as it is
    assert mesh_files.loadable_file(obj) == obj
    corners = np.array([[x, y, z] for x in (-0.1, 0.1) for y in (-0.15, 0.15) for z in (0, 0.1)])
    triangles = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1),
                 (2, 3, 7), (2, 7, 6), (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]
    binary = tmp_path / "box_binary.stl"
    records = np.zeros(len(triangles), dtype=[("normal", "<f4", 3), ("corners", "<f4", (3, 3)),
                                               ("attribute", "<u2")])
    records["corners"] = corners[np.array(triangles)]
    binary.write_bytes(b"solid but binary".ljust(80, b" ") +
                       np.uint32(len(triangles)).tobytes() + records.tobytes())
    assert mesh_files.loadable_file(str(binary)) == str(binary)
    ascii_stl = tmp_path / "box_ascii.stl"  # pybullet crashes on these (segmentation fault)
    ascii_stl.write_text("solid box\n" + "".join(
        "facet normal 0 0 0\nouter loop\n" + "".join(
            f"vertex {x} {y} {z}\n" for x, y, z in corners[list(t)]) + "endloop\nendfacet\n"
        for t in triangles) + "endsolid box\n")
    converted = mesh_files.loadable_file(str(ascii_stl))
    assert converted.endswith(".obj") and conversions == [CM_BOX, str(ascii_stl)]
    for path in (binary, ascii_stl):
        lower, upper = mesh_files.bounds(str(path))
        assert lower == pytest.approx([-0.1, -0.15, 0.0])
        assert upper == pytest.approx([0.1, 0.15, 0.1])


UNREADABLE = {
    "missing.dae": (None, "does not exist"),
    "folder.stl": ("folder", "is not a file"),
    "empty.obj": (b"", "is empty"),
    "words.obj": (b"hello\nworld\n", "not a Wavefront OBJ"),
    "noise.stl": (b"\x00\x01" * 100, "not an STL file"),
    "not_xml.dae": (b"not a Collada file", "not well-formed XML"),
    "other.dae": (b"<mesh/>", "not a Collada file"),
    "nothing.dae": (b'<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" '
                    b'version="1.4.1"><asset><unit meter="1"/></asset><library_visual_scenes>'
                    b'<visual_scene id="S"/></library_visual_scenes><scene>'
                    b'<instance_visual_scene url="#S"/></scene></COLLADA>', "no triangles"),
    "model.ply": (b"ply\nformat ascii 1.0\n", "sim_bridge reads OBJ, STL and Collada"),
}


@pytest.mark.parametrize("name", sorted(UNREADABLE))
def test_a_mesh_that_cannot_be_read_is_refused_saying_why(tmp_path, name):
    content, reason = UNREADABLE[name]
    path = tmp_path / name
    if content == "folder":
        path.mkdir()
    elif content is not None:
        path.write_bytes(content)
    with pytest.raises(MeshError, match=reason):
        mesh_files.loadable_file(str(path))


# --- URDF robots ----------------------------------------------------------------------
@pytest.mark.parametrize("kind", ["package", "file", "absolute", "relative"])
def test_a_robot_with_a_collada_collision_mesh_rests_at_its_height(world, bus, kind,
                                                                   monkeypatch):
    filename = {"package": "package://sim_bridge/test/data/box_cm_zup.dae",
                "file": "file://" + CM_BOX, "absolute": CM_BOX,
                "relative": "box_cm_zup.dae"}[kind]
    monkeypatch.chdir(DATA)  # gzserver's folder, where relative paths are looked for
    # upside down, the box spans z -0.1..0 in the link frame: it rests with the link at 0.1
    # (10 m if the centimetres were taken for metres)
    robot = world.spawn_urdf("block", block_robot(mesh("visual", filename, rpy=f"{PI} 0 0"),
                                                  mesh("collision", filename, rpy=f"{PI} 0 0")),
                             (0, 0, 0.4))
    assert resting_height(world) == pytest.approx(0.1, abs=HEIGHT_TOLERANCE)
    assert bus.warnings == []
    visuals = pb.getVisualShapeData(robot.body, physicsClientId=world.client)
    assert [v[4].decode().endswith(".obj") for v in visuals] == [True]


@pytest.mark.parametrize("filename, rpy, scale, height", [
    (CM_BOX, f"{math.pi / 2!r} 0 0", None, 0.15),       # on its side: y (0.3 m) upwards
    (CM_BOX, f"{PI} 0 0", "2 2 2", 0.2),          # the URDF scale on top of the unit
    (MM_BOX, "0 0 0", None, 0.15),                # Y_UP as written: 0.3 m tall, not 0.1
], ids=["on_its_side", "scaled", "y_up"])
def test_units_up_axis_and_scale_give_the_resting_height(world, bus, filename, rpy, scale,
                                                         height):
    world.spawn_urdf("block", block_robot(mesh("collision", filename, rpy=rpy, scale=scale)),
                     (0, 0, 0.5))
    assert resting_height(world) == pytest.approx(height, abs=HEIGHT_TOLERANCE)
    assert bus.warnings == []


def test_a_second_spawn_converts_nothing(world, tmp_path, conversions, mesh_cache,
                                         monkeypatch):
    urdf = block_robot(mesh("visual", CM_BOX), mesh("collision", CM_BOX))
    world.spawn_urdf("first", urdf, (0, 0, 0.3))
    assert conversions == [CM_BOX]  # the visual and the collision share one conversion
    cached = sorted(mesh_cache.iterdir())
    written = [os.stat(path).st_mtime_ns for path in cached]
    world.spawn_urdf("second", urdf, (1, 0, 0.3))
    world.add_sdf_model(parse_model(
        f'<sdf version="1.6"><model name="crate"><static>true</static><link name="link">'
        f'<collision name="c"><geometry><mesh><uri>{CM_BOX}</uri></mesh></geometry>'
        '</collision></link></model></sdf>'))
    assert conversions == [CM_BOX]
    assert sorted(mesh_cache.iterdir()) == cached
    assert [os.stat(path).st_mtime_ns for path in cached] == written


def test_a_missing_visual_mesh_is_left_out_and_the_robot_spawns(world, bus):
    missing = "package://sim_bridge/meshes/no_such_mesh.dae"
    robot = world.spawn_urdf("block", block_robot(mesh("visual", missing),
                                                  box("visual", "0.1 0.1 0.1"),
                                                  box("collision", "0.2 0.2 0.2")),
                             (0, 0, 0.3))
    assert resting_height(world) == pytest.approx(0.1, abs=HEIGHT_TOLERANCE)
    assert len(bus.warnings) == 1
    warning = bus.warnings[0]
    for words in ("link 'body'", f"visual mesh '{missing}'", "does not exist", "left out"):
        assert words in warning
    visuals = pb.getVisualShapeData(robot.body, physicsClientId=world.client)
    assert [v[2] for v in visuals] == [pb.GEOM_BOX]


def test_a_missing_collision_mesh_falls_back_on_the_other_collisions(world, bus, tmp_path):
    missing = str(tmp_path / "gone.stl")
    world.spawn_urdf("block", block_robot(mesh("collision", missing),
                                          box("collision", "0.2 0.2 0.3")), (0, 0, 0.4))
    assert resting_height(world) == pytest.approx(0.15, abs=HEIGHT_TOLERANCE)
    assert len(bus.warnings) == 1
    for words in ("link 'body'", f"collision mesh '{missing}'", "other collision shape"):
        assert words in bus.warnings[0]


def test_a_missing_collision_mesh_alone_becomes_the_visual_meshs_bounding_box(world, bus):
    # the visual box (upside down, z -0.1..0 in the link frame) gives the collision box
    world.spawn_urdf("block", block_robot(mesh("visual", CM_BOX, rpy=f"{PI} 0 0"),
                                          mesh("collision", "file:///no/such/box.dae")),
                     (0, 0, 0.4))
    assert resting_height(world) == pytest.approx(0.1, abs=HEIGHT_TOLERANCE)
    assert len(bus.warnings) == 1
    for words in ("link 'body'", "collision mesh 'file:///no/such/box.dae'", "bounding box",
                  CM_BOX, "0.2 x 0.3 x 0.1 m"):
        assert words in bus.warnings[0]


def test_a_link_with_no_readable_mesh_keeps_its_inertial_and_has_no_collision(world, bus):
    robot = world.spawn_urdf("block", block_robot(mesh("visual", "/no/such/box.dae"),
                                                  mesh("collision", "/no/such/box.stl"), mass=2.0),
                             (0, 0, 0.4))
    assert len(bus.warnings) == 2
    assert "visual mesh '/no/such/box.dae'" in bus.warnings[0]
    assert "collision mesh '/no/such/box.stl'" in bus.warnings[1]
    assert "it keeps its inertial" in bus.warnings[1]
    assert pb.getDynamicsInfo(robot.body, -1, physicsClientId=world.client)[0] == 2.0
    assert pb.getCollisionShapeData(robot.body, -1, physicsClientId=world.client) == ()


def test_a_mesh_in_an_unknown_package_or_format_is_a_warning(world, bus, tmp_path):
    ply = tmp_path / "part.ply"
    ply.write_text("ply\n")
    world.spawn_urdf("block", block_robot(mesh("visual", "package://no_such_package/a.dae"),
                                          mesh("visual", str(ply)),
                                          box("collision", "0.2 0.2 0.2")), (0, 0, 0.3))
    assert len(bus.warnings) == 2
    assert "ROS package 'no_such_package'" in bus.warnings[0]
    assert "sim_bridge reads OBJ, STL and Collada" in bus.warnings[1]


# --- SDF worlds and models ------------------------------------------------------------
CRATE_SDF = """<?xml version="1.0"?>
<sdf version="1.6">
  <model name="crate">
    <static>true</static>
    <link name="link">
      <collision name="collision"><geometry><mesh>
        <uri>model://crate/meshes/crate.dae</uri><scale>2 2 2</scale></mesh></geometry></collision>
      <visual name="visual"><geometry><mesh>
        <uri>meshes/crate.dae</uri><scale>2 2 2</scale></mesh></geometry></visual>
    </link>
  </model>
</sdf>
"""


def falling_box(name, position):
    return parse_model(f"""<sdf version="1.6"><model name="{name}"><pose>{position} 0 0 0</pose>
        <link name="link"><inertial><mass>1</mass><inertia><ixx>0.002</ixx><iyy>0.002</iyy>
        <izz>0.002</izz></inertia></inertial>
        <collision name="c"><geometry><box><size>0.1 0.1 0.1</size></box></geometry></collision>
        </link></model></sdf>""")


def test_a_static_collada_model_stops_a_falling_body_and_is_seen_by_the_laser(
        world, tmp_path, monkeypatch):
    # model://crate: the centimetre box scaled by 2, so 0.4 x 0.6 x 0.2 m, at x = 2
    folder = tmp_path / "models" / "crate"
    (folder / "meshes").mkdir(parents=True)
    shutil.copy(CM_BOX, folder / "meshes" / "crate.dae")
    (folder / "model.sdf").write_text(CRATE_SDF)
    monkeypatch.setenv("GAZEBO_MODEL_PATH", str(tmp_path / "models"))
    world_file = tmp_path / "crate.world"
    world_file.write_text('<sdf version="1.6"><world name="default"><include>'
                          '<uri>model://crate</uri><pose>2 0 0 0 0 0</pose></include>'
                          '</world></sdf>')
    warnings = []
    spec = load_world(str(world_file), warn=warnings.append)
    assert warnings == []
    for model in spec.models:
        world.add_sdf_model(model)
    world.add_sdf_model(falling_box("dropped", "2 0 1"))
    run(world, 1.5)
    assert body_height(world, "dropped") == pytest.approx(0.2 + 0.05, abs=HEIGHT_TOLERANCE)
    ahead = np.array([[1.0, 0.0, 0.0]])
    assert world.cast_rays((0.0, 0.0, 0.1), ahead, 0.0, 10.0)[0] == pytest.approx(1.8, abs=0.005)
    above = world.cast_rays((2.1, 0.2, 1.0), np.array([[0.0, 0.0, -1.0]]), 0.0, 10.0)[0]
    assert above == pytest.approx(0.8, abs=0.005)


def test_the_gui_saved_world_with_a_missing_mesh_loads_with_one_warning(world, caplog):
    with caplog.at_level(logging.WARNING, logger="rosout.sim_bridge"):
        spec = load_world(os.path.join(DATA, "missing_mesh.world"))  # the default: logged
    warnings = [r.getMessage() for r in caplog.records if r.name == "rosout.sim_bridge"]
    assert len(warnings) == 1
    for words in ("model 'my_crate' link 'link' visual 'visual'",
                  "mesh 'model://my_crate/meshes/my_crate.dae'", "is not found",
                  "the visual is left out", "the same for 1 more link"):
        assert words in warnings[0]
    world.load_world(spec)
    boxes = [m for m in spec.models if m.name.startswith("my_crate")]
    assert [len(m.links[0].visuals) for m in boxes] == [0, 0]
    run(world, 1.0)
    assert body_height(world, "my_crate") == pytest.approx(0.15, abs=HEIGHT_TOLERANCE)


def sdf_block(collisions, visuals, static=False):
    inertial = ("" if static else "<inertial><mass>1</mass><inertia><ixx>0.01</ixx>"
                "<iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>")
    return (f'<sdf version="1.6"><model name="block"><static>{str(static).lower()}</static>'
            f'<pose>0 0 0.5 0 0 0</pose><link name="link">{inertial}'
            + "".join(f'<collision name="c{i}"><geometry>{g}</geometry>'
                      '<surface><friction><ode><mu>0.4</mu></ode></friction></surface>'
                      '</collision>' for i, g in enumerate(collisions))
            + "".join(f'<visual name="v{i}"><pose>{p}</pose><geometry>{g}</geometry></visual>'
                      for i, (p, g) in enumerate(visuals))
            + "</link></model></sdf>")


def sdf_mesh(uri, scale="1 1 1"):
    return f"<mesh><uri>{uri}</uri><scale>{scale}</scale></mesh>"


def test_a_missing_sdf_collision_mesh_becomes_the_visual_meshs_bounding_box(world):
    warnings = []
    # the visual, scaled by 2 and turned upside down, spans z -0.2..0 in the link frame
    spec = parse_model(sdf_block([sdf_mesh("model://nowhere/meshes/crate.stl")],
                                 [(f"0 0 0 {PI} 0 0", sdf_mesh(CM_BOX, "2 2 2"))]),
                       warn=warnings.append)
    assert len(warnings) == 1
    for words in ("model 'block' link 'link' collision 'c0'",
                  "mesh 'model://nowhere/meshes/crate.stl'", "bounding box", CM_BOX,
                  "0.4 x 0.6 x 0.2 m"):
        assert words in warnings[0]
    collision = spec.links[0].collisions[0]
    assert collision.kind == "box" and collision.friction == 0.4
    world.add_sdf_model(spec)
    run(world, 1.5)
    assert body_height(world, "block") == pytest.approx(0.2, abs=HEIGHT_TOLERANCE)


def test_a_missing_sdf_collision_mesh_falls_back_on_the_other_collisions_or_is_dropped():
    warnings = []
    spec = parse_model(sdf_block([sdf_mesh("gone.dae"), "<box><size>1 1 1</size></box>"], []),
                       warn=warnings.append)
    assert [c.kind for c in spec.links[0].collisions] == ["box"]
    assert len(warnings) == 1 and "other collision shape" in warnings[0]
    warnings.clear()
    spec = parse_model(sdf_block([sdf_mesh("file:///no/such.dae")],
                                 [("0 0 0 0 0 0", sdf_mesh("file:///no/such.dae"))]),
                       warn=warnings.append)
    link = spec.links[0]
    assert link.collisions == [] and link.visuals == [] and link.mass == 1.0
    assert len(warnings) == 3  # the third: the free model falls (see the test below)
    assert "visual 'v0': mesh 'file:///no/such.dae' (/no/such.dae) does not exist; the visual " \
        "is left out" in warnings[0]
    assert "collision 'c0'" in warnings[1] and "it keeps its inertial" in warnings[1]


LOST_MESH = "model://nowhere/meshes/crate.stl"
LOST_VISUAL = "model://nowhere/meshes/crate.dae"
FALLS = "falls through the ground with gravity, as in Gazebo"


def test_a_free_model_left_without_collision_shape_falls_as_in_gazebo_and_says_so(world):
    # Gazebo gives a collision whose mesh it cannot load no shape: the body falls through
    # the ground. The same here, without a made-up shape, and a warning that says so.
    warnings = []
    spec = parse_model(sdf_block([sdf_mesh(LOST_MESH)], [("0 0 0 0 0 0", sdf_mesh(LOST_VISUAL))]),
                       warn=warnings.append)
    assert spec.links[0].collisions == [] and spec.links[0].lost_collisions == [LOST_MESH]
    assert len(warnings) == 3
    for words in ("model 'block' is free (not <static>) and has no collision shape left",
                  f"link 'link': mesh '{LOST_MESH}' cannot be read", FALLS,
                  "keeps its mass", "GAZEBO_MODEL_PATH"):
        assert words in warnings[2]
    assert not any(FALLS in text for text in warnings[:2])
    world.add_sdf_model(spec)
    assert world.model_properties("block").geom_names == ()
    run(world, 1.0)
    # ground truth: nothing held it (free fall from 0.5 m: 4.9 m in 1 s, less pybullet's
    # default damping of a multibody)
    position, _ = world.pose("block")
    linear, _ = world.twist("block")
    assert position[2] < 0.5 - 4.0 and linear[2] < -9.0


@pytest.mark.parametrize("static, collisions, rests_at", [
    (True, [sdf_mesh(LOST_MESH)], 0.5),                       # static: nothing moves it
    (False, [sdf_mesh(LOST_MESH), "<box><size>1 1 1</size></box>"], 0.5),  # on its box
])
def test_a_model_still_held_by_static_or_a_shape_gets_no_falling_warning(world, static,
                                                                        collisions, rests_at):
    warnings = []
    spec = parse_model(sdf_block(collisions, [], static=static), warn=warnings.append)
    assert len(warnings) == 1 and FALLS not in warnings[0]
    world.add_sdf_model(spec)
    run(world, 1.5)
    assert world.pose("block")[0][2] == pytest.approx(rests_at, abs=HEIGHT_TOLERANCE)


def test_copies_of_a_shapeless_model_in_a_world_are_one_warning_and_static_ones_none(
        tmp_path, monkeypatch):
    folder = tmp_path / "models" / "lost_crate"
    folder.mkdir(parents=True)
    (folder / "model.sdf").write_text(sdf_block([sdf_mesh(LOST_MESH)], []))
    monkeypatch.setenv("GAZEBO_MODEL_PATH", str(tmp_path / "models"))
    world_file = tmp_path / "lost.world"
    world_file.write_text('<sdf version="1.6"><world name="default">' + "".join(
        f"<include><uri>model://lost_crate</uri><name>{name}</name>{extra}</include>"
        for name, extra in (("a", ""), ("b", ""), ("c", "<static>true</static>")))
        + "</world></sdf>")
    warnings = []
    load_world(str(world_file), warn=warnings.append)
    falling = [text for text in warnings if FALLS in text]
    assert len(falling) == 1
    assert "model 'a'" in falling[0] and falling[0].endswith("(the same for 1 more model)")


def test_an_ascii_stl_scenery_mesh_is_solid(world, tmp_path):
    # pybullet itself crashes on an ASCII STL collision shape: it is converted first
    corners = [(x, y, z) for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (0.0, 1.0)]
    triangles = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1),
                 (2, 3, 7), (2, 7, 6), (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]
    stl = tmp_path / "cube.stl"
    stl.write_text("solid cube\n" + "".join(
        "facet normal 0 0 0\nouter loop\n" + "".join(
            "vertex {} {} {}\n".format(*corners[i]) for i in t) + "endloop\nendfacet\n"
        for t in triangles) + "endsolid cube\n")
    world.add_sdf_model(parse_model(sdf_block([sdf_mesh(str(stl))], [], static=True)
                                    .replace("0 0 0.5 0 0 0", "3 0 0 0 0 0")))
    ahead = np.array([[1.0, 0.0, 0.0]])
    assert world.cast_rays((0.0, 0.0, 0.5), ahead, 0.0, 10.0)[0] == pytest.approx(2.5, abs=0.01)

"""The meshes of Gazebo's model database that worlds saved from Gazebo's GUI name
(``model://cardboard_box/meshes/cardboard_box.dae``, ``jersey_barrier``,
``construction_cone``) are in sim_bridge's model library: our own meshes
(tools/make_model_meshes.py), built so that with the ``<scale>`` and ``<pose>`` of the
database's model.sdf (osrf/gazebo_models 8163eb4) each shape comes out the size Gazebo
shows it and where Gazebo puts it.

test/data/gui_saved_models.world inlines the four database models that share a name with
sim_bridge's (asphalt_plane has no mesh) as Gazebo 11's GUI saves them. The sizes checked
are the models' public dimensions (README, "Model library"), measured on pybullet.DIRECT:
each visual mesh, placed as the world places it, made a static collision of its own
(static meshes collide as their triangles) and measured with pybullet's bounding boxes and
ray casts; the cone, which the database makes collide as its mesh, by where it rests and
where a box dropped on it rests.
"""
import importlib.util
import os

import numpy as np
import pybullet as pb
import pytest
from world_fixtures import DATA, run

from sim_bridge import mesh_files
from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec, load_world, parse_model

WORLD = os.path.join(DATA, "gui_saved_models.world")
REPOSITORY = os.path.abspath(os.path.join(DATA, "..", "..", ".."))
MODELS = os.path.join(REPOSITORY, "sim_bridge", "models")
SCRIPT = os.path.join(REPOSITORY, "tools", "make_model_meshes.py")
# pybullet's contact tolerance; a static mesh's bounding box is exact, a free hull's 2 mm wider
TOLERANCE = 0.003

# The models' public dimensions (x, y, z in m, the shape standing on z = 0), and where the
# world puts them (model poses in gui_saved_models.world):
# - cardboard_box: the collision <box><size>0.5 0.4 0.3 of the database's model.sdf, which
#   its visual's <scale>1.25931896 1.007455168 0.755591376 and <pose>0 0 -0.15 (under the
#   model's 0 0 0.15) give the mesh too;
# - jersey_barrier: 4.06542 m long and 1.143 m (45 in) tall as its model.sdf's collision
#   boxes ('upright': 4.06542 x 0.3063 x 1.143 at z 0.5715), 0.8128 m (32 in) wide at the
#   foot as the database's mesh (its 'base' box: 0.8107 m); mesh at scale 1, no pose;
# - construction_cone: 0.50292 m square foot, 1.08889 m tall, as Gazebo shows the
#   database's mesh (0.050292 x 0.050292 x 0.108889 m) at its model.sdf's <scale>10 10 10.
SHAPES = {
    "cardboard_box": ((0.5, 0.4, 0.3), (3.0, 0.0)),
    "jersey_barrier": ((4.06542, 0.8128, 1.143), (0.0, 3.0)),
    "Construction Cone": ((0.50292, 0.50292, 1.08889), (-3.0, 0.0)),
}
MESHES = {name: os.path.join(MODELS, name, "meshes", f"{name}.dae")
          for name in ("cardboard_box", "jersey_barrier", "construction_cone")}


@pytest.fixture(autouse=True)
def mesh_cache(tmp_path, monkeypatch):
    """Conversions go to a cache folder of the test's own; model:// is looked up in
    sim_bridge's models/ alone (no GAZEBO_MODEL_PATH, no Gazebo database)."""
    monkeypatch.setenv("ROS_HOME", str(tmp_path / "ros_home"))
    monkeypatch.setenv("GAZEBO_MODEL_PATH", "")


def loaded():
    warnings = []
    spec = load_world(WORLD, warn=warnings.append)
    return spec, warnings


def model_spec(spec, name):
    return next(m for m in spec.models if m.name == name)


def test_a_gui_saved_world_finds_every_database_mesh_it_names():
    spec, warnings = loaded()
    assert warnings == []
    assert sorted(m.name for m in spec.models) == sorted(
        ["ground_plane", "asphalt_plane", *SHAPES])
    for name in SHAPES:
        (visual,) = model_spec(spec, name).links[0].visuals
        assert visual.kind == "mesh", name
    (cone,) = model_spec(spec, "Construction Cone").links[0].collisions
    assert cone.kind == "mesh" and cone.scale == (10.0, 10.0, 10.0)


def test_the_loaded_world_shows_the_meshes(world):
    spec, _ = loaded()
    world.load_world(spec)
    for name in SHAPES:
        model = world.model(name)
        bodies = model.static_bodies if model.static_bodies else [model.body]
        shown = [v for body in bodies
                 for v in pb.getVisualShapeData(body, physicsClientId=world.client)]
        meshes = [v for v in shown if v[2] == pb.GEOM_MESH]
        assert len(meshes) == 1, name
        assert meshes[0][4].decode().endswith(".obj"), name


def probe(spec, name):
    """A static model whose collisions are ``name``'s visuals, where the world puts them:
    static meshes collide as their triangles, so pybullet measures the visual itself."""
    model = model_spec(spec, name)
    links = [LinkSpec(link.name, pose=link.pose,
                      collisions=[ShapeSpec("mesh", shape.pose, filename=shape.filename,
                                            scale=shape.scale) for shape in link.visuals])
             for link in model.links]
    return ModelSpec(f"{name} visual", True, pose=model.pose, links=links)


def bounding_box(world, model):
    boxes = [pb.getAABB(body, physicsClientId=world.client) for body in model.static_bodies]
    return (np.min([b[0] for b in boxes], axis=0), np.max([b[1] for b in boxes], axis=0))


def down(world, x, y):
    """The height of what a ray cast straight down at (x, y) hits first."""
    return 5.0 - world.cast_rays((x, y, 5.0), np.array([[0.0, 0.0, -1.0]]), 0.0, 10.0)[0]


def across(world, y, z, x_from=-10.0):
    """Where a ray cast along +x at (y, z) from ``x_from`` hits first, as an x."""
    return x_from + world.cast_rays((x_from, y, z), np.array([[1.0, 0.0, 0.0]]), 0.0, 20.0)[0]


@pytest.mark.parametrize("name", sorted(SHAPES))
def test_each_visual_mesh_has_the_models_dimensions_where_gazebo_puts_it(world, name):
    spec, _ = loaded()
    (length, width, height), (x, y) = SHAPES[name]
    measured = world.add_sdf_model(probe(spec, name))
    lower, upper = bounding_box(world, measured)
    assert lower == pytest.approx([x - length / 2, y - width / 2, 0.0], abs=TOLERANCE)
    assert upper == pytest.approx([x + length / 2, y + width / 2, height], abs=TOLERANCE)
    # solid where it stands: its top seen from above, its foot from the side
    assert down(world, x, y) == pytest.approx(height, abs=TOLERANCE)
    assert across(world, y, 0.02, x_from=x - 10.0) == pytest.approx(x - length / 2,
                                                                      abs=TOLERANCE)


def test_the_jersey_barrier_is_its_full_height_along_its_length_and_wide_at_its_foot(world):
    spec, _ = loaded()
    world.add_sdf_model(probe(spec, "jersey_barrier"))
    for x in (-1.9, 0.0, 1.9):
        assert down(world, x, 3.0) == pytest.approx(1.143, abs=TOLERANCE)
        sideways = world.cast_rays((x, 0.0, 0.02), np.array([[0.0, 1.0, 0.0]]), 0.0, 10.0)[0]
        assert sideways == pytest.approx(3.0 - 0.8128 / 2, abs=TOLERANCE)


CONE_X, CONE_HEIGHT, CONE_FOOT = -3.0, 1.08889, 0.50292


def dropped_box(name, position, size=0.1, mass=0.1):
    inertia = mass * size * size / 6
    return parse_model(f"""<sdf version="1.6"><model name="{name}">
        <pose>{position} 0 0 0</pose><link name="link"><inertial><mass>{mass}</mass>
        <inertia><ixx>{inertia}</ixx><iyy>{inertia}</iyy><izz>{inertia}</izz></inertia>
        </inertial><collision name="c"><geometry><box><size>{size} {size} {size}</size>
        </box></geometry></collision></link></model></sdf>""")


def test_the_cone_collides_by_its_mesh_standing_on_its_foot_and_holding_a_box(world):
    # A free body's collision mesh collides as its convex hull here (README, "Meshes"),
    # as its triangles in Gazebo: the two agree on the foot, the top and the bounding box,
    # which are checked; between them the hull is wider than the cone (README's numbers).
    spec, _ = loaded()
    world.load_world(spec)
    run(world, 1.0)
    (x, y, z), orientation = world.pose("Construction Cone")
    assert (x, y, z) == pytest.approx((CONE_X, 0.0, 0.0), abs=TOLERANCE)  # on its foot
    assert pb.getEulerFromQuaternion(orientation) == pytest.approx((0, 0, 0), abs=1e-3)
    lower, upper = pb.getAABB(world.model("Construction Cone").body,
                              physicsClientId=world.client)
    assert lower == pytest.approx([CONE_X - CONE_FOOT / 2, -CONE_FOOT / 2, 0.0],
                                  abs=TOLERANCE)
    assert upper == pytest.approx([CONE_X + CONE_FOOT / 2, CONE_FOOT / 2, CONE_HEIGHT],
                                  abs=TOLERANCE)
    # a laser sees its foot and its top
    assert across(world, 0.0, 0.03) == pytest.approx(CONE_X - CONE_FOOT / 2, abs=TOLERANCE)
    assert down(world, CONE_X, 0.0) == pytest.approx(CONE_HEIGHT, abs=TOLERANCE)
    # a box dropped on its top rests there, and the cone stands
    world.add_sdf_model(dropped_box("on_top", f"{CONE_X} 0 {CONE_HEIGHT + 0.3}"))
    run(world, 1.5)
    assert world.pose("on_top")[0][2] == pytest.approx(CONE_HEIGHT + 0.05, abs=TOLERANCE)
    assert world.pose("Construction Cone")[0] == pytest.approx((CONE_X, 0.0, 0.0),
                                                              abs=TOLERANCE)


# the cone's radius at heights up its side, from tools/make_model_meshes.py's outline
# (0.17932 m at 0.09059 m to 0.0516 m at 1.08204 m); its 48-sided polygon is within 0.4 mm
CONE_RADII = {0.2: 0.16522, 0.5: 0.12656, 1.0: 0.06216}


@pytest.mark.parametrize("height", sorted(CONE_RADII))
def test_the_free_cone_collides_as_the_cone_not_as_the_hull_of_its_foot_and_top(world, height):
    # each geometry of the Collada file is its own convex hull: the foot, the cone's
    # orange pieces and white bands; one hull of the whole file reached from the foot's
    # corners to the top, 0.226 m out at 0.2 m height, 0.167 at 0.5, 0.069 at 1.0
    spec, _ = loaded()
    world.load_world(spec)
    run(world, 0.5)
    hit = across(world, 0.0, height, x_from=CONE_X - 10.0)
    assert hit == pytest.approx(CONE_X - CONE_RADII[height], abs=TOLERANCE)
    x_from = CONE_X - 10.0
    ray = pb.rayTest((x_from, 0.0, height), (CONE_X, 0.0, height),
                     physicsClientId=world.client)[0]
    assert ray[3][0] == pytest.approx(CONE_X - CONE_RADII[height], abs=TOLERANCE)


def test_the_cone_is_as_heavy_as_the_world_says_and_stands_still(world):
    # the GUI writes Gazebo's defaults for the database cone, which has no <inertial>
    spec, _ = loaded()
    world.load_world(spec)
    body = world.model("Construction Cone").body
    assert pb.getDynamicsInfo(body, -1, physicsClientId=world.client)[0] == 1.0
    run(world, 2.0)
    linear, angular = world.twist("Construction Cone")
    assert np.linalg.norm(linear) < 0.01 and np.linalg.norm(angular) < 0.01


# --- the meshes themselves ------------------------------------------------------------
def make_model_meshes():
    loader = importlib.util.spec_from_file_location("make_model_meshes", SCRIPT)
    module = importlib.util.module_from_spec(loader)
    loader.loader.exec_module(module)
    return module


@pytest.mark.parametrize("model", sorted(MESHES))
def test_each_mesh_is_a_z_up_collada_file_in_metres(model):
    assert mesh_files.collada_unit_and_up_axis(MESHES[model]) == (1.0, "Z_UP")


def test_the_committed_meshes_are_what_the_script_makes(tmp_path):
    import collada
    written = make_model_meshes().main(["--models", str(tmp_path)])
    assert sorted(written) == sorted(
        str(tmp_path / name / "meshes" / f"{name}.dae") for name in MESHES)
    for name, committed in MESHES.items():
        made = collada.Collada(str(tmp_path / name / "meshes" / f"{name}.dae"))
        kept = collada.Collada(committed)
        assert [g.id for g in made.geometries] == [g.id for g in kept.geometries], name
        for a, b in zip(made.geometries, kept.geometries):
            sources = [key for key, value in a.sourceById.items() if hasattr(value, "data")]
            assert len(sources) == 2, (name, a.id)  # positions and normals
            for source in sources:
                assert np.asarray(a.sourceById[source].data) == pytest.approx(
                    np.asarray(b.sourceById[source].data), abs=1e-9), (name, source)
            assert np.array_equal(a.primitives[0].indices, b.primitives[0].indices), name
        assert [m.id for m in made.materials] == [m.id for m in kept.materials], name


@pytest.mark.parametrize("model", sorted(MESHES))
def test_each_mesh_is_closed_and_faces_outward(model):
    # its parts together (the cone's orange and white bands meet): a solid for Gazebo's
    # ODE, which collides with the construction cone's triangles
    import trimesh
    scene = trimesh.load(MESHES[model], file_type="dae", process=False)
    corners = np.vstack([part.vertices[part.faces].reshape(-1, 3)
                         for part in scene.geometry.values()])
    solid = trimesh.Trimesh(corners, np.arange(len(corners)).reshape(-1, 3), process=True)
    assert solid.is_watertight and solid.is_winding_consistent
    assert solid.volume > 0


# pybullet pads a convex hull by a collision margin: a ray meets a 1 m cube's hull 1.000 mm
# before its face (measured at scales 0.1, 1 and 10). The kernel casts the hull itself, as
# Gazebo's laser meets the mesh itself: a reading is the margin over the cosine of the
# beam's angle to the face beyond pybullet's (1 mm head-on, 2.7 mm measured on a beam
# grazing the cone's foot). With its planes pushed out by the margin the kernel reads
# pybullet's within PADDED: pybullet's padding rounds the hull's edges and corners, pushed
# planes do not (0.99 mm measured on a beam past a corner of the free cone's square foot).
PYBULLET_HULL_MARGIN = 0.001
PADDED = 0.002


@pytest.fixture
def ray_tests(monkeypatch):
    """The number of rays each call of pybullet's rayTestBatch (the lasers' pybullet path)
    was given."""
    calls = []
    original = pb.rayTestBatch

    def counted(*args, **kwargs):
        calls.append(len(args[0] if args else kwargs["rayFromPositions"]))
        return original(*args, **kwargs)

    monkeypatch.setattr(pb, "rayTestBatch", counted)
    return calls


def level_scans(origin, heights, beams=720):
    """(origins, directions) of level scans of ``beams`` from ``origin`` at each height."""
    angles = np.linspace(-np.pi, np.pi, beams, endpoint=False)
    directions = np.stack([np.cos(angles), np.sin(angles), np.zeros_like(angles)], axis=1)
    return [((origin[0], origin[1], height), directions) for height in heights]


def assert_reads_as_pybullet(world, origin, directions, near, far):
    """The kernel's readings against pybullet's rayTestBatch: each beam it sees hit,
    pybullet too, and not farther; with the hulls' planes pushed out by the margin, the
    same beams hit, and those that meet the hull itself within PADDED (a beam grazing a
    hull within the margin hits pybullet's padding only)."""
    fast = world.cast_rays(origin, directions, near, far)
    bullet = world._cast_through_pybullet(np.asarray(origin), directions, near, far)
    hits = np.isfinite(fast)
    assert np.isfinite(bullet[hits]).all()
    assert (fast[hits] - bullet[hits]).min() >= -PADDED
    planes = world._ray_scene.planes  # only hulls' here: no static mesh in these scenes
    planes[:, 3] += PYBULLET_HULL_MARGIN
    try:
        padded = world.cast_rays(origin, directions, near, far)
    finally:
        planes[:, 3] -= PYBULLET_HULL_MARGIN
    assert np.array_equal(np.isinf(padded), np.isinf(bullet))
    # along a beam grazing the hull, a round padding and flat planes part by millimetres (4
    # measured): compared where the hull itself is hit, off the edges of what a scan sees
    # (a beam whose neighbours hit too)
    inner = hits & np.roll(hits, 1) & np.roll(hits, -1)
    assert np.abs(padded[inner] - bullet[inner]).max() <= PADDED
    return fast


def test_lasers_cast_the_free_cone_through_the_kernel_as_pybullet_collides_it(world,
                                                                             ray_tests):
    # a moving mesh is cast as its convex hulls (World.cast_rays): no ray goes to pybullet
    # (before: the rays through the cone's bounding box, 18 us each)
    spec, _ = loaded()
    world.load_world(spec)
    run(world, 0.5)
    (x, y, _), _ = world.pose("Construction Cone")
    assert world.model("Construction Cone").mesh_holders == []
    for origin, directions in level_scans((-3.0, -1.0), (0.05, 0.2, 0.5, 0.9)):
        del ray_tests[:]
        world.cast_rays(origin, directions, 0.1, 30.0)
        assert ray_tests == []
        fast = assert_reads_as_pybullet(world, origin, directions, 0.1, 30.0)
        hits = np.isfinite(fast)
        points = np.asarray(origin) + directions[hits] * fast[hits, None]
        assert (np.hypot(points[:, 0] - x, points[:, 1] - y) < CONE_FOOT).any()


def coned_robot():
    """A robot whose mast link collides as the construction cone's mesh (scaled, turned,
    off its link's origin), its laser behind the mast above the base box."""
    return f"""<robot name="coned">
      <link name="base_link"><inertial><mass value="5"/>
        <inertia ixx="0.05" iyy="0.05" izz="0.05" ixy="0" ixz="0" iyz="0"/></inertial>
        <collision><origin xyz="0 0 0.05"/><geometry><box size="0.6 0.4 0.1"/></geometry>
        </collision></link>
      <joint name="mast_joint" type="fixed"><parent link="base_link"/><child link="mast"/>
        <origin xyz="0.12 0.02 0.1" rpy="0 0 0.3"/></joint>
      <link name="mast"><inertial><mass value="0.5"/>
        <inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
        <collision><origin xyz="0.01 0 0" rpy="0 0 0.2"/><geometry>
          <mesh filename="file://{MESHES['construction_cone']}" scale="5 5 5"/></geometry>
        </collision></link>
      <joint name="laser_joint" type="fixed"><parent link="base_link"/><child link="laser"/>
        <origin xyz="-0.2 0 0.3"/></joint>
      <link name="laser"/>
      <gazebo reference="laser"><sensor type="ray" name="scanner"><update_rate>20</update_rate>
        <ray><scan><horizontal><samples>720</samples><min_angle>-3.14159</min_angle>
          <max_angle>3.14159</max_angle></horizontal></scan>
          <range><min>0.1</min><max>10.0</max></range></ray>
        <plugin name="laser" filename="libgazebo_ros_laser.so"><topicName>scan</topicName>
          <frameName>laser</frameName></plugin></sensor></gazebo>
    </robot>"""


def test_a_robots_mesh_link_is_cast_by_the_kernel_as_pybullet_collides_it(world, ray_tests):
    # a robot with a mesh link sent every beam of its own laser to pybullet (its laser is
    # within the mesh links' boxes); now none, and each reads pybullet's within 2 mm
    from sim_bridge.plugins.laser import Laser
    model = world.spawn_urdf("coned", coned_robot(), position=(1.0, 2.0, 0.0),
                             orientation=tuple(pb.getQuaternionFromEuler((0, 0, 0.7))))
    run(world, 0.3)
    assert model.mesh_holders == []
    assert sum(shape.kind == "hull" for shape in model.ray_shapes) == 8  # the cone's parts
    laser = next(p for p in model.plugins if isinstance(p, Laser))
    del ray_tests[:]
    laser.measure()
    assert ray_tests == []
    origin, orientation = laser.sensor_pose()
    directions = laser.directions @ np.array(pb.getMatrixFromQuaternion(orientation)).reshape(3, 3).T
    mast = np.array(model.robot.link_pose("mast")[0])
    fast = assert_reads_as_pybullet(world, origin, directions, laser.range_min,
                                    laser.range_max)
    # the mast in front: the beam straight at it meets it within a few cm of the laser
    assert 0.1 < np.min(fast) < 0.4
    # others' beams cast at the robot from outside, level and slanted
    for height in (0.15, 0.35, 0.55):
        for origin_, directions_ in level_scans(mast[:2] + (1.5, -0.5), (height,)):
            assert_reads_as_pybullet(world, origin_, directions_, 0.1, 10.0)

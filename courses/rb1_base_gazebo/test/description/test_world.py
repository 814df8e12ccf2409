"""worlds/ros2_online_workshop.world read with sim_bridge's loader, no master: every model
resolves as gazebo_ros finds it, the start square has room for the RB1 to stand, turn and
drive ahead, the lasers see walls and shelves, and the world rests when simulated."""
import math
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np
import pytest

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from rb1_workshop_layout import (  # noqa: E402
    MODELS, PACKAGE, SQUARE, START, SWEEP_RADIUS, WORLD, clearance,
    exported_model_folders, load, placed, solids)

from sim_bridge.materials import gazebo_colour  # noqa: E402
from sim_bridge.ray_caster import ShapeSet, cast, primitive_for  # noqa: E402
from sim_bridge.sdf_world import model_search_path, resolve_model_uri  # noqa: E402

# what the course's world has loose (cones, the boxes on the pallet, the block on a table)
FREE = {"cone_1", "cone_2", "cone_3", "cone_4", "cardboard_box", "cardboard_box_0", "demo_cube"}
# free floor the robot must have ahead of it: the 1 m the course drives, and some over
AHEAD = 1.2


@pytest.fixture(scope="module")
def world():
    return load()


@pytest.fixture(scope="module")
def footprints(world):
    return solids(world)


def disc_points(x, y, radius, rings=6, per_ring=72):
    points = [(x, y)]
    for ring in range(1, rings + 1):
        r = radius * ring / rings
        points += [(x + r * math.cos(a), y + r * math.sin(a))
                   for a in np.linspace(0, 2 * math.pi, per_ring, endpoint=False)]
    return points


def test_the_package_exports_its_models_to_gazebo_ros():
    assert os.path.realpath(MODELS) in {os.path.realpath(f) for f in exported_model_folders()}


def test_every_include_resolves_and_ours_come_from_this_package(world, monkeypatch):
    monkeypatch.setenv("GAZEBO_MODEL_PATH", os.pathsep.join(exported_model_folders()))
    uris = [e.findtext("uri").strip() for e in ET.parse(WORLD).getroot().iter("include")]
    assert uris, "the world includes no models"
    for uri in uris:
        path = resolve_model_uri(uri, WORLD, model_search_path())
        if uri.startswith("model://rb1_workshop_"):
            assert os.path.realpath(path).startswith(os.path.realpath(PACKAGE)), (uri, path)
    # every one of this package's models is used, and has a model.config (Gazebo reads them)
    ours = sorted(os.listdir(MODELS))
    assert sorted({u[len("model://"):] for u in uris if u.startswith("model://rb1_")}) == ours
    for name in ours:
        assert os.path.isfile(os.path.join(MODELS, name, "model.config")), name
    # the sun is a light; every other include is a model of the world
    assert len(world.models) == len(uris) - 1


def test_names_physics_and_materials(world):
    names = [m.name for m in world.models]
    assert len(names) == len(set(names))
    assert world.step_size == pytest.approx(0.001)
    assert world.gravity == pytest.approx((0.0, 0.0, -9.8))
    for model in world.models:
        for link in model.links:
            for shape in link.collisions + link.visuals:
                assert shape.kind in ("box", "cylinder", "plane"), (model.name, shape.kind)
            for visual in link.visuals:
                assert visual.rgba is not None, f"{model.name}: a visual without a Gazebo material"
    assert any(s.kind == "plane" for m in world.models for link in m.links
               for s in link.collisions), "no floor"


def test_only_what_the_course_has_loose_is_free(world):
    free = {m.name for m in world.models if not m.static}
    assert free == FREE
    for model in world.models:
        if not model.static:
            (link,) = model.links
            assert link.mass > 0 and link.inertia != (1.0, 1.0, 1.0), model.name


def test_the_disc_at_the_start_lies_inside_the_taped_square():
    x, y = START
    assert SQUARE["x_min"] + SWEEP_RADIUS < x < SQUARE["x_max"] - SWEEP_RADIUS
    assert SQUARE["y_min"] + SWEEP_RADIUS < y < SQUARE["y_max"] - SWEEP_RADIUS


def test_the_square_is_taped_on_three_sides_and_walled_on_the_fourth(world, footprints):
    colours = {tuple(gazebo_colour(name)) for name in ("Gazebo/Yellow", "Gazebo/Black")}
    tape = [(placed(model, link, visual), visual.size)
            for model in world.models for link in model.links for visual in link.visuals
            if visual.kind == "box" and tuple(visual.rgba) in colours
            and placed(model, link, visual)[2, 3] < 0.01]
    assert tape, "no tape on the floor"

    def taped(x, y):
        for matrix, size in tape:
            u, v = (np.linalg.inv(matrix) @ np.array([x, y, matrix[2, 3], 1.0]))[:2]
            if abs(u) <= size[0] / 2 and abs(v) <= size[1] / 2:
                return True
        return False

    along_x = np.linspace(SQUARE["x_min"] + 0.01, SQUARE["x_max"] - 0.01, 40)
    along_y = np.linspace(SQUARE["y_min"] + 0.01, SQUARE["y_max"] - 0.01, 40)
    assert all(taped(x, SQUARE["y_min"] - 0.02) for x in along_x), "south side"
    assert all(taped(x, SQUARE["y_max"] + 0.02) for x in along_x), "north side"
    assert all(taped(SQUARE["x_max"] + 0.02, y) for y in along_y), "east side"
    assert not any(taped(x, y) for x in along_x for y in along_y), "tape inside the square"
    # the west side is the room's wall, its face on the square's edge
    walls = [s for s in footprints if s.model == "room" and s.z_min < 0.1]
    for y in along_y:
        assert min(s.distance(SQUARE["x_min"] - 0.01, y) for s in walls) == 0.0
        assert min(s.distance(SQUARE["x_min"] + 0.01, y) for s in walls) > 0.0


def test_the_disc_at_the_start_and_its_turn_touch_nothing(footprints):
    """A robot turning in place sweeps the disc its farthest point draws: 0.25 m for the RB1
    (a cylinder) and for sim_bridge's test robot (0.4 x 0.3 m)."""
    nearest = clearance(footprints, [START])
    assert min(nearest.values()) > SWEEP_RADIUS + 0.01, sorted(nearest.items(),
                                                                key=lambda kv: kv[1])[:3]
    # the nearest thing is the west wall, about 0.25 m from the disc's edge
    closest = min(nearest, key=nearest.get)
    assert closest == "room" and nearest["room"] == pytest.approx(0.496, abs=0.01)


def test_there_is_free_floor_ahead(footprints):
    """The 1 m the course drives and more: the room's whole length, up to the east wall."""
    x, y = START
    for end in (x + AHEAD, 5.804 - SWEEP_RADIUS - 0.01):
        path = [(x + d, y) for d in np.arange(0.0, end - x + 1e-9, 0.01)]
        nearest = clearance(footprints, path)
        assert min(nearest.values()) > SWEEP_RADIUS, sorted(nearest.items(),
                                                            key=lambda kv: kv[1])[:3]


def test_every_solid_stands_in_the_room_on_the_floor(footprints):
    for solid in footprints:
        assert solid.z_min >= -1e-6 and solid.z_max <= 2.5 + 1e-6, solid.model
        if solid.model != "room":
            assert -0.896 < solid.centre[0] < 5.804 and -5.251 < solid.centre[1] < 0.45, \
                solid.model


@pytest.fixture(scope="module")
def per_model_shapes(world):
    shapes = {}
    for model in world.models:
        primitives = [primitive_for(s.kind, placed(model, link, s), size=s.size,
                                    radius=s.radius, length=s.length)
                      for link in model.links for s in link.collisions if s.kind != "plane"]
        if primitives:
            shapes[model.name] = ShapeSet(primitives)
    return shapes


@pytest.mark.parametrize("height", [0.16, 0.3])
def test_a_laser_at_the_start_sees_the_walls_and_the_shelves(per_model_shapes, height):
    angles = np.linspace(-math.pi, math.pi, 720, endpoint=False)
    directions = np.stack([np.cos(angles), np.sin(angles), np.zeros_like(angles)], axis=1)
    origins = np.tile([START[0], START[1], height], (len(angles), 1))
    names = sorted(per_model_shapes)
    ranges = np.stack([cast([per_model_shapes[n]], origins, directions) for n in names])
    nearest = ranges.min(axis=0)
    seen = {names[i] for i in ranges.argmin(axis=0)[np.isfinite(nearest)]}
    assert {"room", "shelf_west", "shelf_east"} <= seen
    # the room is closed but for its two doors: most beams end on something within 10 m
    assert np.isfinite(nearest).mean() > 0.85
    assert np.all(nearest[np.isfinite(nearest)] < 10.0)

    def beam(angle):
        return nearest[np.argmin(np.abs(angles - angle))]

    assert beam(math.pi) == pytest.approx(START[0] + 0.896, abs=1e-3)       # west wall
    assert beam(math.pi / 2) == pytest.approx(0.45 - START[1], abs=1e-3)    # north wall
    assert beam(-math.pi / 2) == pytest.approx(START[1] + 5.251, abs=1e-3)  # south wall
    assert beam(0.0) == pytest.approx(5.804 - START[0], abs=1e-3)           # east wall


def test_the_world_rests_when_simulated(world):
    """Loaded into sim_bridge (pybullet, no window), after a second of simulated time the
    free bodies are where they were put, upright; a laser ray finds the shelf's leg."""
    from sim_bridge.local_bus import LocalBus
    from sim_bridge.world import World
    simulated = World(LocalBus(), step_size=world.step_size, ray_threads=1)
    try:
        simulated.load_world(world)
        placed_at = {name: simulated.pose(name) for name in FREE}
        for _ in range(1000):
            simulated.step()
        for name in FREE:
            (x0, y0, z0), _ = placed_at[name]
            (x, y, z), (qx, qy, _qz, _qw) = simulated.pose(name)
            assert math.hypot(x - x0, y - y0) < 0.005 and abs(z - z0) < 0.005, name
            assert math.hypot(qx, qy) < 0.01, f"{name} tipped over"
        # the west shelf's south-west leg, seen from the start square along the floor
        leg = np.array([1.3435 - 0.102, -0.3765])
        origin = np.array([START[0], START[1], 0.2])
        direction = np.append(leg - origin[:2], 0.0)
        distance = np.linalg.norm(direction)
        found = simulated.cast_rays(origin, (direction / distance)[None, :], 0.05, 10.0)[0]
        # on the leg's face: short of its axis by less than its half-diagonal (0.033 m)
        assert distance - 0.034 < found < distance
    finally:
        simulated.close()

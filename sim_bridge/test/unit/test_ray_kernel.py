"""The lasers' fast path (compiled kernel, cached scene) against the numpy reference.

The reference is :func:`sim_bridge.ray_caster.cast` with every shape placed anew
(``World.cast_rays(reference=True)``), itself checked against hand-worked intersections
in test_ray_caster.py. Here the fast path must agree with it beam by beam (within
:data:`AGREEMENT` m, and inf exactly where the reference reads inf) on every world of the
repository, with robots in the scene, from level, tilted and upside-down laser poses; and
both must agree with exact rational arithmetic on the warehouse's grazing beams, where
pybullet's ``rayTestBatch`` reads up to half a metre off (see :func:`exact_box_entry`).
"""
import math
import os
import subprocess
from fractions import Fraction

import numpy as np
import pybullet as pb
import pytest

from recording_bus import RecordingBus
from world_fixtures import run

from sim_bridge import ray_kernel, ray_scene
from sim_bridge.plugins.laser import Laser
from sim_bridge.ray_caster import ShapeSet, cast, primitive_for
from sim_bridge.ray_scene import RayScene
from sim_bridge.sdf_world import load_world
from sim_bridge.world import World
from urdf_tools.xacro_loader import expand

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
AGREEMENT = 0.001  # m: the fast path's distances within a millimetre of the reference's
BEAMS = 720
HALF_FIELD = math.radians(135)  # the bench's RB1-class laser: 720 beams over 270 degrees
NEAR, FAR = 0.1, 30.0
SEED = 7
# laser orientations (roll, pitch, yaw): level, the RB1's upside-down mount (roll pi), tilted
# a little (a robot resting on a caster), tilted down onto the floor, and steeply
ORIENTATIONS = [(0.0, 0.0, 0.0), (math.pi, 0.0, 0.4), (math.pi, -0.01, -1.0),
                (0.0, 0.02, 2.0), (0.1, 0.25, -2.5), (math.pi, -0.3, 1.2)]
RB1 = os.path.join(REPO, "my_rb1_description", "urdf", "my_rb1_robot.urdf")
DIFF_BOT = os.path.join(REPO, "sim_bridge", "test", "data", "diff_bot.urdf.xacro")


def repository_worlds():
    try:
        listed = subprocess.run(["git", "ls-files", "*.world"], cwd=REPO, check=True,
                                capture_output=True, text=True).stdout.split()
    except (OSError, subprocess.CalledProcessError):  # not a git checkout: what is there
        listed = [os.path.relpath(os.path.join(folder, name), REPO)
                  for folder, _, names in os.walk(REPO) for name in names
                  if name.endswith(".world") and "/." not in folder]
    return sorted(listed)


def scan_directions(roll, pitch, yaw):
    """A planar scan's unit directions in the world for a laser turned by roll, pitch, yaw."""
    angles = np.linspace(-HALF_FIELD, HALF_FIELD, BEAMS)
    local = np.stack([np.cos(angles), np.sin(angles), np.zeros(BEAMS)], axis=1)
    rotation = np.array(pb.getMatrixFromQuaternion(
        pb.getQuaternionFromEuler([roll, pitch, yaw]))).reshape(3, 3)
    return local @ rotation.T


def assert_agrees(fast, reference, where):
    assert np.array_equal(np.isinf(fast), np.isinf(reference)), \
        f"{where}: inf at different beams: {np.nonzero(np.isinf(fast) != np.isinf(reference))[0]}"
    finite = np.isfinite(reference)
    worst = np.max(np.abs(fast[finite] - reference[finite]), initial=0.0)
    assert worst <= AGREEMENT, f"{where}: {worst:.6f} m from the reference"


@pytest.fixture
def kernel():
    found, why = ray_kernel.load()
    assert found is not None, why
    return found


def test_the_catkin_build_made_the_kernel(kernel):
    assert os.path.exists(kernel.path)


def test_kernel_against_reference_on_random_shapes(kernel):
    """Boxes, cylinders, spheres and a plane in every orientation, rays from origins
    inside and outside them, in every direction."""
    rng = np.random.default_rng(SEED)
    primitives = []
    for index in range(60):
        pose = (*rng.uniform(-4, 4, 3), *rng.uniform(-math.pi, math.pi, 3))
        transform = np.eye(4)
        transform[:3, :3] = np.array(pb.getMatrixFromQuaternion(
            pb.getQuaternionFromEuler(pose[3:]))).reshape(3, 3)
        transform[:3, 3] = pose[:3]
        kind = ("box", "cylinder", "sphere")[index % 3]
        primitives.append(primitive_for(kind, transform, size=rng.uniform(0.05, 2, 3),
                                        radius=rng.uniform(0.05, 1), length=rng.uniform(0.05, 2)))
    floor = np.eye(4)
    floor[2, 3] = -3.0
    primitives.append(primitive_for("plane", floor))
    reference_set = ShapeSet(primitives)
    rows = ray_kernel.rows(primitives)
    for origin in rng.uniform(-4, 4, (40, 3)):
        directions = rng.normal(size=(500, 3))
        directions /= np.linalg.norm(directions, axis=1)[:, None]
        near = rng.uniform(0, 0.5)
        far = rng.uniform(3, 20)
        expected = near + cast([reference_set], origin + directions * near, directions)
        expected = np.where(expected <= far, expected, np.inf)
        assert_agrees(kernel.cast(rows, origin, directions, near, far), expected,
                      f"origin {origin}")


def load(path):
    """A world from the repository; its package's models/ on GAZEBO_MODEL_PATH, as its
    launch files arrange."""
    world = World(RecordingBus(), ray_threads=1)
    models = os.path.join(REPO, os.path.dirname(os.path.dirname(path)), "models")
    saved = os.environ.get("GAZEBO_MODEL_PATH")
    os.environ["GAZEBO_MODEL_PATH"] = os.pathsep.join(p for p in (models, saved) if p)
    try:
        world.load_world(load_world(os.path.join(REPO, path)))
    finally:
        if saved is None:
            del os.environ["GAZEBO_MODEL_PATH"]
        else:
            os.environ["GAZEBO_MODEL_PATH"] = saved
    return world


def scene_extent(world):
    """Where the static shapes are (x, y box), or a 4 m square when there are none but planes."""
    centres = [p.transform[:3, 3] for m in world.models.values() if m.kind == "static"
               for p in m.primitives if p.kind != "plane"]
    if not centres:
        return np.array([-2.0, -2.0]), np.array([2.0, 2.0])
    centres = np.array(centres)[:, :2]
    return centres.min(axis=0), centres.max(axis=0)


@pytest.mark.parametrize("path", repository_worlds())
def test_fast_path_agrees_with_reference_on_every_world(path, kernel):
    world = load(path)
    low, high = scene_extent(world)
    middle = (low + high) / 2.0
    # two robots in the scene: the RB1 (upside-down laser) and a diff bot, both in the
    # lasers' way
    world.spawn_urdf("rb1", expand(RB1, {}), position=(*middle, 0.03))
    world.spawn_urdf("bot", expand(DIFF_BOT, {}), position=(middle[0] + 1.2, middle[1], 0.1))
    run(world, 0.05)  # settled a little: robots' links off their spawn poses
    rng = np.random.default_rng(SEED)
    origins = [np.array([*middle, 0.25]), np.array([middle[0] - 0.8, middle[1] + 0.3, 0.12])]
    origins += [np.array([*rng.uniform(low - 0.5, high + 0.5), rng.uniform(0.05, 1.5)])
                for _ in range(3)]
    fast_scene = RayScene(world, kernel)
    for origin in origins:
        for orientation in ORIENTATIONS:
            directions = scan_directions(*orientation)
            reference = world._cast_reference(origin, directions, NEAR, FAR)
            fast = fast_scene.cast(world.now_ns, origin, directions, NEAR, FAR)
            assert_agrees(fast, reference, f"{path} from {origin} turned {orientation}")
            if not any(m.has_mesh for m in world.models.values()):  # the path lasers take
                assert_agrees(world.cast_rays(origin, directions, NEAR, FAR), reference,
                              f"{path} (cast_rays) from {origin} turned {orientation}")
    world.close()


@pytest.fixture
def hall():
    """The bench world, its robot's laser 720 beams over 270 degrees."""
    world = load(os.path.join("tools", "bench", "bench.world"))
    xml = expand(DIFF_BOT, {"laser_samples": str(BEAMS), "laser_half_fov_degrees": "135"})
    model = world.spawn_urdf("first", xml)
    yield world, next(p for p in model.plugins if isinstance(p, Laser))
    world.close()


def test_moving_shapes_follow_set_state_and_steps(hall):
    """A robot moved in front of the laser, by set_state (no time passing) and by steps,
    is seen where it is now."""
    world, laser = hall
    world.spawn_urdf("second", expand(DIFF_BOT, {}), position=(1.0, 0.0, 0.1))
    run(world, 0.02)
    for position in [(0.8, 0.3, 0.1), (2.0, -0.5, 0.1), (0.7, 0.0, 0.1)]:
        world.set_state("second", position, (0, 0, 0, 1))
        for _ in range(2):  # before and after a step
            origin, orientation = laser.sensor_pose()
            directions = laser.directions @ np.array(
                pb.getMatrixFromQuaternion(orientation)).reshape(3, 3).T
            assert_agrees(world.cast_rays(origin, directions, laser.range_min, laser.range_max),
                          world.cast_rays(origin, directions, laser.range_min, laser.range_max,
                                          reference=True), f"second robot at {position}")
            world.step()


def test_shapes_placed_once_per_time_stamp_for_all_lasers(hall, monkeypatch):
    """Four robots' lasers scanning at one time stamp place each robot's shapes once."""
    world, _ = hall
    for index in range(3):
        world.spawn_urdf(f"extra_{index}", expand(DIFF_BOT, {}),
                         position=(-2.0 + 2.0 * index, 3.0, 0.1))
    lasers = [p for m in world.models.values() for p in m.plugins if isinstance(p, Laser)]
    placed = []
    original = ray_scene._Mover.place
    monkeypatch.setattr(ray_scene._Mover, "place",
                        lambda mover, buffer: (placed.append(mover), original(mover, buffer)))
    for stamp in range(3):
        world.step()
        for laser in lasers:
            laser.measure()
        assert len(placed) == len(lasers) * (stamp + 1), "each robot placed once per stamp"


def test_without_the_kernel_numpy_casts_the_same_with_one_warning(hall, monkeypatch):
    world, laser = hall
    origin, orientation = laser.sensor_pose()
    directions = laser.directions @ np.array(pb.getMatrixFromQuaternion(orientation)).reshape(3, 3).T
    compiled = world.cast_rays(origin, directions, laser.range_min, laser.range_max)
    monkeypatch.setattr(ray_kernel, "load", lambda: (None, "libsim_bridge_rays.so not found"))
    missing = load(os.path.join("tools", "bench", "bench.world"))
    missing.spawn_urdf("first", expand(DIFF_BOT, {"laser_samples": str(BEAMS),
                                                  "laser_half_fov_degrees": "135"}))
    for _ in range(2):
        assert_agrees(missing.cast_rays(origin, directions, laser.range_min, laser.range_max),
                      compiled, "numpy fallback")
        missing.step()
    missing.spawn_urdf("second", expand(DIFF_BOT, {}), position=(2.0, 2.0, 0.1))
    missing.cast_rays(origin, directions, laser.range_min, laser.range_max)
    assert len(missing.bus.warnings) == 1
    assert "libsim_bridge_rays.so not found" in missing.bus.warnings[0]
    missing.close()


# --- the warehouse's grazing beams ---------------------------------------------------------
# The RB1's laser as it rests at the start area of sim_bridge's warehouse.world (the RB1
# spawned at -5, 0, where the RB1 launch file put it before it moved to the course's
# warehouse): 0.2475 m up, mounted upside down, the robot pitched
# 0.57 degrees onto a caster, so its beams sink 1 cm in 1 m and cross the racks' 4 cm
# boards at grazing angles 8-12 m away.
WAREHOUSE_LASER = (-4.748116, 0.0, 0.2474791)
WAREHOUSE_LASER_RPY = (math.pi, -0.009997, 0.0)
RB1_FIELD = (-math.pi / 2, math.pi / 2, 720)
RB1_RANGE = (0.12, 12.0)


def exact_box_entry(primitive, origin, direction, near, far):
    """The distance at which a ray enters a box (or ``near`` if it starts inside), in exact
    rational arithmetic on the float inputs: the truth neither rounding nor a solver's
    tolerance touches. None: it misses within [near, far]."""
    rotation = [[Fraction(v) for v in row] for row in primitive.transform[:3, :3]]
    centre = [Fraction(v) for v in primitive.transform[:3, 3]]
    o = [Fraction(v) for v in origin]
    d = [Fraction(v) for v in direction]
    low, high = Fraction(near), Fraction(far)
    for axis in range(3):
        half = Fraction(primitive.dims[axis]) / 2
        local_o = sum(rotation[k][axis] * (o[k] - centre[k]) for k in range(3))
        local_d = sum(rotation[k][axis] * d[k] for k in range(3))
        if local_d == 0:
            if abs(local_o) > half:
                return None
            continue
        a, b = (-half - local_o) / local_d, (half - local_o) / local_d
        low, high = max(low, min(a, b)), min(high, max(a, b))
        if low > high:
            return None
    return low


def test_warehouse_grazing_beams_agree_with_exact_arithmetic(kernel):
    """Every beam of the resting RB1's scan where pybullet's rayTestBatch and our cast part
    by more than a centimetre: ours is the exact answer (to a micrometre), fast path and
    reference alike."""
    world = load(os.path.join("sim_bridge", "worlds", "warehouse.world"))
    start, end, count = RB1_FIELD
    angles = np.linspace(start, end, count)
    local = np.stack([np.cos(angles), np.sin(angles), np.zeros(count)], axis=1)
    rotation = np.array(pb.getMatrixFromQuaternion(
        pb.getQuaternionFromEuler(WAREHOUSE_LASER_RPY))).reshape(3, 3)
    directions = local @ rotation.T
    origin = np.array(WAREHOUSE_LASER)
    near, far = RB1_RANGE
    fast = world.cast_rays(origin, directions, near, far)
    reference = world.cast_rays(origin, directions, near, far, reference=True)
    assert_agrees(fast, reference, "warehouse")
    starts = origin + directions * near
    results = pb.rayTestBatch(starts.tolist(), (origin + directions * far).tolist(),
                              physicsClientId=world.client)
    bullet = np.array([near + r[2] * (far - near) if r[0] >= 0 else np.inf for r in results])
    with np.errstate(invalid="ignore"):
        parted = np.nonzero(~(np.isinf(fast) & np.isinf(bullet))
                            & ~(np.abs(fast - bullet) <= 0.01))[0]
    boxes = [p for m in world.models.values() if m.kind == "static" for p in m.primitives
             if p.kind == "box"]
    for beam in parted:
        entries = [exact_box_entry(box, origin, directions[beam], near, far) for box in boxes]
        entries = [e for e in entries if e is not None]
        truth = float(min(entries)) if entries else math.inf  # the floor is out of range
        assert (fast[beam] == truth == math.inf) or abs(fast[beam] - truth) < 1e-6, \
            f"beam {beam}: ours {fast[beam]}, exact {truth}, pybullet {bullet[beam]}"
    world.close()


def test_frames_from_poses_are_tfs_transforms():
    from tf.transformations import quaternion_matrix, translation_matrix

    from sim_bridge.ray_scene import frames_from_poses
    rng = np.random.default_rng(7)
    quaternions = rng.normal(size=(20, 4))
    quaternions /= np.linalg.norm(quaternions, axis=1, keepdims=True)
    positions = rng.uniform(-50, 50, size=(20, 3))
    frames = frames_from_poses(positions, quaternions)
    expected = [translation_matrix(p) @ quaternion_matrix(q)
                for p, q in zip(positions, quaternions)]
    assert frames.shape == (20, 4, 4)
    assert np.abs(frames - np.array(expected)).max() < 1e-12
    assert frames_from_poses([], []).shape == (0, 4, 4)


# --- convex hulls (moving bodies' collision meshes) --------------------------------------
def random_pose(rng):
    transform = np.eye(4)
    transform[:3, :3] = np.array(pb.getMatrixFromQuaternion(
        pb.getQuaternionFromEuler(rng.uniform(-math.pi, math.pi, 3)))).reshape(3, 3)
    transform[:3, 3] = rng.uniform(-3, 3, 3)
    return transform


def frustum(bottom, top, height, sides=48):
    """A cone's frustum as a polygon's corners (the construction cone's bands)."""
    angles = np.linspace(0, 2 * math.pi, sides, endpoint=False)
    ring = np.stack([np.cos(angles), np.sin(angles), np.zeros(sides)], axis=1)
    return np.vstack([ring * [bottom, bottom, 0], ring * [top, top, 0] + [0, 0, height]])


def test_a_cube_as_a_hull_reads_as_the_box(kernel):
    from sim_bridge.convex_hulls import hull_planes
    rng = np.random.default_rng(SEED)
    size = np.array([0.4, 1.0, 0.7])
    corners = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]) * size / 2
    planes = hull_planes(corners)
    assert len(planes) == 6
    transform = random_pose(rng)
    box = [primitive_for("box", transform, size=size)]
    hull = [primitive_for("hull", transform, radius=np.linalg.norm(size) / 2, planes=planes)]
    for origin in [transform[:3, 3], *rng.uniform(-4, 4, (20, 3))]:  # inside, outside
        directions = rng.normal(size=(500, 3))
        directions /= np.linalg.norm(directions, axis=1)[:, None]
        as_box = kernel.cast(ray_kernel.rows(box), origin, directions, 0.05, 20.0)
        as_hull = kernel.cast(ray_kernel.rows(hull), origin, directions, 0.05, 20.0,
                              ray_kernel.planes(hull))
        assert np.array_equal(np.isinf(as_box), np.isinf(as_hull))
        finite = np.isfinite(as_box)
        assert np.abs(as_box[finite] - as_hull[finite]).max(initial=0.0) < 1e-9
        reference = cast([ShapeSet(hull)], origin + directions * 0.05, directions) + 0.05
        reference = np.where(reference <= 20.0, reference, np.inf)
        assert_agrees(as_hull, reference, f"cube hull from {origin}")


def test_kernel_against_reference_on_random_hulls(kernel):
    """Hulls of random clouds and of cone frusta, among boxes, from inside and outside."""
    from sim_bridge.convex_hulls import hull_planes
    rng = np.random.default_rng(SEED)
    primitives = []
    for index in range(30):
        points = (frustum(*rng.uniform(0.05, 0.6, 3)) if index % 2
                  else rng.normal(size=(int(rng.integers(4, 200)), 3)) * rng.uniform(0.1, 1))
        centre = (points.min(axis=0) + points.max(axis=0)) / 2
        planes = hull_planes(points)
        planes[:, 3] -= planes[:, :3] @ centre
        primitives.append(primitive_for(
            "hull", random_pose(rng), radius=np.linalg.norm(points - centre, axis=1).max(),
            planes=planes))
        primitives.append(primitive_for("box", random_pose(rng), size=rng.uniform(0.05, 1, 3)))
    reference_set = ShapeSet(primitives)
    rows, planes = ray_kernel.rows(primitives), ray_kernel.planes(primitives)
    for origin in [*[p.transform[:3, 3] for p in primitives[:6:2]], *rng.uniform(-4, 4, (20, 3))]:
        directions = rng.normal(size=(500, 3))
        directions /= np.linalg.norm(directions, axis=1)[:, None]
        near, far = rng.uniform(0, 0.3), rng.uniform(3, 20)
        expected = near + cast([reference_set], origin + directions * near, directions)
        expected = np.where(expected <= far, expected, np.inf)
        assert_agrees(kernel.cast(rows, origin, directions, near, far, planes), expected,
                      f"hulls from {origin}")
        # the fallback's view of the same rows (ray_scene.shape_set) reads the same
        fallback = near + cast([ray_scene.shape_set(rows, planes)], origin + directions * near,
                               directions)
        assert_agrees(np.where(fallback <= far, fallback, np.inf), expected, "shape_set")

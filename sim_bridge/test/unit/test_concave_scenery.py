"""Static scenery meshes collide as their triangles, not as their convex hull: a robot
spawned inside a ring wall (TurtleBot3's default world is one) stays inside it and on
the ground. As a hull, the wall was a solid prism and threw the robot 238 m up."""
import os

import pytest

from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec
from world_fixtures import run

RING_HALF = 2.0      # m, the inner half-width of the square ring
WALL = 0.2           # m thick
HEIGHT = 0.5         # m high


def ring_obj(path):
    """A square ring wall as 4 closed boxes in one OBJ file (a concave mesh)."""
    boxes = [(-RING_HALF - WALL, RING_HALF + WALL, RING_HALF, RING_HALF + WALL),
             (-RING_HALF - WALL, RING_HALF + WALL, -RING_HALF - WALL, -RING_HALF),
             (RING_HALF, RING_HALF + WALL, -RING_HALF, RING_HALF),
             (-RING_HALF - WALL, -RING_HALF, -RING_HALF, RING_HALF)]
    lines, base = [], 0
    for x0, x1, y0, y1 in boxes:
        for z in (0.0, HEIGHT):
            lines += [f"v {x} {y} {z}" for x, y in ((x0, y0), (x1, y0), (x1, y1), (x0, y1))]
        faces = [(1, 2, 3, 4), (5, 8, 7, 6), (1, 5, 6, 2), (2, 6, 7, 3), (3, 7, 8, 4),
                 (4, 8, 5, 1)]
        for face in faces:
            a, b, c, d = (base + i for i in face)
            lines += [f"f {a} {b} {c}", f"f {a} {c} {d}"]
        base += 8
    with open(path, "w") as stream:
        stream.write("\n".join(lines) + "\n")
    return path


def test_a_robot_inside_a_ring_wall_mesh_stays_inside_on_the_ground(world, diff_bot_xml, tmp_path):
    mesh = ring_obj(os.path.join(tmp_path, "ring.obj"))
    world.add_sdf_model(ModelSpec("ring", True, links=[LinkSpec("link", collisions=[
        ShapeSpec("mesh", filename=mesh)])]))
    world.spawn_urdf("robot", diff_bot_xml(), (0.5, -0.5, 0.1))
    run(world, 2.0)
    (x, y, z), _ = world.pose("robot")
    assert (x, y) == pytest.approx((0.5, -0.5), abs=0.05)
    assert z < 0.2

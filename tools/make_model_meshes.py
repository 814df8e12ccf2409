#!/usr/bin/env python3
"""Makes the meshes of sim_bridge's model library that worlds saved from Gazebo's GUI name.

A world saved from Gazebo's GUI (File > Save World As) inlines the models it took from
Gazebo's model database, and their visuals (and the construction cone's collision) name
the database's meshes by ``model://`` uris. sim_bridge looks those uris up in its own
``sim_bridge/models/<name>/`` (after GAZEBO_MODEL_PATH), so the meshes must be there. These
are our own meshes, built here from the models' public dimensions, so that the ``<scale>``
and ``<pose>`` the database's model.sdf applies to each (osrf/gazebo_models 8163eb4) make
the shape the size Gazebo shows and put it where Gazebo puts it:

=========================================  ===========================  =====================
uri (model://...)                          the database's model.sdf     the shape
=========================================  ===========================  =====================
cardboard_box/meshes/cardboard_box.dae     model pose 0 0 0.15, visual  0.5 x 0.4 x 0.3 m box
                                           pose 0 0 -0.15, scale        on the ground: the
                                           1.25931896 1.007455168       collision box's size
                                           0.755591376                  (the mesh: a 0.397 m
                                                                        cube, z 0..0.397)
jersey_barrier/meshes/jersey_barrier.dae   visual at scale 1, no pose;  4.06542 m long (x),
                                           collision: six boxes         0.8128 m (32 in) wide
                                                                        at the foot, 1.143 m
                                                                        (45 in) tall
construction_cone/meshes/construction_     visual and collision, scale  0.50292 m square foot,
cone.dae                                   10 10 10, no pose            1.08889 m tall (the
                                                                        mesh: a tenth of that)
=========================================  ===========================  =====================

Where the numbers come from: the box's and the barrier's length and height are the
collision boxes of their model.sdf; the barrier's outline (half-widths at the breaks of its
New Jersey profile) and the cone's (foot, cone and top radii and heights) are the
dimensions Gazebo shows for the database's models, measured on them (in inches: the
barrier is 160 in long, 32 in wide, 45 in tall). Nothing else of the database's meshes is
used: the shapes are built here, simplified (no end joints, lifting slots or textures; the
cone is closed at the top; white bands and a black foot are ours).

Each mesh is a Collada 1.4.1 file in metres (``<unit meter="1">``), ``Z_UP``, one node and
geometry per part (``<triangles>`` with per-vertex normals: flat faces, the cone smooth
around), each part its own colour (a phong material). Every part is a closed surface with
its faces turned outward, so Gazebo's ODE and pybullet collide with it as a solid. The
geometry is built with NumPy and checked with trimesh (closed, outward, its extent); the
file is written with pycollada, with fixed ids and dates so that a second run writes the
same file (trimesh's own Collada exporter draws random ids and smooths across edges).

Run from anywhere, with the workspace's Python (``source tools/env.bash``):

    python3 tools/make_model_meshes.py                  # into sim_bridge/models/
    python3 tools/make_model_meshes.py --models /tmp/x  # elsewhere, to compare

sim_bridge/test/unit/test_model_meshes.py checks the committed files against this script
and measures the shapes in a world saved from Gazebo's GUI.
"""
from __future__ import annotations

import argparse
import datetime
import math
import os
import sys
from typing import List, Sequence, Tuple

import numpy as np

REPOSITORY = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
MODELS = os.path.join(REPOSITORY, "sim_bridge", "models")
# fixed, so that the files do not change from one run to the next
WRITTEN = datetime.datetime(2025, 1, 1, 0, 0, 0)
AUTHORING_TOOL = "sim_bridge tools/make_model_meshes.py (trimesh, pycollada)"

Colour = Tuple[float, float, float]
CARDBOARD: Colour = (0.76, 0.60, 0.42)
CONCRETE: Colour = (0.78, 0.77, 0.74)
ORANGE: Colour = (1.0, 0.36, 0.0)
WHITE: Colour = (0.95, 0.95, 0.95)
BLACK: Colour = (0.08, 0.08, 0.08)

# --- the models' numbers (m, as Gazebo shows the models) -------------------------------
# cardboard_box/model.sdf: collision <box><size>0.5 0.4 0.3, the visual mesh's <scale>
BOX_SIZE = (0.5, 0.4, 0.3)
BOX_SCALE = (1.25931896, 1.007455168, 0.755591376)

# jersey_barrier/model.sdf: the collision boxes' length 4.06542 m and height 1.143 m
# ('upright', 'base' 0.064516 m tall); the outline as half-widths (y) at heights (z), from
# the foot (32 in wide, a 2.54 in vertical lip) up the lower face (about 53 degrees) and
# the upper face (about 86 degrees) to the 45 in top
BARRIER_LENGTH = 4.06542
BARRIER_OUTLINE = [(0.4064, 0.0), (0.4064, 0.064516), (0.3897, 0.0972), (0.2042, 0.342),
                   (0.1532, 1.1313), (0.1407, 1.143)]

# construction_cone/model.sdf: <scale>10 10 10; the numbers below are the scaled shape
CONE_SCALE = 10.0
CONE_FOOT_HALF = 0.25146       # the foot is 0.50292 m across its flats
CONE_FOOT_CORNER = 0.30363     # its corners cut off on this radius
CONE_FOOT_HEIGHT = 0.06581     # its vertical sides
CONE_FOOT_TOP = 0.07597        # its bevelled top edge, 0.01016 m in
CONE_FOOT_BEVEL = 0.01016
# the cone from the foot up: (radius, height); the last is its flat top
CONE_OUTLINE = [(0.19431, CONE_FOOT_HEIGHT), (0.19431, CONE_FOOT_TOP), (0.17932, 0.09059),
                (0.0516, 1.08204), (0.04242, 1.08889)]
CONE_BANDS = [(0.56, 0.68), (0.78, 0.94)]  # white bands (ours), heights in m
CONE_SECTIONS = 48


class Part:
    """One geometry of a mesh: triangles with per-vertex normals and one colour."""

    def __init__(self, name: str, colour: Colour):
        self.name, self.colour = name, colour
        self.vertices: List[Sequence[float]] = []
        self.normals: List[Sequence[float]] = []

    def triangle(self, corners, normals=None, outward=None) -> None:
        """Adds a triangle, turned so that it faces ``outward`` (a direction), or along
        its corners' ``normals``; flat (the face's normal) when no ``normals``."""
        a, b, c = (np.asarray(p, dtype=float) for p in corners)
        face = np.cross(b - a, c - a)
        facing = np.asarray(outward if outward is not None else np.sum(normals, axis=0))
        if np.dot(face, facing) < 0:
            corners = [corners[0], corners[2], corners[1]]
            normals = None if normals is None else [normals[0], normals[2], normals[1]]
            face = -face
        length = np.linalg.norm(face)
        if length < 1e-15:
            return  # a degenerate triangle (a quad's side on the axis)
        if normals is None:
            normals = [face / length] * 3
        self.vertices.extend(np.asarray(p, dtype=float) for p in corners)
        self.normals.extend(np.asarray(n, dtype=float) / np.linalg.norm(n) for n in normals)

    def quad(self, corners, outward, normals=None) -> None:
        """Two triangles for the corners in order around the quad."""
        a, b, c, d = corners
        first = None if normals is None else [normals[0], normals[1], normals[2]]
        second = None if normals is None else [normals[0], normals[2], normals[3]]
        self.triangle([a, b, c], first, outward)
        self.triangle([a, c, d], second, outward)

    def arrays(self) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(vertices, normals, faces): each corner once for each normal it has (rounded
        to 1 nm and 1e-7, so that a second run writes the same numbers)."""
        vertices = np.round(np.asarray(self.vertices, dtype=float), 9) + 0.0
        normals = np.round(np.asarray(self.normals, dtype=float), 7) + 0.0
        corners, index = np.unique(np.hstack([vertices, normals]), axis=0,
                                   return_inverse=True)
        return corners[:, :3], corners[:, 3:], index.reshape(-1, 3)

    def scaled(self, factor: Sequence[float]) -> "Part":
        """This part with its vertices divided by ``factor`` (per axis; the normals stay:
        they are turned by a non-uniform scale only on slanted faces, which no
        non-uniformly scaled part has)."""
        part = Part(self.name, self.colour)
        part.vertices = [np.asarray(v) / np.asarray(factor, dtype=float) for v in self.vertices]
        part.normals = list(self.normals)
        return part


# --- the shapes -------------------------------------------------------------------------
def cardboard_box() -> List[Part]:
    """A box of BOX_SIZE standing on z = 0, centred on x and y, then divided by the
    visual's scale: a 0.397 m cube that the model.sdf's scale stretches back."""
    half_x, half_y, height = BOX_SIZE[0] / 2, BOX_SIZE[1] / 2, BOX_SIZE[2]
    box = Part("cardboard_box", CARDBOARD)
    corner = {(i, j, k): (i * half_x, j * half_y, k * height)
              for i in (-1, 1) for j in (-1, 1) for k in (0, 1)}
    for axis in range(3):
        for side in (-1, 1):
            outward = [0.0, 0.0, 0.0]
            outward[axis] = side
            keys = [key for key in corner
                    if (key[axis] == side if axis < 2 else key[2] == (side + 1) // 2)]
            # around the face: order the four corners by angle about its centre
            points = np.array([corner[key] for key in keys])
            centre = points.mean(axis=0)
            u, v = [k for k in range(3) if k != axis]
            order = np.argsort(np.arctan2(points[:, v] - centre[v], points[:, u] - centre[u]))
            box.quad([points[i] for i in order], outward)
    return [box.scaled(BOX_SCALE)]


def jersey_barrier() -> List[Part]:
    """BARRIER_OUTLINE (mirrored in y) swept along x over BARRIER_LENGTH, centred."""
    half = BARRIER_LENGTH / 2
    barrier = Part("jersey_barrier", CONCRETE)
    right = [(w, z) for w, z in BARRIER_OUTLINE]
    left = [(-w, z) for w, z in reversed(BARRIER_OUTLINE)]
    outline = right + left  # counter-clockwise in (y, z): up the +y side, down the -y side
    # the ends: one trapezoid between each two heights of the outline
    for x, facing in ((-half, -1.0), (half, 1.0)):
        for (w0, z0), (w1, z1) in zip(BARRIER_OUTLINE, BARRIER_OUTLINE[1:]):
            barrier.quad([(x, -w0, z0), (x, w0, z0), (x, w1, z1), (x, -w1, z1)],
                         (facing, 0.0, 0.0))
    # the sides, bottom and top: one long quad per edge of the outline
    for (y0, z0), (y1, z1) in zip(outline, outline[1:] + outline[:1]):
        outward = (0.0, z1 - z0, -(y1 - y0))  # the outline is counter-clockwise
        barrier.quad([(-half, y0, z0), (half, y0, z0), (half, y1, z1), (-half, y1, z1)],
                      outward)
    return [barrier]


def _octagon(half: float, corner: float, z: float) -> List[Tuple[float, float, float]]:
    """A square of half-width ``half`` with its corners cut on radius ``corner``,
    counter-clockwise from the +x side."""
    cut = math.sqrt(corner * corner - half * half)
    points = []
    for quarter in range(4):
        angle = quarter * math.pi / 2
        c, s = math.cos(angle), math.sin(angle)
        for x, y in ((half, -cut), (half, cut)):
            points.append((c * x - s * y, s * x + c * y, z))
    return points


def _cone_foot() -> Part:
    foot = Part("foot", BLACK)
    cut = math.sqrt(CONE_FOOT_CORNER ** 2 - CONE_FOOT_HALF ** 2)
    # the bevelled top: every edge 0.01016 m in, the cut corners too
    inner_half = CONE_FOOT_HALF - CONE_FOOT_BEVEL
    inner_cut = CONE_FOOT_HALF + cut - CONE_FOOT_BEVEL * math.sqrt(2) - inner_half
    inner_corner = math.hypot(inner_half, inner_cut)
    rings = [_octagon(CONE_FOOT_HALF, CONE_FOOT_CORNER, 0.0),
             _octagon(CONE_FOOT_HALF, CONE_FOOT_CORNER, CONE_FOOT_HEIGHT),
             _octagon(inner_half, inner_corner, CONE_FOOT_TOP)]
    for ring, z, facing in ((rings[0], 0.0, -1.0), (rings[2], CONE_FOOT_TOP, 1.0)):
        for a, b in zip(ring[1:-1], ring[2:]):  # a fan: the octagon is convex
            foot.triangle([ring[0], a, b], outward=(0.0, 0.0, facing))
    for lower, upper in zip(rings, rings[1:]):
        for i in range(8):
            j = (i + 1) % 8
            quad = [lower[i], lower[j], upper[j], upper[i]]
            middle = np.mean(quad, axis=0)
            foot.quad(quad, outward=(middle[0], middle[1], 0.0))
    return foot


def _revolved(name: str, colour: Colour, outline: Sequence[Tuple[float, float]]) -> Part:
    """The surface swept by turning ``outline`` ((radius, height) points, going up the
    outside) about z: smooth around, sharp at the outline's corners."""
    part = Part(name, colour)
    angles = [2 * math.pi * k / CONE_SECTIONS for k in range(CONE_SECTIONS + 1)]
    for (r0, z0), (r1, z1) in zip(outline, outline[1:]):
        normal = np.array([z1 - z0, -(r1 - r0)])  # outward, the outline going up/inwards
        normal /= np.linalg.norm(normal)
        for a, b in zip(angles, angles[1:]):
            corners = [(r0 * math.cos(a), r0 * math.sin(a), z0),
                       (r0 * math.cos(b), r0 * math.sin(b), z0),
                       (r1 * math.cos(b), r1 * math.sin(b), z1),
                       (r1 * math.cos(a), r1 * math.sin(a), z1)]
            normals = [(normal[0] * math.cos(t), normal[0] * math.sin(t), normal[1])
                       for t in (a, b, b, a)]
            part.quad(corners, None, normals)
    return part


def construction_cone() -> List[Part]:
    """The foot, and the cone on it in orange and white bands (closed at the bottom,
    inside the foot, and at its flat top), at the shape's size divided by CONE_SCALE."""
    (r_base, z_base), (r_mid, z_mid), (r_top, z_top) = CONE_OUTLINE[2:5]

    def radius(z: float) -> float:  # on the straight face from the foot to the top
        return r_mid + (r_base - r_mid) * (z_mid - z) / (z_mid - z_base)

    # the cone's outline, cut into orange and white pieces at the bands, and the foot's
    # ring, the bevel and the cone apart: each piece is convex, so that a simulator that
    # collides with one convex hull per geometry (pybullet) collides with the cone itself
    pieces: List[Tuple[Colour, List[Tuple[float, float]]]] = [
        (ORANGE, [(0.0, CONE_FOOT_HEIGHT)] + CONE_OUTLINE[:2]),
        (ORANGE, CONE_OUTLINE[1:3])]
    body = CONE_OUTLINE[2:3]
    for low, high in CONE_BANDS:
        pieces.append((ORANGE, body + [(radius(low), low)]))
        pieces.append((WHITE, [(radius(low), low), (radius(high), high)]))
        body = [(radius(high), high)]
    pieces.append((ORANGE, body + [(r_mid, z_mid), (r_top, z_top), (0.0, z_top)]))
    parts = [_cone_foot()]
    counts = {ORANGE: 0, WHITE: 0}
    for colour, piece in pieces:
        kind = "band" if colour == WHITE else "cone"
        parts.append(_revolved(f"{kind}_{counts[colour]}", colour, piece))
        counts[colour] += 1
    return [part.scaled((CONE_SCALE,) * 3) for part in parts]


SHAPES = {"cardboard_box": cardboard_box, "jersey_barrier": jersey_barrier,
          "construction_cone": construction_cone}


# --- checks and the Collada file --------------------------------------------------------
def check(name: str, parts: Sequence[Part]) -> Tuple[np.ndarray, np.ndarray]:
    """Fails unless the parts together are closed surfaces turned outward; returns the
    mesh's bounds."""
    import trimesh
    corners = []
    for part in parts:
        vertices, _, faces = part.arrays()
        corners.append(vertices[faces].reshape(-1, 3))
    vertices = np.vstack(corners)
    faces = np.arange(len(vertices)).reshape(-1, 3)
    solid = trimesh.Trimesh(vertices, faces, process=True)  # welds the shared corners
    if not (solid.is_watertight and solid.is_winding_consistent and solid.volume > 0):
        raise SystemExit(f"make_model_meshes: {name} is not a closed surface facing out")
    return solid.bounds[0], solid.bounds[1]


def write_collada(path: str, model: str, parts: Sequence[Part]) -> None:
    import collada
    from collada import asset, geometry, material, scene, source
    document = collada.Collada()
    document.assetInfo = asset.Asset(
        created=WRITTEN, modified=WRITTEN, title=model, unitname="meter", unitmeter=1.0,
        upaxis=asset.UP_AXIS.Z_UP,
        contributors=[asset.Contributor(authoring_tool=AUTHORING_TOOL)])
    nodes = []
    for part in parts:
        vertices, normals, faces = part.arrays()
        effect = material.Effect(f"{part.name}-effect", [], "phong",
                                 diffuse=(*part.colour, 1.0), ambient=(*part.colour, 1.0),
                                 specular=(0.1, 0.1, 0.1, 1.0), shininess=8.0)
        mat = material.Material(f"{part.name}-material", part.name, effect)
        document.effects.append(effect)
        document.materials.append(mat)
        positions = source.FloatSource(f"{part.name}-positions", vertices.ravel(),
                                       ("X", "Y", "Z"))
        normal_source = source.FloatSource(f"{part.name}-normals", normals.ravel(),
                                           ("X", "Y", "Z"))
        mesh = geometry.Geometry(document, f"{part.name}-mesh", part.name,
                                 [positions, normal_source])
        inputs = source.InputList()
        inputs.addInput(0, "VERTEX", f"#{part.name}-positions")
        inputs.addInput(1, "NORMAL", f"#{part.name}-normals")
        indices = np.repeat(faces.ravel(), 2)  # the vertex and its normal
        mesh.primitives.append(mesh.createTriangleSet(indices, inputs, f"{part.name}-symbol"))
        document.geometries.append(mesh)
        bound = scene.MaterialNode(f"{part.name}-symbol", mat, inputs=[])
        nodes.append(scene.Node(part.name, children=[scene.GeometryNode(mesh, [bound])]))
    root = scene.Scene("scene", nodes)
    document.scenes.append(root)
    document.scene = root
    os.makedirs(os.path.dirname(path), exist_ok=True)
    temporary = path + ".part"
    document.write(temporary)
    os.replace(temporary, path)


def main(argv: Sequence[str] = ()) -> List[str]:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--models", default=MODELS,
                        help="the model folders' parent (default: sim_bridge/models)")
    arguments = parser.parse_args(list(argv))
    written = []
    for model, build in SHAPES.items():
        parts = build()
        lower, upper = check(model, parts)
        path = os.path.join(arguments.models, model, "meshes", f"{model}.dae")
        write_collada(path, model, parts)
        written.append(path)
        size = " x ".join(f"{v:.5f}" for v in upper - lower)
        print(f"{path}: {size} m as written, z {lower[2]:.5f}..{upper[2]:.5f}")
    return written


if __name__ == "__main__":
    main(sys.argv[1:])

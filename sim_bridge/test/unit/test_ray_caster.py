"""sim_bridge.ray_caster against hand-worked intersections."""
import math

import numpy as np
import pytest

from sim_bridge.poses import pose6_matrix
from sim_bridge.ray_caster import ShapeSet, cast, primitive_for

X = np.array([[1.0, 0.0, 0.0]])


def distance(primitive, origin, direction=X):
    return cast([ShapeSet([primitive])], np.array([origin], dtype=float),
                np.asarray(direction, dtype=float))[0]


def test_box_face_and_a_rotated_box():
    box = primitive_for("box", pose6_matrix((5, 0, 0, 0, 0, 0)), size=(2, 2, 2))
    assert distance(box, (0, 0, 0)) == pytest.approx(4.0)
    # turned 45 degrees about z, the box's edge points at the ray: sqrt(2) from its centre
    turned = primitive_for("box", pose6_matrix((5, 0, 0, 0, 0, math.pi / 4)), size=(2, 2, 2))
    assert distance(turned, (0, 0, 0)) == pytest.approx(5.0 - math.sqrt(2.0))
    assert distance(box, (0, 3, 0)) == math.inf  # passes beside it
    assert distance(box, (10, 0, 0)) == math.inf  # behind the ray
    assert distance(box, (5, 0, 0)) == 0.0  # starts inside


def test_cylinder_side_and_cap():
    upright = primitive_for("cylinder", pose6_matrix((3, 0, 0, 0, 0, 0)), radius=0.5, length=2)
    assert distance(upright, (0, 0, 0)) == pytest.approx(2.5)
    assert distance(upright, (0, 0.4, 0)) == pytest.approx(3 - math.sqrt(0.25 - 0.16))
    assert distance(upright, (0, 0, 1.5)) == math.inf  # above it
    down = np.array([[0.0, 0.0, -1.0]])
    assert distance(upright, (3, 0, 5), down) == pytest.approx(4.0)  # onto the top cap


def test_sphere_and_plane():
    sphere = primitive_for("sphere", pose6_matrix((4, 0, 0, 0, 0, 0)), radius=1)
    assert distance(sphere, (0, 0, 0)) == pytest.approx(3.0)
    plane = primitive_for("plane", pose6_matrix((0, 0, 0, 0, 0, 0)))
    slanted = np.array([[1.0, 0.0, -1.0]]) / math.sqrt(2.0)
    assert distance(plane, (0, 0, 2), slanted) == pytest.approx(2 * math.sqrt(2.0))
    assert distance(plane, (0, 0, 2)) == math.inf  # parallel


def test_nearest_of_many_shapes_for_many_rays():
    shapes = ShapeSet([
        primitive_for("box", pose6_matrix((5, 0, 0, 0, 0, 0)), size=(2, 2, 2)),
        primitive_for("sphere", pose6_matrix((2, 0, 0, 0, 0, 0)), radius=0.5),
        primitive_for("cylinder", pose6_matrix((0, 3, 0, 0, 0, 0)), radius=0.5, length=1),
    ])
    directions = np.array([[1.0, 0, 0], [0, 1.0, 0], [-1.0, 0, 0]])
    found = cast([shapes], np.zeros((3, 3)), directions)
    np.testing.assert_allclose(found, [1.5, 2.5, math.inf])

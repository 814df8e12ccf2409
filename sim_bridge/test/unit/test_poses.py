"""sim_bridge.poses: the yaw written out in floats gives tf.transformations' yaw."""
import math

import numpy as np
from tf.transformations import euler_from_quaternion, quaternion_from_euler

from sim_bridge.poses import yaw_from_quaternion


def test_the_yaw_is_tfs_for_random_and_awkward_quaternions():
    rng = np.random.default_rng(7)
    quaternions = [tuple(q) for q in rng.normal(size=(20000, 4))]  # not unit, as sent
    quaternions += [tuple(quaternion_from_euler(*angles)) for angles in
                    rng.uniform(-math.pi, math.pi, size=(5000, 3))]
    quaternions += [(0.0, 0.0, 0.0, 1.0), (0.0, 0.0, 0.0, 0.0), (0.0, 0.0, 1.0, 0.0),
                    (1e-9, 0.0, 0.0, 0.0), tuple(quaternion_from_euler(0.3, math.pi / 2, 0.2)),
                    tuple(quaternion_from_euler(0.0, -math.pi / 2, 1.0)), (0.5, 0.5, 0.5, 0.5)]
    worst = max(abs(yaw_from_quaternion(q) - euler_from_quaternion(q)[2]) for q in quaternions)
    assert worst <= 1e-12, f"the yaw differs from tf's by up to {worst} rad"

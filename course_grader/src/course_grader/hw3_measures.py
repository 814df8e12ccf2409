"""Figures for ME495 homework 3 from ground-truth samples, no ROS: flips counted from the
body's up axis, distance travelled in the plane, whether a point has come to rest, and
which Gazebo model each name of a world file stands for."""
from __future__ import annotations

import glob
import math
import os
import xml.etree.ElementTree as ET
from typing import Dict, Optional, Sequence, Tuple

import numpy as np


class FlipCount:
    """Flips over from the z component of the body's up axis (1 upright, -1 upside down):
    a flip is a change of side, a side counting only beyond ``dead_band`` so that a wobble
    on its edge is not two flips."""

    def __init__(self, dead_band: float):
        self.dead_band = dead_band
        self.side: Optional[int] = None
        self.flips = 0

    def update(self, up_z: float) -> bool:
        if abs(up_z) <= self.dead_band:
            return False
        side = 1 if up_z > 0 else -1
        flipped = self.side is not None and side != self.side
        self.flips += int(flipped)
        self.side = side
        return flipped


def planar_travel(points: Sequence[Tuple[float, float]]) -> float:
    """The length of the path through ``points`` (x, y), m."""
    return sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(points, points[1:]))


def still_points(samples: Sequence[Tuple[float, np.ndarray]], window: float,
                 speed: float) -> bool:
    """``samples`` (time, point) cover at least ``window`` s and, over the last ``window``
    s, the point stayed within ``speed * window`` of where it ended."""
    if not samples or samples[-1][0] - samples[0][0] < window:
        return False
    end_time, end = samples[-1]
    recent = [p for t, p in samples if t >= end_time - window]
    return max(float(np.linalg.norm(np.asarray(p) - end)) for p in recent) <= speed * window


def included_models(worlds_dir: str) -> Dict[str, str]:
    """Model name -> the ``model://`` uri it was included from, for every ``<include>`` of
    the .world files in ``worlds_dir`` (a student names an included jersey_barrier "wall_1";
    it is a jersey barrier all the same). An include without ``<name>`` is named by its
    model, so only named ones are listed."""
    named: Dict[str, str] = {}
    for path in sorted(glob.glob(os.path.join(worlds_dir, "*.world"))):
        try:
            root = ET.parse(path).getroot()
        except ET.ParseError:
            continue
        for include in root.iter("include"):
            uri, name = include.findtext("uri"), include.findtext("name")
            if uri and name:
                named[name.strip()] = uri.strip()
    return named

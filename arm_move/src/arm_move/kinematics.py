"""The PincherX 100's kinematics from config/px100.yaml: forward kinematics of the points
the planner needs, and inverse kinematics for a position target.

The arm is planar once the waist has turned: the shoulder, elbow and wrist_angle axes
are parallel (y of the turned frame). A joint's positive rotation about y tips a link
that points forward downwards, so in the arm's vertical plane a link's elevation is its
elevation at zero minus the sum of the joint angles before it. With four joints and a
position target, one degree of freedom is left: the gripper's pitch (the elevation
below horizontal; pi/2 points straight down). IK is solved for a given pitch, two
solutions (elbow up and down) per waist direction, and the waist can also face away
from the target with the arm bent back over itself.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Iterable, List, Mapping, Sequence, Tuple

import numpy as np
import yaml

ARM_JOINTS = ("waist", "shoulder", "elbow", "wrist_angle")
FINGER_JOINTS = ("left_finger", "right_finger")


@dataclass(frozen=True)
class ArmKinematics:
    """Numbers of the arm (m, rad) and its kinematics."""

    waist_z: float
    shoulder_z: float
    elbow_x: float
    elbow_z: float
    wrist_x: float
    ee_arm_x: float
    gripper_bar_x: float
    ee_gripper_x: float
    lower: Tuple[float, ...]     # per arm joint
    upper: Tuple[float, ...]
    max_speed: float             # rad/s, every arm joint
    finger_min: float
    finger_max: float
    finger_speed: float
    named_poses: Mapping[str, Tuple[float, ...]]

    @classmethod
    def from_config(cls, config: Mapping) -> "ArmKinematics":
        joints, limits, finger = config["joints"], config["limits"], config["finger"]
        return cls(
            waist_z=joints["waist_z"], shoulder_z=joints["shoulder_z"],
            elbow_x=joints["elbow_x"], elbow_z=joints["elbow_z"], wrist_x=joints["wrist_angle_x"],
            ee_arm_x=joints["ee_arm_x"], gripper_bar_x=joints["gripper_bar_x"],
            ee_gripper_x=joints["ee_gripper_x"],
            lower=tuple(math.radians(limits[j][0]) for j in ARM_JOINTS),
            upper=tuple(math.radians(limits[j][1]) for j in ARM_JOINTS),
            max_speed=math.radians(limits["max_speed_degrees"]),
            finger_min=finger["min"], finger_max=finger["max"], finger_speed=finger["speed"],
            named_poses={k: tuple(v) for k, v in config["named_poses"].items()})

    @classmethod
    def from_file(cls, path: str) -> "ArmKinematics":
        with open(path) as stream:
            return cls.from_config(yaml.safe_load(stream))

    # --- derived lengths -----------------------------------------------------------------
    @property
    def shoulder_height(self) -> float:
        return self.waist_z + self.shoulder_z

    @property
    def upper_arm(self) -> Tuple[float, float]:
        """Length and elevation at zero of the shoulder-to-elbow segment."""
        return math.hypot(self.elbow_x, self.elbow_z), math.atan2(self.elbow_z, self.elbow_x)

    @property
    def hand_length(self) -> float:
        """wrist_angle axis to the gripper point."""
        return self.ee_arm_x + self.gripper_bar_x + self.ee_gripper_x

    def within_limits(self, q: Sequence[float], slack: float = 1e-9) -> bool:
        return all(lo - slack <= v <= hi + slack for v, lo, hi in zip(q, self.lower, self.upper))

    # --- forward kinematics --------------------------------------------------------------
    def planar_points(self, q: Sequence[float]):
        """Shoulder, elbow, wrist and gripper point in the arm's plane as (r, z), and the
        gripper's direction there."""
        _, q1, q2, q3 = q
        a1, e10 = self.upper_arm
        s = np.array([0.0, self.shoulder_height])
        e = s + a1 * np.array([math.cos(e10 - q1), math.sin(e10 - q1)])
        w = e + self.wrist_x * np.array([math.cos(-(q1 + q2)), math.sin(-(q1 + q2))])
        direction = np.array([math.cos(-(q1 + q2 + q3)), math.sin(-(q1 + q2 + q3))])
        g = w + self.hand_length * direction
        return s, e, w, g, direction

    @staticmethod
    def to_3d(q0: float, r: float, z: float, lateral: float = 0.0) -> np.ndarray:
        c, s = math.cos(q0), math.sin(q0)
        return np.array([r * c - lateral * s, r * s + lateral * c, z])

    def gripper_point(self, q: Sequence[float]) -> np.ndarray:
        _, _, _, g, _ = self.planar_points(q)
        return self.to_3d(q[0], g[0], g[1])

    # --- inverse kinematics --------------------------------------------------------------
    def ik(self, target: Sequence[float], pitch: float) -> List[Tuple[float, float, float, float]]:
        """Joint solutions (within limits) putting the gripper point at ``target`` with the
        gripper pitched ``pitch`` below horizontal (in the arm's plane)."""
        x, y, z = target
        solutions = []
        radius = math.hypot(x, y)
        facing = math.atan2(y, x) if radius > 1e-9 else 0.0
        a1, e10 = self.upper_arm
        a2 = self.wrist_x
        for waist, r in ((facing, radius), (_wrap(facing + math.pi), -radius)):
            # the wrist is a hand's length back from the target along the gripper
            wr = r - self.hand_length * math.cos(-pitch)
            wz = z - self.hand_length * math.sin(-pitch)
            dr, dz = wr, wz - self.shoulder_height
            reach = math.hypot(dr, dz)
            if reach > a1 + a2 or reach < abs(a1 - a2) or reach < 1e-9:
                continue
            cos_inner = (a1 * a1 + reach * reach - a2 * a2) / (2 * a1 * reach)
            inner = math.acos(max(-1.0, min(1.0, cos_inner)))
            toward = math.atan2(dz, dr)
            for e1 in (toward + inner, toward - inner):
                er, ez = a1 * math.cos(e1), a1 * math.sin(e1)
                e2 = math.atan2(dz - ez, dr - er)
                q1 = _wrap(e10 - e1)
                q2 = _wrap(-e2 - q1)
                q3 = _wrap(pitch - q1 - q2)
                q = (waist, q1, q2, q3)
                if self.within_limits(q):
                    solutions.append(q)
        return solutions

    def ik_candidates(self, target: Sequence[float], pitches: Iterable[float]):
        """IK solutions over a sequence of pitches, in that order of preference."""
        for pitch in pitches:
            yield from self.ik(target, pitch)


def _wrap(angle: float) -> float:
    return math.atan2(math.sin(angle), math.cos(angle))

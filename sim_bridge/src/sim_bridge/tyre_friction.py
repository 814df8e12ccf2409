"""Coulomb friction for a robot's tyres that is the same at every heading.

pybullet gives the contacts of a robot (a multibody) friction on two directions taken from
the contact normal alone: on a flat floor, the world's x and y axes, whatever the robot's
heading. With the friction pyramid (``enableConeFriction=0``) a tyre slipping along a
diagonal grips 41% harder than one slipping along an axis; with pybullet's cone the two
rows are still solved on the world's axes and the result still depends on the heading
(measured: a box sliding at 20 degrees to its own axis turned by +0.7 degrees at heading 0
and by -9.3 degrees at heading 45; a flipping robot driven along x ran off its line toward
the nearest diagonal, 0.3 to 0.9 m in 60 s, and stayed on it only when started there).
Neither can be changed through pybullet's interface.

So the contacts of a tyre get their friction here instead, and pybullet's friction for the
tyre is set to 0. Each step, before pybullet's, for every contact point of a tyre link
(normal force from pybullet's last step): the sliding velocity of the tyre's surface
against the other body at that point, in the contact plane, and a force against it,

    F = -min(N * M * s / |s|,  k * s),   M = mu1 along fdir1, mu2 across it,

at the contact point (the other body gets the opposite force when it moves). With
mu1 = mu2 this is Coulomb's isotropic cone: it depends on nothing but the contact, so a
robot behaves the same at every heading (tested at 0, 30, 45 and 90 degrees). Below the
slip at which ``k * s`` reaches Coulomb's force, the force grows linearly with the slip:
an explicit force stiffer than that would overshoot. ``k`` is half of what would stop the
robot's share of mass (its mass over its tyres) sliding within one step: all its tyres
together take at most half a step's slip away. A tyre under steady load therefore creeps,
at (force needed) / k: 0.16 mm/s per newton for a 25 kg robot on two tyres at a 1 ms step.
(A first version set the linear zone at 2 mu g dt instead: with a student's mu of 25 that
was 0.49 m/s, and the robot drove 0.53 m of a commanded 1 m.) ``fdir1`` is Gazebo's: a
direction in the link's frame, projected on the contact plane; without it mu1 acts along
the tyre's rolling direction and mu2 along its axle, which is the only frame a spinning
wheel keeps.

The normal force a contact's friction may use is capped at LOAD_CAP_SHARE times the tyre's
static share of the robot's weight. pybullet's normal force of the last step is an
impulse over the step: a robot dropped from 1 m (launch files spawn at ``-z 1``) lands at
4.4 m/s with 8-53 kN on a wheel for one step; the next step that load, with the contact
already opening, gave a friction kick of 8 kN that spun the wheel and shot a 25 kg RB1 up
to 13 cm sideways and 10 degrees off its heading (43 cm and 5 degrees without its drive
plugin), depending on where in a step it touched down. Capped, it rests within a few
millimetres, as a body landing flat does (no torque acts on it). A steady load above the
cap (a payload twice the robot's weight) would grip less than Coulomb says. (A rule that
took a tyre leaving the surface as having no load brought a free-wheeled landing from 0.8
to 0.1 degrees of heading, and stopped the flipping robot of diff_drive from flipping: its
wheels hop as it reverses.)

A tyre is what :mod:`sim_bridge.robot_body` crowns: a collision cylinder turning about its
own axis on a continuous or revolute joint; a link whose ``<gazebo>`` block gives
``fdir1`` is treated the same way. Other links (bodies, casters, grippers, which must hold
what they grasp without creeping) keep pybullet's friction.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Dict, List, Optional, Sequence, Set, Tuple

import pybullet as pb

# the share of one step's slip all of a robot's tyres together may take away (see above)
STIFFNESS_SHARE = 0.5
# the most normal force a contact's friction uses, in tyres' static shares of the robot's
# weight (see above)
LOAD_CAP_SHARE = 3.0
# below this length a projected direction has vanished (fdir1 along the contact normal)
DEGENERATE = 1e-6

Vector = Tuple[float, float, float]


@dataclass(frozen=True)
class Tyre:
    """One tyre link: its friction coefficients and the directions they act along, in the
    link's frame (``fdir1``: Gazebo's, or None; ``axle``: the axis the link turns about)."""

    link: int
    mu1: float
    mu2: float
    fdir1: Optional[Vector]
    axle: Optional[Vector]


def _cross(a: Sequence[float], b: Sequence[float]) -> Vector:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _dot(a: Sequence[float], b: Sequence[float]) -> float:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _in_plane(vector: Sequence[float], normal: Sequence[float]) -> Optional[Vector]:
    """``vector`` projected on the plane of ``normal``, unit length; None when it vanishes."""
    along = _dot(vector, normal)
    x, y, z = (vector[0] - along * normal[0], vector[1] - along * normal[1],
               vector[2] - along * normal[2])
    length = math.sqrt(x * x + y * y + z * z)
    if length < DEGENERATE:
        return None
    return (x / length, y / length, z / length)


def _rotate(matrix: Sequence[float], vector: Sequence[float]) -> Vector:
    """A row-major 3x3 (pybullet's getMatrixFromQuaternion) times ``vector``."""
    return (matrix[0] * vector[0] + matrix[1] * vector[1] + matrix[2] * vector[2],
            matrix[3] * vector[0] + matrix[4] * vector[1] + matrix[5] * vector[2],
            matrix[6] * vector[0] + matrix[7] * vector[1] + matrix[8] * vector[2])


def stiffness(robot_mass: float, tyres: int, step_size: float) -> float:
    """k (N per m/s of slip) of each of a robot's tyres (see the module's notes)."""
    return STIFFNESS_SHARE * robot_mass / (max(tyres, 1) * step_size)


def point_velocity(client: int, body: int, link: int, point: Sequence[float]) -> Vector:
    """The velocity of the material of ``body``'s ``link`` at world ``point``."""
    if link < 0:
        (linear, angular) = pb.getBaseVelocity(body, physicsClientId=client)
        centre = pb.getBasePositionAndOrientation(body, physicsClientId=client)[0]
    else:
        state = pb.getLinkState(body, link, computeLinkVelocity=1, physicsClientId=client)
        centre, linear, angular = state[0], state[6], state[7]
    lever = (point[0] - centre[0], point[1] - centre[1], point[2] - centre[2])
    spin = _cross(angular, lever)
    return (linear[0] + spin[0], linear[1] + spin[1], linear[2] + spin[2])


class TyreFriction:
    """The friction of one robot's tyres; :meth:`apply` once before every physics step.

    ``all_tyres`` is shared by every robot's TyreFriction in a world: (body, link) of each
    tyre, so that a tyre touching another robot's tyre leaves that tyre's force to it.

    Two ways to the same forces: :meth:`forces`, the fast path the simulator takes, and
    :meth:`reference_forces`, the maths one contact at a time as first written;
    ``test_tyre_friction`` steps robots with the one while checking every step that the
    other gives the same forces to the last bit. What the fast path saves: whatever does
    not change between steps is worked out once per pair of touching links (the friction
    coefficients the contact takes, the cap on its linear zone, whether the other body
    moves and takes the opposite force), and pybullet is called with positional arguments.
    Measured on the 2-core VM, a whole :meth:`apply` (queries, maths, forces): 6.8 us a step
    for a robot on two tyres (7.8 before), 10.1 on four (12.4); a physics step of either
    robot alone on a plane costs 7 and 14 us. A compiled kernel would not help: pybullet's
    own queries (the robot's contact points, about 2.5 us; its tyres' states, 2; 0.3 a
    force) are most of what is left, and handing a few contacts to C through ctypes costs
    about what their maths does in Python (about 1 us a contact).
    """

    def __init__(self, client: int, body: int, tyres: Sequence[Tyre], step_size: float,
                 all_tyres: Set[Tuple[int, int]], gravity: Sequence[float] = (0.0, 0.0, -9.8)):
        self.mass = sum(pb.getDynamicsInfo(body, link, physicsClientId=client)[0]
                        for link in range(-1, pb.getNumJoints(body, physicsClientId=client)))
        self.client, self.body = client, body
        self.tyres: Dict[int, Tyre] = {tyre.link: tyre for tyre in tyres}
        self.links = sorted(self.tyres)
        # where each tyre's state is in what getLinkStates returns for self.links
        self._slot = {link: index for index, link in enumerate(self.links)}
        self.all_tyres = all_tyres
        all_tyres.update((body, link) for link in self.links)
        # (body, link) -> (moves, mu): what a contact needs of the other body
        self._others: Dict[Tuple[int, int], Tuple[bool, float]] = {}
        # (tyre link, other body, other link) -> _Pair: the fast path's per-pair constants
        self._pairs: Dict[Tuple[int, int, int], "_Pair"] = {}
        self.set_physics(step_size, gravity)
        for link in self.links:  # pybullet's own friction for these links: none
            pb.changeDynamics(body, link, lateralFriction=0.0, physicsClientId=client)

    def set_physics(self, step_size: float, gravity: Sequence[float]) -> None:
        """The world's step and gravity: the slip stiffness follows the step, the load cap
        the weight (none without gravity: no weight to compare a load with)."""
        self.stiffness = stiffness(self.mass, len(self.tyres), step_size)
        weight = self.mass * math.sqrt(sum(g * g for g in gravity))
        self.load_cap = LOAD_CAP_SHARE * weight / max(len(self.tyres), 1) if weight > 0 \
            else math.inf
        self._pairs.clear()  # their caps follow the stiffness

    def forget(self) -> None:
        """The world's bodies changed: what was cached about other bodies may be stale."""
        self._others.clear()
        self._pairs.clear()

    def remove(self) -> None:
        self.all_tyres.difference_update((self.body, link) for link in self.links)

    def apply(self) -> None:
        """Applies this step's tyre forces (:meth:`forces`)."""
        client = self.client
        # positional arguments: pybullet parses keywords slower, 0.4 us a call (the -1s and
        # -2s are getContactPoints' defaults: any other body, any link)
        for body, link, force, point in self.forces(
                pb.getContactPoints(self.body, -1, -2, -2, client)):
            pb.applyExternalForce(body, link, force, point, pb.WORLD_FRAME,
                                  physicsClientId=client)

    def forces(self, contacts) -> List[Tuple[int, int, Vector, Vector]]:
        """(body, link, force, point in the world) to apply for ``contacts`` (pybullet's
        getContactPoints with this robot as body A), in order; the fast path, equal to
        :meth:`reference_forces` (see the class's notes). Written out component by
        component: this runs every step."""
        tyres, pairs, body = self.tyres, self._pairs, self.body
        states = None
        out: List[Tuple[int, int, Vector, Vector]] = []
        for contact in contacts:
            link, load = contact[3], contact[9]
            if link not in tyres or not load > 0.0:
                continue
            if load > self.load_cap:
                load = self.load_cap
            if states is None:  # computeLinkVelocity 1, computeForwardKinematics 0
                states = pb.getLinkStates(body, self.links, 1, 0, self.client)
            other, other_link = contact[2], contact[4]
            pair = pairs.get((link, other, other_link))
            if pair is None:
                pair = pairs[(link, other, other_link)] = self._pair(link, other, other_link)
            state = states[self._slot[link]]
            (px, py, pz), (nx, ny, nz) = contact[5], contact[7]
            (cx, cy, cz), (vx, vy, vz), (wx, wy, wz) = state[0], state[6], state[7]
            rx, ry, rz = px - cx, py - cy, pz - cz
            vx += wy * rz - wz * ry  # the velocity of the tyre's material at the contact
            vy += wz * rx - wx * rz
            vz += wx * ry - wy * rx
            if pair.moving:
                tx, ty, tz = point_velocity(self.client, other, other_link, (px, py, pz))
                vx, vy, vz = vx - tx, vy - ty, vz - tz
            along = vx * nx + vy * ny + vz * nz
            sx, sy, sz = vx - along * nx, vy - along * ny, vz - along * nz
            speed = math.sqrt(sx * sx + sy * sy + sz * sz)
            if speed == 0.0:
                continue
            scale = min(load / speed, pair.cap)  # Coulomb's mu N, or less: k * slip
            if pair.isotropic:
                factor = -pair.mu1 * scale
                force = (factor * sx, factor * sy, factor * sz)
            else:
                force = _anisotropic(tyres[link], pair.mu1, pair.mu2, scale, (sx, sy, sz),
                                     state[5], (nx, ny, nz))
            point = (px, py, pz)
            out.append((body, link, force, point))
            if pair.react:
                out.append((other, other_link, (-force[0], -force[1], -force[2]), point))
        return out

    def _pair(self, link: int, other: int, other_link: int) -> "_Pair":
        """What does not change between steps about ``link`` touching ``other_link``."""
        tyre = self.tyres[link]
        other_is_tyre = (other, other_link) in self.all_tyres
        moving, other_mu = self._other(other, other_link)
        if other_is_tyre:  # pybullet's mu of a tyre is 0; Gazebo takes the lesser of two
            other_mu = math.inf
        mu1, mu2 = min(tyre.mu1, other_mu), min(tyre.mu2, other_mu)
        return _Pair(moving, mu1, mu2, self.stiffness / max(mu1, mu2, 1e-12), mu1 == mu2,
                     moving and not other_is_tyre)

    def reference_forces(self, contacts) -> List[Tuple[int, int, Vector, Vector]]:
        """The same as :meth:`forces`, one contact at a time, nothing kept between steps
        but what the other body is: the reference the fast path is tested against."""
        tyres = self.tyres
        contacts = [c for c in contacts if c[3] in tyres and c[9] > 0.0]
        if not contacts:
            return []
        states = dict(zip(self.links, pb.getLinkStates(self.body, self.links,
                                                       computeLinkVelocity=1,
                                                       physicsClientId=self.client)))
        out: List[Tuple[int, int, Vector, Vector]] = []
        for contact in contacts:
            out.extend(self._reference_one(contact, states[contact[3]]))
        return out

    def _other(self, body: int, link: int) -> Tuple[bool, float]:
        key = (body, link)
        if key not in self._others:
            info = pb.getDynamicsInfo(body, link, physicsClientId=self.client)
            self._others[key] = (info[0] > 0.0, info[1])
        return self._others[key]

    def _reference_one(self, contact, state) -> List[Tuple[int, int, Vector, Vector]]:
        client, body = self.client, self.body
        link, other, other_link = contact[3], contact[2], contact[4]
        (px, py, pz), (nx, ny, nz) = contact[5], contact[7]
        load = min(contact[9], self.load_cap)
        tyre = self.tyres[link]
        other_is_tyre = (other, other_link) in self.all_tyres
        moving, other_mu = self._other(other, other_link)
        if other_is_tyre:  # pybullet's mu of a tyre is 0; Gazebo takes the lesser of two
            other_mu = math.inf
        mu1, mu2 = min(tyre.mu1, other_mu), min(tyre.mu2, other_mu)
        (cx, cy, cz), (vx, vy, vz), (wx, wy, wz) = state[0], state[6], state[7]
        rx, ry, rz = px - cx, py - cy, pz - cz
        vx += wy * rz - wz * ry  # the velocity of the tyre's material at the contact
        vy += wz * rx - wx * rz
        vz += wx * ry - wy * rx
        if moving:
            tx, ty, tz = point_velocity(client, other, other_link, (px, py, pz))
            vx, vy, vz = vx - tx, vy - ty, vz - tz
        along = vx * nx + vy * ny + vz * nz
        sx, sy, sz = vx - along * nx, vy - along * ny, vz - along * nz
        speed = math.sqrt(sx * sx + sy * sy + sz * sz)
        if speed == 0.0:
            return []
        # Coulomb's mu N, or less while k * slip is less
        scale = min(load / speed, self.stiffness / max(mu1, mu2, 1e-12))
        if mu1 == mu2:
            factor = -mu1 * scale
            force = (factor * sx, factor * sy, factor * sz)
        else:
            force = _anisotropic(tyre, mu1, mu2, scale, (sx, sy, sz), state[5], (nx, ny, nz))
        point = (px, py, pz)
        out = [(body, link, force, point)]
        if moving and not other_is_tyre:
            out.append((other, other_link, (-force[0], -force[1], -force[2]), point))
        return out


@dataclass(frozen=True)
class _Pair:
    """A tyre link touching another link: what its contacts need that does not change."""

    moving: bool  # the other body moves: the tyre slips against its surface's velocity
    mu1: float  # the coefficients the contact takes (the lesser of the two surfaces')
    mu2: float
    cap: float  # k / max(mu1, mu2): where the linear zone ends, per newton of load
    isotropic: bool  # mu1 == mu2: no direction to work out
    react: bool  # the other body gets the opposite force (it moves and is no tyre)


def _anisotropic(tyre: Tyre, mu1: float, mu2: float, scale: float, slip: Vector,
                 orientation, normal: Vector) -> Vector:
    """The force for mu1 != mu2: mu1 along its direction at this contact, mu2 across it."""
    first = _first_direction(tyre, orientation, normal)
    second = _cross(normal, first)
    a, b = mu1 * _dot(slip, first), mu2 * _dot(slip, second)
    return tuple(-scale * (a * first[i] + b * second[i]) for i in range(3))


def _first_direction(tyre: Tyre, orientation, normal) -> Vector:
    """mu1's direction at this contact: fdir1, else the rolling direction."""
    matrix = pb.getMatrixFromQuaternion(orientation)
    if tyre.fdir1 is not None:
        direction = _in_plane(_rotate(matrix, tyre.fdir1), normal)
        if direction is not None:
            return direction
    if tyre.axle is not None:
        rolling = _in_plane(_cross(normal, _rotate(matrix, tyre.axle)), normal)
        if rolling is not None:
            return rolling
    return _in_plane((1.0, 0.0, 0.0), normal) or (0.0, 1.0, 0.0)

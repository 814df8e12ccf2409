"""Forces from outside, for a while of simulated time: gazebo_ros's ``apply_body_wrench``
and ``apply_joint_effort`` and their ``clear_`` services. No rospy.

A request becomes a job with a window of simulated time: from its start (now, if the start
asked for has passed) for its duration, or until cleared when the duration is negative.
Before each physics step the world applies every job whose window holds the step's start
time, so a job of duration d acts on d / step steps and gives an impulse of exactly F·d
(Gazebo's scheduler includes both ends of the window: one step more). pybullet forgets
external forces and joint torques after each step, as Gazebo does, so they are applied
again every step.

A wrench is kept in world axes, as Gazebo keeps it (its ``Link::SetForce`` and
``SetTorque`` take world vectors): the force acts at the body's centre of mass, the
torque about it. A body is one of Gazebo's links, which may be several URDF links lumped
together (see :mod:`sim_bridge.model_structure`); its centre of mass is theirs.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, List, Sequence, Tuple

import numpy as np
import pybullet as pb

# (pybullet link index, mass) of each pybullet link that makes up one of Gazebo's bodies
LinkMasses = Sequence[Tuple[int, float]]


@dataclass(frozen=True)
class Window:
    """When a job acts: steps starting at or after ``start_ns`` and before
    ``start_ns + duration_ns``; a negative duration never ends."""

    start_ns: int
    duration_ns: int

    @classmethod
    def starting(cls, now_ns: int, start_ns: int, duration_ns: int) -> "Window":
        return cls(max(int(start_ns), int(now_ns)), int(duration_ns))

    def holds(self, now_ns: int) -> bool:
        return now_ns >= self.start_ns and (self.duration_ns < 0
                                            or now_ns < self.start_ns + self.duration_ns)

    def over(self, now_ns: int) -> bool:
        return self.duration_ns >= 0 and now_ns >= self.start_ns + self.duration_ns


def centre_of_mass(client: int, body_id: int, links: LinkMasses) -> np.ndarray:
    """World position of the centre of mass of some links of a pybullet body."""
    total = 0.0
    weighted = np.zeros(3)
    for index, mass in links:
        if index == -1:
            position = pb.getBasePositionAndOrientation(body_id, physicsClientId=client)[0]
        else:
            position = pb.getLinkState(body_id, index, computeForwardKinematics=1,
                                       physicsClientId=client)[0]
        weighted += mass * np.asarray(position)
        total += mass
    if total <= 0.0:  # massless: the first link's own centre
        index = links[0][0]
        return np.asarray(
            pb.getBasePositionAndOrientation(body_id, physicsClientId=client)[0] if index == -1
            else pb.getLinkState(body_id, index, physicsClientId=client)[0])
    return weighted / total


@dataclass
class BodyWrench:
    model: str
    body: str  # Gazebo's link name (not scoped)
    body_id: int
    links: LinkMasses  # the first is the pybullet link the wrench is applied to
    force: np.ndarray  # world axes, N, at the centre of mass
    torque: np.ndarray  # world axes, N m, about the centre of mass
    window: Window

    def apply(self, client: int) -> None:
        index = self.links[0][0]
        if np.any(self.force):
            pb.applyExternalForce(self.body_id, index, self.force.tolist(),
                                  centre_of_mass(client, self.body_id, self.links).tolist(),
                                  pb.WORLD_FRAME, physicsClientId=client)
        if np.any(self.torque):
            pb.applyExternalTorque(self.body_id, index, self.torque.tolist(), pb.WORLD_FRAME,
                                   physicsClientId=client)


@dataclass
class JointEffort:
    model: str
    joint: str
    body_id: int
    index: int  # pybullet joint index
    effort: float  # N m (revolute) or N (prismatic)
    window: Window


class ExternalForces:
    """The jobs of a world; ``apply(now_ns)`` before each physics step."""

    def __init__(self, client: int):
        self.client = client
        self.wrenches: List[BodyWrench] = []
        self.efforts: List[JointEffort] = []

    def __bool__(self) -> bool:
        return bool(self.wrenches or self.efforts)

    def apply(self, now_ns: int) -> None:
        """Applies what acts on the step starting at ``now_ns``; drops what is over."""
        for wrench in self.wrenches:
            if wrench.window.holds(now_ns):
                wrench.apply(self.client)
        torques = {}
        for effort in self.efforts:
            if effort.window.holds(now_ns):
                key = (effort.body_id, effort.index)
                torques[key] = torques.get(key, 0.0) + effort.effort
        for (body_id, index), torque in torques.items():
            # added to what the joint's motor does this step (pybullet sums them)
            pb.setJointMotorControl2(body_id, index, pb.TORQUE_CONTROL, force=torque,
                                     physicsClientId=self.client)
        self.wrenches = [w for w in self.wrenches if not w.window.over(now_ns)]
        self.efforts = [e for e in self.efforts if not e.window.over(now_ns)]

    def clear_wrenches(self, matches: Callable[[BodyWrench], bool]) -> int:
        kept = [w for w in self.wrenches if not matches(w)]
        cleared = len(self.wrenches) - len(kept)
        self.wrenches = kept
        return cleared

    def clear_efforts(self, matches: Callable[[JointEffort], bool]) -> int:
        kept = [e for e in self.efforts if not matches(e)]
        cleared = len(self.efforts) - len(kept)
        self.efforts = kept
        return cleared

    def forget_model(self, model: str) -> None:
        self.clear_wrenches(lambda w: w.model == model)
        self.clear_efforts(lambda e: e.model == model)

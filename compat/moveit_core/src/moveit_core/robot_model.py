"""A robot as MoveIt sees it: the URDF's kinematic tree, the SRDF's groups resolved to
joints and links as MoveIt's ``JointModelGroup`` resolves them, variable bounds (URDF limits,
overridden by ``robot_description_planning``), named states and forward kinematics of every
link.

MoveIt's own rules are kept where a user can see them:
- joints are ordered depth-first from the root, a link's children in the order of their
  joints' names (urdfdom keeps joints in a map by name): a group's joint order, and so the
  order of ``get_current_joint_values()``, follows;
- a group holds the joints it lists, the parent joint of each link it lists, every joint of
  each chain (base to tip) and its subgroups' joints; its variables are the movable ones
  that are neither mimic nor passive;
- a group whose joints form one path down the tree is a chain; its tip is the last link;
- a variable's default is 0 when its bounds hold 0, else the middle of its bounds.
No ROS here; numpy and urdf_tools' transforms.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Dict, List, Mapping, Optional, Sequence, Tuple

import numpy as np

from moveit_core.srdf import Srdf, parse_srdf
from urdf_tools import Joint, RobotModel as Urdf, parse_urdf
from urdf_tools.kinematics import joint_transform

VARIABLE_TYPES = ("revolute", "continuous", "prismatic")


class RobotModelError(ValueError):
    """A group or joint that MoveIt would refuse; the message names it."""


@dataclass(frozen=True)
class Bounds:
    """One variable's limits, as MoveIt's VariableBounds: positions (continuous joints are
    unbounded and wrap), speed and acceleration when known."""

    lower: float = -math.inf
    upper: float = math.inf
    max_velocity: Optional[float] = None
    max_acceleration: Optional[float] = None

    @property
    def bounded(self) -> bool:
        return math.isfinite(self.lower) and math.isfinite(self.upper)

    def default(self) -> float:
        if self.lower <= 0.0 <= self.upper:
            return 0.0
        return (self.lower + self.upper) / 2.0

    def contains(self, value: float, margin: float = 0.0) -> bool:
        return self.lower - margin <= value <= self.upper + margin

    def clamp(self, value: float) -> float:
        return min(max(value, self.lower), self.upper)


@dataclass
class JointModelGroup:
    name: str
    joints: List[str]                  # every joint, fixed ones too, in the model's order
    variables: List[str]               # what a state of the group sets
    links: List[str]                   # the links its joints move, and those it lists
    is_chain: bool
    base_link: str                     # parent link of its first joint
    tip_link: str                      # last link (a chain's tip)
    end_effector_links: List[str] = field(default_factory=list)   # SRDF end effectors on it
    subgroups: List[str] = field(default_factory=list)


class RobotModel:
    """A URDF and its SRDF (``srdf`` may be empty text: no groups)."""

    def __init__(self, urdf: Urdf, srdf: Srdf,
                 joint_limits: Optional[Mapping[str, Mapping]] = None):
        self.urdf, self.srdf = urdf, srdf
        self.name = urdf.name
        virtual = srdf.virtual_joints[0] if srdf.virtual_joints else None
        # MoveIt's model frame: the virtual joint's parent frame, else the URDF's root link
        self.model_frame = virtual.parent_frame if virtual else urdf.root()
        self.root_link = urdf.root()
        self._children = _children(urdf)
        self.joint_order = _preorder(urdf, self.root_link, self._children)
        passive = set(srdf.passive_joints)
        self.variables = [j for j in self.joint_order
                          if urdf.joints[j].type in VARIABLE_TYPES
                          and urdf.joints[j].mimic is None and j not in passive]
        self.mimics = {j.name: j.mimic for j in urdf.joints.values()
                       if j.mimic is not None and j.type in VARIABLE_TYPES}
        for name, mimic in self.mimics.items():
            if mimic.joint not in urdf.joints:
                raise RobotModelError(f"joint '{name}' mimics '{mimic.joint}', which the "
                                      "robot lacks")
        self.bounds = {j: _bounds(urdf.joints[j], (joint_limits or {}).get(j, {}))
                       for j in self.joint_order if urdf.joints[j].type in VARIABLE_TYPES}
        self._chain_steps = [_step(urdf.joints[j]) for j in self.joint_order]
        self.groups: Dict[str, JointModelGroup] = {}
        for name in srdf.groups:
            self.groups[name] = self._group(name, ())

    # --- construction ------------------------------------------------------------------

    def _group(self, name: str, visiting: Tuple[str, ...]) -> JointModelGroup:
        if name in self.groups:
            return self.groups[name]
        if name in visiting:
            raise RobotModelError(f"group '{name}' contains itself (through "
                                  f"{' -> '.join(visiting + (name,))})")
        spec = self.srdf.groups[name]
        joints = set(spec.joints)
        listed_links = list(spec.links)
        for link in spec.links:
            parent = self.urdf.parent_joint(link)
            if parent is not None:
                joints.add(parent.name)
        for base, tip in spec.chains:
            try:
                joints.update(j.name for j in self.urdf.chain(base, tip))
            except ValueError as error:
                raise RobotModelError(f"group '{name}': chain from '{base}' to '{tip}': "
                                      f"{error}") from error
        subgroups = []
        for sub in spec.subgroups:
            if sub not in self.srdf.groups:
                raise RobotModelError(f"group '{name}' names subgroup '{sub}', which the "
                                      "SRDF lacks")
            joints.update(self._group(sub, visiting + (name,)).joints)
            subgroups.append(sub)
        virtual = {v.name for v in self.srdf.virtual_joints}
        ordered = [j for j in self.joint_order if j in joints]
        if not ordered and not (joints & virtual):
            raise RobotModelError(f"group '{name}' holds no joint of the robot")
        variables = [j for j in ordered if j in self.variables]
        links = [self.urdf.joints[j].child for j in ordered]
        links += [link for link in listed_links if link not in links]
        base = self.urdf.joints[ordered[0]].parent if ordered else self.root_link
        is_chain = bool(variables) and self._is_path(ordered)
        eef_links = [e.parent_link for e in self.srdf.end_effectors
                     if e.parent_group == name or (not e.parent_group and e.parent_link in links
                                                   and e.group != name)]
        return JointModelGroup(name, ordered, variables, links, is_chain, base,
                               links[-1] if links else base, eef_links, subgroups)

    def _is_path(self, ordered: Sequence[str]) -> bool:
        """The joints, in depth-first order, lie on one path down the tree."""
        for before, after in zip(ordered, ordered[1:]):
            if not self._descends(self.urdf.joints[after].parent,
                                  self.urdf.joints[before].child):
                return False
        return True

    def _descends(self, link: str, ancestor: str) -> bool:
        while link != ancestor:
            joint = self.urdf.parent_joint(link)
            if joint is None:
                return False
            link = joint.parent
        return True

    # --- queries -----------------------------------------------------------------------

    def group(self, name: str) -> JointModelGroup:
        try:
            return self.groups[name]
        except KeyError:
            raise RobotModelError(f"no group '{name}' (the SRDF has: "
                                  f"{', '.join(self.groups) or 'none'})") from None

    def named_state(self, group: str, name: str) -> Dict[str, float]:
        """A group state of the SRDF (Home, Sleep...) by variable."""
        state = self.srdf.group_state(group, name)
        if state is None:
            known = [s.name for s in self.srdf.group_states if s.group == group]
            raise RobotModelError(f"group '{group}' has no state '{name}' (it has: "
                                  f"{', '.join(known) or 'none'})")
        return {j: v[0] for j, v in state.values.items() if j in self.variables}

    def default_positions(self) -> Dict[str, float]:
        return {j: self.bounds[j].default() for j in self.variables}

    def complete(self, positions: Mapping[str, float]) -> Dict[str, float]:
        """Every variable and mimic joint's position: ``positions`` over the defaults."""
        full = self.default_positions()
        full.update({j: float(v) for j, v in positions.items() if j in self.bounds})
        for name, mimic in self.mimics.items():
            full[name] = mimic.multiplier * full.get(mimic.joint, 0.0) + mimic.offset
        return full

    def link_poses(self, positions: Mapping[str, float]) -> Dict[str, np.ndarray]:
        """Each link's pose (4x4) in the root link's frame: the same transforms as
        urdf_tools.kinematics.joint_transform, with each joint's origin and axis prepared
        once (collision checks call this for every state they check)."""
        full = self.complete(positions)
        poses = {self.root_link: np.eye(4)}
        for name, parent, child, origin, kind, axis, cross in self._chain_steps:
            if kind == 0:
                poses[child] = poses[parent] @ origin
                continue
            value = full.get(name, 0.0)
            motion = np.eye(4)
            if kind == 1:     # Rodrigues: R = I + sin(q) K + (1 - cos(q)) K^2
                motion[:3, :3] += math.sin(value) * cross + (1.0 - math.cos(value)) * (
                    cross @ cross)
            else:
                motion[:3, 3] = axis * value
            poses[child] = poses[parent] @ origin @ motion
        return poses

    def link_poses_many(self, positions: Mapping[str, float], variables: Sequence[str],
                        values: np.ndarray) -> Dict[str, np.ndarray]:
        """Each link's pose for many states at once (N x 4 x 4 per link): ``values`` (N x
        len(variables)) over ``positions``. The same transforms as :meth:`link_poses`, one
        numpy operation per joint for all states (checking a motion's hundreds of states)."""
        values = np.asarray(values, dtype=float).reshape(-1, len(variables))
        count = len(values)
        full = self.complete(positions)
        columns = {name: values[:, i] for i, name in enumerate(variables)
                   if name in self.bounds}
        for name, mimic in self.mimics.items():
            if mimic.joint in columns:
                columns[name] = mimic.multiplier * columns[mimic.joint] + mimic.offset
        poses = {self.root_link: np.broadcast_to(np.eye(4), (count, 4, 4))}
        for name, parent, child, origin, kind, axis, cross in self._chain_steps:
            placed = poses[parent] @ origin
            if kind == 0:
                poses[child] = placed
                continue
            value = columns.get(name, np.full(count, full.get(name, 0.0)))
            motion = np.zeros((count, 4, 4))
            motion[:, 3, 3] = 1.0
            if kind == 1:     # Rodrigues, as link_poses
                motion[:, :3, :3] = np.eye(3) + np.sin(value)[:, None, None] * cross + (
                    1.0 - np.cos(value))[:, None, None] * (cross @ cross)
            else:
                motion[:, :3, :3] = np.eye(3)
                motion[:, :3, 3] = value[:, None] * axis
            poses[child] = placed @ motion
        return poses

    def within_bounds(self, positions: Mapping[str, float], margin: float = 0.0
                      ) -> List[str]:
        """The variables of ``positions`` outside their bounds, each with its value."""
        return [f"{j} = {v:.4f} (bounds {self.bounds[j].lower:.4f} to "
                f"{self.bounds[j].upper:.4f})" for j, v in positions.items()
                if j in self.bounds and not self.bounds[j].contains(v, margin)]


def _step(joint: Joint) -> tuple:
    """A joint prepared for link_poses: (name, parent, child, origin 4x4, kind (0 fixed,
    1 revolute, 2 prismatic), unit axis, the axis' cross-product matrix)."""
    origin = joint_transform(Joint(joint.name, "fixed", joint.parent, joint.child,
                                   joint.origin))
    axis = np.asarray(joint.axis, dtype=float)
    axis = axis / (np.linalg.norm(axis) or 1.0)
    cross = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]],
                      [-axis[1], axis[0], 0.0]])
    kind = {"revolute": 1, "continuous": 1, "prismatic": 2}.get(joint.type, 0)
    return joint.name, joint.parent, joint.child, origin, kind, axis, cross


def _children(urdf: Urdf) -> Dict[str, List[str]]:
    children: Dict[str, List[str]] = {}
    for joint in sorted(urdf.joints.values(), key=lambda j: j.name):
        children.setdefault(joint.parent, []).append(joint.name)
    return children


def _preorder(urdf: Urdf, root: str, children: Dict[str, List[str]]) -> List[str]:
    order: List[str] = []
    stack = list(reversed(children.get(root, [])))
    while stack:
        joint = stack.pop()
        order.append(joint)
        stack.extend(reversed(children.get(urdf.joints[joint].child, [])))
    return order


def _bounds(joint: Joint, planning: Mapping) -> Bounds:
    """URDF limits, then ``robot_description_planning/joint_limits/<joint>`` as MoveIt reads
    it (``has_*_limits`` switch each one on or off)."""
    lower, upper = -math.inf, math.inf
    velocity = acceleration = None
    if joint.limit is not None:
        if joint.type != "continuous":
            lower, upper = joint.limit.lower, joint.limit.upper
        velocity = joint.limit.velocity if joint.limit.velocity > 0 else None
    if planning.get("has_position_limits") and joint.type != "continuous":
        lower = float(planning.get("min_position", lower))
        upper = float(planning.get("max_position", upper))
    if "has_velocity_limits" in planning:
        velocity = float(planning["max_velocity"]) if planning["has_velocity_limits"] \
            and "max_velocity" in planning else None
    if planning.get("has_acceleration_limits") and "max_acceleration" in planning:
        acceleration = float(planning["max_acceleration"])
    return Bounds(lower, upper, velocity, acceleration)


def load(urdf_text: str, srdf_text: str, joint_limits: Optional[Mapping] = None,
         source: str = "robot_description") -> RobotModel:
    """The model from the texts of ``robot_description`` and ``robot_description_semantic``
    (``joint_limits``: ``robot_description_planning/joint_limits``)."""
    urdf = parse_urdf(urdf_text, source)
    srdf = parse_srdf(srdf_text, urdf, f"{source}_semantic") if srdf_text.strip() else \
        Srdf(name=urdf.name)
    return RobotModel(urdf, srdf, joint_limits)

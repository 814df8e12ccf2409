"""A robot's semantic description (SRDF, what MoveIt's Setup Assistant writes and
``robot_description_semantic`` holds) read into plain Python objects, checked against the
robot's URDF as srdfdom checks it.

srdfdom's tolerance is kept: an element that names a link, joint or group the robot lacks,
or that misses an attribute, is left out with a warning naming it and why, and the rest is
read (MoveIt starts with such a file). A document that is not XML, or whose root is not
``<robot>``, cannot be read at all: :class:`SrdfError` names the cause.
"""
from __future__ import annotations

import logging
import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Tuple

from urdf_tools import RobotModel as Urdf

# rospy shows the rosout.* loggers on the console and /rosout
LOG = logging.getLogger("rosout.moveit_core")

VIRTUAL_JOINT_TYPES = ("fixed", "floating", "planar")


class SrdfError(ValueError):
    """An SRDF that cannot be read at all; the message names the source and why."""


@dataclass(frozen=True)
class Group:
    """A ``<group>``: its members as the file lists them (resolved to joints by
    :mod:`moveit_core.robot_model`)."""

    name: str
    joints: Tuple[str, ...] = ()
    links: Tuple[str, ...] = ()
    chains: Tuple[Tuple[str, str], ...] = ()      # (base_link, tip_link)
    subgroups: Tuple[str, ...] = ()


@dataclass(frozen=True)
class GroupState:
    """A ``<group_state>``: a named pose of a group (Home, Sleep...), positions by joint."""

    name: str
    group: str
    values: Dict[str, Tuple[float, ...]]


@dataclass(frozen=True)
class EndEffector:
    name: str
    parent_link: str
    group: str
    parent_group: str = ""


@dataclass(frozen=True)
class VirtualJoint:
    name: str
    type: str
    parent_frame: str
    child_link: str


@dataclass(frozen=True)
class DisabledCollision:
    link1: str
    link2: str
    reason: str = ""


@dataclass
class Srdf:
    name: str
    groups: Dict[str, Group] = field(default_factory=dict)
    group_states: List[GroupState] = field(default_factory=list)
    end_effectors: List[EndEffector] = field(default_factory=list)
    virtual_joints: List[VirtualJoint] = field(default_factory=list)
    passive_joints: List[str] = field(default_factory=list)
    disabled_collisions: List[DisabledCollision] = field(default_factory=list)
    # links whose collisions with every other link are off unless enabled (srdfdom 0.6)
    disabled_default_collisions: List[str] = field(default_factory=list)
    enabled_collisions: List[Tuple[str, str]] = field(default_factory=list)
    source: str = "<string>"
    # each element left out, one sentence naming it and why (also logged)
    warnings: List[str] = field(default_factory=list)

    def group_state(self, group: str, name: str) -> Optional[GroupState]:
        return next((s for s in self.group_states if s.group == group and s.name == name), None)


class _Reader:
    """One document's reading: collects the warnings of what it leaves out."""

    def __init__(self, source: str, urdf: Optional[Urdf]):
        self.source, self.urdf = source, urdf
        self.warnings: List[str] = []

    def warn(self, message: str) -> None:
        message = f"{self.source}: {message}"
        LOG.warning(message)
        self.warnings.append(message)

    def attributes(self, element: ET.Element, *names: str) -> Optional[Tuple[str, ...]]:
        values = tuple((element.get(n) or "").strip() for n in names)
        missing = [n for n, v in zip(names, values) if not v]
        if missing:
            self.warn(f"<{element.tag}> without {', '.join(repr(m) for m in missing)} "
                      "left out")
            return None
        return values

    def known_link(self, link: str, where: str) -> bool:
        if self.urdf is None or link in self.urdf.links:
            return True
        self.warn(f"{where} names link '{link}', which the robot lacks: left out")
        return False

    def known_joint(self, joint: str, where: str, srdf: Srdf) -> bool:
        virtual = {v.name for v in srdf.virtual_joints}
        if self.urdf is None or joint in self.urdf.joints or joint in virtual:
            return True
        self.warn(f"{where} names joint '{joint}', which the robot lacks: left out")
        return False


def parse_srdf(text: str, urdf: Optional[Urdf] = None, source: str = "<string>") -> Srdf:
    """Reads SRDF ``text``; with ``urdf``, the names it uses are checked against the robot
    (what names nothing there is left out with a warning)."""
    try:
        root = ET.fromstring(text.lstrip())
    except ET.ParseError as error:
        raise SrdfError(f"{source}: not an SRDF document: {error}") from error
    if root.tag != "robot":
        raise SrdfError(f"{source}: the root element is <{root.tag}>, an SRDF's is <robot>")
    reader = _Reader(source, urdf)
    srdf = Srdf(name=root.get("name", ""), source=source)
    if urdf is not None and srdf.name and srdf.name != urdf.name:
        reader.warn(f"the SRDF is for robot '{srdf.name}', the URDF is '{urdf.name}'")
    for element in root.findall("virtual_joint"):
        _virtual_joint(reader, element, srdf)
    for element in root.findall("group"):
        _group(reader, element, srdf)
    for element in root.findall("group_state"):
        _group_state(reader, element, srdf)
    for element in root.findall("end_effector"):
        _end_effector(reader, element, srdf)
    for element in root.findall("passive_joint"):
        found = reader.attributes(element, "name")
        if found and reader.known_joint(found[0], "<passive_joint>", srdf):
            srdf.passive_joints.append(found[0])
    for element in root.findall("disable_collisions"):
        found = reader.attributes(element, "link1", "link2")
        if found and all(reader.known_link(link, "<disable_collisions>") for link in found):
            srdf.disabled_collisions.append(
                DisabledCollision(*found, element.get("reason", "")))
    for element in root.findall("disable_default_collisions"):
        found = reader.attributes(element, "link")
        if found and reader.known_link(found[0], "<disable_default_collisions>"):
            srdf.disabled_default_collisions.append(found[0])
    for element in root.findall("enable_collisions"):
        found = reader.attributes(element, "link1", "link2")
        if found and all(reader.known_link(link, "<enable_collisions>") for link in found):
            srdf.enabled_collisions.append(found)
    srdf.warnings = reader.warnings
    return srdf


def _virtual_joint(reader: _Reader, element: ET.Element, srdf: Srdf) -> None:
    found = reader.attributes(element, "name", "type", "parent_frame", "child_link")
    if not found:
        return
    name, kind, parent, child = found
    if kind not in VIRTUAL_JOINT_TYPES:
        reader.warn(f"virtual joint '{name}' has type '{kind}' (known: "
                    f"{', '.join(VIRTUAL_JOINT_TYPES)}): left out")
    elif reader.known_link(child, f"virtual joint '{name}'"):
        srdf.virtual_joints.append(VirtualJoint(name, kind, parent, child))


def _group(reader: _Reader, element: ET.Element, srdf: Srdf) -> None:
    found = reader.attributes(element, "name")
    if not found:
        return
    name = found[0]
    if name in srdf.groups:
        reader.warn(f"group '{name}' is defined twice: the second left out")
        return
    where = f"group '{name}'"
    joints, links, chains, subgroups = [], [], [], []
    for child in element:
        if child.tag == "joint":
            member = reader.attributes(child, "name")
            if member and reader.known_joint(member[0], where, srdf):
                joints.append(member[0])
        elif child.tag == "link":
            member = reader.attributes(child, "name")
            if member and reader.known_link(member[0], where):
                links.append(member[0])
        elif child.tag == "chain":
            member = reader.attributes(child, "base_link", "tip_link")
            if member and all(reader.known_link(link, where) for link in member):
                chains.append(member)
        elif child.tag == "group":
            member = reader.attributes(child, "name")
            if member:
                subgroups.append(member[0])
    srdf.groups[name] = Group(name, tuple(joints), tuple(links), tuple(chains), tuple(subgroups))


def _group_state(reader: _Reader, element: ET.Element, srdf: Srdf) -> None:
    found = reader.attributes(element, "name", "group")
    if not found:
        return
    name, group = found
    if group not in srdf.groups:
        reader.warn(f"group state '{name}' is of group '{group}', which the SRDF lacks: "
                    "left out")
        return
    values: Dict[str, Tuple[float, ...]] = {}
    for joint in element.findall("joint"):
        member = reader.attributes(joint, "name", "value")
        if not member or not reader.known_joint(member[0], f"group state '{name}'", srdf):
            continue
        try:
            numbers = tuple(float(v) for v in member[1].split())
        except ValueError:
            numbers = ()
        if not numbers or not all(math.isfinite(v) for v in numbers):
            reader.warn(f"group state '{name}': joint '{member[0]}' has value "
                        f"'{member[1]}', not numbers: left out")
            continue
        values[member[0]] = numbers
    srdf.group_states.append(GroupState(name, group, values))


def _end_effector(reader: _Reader, element: ET.Element, srdf: Srdf) -> None:
    found = reader.attributes(element, "name", "parent_link", "group")
    if not found:
        return
    name, parent_link, group = found
    if group not in srdf.groups:
        reader.warn(f"end effector '{name}' names group '{group}', which the SRDF lacks: "
                    "left out")
        return
    if not reader.known_link(parent_link, f"end effector '{name}'"):
        return
    parent_group = element.get("parent_group", "")
    if parent_group and parent_group not in srdf.groups:
        reader.warn(f"end effector '{name}' names parent group '{parent_group}', which the "
                    "SRDF lacks: read without it")
        parent_group = ""
    srdf.end_effectors.append(EndEffector(name, parent_link, group, parent_group))

"""An articulated SDF model (links and joints, as Gazebo's model library and students' worlds
have them) as the URDF robot sim_bridge builds: links, joints, limits, dynamics, colours,
and the model's plugins and sensors in ``<gazebo>`` blocks, so that they run as a URDF
robot's do.

SDF places every link in the model's frame and a joint in its child link's frame; URDF puts
a link's frame on the joint that carries it. So a child link's URDF frame is its SDF pose
composed with its joint's pose, and what the link holds (inertial, collisions, visuals) is
re-expressed from the SDF link frame into that one. A joint's ``<axis><xyz>`` is read in the
joint's frame (SDF 1.5 on), or in the model's with ``<use_parent_model_frame>true`` or
``expressed_in="__model__"``. Joint types: revolute (continuous when it gives no limits or
Gazebo's +-1e16), prismatic, fixed; a joint to ``world`` fixes the model there. Ball,
universal, revolute2, gearbox and screw joints, and links that no joint connects, are
:class:`~sim_bridge.sdf_world.UnsupportedModel`: the model is left out, named.
"""
from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np

from sim_bridge.poses import matrix_pose6, pose6_matrix

Pose6 = Tuple[float, ...]
JOINT_TYPES = {"revolute": "revolute", "prismatic": "prismatic", "fixed": "fixed",
               "continuous": "continuous"}
# Gazebo's "no limit" for a revolute joint
UNLIMITED = 1e15
WORLD = "world"


class ArticulationError(ValueError):
    """Why an articulated model cannot become a URDF robot (the caller names the model)."""


def _numbers(text: Optional[str], count: int, default: Sequence[float]) -> List[float]:
    if text is None or not text.strip():
        return list(default)
    values = [float(v) for v in text.split()]
    if len(values) != count or not all(math.isfinite(v) for v in values):
        raise ArticulationError(f"'{text}' is not {count} finite numbers")
    return values


def _pose_text(pose: Sequence[float]) -> Dict[str, str]:
    return {"xyz": " ".join(f"{v:.9g}" for v in pose[:3]),
            "rpy": " ".join(f"{v:.9g}" for v in pose[3:6])}


def _relative(frame: np.ndarray, pose: Sequence[float]) -> Pose6:
    """``pose`` (in the SDF link frame) in the URDF link frame ``frame`` (also in the SDF
    link frame)."""
    return matrix_pose6(np.linalg.inv(frame) @ pose6_matrix(pose))


def _geometry(parent: ET.Element, shape) -> bool:
    geometry = ET.SubElement(parent, "geometry")
    if shape.kind == "box":
        ET.SubElement(geometry, "box", size=" ".join(f"{v:.9g}" for v in shape.size))
    elif shape.kind == "cylinder":
        ET.SubElement(geometry, "cylinder", radius=f"{shape.radius:.9g}",
                      length=f"{shape.length:.9g}")
    elif shape.kind == "sphere":
        ET.SubElement(geometry, "sphere", radius=f"{shape.radius:.9g}")
    elif shape.kind == "mesh":
        ET.SubElement(geometry, "mesh", filename=shape.filename,
                      scale=" ".join(f"{v:.9g}" for v in shape.scale))
    else:  # a plane has no URDF geometry
        return False
    return True


def _link(robot: ET.Element, link, frame: np.ndarray) -> None:
    element = ET.SubElement(robot, "link", name=link.name)
    inertial = ET.SubElement(element, "inertial")
    ET.SubElement(inertial, "origin", _pose_text(_relative(frame, link.inertial_pose)))
    ET.SubElement(inertial, "mass", value=f"{max(link.mass, 1e-6):.9g}")
    ixx, iyy, izz = link.inertia
    ET.SubElement(inertial, "inertia", ixx=f"{ixx:.9g}", ixy="0", ixz="0", iyy=f"{iyy:.9g}",
                  iyz="0", izz=f"{izz:.9g}")
    for kind, shapes in (("visual", link.visuals), ("collision", link.collisions)):
        for shape in shapes:
            child = ET.Element(kind)
            ET.SubElement(child, "origin", _pose_text(_relative(frame, shape.pose)))
            if not _geometry(child, shape):
                continue
            if kind == "visual" and shape.rgba is not None:
                material = ET.SubElement(child, "material", name=f"{link.name}_colour")
                ET.SubElement(material, "color", rgba=" ".join(f"{v:.4g}" for v in shape.rgba))
            element.append(child)


class _Joint:
    def __init__(self, element: ET.Element, model: str):
        self.name = element.get("name", "")
        self.type = (element.get("type") or "").strip()
        self.parent = (element.findtext("parent") or "").strip()
        self.child = (element.findtext("child") or "").strip()
        what = f"joint '{self.name}'"
        if self.type not in JOINT_TYPES:
            raise ArticulationError(f"{what} is of type '{self.type}', which sim_bridge does "
                                    "not build (revolute, continuous, prismatic, fixed)")
        try:
            self.pose = tuple(_numbers(element.findtext("pose"), 6, (0.0,) * 6))
            axis = element.find("axis")
            xyz = axis.find("xyz") if axis is not None else None
            self.axis = np.array(_numbers(xyz.text if xyz is not None else None, 3, (0, 0, 1)))
            self.axis_in_model = axis is not None and (
                (axis.findtext("use_parent_model_frame") or "").strip().lower() in ("1", "true")
                or (xyz is not None and xyz.get("expressed_in") == "__model__"))
            limit = axis.find("limit") if axis is not None else None
            self.limit = {tag: float(limit.findtext(tag)) for tag in
                          ("lower", "upper", "effort", "velocity")
                          if limit is not None and limit.findtext(tag)}
            dynamics = axis.find("dynamics") if axis is not None else None
            self.dynamics = {tag: float(dynamics.findtext(tag)) for tag in ("damping", "friction")
                             if dynamics is not None and dynamics.findtext(tag)}
        except ValueError as error:
            raise ArticulationError(f"{what}: {error}") from None
        if not self.parent or not self.child:
            raise ArticulationError(f"{what} needs a <parent> and a <child>")
        if np.linalg.norm(self.axis) == 0:
            raise ArticulationError(f"{what}: <axis><xyz> is the zero vector")

    def urdf_type(self) -> str:
        if self.type == "revolute" and (
                not self.limit or (abs(self.limit.get("lower", -UNLIMITED)) >= UNLIMITED and
                                   abs(self.limit.get("upper", UNLIMITED)) >= UNLIMITED)):
            return "continuous"
        return JOINT_TYPES[self.type]


def to_urdf(model_element: ET.Element, spec) -> Tuple[str, Pose6]:
    """(URDF text, the root link's pose in the model's frame) of an articulated model;
    ``spec`` is its ModelSpec as sdf_world parsed it (links with their shapes)."""
    name = spec.name
    links = {link.name: link for link in spec.links}
    joints = [_Joint(element, name) for element in model_element.findall("joint")]
    for joint in joints:
        for end in (joint.parent, joint.child):
            if end != WORLD and end not in links:
                raise ArticulationError(f"joint '{joint.name}' names link '{end}', which the "
                                        "model does not have")
    children = {joint.child for joint in joints}
    roots = [link for link in links if link not in children]
    fixed_to_world = any(joint.parent == WORLD for joint in joints)
    if fixed_to_world:
        roots = [WORLD]
    if len(roots) != 1:
        raise ArticulationError(f"its links do not form one tree (roots: {', '.join(roots)})")
    robot = ET.Element("robot", name=name)
    frames: Dict[str, np.ndarray] = {}  # URDF link frame in the model frame
    gazebo_tags: List[ET.Element] = []
    root = roots[0]
    if root == WORLD:
        ET.SubElement(robot, "link", name=WORLD)
        frames[WORLD] = np.eye(4)
        root_pose: Pose6 = (0.0,) * 6
    else:
        frames[root] = pose6_matrix(links[root].pose)
        root_pose = links[root].pose
        _link(robot, links[root], np.eye(4))
    pending = list(joints)
    while pending:
        ready = [joint for joint in pending if joint.parent in frames]
        if not ready:
            raise ArticulationError("its joints form a loop or leave links unconnected")
        for joint in ready:
            pending.remove(joint)
            child = links[joint.child]
            child_sdf = pose6_matrix(child.pose)
            joint_frame = child_sdf @ pose6_matrix(joint.pose)  # in the model frame
            frames[joint.child] = joint_frame
            _link(robot, child, pose6_matrix(joint.pose))
            element = ET.SubElement(robot, "joint", name=joint.name, type=joint.urdf_type())
            ET.SubElement(element, "parent", link=joint.parent)
            ET.SubElement(element, "child", link=joint.child)
            ET.SubElement(element, "origin", _pose_text(matrix_pose6(
                np.linalg.inv(frames[joint.parent]) @ joint_frame)))
            if joint.urdf_type() != "fixed":
                axis = joint.axis / np.linalg.norm(joint.axis)
                if joint.axis_in_model:
                    axis = joint_frame[:3, :3].T @ axis
                ET.SubElement(element, "axis", xyz=" ".join(f"{v:.9g}" for v in axis))
                if joint.urdf_type() != "continuous":
                    ET.SubElement(element, "limit", lower=f"{joint.limit.get('lower', 0):.9g}",
                                  upper=f"{joint.limit.get('upper', 0):.9g}",
                                  effort=f"{joint.limit.get('effort', 0):.9g}",
                                  velocity=f"{joint.limit.get('velocity', 0):.9g}")
                if joint.dynamics:
                    ET.SubElement(element, "dynamics", {k: f"{v:.9g}"
                                                        for k, v in joint.dynamics.items()})
    # the model's plugins and its links' sensors, where a URDF robot keeps them
    for plugin in model_element.findall("plugin"):
        block = ET.Element("gazebo")
        block.append(plugin)
        gazebo_tags.append(block)
    for link in model_element.findall("link"):
        for sensor in link.findall("sensor"):
            block = ET.Element("gazebo", reference=link.get("name", ""))
            block.append(sensor)
            gazebo_tags.append(block)
    robot.extend(gazebo_tags)
    return ET.tostring(robot, encoding="unicode"), tuple(root_pose)

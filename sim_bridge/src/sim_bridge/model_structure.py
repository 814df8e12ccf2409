"""Gazebo's names for a model's parts: its links ("bodies"), joints and collisions.

Gazebo does not load a URDF as written: sdformat converts it first, and *lumps* every link
hanging on a fixed joint into its parent (recursively, so a chain of fixed joints ends in
one link): the child's collisions, visuals and mass move to the parent, and the child and
the fixed joint are gone. A robot whose root ``base_footprint`` carries ``base_link`` on a
fixed joint therefore has, in Gazebo, a link ``base_footprint`` and no link ``base_link``;
``get_link_state`` of ``robot::base_link`` fails there. A fixed joint is kept when its
``<gazebo reference="joint">`` says ``<preserveFixedJoint>true</preserveFixedJoint>`` (or
``<disableFixedJointLumping>true</disableFixedJointLumping>``), and a joint to a root link
named ``world`` is never lumped (it fixes the robot to the world).

pybullet keeps every URDF link; this module says which of them Gazebo's interface shows,
so that what runs on sim_bridge runs in Gazebo. Collision names are sdformat 9's (Gazebo
11's; gazebosim/sdformat sdf9 9ee2d4f src/parser_urdf.cc:2880-2901, :3168-3179): the URDF
collision's ``name``, or its link's name when it has none, then ``_collision``, then ``_1``,
``_2``... after the first of the Gazebo link; a name that does not begin with the Gazebo
link's own name is prefixed ``<link>_fixed_joint_lump__``: a lumped link's unnamed
collision is ``<link>_fixed_joint_lump__<its own link>_collision``, and so is a named one
anywhere (Kobuki's ``base`` on ``base_link`` lumped into ``base_footprint``:
``base_footprint_fixed_joint_lump__base_collision``). Links follow sdformat's order (the root
first, then depth first, children by joint name), joints the order of their child links.

An SDF model here is a list of links without joints (sim_bridge's SDF reader keeps no
collision names, so an SDF link's collisions are named as a URDF link's would be).
No pybullet, no rospy.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Dict, List, Mapping, Tuple

from sim_bridge.sdf_world import ModelSpec
from urdf_tools.model import Joint, RobotModel

LUMP_INFIX = "_fixed_joint_lump__"
WORLD_LINK = "world"
# <gazebo reference="joint"> tags that keep a fixed joint (and its child link)
KEEP_TAGS = ("preserveFixedJoint", "disableFixedJointLumping")


@dataclass(frozen=True)
class Structure:
    """A model as Gazebo's interface shows it."""

    bodies: Tuple[str, ...]  # Gazebo's links; the first is the canonical one
    joints: Tuple[str, ...] = ()
    geoms: Tuple[str, ...] = ()
    # every link of the description (world excepted) → the body holding it
    body_of: Mapping[str, str] = field(default_factory=dict)
    # a lumped link → the fixed joint that lumped it
    lumped_by: Mapping[str, str] = field(default_factory=dict)
    # a collision's name (as in geoms) → the description's link it is written in
    geom_links: Mapping[str, str] = field(default_factory=dict)

    @property
    def canonical(self) -> str:
        return self.bodies[0] if self.bodies else ""

    def links_of(self, body: str) -> List[str]:
        """The description's links that make up ``body`` (itself and what it lumps)."""
        return [link for link, holder in self.body_of.items() if holder == body]


def _true(text: str) -> bool:
    return text.strip().lower() in ("1", "true")


def is_lumped(model: RobotModel, joint: Joint) -> bool:
    """Whether sdformat merges ``joint``'s child link into its parent."""
    if joint.type != "fixed" or joint.parent == WORLD_LINK:
        return False
    properties = model.gazebo_properties(joint.name)
    return not any(_true(properties.get(tag, "")) for tag in KEEP_TAGS)


def _geom_names(body: str, sources: List[Tuple[str, str]]) -> List[str]:
    """sdformat's names of the collisions of ``body``, from (link, collision name) in its
    order (see the module's doc)."""
    names = []
    for index, (link, own) in enumerate(sources):
        name = f"{own or link}_collision" + (f"_{index}" if index else "")
        names.append(name if name.startswith(body) else f"{body}{LUMP_INFIX}{name}")
    return names


def urdf_structure(model: RobotModel) -> Structure:
    children: Dict[str, List[Joint]] = {}
    for joint in sorted(model.joints.values(), key=lambda j: j.name):
        children.setdefault(joint.parent, []).append(joint)
    bodies: List[str] = []
    joints: List[str] = []
    geoms: List[str] = []
    body_of: Dict[str, str] = {}
    lumped_by: Dict[str, str] = {}
    geom_links: Dict[str, str] = {}

    # Depth-first, as sdformat walks the tree, without recursion: a chain of a thousand
    # links (urdf_tools.model.MAX_LINKS) is deeper than Python's recursion limit.
    def gather(link: str) -> List[Joint]:
        """The body ``link`` starts: its lumped links' collisions in order; the joints to
        further bodies, in the order met."""
        sources: List[Tuple[str, str]] = []
        kept: List[Joint] = []
        stack: List = []

        def visit(member: str) -> None:
            body_of[member] = link
            sources.extend((member, shape.name) for shape in model.links[member].collisions)
            stack.append(iter(children.get(member, [])))

        visit(link)
        while stack:
            joint = next(stack[-1], None)
            if joint is None:
                stack.pop()
            elif is_lumped(model, joint):
                lumped_by[joint.child] = joint.name
                visit(joint.child)
            else:
                kept.append(joint)
        names = _geom_names(link, sources)
        geoms.extend(names)
        geom_links.update(zip(names, (member for member, _ in sources)))
        return kept

    def add_body(link: str) -> None:
        bodies.append(link)
        stack = [iter(gather(link))]
        while stack:
            joint = next(stack[-1], None)
            if joint is None:
                stack.pop()
                continue
            joints.append(joint.name)
            bodies.append(joint.child)
            stack.append(iter(gather(joint.child)))

    root = model.root()
    if root == WORLD_LINK:  # fixed (or jointed) to the world: world is no link of the model
        for joint in children.get(root, []):
            joints.append(joint.name)
            add_body(joint.child)
    else:
        add_body(root)
    return Structure(tuple(bodies), tuple(joints), tuple(geoms), body_of, lumped_by,
                     geom_links)


def sdf_structure(spec: ModelSpec) -> Structure:
    geoms: List[str] = []
    for link in spec.links:
        geoms.extend(_geom_names(link.name, [(link.name, "")] * len(link.collisions)))
    names = tuple(link.name for link in spec.links)
    return Structure(names, (), tuple(geoms), {name: name for name in names}, {})

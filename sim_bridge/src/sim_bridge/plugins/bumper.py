"""``<sensor type="contact">`` with ``libgazebo_ros_bumper.so``: what a collision touches,
gazebo_msgs/ContactsState.

From the sensor: ``<contact><collision>NAME</collision></contact>`` (one or more), Gazebo's
name of a collision (sdformat's: ``<link>_collision``, a lumped link's
``<parent>_fixed_joint_lump__<link>_collision``, a second one ``..._collision_1``), and
``<update_rate>`` (Hz of simulated time; every step when 0). From the plugin, with
gazebo_ros_bumper's defaults: ``bumperTopicName`` (bumper_states), ``frameName`` (world):
the header's frame alone, through tf::resolve with the tf_prefix. As Noetic's (gazebo_ros_pkgs
noetic-devel f9e1a46, gazebo_plugins/src/gazebo_ros_bumper.cpp:151), whose code to move the
contacts into the named link is commented out (:155-208): positions, normals and wrenches
are in the world's coordinates whatever it names.

One ContactState per pair of touching links, every update (an empty list when nothing
touches, as Gazebo publishes): the contact points, their normals (pointing at this
collision), depths (penetration, m), each point's wrench on this collision (the normal
force along the normal; pybullet's friction forces added; the torque about the world's
origin) and their sum.
Collision names are ``<model>::<link>::<collision>`` as Gazebo scopes them.
"""
from __future__ import annotations

from typing import Dict, List, Tuple

import numpy as np
import pybullet as pb
from gazebo_msgs.msg import ContactsState, ContactState
from geometry_msgs.msg import Vector3, Wrench

from sim_bridge.model_structure import LUMP_INFIX
from sim_bridge.plugins.base import Plugin, PluginError, Rate, stamp


def link_of_collision(name: str) -> str:
    """The description's link a Gazebo collision name comes from."""
    name = name.rpartition("::")[2]
    stem, marker, index = name.rpartition("_collision_")
    if marker and index.isdigit():
        name = f"{stem}_collision"
    name = name[: -len("_collision")] if name.endswith("_collision") else name
    return name.partition(LUMP_INFIX)[2] or name


class Bumper(Plugin):
    def __init__(self, context, spec, sensor):
        super().__init__(context, spec)
        robot = context.robot
        names = [(c.text or "").strip() for c in sensor.element.findall("contact/collision")]
        if not names:
            raise PluginError(f"sensor '{sensor.name}' of type contact needs "
                              "<contact><collision>, the name of a collision")
        self.collisions: Dict[int, str] = {}  # pybullet link → the collision's scoped name
        structure = context.structure
        for name in names:
            collision = name.rpartition("::")[2]
            # the model's own name for it (sdformat's, model_structure), else read from the
            # name's pattern (a model described without one)
            link = (structure.geom_links.get(collision) if structure is not None else None) \
                or link_of_collision(name)
            if link not in robot.link_index:
                raise PluginError(f"sensor '{sensor.name}': <collision> '{name}' is no "
                                  f"collision of model '{context.model_name}' (links: "
                                  f"{', '.join(sorted(robot.link_index))})")
            holder = structure.body_of.get(link, link) if structure is not None else \
                (collision.partition(LUMP_INFIX)[0] if LUMP_INFIX in collision else link)
            self.collisions[robot.link_index[link]] = \
                f"{context.model_name}::{holder}::{collision}"
        self.rate = Rate(_rate(sensor))
        # gazebo_plugins/src/gazebo_ros_bumper.cpp:95-101, :113-116: any name, world by
        # default, through tf::resolve; the header's only (:151): nothing is looked up
        self.frame_id = self.frame(self.param("frameName", "world"))
        self.output = context.bus.publisher(
            self.topic(self.param("bumperTopicName", "bumper_states")), ContactsState,
            queue_size=1)

    def contacts(self) -> List[ContactState]:
        """In the world's coordinates: gazebo_plugins/src/gazebo_ros_bumper.cpp:202-208 use
        the identity as the frame (the link's pose is commented out, :193-201)."""
        client, body = self.context.client, self.context.robot.id
        pairs: Dict[Tuple[int, int, int], ContactState] = {}
        for link, name in self.collisions.items():
            for point in pb.getContactPoints(bodyA=body, linkIndexA=link,
                                             physicsClientId=client):
                other, other_link = point[2], point[4]
                key = (link, other, other_link)
                state = pairs.get(key)
                if state is None:
                    state = pairs[key] = ContactState(
                        collision1_name=name,
                        collision2_name=self._collision_name(other, other_link))
                    state.info = f"{state.collision1_name} touches {state.collision2_name}"
                normal = np.asarray(point[7])  # on B, pointing at A: this collision
                force = point[9] * normal + point[10] * np.asarray(point[11]) \
                    + point[12] * np.asarray(point[13])
                world_point = np.asarray(point[5])
                state.contact_positions.append(Vector3(*world_point))
                state.contact_normals.append(Vector3(*normal))
                state.depths.append(max(0.0, -point[8]))
                torque = np.cross(world_point, force)
                state.wrenches.append(Wrench(force=Vector3(*force), torque=Vector3(*torque)))
        for state in pairs.values():
            state.total_wrench.force = Vector3(*np.sum([[w.force.x, w.force.y, w.force.z]
                                                        for w in state.wrenches], axis=0))
            state.total_wrench.torque = Vector3(*np.sum([[w.torque.x, w.torque.y, w.torque.z]
                                                         for w in state.wrenches], axis=0))
        return list(pairs.values())

    def _link_name(self, body: int, link: int) -> str:
        client = self.context.client
        if link < 0:
            return pb.getBodyInfo(body, physicsClientId=client)[0].decode()
        return pb.getJointInfo(body, link, physicsClientId=client)[12].decode()

    def _collision_name(self, body: int, link: int) -> str:
        client = self.context.client
        model = self.context.model_of_body(body) or \
            pb.getBodyInfo(body, physicsClientId=client)[1].decode()
        link_name = self._link_name(body, link) if link >= 0 else \
            (pb.getBodyInfo(body, physicsClientId=client)[0].decode() or "link")
        return f"{model}::{link_name}::{link_name}_collision"

    def quiet_until_ns(self, now_ns: int, step_ns: int) -> int:
        return self.rate.quiet_until_ns()  # after_step asks the rate first

    def after_step(self, now_ns: int) -> None:
        # nothing for nobody, as Noetic's OnContact (gazebo_ros_pkgs noetic-devel f9e1a46,
        # gazebo_plugins/src/gazebo_ros_bumper.cpp:142-143)
        if not self.rate.due(now_ns) or not self.context.bus.listened(self.output):
            return
        message = ContactsState(states=self.contacts())
        message.header.stamp = stamp(now_ns)
        message.header.frame_id = self.frame_id
        self.output.publish(message)


def _rate(sensor) -> float:
    text = (sensor.element.findtext("update_rate") or "").strip()
    try:
        return float(text) if text else 0.0
    except ValueError:
        raise PluginError(f"sensor '{sensor.name}': <update_rate> '{text}' is not a "
                          "number") from None

"""One simulator per name: a second one refuses to start instead of replacing the first.

ROS lets a node take a name another node holds: the master tells the first to shut down.
A user who starts a world launch file and then a robot's launch file that includes
empty_world.launch again (tutorials do, e.g. one launch per step) would see the first
simulator, with the world and the robot in it, replaced by an empty one whose /clock
starts again from 0. Gazebo's second gzserver fails instead (its port is taken: "There is
probably another Gazebo process running") and the first keeps running; so does this.
"""
from __future__ import annotations

import socket
import xmlrpc.client
from typing import Optional

import rosgraph
import rosgraph.names
import rospy.names

# how long (s) the node holding the name has to answer before it counts as gone
ANSWER_TIMEOUT = 2.0


def resolved_node_name(default: str) -> str:
    """The name rospy.init_node(``default``) will register: ``__name:=`` and the namespace
    (``__ns:=``, ROS_NAMESPACE) applied."""
    name = rospy.names.get_mappings().get("__name", default)
    return rosgraph.names.ns_join(rosgraph.names.get_ros_namespace(), name)


def live_node_uri(name: str) -> Optional[str]:
    """The XML-RPC URI of a node registered as ``name`` that answers, else None (none
    registered, a stale registration, or no master: init_node reports that itself)."""
    master = rosgraph.Master("/sim_bridge_name_check")
    try:
        uri = master.lookupNode(name)
    except (rosgraph.MasterError, OSError):
        return None
    previous = socket.getdefaulttimeout()
    socket.setdefaulttimeout(ANSWER_TIMEOUT)
    try:
        code, _, _ = xmlrpc.client.ServerProxy(uri).getPid("/sim_bridge_name_check")
        return uri if code == 1 else None
    except (OSError, xmlrpc.client.Error):
        return None
    finally:
        socket.setdefaulttimeout(previous)


def refusal(name: str) -> Optional[str]:
    """Why a simulator named ``name`` must not start now, or None."""
    uri = live_node_uri(name)
    if uri is None:
        return None
    return (f"a simulator is already running as {name} ({uri}); this one stops, as "
            "Gazebo's gzserver would ('There is probably another Gazebo process running'). "
            "Stop the other one first, or start this one in another namespace.")

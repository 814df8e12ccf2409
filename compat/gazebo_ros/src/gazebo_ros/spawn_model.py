"""``rosrun gazebo_ros spawn_model``: gazebo_ros's spawn_model, with its flags.

  -urdf | -sdf            the description's format
  -file FILE | -param P | -topic T | -database NAME | -stdin
                          where it is: a file, a parameter (robot_description), a latched
                          std_msgs/String topic, a model of the model path (model://NAME),
                          or standard input
  -model NAME             the model's name (required)
  -x -y -z -R -P -Y       initial pose (m, rad)
  -J JOINT VALUE          initial joint position (repeatable)
  -unpause                unpause physics once spawned
  -wait MODEL             wait until MODEL exists before spawning
  -robot_namespace NS     namespace of the model's plugins (default: this node's namespace)
  -reference_frame FRAME  the pose's frame ("" or "world" for the world)
  -gazebo_namespace NS    the simulator's namespace (/gazebo)
  -package_to_model       turn package:// mesh URIs into model:// ones
  -timeout SECONDS        how long to wait for the simulator, a parameter or a model (60)
  -b                      stay, and delete the model when this node stops
Exit status 0 once spawned; 1 with a message naming the cause otherwise.
"""
from __future__ import annotations

import argparse
import re
import socket
import sys
import time
from typing import List, Optional

import rosgraph
import rosgraph.network
import rospy
from geometry_msgs.msg import Pose
from std_msgs.msg import String
from std_srvs.srv import Empty
from tf.transformations import quaternion_from_euler

from gazebo_msgs.srv import (DeleteModel, GetWorldProperties, SetModelConfiguration,
                             SpawnModel)
from sim_bridge.stop_signals import StopSignals, shut_rospy_down

# What -database spawns: the model of that name from the model path, as upstream.
DATABASE_TEMPLATE = """<sdf version="1.4">
  <world name="default">
    <include>
      <uri>model://{}</uri>
    </include>
  </world>
</sdf>"""
# How often a waiting loop looks again (wall seconds).
POLL_PERIOD = 0.1
# How often the spawn service is looked up while the simulator starts (wall seconds): a
# lookup is one call to the master; rospy's wait_for_service looks every 0.3 s, which was
# most of the time from a launch's start to its robot's first scan.
SERVICE_POLL_PERIOD = 0.02
# How long a probe of the spawn service waits for the connection (wall seconds); on this
# machine a dead simulator's port refuses at once, a live one accepts in well under 1 ms.
PROBE_TIMEOUT = 1.0


class SpawnError(Exception):
    """A cause that stops the spawn, said to the user."""


def parse_arguments(argv: List[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="spawn_model", description=__doc__.split("\n")[0])
    kind = parser.add_mutually_exclusive_group(required=True)
    kind.add_argument("-urdf", action="store_true")
    kind.add_argument("-sdf", action="store_true")
    source = parser.add_mutually_exclusive_group(required=True)
    source.add_argument("-file")
    source.add_argument("-param")
    source.add_argument("-topic")
    source.add_argument("-database")
    source.add_argument("-stdin", action="store_true")
    parser.add_argument("-model", required=True)
    for axis in ("x", "y", "z", "R", "P", "Y"):
        parser.add_argument(f"-{axis}", type=float, default=0.0)
    parser.add_argument("-J", nargs=2, action="append", default=[], metavar=("JOINT", "VALUE"))
    parser.add_argument("-unpause", action="store_true")
    parser.add_argument("-wait", default="")
    parser.add_argument("-robot_namespace", default=None)
    parser.add_argument("-reference_frame", default="")
    parser.add_argument("-gazebo_namespace", default="/gazebo")
    parser.add_argument("-package_to_model", action="store_true")
    parser.add_argument("-timeout", type=float, default=60.0)
    parser.add_argument("-b", action="store_true")
    return parser.parse_args(argv)


def _wait(condition, what: str, timeout: float, period: float = POLL_PERIOD):
    """``condition()``'s first true value, polled every ``period`` until ``timeout`` wall
    seconds pass."""
    deadline = time.monotonic() + timeout
    while not rospy.is_shutdown():
        value = condition()
        if value:
            return value
        if time.monotonic() > deadline:
            raise SpawnError(f"{what} (waited {timeout:g} s)")
        time.sleep(period)
    raise SpawnError("shut down while waiting")


def service_answers(service: str) -> bool:
    """Whether ``service`` is registered at the master *and* takes a connection, as
    rospy.wait_for_service checks it: a simulator that was killed (SIGKILL, a crash, the OOM
    killer) never unregisters, and its stale registration answers ``lookupService`` until a
    new simulator registers the name again. A stale one is "not up yet", not a failure."""
    try:
        uri = rosgraph.Master(rospy.get_name()).lookupService(rospy.resolve_name(service))
    except (rosgraph.MasterError, OSError):  # not registered yet; the master unreachable
        return False
    try:
        address = rospy.core.parse_rosrpc_uri(uri)
    except rospy.ROSException:  # a malformed registration: not a service that answers
        return False
    try:
        with socket.create_connection(address, timeout=PROBE_TIMEOUT) as connection:
            # the probe header rospy sends: the server reads it and drops the connection
            rosgraph.network.write_ros_handshake_header(connection, {
                "probe": "1", "md5sum": "*", "callerid": rospy.get_name(),
                "service": rospy.resolve_name(service)})
        return True
    except OSError:  # refused (the process is gone), unreachable, or timed out
        return False


def read_description(args: argparse.Namespace) -> str:
    if args.file:
        try:
            with open(args.file, encoding="utf-8") as stream:
                xml = stream.read()
        except OSError as error:
            raise SpawnError(f"cannot read {args.file}: {error.strerror}") from None
        where = f"file {args.file}"
    elif args.param:
        xml = _wait(lambda: rospy.has_param(args.param) and str(rospy.get_param(args.param)),
                    f"parameter {args.param} is not set", args.timeout)
        where = f"parameter {args.param}"
    elif args.topic:
        received: List[str] = []
        rospy.Subscriber(args.topic, String, lambda message: received.append(message.data))
        xml = _wait(lambda: received and received[-1],
                    f"nothing was published on {args.topic}", args.timeout)
        where = f"topic {args.topic}"
    elif args.database:
        return DATABASE_TEMPLATE.format(args.database)
    else:
        xml = sys.stdin.read()
        where = "standard input"
    if not xml.strip():
        raise SpawnError(f"the {where} is empty")
    return xml


# a <mesh> element's filename="package://" (gazebo_ros noetic-devel f9e1a46
# scripts/spawn_model:155-163 rewrites these alone)
MESH_FILENAME = re.compile(r"""(<mesh\b[^>]*?\bfilename\s*=\s*["'])package://""")


def package_to_model(xml: str) -> str:
    """``<mesh filename="package://pkg/...">`` → ``model://pkg/...``, as upstream's
    -package_to_model: only mesh elements' filename attributes; any other ``package://``
    (an SDF ``<uri>``, a plugin's parameter, a texture) stays as written."""
    return MESH_FILENAME.sub(r"\1model://", xml)


def answering_proxy(service: str, kind, timeout: float) -> rospy.ServiceProxy:
    """A proxy of ``service`` once it answers (see service_answers): after a relaunch, the
    dead simulator's registrations of the other services may outlive the spawn service's."""
    _wait(lambda: service_answers(service), f"service {service} is not available", timeout,
          SERVICE_POLL_PERIOD)
    return rospy.ServiceProxy(service, kind)


def wait_for_model(namespace: str, model: str, timeout: float) -> None:
    properties = answering_proxy(f"{namespace}/get_world_properties", GetWorldProperties,
                                 timeout)
    _wait(lambda: model in properties().model_names,
          f"model '{model}' did not appear", timeout)


def initial_pose(args: argparse.Namespace) -> Pose:
    pose = Pose()
    pose.position.x, pose.position.y, pose.position.z = args.x, args.y, args.z
    pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w = \
        quaternion_from_euler(args.R, args.P, args.Y)
    return pose


def spawn(args: argparse.Namespace) -> None:
    namespace = args.gazebo_namespace.rstrip("/")
    try:
        joints = [(name, float(value)) for name, value in args.J]
    except ValueError:
        raise SpawnError("-J takes a joint name and a number") from None
    xml = read_description(args)
    if args.package_to_model:
        xml = package_to_model(xml)
    service = f"{namespace}/spawn_{'urdf' if args.urdf else 'sdf'}_model"
    try:
        spawner = answering_proxy(service, SpawnModel, args.timeout)
    except SpawnError:
        raise SpawnError(f"service {service} not available after {args.timeout:g} s; is the "
                         "simulator (gazebo_ros's empty_world.launch) running?") from None
    if args.wait:
        wait_for_model(namespace, args.wait, args.timeout)
    robot_namespace = rospy.get_namespace() if args.robot_namespace is None \
        else args.robot_namespace
    response = spawner(args.model, xml, robot_namespace, initial_pose(args),
                       args.reference_frame)
    if not response.success:
        raise SpawnError(response.status_message)
    rospy.loginfo(f"spawn_model: {response.status_message}")
    if joints:
        configured = answering_proxy(f"{namespace}/set_model_configuration",
                                     SetModelConfiguration, args.timeout)(
            args.model, "", [name for name, _ in joints], [value for _, value in joints])
        if not configured.success:
            raise SpawnError(configured.status_message)
    if args.unpause:
        answering_proxy(f"{namespace}/unpause_physics", Empty, args.timeout)()


def stay_then_delete(args: argparse.Namespace, stop: StopSignals) -> None:
    """-b: stay until Ctrl-C (or SIGTERM, as roslaunch sends), then delete the model. rospy's
    own signal handling is off for -b (sim_bridge.stop_signals says why), so that the node
    is still up to make that call; ``stop`` was installed before the spawn, so a Ctrl-C
    during it (while its log line still goes out) is not lost."""
    while not rospy.is_shutdown() and not stop.requested:
        time.sleep(POLL_PERIOD)
    try:
        rospy.ServiceProxy(f"{args.gazebo_namespace.rstrip('/')}/delete_model",
                           DeleteModel)(args.model)
    except (rospy.ServiceException, rospy.ROSException) as error:
        print(f"spawn_model: could not delete '{args.model}': {error}", file=sys.stderr)
    shut_rospy_down("spawn_model -b: stopped, model deleted")


def main(argv: Optional[List[str]] = None) -> int:
    arguments = rospy.myargv(argv if argv is not None else sys.argv)[1:]
    args = parse_arguments(arguments)
    rospy.init_node("spawn_model", anonymous=True, disable_signals=args.b)
    stop = StopSignals().install() if args.b else None
    try:
        spawn(args)
    except (SpawnError, rospy.ServiceException) as error:
        print(f"spawn_model: {error}", file=sys.stderr)
        return 1
    if args.b:
        stay_then_delete(args, stop)
    return 0

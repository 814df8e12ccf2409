"""``rosrun sim_bridge spawn_model``: gazebo_ros's spawn_model, with its flags.

  -urdf | -sdf            the description's format
  -file FILE | -param P   where it is (a file, or a parameter such as robot_description)
  -model NAME             the model's name (required)
  -x -y -z -R -P -Y       initial pose (m, rad)
  -J JOINT VALUE          initial joint position (repeatable)
  -unpause                unpause physics once spawned
  -wait MODEL             wait until MODEL exists before spawning
  -robot_namespace NS     namespace of the model's plugins
  -reference_frame FRAME  the pose's frame ("" for the world)
  -gazebo_namespace NS    the simulator's namespace (/gazebo)
  -timeout SECONDS        how long to wait for the simulator (60)
  -b                      stay, and delete the model when this node stops
Exit status 0 once spawned; 1 with a message naming the cause otherwise.
"""
from __future__ import annotations

import argparse
import sys
import time
from typing import List, Optional

import rospy
from geometry_msgs.msg import Pose
from std_srvs.srv import Empty

from sim_bridge.poses import quaternion_from_rpy
from sim_bridge.srv import (DeleteModel, GetWorldProperties, SetModelConfiguration,
                            SpawnModel)


def parse_arguments(argv: List[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="spawn_model", description=__doc__.split("\n")[0])
    kind = parser.add_mutually_exclusive_group(required=True)
    kind.add_argument("-urdf", action="store_true")
    kind.add_argument("-sdf", action="store_true")
    source = parser.add_mutually_exclusive_group(required=True)
    source.add_argument("-file")
    source.add_argument("-param")
    parser.add_argument("-model", required=True)
    for axis in ("x", "y", "z", "R", "P", "Y"):
        parser.add_argument(f"-{axis}", type=float, default=0.0)
    parser.add_argument("-J", nargs=2, action="append", default=[], metavar=("JOINT", "VALUE"))
    parser.add_argument("-unpause", action="store_true")
    parser.add_argument("-wait", default="")
    parser.add_argument("-robot_namespace", default="")
    parser.add_argument("-reference_frame", default="")
    parser.add_argument("-gazebo_namespace", default="/gazebo")
    parser.add_argument("-timeout", type=float, default=60.0)
    parser.add_argument("-b", action="store_true")
    return parser.parse_args(argv)


def read_description(args: argparse.Namespace) -> str:
    if args.file:
        try:
            with open(args.file, encoding="utf-8") as stream:
                return stream.read()
        except OSError as error:
            raise SystemExit(f"spawn_model: cannot read {args.file}: {error.strerror}")
    deadline = time.monotonic() + args.timeout
    while not rospy.is_shutdown():
        if rospy.has_param(args.param):
            return rospy.get_param(args.param)
        if time.monotonic() > deadline:
            raise SystemExit(f"spawn_model: parameter {args.param} is not set "
                             f"(waited {args.timeout:g} s)")
        time.sleep(0.1)
    raise SystemExit(1)


def wait_for_model(namespace: str, model: str, timeout: float) -> None:
    properties = rospy.ServiceProxy(f"{namespace}/get_world_properties", GetWorldProperties)
    deadline = time.monotonic() + timeout
    while not rospy.is_shutdown():
        if model in properties().model_names:
            return
        if time.monotonic() > deadline:
            raise SystemExit(f"spawn_model: model '{model}' did not appear within {timeout:g} s")
        time.sleep(0.2)


def main(argv: Optional[List[str]] = None) -> int:
    arguments = rospy.myargv(argv if argv is not None else sys.argv)[1:]
    args = parse_arguments(arguments)
    rospy.init_node("spawn_model", anonymous=True)
    namespace = args.gazebo_namespace.rstrip("/")
    xml = read_description(args)
    service = f"{namespace}/spawn_{'urdf' if args.urdf else 'sdf'}_model"
    try:
        rospy.wait_for_service(service, timeout=args.timeout)
    except rospy.ROSException:
        print(f"spawn_model: service {service} not available after {args.timeout:g} s; is "
              "sim_bridge running?", file=sys.stderr)
        return 1
    if args.wait:
        wait_for_model(namespace, args.wait, args.timeout)
    pose = Pose()
    pose.position.x, pose.position.y, pose.position.z = args.x, args.y, args.z
    pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w = \
        quaternion_from_rpy(args.R, args.P, args.Y)
    response = rospy.ServiceProxy(service, SpawnModel)(
        args.model, xml, args.robot_namespace, pose, args.reference_frame)
    if not response.success:
        print(f"spawn_model: {response.status_message}", file=sys.stderr)
        return 1
    print(f"spawn_model: {response.status_message}")
    if args.J:
        try:
            positions = [float(value) for _, value in args.J]
        except ValueError:
            print("spawn_model: -J takes a joint name and a number", file=sys.stderr)
            return 1
        configured = rospy.ServiceProxy(f"{namespace}/set_model_configuration",
                                        SetModelConfiguration)(
            args.model, "", [name for name, _ in args.J], positions)
        if not configured.success:
            print(f"spawn_model: {configured.status_message}", file=sys.stderr)
            return 1
    if args.unpause:
        rospy.ServiceProxy(f"{namespace}/unpause_physics", Empty)()
    if args.b:
        rospy.spin()
        try:
            rospy.ServiceProxy(f"{namespace}/delete_model", DeleteModel)(args.model)
        except rospy.ServiceException:
            pass
    return 0

"""``rosrun controller_manager controller_manager COMMAND [NAME...]``:
list | load | unload | start | stop | spawn | kill, against ``controller_manager`` in this
node's namespace (or ``--namespace``)."""
from __future__ import annotations

import argparse
import sys

import rospy

from controller_manager.services import ControllerManager

COMMANDS = ("list", "load", "unload", "start", "stop", "spawn", "kill")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="controller_manager", description=__doc__.split("\n")[0])
    parser.add_argument("command", choices=COMMANDS)
    parser.add_argument("controllers", nargs="*")
    parser.add_argument("--namespace", default="")
    args = parser.parse_args(rospy.myargv(argv if argv is not None else sys.argv)[1:])
    rospy.init_node("controller_manager_cli", anonymous=True)
    manager = ControllerManager(args.namespace)
    if not manager.wait(10.0):
        print(f"controller_manager: {manager.load_service} is not available", file=sys.stderr)
        return 1
    if args.command == "list":
        for state in manager.list().controller:
            print(f"{state.name} - {state.type} ( {state.state} )")
        return 0
    ok = True
    if args.command in ("load", "spawn"):
        ok = all(manager.load(name).ok for name in args.controllers)
    if ok and args.command in ("start", "spawn"):
        ok = manager.start(args.controllers)
    if args.command in ("stop", "kill"):
        ok = manager.stop(args.controllers)
    if ok and args.command in ("unload", "kill"):
        ok = all(manager.unload(name).ok for name in args.controllers)
    if not ok:
        print(f"controller_manager: {args.command} {args.controllers} failed (the simulator's "
              "log says why)", file=sys.stderr)
    return 0 if ok else 1

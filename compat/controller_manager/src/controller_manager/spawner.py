"""``rosrun controller_manager spawner [options] NAME...``: loads and starts controllers,
and stops and unloads them when it is shut down (as ros_control's spawner).

  --stopped              load only, do not start
  --namespace NS         the controller manager's namespace (default: this node's)
  --timeout SECONDS      how long to wait for the controller manager (30; 0 = forever)
  --shutdown-timeout S   accepted
Exit status 1 with a message when a controller cannot be loaded or started.
"""
from __future__ import annotations

import argparse
import sys

import rospy

from controller_manager.services import ControllerManager


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="spawner", description=__doc__.split("\n")[0])
    parser.add_argument("controllers", nargs="+")
    parser.add_argument("--stopped", action="store_true")
    parser.add_argument("--namespace", default="")
    parser.add_argument("--timeout", type=float, default=30.0)
    parser.add_argument("--shutdown-timeout", type=float, default=30.0)
    parser.add_argument("--wait-for", default="")
    args = parser.parse_args(rospy.myargv(argv if argv is not None else sys.argv)[1:])
    rospy.init_node("spawner", anonymous=True)
    manager = ControllerManager(args.namespace)
    if not manager.wait(args.timeout):
        rospy.logerr(f"spawner: {manager.load_service} did not appear within {args.timeout:g} s; "
                     "does the robot have libgazebo_ros_control.so, in this namespace?")
        return 1
    loaded = []
    for name in args.controllers:
        if not manager.load(name).ok:
            rospy.logerr(f"spawner: could not load controller '{name}' (the simulator's log "
                         "says why)")
            return 1
        loaded.append(name)
    if not args.stopped and not manager.start(loaded):
        rospy.logerr(f"spawner: could not start {loaded} (the simulator's log says why)")
        return 1
    rospy.loginfo(f"spawner: {'loaded' if args.stopped else 'started'} {', '.join(loaded)}")

    def unload():
        try:
            manager.stop(loaded)
            for name in loaded:
                manager.unload(name)
        except (rospy.ServiceException, rospy.ROSException):
            pass  # the simulator is gone already
    rospy.on_shutdown(unload)
    rospy.spin()
    return 0

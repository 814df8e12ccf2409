#!/usr/bin/env python3
"""make bench's Python MoveIt client (moveit_cost.py), the twin of moveit_ros_planning_interface's
plan_timing (C++): MoveGroupCommander.plan() to the group's named targets in turn, each
timed from the call to its answer, beside the planning time move_group reports; one JSON
line per plan. Private parameters as the C++ node's: ~group, ~targets, ~count."""
import json
import sys
import time

import moveit_commander
import rospy

DEFAULT_COUNT = 40


def main() -> int:
    moveit_commander.roscpp_initialize(sys.argv)
    rospy.init_node("plan_timing_py")
    group = rospy.get_param("~group", "interbotix_arm")
    count = int(rospy.get_param("~count", DEFAULT_COUNT))
    targets = rospy.get_param("~targets", [])
    if not targets:
        rospy.logfatal("plan_timing: ~targets (a list of the group's named targets) is not set")
        return 1
    move_group = moveit_commander.MoveGroupCommander(group)
    for i in range(count):
        move_group.set_named_target(targets[i % len(targets)])
        began = time.perf_counter()
        planned, _, planning_time, _ = move_group.plan()
        wall = time.perf_counter() - began
        print(json.dumps({"wall_ms": 1000 * wall, "planning_ms": 1000 * planning_time,
                          "planned": bool(planned)}), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

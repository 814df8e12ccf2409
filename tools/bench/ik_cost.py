"""Inverse kinematics figures for ``make bench``: move_group's compute_ik (its own function,
in this process: no master) on the FK poses of 200 random collision-free states of a 4-, a
5- and a 6-joint Interbotix arm (px100, wx200, wx250s with Interbotix's kinematics.yaml),
seeded at the default state, collision-aware, 0.1 s a request: wall ms per solve (median,
95th percentile) and the share solved. The same round trip is a unit test
(compat/moveit_ros_move_group/test/unit/test_ik_round_trip_services.py)."""
from __future__ import annotations

import os
import time
from typing import Dict

import numpy as np

ARMS = ("px100", "wx200", "wx250s")
STATES = 200
TIMEOUT = 0.1       # s a request


def _context(model_name: str):
    import rospkg
    import yaml
    from moveit_ros_move_group.context import from_parameters
    from urdf_tools.xacro_loader import expand
    packages = rospkg.RosPack()
    moveit = packages.get_path("interbotix_xsarm_moveit")
    with open(os.path.join(moveit, "config", "kinematics.yaml"), encoding="utf-8") as stream:
        kinematics = yaml.safe_load(stream)
    values = {
        "robot_description": expand(os.path.join(
            packages.get_path("interbotix_xsarm_descriptions"), "urdf",
            f"{model_name}.urdf.xacro"), {"robot_name": model_name}),
        "robot_description_semantic": expand(os.path.join(
            moveit, "config", "srdf", f"{model_name}.srdf.xacro"), {"robot_name": model_name}),
        "robot_description_kinematics": kinematics}
    return from_parameters(lambda name: values[name])


def measure_arm(model_name: str) -> Dict[str, float]:
    import rospy
    from moveit_msgs.msg import MoveItErrorCodes
    from moveit_msgs.srv import GetPositionIKRequest
    from moveit_core.planning_scene import PlanningScene
    from moveit_ros_move_group import kinematics_service
    from moveit_ros_move_group.conversions import matrix_pose
    context = _context(model_name)
    scene = PlanningScene(context.model)

    class Monitor:  # what the service reads of move_group's scene monitor
        @staticmethod
        def snapshot():
            return scene

    solver = context.solver("interbotix_arm")
    rng = np.random.default_rng(5)
    start = context.model.default_positions()
    seconds, solved = [], 0
    while len(seconds) < STATES:
        state = dict(start, **{j: rng.uniform(context.model.bounds[j].lower,
                                              context.model.bounds[j].upper)
                               for j in solver.joints})
        if scene.contacts(state, "interbotix_arm"):
            continue
        request = GetPositionIKRequest()
        request.ik_request.group_name = "interbotix_arm"
        request.ik_request.avoid_collisions = True
        request.ik_request.timeout = rospy.Duration(TIMEOUT)
        request.ik_request.pose_stamped.header.frame_id = context.model.model_frame
        request.ik_request.pose_stamped.pose = matrix_pose(
            context.model.link_poses(state)[solver.tip])
        began = time.monotonic()
        answer = kinematics_service.compute_ik(context, request, Monitor)
        seconds.append(time.monotonic() - began)
        solved += answer.error_code.val == MoveItErrorCodes.SUCCESS
    return {"joints": len(solver.joints), "median": 1000 * float(np.median(seconds)),
            "p95": 1000 * float(np.percentile(seconds, 95)), "solved": 100.0 * solved / STATES}


def measure() -> Dict[str, Dict[str, float]]:
    return {name: measure_arm(name) for name in ARMS}


if __name__ == "__main__":
    for arm, figures in measure().items():
        print(arm, {k: round(v, 2) for k, v in figures.items()})

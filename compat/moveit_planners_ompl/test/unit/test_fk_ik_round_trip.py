"""FK -> IK round trip of pose goals (issue 32), at the planner's goal sampling: for random
collision-free states within the bounds, the pose their forward kinematics gives (position
and orientation of the group's tip) is sampled back as a goal state, with the goal
constraints moveit_commander's set_pose_target writes (a 0.1 mm sphere, 1e-3 rad about each
axis), on the 4-joint px100 and a 6-joint arm, position_only_ik false. A state in
self-collision is no goal MoveIt would take either, so the states are drawn free."""
import math
import os
import time

import numpy as np
import pytest
from geometry_msgs.msg import Pose, Quaternion
from moveit_msgs.msg import Constraints, OrientationConstraint, PositionConstraint
from shape_msgs.msg import SolidPrimitive
from tf import transformations

from moveit_core import robot_model
from moveit_core.planning_scene import PlanningScene
from moveit_kinematics.kdl_solver import KdlSolver, SolverSettings
from moveit_planners_ompl.goals import pose_goals, satisfied

DATA = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))), "moveit_core", "test", "data")
STATES = 200           # random collision-free states per arm
DRAWS = 2000           # states drawn at most to find them
# s: the goal sampling's deadline per pose: the planning time a MoveGroupInterface
# (moveit_commander) allows by default (DEFAULT_ALLOWED_PLANNING_TIME,
# move_group_interface.cpp, noetic-devel); a pose at a 6-axis arm's wrist singularity, free
# on one branch only, takes some 0.5 s
GOAL_TIME = 5.0
POSITION_TOLERANCE = 1e-4       # m: moveit_commander's goal_position_tolerance
ORIENTATION_TOLERANCE = 1e-3    # rad: its goal_orientation_tolerance
ARMS = [("px100", "interbotix_arm", "px100/ee_gripper_link"),
        ("six_axis_arm", "manipulator", "tool0")]


def pose_constraints(link: str, pose: np.ndarray) -> Constraints:
    """As moveit_commander's set_pose_target: a sphere about the position, the orientation
    within its tolerance about each axis, in the world frame."""
    position = PositionConstraint(link_name=link, weight=1.0)
    position.header.frame_id = "world"
    position.constraint_region.primitives = [
        SolidPrimitive(type=SolidPrimitive.SPHERE, dimensions=[POSITION_TOLERANCE])]
    centre = Pose()
    centre.position.x, centre.position.y, centre.position.z = pose[:3, 3]
    centre.orientation.w = 1.0
    position.constraint_region.primitive_poses = [centre]
    orientation = OrientationConstraint(
        link_name=link, weight=1.0, absolute_x_axis_tolerance=ORIENTATION_TOLERANCE,
        absolute_y_axis_tolerance=ORIENTATION_TOLERANCE,
        absolute_z_axis_tolerance=ORIENTATION_TOLERANCE,
        orientation=Quaternion(*transformations.quaternion_from_matrix(pose)))
    orientation.header.frame_id = "world"
    return Constraints(position_constraints=[position], orientation_constraints=[orientation])


@pytest.mark.parametrize("name, group, tip", ARMS)
def test_every_reachable_pose_is_solved(name, group, tip):
    with open(os.path.join(DATA, f"{name}.urdf"), encoding="utf-8") as urdf, \
            open(os.path.join(DATA, f"{name}.srdf"), encoding="utf-8") as srdf:
        model = robot_model.load(urdf.read(), srdf.read(), {})
    scene = PlanningScene(model)
    solver = KdlSolver(model, group, SolverSettings(kinematics_solver_timeout=0.005), seed=1)
    rng = np.random.default_rng(1)
    start = model.default_positions()
    unsolved, seconds, draws = [], [], 0
    while len(seconds) < STATES:
        draws += 1
        assert draws <= DRAWS, f"{name}: fewer than {STATES} collision-free states in {DRAWS}"
        state = dict(start, **{j: rng.uniform(*(
            (model.bounds[j].lower, model.bounds[j].upper) if model.bounds[j].bounded
            else (-math.pi, math.pi))) for j in solver.joints})
        if scene.contacts(state, group):
            continue
        constraints = pose_constraints(tip, model.link_poses(state)[tip])
        began = time.monotonic()
        goals = pose_goals(scene, group, start, constraints, solver,
                           time.monotonic() + GOAL_TIME, rng, wanted=1)
        seconds.append(time.monotonic() - began)
        if not goals.states:
            unsolved.append({j: round(state[j], 4) for j in solver.joints})
        else:
            assert satisfied(scene, goals.states[0], constraints) is None
    print(f"{name}: {STATES - len(unsolved)} of {STATES} solved; median "
          f"{1000 * np.median(seconds):.1f} ms, 95th percentile "
          f"{1000 * np.percentile(seconds, 95):.1f} ms")
    assert unsolved == [], f"{name}: poses of these states not solved: {unsolved}"

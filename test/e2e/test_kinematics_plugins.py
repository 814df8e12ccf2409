"""C++ kinematics plugins in move_group, as a user's IKFast plugin package is used: the
fixture six_axis_arm_ikfast_manipulator_plugin (test/fixtures/moveit_ws: the files IKFast's
generator writes, include/ikfast.h, a closed-form solver for six_axis_arm's manipulator and an
ikfast_kinematics_plugin::IKFastKinematicsPlugin exported for pluginlib) is built in an
overlay beside six_axis_arm_moveit_config, and its demo.launch runs the config's demo with
the plugin named in robot_description_kinematics.

- move_group's log names the plugin loaded; 100 compute_ik requests for the tool poses of
  random states (urdf_tools' forward kinematics, apart from the plugin's) are each answered
  by the plugin (its log line per solved request) with joints whose forward kinematics is
  the pose to 1e-6 m and 1e-6 rad; a collision-aware request (the scene's check as the
  plugin's solution callback), a pose goal and a Cartesian path are solved through it.
- the same plugin in a C++ client (six_axis_arm_demo's ik_round_trip node, built in the same
  overlay): robot_model_loader::RobotModelLoader gives the group the IKFast plugin (its class,
  base and tip, kinematics.yaml's timeout), 50 RobotState::setFromIK
  round trips and MoveGroupInterface::setJointValueTarget(pose) are solved by it in the node's
  process (the plugin's lines in the node's log grow by exactly those requests, move_group's do
  not), each answer's forward kinematics (urdf_tools) the pose to 1e-6 m and 1e-6 rad.
- a kinematics.yaml naming a plugin that is not installed: move_group says why and solves
  with KDL; a plugin whose initialize() refuses the group (a tip it was not written for):
  the same, with that reason.
"""
import math
import os
import shutil
import subprocess
import sys

import numpy as np
import pytest
import yaml

import headless
from urdf_tools import load_urdf
from urdf_tools.kinematics import link_transform

FIXTURE = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                       "fixtures", "moveit_ws", "src")
PACKAGES = ("six_axis_arm_description", "six_axis_arm_moveit_config",
            "six_axis_arm_ikfast_manipulator_plugin", "six_axis_arm_demo")
IKFAST = "six_axis_arm_manipulator/IKFastKinematicsPlugin"
MISSING = "six_axis_arm_gripper/IKFastKinematicsPlugin"
JOINTS = ["shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint", "wrist_1_joint",
          "wrist_2_joint", "wrist_3_joint"]
ROUND_TRIPS = 100
SAME_POSE = 1e-6           # m and rad: a closed-form solver's answer
REACHED_METRES, REACHED_RADIANS = 0.001, 0.01   # a planned pose goal's last point
SOLVED_LINE = "IKFast request"   # the fixture plugin's line per solved request
BUILD_LIMIT = 600.0
START_LIMIT = 60.0
LOG_LIMIT = 10.0           # s for lines already written to reach the log file
SERVICE_LIMIT = 30.0
IK_TIMEOUT = 0.05          # s per compute_ik request
PLANNING_TIME = 5.0        # s for the pose goal
SUCCESS = 1                # moveit_msgs/MoveItErrorCodes
READY = [0.0, 0.4, 0.8, 0.3, 0.5, 0.0]   # the config's "ready" (collision-free)
CARTESIAN_DROP = 0.05      # m: the Cartesian path's straight line down
CARTESIAN_STEP = 0.01      # m: its max_step
CPP_ROUND_TRIPS = 50       # the C++ node's setFromIK round trips
CPP_NODE_LIMIT = 120.0     # s for the C++ node's run
# the class IKFast's generated plugin defines
IKFAST_CLASS = "ikfast_kinematics_plugin::IKFastKinematicsPlugin"


@pytest.fixture(scope="module")
def overlay(tmp_path_factory):
    """The fixture's config and plugin packages built with catkin_make on this workspace."""
    workspace = tmp_path_factory.mktemp("kinematics_ws")
    for package in PACKAGES:
        shutil.copytree(os.path.join(FIXTURE, package), workspace / "src" / package)
    build = subprocess.run(["catkin_make", "-C", str(workspace),
                            "-DPYTHON_EXECUTABLE=/usr/bin/python3"], cwd=workspace,
                           capture_output=True, text=True, timeout=BUILD_LIMIT, check=False)
    assert build.returncode == 0, build.stdout[-3000:] + build.stderr[-3000:]
    sourced = subprocess.run(["bash", "-c", "source devel/setup.bash && env -0"],
                             cwd=workspace, capture_output=True, text=True, check=True)
    return workspace, dict(line.split("=", 1) for line in sourced.stdout.split("\0")
                           if "=" in line)


def environment(overlay_env, ros_env):
    env = dict(overlay_env, ROS_MASTER_URI=ros_env["ROS_MASTER_URI"],
               ROS_HOME=ros_env["ROS_HOME"])
    env.pop("DISPLAY", None)
    return env


def started(launch):
    assert launch.running(), launch.output()[-3000:]
    return "You can start planning now!" in launch.output()


def rotation_angle(a, b):
    turn = a[:3, :3].T @ b[:3, :3]
    return math.acos(max(-1.0, min(1.0, (np.trace(turn) - 1) / 2)))


def pose_message(matrix):
    from geometry_msgs.msg import Pose
    from tf.transformations import quaternion_from_matrix
    pose = Pose()
    pose.position.x, pose.position.y, pose.position.z = (float(v) for v in matrix[:3, 3])
    (pose.orientation.x, pose.orientation.y, pose.orientation.z,
     pose.orientation.w) = (float(v) for v in quaternion_from_matrix(matrix))
    return pose


def random_states(urdf, count, seed):
    rng = np.random.default_rng(seed)
    limits = [(urdf.joints[j].limit.lower, urdf.joints[j].limit.upper) for j in JOINTS]
    return [[rng.uniform(lower, upper) for lower, upper in limits] for _ in range(count)]


def tool_pose(urdf, joints):
    return link_transform(urdf, "base_link", "tool0", dict(zip(JOINTS, joints)))


def compute_ik(service, matrix, seed, avoid_collisions=False):
    """compute_ik for the tool at ``matrix`` (base_link); the group's joints or None."""
    from moveit_msgs.msg import PositionIKRequest
    import rospy
    request = PositionIKRequest()
    request.group_name = "manipulator"
    request.robot_state.joint_state.name = JOINTS
    request.robot_state.joint_state.position = seed
    request.avoid_collisions = avoid_collisions
    request.pose_stamped.header.frame_id = "base_link"
    request.pose_stamped.pose = pose_message(matrix)
    request.timeout = rospy.Duration(IK_TIMEOUT)
    response = service(request)
    if response.error_code.val != SUCCESS:
        return None
    names = list(response.solution.joint_state.name)
    return [response.solution.joint_state.position[names.index(j)] for j in JOINTS]


def pose_goal_request(matrix):
    """A planning request for the tool at ``matrix``, as MoveIt's constructGoalConstraints
    builds it (a 1e-3 m sphere, 1e-3 rad about each axis)."""
    from moveit_msgs.msg import (Constraints, MotionPlanRequest, OrientationConstraint,
                                 PositionConstraint)
    from shape_msgs.msg import SolidPrimitive
    request = MotionPlanRequest()
    request.group_name = "manipulator"
    request.num_planning_attempts = 1
    request.allowed_planning_time = PLANNING_TIME
    request.start_state.joint_state.name = JOINTS
    request.start_state.joint_state.position = READY
    position = PositionConstraint()
    position.header.frame_id = "base_link"
    position.link_name = "tool0"
    sphere = SolidPrimitive(type=SolidPrimitive.SPHERE, dimensions=[1e-3])
    position.constraint_region.primitives.append(sphere)
    position.constraint_region.primitive_poses.append(pose_message(matrix))
    position.weight = 1.0
    orientation = OrientationConstraint()
    orientation.header.frame_id = "base_link"
    orientation.link_name = "tool0"
    orientation.orientation = pose_message(matrix).orientation
    orientation.absolute_x_axis_tolerance = orientation.absolute_y_axis_tolerance = \
        orientation.absolute_z_axis_tolerance = 1e-3
    orientation.weight = 1.0
    request.goal_constraints.append(Constraints(position_constraints=[position],
                                                orientation_constraints=[orientation]))
    return request


def cartesian_request(start, end):
    """A straight line of the tool from its pose at ``start`` to ``end`` (base_link)."""
    from moveit_msgs.srv import GetCartesianPathRequest
    request = GetCartesianPathRequest()
    request.header.frame_id = "base_link"
    request.group_name = "manipulator"
    request.link_name = "tool0"
    request.start_state.joint_state.name = JOINTS
    request.start_state.joint_state.position = start
    request.waypoints = [pose_message(end)]
    request.max_step = CARTESIAN_STEP
    request.jump_threshold = 0.0
    request.avoid_collisions = True
    return request


def solved_lines(launch):
    return launch.output().count(SOLVED_LINE)


def test_move_group_answers_ik_and_pose_goals_with_the_ikfast_plugin(overlay, ros_env,
                                                                      results_dir, monkeypatch):
    workspace, overlay_env = overlay
    env = environment(overlay_env, ros_env)
    monkeypatch.setenv("ROS_MASTER_URI", env["ROS_MASTER_URI"])
    import rospy
    from moveit_msgs.srv import GetCartesianPath, GetMotionPlan, GetPositionIK
    urdf = load_urdf(str(workspace / "src" / "six_axis_arm_description" / "urdf" /
                         "six_axis_arm.urdf"))
    with headless.roslaunch(["six_axis_arm_ikfast_manipulator_plugin", "demo.launch",
                             "use_rviz:=false"], env,
                            os.path.join(results_dir, "demo_ikfast.log")) as launch:
        headless.wait_until(lambda: started(launch), START_LIMIT, "move_group")
        output = launch.output()
        assert f"group 'manipulator': kinematics solver '{IKFAST}' loaded" in output
        assert "solving with KDL" not in output
        rospy.wait_for_service("/compute_ik", SERVICE_LIMIT)
        service = rospy.ServiceProxy("/compute_ik", GetPositionIK)
        before = solved_lines(launch)
        worst_metres = worst_radians = 0.0
        for state in random_states(urdf, ROUND_TRIPS, seed=34):
            wanted = tool_pose(urdf, state)
            solution = compute_ik(service, wanted, [0.0] * len(JOINTS))
            assert solution is not None, f"no IK for the tool pose of {state}"
            reached = tool_pose(urdf, solution)
            worst_metres = max(worst_metres, float(np.linalg.norm(reached[:3, 3] -
                                                                  wanted[:3, 3])))
            worst_radians = max(worst_radians, rotation_angle(reached, wanted))
        assert worst_metres <= SAME_POSE and worst_radians <= SAME_POSE, \
            (worst_metres, worst_radians)
        # each request was the plugin's
        headless.wait_until(lambda: solved_lines(launch) >= before + ROUND_TRIPS, LOG_LIMIT,
                            f"{ROUND_TRIPS} '{SOLVED_LINE}' lines in move_group's log")

        before = solved_lines(launch)
        goal = tool_pose(urdf, [0.5, -0.3, 1.2, 0.4, -0.6, 0.3])
        planner = rospy.ServiceProxy("/plan_kinematic_path", GetMotionPlan)
        response = planner(pose_goal_request(goal)).motion_plan_response
        assert response.error_code.val == SUCCESS, response.error_code.val
        trajectory = response.trajectory.joint_trajectory
        last = dict(zip(trajectory.joint_names, trajectory.points[-1].positions))
        reached = tool_pose(urdf, [last[j] for j in JOINTS])
        assert np.linalg.norm(reached[:3, 3] - goal[:3, 3]) <= REACHED_METRES
        assert rotation_angle(reached, goal) <= REACHED_RADIANS
        headless.wait_until(lambda: solved_lines(launch) > before, LOG_LIMIT,
                            "the pose goal's IK by the plugin in move_group's log")

        # collision-aware IK: move_group's scene check is the plugin's solution callback
        before = solved_lines(launch)
        wanted = tool_pose(urdf, READY)
        solution = compute_ik(service, wanted, [0.0] * len(JOINTS), avoid_collisions=True)
        assert solution is not None
        reached = tool_pose(urdf, solution)
        assert np.linalg.norm(reached[:3, 3] - wanted[:3, 3]) <= SAME_POSE
        assert rotation_angle(reached, wanted) <= SAME_POSE

        # a Cartesian path: each step's IK by the plugin, nearest the step before
        end = wanted.copy()
        end[2, 3] -= CARTESIAN_DROP
        cartesian = rospy.ServiceProxy("/compute_cartesian_path", GetCartesianPath)
        path = cartesian(cartesian_request(READY, end))
        assert path.error_code.val == SUCCESS and path.fraction == pytest.approx(1.0)
        points = path.solution.joint_trajectory.points
        names = list(path.solution.joint_trajectory.joint_names)
        last = tool_pose(urdf, [points[-1].positions[names.index(j)] for j in JOINTS])
        assert np.linalg.norm(last[:3, 3] - end[:3, 3]) <= SAME_POSE
        assert rotation_angle(last, end) <= SAME_POSE
        steps = round(CARTESIAN_DROP / CARTESIAN_STEP)
        headless.wait_until(lambda: solved_lines(launch) >= before + 1 + steps, LOG_LIMIT,
                            "the IK of each Cartesian step by the plugin in move_group's log")

        # the same plugin in a C++ client, loaded by its RobotModelLoader
        in_move_group = solved_lines(launch)
        check_cpp_client(workspace, env, urdf)
        assert solved_lines(launch) == in_move_group, "the C++ client's IK was move_group's"


def values_after(words, label, count):
    start = words.index(label) + 1
    return [float(v) for v in words[start:start + count]]


def check_cpp_client(workspace, env, urdf):
    """six_axis_arm_demo's ik_round_trip against the running demo (see the module)."""
    node = subprocess.run(["rosrun", "six_axis_arm_demo", "ik_round_trip",
                           f"_round_trips:={CPP_ROUND_TRIPS}"], env=env, capture_output=True,
                          text=True, timeout=CPP_NODE_LIMIT, check=False)
    output = node.stdout + node.stderr
    assert node.returncode == 0, output[-3000:]
    with open(workspace / "src" / "six_axis_arm_ikfast_manipulator_plugin" / "config" /
              "kinematics.yaml") as stream:
        entry = yaml.safe_load(stream)["manipulator"]
    solver = next(line.split() for line in output.splitlines() if line.startswith("SOLVER "))
    assert solver[1:6] == [IKFAST_CLASS, "base", "base_link", "tip", "tool0"], solver
    assert float(solver[7]) == pytest.approx(entry["kinematics_solver_timeout"])
    # the search resolution reached initialize(); getSearchDiscretization() reports it per redundant
    # joint and 0 without one, as a six-joint IKFast solver has none (kinematics_base.h l. 516-553)
    assert entry["kinematics_solver_search_resolution"] > 0 and float(solver[9]) == 0.0

    trips = [line.split() for line in output.splitlines() if line.startswith("ROUND_TRIP ")]
    assert len(trips) == CPP_ROUND_TRIPS
    worst_metres = worst_radians = 0.0
    for words in trips:
        assert words[3] == "1", " ".join(words)
        wanted = tool_pose(urdf, values_after(words, "target", len(JOINTS)))
        reached = tool_pose(urdf, values_after(words, "solution", len(JOINTS)))
        worst_metres = max(worst_metres, float(np.linalg.norm(reached[:3, 3] - wanted[:3, 3])))
        worst_radians = max(worst_radians, rotation_angle(reached, wanted))
    assert worst_metres <= SAME_POSE and worst_radians <= SAME_POSE, (worst_metres, worst_radians)

    target = next(line.split() for line in output.splitlines() if line.startswith("POSE_TARGET "))
    assert target[2] == "1" and target[4] == "tool0", " ".join(target)
    wanted = tool_pose(urdf, values_after(target, "goal", len(JOINTS)))
    reached = tool_pose(urdf, values_after(target, "solution", len(JOINTS)))
    assert np.linalg.norm(reached[:3, 3] - wanted[:3, 3]) <= SAME_POSE
    assert rotation_angle(reached, wanted) <= SAME_POSE
    # each of the node's requests was the plugin's, in the node's process
    assert output.count(SOLVED_LINE) == CPP_ROUND_TRIPS + 1, output.count(SOLVED_LINE)


def test_a_plugin_that_is_not_installed_falls_back_to_kdl_with_the_reason(overlay, ros_env,
                                                                          results_dir):
    _, overlay_env = overlay
    env = environment(overlay_env, ros_env)
    with headless.roslaunch(["six_axis_arm_ikfast_manipulator_plugin", "demo.launch",
                             "use_rviz:=false", f"kinematics_solver:={MISSING}"], env,
                            os.path.join(results_dir, "demo_missing.log")) as launch:
        headless.wait_until(lambda: started(launch), START_LIMIT, "move_group")
        output = launch.output()
    assert (f"group 'manipulator': kinematics solver '{MISSING}' could not be loaded: "
            f"pluginlib knows no plugin '{MISSING}'") in output
    assert f"declared: {IKFAST}" in output
    assert "solving with KDL (kdl_kinematics_plugin/KDLKinematicsPlugin) instead" in output
    assert SOLVED_LINE not in output


# run in the overlay's environment: the plugin's initialize() refuses a tip it was not
# written for (kinematics_solver_ik_links), and the group is answered by KDL
REFUSED_TIP = """
import logging, sys
logging.basicConfig(level=logging.INFO, stream=sys.stdout)
from moveit_core import robot_model
from moveit_kinematics.solvers import load_solver
urdf, srdf = open(sys.argv[1]).read(), open(sys.argv[2]).read()
model = robot_model.load(urdf, srdf)
solver = load_solver(model, "manipulator", {"kinematics_solver": sys.argv[3],
                     "kinematics_solver_ik_links": ["wrist_3_link"]}, urdf, srdf)
print("SOLVER", type(solver).__name__, solver.tip)
"""


def test_a_plugin_whose_initialize_fails_falls_back_to_kdl(overlay, master):
    workspace, overlay_env = overlay
    env = dict(overlay_env, ROS_MASTER_URI=master["ROS_MASTER_URI"], ROS_HOME=master["ROS_HOME"])
    src = workspace / "src"
    run = subprocess.run([sys.executable, "-c", REFUSED_TIP,
                          str(src / "six_axis_arm_description" / "urdf" / "six_axis_arm.urdf"),
                          str(src / "six_axis_arm_moveit_config" / "config" /
                              "six_axis_arm.srdf"), IKFAST],
                         env=env, capture_output=True, text=True, timeout=SERVICE_LIMIT,
                         check=False)
    output = run.stdout + run.stderr
    assert run.returncode == 0, output[-3000:]
    assert (f"group 'manipulator': kinematics solver '{IKFAST}' could not be loaded: its "
            "initialize() returned false for group 'manipulator' (base 'base_link', tip "
            "'wrist_3_link')") in output
    assert "This solver was written for base_link -> tool0" in output   # the plugin's own
    assert "SOLVER KdlSolver tool0" in output

"""MoveIt's figures for ``make bench``: move_group on the px100 as the arm homework starts
it (``xsarm_moveit.launch robot_model:=px100 dof:=4 use_fake:=true``), the table and the
RealSense box of arm_move's scene in its planning scene.

  move_group up          wall seconds from roslaunch (master already up) until the
                         move_group action and compute_ik answer
  planning               plan_kinematic_path for random reachable targets (a random free
                         state's gripper pose, its orientation reachable by the 4-joint
                         arm), each from where the last ended: wall ms per request (median,
                         95th percentile) and the share planned
  IK                     the group's KDL solver (Interbotix's kinematics.yaml) on the same
                         targets, in this process: ms per call (median)
  C++ client             MoveGroupInterface::plan (moveit_ros_planning_interface's plan_timing)
                         against moveit_commander's plan() (plan_timing.py), the same named
                         targets in turn from Sleep, each client run twice, alternately: per
                         plan, the wall ms beyond the planning time move_group reports (the
                         client, the transport and move_group's own work); the C++ client's
                         median of it, and that median minus the Python client's.
                         move_group waits for a joint_states message newer than each plan
                         request (move_action_capability.cpp:67): meanwhile this publishes the
                         arm's state at CLIENT_STATE_RATE, so the wait is under a millisecond
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
import threading
import time
from typing import Dict, List

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import headless  # noqa: E402  (tools/ is not a package)

HERE = os.path.dirname(os.path.abspath(__file__))

TARGETS = 200
START_LIMIT = 60.0        # s (wall): the longest move_group may take to answer
ARM = ["waist", "shoulder", "elbow", "wrist_angle"]
TIP = "px100/ee_gripper_link"
# arm_move's scene (config/scene.yaml), in the arm's base frame
TABLE = ((0.8, 1.0, 0.75), (0.2, 0.0, -0.375))
REALSENSE = ((0.14, 0.09, 0.05), (0.16, -0.17, 0.025))
CLIENT_TARGETS = ["Home", "Upright"]      # the px100's named states (its SRDF)
CLIENT_PLANS = 20          # plans per client run; each client runs CLIENT_RUNS times
CLIENT_RUNS = 2
CLIENT_STATE_RATE = 1000.0  # Hz: joint_states while the clients plan
CLIENT_LIMIT = 120.0       # s (wall): the longest one client run may take


def _box(name, size, centre):
    from geometry_msgs.msg import Pose
    from moveit_msgs.msg import CollisionObject
    from shape_msgs.msg import SolidPrimitive
    box = CollisionObject(id=name, operation=CollisionObject.ADD)
    box.header.frame_id = "px100/base_link"
    box.pose.position.x, box.pose.position.y, box.pose.position.z = centre
    box.pose.orientation.w = 1.0
    box.primitives = [SolidPrimitive(type=SolidPrimitive.BOX, dimensions=list(size))]
    identity = Pose()
    identity.orientation.w = 1.0
    box.primitive_poses = [identity]
    return box


def _targets(scene, rng) -> List[Dict[str, float]]:
    """Random states of the arm, free in the scene, the gripper above the table."""
    model = scene.model
    found = []
    while len(found) < TARGETS:
        state = {j: rng.uniform(model.bounds[j].lower, model.bounds[j].upper) for j in ARM}
        if model.link_poses(state)[TIP][2, 3] > 0.02 and \
                not scene.contacts(state, "interbotix_arm"):
            found.append(state)
    return found


def _request(model, start, pose):
    from geometry_msgs.msg import Pose
    from moveit_msgs.msg import (Constraints, MotionPlanRequest, OrientationConstraint,
                                 PositionConstraint)
    from shape_msgs.msg import SolidPrimitive
    from tf.transformations import quaternion_from_matrix
    request = MotionPlanRequest(group_name="interbotix_arm", allowed_planning_time=5.0,
                                max_velocity_scaling_factor=1.0,
                                max_acceleration_scaling_factor=1.0)
    request.start_state.joint_state.name = ARM
    request.start_state.joint_state.position = [start[j] for j in ARM]
    position = PositionConstraint(link_name=TIP, weight=1.0)
    position.header.frame_id = model.model_frame
    position.constraint_region.primitives = [SolidPrimitive(type=SolidPrimitive.SPHERE,
                                                            dimensions=[1e-4])]
    region = Pose()
    region.position.x, region.position.y, region.position.z = pose[:3, 3]
    region.orientation.w = 1.0
    position.constraint_region.primitive_poses = [region]
    rotation = np.eye(4)
    rotation[:3, :3] = pose[:3, :3]
    q = quaternion_from_matrix(rotation)
    orientation = OrientationConstraint(link_name=TIP, weight=1.0,
                                        absolute_x_axis_tolerance=1e-3,
                                        absolute_y_axis_tolerance=1e-3,
                                        absolute_z_axis_tolerance=1e-3)
    orientation.header.frame_id = model.model_frame
    (orientation.orientation.x, orientation.orientation.y, orientation.orientation.z,
     orientation.orientation.w) = q
    request.goal_constraints = [Constraints(position_constraints=[position],
                                            orientation_constraints=[orientation])]
    return request


def _client_run(command: List[str], env: Dict[str, str], log) -> List[float]:
    """One client's plans: the wall ms of each beyond move_group's planning time (each
    must have planned)."""
    done = subprocess.run(command, env=env, capture_output=True, text=True,
                          timeout=CLIENT_LIMIT, check=False)
    log.write(f"$ {' '.join(command)}\n{done.stdout}{done.stderr}\n")
    lines = [json.loads(line) for line in done.stdout.splitlines() if line.startswith("{")]
    assert done.returncode == 0 and len(lines) == CLIENT_PLANS, done.stdout + done.stderr
    assert all(line["planned"] for line in lines), done.stdout
    return [line["wall_ms"] - line["planning_ms"] for line in lines]


def _clients(env: Dict[str, str], log_path: str) -> Dict[str, float]:
    """The C++ and the Python client planning the same targets on move_group (px100)."""
    import rospy
    from sensor_msgs.msg import JointState
    heard = rospy.wait_for_message("/px100/joint_states", JointState, timeout=START_LIMIT)
    publisher = rospy.Publisher("/px100/joint_states", JointState, queue_size=1)
    stop = threading.Event()

    def publish():
        # stamped by the wall clock, which the launch's nodes follow (see measure), whatever
        # clock this process's rospy follows
        while not stop.wait(1.0 / CLIENT_STATE_RATE):
            heard.header.stamp = rospy.Time.from_sec(time.time())
            publisher.publish(heard)
    publishing = threading.Thread(target=publish, daemon=True)
    publishing.start()
    client_env = dict(env, ROS_NAMESPACE="px100")
    for node in ("plan_timing_cpp", "plan_timing_py"):
        rospy.set_param(f"/px100/{node}/group", "interbotix_arm")
        rospy.set_param(f"/px100/{node}/targets", CLIENT_TARGETS)
        rospy.set_param(f"/px100/{node}/count", CLIENT_PLANS)
    commands = {"cpp": ["rosrun", "moveit_ros_planning_interface", "plan_timing"],
                "py": ["python3", os.path.join(HERE, "plan_timing.py")]}
    beyond: Dict[str, List[float]] = {"cpp": [], "py": []}
    try:
        with open(log_path, "a", encoding="utf-8") as log:
            for _ in range(CLIENT_RUNS):
                for client, command in commands.items():
                    beyond[client] += _client_run(command, client_env, log)
    finally:
        stop.set()
        publishing.join(timeout=1.0)
        publisher.unregister()
    cpp, py = float(np.median(beyond["cpp"])), float(np.median(beyond["py"]))
    return {"cpp_beyond_planning": cpp, "py_beyond_planning": py, "cpp_added": cpp - py}


def measure(env: Dict[str, str], log_path: str) -> Dict[str, float]:
    import rospy
    from moveit_msgs.msg import MoveItErrorCodes, PlanningScene
    from moveit_msgs.srv import ApplyPlanningScene, GetMotionPlan, GetPositionIK
    from moveit_core import robot_model
    from moveit_core.planning_scene import PlanningScene as Scene
    from moveit_kinematics.kdl_solver import KdlSolver, SolverSettings

    if not rospy.core.is_initialized():     # make bench's probe node serves, when it runs
        os.environ.update(ROS_MASTER_URI=env["ROS_MASTER_URI"])
        rospy.init_node("bench_moveit", anonymous=True, disable_signals=True)
    # the fake arm runs on the wall clock: make bench's simulator runs before this left
    # /use_sim_time set on the master, and without /clock the driver's timers would not fire
    rospy.set_param("/use_sim_time", False)
    started = time.monotonic()
    with headless.roslaunch(["interbotix_xsarm_moveit", "xsarm_moveit.launch",
                             "robot_model:=px100", "dof:=4", "use_fake:=true",
                             "use_moveit_rviz:=false"], env, log_path) as launch:
        def answering():
            assert launch.running(), launch.output()[-2000:]
            try:
                rospy.wait_for_service("/px100/compute_ik", timeout=0.05)
            except rospy.ROSException:
                return False
            topics = {name for name, _ in rospy.get_published_topics()}
            return "/px100/move_group/status" in topics
        headless.wait_until(answering, START_LIMIT, "move_group", interval=0.02)
        up = time.monotonic() - started
        model = robot_model.load(rospy.get_param("/px100/robot_description"),
                                 rospy.get_param("/px100/robot_description_semantic"))
        scene = Scene(model)
        diff = PlanningScene(is_diff=True)
        diff.world.collision_objects = [_box("table", *TABLE), _box("realsense", *REALSENSE)]
        scene.apply(diff)
        assert rospy.ServiceProxy("/px100/apply_planning_scene", ApplyPlanningScene)(
            scene=diff).success
        plan = rospy.ServiceProxy("/px100/plan_kinematic_path", GetMotionPlan)
        ik = rospy.ServiceProxy("/px100/compute_ik", GetPositionIK)
        kinematics = rospy.get_param("/px100/robot_description_kinematics/interbotix_arm")
        solver = KdlSolver(model, "interbotix_arm", SolverSettings.from_parameters(kinematics))
        rng = np.random.default_rng(7)
        start = {j: 0.0 for j in ARM}
        seconds, ik_seconds, planned = [], [], 0
        for target in _targets(scene, rng):
            pose = model.link_poses(target)[TIP]
            began = time.perf_counter()
            solver.inverse(pose, [start[j] for j in ARM])
            ik_seconds.append(time.perf_counter() - began)
            request = _request(model, start, pose)
            began = time.perf_counter()
            answer = plan(motion_plan_request=request).motion_plan_response
            seconds.append(time.perf_counter() - began)
            if answer.error_code.val == MoveItErrorCodes.SUCCESS:
                planned += 1
                points = answer.trajectory.joint_trajectory.points
                start = dict(zip(answer.trajectory.joint_trajectory.joint_names,
                                 points[-1].positions))
        del ik
        clients = _clients(env, log_path + ".clients")
    return dict(clients, up=up, median=1000 * float(np.median(seconds)),
                p95=1000 * float(np.percentile(seconds, 95)),
                success=100.0 * planned / TARGETS,
                ik=1000 * float(np.median(ik_seconds)))


if __name__ == "__main__":
    # the MoveIt figures alone: python3 tools/bench/moveit_cost.py (a master of its own)
    with headless.private_master() as own:
        core = subprocess.Popen(["roscore", "-p", own["ROS_MASTER_URI"].rsplit(":", 1)[1]],
                                env=own, stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT,
                                start_new_session=True)
        try:
            import rosgraph
            os.environ.update(ROS_MASTER_URI=own["ROS_MASTER_URI"])
            headless.wait_until(rosgraph.is_master_online, 30, "the master")
            print(measure(own, "/tmp/bench_moveit.log"))
        finally:
            core.terminate()
            core.wait(timeout=20)

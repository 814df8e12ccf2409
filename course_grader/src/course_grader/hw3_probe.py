"""ME495 homework 3's probes, run in the probe process against one scenario's master and
judged in the simulator's ground truth (``/gazebo/...``), never in what the student's nodes
believe: the world's models and ``ddrive.launch paused:=true`` (the clock stands still until
``/gazebo/unpause_physics``); flips counted from the robot's true orientation; the arm's
``step`` service into the floor and to a reachable point, the true gripper point compared
with the target. Named in config/me495_hw3.yaml as ``course_grader.hw3_probe:<name>``."""
from __future__ import annotations

import os
import threading
import time
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np
import rospy
from tf import transformations

from course_grader.hw3_measures import FlipCount, included_models, planar_travel, still_points
from course_grader.measures import thin
from course_grader.probe import Truth, pose_recorder, simulated
from course_grader.probe_tools import ProbeError, check, wait_until
from course_grader.ros_run import declared_args

SUCCESS = 1                 # moveit_msgs/MoveItErrorCodes SUCCESS
POLL = 0.05                 # s (wall) between looks at the true gripper point


def _joints_of(param: str, timeout: float) -> Tuple[object, List[str]]:
    from urdf_tools import parse_urdf
    wait_until(lambda: rospy.has_param(param), timeout, f"the parameter {param}")
    model = parse_urdf(rospy.get_param(param), param)
    return model, [j.name for j in model.joints.values() if j.movable] or list(model.joints)


# --- ddrive.launch paused:=true: the world and the paused clock --------------------------


def world(course, scenario: str) -> Dict:
    import rospkg
    from std_srvs.srv import Empty
    spec, limit = course.checks[scenario], course.limits["startup"]
    truth = Truth(limit)
    # the world's contents need no robot: one that comes within robot_wait is told apart
    # from the world's models, and a world launched without one is graded all the same
    try:
        _, joints = _joints_of("/robot_description", spec["robot_wait"])
        robot = truth.find_robot(joints, spec["robot_wait"])
        robot_note = f"robot '{robot}'"
    except ProbeError as error:
        robot = ""
        robot_note = f"no robot in the world ({error}): the world's contents need none"
    names = [n for n in truth.world().model_names if n != robot]
    package, launch_file = spec["launch"]
    package_dir = rospkg.RosPack().get_path(package)
    # a model is what it was included as, whatever the student named it
    uris = included_models(os.path.join(package_dir, "worlds"))
    contents = []
    for wanted in spec["models"]:
        key = wanted["name"].lower()
        found = [n for n in names if key in n.lower() or key in uris.get(n, "").lower()]
        shown = [n if key in n.lower() else f"{n} ({uris[n]})" for n in found]
        contents.append(check(f"at least {wanted['at_least']} {wanted['name']}",
                              len(found) >= wanted["at_least"],
                              f"{len(found)} model(s) *{wanted['name']}* by name or uri "
                              f"(at least {wanted['at_least']}): {', '.join(shown) or 'none'}"))
    path = os.path.join(package_dir, "launch", launch_file)
    declares = "paused" in declared_args(path)
    before = truth.sim_time()
    ends = time.monotonic() + spec["still_window"]
    while time.monotonic() < ends:      # the measurement itself: the clock over a wall window
        time.sleep(POLL)
    after = truth.sim_time()
    stood = after - before <= spec["still_tolerance"]
    rospy.wait_for_service("/gazebo/unpause_physics", timeout=limit)
    rospy.ServiceProxy("/gazebo/unpause_physics", Empty)()
    target = after + spec["advance"]
    try:
        wait_until(lambda: truth.sim_time() >= target, limit, "the clock to run once unpaused")
        advanced = True
    except ProbeError:
        advanced = False
    gained = truth.sim_time() - after
    return {"checks": {
        "world_contents": contents,
        "ddrive_paused": [
            check("declares paused", declares,
                  f"{launch_file} {'declares' if declares else 'does not declare'} an argument "
                  f"'paused' ({', '.join(declared_args(path)) or 'no arguments'})"),
            check("paused at start", stood,
                  f"with paused:=true the simulated clock moved {after - before:.3f} s in "
                  f"{spec['still_window']:g} s (wall)"),
            check("runs once unpaused", advanced,
                  f"after /gazebo/unpause_physics it gained {gained:.2f} s "
                  f"(at least {spec['advance']:g})"),
        ]}, "notes": {"world_contents": [f"{robot_note}; world models: {', '.join(names)}"]}}


# --- ddrive.launch flip:=true: flips in ground truth --------------------------------------


def flip(course, scenario: str) -> Dict:
    spec, limit = course.checks[scenario], course.limits["startup"]
    truth = Truth(limit)
    _, joints = _joints_of("/robot_description", limit)
    model = truth.find_robot(joints)
    recorder = pose_recorder(model)
    wait_until(recorder.copy, limit, "/gazebo/model_states with the robot")
    began = recorder.copy()[0][0]
    end = began + spec["duration"]
    wait_until(lambda: recorder.samples[-1][0] >= end, spec["duration"] * 10 + limit,
               f"{spec['duration']} s of simulated time")
    samples = [s for s in recorder.copy() if s[0] <= end]
    counter = FlipCount(spec["dead_band"])
    flipped_at = [sample[0] for sample in samples if counter.update(sample[3])]
    travel = planar_travel([(s[1], s[2]) for s in samples])
    span = samples[-1][0] - samples[0][0]
    return {"checks": {"flips": [
        check("flips over", counter.flips >= spec["min_flips"],
              f"'{model}' flipped {counter.flips} times in {span:.1f} s of simulated time "
              f"(at least {spec['min_flips']}), from its true orientation",
              value=max(0, spec["min_flips"] - counter.flips)),
        check("keeps driving", travel >= spec["min_travel"],
              f"travelled {travel:.1f} m in truth (at least {spec['min_travel']:g})"),
    ]}, "notes": {"flips": [f"{len(samples)} ground-truth samples; up axis z from "
                            f"{min(s[3] for s in samples):+.2f} to {max(s[3] for s in samples):+.2f}"]},
        "samples": {"flip": {"item": "flips", "dead_band": spec["dead_band"], "flips": flipped_at,
                             "samples": thin([(s[0], s[3]) for s in samples],
                                             course.report["plot_points"])}}}


# --- arm.launch: the step service in ground truth ------------------------------------------


def _pose_matrix(pose) -> np.ndarray:
    p, q = pose.position, pose.orientation
    matrix = transformations.quaternion_matrix([q.x, q.y, q.z, q.w])
    matrix[:3, 3] = [p.x, p.y, p.z]
    return matrix


class ArmTruth:
    """A URDF frame's true pose: the simulator's link state, or, for a frame Gazebo lumps
    into its parent (a fixed joint), the nearest link it has times the fixed joints'
    origins from robot_description."""

    def __init__(self, model_name: str, model, timeout: float):
        from gazebo_msgs.srv import GetLinkState
        rospy.wait_for_service("/gazebo/get_link_state", timeout=timeout)
        self.link_state = rospy.ServiceProxy("/gazebo/get_link_state", GetLinkState)
        self.model_name, self.model = model_name, model

    def frame(self, suffix: str) -> str:
        names = sorted((n for n in self.model.links if n.endswith(suffix)), key=len)
        if not names:
            raise ProbeError(f"robot_description has no link ending in '{suffix}'")
        return names[0]

    def pose(self, link: str) -> np.ndarray:
        from urdf_tools.kinematics import origin_transform
        offset = np.eye(4)
        while True:
            state = self.link_state(f"{self.model_name}::{link}", "")
            if state.success:
                return _pose_matrix(state.link_state.pose) @ offset
            joint = self.model.parent_joint(link)
            if joint is None or joint.type != "fixed":
                raise ProbeError(f"the simulator has no link '{link}': {state.status_message}")
            offset = origin_transform(joint.origin) @ offset
            link = joint.parent

    def point_in(self, base: str, tip: str) -> np.ndarray:
        return (np.linalg.inv(self.pose(base)) @ self.pose(tip))[:3, 3]


class JointStateArm:
    """The arm where no simulator runs (MoveIt's fake controllers: the joints are where
    the plans put them, and nothing else is): a frame's pose from the arm's /joint_states
    through robot_description's kinematics, the same frames as ArmTruth."""

    def __init__(self, model, joint_states: str, timeout: float):
        from sensor_msgs.msg import JointState
        self.model, self.topic = model, joint_states
        self.positions: Dict[str, float] = {}
        self.lock = threading.Lock()
        self.subscriber = rospy.Subscriber(joint_states, JointState, self._on_states,
                                           queue_size=10)
        wait_until(lambda: self.positions, timeout, f"{joint_states}")

    def _on_states(self, message) -> None:
        with self.lock:
            self.positions.update(zip(message.name, message.position))

    frame = ArmTruth.frame

    def point_in(self, base: str, tip: str) -> np.ndarray:
        from urdf_tools.kinematics import link_transform
        with self.lock:
            positions = dict(self.positions)
        return link_transform(self.model, base, tip, positions)[:3, 3]


def fill_request(request, target: Sequence[float], gripper_open: bool) -> List[str]:
    """Puts ``target`` into the step request's position (a Point, a Pose's position, or x,
    y, z fields) and the gripper flag into its bool; returns what was set."""
    done: List[str] = []

    def visit(message, path: str) -> None:
        for name, kind in zip(message.__slots__, message._slot_types):  # pylint: disable=protected-access
            value = getattr(message, name)
            if kind == "geometry_msgs/Point" and not any("position" in d for d in done):
                value.x, value.y, value.z = target
                done.append(f"{path}{name} (position)")
            elif kind == "geometry_msgs/Quaternion":
                value.w = 1.0    # a Pose target: the identity, not a zero-length quaternion
            elif kind == "bool":
                setattr(message, name, bool(gripper_open) if "clos" not in name.lower()
                        else not gripper_open)
                done.append(f"{path}{name} (gripper)")
            elif hasattr(value, "__slots__"):
                visit(value, f"{path}{name}.")
        slots = list(message.__slots__)
        if not any("position" in d for d in done) and all(a in slots for a in "xyz"):
            for axis, number in zip("xyz", target):
                setattr(message, axis, float(number))
            done.append(f"{path}x, y, z (position)")
    visit(request, "")
    if not any("position" in d for d in done):
        raise ProbeError(f"the step request {type(request).__name__} has no position field "
                         f"(fields: {', '.join(request.__slots__)})")
    return done


def response_code(response) -> Optional[int]:
    """The MoveIt error code in a step response: a MoveItErrorCodes' ``val`` or the first
    integer field."""
    for name, kind in zip(response.__slots__, response._slot_types):  # pylint: disable=protected-access
        value = getattr(response, name)
        if kind.endswith("MoveItErrorCodes"):
            return int(value.val)
        if kind.startswith("int") or kind.startswith("uint"):
            return int(value)
    return None


def _text(response) -> str:
    words = [str(getattr(response, n)) for n, k in
             zip(response.__slots__, response._slot_types) if k == "string"]  # pylint: disable=protected-access
    return " ".join(words)[:80]


def step(course, scenario: str) -> Dict:
    import rosservice
    spec, limit = course.checks[scenario], course.limits["startup"]
    model, joints = _joints_of(spec["robot_description"], limit)
    if simulated():
        truth = Truth(limit)
        model_name = truth.find_robot(joints)
        arm = ArmTruth(model_name, model, limit)
        source = f"the simulator's model '{model_name}'"
        measured = "true gripper point"
    else:
        states = rospy.names.ns_join(rospy.names.namespace(spec["robot_description"]),
                                     "joint_states")
        arm = JointStateArm(model, states, limit)
        source = (f"the joints of MoveIt's fake controllers (no simulator runs): {states} "
                  "through robot_description's kinematics")
        measured = "gripper point"
    base, tip = arm.frame(spec["base_frame"]), arm.frame(spec["gripper_frame"])
    rospy.wait_for_service(spec["service"], timeout=limit)
    service_class = rosservice.get_service_class_by_name(spec["service"])
    proxy = rospy.ServiceProxy(spec["service"], service_class)

    def samples_since(start: float):
        recorded = []

        def rest():
            recorded.append((rospy.get_time(), arm.point_in(base, tip)))
            return still_points([r for r in recorded if r[0] >= start],
                                spec["still_window"], spec["still_speed"])
        wait_until(rest, limit, "the gripper to come to rest")
        return recorded[-1][1]

    def call(target):
        request = service_class._request_class()  # pylint: disable=protected-access
        fields = fill_request(request, target, spec["gripper_open"])
        answer: Dict = {}

        def worker():
            try:
                answer["response"] = proxy(request)
            except Exception as error:  # pylint: disable=broad-except
                answer["error"] = f"{type(error).__name__}: {error}"
        thread = threading.Thread(target=worker, daemon=True)
        thread.start()
        thread.join(spec["call_timeout"])
        if "response" not in answer:
            return None, answer.get("error", f"no answer within {spec['call_timeout']:g} s"), fields
        response = answer["response"]
        return response_code(response), _text(response), fields

    start = samples_since(rospy.get_time())
    floor = spec["floor_target"]
    code, text, fields = call(floor)
    after = samples_since(rospy.get_time())
    moved = float(np.linalg.norm(after - start))
    floor_checks = [
        check("an error code", code is not None and code != SUCCESS,
              f"step to {floor} answered code {code} '{text}'"),
        check("nothing moved", moved <= spec["moved_tolerance"],
              f"the {measured} moved {1000 * moved:.1f} mm "
              f"(at most {1000 * spec['moved_tolerance']:g})")]
    target = spec["reachable_target"]
    code, text, _ = call(target)
    reached = samples_since(rospy.get_time())
    error = float(np.linalg.norm(reached - np.asarray(target)))
    reach_checks = [
        check("answers SUCCESS", code == SUCCESS, f"step to {target} answered code {code} '{text}'"),
        check("the gripper ends at the target", error <= spec["tolerance"],
              f"{measured} ({', '.join(f'{v:.3f}' for v in reached)}) in {base}, "
              f"{1000 * error:.1f} mm from the target (at most {1000 * spec['tolerance']:g})",
              value=error)]
    return {"checks": {"step_floor_error": floor_checks, "step_reachable": reach_checks},
            "notes": {"step_floor_error": [f"request fields set: {', '.join(fields)}; "
                                           f"gripper frame {tip}, measured on {source}"]}}

"""The measuring side of a scenario, run as ``python3 -m course_grader.probe SCENARIO
COURSE_YAML [FOLDER]`` in a child process against that scenario's master (rospy can join
one master per process). It prints one JSON line: ``{"checks": {item: [check...]},
"notes": {item: [text...]}}`` or ``{"error": text}``, and, for the report, ``"samples":
{plot kind: {"item": id, ...the ground-truth samples measured}}`` (drawn by
course_grader.plots) and ``"figures": {item: [{"title", "file" or "missing", "caption"}]}``
for pictures the probe wrote into FOLDER (the report's). Every wait is bounded."""
from __future__ import annotations

import importlib
import json
import math
import os
import sys
import threading
import traceback
from typing import Callable, Dict, List, Optional, Tuple

import rospy
from tf import transformations

from course_grader import course as course_file
from course_grader.answer_words import answer_text
from course_grader.course import scenario_spec
from course_grader.ros_run import NO_SIMULATOR_ENV
from course_grader.probe_tools import (ProbeError, check, publishers_of, robot_description,
                                       subscribers_of, wait_for_simulated_time, wait_until)
from course_grader.measures import (Rotation, distance_outside, is_still, stop_time, thin,
                                    tilt_degrees, unwrap, yaw_of)

# --- the simulator ---------------------------------------------------------------------


class Truth:
    """The simulator's /gazebo interface: which model is the robot, its pose, the time."""

    def __init__(self, timeout: float):
        from gazebo_msgs.srv import GetModelProperties, GetModelState, GetWorldProperties
        for name in ("get_world_properties", "get_model_properties", "get_model_state"):
            rospy.wait_for_service(f"/gazebo/{name}", timeout=timeout)
        self.world = rospy.ServiceProxy("/gazebo/get_world_properties", GetWorldProperties)
        self.properties = rospy.ServiceProxy("/gazebo/get_model_properties", GetModelProperties)
        self.state = rospy.ServiceProxy("/gazebo/get_model_state", GetModelState)
        self.timeout = timeout
        self.model = ""

    def sim_time(self) -> float:
        return self.world().sim_time

    def find_robot(self, joints: List[str], timeout: Optional[float] = None) -> str:
        """The spawned model whose joints are robot_description's (the student names it),
        waited for ``timeout`` s (the start-up limit when None)."""
        def robot():
            best, overlap = "", 0
            for name in self.world().model_names:
                shared = len(set(self.properties(name).joint_names) & set(joints))
                if shared > overlap:
                    best, overlap = name, shared
            return best
        self.model = wait_until(robot, self.timeout if timeout is None else timeout,
                                f"a model with the joints {joints} to be spawned")
        return self.model

    def pose(self):
        state = self.state(self.model, "")
        if not state.success:
            raise ProbeError(f"/gazebo/get_model_state '{self.model}': {state.status_message}")
        return state.pose

    def wait_sim(self, seconds: float, what: str) -> float:
        target = self.sim_time() + seconds
        wall = seconds * 10 + self.timeout   # the simulator may run slower than real time
        wait_until(lambda: self.sim_time() >= target, wall, what)
        return target


def _movable_joints(timeout: float) -> List[str]:
    model = robot_description(timeout)
    return [j.name for j in model.joints.values() if j.movable] or list(model.joints)


class ModelRecorder:
    """Samples of one model's true pose from /gazebo/model_states, against simulated time:
    each message gives ``sample(time, pose, the previous sample or None)``."""

    def __init__(self, model: str, sample: Callable):
        from gazebo_msgs.msg import ModelStates
        self.model = model
        self.sample = sample
        self.samples: List[Tuple] = []
        self.lock = threading.Lock()
        self.subscriber = rospy.Subscriber("/gazebo/model_states", ModelStates, self._on_states,
                                           queue_size=10)

    def _on_states(self, message) -> None:
        if self.model not in message.name:
            return
        pose = message.pose[message.name.index(self.model)]
        now = rospy.get_time()
        with self.lock:
            previous = self.samples[-1] if self.samples else None
            self.samples.append(self.sample(now, pose, previous))

    def copy(self):
        with self.lock:
            return list(self.samples)

    def since(self, start: float):
        with self.lock:
            return [s for s in self.samples if s[0] >= start]

    def latest(self):
        with self.lock:
            return self.samples[-1] if self.samples else None


def _position_and_up(now: float, pose, previous) -> Tuple[float, float, float, float]:
    """(t, x, y, up_z): the body's up axis is the z of its local z."""
    q = pose.orientation
    up_z = transformations.quaternion_matrix([q.x, q.y, q.z, q.w])[2, 2]
    return now, pose.position.x, pose.position.y, up_z


def _unwrapped_yaw(now: float, pose, previous) -> Tuple[float, float]:
    """(t, yaw) with yaw unwrapped against the previous sample's."""
    q = pose.orientation
    return now, unwrap(previous[1] if previous else None, yaw_of(q.x, q.y, q.z, q.w))


def pose_recorder(model: str) -> ModelRecorder:
    """A model's true position and body up axis, (t, x, y, up_z) samples."""
    return ModelRecorder(model, _position_and_up)


def yaw_recorder(model: str) -> ModelRecorder:
    """The robot's true heading, unwrapped, (t, yaw) samples."""
    return ModelRecorder(model, _unwrapped_yaw)


# Every built-in probe takes the course and the folder where it may write pictures for the
# report (only display's does).


def spawn(course, folder: str = "") -> Dict:
    spec, limit = course.checks["spawn"], course.limits["startup"]
    truth = Truth(limit)
    model = truth.find_robot(_movable_joints(limit))
    truth.wait_sim(spec["settle"], f"{spec['settle']} s of simulated time after the spawn")
    pose = truth.pose()
    p, q = pose.position, pose.orientation
    tilt = tilt_degrees(q.x, q.y, q.z, q.w)
    outside = distance_outside(p.x, p.y, spec["square_x"], spec["square_y"])
    worlds = truth.world().model_names
    course_world = set(spec["course_world_models"]) <= set(worlds)
    return {"checks": {"spawn_in_start_square": [
        check("inside the start square", outside == 0.0,
              f"'{model}' at ({p.x:.3f}, {p.y:.3f}) m, "
              + ("inside" if outside == 0.0 else f"{outside:.3f} m outside")
              + f" the square x {spec['square_x']}, y {spec['square_y']}", outside),
        check("standing", tilt <= spec["max_tilt"], f"tilted {tilt:.1f} deg (at most {spec['max_tilt']:g})"),
    ]}, "notes": {"spawn_in_start_square": [
        f"the course's warehouse ({', '.join(spec['course_world_models'])}) is "
        f"{'loaded' if course_world else 'not loaded: the launch file starts another world'}",
        f"world models: {', '.join(sorted(set(worlds) - {model}))}"]}}


def drive(course, folder: str = "") -> Dict:
    from geometry_msgs.msg import Twist
    spec, limit = course.checks["drive"], course.limits["startup"]
    truth = Truth(limit)
    recorder = pose_recorder(truth.find_robot(_movable_joints(limit)))
    wait_until(recorder.copy, limit, "/gazebo/model_states with the robot")
    publisher = rospy.Publisher("/cmd_vel", Twist, queue_size=1)
    wait_until(lambda: publisher.get_num_connections() > 0, limit, "a subscriber of /cmd_vel")
    start = truth.pose().position
    # the path is the samples that arrive while driving
    first = len(recorder.copy())
    command = Twist()
    command.linear.x = spec["speed"]
    began = truth.sim_time()
    target = began + spec["duration"]

    def driven():
        publisher.publish(command)
        return truth.sim_time() >= target
    wait_until(driven, spec["duration"] * 10 + limit, f"{spec['duration']} s of simulated time")
    end = truth.pose().position
    publisher.publish(Twist())
    moved = math.hypot(end.x - start.x, end.y - start.y)
    path = [(x, y) for _, x, y, _ in recorder.copy()[first:]]
    return {"checks": {"cmd_vel_moves": [check(
        "moves on /cmd_vel", moved >= spec["min_distance"],
        f"moved {moved:.3f} m in truth in {truth.sim_time() - began:.1f} s at "
        f"{spec['speed']:g} m/s on /cmd_vel (at least {spec['min_distance']:g})")]},
        "samples": {"drive": {
            "item": "cmd_vel_moves",
            "command": f"/cmd_vel at {spec['speed']:g} m/s for {spec['duration']:g} s",
            "path": thin([(start.x, start.y)] + path + [(end.x, end.y)],
                         course.report["plot_points"])}}}


def scan(course, folder: str = "") -> Dict:
    from sensor_msgs.msg import LaserScan
    spec = course.checks["scan"]
    try:
        message = rospy.wait_for_message("/scan", LaserScan, timeout=spec["timeout"])
    except rospy.ROSException:
        return {"checks": {"scan_readable": [check(
            "a LaserScan on /scan", False,
            f"no LaserScan on /scan within {spec['timeout']:g} s "
            f"(publishers: {publishers_of('/scan') or 'none'})")]}}
    ranges = list(message.ranges)
    valid = [r for r in ranges if math.isfinite(r) and message.range_min <= r <= message.range_max]
    fraction = len(valid) / len(ranges) if ranges else 0.0
    return {"checks": {"scan_readable": [check(
        "a LaserScan on /scan with ranges", bool(ranges) and fraction >= spec["min_finite_fraction"],
        f"{len(ranges)} beams in frame '{message.header.frame_id}', {100 * fraction:.0f}% in "
        f"[{message.range_min:g}, {message.range_max:g}] m"
        + (f", nearest {min(valid):.2f} m" if valid else ""))]}}


class RotateCaller:
    """Asks /rotate_robot for turns and measures each in ground truth: the robot still
    before the request, the call bounded by ``call_timeout``, the robot still again after
    the answer."""

    def __init__(self, spec: Dict, recorder: ModelRecorder, proxy, limit: float):
        self.spec, self.recorder, self.proxy, self.limit = spec, recorder, proxy, limit

    def still(self, since: float) -> bool:
        return is_still(self.recorder.since(since), self.spec["still_window"],
                        self.spec["still_speed"])

    def ask(self, degrees: float) -> Tuple[Rotation, Dict, float, bool]:
        """(the turn, its true yaw samples in degrees for the plot, its duration from the
        request until the robot stopped in simulated s, whether the call went unanswered)."""
        spec, recorder = self.spec, self.recorder
        now = rospy.get_time()
        wait_until(lambda: self.still(now), self.limit, "the robot to be still before the request")
        began, yaw0 = recorder.latest()
        answer: Dict = {}

        def call():
            try:
                answer["response"] = self.proxy(degrees=int(degrees))
            except Exception as error:  # pylint: disable=broad-except
                answer["error"] = f"{type(error).__name__}: {error}"
            answer["at"] = rospy.get_time()
        worker = threading.Thread(target=call, daemon=True)
        worker.start()
        worker.join(spec["call_timeout"])
        hung = "at" not in answer
        if hung:
            answer.update(at=float("inf"), error="no answer")
        response = answer.get("response")
        text = answer_text(response) if response is not None else answer.get("error", "")
        after = min(answer["at"], rospy.get_time())
        wait_until(lambda: self.still(after), self.limit, f"the robot to stop after rotate {degrees}")
        samples = recorder.since(began)
        plotted = {"requested": float(degrees), "began": began, "start": math.degrees(yaw0),
                   "answered_at": answer["at"] if math.isfinite(answer["at"]) else None,
                   "samples": [(t, math.degrees(yaw)) for t, yaw in samples]}
        rotation = Rotation(
            requested=float(degrees), turned=math.degrees(samples[-1][1] - yaw0),
            answer=text.strip(), answered_at=answer["at"],
            stopped_at=stop_time(samples, math.radians(spec["stopped_band"])))
        return rotation, plotted, rotation.stopped_at - began, hung


def rotate(course, folder: str = "") -> Dict:
    import rosservice
    spec, limit = course.checks["rotate"], course.limits["startup"]
    truth = Truth(limit)
    model = truth.find_robot(_movable_joints(limit))
    recorder = yaw_recorder(model)
    wait_until(recorder.latest, limit, "/gazebo/model_states with the robot")
    rospy.wait_for_service("/rotate_robot", timeout=limit)
    node = rosservice.get_service_node("/rotate_robot")
    service_class = rosservice.get_service_class_by_name("/rotate_robot")
    caller = RotateCaller(spec, recorder, rospy.ServiceProxy("/rotate_robot", service_class),
                          limit)

    rotations: List[Rotation] = []
    durations: List[float] = []
    unasked: List[float] = []
    plotted: List[Dict] = []        # per request: its true yaw samples, in degrees
    failures: List[str] = []
    for index, degrees in enumerate(spec["requests"]):
        rotation, samples, seconds, hung = caller.ask(degrees)
        if hung:
            failures.append(f"rotate {degrees}: no answer within {spec['call_timeout']:g} s")
        rotations.append(rotation)
        durations.append(seconds)
        plotted.append(samples)
        rest = spec["requests"][index + 1:]
        if rest and (hung or abs(rotation.error()) >= spec["done_within"]):
            # a service that did not answer, or whose turn was not done at all, would do no
            # better with the next (and each may take its call's whole time): the rest
            # are not asked and count as nothing
            failures.append(f"not asked after {'a call with no answer' if hung else 'a turn not done'}"
                            f" (each counts as nothing): {rest}")
            unasked.extend(rest)
            break
    # asked last: the robot is respawned geared down for it
    uses_odom = odometry_use(spec, truth, caller, node, rotations[0], durations[0],
                             math.isfinite(rotations[0].answered_at))

    def describe(r: Rotation) -> str:
        return (f"asked {r.requested:+.0f}: turned {r.turned:+.1f} deg in truth, answer "
                f"'{r.answer[:60]}' {r.answered_at - r.stopped_at:+.2f} s after it stopped")
    degrees_ok = [check(f"rotate {r.requested:+.0f}", r.turned_ok(spec["tolerance"]),
                        f"asked {r.requested:+.0f} deg, turned {r.turned:+.1f} in truth "
                        f"(error {r.error():+.1f})", abs(r.error())) for r in rotations]
    success_ok = [check(f"answer to {r.requested:+.0f}",
                        r.answered_when_done(spec["answer_lag"], spec["done_within"]),
                        describe(r))
                  for r in rotations]
    for degrees in unasked:
        reason = f"asked {degrees:+.0f}: not asked after the turn before failed"
        degrees_ok.append(check(f"rotate {degrees:+.0f}", False, reason, float("inf")))
        success_ok.append(check(f"answer to {degrees:+.0f}", False, reason))
    per_request = max(2, course.report["plot_points"] // max(1, len(plotted)))
    for request in plotted:
        request["samples"] = thin(request["samples"], per_request)
    return {"checks": {
        "rotate_degrees": degrees_ok,
        "rotate_uses_odom": [uses_odom],
        "rotate_answers_success": success_ok,
    }, "notes": {"rotate_degrees": failures},
        "samples": {"rotate": {"item": "rotate_degrees", "requests": plotted}}}


def odometry_use(spec: Dict, truth: Truth, caller: RotateCaller, node: str, free: Rotation,
                 free_seconds: float, answered: bool) -> Dict:
    """The odometry item's check: the service's node subscribes to the odometry topic, and
    a turn asked of the robot geared down (course_grader.odometry_use) still reaches the
    angle, as a turn by odometry does and a turn by the clock does not. When that turn
    cannot tell (the first turn was not done, the robot cannot be geared down) the
    subscription decides and the item is marked for review, saying why."""
    from course_grader.odometry_use import CannotGearDown, gear_down, judge
    topic, slowed = spec["odom_topic"], spec["slowed"]
    subscribers = subscribers_of(topic)
    subscribed = (f"{node} (serves /rotate_robot) {'is' if node in subscribers else 'is not'} "
                  f"among the subscribers of {topic}: {subscribers or 'none'}")
    name = f"turns by {topic}"

    def by_subscription(why: str) -> Dict:
        why = f"not judged by behaviour: {why}"
        return check(name, True, f"{subscribed}; {why}", review=why)
    if node not in subscribers:
        return check(name, False, f"{subscribed}; the geared-down turn was not asked")
    if not answered or abs(free.error()) >= spec["done_within"] or not free.turned:
        return by_subscription(
            f"the first turn ({free.requested:+.0f}) was not done (turned {free.turned:+.1f} "
            f"deg{'' if answered else ', no answer'}), so a slowed one cannot tell odometry "
            "from the clock")
    try:
        geared = gear_down(rospy.get_param("/robot_description"), slowed["factor"])
    except CannotGearDown as error:
        return by_subscription(f"the robot cannot be geared down: {error}")
    try:
        respawn(truth, geared.xml, topic)
        rotation, _, seconds, hung = caller.ask(slowed["request"])
    except (ProbeError, rospy.ROSException, rospy.ServiceException) as error:
        return by_subscription(f"the geared-down turn could not be measured: {error}")
    turned_by_odometry, evidence = judge(free, free_seconds, rotation, seconds,
                                         slowed["factor"], spec["tolerance"])
    if hung:
        evidence += f"; no answer within {spec['call_timeout']:g} s"
    return check(name, turned_by_odometry, f"{subscribed}; {geared.describe()}; {evidence}")


def respawn(truth: Truth, urdf_xml: str, odom_topic: str) -> None:
    """The robot deleted and spawned again from ``urdf_xml`` where it stands, under the
    same name and the top-level namespace spawn_model gives by default (gazebo_ros's
    /gazebo/delete_model and /gazebo/spawn_urdf_model), then its odometry awaited."""
    from gazebo_msgs.srv import DeleteModel, SpawnModel
    from nav_msgs.msg import Odometry
    pose = truth.pose()
    for service, kind, request in (("delete_model", DeleteModel, (truth.model,)),
                                   ("spawn_urdf_model", SpawnModel,
                                    (truth.model, urdf_xml, "/", pose, "world"))):
        rospy.wait_for_service(f"/gazebo/{service}", timeout=truth.timeout)
        answer = rospy.ServiceProxy(f"/gazebo/{service}", kind)(*request)
        if not answer.success:
            raise ProbeError(f"/gazebo/{service} '{truth.model}' to gear the robot down: "
                             f"{answer.status_message}")
    # the robot's odometry again, from its new plugin: the service's node, which listens
    # to the same topic, is reconnected by then as this probe is
    rospy.wait_for_message(odom_topic, Odometry, timeout=truth.timeout)


# --- display.launch (task 1) -------------------------------------------------------------


def display(course, folder: str = "") -> Dict:
    from course_grader.display_probe import measure
    return measure(course, folder)


SCENARIOS = {"display": display, "spawn": spawn, "drive": drive, "scan": scan,
             "rotate": rotate}


def measure(scenario: str, course, folder: str = "") -> Dict:
    """The scenario's probe: the course file's ``module:function`` when it names one,
    else the built-in RB1 probe of that name (given ``folder`` for its pictures)."""
    target = scenario_spec(course, scenario).probe
    if ":" not in target:
        return SCENARIOS[target](course, folder)
    module_name, _, function = target.partition(":")
    return getattr(importlib.import_module(module_name), function)(course, scenario)


def unpause_if_paused(timeout: float) -> str:
    """A world its launch file started paused is unpaused (/gazebo/unpause_physics), as
    the assignment tells students to ("press play"); what was done, for the report, or ""
    when the world was running."""
    from gazebo_msgs.srv import GetPhysicsProperties
    from std_srvs.srv import Empty
    rospy.wait_for_service("/gazebo/get_physics_properties", timeout=timeout)
    properties = rospy.ServiceProxy("/gazebo/get_physics_properties", GetPhysicsProperties)
    if not properties().pause:
        return ""
    rospy.wait_for_service("/gazebo/unpause_physics", timeout=timeout)
    rospy.ServiceProxy("/gazebo/unpause_physics", Empty)()
    return (f"the world started paused (at {rospy.get_time():.3f} s of simulated time); "
            "the grader unpaused it with /gazebo/unpause_physics, as the assignment tells "
            "students to ('press play')")


def simulated() -> bool:
    """Whether a simulator runs in this scenario: the grader says when none of its launch
    files starts one (ros_run.NO_SIMULATOR_ENV; MoveIt's fake controllers), and the probe
    then waits for no simulated clock and no /gazebo."""
    return os.environ.get(NO_SIMULATOR_ENV, "") != "1"


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    scenario, config_path = argv[0], argv[1]
    folder = argv[2] if len(argv) > 2 else ""
    course = course_file.parse(config_path)
    spec = scenario_spec(course, scenario)
    in_simulation = simulated() and not spec.display
    if in_simulation:  # on the simulation's clock
        wait_for_simulated_time(course.limits["startup"])
    rospy.init_node("course_grader_probe", anonymous=True, disable_signals=True)
    try:
        said = unpause_if_paused(course.limits["startup"]) \
            if spec.unpause and in_simulation else ""
        answer = measure(scenario, course, folder)
        if said:
            for item in course.items_of(scenario):
                answer.setdefault("notes", {}).setdefault(item.id, []).insert(0, said)
    except Exception as error:  # pylint: disable=broad-except
        traceback.print_exc()
        answer = {"error": f"{type(error).__name__}: {error}"}
    print(json.dumps(answer), flush=True)
    rospy.signal_shutdown("done")
    return 0


if __name__ == "__main__":
    sys.exit(main())

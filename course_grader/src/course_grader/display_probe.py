"""Task 1 measured on ``display.launch`` as typed: every link's TF as robot_description
says (at the joint positions being published), a screenshot of rviz for the report once
that is measured, the slider publisher naming the wheel joints, and a wheel position
published as the sliders do turning the wheel's frame by it.

The slider window cannot be dragged here, so once it is seen publishing the wheel joints
its process is paused (SIGSTOP) while the probe publishes /joint_states in its place, and
resumed (SIGCONT) after. Paused, not stopped: a launch file may mark the slider node
``required="true"``, and a required node that ends takes the whole launch down (rviz,
robot_state_publisher) for a reason that is the grader's, not the student's."""
from __future__ import annotations

import math
import os
import signal
import threading
from typing import Dict, List
from xmlrpc.client import ServerProxy

import numpy as np
import rosgraph
import rosnode
import rospy
import tf2_ros
from sensor_msgs.msg import JointState

from course_grader import screenshot
from course_grader.probe_tools import (ProbeError, check, publishers_of, robot_description,
                                       wait_until)
from course_grader.ros_run import SESSION_TAG
from course_grader.urdf_checks import part_link
from urdf_tools.kinematics import link_transform


def _matrix(transform) -> np.ndarray:
    t, q = transform.transform.translation, transform.transform.rotation
    x, y, z, w = q.x, q.y, q.z, q.w
    m = np.eye(4)
    m[:3, :3] = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                 [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                 [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    m[:3, 3] = [t.x, t.y, t.z]
    return m


def _difference(a: np.ndarray, b: np.ndarray):
    """(metres, degrees) between two poses."""
    distance = float(np.linalg.norm(a[:3, 3] - b[:3, 3]))
    cos_angle = (np.trace(a[:3, :3].T @ b[:3, :3]) - 1.0) / 2.0
    return distance, math.degrees(math.acos(max(-1.0, min(1.0, cos_angle))))


class JointStates:
    """The latest /joint_states positions, by joint name."""

    def __init__(self):
        self.positions: Dict[str, float] = {}
        self.lock = threading.Lock()
        rospy.Subscriber("/joint_states", JointState, self._on_message, queue_size=10)

    def _on_message(self, message) -> None:
        with self.lock:
            self.positions.update(zip(message.name, message.position))

    def snapshot(self) -> Dict[str, float]:
        with self.lock:
            return dict(self.positions)


def measure(course, folder: str = "") -> Dict:
    spec, limit = course.checks["display"], course.limits["startup"]
    model = robot_description(limit)
    root = model.root()
    links = [name for name in model.links if name != root]
    states = JointStates()
    buffer = tf2_ros.Buffer()
    tf2_ros.TransformListener(buffer)
    movable = [j.name for j in model.joints.values() if j.movable]
    if movable:
        wait_until(lambda: set(movable) <= set(states.snapshot()), limit,
                   f"/joint_states naming {movable}")

    def all_frames():
        return all(buffer.can_transform(root, link, rospy.Time(0)) for link in links)
    try:
        wait_until(all_frames, spec["settle"] + limit, f"TF from {root} to every link")
    except RuntimeError:
        pass
    errors, absent = {}, []
    positions = states.snapshot()
    for link in links:
        try:
            seen = _matrix(buffer.lookup_transform(root, link, rospy.Time(0)))
        except tf2_ros.TransformException:
            absent.append(link)
            continue
        errors[link] = _difference(seen, link_transform(model, root, link, positions))
    worst_m = max((e[0] for e in errors.values()), default=0.0)
    worst_deg = max((e[1] for e in errors.values()), default=0.0)
    wrong = [link for link, (m, deg) in errors.items()
             if m > spec["position_tolerance"] or deg > spec["angle_tolerance"]]
    tf_ok = not absent and not wrong
    display_checks = [check(
        "TF of every link as the URDF", tf_ok,
        f"{len(errors)} of {len(links)} links in TF from {root}, largest difference "
        f"{1000 * worst_m:.1f} mm, {worst_deg:.2f} deg"
        + (f"; missing {absent}" if absent else "") + (f"; off {wrong}" if wrong else ""))]
    viewers = [n for n in rosnode.get_node_names() if "rviz" in n]
    notes = [f"rviz nodes running: {viewers or 'none'}"]
    picture = _screenshot(course, folder, tf_ok, viewers)
    wheel_checks, wheel_notes = _wheels(course, model, states, buffer)
    return {"checks": {"display_links_tf": display_checks, "wheel_joints_move": wheel_checks},
            "notes": {"display_links_tf": notes, "wheel_joints_move": wheel_notes},
            "figures": {"display_links_tf": [picture]}}


def _screenshot(course, folder: str, tf_ok: bool, viewers: List[str]) -> Dict:
    """The virtual screen once TF is measured (the robot as rviz draws it), saved as
    display.png in the report's folder; or why there is none."""
    title = "rviz showing display.launch"
    if not folder:
        return {"title": title, "missing": "the probe was given no folder for pictures"}
    spec = dict(course.report["screenshot"])
    if not viewers:       # no rviz node: look for its window once, do not wait for it
        spec["timeout"] = 0.0
    shot = screenshot.take(os.environ.get("DISPLAY", ""), os.path.join(folder, screenshot.REPORT_FILE),
                           spec["window"], spec)
    if not shot.path:
        return {"title": title, "missing": f"{shot.why} (rviz nodes running: "
                                           f"{', '.join(viewers) or 'none'})"}
    return {"title": title, "file": screenshot.REPORT_FILE, "caption": (
        f"The windows display.launch opened on the virtual screen (Xvfb, software GL; "
        f"{', '.join(repr(t) for t in shot.windows)}), {shot.seconds:.1f} s after the TF "
        f"check {'passed' if tf_ok else 'failed'}: {shot.colours} colours"
        + ("" if shot.settled else ", still changing when taken") + ".")}


def _node_pids(nodes: List[str]) -> Dict[str, int]:
    """The process of each node (its XML-RPC getPid), only those of this scenario: carrying
    the probe's own SESSION_TAG, as every process the grader starts for a scenario does."""
    master = rosgraph.Master(rospy.get_name())
    tag = os.environ.get(SESSION_TAG)
    pids = {}
    for node in nodes:
        uri = rosnode.get_api_uri(master, node, skip_cache=True)
        if not uri:
            raise ProbeError(f"the node {node} has no API address at the master")
        code, message, pid = ServerProxy(uri).getPid(rospy.get_name())
        if code != 1:
            raise ProbeError(f"the node {node} did not give its process id: {message}")
        if tag is not None:
            try:
                with open(f"/proc/{pid}/environ", "rb") as stream:
                    ours = f"{SESSION_TAG}={tag}".encode() in stream.read().split(b"\0")
            except OSError:
                ours = False
            if not ours:
                raise ProbeError(f"the node {node} (process {pid}) is not one this scenario "
                                 "started")
        pids[node] = int(pid)
    return pids


def _signal_all(pids: Dict[str, int], number: int) -> None:
    for pid in pids.values():
        try:
            os.kill(pid, number)
        except ProcessLookupError:
            pass


def _wheels(course, model, states, buffer):
    """The wheel item's checks and notes."""
    wheels = [link for link in (part_link(model, course.urdf, w)
                                for w in course.urdf["wheels"]["links"]) if link is not None]
    joints = [model.parent_joint(w) for w in wheels]
    joints = [j for j in joints if j is not None and j.movable]
    if not joints:
        return [check("wheel joints", False,
                      f"no movable joint above {wheels or 'the wheels'}")], []
    names = [j.name for j in joints]
    publishers = [n for n in publishers_of("/joint_states") if n != rospy.get_name()]
    published = set(names) <= set(states.snapshot())
    checks = [check("sliders publish the wheel joints", published and bool(publishers),
                    f"{publishers or 'nobody'} publish(es) /joint_states with "
                    f"{sorted(set(names) & set(states.snapshot()))}")]
    pids = _node_pids(publishers)
    _signal_all(pids, signal.SIGSTOP)
    try:
        return checks + [_turn_wheels(course, model, joints, buffer)], [
            f"{', '.join(publishers)} (process {', '.join(map(str, pids.values()))}) paused "
            "(SIGSTOP) while the probe published the wheel position, resumed (SIGCONT) after"]
    finally:
        _signal_all(pids, signal.SIGCONT)


def _turn_wheels(course, model, joints, buffer) -> Dict:
    """Publishes the wheel joints at ``wheel_angle`` on /joint_states, as the sliders do;
    the check that each wheel's frame turned by it."""
    spec, limit = course.checks["display"], course.limits["startup"]
    names = [j.name for j in joints]
    angle = spec["wheel_angle"]
    command = JointState(name=[j.name for j in model.joints.values() if j.movable])
    command.position = [angle if n in names else 0.0 for n in command.name]
    publisher = rospy.Publisher("/joint_states", JointState, queue_size=1)
    turned = {}

    def follows():
        command.header.stamp = rospy.Time.now()
        publisher.publish(command)
        for joint in joints:
            try:
                seen = _matrix(buffer.lookup_transform(joint.parent, joint.child, rospy.Time(0)))
            except tf2_ros.TransformException:
                return False
            expected = link_transform(model, joint.parent, joint.child, {joint.name: angle})
            turned[joint.name] = _difference(seen, expected)[1]
        return all(deg <= spec["wheel_tolerance"] for deg in turned.values())
    try:
        wait_until(follows, limit, f"the wheels' TF to turn by {angle} rad")
        moved = True
    except RuntimeError:
        moved = False
    return check(
        "wheel frames turn with the joint", moved,
        f"{', '.join(names)} at {angle:g} rad: frames within "
        + ", ".join(f"{deg:.2f}" for deg in turned.values()) + f" deg of it "
        f"(tolerance {spec['wheel_tolerance']:g})")

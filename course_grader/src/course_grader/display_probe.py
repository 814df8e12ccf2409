"""Task 1 measured on ``display.launch`` as typed: every link's TF as robot_description
says (at the joint positions being published), the slider publisher naming the wheel
joints, and a wheel position published as the sliders do turning the wheel's frame by it.

The slider window cannot be dragged here, so once it is seen publishing the wheel joints
its node is stopped and the probe publishes /joint_states in its place."""
from __future__ import annotations

import math
import threading
from typing import Dict

import numpy as np
import rosnode
import rospy
import tf2_ros
from sensor_msgs.msg import JointState

from course_grader.probe_tools import check, publishers_of, robot_description, wait_until
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


def measure(course) -> Dict:
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
    return {"checks": {"display_links_tf": display_checks,
                       "wheel_joints_move": _wheels(course, model, states, buffer)},
            "notes": {"display_links_tf": notes}}


def _wheels(course, model, states, buffer):
    spec, limit = course.checks["display"], course.limits["startup"]
    wheels = [w for w in course.urdf["wheels"]["links"] if w in model.links]
    joints = [model.parent_joint(w) for w in wheels]
    joints = [j for j in joints if j is not None and j.movable]
    if not joints:
        return [check("wheel joints", False, f"no movable joint above {wheels or 'the wheels'}")]
    names = [j.name for j in joints]
    publishers = [n for n in publishers_of("/joint_states") if n != rospy.get_name()]
    published = set(names) <= set(states.snapshot())
    checks = [check("sliders publish the wheel joints", published and bool(publishers),
                    f"{publishers or 'nobody'} publish(es) /joint_states with "
                    f"{sorted(set(names) & set(states.snapshot()))}")]
    rosnode.kill_nodes(publishers)
    wait_until(lambda: not [n for n in publishers_of("/joint_states") if n != rospy.get_name()],
               limit, f"{publishers} to stop publishing /joint_states")
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
    checks.append(check(
        "wheel frames turn with the joint", moved,
        f"{', '.join(names)} at {angle:g} rad: frames within "
        + ", ".join(f"{deg:.2f}" for deg in turned.values()) + f" deg of it "
        f"(tolerance {spec['wheel_tolerance']:g})"))
    return checks

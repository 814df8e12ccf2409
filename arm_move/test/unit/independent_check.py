"""An independent collision check for planned paths: the arm's URDF collision shapes and
the scene's boxes in pybullet (exact boxes and cylinders, no spheres, no padding), every
path state no more than a degree apart in every joint. It shares nothing with the
planner's checker but the list of self-collision pairs (as MoveIt's checker and its
planner share an SRDF)."""
import math

import numpy as np
import pybullet as pb

from arm_move.kinematics import ARM_JOINTS, FINGER_JOINTS

# the planner's link groups, by URDF link
GROUP_LINKS = {
    "base": ["base_link"],
    "shoulder": ["shoulder_link"],
    "upper_arm": ["upper_arm_link"],
    "forearm": ["forearm_link"],
    "hand": ["gripper_link", "gripper_bar_link", "left_finger_link", "right_finger_link"],
}
MOVING_GROUPS = ("upper_arm", "forearm", "hand")


class IndependentChecker:
    def __init__(self, urdf_path, prefix, self_pairs, scene_boxes, floor_z):
        self.client = pb.connect(pb.DIRECT)
        self.arm = pb.loadURDF(urdf_path, useFixedBase=True, physicsClientId=self.client,
                               flags=pb.URDF_USE_IMPLICIT_CYLINDER)
        links, joints = {f"{prefix}/base_link": -1}, {}  # the root is link -1
        for index in range(pb.getNumJoints(self.arm, physicsClientId=self.client)):
            info = pb.getJointInfo(self.arm, index, physicsClientId=self.client)
            joints[info[1].decode()] = index
            links[info[12].decode()] = index
        self.joint_index = [joints[name] for name in ARM_JOINTS]
        self.finger_index = [joints[name] for name in FINGER_JOINTS]
        self.group_links = {group: [links[f"{prefix}/{name}"] for name in names]
                            for group, names in GROUP_LINKS.items()}
        self.self_pairs = [(a, b) for a, b in self_pairs]
        self.obstacles = []
        for box in scene_boxes:
            shape = pb.createCollisionShape(pb.GEOM_BOX, halfExtents=list(np.asarray(box.size) / 2),
                                            physicsClientId=self.client)
            quaternion = list(box.orientation)
            self.obstacles.append((box.name, pb.createMultiBody(0, shape, -1, list(box.center),
                                                                 quaternion,
                                                                 physicsClientId=self.client)))
        plane = pb.createCollisionShape(pb.GEOM_PLANE, physicsClientId=self.client)
        self.obstacles.append(("floor", pb.createMultiBody(0, plane, -1, [0, 0, floor_z],
                                                           physicsClientId=self.client)))

    def close(self):
        pb.disconnect(self.client)

    def touches(self, q, finger):
        """What the arm touches at q ("self: a-b", an obstacle's name) or None."""
        for index, value in zip(self.joint_index, q):
            pb.resetJointState(self.arm, index, float(value), physicsClientId=self.client)
        for index in self.finger_index:
            pb.resetJointState(self.arm, index, float(finger), physicsClientId=self.client)
        for a, b in self.self_pairs:
            for la in self.group_links[a]:
                for lb in self.group_links[b]:
                    if pb.getClosestPoints(self.arm, self.arm, 0.0, la, lb,
                                           physicsClientId=self.client):
                        return f"self: {a}-{b}"
        for name, body in self.obstacles:
            for group in MOVING_GROUPS:
                for link in self.group_links[group]:
                    points = pb.getClosestPoints(self.arm, body, 0.0, link, -1,
                                                 physicsClientId=self.client)
                    if any(p[8] < 0.0 for p in points):
                        return name
        return None

    def clearance(self, path, finger, obstacle, step_degrees=1.0, reach=0.1):
        """The least distance (m) between the arm's moving links and one obstacle (by name)
        over the dense path; ``reach`` when nothing comes that close."""
        body = dict(self.obstacles)[obstacle]
        least = reach
        for q in self.dense(path, step_degrees):
            self.touches(q, finger)  # sets the joints
            for group in MOVING_GROUPS:
                for link in self.group_links[group]:
                    for point in pb.getClosestPoints(self.arm, body, reach, link, -1,
                                                     physicsClientId=self.client):
                        least = min(least, point[8])
        return least

    @staticmethod
    def dense(path, step_degrees=1.0):
        """The path's states, no more than ``step_degrees`` apart in every joint."""
        step = math.radians(step_degrees)
        for a, b in zip(path, path[1:]):
            a, b = np.asarray(a, float), np.asarray(b, float)
            count = max(1, int(math.ceil(np.max(np.abs(b - a)) / step)))
            for t in np.linspace(0.0, 1.0, count + 1):
                yield a + t * (b - a)

    def first_collision(self, path, finger, step_degrees=1.0):
        """The first state along the path (dense) that touches something, or None."""
        step = math.radians(step_degrees)
        for a, b in zip(path, path[1:]):
            a, b = np.asarray(a, float), np.asarray(b, float)
            count = max(1, int(math.ceil(np.max(np.abs(b - a)) / step)))
            for t in np.linspace(0.0, 1.0, count + 1):
                q = a + t * (b - a)
                hit = self.touches(q, finger)
                if hit:
                    return q, hit
        return None


"""moveit_commander.conversions: messages to and from bytes, poses and transforms to and
from lists ([x, y, z, qx, qy, qz, qw], or [x, y, z, roll, pitch, yaw])."""
from __future__ import annotations

from io import BytesIO

import rospy
from geometry_msgs.msg import Pose, PoseStamped, Transform
from tf.transformations import quaternion_from_euler

from moveit_commander.exception import MoveItCommanderException


def msg_to_string(msg) -> bytes:
    buffer = BytesIO()
    msg.serialize(buffer)
    return buffer.getvalue()


def msg_from_string(msg, data):
    msg.deserialize(data)
    return msg


def pose_to_list(pose_msg: Pose) -> list:
    p, o = pose_msg.position, pose_msg.orientation
    return [p.x, p.y, p.z, o.x, o.y, o.z, o.w]


def list_to_pose(pose_list) -> Pose:
    pose = Pose()
    values = list(pose_list)
    if len(values) not in (6, 7):
        raise MoveItCommanderException("Expected either 6 or 7 elements in list: (x,y,z,r,p,y) "
                                       "or (x,y,z,qx,qy,qz,qw)")
    pose.position.x, pose.position.y, pose.position.z = (float(v) for v in values[:3])
    q = values[3:] if len(values) == 7 else quaternion_from_euler(*values[3:])
    pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w = \
        (float(v) for v in q)
    return pose


def list_to_pose_stamped(pose_list, target_frame: str) -> PoseStamped:
    stamped = PoseStamped(pose=list_to_pose(pose_list))
    stamped.header.frame_id = target_frame
    stamped.header.stamp = rospy.Time.now()
    return stamped


def transform_to_list(trf_msg: Transform) -> list:
    t, r = trf_msg.translation, trf_msg.rotation
    return [t.x, t.y, t.z, r.x, r.y, r.z, r.w]


def list_to_transform(trf_list) -> Transform:
    transform = Transform()
    values = list(trf_list)
    transform.translation.x, transform.translation.y, transform.translation.z = values[:3]
    (transform.rotation.x, transform.rotation.y, transform.rotation.z,
     transform.rotation.w) = values[3:7]
    return transform

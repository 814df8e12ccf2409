"""The planning scene and the planned path as rviz markers (frame: the planning frame)."""
from __future__ import annotations

from typing import Iterable, Sequence

from geometry_msgs.msg import Point, Pose, Quaternion
from std_msgs.msg import ColorRGBA
from visualization_msgs.msg import Marker, MarkerArray

from arm_move.collision import Scene

SCENE_COLOUR = ColorRGBA(0.2, 0.6, 0.3, 0.6)
PATH_COLOUR = ColorRGBA(1.0, 0.5, 0.0, 1.0)


def scene_markers(scene: Scene, frame: str, stamp, held: Sequence = ()) -> MarkerArray:
    """One cube per scene box and per ``held`` box (an attached object where the hand holds
    it); deletes what was drawn before (objects may go away)."""
    markers = MarkerArray()
    clear = Marker(action=Marker.DELETEALL)
    clear.header.frame_id = frame
    markers.markers.append(clear)
    for index, box in enumerate(list(scene.boxes.values()) + list(held)):
        marker = Marker(type=Marker.CUBE, action=Marker.ADD, id=index, ns=box.name,
                        color=SCENE_COLOUR)
        marker.header.frame_id, marker.header.stamp = frame, stamp
        marker.pose = Pose(Point(*box.center), Quaternion(*box.orientation))
        marker.scale.x, marker.scale.y, marker.scale.z = box.size
        markers.markers.append(marker)
    return markers


def path_marker(points: Iterable[Sequence[float]], frame: str, stamp) -> Marker:
    """The gripper point's way along a plan, as a line."""
    marker = Marker(type=Marker.LINE_STRIP, action=Marker.ADD, ns="planned_path", id=0,
                    color=PATH_COLOUR)
    marker.header.frame_id, marker.header.stamp = frame, stamp
    marker.pose.orientation.w = 1.0
    marker.scale.x = 0.004
    marker.points = [Point(*map(float, p)) for p in points]
    return marker

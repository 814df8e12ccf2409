"""``roscpp_initialize`` and ``roscpp_shutdown``: the real commander starts roscpp for its
C++ core; this one is rospy all through, so they only keep the arguments (remappings and
``__ns:=`` apply through rospy.init_node) and end the node at shutdown. Scripts call them
around ``rospy.init_node`` as MoveIt's tutorial does; they may also be left out."""
from __future__ import annotations

from typing import List, Optional

import rospy

_ARGS: List[str] = []


def roscpp_initialize(args: Optional[List[str]] = None) -> None:
    _ARGS[:] = [a for a in (args or []) if not a.startswith("__name:=")]


def roscpp_shutdown() -> None:
    if rospy.core.is_initialized():
        rospy.signal_shutdown("moveit_commander.roscpp_shutdown")


def ensure_node() -> None:
    """A node for the commander's subscriptions when the script started none (as the C++
    wrappers start one of their own)."""
    if not rospy.core.is_initialized():
        rospy.init_node("moveit_python_wrappers", anonymous=True, disable_signals=True)

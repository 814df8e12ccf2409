"""Ctrl-C and SIGTERM for a node whose main thread does ROS work: a flag, not rospy's handler.

rospy's own handler runs the node's whole shutdown inside the signal handler, that is in
the middle of whatever the main thread was doing. The simulator's main thread publishes
/clock hundreds of times a second; when the signal arrived inside ``Publisher.publish``,
which holds the connection's lock, the shutdown closed that connection and waited for the
same lock, for ever (seen with py-spy; 1 stop in 20 at full speed). Later signals reached
the same handler, which does nothing once a shutdown has begun, so only SIGKILL ended it.

So such a node starts rospy with ``disable_signals=True`` and installs :class:`StopSignals`:
the handler only records the request, and the main loop, between two pieces of work,
sees it and shuts rospy down from a clean point (:func:`shut_rospy_down`). A second signal
while that shutdown is under way ends the process at once, as a user pressing Ctrl-C twice
expects.
"""
from __future__ import annotations

import os
import signal
import sys
from typing import Optional

import rospy
import rospy.core
from rospy.impl.registration import RegManager, get_registration_listeners

# what the process exits with when a second signal cuts its shutdown short
FORCED_EXIT_STATUS = 1


class StopSignals:
    """Records SIGINT and SIGTERM; :attr:`requested` is true once one arrived."""

    def __init__(self):
        self.reason: Optional[str] = None

    def install(self) -> "StopSignals":
        signal.signal(signal.SIGINT, self._handle)
        signal.signal(signal.SIGTERM, self._handle)
        return self

    @property
    def requested(self) -> bool:
        return self.reason is not None

    def _handle(self, number, _frame) -> None:
        name = signal.Signals(number).name
        if self.reason is not None:
            print(f"{name} again while stopping: exiting now", file=sys.stderr)
            os._exit(FORCED_EXIT_STATUS)
        self.reason = name


def shut_rospy_down(reason: str) -> None:
    """``rospy.signal_shutdown(reason)``, without waiting out rospy's registration thread:
    that thread waits on its condition 0.5 s at a time and looks for the shutdown only
    then, and signal_shutdown joins it, so every stop of the simulator took 0.6-0.7 s
    (measured with py-spy dumps every 50 ms). A shutdown hook, run once the shutdown flag
    is up, wakes it instead; it sees the flag and ends."""
    managers = [listener for listener in get_registration_listeners().listeners
                if isinstance(listener, RegManager)]

    def wake(_reason):
        for manager in managers:
            with manager.cond:
                manager.cond.notify_all()
    rospy.core.add_shutdown_hook(wake)
    rospy.signal_shutdown(reason)

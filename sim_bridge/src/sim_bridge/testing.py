"""For tests that run against sim_bridge (its own rostests and other packages'): waiting
on a condition with a timeout, in wall-clock time, instead of sleeping a fixed time."""
from __future__ import annotations

import time

import rospy

TIMEOUT = 60.0  # wall seconds any one wait may take


def wait_until(condition, what: str, timeout: float = TIMEOUT, interval: float = 0.01) -> None:
    """Polls ``condition`` until it is true; AssertionError naming ``what`` after ``timeout``."""
    end = time.monotonic() + timeout
    while not rospy.is_shutdown():
        if condition():
            return
        if time.monotonic() > end:
            raise AssertionError(f"timed out after {timeout:.0f} s waiting for {what}")
        time.sleep(interval)


def service_proxy(name: str, service_class, timeout: float = TIMEOUT) -> rospy.ServiceProxy:
    """A proxy for ``name`` once the service is there (the simulator advertises its
    services one after another: one being up says nothing of the next)."""
    rospy.wait_for_service(name, timeout=timeout)
    return rospy.ServiceProxy(name, service_class)

"""What the probes share: bounded waits, a check's JSON form, the master's view of who
publishes and subscribes, and robot_description parsed."""
from __future__ import annotations

import time
from typing import Callable, Dict, List

import rosgraph
import rospy

POLL = 0.02   # s (wall) between looks at a condition


class ProbeError(RuntimeError):
    """A measurement could not be made; the message names what was awaited."""


def wait_until(condition: Callable, timeout: float, what: str):
    deadline = time.monotonic() + timeout
    while not rospy.is_shutdown():
        result = condition()
        if result:
            return result
        if time.monotonic() > deadline:
            raise ProbeError(f"timed out after {timeout:.0f} s waiting for {what}")
        time.sleep(POLL)
    raise ProbeError(f"shut down while waiting for {what}")


def check(name: str, passed: bool, evidence: str) -> Dict:
    return {"name": name, "passed": bool(passed), "evidence": evidence}


def system_state():
    return rosgraph.Master(rospy.get_name()).getSystemState()


def publishers_of(topic: str) -> List[str]:
    return next((nodes for name, nodes in system_state()[0] if name == topic), [])


def subscribers_of(topic: str) -> List[str]:
    return next((nodes for name, nodes in system_state()[1] if name == topic), [])


def robot_description(timeout: float):
    from urdf_tools import parse_urdf
    wait_until(lambda: rospy.has_param("/robot_description"), timeout,
               "the parameter /robot_description")
    return parse_urdf(rospy.get_param("/robot_description"), "/robot_description")

"""Runs the platform's joint_state_publisher_gui node, made to work with its PyQt5.

This package has the upstream name, so ``pkg="joint_state_publisher_gui"`` in a course's
display.launch finds this node first; the platform's own node is then found by path, in the
prefixes after this workspace's."""
from __future__ import annotations

import os
import runpy
import sys

from slider_fix.qt_sliders import accept_float_slider_values

NODE = os.path.join("lib", "joint_state_publisher_gui", "joint_state_publisher_gui")


def platform_node() -> str:
    """Debian's (or any underlay's) node script: the first on CMAKE_PREFIX_PATH, then /usr,
    that builds the GUI itself (this package's node and catkin's relays to it do not)."""
    prefixes = [p for p in os.environ.get("CMAKE_PREFIX_PATH", "").split(os.pathsep) if p]
    for prefix in prefixes + ["/usr"]:
        candidate = os.path.join(prefix, NODE)
        if os.path.isfile(candidate):
            with open(candidate, encoding="utf-8") as stream:
                if "JointStatePublisherGui(" in stream.read():
                    return candidate
    sys.exit("joint_state_publisher_gui: the platform's node is not installed "
             "(Debian: apt-get install joint-state-publisher-gui)")


def main() -> None:
    script = platform_node()
    accept_float_slider_values()
    sys.argv[0] = script
    runpy.run_path(script, run_name="__main__")

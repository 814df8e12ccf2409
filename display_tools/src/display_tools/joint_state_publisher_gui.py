"""Runs the platform's joint_state_publisher_gui, made to work with its PyQt5."""
from __future__ import annotations

import runpy
import sys

import roslib.packages

from display_tools.qt_sliders import accept_float_slider_values


def main() -> None:
    script = roslib.packages.find_node("joint_state_publisher_gui", "joint_state_publisher_gui")
    if not script:
        sys.exit("joint_state_publisher_gui is not installed (Debian: joint-state-publisher-gui)")
    accept_float_slider_values()
    sys.argv[0] = script[0]
    runpy.run_path(script[0], run_name="__main__")

"""``make demo``: shows the RB1 description in rviz.

With a screen (DISPLAY set and answering) it runs ``roslaunch my_rb1_description
display.launch`` in the foreground, sliders included, until rviz is closed. Without one it
renders rviz under Xvfb, saves a screenshot, prints its path and exits 0.
"""
from __future__ import annotations

import os
import subprocess
import sys

import headless

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUTPUT = os.path.join(REPO, "test_results", "demo")


def have_screen() -> bool:
    display = os.environ.get("DISPLAY")
    return bool(display) and subprocess.run(["xdpyinfo", "-display", display],
                                            capture_output=True, check=False).returncode == 0


def main() -> int:
    if have_screen():
        print("demo: a screen is present; starting display.launch (close rviz to end)")
        return subprocess.run(["roslaunch", "my_rb1_description", "display.launch"],
                              check=False).returncode
    os.makedirs(OUTPUT, exist_ok=True)
    shot = os.path.join(OUTPUT, "rb1_display.png")
    log = os.path.join(OUTPUT, "display.launch.log")
    print("demo: no screen; rendering display.launch in rviz under Xvfb")
    with headless.private_master(os.path.join(OUTPUT, "ros_home")) as env, \
            headless.virtual_display() as display:
        env.update(DISPLAY=display, LIBGL_ALWAYS_SOFTWARE="1")
        with headless.roslaunch(["my_rb1_description", "display.launch", "gui:=false"],
                                env, log) as launch:
            headless.stable_screenshot(display, shot, "RViz", launch)
    print(f"demo: screenshot saved: {shot}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

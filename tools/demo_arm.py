"""``make demo-arm``: the homework's arm in MoveIt's rviz, with its planning scene.

Runs ``roslaunch arm_move arm.launch use_sim:=true fake:=true`` (Interbotix's px100 on
MoveIt's fake controllers, the mover, rviz with the MotionPlanning display) on the screen if
there is one, otherwise under Xvfb; puts the RealSense box on the table with ``/px100/reset``
and moves the gripper above the block with ``/px100/step``, as the README shows; saves an
rviz screenshot (the arm, the table, the block and the box), prints its path and exits 0. A
launch whose rviz died of a signal is started again (headless.run_while_node_lives).
"""
from __future__ import annotations

import os
import subprocess
import sys

import headless

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUTPUT = os.path.join(REPO, "test_results", "demo_arm")
TIMEOUT = 90.0  # wall seconds for MoveIt and the mover to come up
RESET = ("{box_pose: {position: {x: 0.16, y: -0.17, z: 0.025}, orientation: {w: 1}}, "
         "clear_waypoints: true}")
STEP = "{position: {x: 0.15, y: 0.09, z: 0.1}, gripper_open: true}"


def call(env, service: str, request: str) -> str:
    print(f'demo-arm: rosservice call {service} "{request}"')
    answer = subprocess.run(["rosservice", "call", service, request], env=env,
                            capture_output=True, text=True, timeout=TIMEOUT, check=True).stdout
    print("demo-arm: " + " ".join(answer.split()))
    return answer


def main() -> int:
    os.makedirs(OUTPUT, exist_ok=True)
    shot = os.path.join(OUTPUT, "arm_planning_scene.png")
    log = os.path.join(OUTPUT, "arm.launch.log")
    with headless.private_master(os.path.join(OUTPUT, "ros_home")) as env, \
            headless.screen_or_virtual("demo-arm") as display:
        env.update(DISPLAY=display, LIBGL_ALWAYS_SOFTWARE="1")
        print(f"demo-arm: roslaunch arm_move arm.launch use_sim:=true fake:=true (log {log})")

        def picture(launch: headless.Launch) -> bool:
            headless.wait_until(lambda: "/px100/step" in subprocess.run(
                ["rosservice", "list"], env=env, capture_output=True, text=True,
                check=False).stdout or not launch.running(), TIMEOUT, "the mover's services")
            if not launch.running():
                raise launch.exited_early()
            done = "val: 1" in call(env, "/px100/reset", RESET)
            done = "val: 1" in call(env, "/px100/step", STEP) and done
            headless.stable_screenshot(display, shot, "RViz", launch)
            return done

        done = headless.run_while_node_lives(["arm_move", "arm.launch", "use_sim:=true",
                                              "fake:=true"], env, log, picture)
    print(f"demo-arm: screenshot saved: {shot}")
    return 0 if done else 1


if __name__ == "__main__":
    sys.exit(main())

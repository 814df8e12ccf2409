"""``make demo``: the RB1 in the warehouse turns -90 degrees on request, and rviz shows it.

Runs ``roslaunch my_rb1_ros rotate_demo.launch`` (the warehouse on sim_bridge, the rotate
service, rviz with the robot, TF and the laser scan) on the screen if there is one,
otherwise under Xvfb; calls ``/rotate_robot`` with ``degrees: -90``; prints the answer and
the robot's true yaw before and after (from the simulator); pauses the physics so that the
picture is still, saves an rviz screenshot, prints its path and exits 0.
"""
from __future__ import annotations

import contextlib
import math
import os
import subprocess
import sys

import headless

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUTPUT = os.path.join(REPO, "test_results", "demo")
TIMEOUT = 90.0  # wall seconds for the simulation to come up, and for the rotation
DEGREES = -90


def real_screen() -> bool:
    display = os.environ.get("DISPLAY")
    return bool(display) and subprocess.run(["xdpyinfo", "-display", display],
                                            capture_output=True, check=False).returncode == 0


def true_yaw_degrees(get_state) -> float:
    from tf.transformations import euler_from_quaternion  # ROS's, once the workspace is set up
    q = get_state("my_rb1", "").pose.orientation
    return math.degrees(euler_from_quaternion((q.x, q.y, q.z, q.w))[2])


def main() -> int:
    os.makedirs(OUTPUT, exist_ok=True)
    shot = os.path.join(OUTPUT, "rb1_warehouse_rviz.png")
    log = os.path.join(OUTPUT, "rotate_demo.launch.log")
    on_screen = real_screen()
    if not on_screen:
        print("demo: no screen; rendering rviz under Xvfb")
    # On Xvfb everything renders in software: rviz alone, not pybullet's window as well.
    arguments = ["my_rb1_ros", "rotate_demo.launch", f"gui:={str(on_screen).lower()}"]
    screen = (contextlib.nullcontext(os.environ["DISPLAY"]) if on_screen
              else headless.virtual_display())
    with headless.private_master(os.path.join(OUTPUT, "ros_home")) as env, screen as display:
        env.update(DISPLAY=display, LIBGL_ALWAYS_SOFTWARE="1")
        os.environ.update(ROS_MASTER_URI=env["ROS_MASTER_URI"], ROS_HOME=env["ROS_HOME"],
                          ROS_IP="127.0.0.1")
        print(f"demo: roslaunch my_rb1_ros rotate_demo.launch (log {log})")
        with headless.roslaunch(arguments, env, log) as launch:
            import rosgraph
            import rospy
            from std_srvs.srv import Empty

            from my_rb1_ros.srv import Rotate
            from gazebo_msgs.srv import GetModelState

            headless.wait_until(lambda: rosgraph.is_master_online() or not launch.running(),
                                TIMEOUT, "the ROS master")
            rospy.init_node("demo", anonymous=True, disable_signals=True)
            rospy.wait_for_service("/rotate_robot", timeout=TIMEOUT)
            rospy.wait_for_service("/gazebo/get_model_state", timeout=TIMEOUT)
            get_state = rospy.ServiceProxy("/gazebo/get_model_state", GetModelState)
            headless.wait_until(lambda: get_state("my_rb1", "").success, TIMEOUT,
                                "the RB1 to be spawned")
            rospy.sleep(1.0)  # simulated time: let it settle on its wheels
            before = true_yaw_degrees(get_state)
            print(f'demo: rosservice call /rotate_robot "degrees: {DEGREES}"')
            result = rospy.ServiceProxy("/rotate_robot", Rotate)(DEGREES).result
            rospy.sleep(0.5)
            after = true_yaw_degrees(get_state)
            print(f"demo: result: {result}")
            print(f"demo: true yaw before {before:.2f} degrees, after {after:.2f} degrees "
                  f"(turned {math.remainder(after - before, 360):.2f})")
            rospy.ServiceProxy("/gazebo/pause_physics", Empty)()  # a still picture
            headless.stable_screenshot(display, shot, "RViz", launch)
    print(f"demo: screenshot saved: {shot}")
    return 0 if result.startswith("success") else 1


if __name__ == "__main__":
    sys.exit(main())

"""``make demo``: the RB1 in the warehouse turns -90 degrees on request, and rviz shows it.

Runs ``roslaunch my_rb1_ros rotate_demo.launch`` (the warehouse on sim_bridge, the rotate
service, rviz with the robot, TF and the laser scan) on the screen if there is one,
otherwise under Xvfb; calls ``/rotate_robot`` with ``degrees: -90``; prints the answer and
the robot's true yaw before and after (from the simulator); pauses the physics so that the
picture is still, saves an rviz screenshot, prints its path and exits 0. An rviz that dies
of a signal (Debian's, drawing in software: about 1 start in 25) is started again.
"""
from __future__ import annotations

import contextlib
import math
import os
import subprocess
import sys
from typing import Callable

import headless

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUTPUT = os.path.join(REPO, "test_results", "demo")
TIMEOUT = 90.0  # wall seconds for the simulation to come up, and for the rotation
DEGREES = -90
SETTLE = 2.0  # simulated s that an rviz started again runs before the picture (TF, scan)


def true_yaw_degrees(get_state) -> float:
    from tf.transformations import euler_from_quaternion  # ROS's, once the workspace is set up
    q = get_state("my_rb1", "").pose.orientation
    return math.degrees(euler_from_quaternion((q.x, q.y, q.z, q.w))[2])


def rviz_crashed(viewer: headless.Launch) -> bool:
    """rviz died of a signal: in the launch (roslaunch says so), or started by itself."""
    return headless.died_of_signal(viewer.output(), "rviz") or (
        viewer.process.poll() is not None and viewer.process.returncode < 0)


def rviz_picture(display: str, shot: str, launch: headless.Launch, env,
                 restarted: contextlib.ExitStack, physics: Callable[[bool], None],
                 settle: Callable[[], None]) -> None:
    """Saves rviz's picture with the physics paused (``physics(False)``). Debian's rviz
    now and then dies of a signal under Xvfb, as it starts or draws its first frames (see
    headless.RVIZ_STARTS): rviz is then started again by itself with the launch's view, as a
    user would, and given ``settle()`` with the physics running so that it has TF (up to
    RVIZ_STARTS starts in all; ``restarted`` stops them)."""
    view = os.path.join(subprocess.run(["rospack", "find", "my_rb1_description"], env=env,
                                       capture_output=True, text=True, check=True
                                       ).stdout.strip(), "rviz", "simulation.rviz")
    viewer = launch
    for start in range(1, headless.RVIZ_STARTS + 1):
        try:
            headless.wait_until(lambda: headless.window_mapped(display, "RViz")
                                or rviz_crashed(viewer) or not viewer.running(),
                                TIMEOUT, "rviz's window")
            if not rviz_crashed(viewer):
                if viewer is not launch:
                    settle()  # a new rviz has no TF yet: it comes while the physics runs
                physics(False)  # a still picture
                headless.stable_screenshot(display, shot, "RViz", viewer)
                return
        except RuntimeError:
            if not rviz_crashed(viewer) or start == headless.RVIZ_STARTS:
                raise
        if start == headless.RVIZ_STARTS:
            raise RuntimeError(f"rviz died of a signal {start} times; see {viewer.log_path}")
        log = os.path.join(OUTPUT, f"rviz-{start + 1}.log")
        print(f"demo: rviz died of a signal (see {viewer.log_path}); starting it again "
              f"(log {log})")
        physics(True)
        with open(log, "w", encoding="utf-8") as output:
            process = subprocess.Popen(["rosrun", "rviz", "rviz", "-d", view], env=env,
                                       stdout=output, stderr=subprocess.STDOUT,
                                       stdin=subprocess.DEVNULL, start_new_session=True)
        viewer = headless.Launch(process, log)
        restarted.callback(viewer.stop)


def main() -> int:
    os.makedirs(OUTPUT, exist_ok=True)
    shot = os.path.join(OUTPUT, "rb1_warehouse_rviz.png")
    log = os.path.join(OUTPUT, "rotate_demo.launch.log")
    on_screen = headless.real_screen()
    # On Xvfb everything renders in software: rviz alone, not pybullet's window as well.
    arguments = ["my_rb1_ros", "rotate_demo.launch", f"gui:={str(on_screen).lower()}"]
    screen = headless.screen_or_virtual("demo")
    with headless.private_master(os.path.join(OUTPUT, "ros_home")) as env, screen as display:
        env.update(DISPLAY=display, LIBGL_ALWAYS_SOFTWARE="1")
        os.environ.update(ROS_MASTER_URI=env["ROS_MASTER_URI"], ROS_HOME=env["ROS_HOME"],
                          ROS_IP="127.0.0.1")
        print(f"demo: roslaunch my_rb1_ros rotate_demo.launch (log {log})")
        with headless.roslaunch(arguments, env, log) as launch, \
                contextlib.ExitStack() as restarted:
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

            def physics(running: bool) -> None:
                name = "unpause_physics" if running else "pause_physics"
                rospy.ServiceProxy(f"/gazebo/{name}", Empty)()

            rviz_picture(display, shot, launch, env, restarted, physics,
                         lambda: rospy.sleep(SETTLE))
    print(f"demo: screenshot saved: {shot}")
    return 0 if result.startswith("success") else 1


if __name__ == "__main__":
    sys.exit(main())

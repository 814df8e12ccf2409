"""arm.launch as a user runs it on a screen: with the homework's use_sim:=true fake:=true,
Interbotix's MoveIt with its rviz and the mover start; reset and step answer from the
command line (rosservice, as the README shows) and rviz shows the arm. With use_sim:=false
(the real arm) the launch ends, naming the driver it needs."""
import os
import shutil
import subprocess

import headless

# the px100's lit grey links in MoveIt's saved view (see test_moveit_rviz)
ROBOT_PIXELS = 300


def call(env, *arguments):
    return subprocess.run(["rosservice", "call", *arguments], env=env, capture_output=True,
                          text=True, timeout=60, check=True).stdout


def test_services_answer_and_rviz_shows_the_arm(screen_env, results_dir, repo):
    log = os.path.join(results_dir, "arm.log")
    shot = os.path.join(results_dir, "arm_rviz.png")

    def services_then_picture(launch):
        headless.wait_until(lambda: "/px100/step" in subprocess.run(
            ["rosservice", "list"], env=screen_env, capture_output=True, text=True,
            check=False).stdout or not launch.running(), 90, "the mover's services")
        assert launch.running(), launch.output()[-2000:]
        reset = call(screen_env, "/px100/reset", "{box_pose: {position: {x: 0.16, y: -0.17, "
                     "z: 0.025}, orientation: {w: 1}}, clear_waypoints: true}")
        assert "val: 1" in reset, reset
        step = call(screen_env, "/px100/step", "{position: {x: 0.15, y: 0.09, z: 0.1}, "
                    "gripper_open: true}")
        assert "val: 1" in step, step
        headless.stable_screenshot(screen_env["DISPLAY"], shot, "RViz", launch)

    headless.run_while_node_lives(["arm_move", "arm.launch", "use_sim:=true",
                                   "fake:=true"], screen_env,
                                  log, services_then_picture)
    grey = headless.pixels_near(shot, "rgb(140,140,150)", fuzz="8%")
    assert grey > ROBOT_PIXELS, f"{grey} pixels look like the robot's grey links"
    if os.environ.get("UPDATE_DOC_IMAGES") == "1":
        shutil.copyfile(shot, os.path.join(repo, "arm_move", "doc", "arm_rviz.png"))


def test_the_real_arm_stops_naming_its_driver(ros_env, results_dir):
    done = subprocess.run(["roslaunch", "arm_move", "arm.launch", "use_sim:=false", "rviz:=false"],
                          env=ros_env, capture_output=True, text=True, timeout=120, check=False)
    output = done.stdout + done.stderr
    with open(os.path.join(results_dir, "arm.log"), "w", encoding="utf-8") as log:
        log.write(output)
    assert "the real arm's driver (Interbotix's interbotix_xs_sdk" in output, output[-2000:]
    assert "REQUIRED process [px100/xs_hardware_interface-2] has died" in output, output[-2000:]

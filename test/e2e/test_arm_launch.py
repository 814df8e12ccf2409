"""arm.launch as a user runs it: with fake:=true rviz shows the arm, the planning scene and
the planned path, and reset and step answer from the command line; with use_sim:=false and
no driver, the launch stops with a message naming what a driver must provide."""
import os
import shutil
import subprocess

import headless

# in the saved view the table's and the box's markers cover well over 100,000 pixels of the
# 1024x768 screen; the path, a 4 mm line, a few hundred
SCENE_PIXELS = 50000
PATH_PIXELS = 100


def call(env, *arguments):
    return subprocess.run(["rosservice", "call", *arguments], env=env, capture_output=True,
                          text=True, timeout=60, check=True).stdout


def test_rviz_shows_the_scene_and_the_path(screen_env, results_dir, repo):
    log = os.path.join(results_dir, "arm.log")
    shot = os.path.join(results_dir, "arm_rviz.png")
    with headless.roslaunch(["arm_move", "arm.launch", "fake:=true"], screen_env, log) as launch:
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
    # the scene's green (alpha 0.6 over the background) and the path's orange
    scene = headless.pixels_near(shot, "rgb(95,151,135)", fuzz="12%")
    path = headless.pixels_near(shot, "rgb(255,128,0)", fuzz="15%")
    assert scene > SCENE_PIXELS, f"{scene} pixels look like the planning scene"
    assert path > PATH_PIXELS, f"{path} pixels look like the planned path"
    if os.environ.get("UPDATE_DOC_IMAGES") == "1":
        shutil.copyfile(shot, os.path.join(repo, "arm_move", "doc", "arm_rviz.png"))


def test_without_a_driver_the_launch_stops_naming_what_is_missing(ros_env, results_dir):
    result = subprocess.run(
        ["roslaunch", "-p", ros_env["ROS_MASTER_URI"].rsplit(":", 1)[1], "arm_move",
         "arm.launch", "use_sim:=false", "rviz:=false", "driver_timeout:=2"],
        env=ros_env, capture_output=True, text=True, timeout=90, check=False)
    output = result.stdout + result.stderr
    assert "no driver answers on /px100/arm_controller/follow_joint_trajectory" in output, \
        output[-3000:]
    for topic in ("/px100/joint_states", "gripper_controller/follow_joint_trajectory"):
        assert topic in output
    assert "mover" in output and "required" in output.lower()  # the launch ended with it

"""display.launch as a user runs it: rviz draws the RB1; a broken model stops the launch."""
import os
import shutil
import subprocess

import headless

HERE = os.path.dirname(os.path.abspath(__file__))
EMPTY = os.path.join(HERE, "data", "empty_robot.urdf")
# The body alone covers about 50,000 pixels of the 1024x768 screen in the saved view; the
# TF names and axes of an empty description differ by a few thousand at most.
ROBOT_PIXELS = 20000


def render(env, results_dir, name, *launch_args):
    log = os.path.join(results_dir, f"{name}.log")
    path = os.path.join(results_dir, f"{name}.png")
    with headless.roslaunch(["my_rb1_description", "display.launch", "gui:=false",
                             *launch_args], env, log) as launch:
        headless.stable_screenshot(env["DISPLAY"], path, "RViz", launch)
    return path


def test_rviz_draws_the_robot(screen_env, results_dir, repo):
    robot = render(screen_env, results_dir, "rb1")
    empty = render(screen_env, results_dir, "empty", f"model:={EMPTY}")
    robot_pixels = headless.differing_pixels(robot, empty)
    assert robot_pixels > ROBOT_PIXELS, f"only {robot_pixels} pixels show the robot"
    # keep the latest picture for the package's README when asked to
    if os.environ.get("UPDATE_DOC_IMAGES") == "1":
        shutil.copyfile(robot, os.path.join(repo, "my_rb1_description", "doc", "display.png"))


def test_a_malformed_model_stops_the_launch_naming_file_and_error(ros_env, results_dir):
    broken = os.path.join(results_dir, "broken_robot.urdf")
    with open(broken, "w", encoding="utf-8") as stream:
        stream.write('<robot name="broken">\n  <link name="base_link">\n</robot>\n')
    result = subprocess.run(
        ["roslaunch", "-p", ros_env["ROS_MASTER_URI"].rsplit(":", 1)[1], "my_rb1_description",
         "display.launch", f"model:={broken}", "gui:=false", "rviz:=false"],
        env=ros_env, capture_output=True, text=True, timeout=60, check=False)
    output = result.stdout + result.stderr
    assert result.returncode != 0
    assert broken in output
    assert "mismatched tag: line 3" in output

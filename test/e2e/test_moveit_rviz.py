"""xsarm_moveit.launch with its rviz (use_moveit_rviz's default): MoveIt's rviz plugins are
not provided, so rviz must start all the same, show the robot (its RobotModel display) and
say which class it could not load; move_group plans meanwhile."""
import os

import headless

# the px100's lit grey links (shoulder, hand, fingers) in the saved view: about 1000 pixels
# within 8 % of their colour on the 1024x768 screen; the grid's lines (about #5A5A5C) and
# the background (#303030) are farther than that
ROBOT_PIXELS = 300


def test_rviz_starts_shows_the_robot_and_names_the_missing_plugin(screen_env, results_dir):
    log = os.path.join(results_dir, "xsarm_moveit.log")
    shot = os.path.join(results_dir, "moveit_rviz.png")

    def picture_and_output(launch):
        headless.wait_until(lambda: "You can start planning now!" in launch.output()
                            or not launch.running(), 90, "move_group")
        headless.stable_screenshot(screen_env["DISPLAY"], shot, "RViz", launch)
        assert launch.running(), launch.output()[-3000:]
        return launch.output()

    output = headless.run_while_node_lives(
        ["interbotix_xsarm_moveit", "xsarm_moveit.launch", "robot_model:=px100", "dof:=4",
         "use_fake:=true"], screen_env, log, picture_and_output)
    assert "moveit_rviz_plugin/MotionPlanning" in output, output[-3000:]
    grey = headless.pixels_near(shot, "rgb(140,140,150)", fuzz="8%")
    assert grey > ROBOT_PIXELS, f"{grey} pixels look like the robot's grey links"

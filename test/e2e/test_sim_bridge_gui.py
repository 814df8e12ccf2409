"""gazebo_ros empty_world.launch gui:=true on a screen: sim_bridge shows pybullet's window."""
import os

import headless

ORANGE = "rgb(255,130,12)"  # Gazebo/Orange, the bench world's drums


def test_gui_window_shows_the_world(screen_env, results_dir, repo):
    world = os.path.join(repo, "tools", "bench", "bench.world")
    shot = os.path.join(results_dir, "sim_bridge_gui.png")
    with headless.roslaunch(["gazebo_ros", "empty_world.launch", "gui:=true",
                             f"world_name:={world}"], screen_env,
                            os.path.join(results_dir, "empty_world.log")) as launch:
        headless.stable_screenshot(screen_env["DISPLAY"], shot, "Bullet", launch, settle=2)
    # the drums are drawn: thousands of orange pixels (none without the world)
    assert headless.pixels_near(shot, ORANGE, "25%") > 2000

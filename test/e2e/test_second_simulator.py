"""A second simulator under the same name refuses to start and the first keeps running
with its world (before, the master shut the first down and the world was gone)."""
import subprocess

import headless

GZSERVER = ["rosrun", "gazebo_ros", "gzserver", "worlds/shapes.world"]


def world_properties(env):
    return subprocess.run(["rosservice", "call", "/gazebo/get_world_properties"], env=env,
                          capture_output=True, text=True, timeout=30, check=False).stdout


def test_a_second_simulator_stops_and_the_first_keeps_its_world(master):
    first = subprocess.Popen(GZSERVER, env=master, stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL, start_new_session=True)
    try:
        headless.wait_until(lambda: "box" in world_properties(master), 60,
                            "the first simulator's world")
        second = subprocess.run(GZSERVER, env=master, capture_output=True, text=True,
                                timeout=60, check=False)
        assert second.returncode == 255, second.stdout + second.stderr
        assert "a simulator is already running as /gazebo" in second.stderr
        assert first.poll() is None, "the first simulator stopped"
        assert "box" in world_properties(master)
    finally:
        first.terminate()
        first.wait(timeout=20)

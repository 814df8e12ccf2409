"""``verbose:=true`` on empty_world.launch, as the course template passes it: the console shows
what the simulator loads, as gzserver --verbose does, and nothing of rospy's internals.

Before, --verbose raised every rospy logger to DEBUG, and each subscriber that left printed
'[DEBUG] ...: ERROR: Broken Pipe', which reads as an error to a student."""
import os
import re
import subprocess

import headless

LAUNCH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "verbose_world.launch")
SPAWN_LIMIT = 60   # s (wall)
ECHO_LIMIT = 30    # s (wall) for one message


def echo_once(env, topic):
    echo = subprocess.run(["rostopic", "echo", "-n", "1", topic], env=env, capture_output=True,
                          text=True, timeout=ECHO_LIMIT, check=False)
    assert echo.returncode == 0, echo.stderr


def test_verbose_prints_the_simulators_messages_not_rospys(ros_env, results_dir):
    with headless.roslaunch([LAUNCH], ros_env, os.path.join(results_dir, "launch.log")) as run:
        headless.wait_until(lambda: "spawned model 'diff_bot'" in run.output(), SPAWN_LIMIT,
                            "the robot to be spawned")
        # subscribers come and go; each departure is met by the publisher's next message,
        # well before the next subscriber has started
        for topic in ("/odom", "/scan", "/odom", "/clock"):
            echo_once(ros_env, topic)
        output = run.output()
    assert "loaded world worlds/empty.world" in output
    assert "world model 'ground_plane'" in output
    drive = re.search(r"model 'diff_bot': plugin 'diff_drive' \(libgazebo_ros_diff_drive\.so\) "
                      r"loaded: (.*)", output)
    assert drive, output[-3000:]
    # the parameters it runs with, as written and as defaulted
    for words in ("<leftJoint> left_wheel_joint", "<wheelSeparation> 0.34",
                  "<publishWheelTF> False (default)"):
        assert words in drive.group(1), drive.group(1)
    assert "sensor 'laser_sensor' plugin 'laser' (libgazebo_ros_laser.so) loaded: " in output
    internals = [line for line in output.splitlines()
                 if "[DEBUG]" in line or "broken pipe" in line.lower()]
    assert not internals, internals[:5]

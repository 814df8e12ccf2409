"""The RB1 project as a student runs it: the course's commands as typed, and make demo."""
import os
import re
import subprocess
import sys

import headless


def test_course_commands_as_typed(ros_env, results_dir):
    with headless.roslaunch(["my_rb1_gazebo", "my_rb1_robot_warehouse.launch"], ros_env,
                            os.path.join(results_dir, "warehouse.log")) as warehouse:
        # the second command is typed once the first is up (its master included)
        headless.wait_until(lambda: "spawned model 'my_rb1'" in warehouse.output(), 90,
                            "the RB1 to be spawned in the warehouse")
        with headless.roslaunch(["my_rb1_ros", "rotate_service.launch"], ros_env,
                                os.path.join(results_dir, "rotate_service.log")) as service:
            headless.wait_until(lambda: "Service Ready" in service.output(), 90,
                                "rotate_service to say Service Ready")
            call = subprocess.run(["rosservice", "call", "/rotate_robot", "degrees: -90"],
                                  env=ros_env, capture_output=True, text=True, timeout=120,
                                  check=False)
            assert call.returncode == 0, call.stderr
            assert re.search(r'result: "success: rotated -90 degrees', call.stdout), call.stdout
            headless.wait_until(lambda: "Service Completed: success" in service.output(), 10,
                                "Service Completed in the service's log")
            assert "Service Requested" in service.output()


def test_make_demo_turns_the_robot_and_saves_a_screenshot(repo, results_dir):
    environment = dict(os.environ)
    environment.pop("DISPLAY", None)  # as on a machine without a screen
    demo = subprocess.run([sys.executable, os.path.join(repo, "tools", "demo.py")],
                          env=environment, capture_output=True, text=True, timeout=300,
                          check=False)
    assert demo.returncode == 0, demo.stdout + demo.stderr
    assert "demo: result: success: rotated -90 degrees" in demo.stdout
    turned = float(re.search(r"turned (-?[0-9.]+)\)", demo.stdout).group(1))
    assert abs(turned + 90.0) < 1.0
    shot = re.search(r"demo: screenshot saved: (\S+)", demo.stdout).group(1)
    assert os.path.isfile(shot)
    # the laser scan is drawn: red squares along the warehouse's walls and racks
    assert headless.pixels_near(shot, "rgb(255,40,40)", "20%") > 1000

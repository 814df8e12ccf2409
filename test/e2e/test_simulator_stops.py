"""The simulator stops on Ctrl-C, every time: started and stopped 50 times (with a robot,
running at full speed, paused, unpaused, with service calls in flight), each stop ends
within 2 s of the SIGINT roslaunch sends, and no simulator is left running. Before, a
SIGINT that arrived while the main thread was publishing /clock deadlocked rospy's
shutdown (sim_bridge.stop_signals)."""
import os
import subprocess
import sys

CYCLES = 50
STOP_LIMIT = 2.0  # s from SIGINT to the process's end


def test_fifty_starts_and_stops_each_end_within_two_seconds(master, repo, results_dir):
    robot = os.path.join(results_dir, "robot.urdf")
    with open(robot, "w") as stream:
        subprocess.run(["xacro", os.path.join(repo, "sim_bridge", "test", "data",
                                              "diff_bot.urdf.xacro")],
                       env=master, stdout=stream, check=True, timeout=60)
    run = subprocess.run([sys.executable, os.path.join(repo, "test", "e2e", "data",
                                                      "stop_cycles.py"), str(CYCLES), robot],
                         env=master, capture_output=True, text=True, timeout=CYCLES * 15)
    with open(os.path.join(results_dir, "cycles.txt"), "w") as stream:
        stream.write(run.stdout + run.stderr)
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    lines = [line.split() for line in run.stdout.splitlines() if line.startswith("cycle ")]
    assert len(lines) == CYCLES, run.stdout[-2000:]
    # each line: cycle <index> <state> <seconds or hung> <exit status>
    slow = [line[1:] for line in lines if line[3] == "hung" or float(line[3]) > STOP_LIMIT]
    assert not slow, f"stops over {STOP_LIMIT} s (cycle, state, seconds, status): {slow}"
    assert all(line[4] == "0" for line in lines), f"non-zero exit: {lines}"
    left = subprocess.run(["pgrep", "-f", "gazebo_ros/gzserver _real_time_factor:=0"],
                          capture_output=True, text=True)
    assert left.stdout == "", f"simulators left running: {left.stdout}"

"""The simulator stops on Ctrl-C, every time: started and stopped again and again (with a
robot, running at full speed, paused, unpaused, with service calls in flight), each stop
ends within 2 s of the SIGINT roslaunch sends, and no simulator is left running. Before, a
SIGINT that arrived while the main thread was publishing /clock deadlocked rospy's
shutdown (sim_bridge.stop_signals).

make test runs 12 cycles, each of the four states three times (about 20 s); make soak runs
the same check 50 times over (test/soak/test_simulator_stops_fifty_times.py), as this test
did in make test before: a race that shows once in many stops is the soak's to find."""
import os
import subprocess
import sys

CYCLES = 12       # make test: each of stop_cycles.py's four states three times
STOP_LIMIT = 2.0  # s from SIGINT to the process's end
CYCLE_LIMIT = 15  # s (wall) a cycle may take, start to stop, on a busy machine


def check_starts_and_stops(master, repo, results_dir, cycles):
    """Runs ``cycles`` start-and-stop cycles under ``master``; asserts each stopped within
    STOP_LIMIT with status 0 and that no simulator is left."""
    robot = os.path.join(results_dir, "robot.urdf")
    with open(robot, "w") as stream:
        subprocess.run(["xacro", os.path.join(repo, "sim_bridge", "test", "data",
                                              "diff_bot.urdf.xacro")],
                       env=master, stdout=stream, check=True, timeout=60)
    run = subprocess.run([sys.executable, os.path.join(repo, "test", "e2e", "data",
                                                      "stop_cycles.py"), str(cycles), robot],
                         env=master, capture_output=True, text=True,
                         timeout=cycles * CYCLE_LIMIT)
    with open(os.path.join(results_dir, "cycles.txt"), "w") as stream:
        stream.write(run.stdout + run.stderr)
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    lines = [line.split() for line in run.stdout.splitlines() if line.startswith("cycle ")]
    assert len(lines) == cycles, run.stdout[-2000:]
    # each line: cycle <index> <state> <seconds or hung> <exit status>
    slow = [line[1:] for line in lines if line[3] == "hung" or float(line[3]) > STOP_LIMIT]
    assert not slow, f"stops over {STOP_LIMIT} s (cycle, state, seconds, status): {slow}"
    assert all(line[4] == "0" for line in lines), f"non-zero exit: {lines}"
    left = subprocess.run(["pgrep", "-f", "gazebo_ros/gzserver _real_time_factor:=0"],
                          capture_output=True, text=True)
    assert left.stdout == "", f"simulators left running: {left.stdout}"


def test_twelve_starts_and_stops_each_end_within_two_seconds(master, repo, results_dir):
    check_starts_and_stops(master, repo, results_dir, CYCLES)

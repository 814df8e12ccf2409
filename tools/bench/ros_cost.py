"""Where the simulator's time goes on the ROS path, and its figures alone (issue 36).

Runs ``make bench``'s scene (tools/bench/bench.launch: the bench world and the RB1-class
robot driving its circle) the way ``tools/bench.py``'s ``measure_ros`` does, on a master
of its own, and prints one line per measure:

  fast   max real-time factor with /clock every step, and the simulator's CPU ms per
         simulated second
  paced  the same at real_time_factor:=1: CPU as a share of one core
  bare   ``bench.measure_bare``: the same scene's physics alone (no plugins, no ROS)

``--profile FILE`` also samples the simulator with py-spy (``--nonblocking``, 1 kHz) over
the first window measured (fast, else paced) and writes its collapsed stacks to FILE; ``--parts FILE`` prints the
stacks of such a file sorted into the parts the README's breakdown table lists (what runs
where, ms per simulated second when the run's simulated seconds are given).

Usage: python3 tools/bench/ros_cost.py [fast] [paced] [bare] [--profile FILE]
       python3 tools/bench/ros_cost.py --parts FILE SIMULATED_SECONDS

The machine is shared while this runs: compare runs made alternately, not single figures.
"""
from __future__ import annotations

import argparse
import collections
import os
import subprocess
import sys
import tempfile
import time
from typing import Dict, List, Optional, Sequence, Tuple

TOOLS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, TOOLS)
import bench  # noqa: E402  (tools/ is not a package)
import headless  # noqa: E402

SAMPLE_RATE = 1000  # py-spy's samples a second
# The parts of the breakdown, first match wins: (part, what in a stack marks it). A stack
# is py-spy's "function (file:line)" frames joined by ";", outermost first.
PARTS: Tuple[Tuple[str, Tuple[str, ...]], ...] = (
    ("pybullet.stepSimulation", ("step_physics (sim_bridge/world.py", "stepSimulation")),
    ("tyre friction", ("tyre_friction.py",)),
    ("laser: cast and message", ("plugins/laser.py", "ray_scene.py", "ray_kernel.py")),
    ("drive plugin: odometry, TF, joint states", ("plugins/diff_drive.py",)),
    ("/clock", ("ros_publishing.py",)),
    ("model_states, link_states, performance_metrics",
     ("_publish_model_states", "_publish_link_states", "_publish_performance")),
    ("service queue", ("serve (sim_bridge/ros_node.py",)),
    ("pacing (sleep)", ("_pace (sim_bridge/ros_node.py",)),
    ("other plugins, native plugin host", ("sim_bridge/plugins/", "native_plugins.py")),
    ("the step loop's own Python", ("run (sim_bridge/ros_node.py", "step (sim_bridge/world.py")),
)


def profile(pid: int, seconds: float, path: str) -> subprocess.Popen:
    """py-spy sampling ``pid`` for ``seconds`` into ``path`` (collapsed stacks), every
    thread, without stopping the process at each sample."""
    return subprocess.Popen(["py-spy", "record", "--nonblocking", "--format", "raw",
                             "--rate", str(SAMPLE_RATE), "--duration", str(int(seconds)),
                             "--threads", "--idle", "--pid", str(pid), "--output", path],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def user_and_system(pid: int) -> Tuple[float, float]:
    """The process's user and system CPU seconds so far."""
    with open(f"/proc/{pid}/stat", encoding="ascii") as stream:
        fields = stream.read().rsplit(")", 1)[1].split()
    tick = os.sysconf("SC_CLK_TCK")
    return int(fields[11]) / tick, int(fields[12]) / tick


def parts(path: str) -> Dict[str, int]:
    """Samples by part, the main thread's apart from other threads' (rospy's)."""
    counts: Dict[str, int] = collections.Counter()
    with open(path, encoding="utf-8") as stream:
        for line in stream:
            stack, _, count = line.rstrip("\n").rpartition(" ")
            if not stack:
                continue
            thread = stack.split(";", 1)[0]
            if "run (sim_bridge/ros_node.py" not in stack:
                counts["other threads (rospy's readers and writers, roscpp host)" if
                       "MainThread" not in thread and "main_thread" not in thread
                       else "main thread, outside the loop"] += int(count)
                continue
            counts["main thread, all"] += int(count)
            for part, marks in PARTS:
                if any(mark in stack for mark in marks):
                    counts[part] += int(count)
                    break
            else:
                counts["main thread, elsewhere"] += int(count)
    return counts


def measure(which: Sequence[str], profile_path: Optional[str]) -> Dict[str, Dict[str, float]]:
    results: Dict[str, Dict[str, float]] = {}
    with tempfile.TemporaryDirectory(prefix="ros_cost_") as output:
        bench.OUTPUT = output  # the launch logs, not make bench's folder
        with headless.private_master(os.path.join(output, "ros_home")) as env:
            os.environ.update(ROS_MASTER_URI=env["ROS_MASTER_URI"], ROS_HOME=env["ROS_HOME"],
                              ROS_IP="127.0.0.1")
            port = env["ROS_MASTER_URI"].rsplit(":", 1)[1]
            core = subprocess.Popen(["roscore", "-p", port], env=env,
                                    stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT,
                                    start_new_session=True)
            try:
                import rosgraph
                headless.wait_until(lambda: rosgraph.is_master_online(), 30, "the master")
                probe = bench.RosProbe()
                original = bench.measure_window
                sampler: List[subprocess.Popen] = []

                def window(probe_, pid):
                    if profile_path and not sampler:
                        sampler.append(profile(pid, bench.WINDOW, profile_path))
                    before = user_and_system(pid)
                    figures = original(probe_, pid)
                    after = user_and_system(pid)
                    # the simulator's CPU split: its own code against the kernel's work
                    # for it (sends, wake-ups, sleeps)
                    figures["user_ms_per_sim_s"], figures["sys_ms_per_sim_s"] = (
                        1000.0 * (b - a) / max(figures["rtf"] * bench.WINDOW, 1e-9)
                        for a, b in zip(before, after))
                    return figures

                bench.measure_window = window
                if "fast" in which:
                    results["fast"] = bench.measure_ros(env, probe, "fast")
                if "paced" in which:
                    results["paced"] = bench.measure_ros(env, probe, "paced",
                                                         real_time_factor="1")
                bench.measure_window = original
                if sampler:
                    sampler[0].wait(timeout=60)
            finally:
                core.terminate()
                core.wait(timeout=20)
    if "bare" in which:
        results["bare"] = {"rtf": bench.measure_bare()}
    return results


def main(argv: Optional[Sequence[str]] = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("which", nargs="*", default=["fast", "paced"],
                        help="fast, paced, bare (default: fast paced)")
    parser.add_argument("--profile", help="py-spy's collapsed stacks of the fast window")
    parser.add_argument("--parts", nargs=2, metavar=("FILE", "SIMULATED_SECONDS"),
                        help="sort a profile's stacks into parts")
    arguments = parser.parse_args(argv)
    if arguments.parts:
        counts = parts(arguments.parts[0])
        simulated = float(arguments.parts[1])
        for part, count in sorted(counts.items(), key=lambda item: -item[1]):
            # a sample is 1/SAMPLE_RATE s of the thread's wall time
            print(f"{part:55} {count:7d} samples  "
                  f"{1000.0 * count / SAMPLE_RATE / simulated:7.2f} ms per simulated s")
        return 0
    started = time.monotonic()
    results = measure(arguments.which, arguments.profile)
    for name, figures in results.items():
        line = " ".join(f"{key} {value:.3f}" for key, value in figures.items()
                        if key in ("rtf", "cpu", "cpu_ms_per_sim_s", "user_ms_per_sim_s",
                                   "sys_ms_per_sim_s"))
        print(f"{name}: {line}", flush=True)
    print(f"({time.monotonic() - started:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""``make bench``: sim_bridge's speed and memory, measured in one run, printed as a table.

The scene (tools/bench/): a closed hall with 40 static objects and an RB1-class robot
(diff drive, 720-beam laser at 20 Hz), driving in a circle while measured.

  max real-time factor, ROS     roslaunch bench.launch real_time_factor:=0; simulated
                                seconds per wall second over the window, from /clock
  max real-time factor, bare    the same world and robot built by sim_bridge's core, then
                                stepped by pybullet alone (stepSimulation, and the 720 rays
                                every 50 steps), no ROS
  ROS overhead                  bare / ROS
  CPU at real time              the simulator process's CPU time per wall second, paced
                                at real_time_factor:=1 (share of one core)
  first /scan                   wall seconds from starting roslaunch (master already up)
                                to the first /scan message
  peak RSS                      the simulator process's VmHWM
  planning time                 arm_move's planner on 200 random reachable, collision-free
                                targets in the table scene, each from where the last
                                ended (the unit test's targets): median and 95th percentile

The master is started first so that its start-up is not counted. Results also go to
bench_results/bench.txt.
"""
from __future__ import annotations

import os
import subprocess
import sys
import time
from typing import Dict, Optional

import headless

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUTPUT = os.path.join(REPO, "bench_results")
WINDOW = 10.0  # wall seconds each rate is measured over
TARGETS = {
    "max real-time factor, ROS": (">=", 10.0),
    "ROS overhead (bare / ROS)": ("<=", 1.5),
    "CPU at real time (% of a core)": ("<=", 15.0),
    "first /scan after roslaunch (s)": ("<=", 3.0),
    "peak RSS (MB)": ("<=", 300.0),
    "arm planning, median (ms)": ("<=", 50.0),
}
PLANNING_TARGETS = 200


def simulator_pid() -> Optional[int]:
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/cmdline", "rb") as stream:
                command = stream.read().split(b"\0")
        except OSError:
            continue
        if any(part.endswith(b"gazebo_ros/gzserver") for part in command) and \
                b"__name:=gazebo" in command:
            return int(entry)
    return None


def cpu_seconds(pid: int) -> float:
    with open(f"/proc/{pid}/stat", encoding="ascii") as stream:
        fields = stream.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def peak_rss_mb(pid: int) -> float:
    with open(f"/proc/{pid}/status", encoding="ascii") as stream:
        for line in stream:
            if line.startswith("VmHWM:"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


class RosProbe:
    """A rospy node in this process: the first /scan, the latest /clock, a driving command."""

    def __init__(self):
        import rospy
        from geometry_msgs.msg import Twist
        from rosgraph_msgs.msg import Clock
        from sensor_msgs.msg import LaserScan
        self.rospy = rospy
        rospy.init_node("bench_probe", anonymous=True, disable_signals=True)
        self.first_scan_wall: Optional[float] = None
        self.clock = 0.0
        rospy.Subscriber("/scan", LaserScan, self._on_scan, queue_size=1)
        rospy.Subscriber("/clock", Clock, self._on_clock, queue_size=1)
        self.command = rospy.Publisher("/cmd_vel", Twist, queue_size=1, latch=True)
        circle = Twist()
        circle.linear.x, circle.angular.z = 0.3, 0.5
        self.circle = circle

    def _on_scan(self, _message):
        if self.first_scan_wall is None:
            self.first_scan_wall = time.monotonic()

    def _on_clock(self, message):
        self.clock = message.clock.to_sec()

    def reset(self):
        self.first_scan_wall = None
        self.clock = 0.0


def measure_ros(env: Dict[str, str], probe: RosProbe, real_time_factor: str) -> Dict[str, float]:
    results: Dict[str, float] = {}
    probe.reset()
    log = os.path.join(OUTPUT, f"bench_rtf{real_time_factor}.log")
    started = time.monotonic()
    with headless.roslaunch([os.path.join(REPO, "tools", "bench", "bench.launch"),
                             f"real_time_factor:={real_time_factor}"], env, log) as launch:
        headless.wait_until(lambda: probe.first_scan_wall is not None or not launch.running(),
                            60, "the first /scan")
        if probe.first_scan_wall is None:
            raise RuntimeError(f"the simulator stopped; see {log}")
        results["first_scan"] = probe.first_scan_wall - started
        pid = simulator_pid()
        probe.command.publish(probe.circle)
        wall0, sim0, cpu0 = time.monotonic(), probe.clock, cpu_seconds(pid)
        headless.wait_until(lambda: time.monotonic() - wall0 >= WINDOW, WINDOW + 5, "the window")
        wall1, sim1, cpu1 = time.monotonic(), probe.clock, cpu_seconds(pid)
        results["rtf"] = (sim1 - sim0) / (wall1 - wall0)
        results["cpu"] = 100.0 * (cpu1 - cpu0) / (wall1 - wall0)
        results["rss"] = peak_rss_mb(pid)
    return results


def measure_bare() -> float:
    """Real-time factor of the same scene stepped by pybullet alone."""
    import pybullet as pb
    from geometry_msgs.msg import Twist

    from sim_bridge.plugins.base import Bus
    from sim_bridge.plugins.laser import Laser
    from sim_bridge.sdf_world import load_world
    from sim_bridge.world import World
    from urdf_tools.xacro_loader import expand

    class NullBus(Bus):
        class _Nothing:
            def publish(self, _message):
                pass

            def unregister(self):
                pass

        def publisher(self, topic, msg_class, queue_size=10, latch=False):
            return self._Nothing()

        def subscriber(self, topic, msg_class, callback):
            self.callback = callback
            return self._Nothing()

        def send_transforms(self, transforms):
            pass

        def info(self, text):
            pass

        def warn(self, text):
            pass

        def warn_throttled(self, key, period, text):
            pass

    bus = NullBus()
    world = World(bus)
    world.load_world(load_world(os.path.join(REPO, "tools", "bench", "bench.world")))
    xml = expand(os.path.join(REPO, "sim_bridge", "test", "data", "diff_bot.urdf.xacro"),
                 {"laser_samples": "720", "laser_half_fov_degrees": "135"})
    model = world.spawn_urdf("rb1_class", xml)
    laser = next(p for p in model.plugins if isinstance(p, Laser))
    drive = next(p for p in model.plugins if not isinstance(p, Laser))
    circle = Twist()
    circle.linear.x, circle.angular.z = 0.3, 0.5
    bus.callback(circle)
    drive.before_step(0)  # sets the wheel motors once; then pybullet alone
    steps_per_scan = int(round(0.05 / world.step_size))
    steps = int(round(WINDOW / world.step_size))
    started = time.perf_counter()
    for step in range(steps):
        pb.stepSimulation(physicsClientId=world.client)
        if step % steps_per_scan == 0:
            laser.measure()
    elapsed = time.perf_counter() - started
    world.close()
    return steps * world.step_size / elapsed


def measure_planning() -> Dict[str, float]:
    """Plans to the random targets of arm_move's planner test, as the mover would."""
    import numpy as np
    import yaml
    from arm_move.planner import planner_from_config, random_reachable_targets
    from arm_move.scene_config import world_scene

    config = os.path.join(REPO, "arm_move", "config")

    def load(name):
        with open(os.path.join(config, name), encoding="utf-8") as stream:
            return yaml.safe_load(stream)
    robot = load("px100.yaml")
    planner = planner_from_config(robot, load("mover.yaml"))
    scene = world_scene(load("scene.yaml"))
    opening = robot["finger"]["max"]
    start, seconds, failed = np.zeros(4), [], 0
    for target in random_reachable_targets(planner, scene, PLANNING_TARGETS, opening):
        plan = planner.plan_to_position(start, opening, target, scene)
        seconds.append(plan.planning_seconds)
        if plan.ok:
            start = plan.path[-1]
        else:
            failed += 1
    return {"median": 1000 * float(np.median(seconds)),
            "p95": 1000 * float(np.percentile(seconds, 95)),
            "success": 100.0 * (PLANNING_TARGETS - failed) / PLANNING_TARGETS}


def verdict(name: str, value: float) -> str:
    sense, target = TARGETS[name]
    met = value >= target if sense == ">=" else value <= target
    return f"{sense} {target:g}", "met" if met else "NOT met"


def main() -> int:
    os.makedirs(OUTPUT, exist_ok=True)
    with headless.private_master(os.path.join(OUTPUT, "ros_home")) as env:
        os.environ.update(ROS_MASTER_URI=env["ROS_MASTER_URI"], ROS_HOME=env["ROS_HOME"],
                          ROS_IP="127.0.0.1")
        port = env["ROS_MASTER_URI"].rsplit(":", 1)[1]
        core = subprocess.Popen(["roscore", "-p", port], env=env, stdout=subprocess.DEVNULL,
                                stderr=subprocess.STDOUT, start_new_session=True)
        try:
            import rosgraph
            headless.wait_until(lambda: rosgraph.is_master_online(), 30, "the master")
            probe = RosProbe()
            print("bench: max real-time factor with ROS...", flush=True)
            fast = measure_ros(env, probe, "0")
            print("bench: CPU at real time...", flush=True)
            paced = measure_ros(env, probe, "1")
        finally:
            core.terminate()
            core.wait(timeout=20)
    print("bench: the same scene on bare pybullet...", flush=True)
    bare = measure_bare()
    print("bench: arm planning...", flush=True)
    planning = measure_planning()
    rows = [
        ("max real-time factor, ROS", fast["rtf"], "{:.1f}"),
        ("max real-time factor, bare pybullet", bare, "{:.1f}"),
        ("ROS overhead (bare / ROS)", bare / fast["rtf"], "{:.2f}"),
        ("CPU at real time (% of a core)", paced["cpu"], "{:.1f}"),
        ("real-time factor when paced", paced["rtf"], "{:.3f}"),
        ("first /scan after roslaunch (s)", fast["first_scan"], "{:.2f}"),
        ("peak RSS (MB)", max(fast["rss"], paced["rss"]), "{:.0f}"),
        ("arm planning, median (ms)", planning["median"], "{:.1f}"),
        ("arm planning, 95th percentile (ms)", planning["p95"], "{:.1f}"),
        ("arm planning, targets reached (%)", planning["success"], "{:.1f}"),
    ]
    lines = ["sim_bridge benchmark: 40 static objects, diff drive, 720-beam laser at 20 Hz, "
             f"{WINDOW:g} s windows; arm_move planning: {PLANNING_TARGETS} random targets", "",
             f"| {'figure':38} | {'measured':>9} | {'target':>8} | {'':7} |",
             f"|{'-' * 40}|{'-' * 11}|{'-' * 10}|{'-' * 9}|"]
    for name, value, form in rows:
        target, met = verdict(name, value) if name in TARGETS else ("", "")
        lines.append(f"| {name:38} | {form.format(value):>9} | {target:>8} | {met:7} |")
    table = "\n".join(lines)
    print(table)
    with open(os.path.join(OUTPUT, "bench.txt"), "w", encoding="utf-8") as stream:
        stream.write(table + "\n")
    print(f"bench: written to {os.path.join(OUTPUT, 'bench.txt')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""Where the simulator's time goes on the ROS path, and its figures alone (issue 36).

Runs ``make bench``'s scene (tools/bench/bench.launch: the bench world and the RB1-class
robot driving its circle) the way ``tools/bench.py``'s ``measure_ros`` does, on a master
of its own, and prints one line per measure:

  fast   max real-time factor with /clock every step, and the simulator's CPU ms per
         simulated second
  paced  the same at real_time_factor:=1: CPU as a share of one core
  robots make bench's "8 robots" measure (their lasers unheard: only the probe listens,
         to /scan and /clock); robots_heard: the same with each robot's scan listened to
  bare   ``bench.BareScene``: the same scene's physics alone (no plugins, no ROS); with
         fast or paced, in windows alternating with theirs as make bench measures
         (fast: its real-time factor; paced: bare_cpu, its CPU paced alike)
  plugins
         in this process, without ROS: each emulated plugin's own time per step (before
         and after the physics), in the bench world, with its topics heard (each message
         serialised as rospy would, not sent) and unheard; the robots: the RB1-class
         (diff drive, laser), burger_like (IMU), gadget_bot (joint states, imu_sensor,
         planar_move), sensor_bot (camera, depth camera, range) and a bumper plate robot

``--profile FILE`` (needs PyPI's py-spy on PATH) also samples the simulator with py-spy
(``--nonblocking``, 1 kHz) over the first window measured (fast, else paced) and writes
its collapsed stacks to FILE; ``--parts FILE SIMULATED_SECONDS`` sorts the stacks of such
a file into the parts the README's breakdown table lists (ms per simulated second, and
each part's share of the simulator's main thread).

Usage: python3 tools/bench/ros_cost.py [fast] [paced] [robots] [robots_heard] [bare]
                                       [plugins] [--profile FILE]
       python3 tools/bench/ros_cost.py --parts FILE SIMULATED_SECONDS [--step-line N]

The machine is shared while this runs: compare runs made alternately, not single figures.
"""
from __future__ import annotations

import argparse
import collections
import os
import shutil
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
# The parts of the breakdown: (part, what marks a frame of it). A stack is py-spy's
# "function (file:line)" frames joined by ";", outermost first; it is read from its
# innermost frame outwards and goes to the first part a frame marks (py-spy's
# --nonblocking stacks may mix two moments: the innermost frame is the surest).
PARTS: Tuple[Tuple[str, Tuple[str, ...]], ...] = (
    ("pybullet.stepSimulation", ("step_physics (sim_bridge/world.py:STEP)",)),
    ("tyre friction", ("tyre_friction.py",)),
    ("laser: cast, message, send", ("plugins/laser.py", "ray_scene.py", "ray_kernel.py",
                                    "_LaserScan.py")),
    ("drive plugin: commands, odometry, TF, joint states", ("plugins/diff_drive.py",
                                                            "drive_base.py")),
    ("/clock: rospy's time, packing, writes", ("ros_publishing.py", "_publish_clock")),
    ("model_states, link_states, performance_metrics checks",
     ("_publish_model_states", "_publish_link_states", "_publish_performance",
      "PerformanceMeter")),
    ("service queue", ("PhysicsThread.serve",)),
    ("pacing (sleeping included)", ("._pace (sim_bridge/ros_node.py",)),
    ("C++ plugin host (none loaded)", ("native_plugins.py",)),
    ("the step loop's own Python, other physics lines",
     ("SimBridgeNode.run (sim_bridge/ros_node.py", "World.step (sim_bridge/world.py",
      "World.step_physics (sim_bridge/world.py", "World._refresh_step_lists",
      "World._apply_native_efforts")),
)


def profile(pid: int, seconds: float, path: str) -> subprocess.Popen:
    """py-spy sampling ``pid`` for ``seconds`` into ``path`` (collapsed stacks), every
    thread, without stopping the process at each sample."""
    if shutil.which("py-spy") is None:
        raise SystemExit("--profile needs py-spy on PATH (pip install py-spy)")
    return subprocess.Popen(["py-spy", "record", "--nonblocking", "--format", "raw",
                             "--rate", str(SAMPLE_RATE), "--duration", str(int(seconds)),
                             "--threads", "--pid", str(pid), "--output", path],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def user_and_system(pid: int) -> Tuple[float, float]:
    """The process's user and system CPU seconds so far."""
    with open(f"/proc/{pid}/stat", encoding="ascii") as stream:
        fields = stream.read().rsplit(")", 1)[1].split()
    tick = os.sysconf("SC_CLK_TCK")
    return int(fields[11]) / tick, int(fields[12]) / tick


def step_line() -> str:
    """``world.py:<line>`` of the stepSimulation call in World.step_physics (the frame py-spy
    shows for time spent in pybullet's step)."""
    import inspect
    from sim_bridge import world
    lines, first = inspect.getsourcelines(world.World.step_physics)
    for offset, line in enumerate(lines):
        if "pb.stepSimulation(" in line:
            return str(first + offset)
    raise RuntimeError("World.step_physics no longer calls pb.stepSimulation")


def parts(path: str, step: Optional[str] = None) -> Dict[str, int]:
    """The main thread's samples by part (PARTS), and what other threads took."""
    step = step or step_line()
    marks = [(part, tuple(mark.replace("STEP", step) for mark in frame_marks))
             for part, frame_marks in PARTS]
    counts: Dict[str, int] = collections.Counter()
    with open(path, encoding="utf-8") as stream:
        for line in stream:
            stack, _, count = line.rstrip("\n").rpartition(" ")
            if not stack:
                continue
            frames = stack.split(";")
            if "MainThread" not in frames[0]:
                counts["other threads (rospy's readers and writers)"] += int(count)
                continue
            if not any("SimBridgeNode.run" in frame for frame in frames):
                continue  # start-up or shut-down
            counts["main thread, all"] += int(count)
            for frame in reversed(frames):
                part = next((part for part, frame_marks in marks
                             if any(mark in frame for mark in frame_marks)), None)
                if part is not None:
                    counts[part] += int(count)
                    break
            else:
                counts["main thread, elsewhere"] += int(count)
    return counts


# a robot with a contact sensor's bumper plate (as sim_bridge/test/unit/test_bumper.py's)
BUMPER_ROBOT = """<robot name="bumper_bot">
  <link name="base_link"><inertial><mass value="10"/><inertia ixx="0.2" ixy="0" ixz="0"
    iyy="0.2" iyz="0" izz="0.2"/></inertial>
    <collision><geometry><box size="0.4 0.4 0.2"/></geometry></collision></link>
  <joint name="bumper_joint" type="fixed"><parent link="base_link"/><child link="bumper"/>
    <origin xyz="0 0 0.11"/></joint>
  <link name="bumper"><inertial><mass value="0.1"/><inertia ixx="1e-3" ixy="0" ixz="0"
    iyy="1e-3" iyz="0" izz="1e-3"/></inertial>
    <collision><geometry><box size="0.3 0.3 0.02"/></geometry></collision></link>
  <gazebo reference="bumper"><sensor name="plate" type="contact">
    <update_rate>50</update_rate>
    <contact><collision>base_link_fixed_joint_lump__bumper_collision</collision></contact>
    <plugin name="plate_plugin" filename="libgazebo_ros_bumper.so">
      <bumperTopicName>plate_bumper</bumperTopicName></plugin>
  </sensor></gazebo></robot>"""
PLUGIN_STEPS = 2000  # steps each robot is timed over (2 s at the bench world's 1 ms)
# where each robot stands in the bench hall (x, y): apart, on free floor
PLUGIN_SPOTS = ((0.0, 0.0), (-2.5, 0.0), (2.5, 0.0), (0.0, 2.5), (0.0, -2.5))


def plugin_costs(heard: bool) -> Dict[str, float]:
    """Microseconds per step of each plugin's before_step and after_step (summed over the
    plugins of a type), the robots above together in the bench world."""
    import io

    from geometry_msgs.msg import Twist

    from sim_bridge.local_bus import LocalBus
    from sim_bridge.sdf_world import load_world
    from sim_bridge.world import World
    from urdf_tools.xacro_loader import expand

    class Bus(LocalBus):
        """Every message serialised as rospy's publish would; heard or not, as asked."""

        def publish(self, topic, message):
            message.serialize(io.BytesIO())
            super().publish(topic, message)

        def send_transforms(self, transforms):
            from tf2_msgs.msg import TFMessage
            TFMessage(transforms=list(transforms)).serialize(io.BytesIO())

        def listened(self, publisher=None):
            return heard

        def info(self, text):
            pass

        def warn(self, text):
            pass

    data = os.path.join(os.path.dirname(TOOLS), "sim_bridge", "test", "data")
    world = World(Bus(), ray_threads=1)
    world.load_world(load_world(os.path.join(TOOLS, "bench", "bench.world"),
                                warn=lambda _text: None))
    robots = [
        ("rb1_class", expand(os.path.join(data, "diff_bot.urdf.xacro"),
                             {"laser_samples": "720", "laser_half_fov_degrees": "135"})),
        ("burger", expand(os.path.join(data, "burger_like.urdf.xacro"), {})),
        ("gadget", open(os.path.join(data, "gadget_bot.urdf"), encoding="utf-8").read()),
        ("sensors", expand(os.path.join(data, "sensor_bot.urdf.xacro"), {})),
        ("bumper", BUMPER_ROBOT),
    ]
    spent: Dict[str, float] = collections.Counter()
    for (name, xml), (x, y) in zip(robots, PLUGIN_SPOTS):
        model = world.spawn_urdf(name, xml, (x, y, 0.05))
        for plugin in model.plugins:
            kind = type(plugin).__name__
            for hook in ("before_step", "after_step"):
                original = getattr(plugin, hook)

                def timed(now_ns, original=original, kind=kind):
                    started = time.perf_counter()
                    original(now_ns)
                    spent[kind] += time.perf_counter() - started

                setattr(plugin, hook, timed)
    circle = Twist()
    circle.linear.x, circle.angular.z = 0.3, 0.5
    world.bus.publish("/cmd_vel", circle)
    for _ in range(PLUGIN_STEPS):
        world.step()
    world.close()
    return {kind: 1e6 * seconds / PLUGIN_STEPS for kind, seconds in spent.items()}


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

                def window(probe_, pid, seconds=bench.WINDOW):
                    if profile_path and not sampler:
                        sampler.append(profile(pid, seconds, profile_path))
                    before = user_and_system(pid)
                    figures = original(probe_, pid, seconds)
                    after = user_and_system(pid)
                    # the simulator's CPU split: its own code against the kernel's work
                    # for it (sends, wake-ups, sleeps)
                    figures["user_ms_per_sim_s"], figures["sys_ms_per_sim_s"] = (
                        1000.0 * (b - a) / max(figures["simulated"], 1e-9)
                        for a, b in zip(before, after))
                    return figures

                bench.measure_window = window
                # with bare asked for too: alternating with it, as make bench measures
                scene = bench.BareScene() if "bare" in which and (
                    "fast" in which or "paced" in which) else None
                if "fast" in which:
                    results["fast"] = bench.measure_ros(env, probe, "fast", bare=scene)
                if "paced" in which:
                    results["paced"] = bench.measure_ros(env, probe, "paced",
                                                         real_time_factor="1", bare=scene)
                if scene is not None:
                    scene.close()
                if "robots" in which:  # as make bench's "8 robots" row runs them
                    results["robots"] = bench.measure_ros(env, probe, "robots_8", robots=8)
                if "robots_heard" in which:  # the same, each robot's /scan listened to
                    results["robots_heard"] = bench.measure_ros(
                        env, probe, "robots_8_heard", robots=8,
                        listen=[f"/r{index}/scan" for index in range(8)])
                bench.measure_window = original
                if sampler:
                    sampler[0].wait(timeout=60)
            finally:
                core.terminate()
                core.wait(timeout=20)
    if "bare" in which and "fast" in results:
        results["bare"] = {"rtf": results["fast"]["bare"]}
    elif "bare" in which and "paced" not in results:
        results["bare"] = {"rtf": bench.measure_bare()}
    if "plugins" in which:
        heard, unheard = plugin_costs(True), plugin_costs(False)
        for kind in sorted(heard, key=lambda k: -heard[k]):
            print(f"plugin {kind:28} heard {heard[kind]:8.2f} us/step   "
                  f"unheard {unheard.get(kind, float('nan')):8.2f} us/step")
    return results


def main(argv: Optional[Sequence[str]] = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("which", nargs="*", default=["fast", "paced"],
                        help="fast, paced, robots, robots_heard, bare, plugins "
                        "(default: fast paced)")
    parser.add_argument("--profile", help="py-spy's collapsed stacks of the fast window")
    parser.add_argument("--parts", nargs=2, metavar=("FILE", "SIMULATED_SECONDS"),
                        help="sort a profile's stacks into parts")
    parser.add_argument("--step-line", help="world.py's line of pb.stepSimulation when the "
                        "profile was taken (default: today's)")
    arguments = parser.parse_args(argv)
    if arguments.parts:
        counts = parts(arguments.parts[0], arguments.step_line)
        simulated = float(arguments.parts[1])
        main_thread = max(counts.get("main thread, all", 0), 1)
        for part, count in sorted(counts.items(), key=lambda item: -item[1]):
            # a sample is 1/SAMPLE_RATE s of the thread's wall time
            print(f"{part:55} {count:7d} samples {1000.0 * count / SAMPLE_RATE / simulated:7.2f} "
                  f"ms per simulated s {100.0 * count / main_thread:5.1f} %")
        return 0
    started = time.monotonic()
    results = measure(arguments.which, arguments.profile)
    for name, figures in results.items():
        line = " ".join(f"{key} {value:.3f}" for key, value in figures.items()
                        if key in ("rtf", "cpu", "cpu_ms_per_sim_s", "user_ms_per_sim_s",
                                   "sys_ms_per_sim_s", "bare", "bare_cpu"))
        print(f"{name}: {line}", flush=True)
    print(f"({time.monotonic() - started:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())

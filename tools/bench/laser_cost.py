"""What the simulator's lasers cost, measured in the bench world (tools/bench/bench.world).

  python3 tools/bench/laser_cost.py        (after `source tools/env.bash`)

prints a table; :func:`measure` returns the same figures for tools/bench.py. Rows:

  scan, N beams           ms per scan of one RB1-class laser (270 degrees, 10 m) on a robot
                          in the middle of the hall: the laser plugin's measure() (sensor
                          pose, directions, cast), each scan at a new time stamp, as after a
                          physics step (the step itself is not timed)
  fixed cost per scan     the same with a 1-beam laser: what a scan costs besides its beams
  N robots                N robots, each with a 720-beam laser at its 20 Hz, in the hall:
                          ms of laser CPU per simulated second, all lasers together

Columns (``compare=True``): ``before``, the numpy reference with every moving shape placed
anew for every scan (sim_bridge's casting before the compiled kernel); ``after``, what the
simulator does now. Each figure is the minimum over ROUNDS, before and after measured
alternately in one process, so that a machine shared with other work disturbs both alike.
"""
from __future__ import annotations

import functools
import math
import os
import sys
import time
from typing import Dict, List

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
WORLD = os.path.join(REPO, "tools", "bench", "bench.world")
ROBOT = os.path.join(REPO, "sim_bridge", "test", "data", "diff_bot.urdf.xacro")
BEAM_COUNTS = (360, 720, 1440)
ROBOT_COUNTS = (1, 2, 4, 8)
HALF_FIELD_DEGREES = "135"  # the bench's RB1-class laser: 270 degrees
CROWD_BEAMS = 720
# free lanes of the hall (its objects stand at odd multiples of 1.25 m): robots here
SPOTS = [(0.0, 0.0), (2.5, 0.0), (-2.5, 0.0), (0.0, 2.5), (0.0, -2.5), (2.5, 2.5),
         (-2.5, -2.5), (2.5, -2.5)]
SPAWN_HEIGHT = 0.1  # m; the world sets a robot on the ground
ROUNDS = 5
SCANS = 40  # scans per round for the per-scan figures
SIMULATED_SECONDS = 1.0  # per round for the crowd figures


def _null_bus():
    from sim_bridge.plugins.base import Bus

    class Nowhere:
        def publish(self, _message):
            pass

        def unregister(self):
            pass

    class NullBus(Bus):
        """Publishes nowhere: only the simulator's own work is timed."""

        def publisher(self, topic, msg_class, queue_size=10, latch=False):
            return Nowhere()

        def subscriber(self, topic, msg_class, callback):
            return Nowhere()

        def send_transforms(self, transforms):
            pass

        def info(self, text):
            pass

        def warn(self, text):
            print(f"warning: {text}", file=sys.stderr)

        def warn_throttled(self, key, period, text):
            self.warn(text)

    return NullBus()


def _hall(robots: int, beams: int):
    """The bench world with robots (each with a laser of ``beams``); (world, lasers)."""
    from sim_bridge.plugins.laser import Laser
    from sim_bridge.sdf_world import load_world
    from sim_bridge.world import World
    from urdf_tools.xacro_loader import expand

    world = World(_null_bus(), ray_threads=1)
    world.load_world(load_world(WORLD))
    xml = expand(ROBOT, {"laser_samples": str(beams), "laser_half_fov_degrees": HALF_FIELD_DEGREES})
    lasers = []
    for index in range(robots):
        x, y = SPOTS[index]
        model = world.spawn_urdf(f"robot_{index}", xml, position=(x, y, SPAWN_HEIGHT),
                                 orientation=(0.0, 0.0, math.sin(index / 2), math.cos(index / 2)))
        lasers.append(next(p for p in model.plugins if isinstance(p, Laser)))
    world.step()
    return world, lasers


def _use(world, lasers, reference: bool) -> None:
    """Lasers cast through the fast path, or through the numpy reference (every shape
    placed anew for every scan, as before)."""
    for laser in lasers:
        laser.context.cast_rays = functools.partial(world.cast_rays, reference=reference)


def _next_stamp(world, seconds: float) -> None:
    """Simulated time moves on without a physics step: what a scan meets after a step
    (its moving shapes to place again), without timing the step."""
    world.now_ns += int(round(seconds * 1e9))


def _per_scan_ms(world, laser, reference: bool) -> float:
    _use(world, [laser], reference)
    elapsed = 0.0
    for _ in range(SCANS):
        _next_stamp(world, world.step_size)
        started = time.perf_counter()
        laser.measure()
        elapsed += time.perf_counter() - started
    return elapsed / SCANS * 1e3


def _crowd_ms_per_second(world, lasers, reference: bool) -> float:
    """ms of CPU for all lasers' scans in SIMULATED_SECONDS, per simulated second."""
    _use(world, lasers, reference)
    period = lasers[0].scan_time
    scans = int(round(SIMULATED_SECONDS / period))
    elapsed = 0.0
    for _ in range(scans):
        _next_stamp(world, period)
        started = time.perf_counter()
        for laser in lasers:
            laser.measure()
        elapsed += time.perf_counter() - started
    return elapsed * 1e3 / SIMULATED_SECONDS


def _alternate(measure_one, compare: bool) -> Dict[str, float]:
    """min over ROUNDS of measure_one(reference), before and after interleaved."""
    results: Dict[str, List[float]] = {"after": []}
    if compare:
        results["before"] = []
    for _ in range(ROUNDS):
        for column in results:
            results[column].append(measure_one(column == "before"))
    return {column: min(values) for column, values in results.items()}


def measure(compare: bool = False) -> Dict[str, object]:
    """The figures, keyed by row name: each a dict {"after": ms} (and "before" with
    ``compare``); "kernel": the compiled kernel's path, or why it is not used."""
    from sim_bridge import ray_kernel

    kernel, where = ray_kernel.load()
    figures: Dict[str, object] = {"kernel": where if kernel is not None else f"none: {where}"}
    for beams in BEAM_COUNTS:
        world, (laser,) = _hall(1, beams)
        figures[f"scan, {beams} beams (ms)"] = _alternate(
            functools.partial(_per_scan_ms, world, laser), compare)
        world.close()
    world, (laser,) = _hall(1, 1)
    figures["fixed cost per scan, 1 beam (ms)"] = _alternate(
        functools.partial(_per_scan_ms, world, laser), compare)
    world.close()
    for robots in ROBOT_COUNTS:
        world, lasers = _hall(robots, CROWD_BEAMS)
        figures[f"{robots} robots x {CROWD_BEAMS}-beam laser at "
                f"{1.0 / lasers[0].scan_time:g} Hz (ms per simulated s)"] = _alternate(
            functools.partial(_crowd_ms_per_second, world, lasers), compare)
        world.close()
    return figures


def table(figures: Dict[str, object]) -> str:
    rows = [(name, value) for name, value in figures.items() if isinstance(value, dict)]
    width = max(len(name) for name, _ in rows)
    columns = [c for c in ("before", "after") if any(c in v for _, v in rows)]
    lines = [f"laser cost in {os.path.relpath(WORLD, REPO)} "
             f"(min of {ROUNDS} rounds; kernel: {figures['kernel']})",
             f"{'':{width}}" + "".join(f"{c:>10}" for c in columns)
             + ("   before/after" if len(columns) == 2 else "")]
    for name, value in rows:
        line = f"{name:{width}}" + "".join(f"{value[c]:10.3f}" for c in columns)
        if len(columns) == 2:
            line += f"   {value['before'] / value['after']:8.1f}x"
        lines.append(line)
    return "\n".join(lines)


def main() -> int:
    print(table(measure(compare=True)))
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""What a Gazebo C++ plugin costs sim_bridge per step (issue 35's figure).

  python3 tools/bench/plugin_cost.py        (after `source tools/env.bash`)

Gazebo's model_push tutorial plugin (sim_bridge/test/data/gazebo_plugins, built here with
plain CMake against the devel space's find_package(gazebo)) pushes a box in its world:
WorldUpdateBegin before every step, where it sets the box's linear velocity. The same world
without the plugin, the box pushed the same way by one pybullet call before each step
(resetBaseVelocity: the same sliding, the same contacts), is the reference: the physics. Each
is stepped STEPS times with World.step (plugins, physics, the plugin host's lockstep), the
two alternately for ROUNDS; the figure is the difference of the two minima in microseconds
per step: the callback, the host's calls into it and back into the world.
"""
from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from typing import Dict

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PLUGINS = os.path.join(REPO, "sim_bridge", "test", "data", "gazebo_plugins")
WORLD = os.path.join(PLUGINS, "model_push.world")
STEPS = 10_000
ROUNDS = 3


def _devel_space() -> str:
    for prefix in os.environ.get("CMAKE_PREFIX_PATH", "").split(os.pathsep):
        if os.path.isfile(os.path.join(prefix, "share", "gazebo", "cmake", "gazeboConfig.cmake")):
            return prefix
    raise RuntimeError("no find_package(gazebo) config in CMAKE_PREFIX_PATH "
                       "(source tools/env.bash after make setup)")


def _build(directory: str) -> None:
    for command in (["cmake", "-S", PLUGINS, "-B", directory,
                     f"-DCMAKE_PREFIX_PATH={_devel_space()}", "-DCMAKE_BUILD_TYPE=Release"],
                    ["make", "-C", directory, "-j2", "model_push"]):
        subprocess.run(command, check=True, capture_output=True, text=True)


PUSH = [0.3, 0.0, 0.0]  # m/s: model_push's velocity (model_push.cc)


def _seconds_per_step(world_file: str, push_directly: bool) -> float:
    import pybullet as pb

    from sim_bridge.local_bus import LocalBus
    from sim_bridge.sdf_world import load_world
    from sim_bridge.world import World

    world = World(LocalBus())
    try:
        world.load_world(load_world(world_file, warn=lambda _text: None))
        body, client = world.model("box").body, world.client
        started = time.perf_counter()
        for _ in range(STEPS):
            if push_directly:
                pb.resetBaseVelocity(body, PUSH, physicsClientId=client)
            world.step()
        return (time.perf_counter() - started) / STEPS
    finally:
        world.close()


def measure() -> Dict[str, float]:
    """Microseconds per step with the plugin, without it, and the difference."""
    with tempfile.TemporaryDirectory() as build:
        _build(build)
        os.environ["GAZEBO_PLUGIN_PATH"] = build
        bare_world = os.path.join(build, "no_plugin.world")
        with open(WORLD, encoding="utf-8") as stream:
            text = stream.read()
        without = text.replace('<plugin name="model_push" filename="libmodel_push.so"/>', "")
        assert without != text, "model_push.world no longer names its plugin as expected"
        with open(bare_world, "w", encoding="utf-8") as stream:
            stream.write(without)
        plugin, bare = [], []
        for _ in range(ROUNDS):
            plugin.append(_seconds_per_step(WORLD, push_directly=False))
            bare.append(_seconds_per_step(bare_world, push_directly=True))
    with_plugin, without_plugin = 1e6 * min(plugin), 1e6 * min(bare)
    return {"with": with_plugin, "without": without_plugin,
            "cost": with_plugin - without_plugin}


if __name__ == "__main__":
    figures = measure()
    print(f"step with model_push: {figures['with']:.1f} us; pushed by pybullet: {figures['without']:.1f} us;"
          f" the plugin costs {figures['cost']:.1f} us per step")
    sys.exit(0)

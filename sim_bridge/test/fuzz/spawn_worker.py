"""The spawn path's fuzz worker: a long-lived process that reads cases from stdin, one JSON
object a line, and answers each on its protocol stream (the original stdout; pybullet's
chatter on fd 1 goes to stderr instead), one JSON object a line.

A case: {"kind": "urdf" | "sdf" | "world", "text": ..., "name": ..., "position": [x, y, z],
"orientation": [x, y, z, w], "files": {relative path: text}} (files: a world's model
folders, written under a temporary folder that is put first on GAZEBO_MODEL_PATH).

URDF and SDF cases are spawned into one World on pybullet.DIRECT with a ground plane, as
the simulator's spawn services do (World.spawn_urdf; sdf_world.parse_model then
World.add_sdf_model), stepped, then deleted; a world case is read with sdf_world.load_world
and loaded into a World of its own. The answer: {"outcome": "model" | "refused" |
"unexpected", "type", "message", "traceback", "finite" (the model's pose after the steps),
"leaked" (pybullet bodies left behind), "seconds"}. A crash (a signal) or a hang is seen by
the client (spawn_client.py), which restarts the worker.
"""
import json
import math
import os
import sys
import time
import traceback

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "unit"))

# the protocol keeps the real stdout; whatever pybullet prints goes to stderr
PROTOCOL = os.fdopen(os.dup(1), "w", encoding="utf-8")
os.dup2(2, 1)

import pybullet as pb  # noqa: E402

from recording_bus import RecordingBus  # noqa: E402
from world_folder import written_world  # noqa: E402
from sim_bridge import sdf_world  # noqa: E402
from sim_bridge.sdf_world import LinkSpec, ModelSpec, SdfError, ShapeSpec  # noqa: E402
from sim_bridge.world import SimError, World  # noqa: E402
from urdf_tools.model import UrdfError  # noqa: E402

DOCUMENTED = (SimError, UrdfError, SdfError)
STEPS = 10


def _world(bus):
    world = World(bus, ray_threads=1)
    world.add_sdf_model(ModelSpec("ground", True, links=[
        LinkSpec("link", collisions=[ShapeSpec("plane")])]))
    return world


def _bodies(world):
    return pb.getNumBodies(physicsClientId=world.client)


def _finite_pose(world, name):
    position, orientation = world.pose(name)
    return all(math.isfinite(v) for v in (*position, *orientation))


def _spawn(world, case):
    """Spawns, steps and deletes one model; returns (outcome fields)."""
    before = _bodies(world)
    name = case.get("name", "fuzz")
    # the request's pose checked and turned into the world first, as the spawn services do
    position, orientation, _, _ = world.state_in_world(
        "", case.get("position", (0, 0, 0.1)), case.get("orientation", (0, 0, 0, 1)),
        (0, 0, 0), (0, 0, 0))
    if case["kind"] == "urdf":
        world.spawn_urdf(name, case["text"], position, orientation, source=f"model '{name}'")
    else:
        spec = sdf_world.parse_model(case["text"], f"model '{name}'", warn=world.bus.warn)
        spec.name = name
        world.add_sdf_model(spec, position, orientation)
    for _ in range(STEPS):
        world.step()
    finite = _finite_pose(world, name)
    world.delete(name)
    return {"outcome": "model", "finite": finite, "leaked": _bodies(world) - before}


def _load_world(case):
    with written_world(case["text"], case.get("files", {}), "fuzz_world_",
                       keep_model_path=True) as (_, world_file):
        spec = sdf_world.load_world(world_file, warn=lambda text: None)
        world = World(RecordingBus(), step_size=spec.step_size, ray_threads=1)
        try:
            world.load_world(spec)
            for _ in range(STEPS):
                world.step()
            finite = all(_finite_pose(world, name) for name in world.models)
        finally:
            world.close()
        return {"outcome": "model", "finite": finite, "leaked": 0}


def main():
    bus = RecordingBus()
    world = _world(bus)
    PROTOCOL.write(json.dumps({"ready": os.getpid()}) + "\n")
    PROTOCOL.flush()
    for line in sys.stdin:
        case = json.loads(line)
        started = time.monotonic()
        bus.warnings.clear()
        before = _bodies(world)
        try:
            answer = _load_world(case) if case["kind"] == "world" else _spawn(world, case)
        except DOCUMENTED as error:
            answer = {"outcome": "refused", "type": type(error).__name__, "message": str(error),
                      "leaked": _bodies(world) - before}
        except Exception as error:  # the defect the fuzzing looks for
            answer = {"outcome": "unexpected", "type": type(error).__name__,
                      "message": str(error)[:2000], "traceback": traceback.format_exc()[-4000:],
                      "leaked": _bodies(world) - before}
        if case["kind"] != "world" and case.get("name", "fuzz") in world.models:
            try:  # a model half-added: gone for the next case
                world.delete(case.get("name", "fuzz"))
            except Exception:
                pass
        if answer.get("leaked") or answer["outcome"] == "unexpected":
            world.close()  # a clean world for the next case
            world = _world(bus)
        answer["seconds"] = time.monotonic() - started
        PROTOCOL.write(json.dumps(answer) + "\n")
        PROTOCOL.flush()


if __name__ == "__main__":
    main()

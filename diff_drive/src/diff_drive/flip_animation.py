"""An animated GIF of the flip routine, drawn by the simulator itself with no screen:
sim_bridge's World (the same physics and plugins as the ROS node, driven through an
in-process bus instead of a master) and pybullet's software renderer.

    rosrun diff_drive render_flip_gif [output.gif] [simulated seconds]
"""
from __future__ import annotations

import math
import os
import sys
import tempfile

import rospkg
from geometry_msgs.msg import Twist

from diff_drive.flip import (FlipSettings, commanded_speed, load_defaults,
                             packaged_settings_path)
from sim_bridge.local_bus import LocalBus
from sim_bridge.poses import quaternion_from_rpy
from sim_bridge.sdf_world import load_world
from sim_bridge.snapshots import render, write_gif, write_ppm
from sim_bridge.world import World
from urdf_tools.xacro_loader import expand

FRAME_SECONDS = 0.08   # 12.5 frames per simulated second, played back in real time
# where ddrive.launch spawns the robot by default: its lane runs along the diagonal
SPAWN_POSITION = (-1.2, -1.2, 0.125)   # z: the wheel radius and 5 mm
SPAWN_YAW = math.pi / 4
EYE, TARGET = (2.2, -1.8, 0.8), (0.3, 0.1, 0.2)  # beside the lane, looking across it


def render_flip(output: str, seconds: float) -> int:
    """Simulates ``seconds`` of the routine with the packaged settings, writes the GIF and
    returns the number of frames."""
    package = rospkg.RosPack().get_path("diff_drive")
    defaults = packaged_settings_path()
    settings = FlipSettings.from_mapping(load_defaults(defaults), defaults)
    bus = LocalBus()
    world = World(bus)
    try:
        world.load_world(load_world(os.path.join(package, "worlds", "ddrive.world")))
        world.spawn_urdf("ddrive", expand(os.path.join(package, "urdf", "ddrive.urdf.xacro")),
                         SPAWN_POSITION, quaternion_from_rpy(0.0, 0.0, SPAWN_YAW))
        command = Twist()
        steps_per_frame = int(round(FRAME_SECONDS / world.step_size))
        with tempfile.TemporaryDirectory() as folder:
            frames = []
            for index in range(int(seconds / FRAME_SECONDS)):
                command.linear.x = commanded_speed(settings, index * FRAME_SECONDS)
                bus.publish("/diff/cmd_vel", command)
                for _ in range(steps_per_frame):
                    world.step()
                frames.append(os.path.join(folder, f"{index:04d}.ppm"))
                write_ppm(frames[-1], render(world.client, EYE, TARGET))
            write_gif(frames, output, FRAME_SECONDS)
    finally:
        world.close()
    return len(frames)


def main(argv=None) -> None:
    arguments = sys.argv[1:] if argv is None else argv
    output = arguments[0] if arguments else "flip.gif"
    seconds = float(arguments[1]) if len(arguments) > 1 else 6.2
    print(f"wrote {output} ({render_flip(output, seconds)} frames)")

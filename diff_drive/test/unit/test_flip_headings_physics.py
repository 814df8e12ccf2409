"""The flip routine's physics at four headings, without ROS's timing: the robot of
config/ddrive.yaml in worlds/ddrive.world on sim_bridge's World, driven by the routine's
own schedule (commanded_speed at its 20 Hz, applied on time), 60 s of simulated time at
yaw 0, 30, 45 and 90 degrees. At each: at least 4 flips, reversals along the line, less
than 0.2 m off it and 5 degrees off its heading (the issue's limits); and the same motion
at every heading. The rostest (test/rostest/flip_headings.test) runs the same through
ROS; this one holds the simulator's part of it exactly."""
import math
import os

import pytest
from geometry_msgs.msg import Twist
from tf.transformations import quaternion_from_euler, quaternion_matrix

from diff_drive.flip import FlipCounter, FlipSettings, commanded_speed, load_defaults
from sim_bridge.local_bus import LocalBus
from sim_bridge.sdf_world import load_world
from sim_bridge.world import World
from urdf_tools.xacro_loader import expand

PACKAGE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DEFAULTS = os.path.join(PACKAGE, "config", "flip.yaml")
DURATION = 60.0
MAX_SIDEWAYS = 0.2                  # m
MAX_DRIFT = math.radians(5.0)
FLAT = 0.7                          # |up z| above which the body has a heading
START = (0.0, 0.0, 0.125)           # the lane's middle, clear of everything along any heading
COMMANDS = "/diff/cmd_vel"          # urdf/ddrive.gazebo's drive plugin, in no namespace


def flip_run(yaw_degrees):
    """(flips, reversals, furthest sideways m, largest heading error rad, travel range)."""
    settings = FlipSettings.from_mapping(load_defaults(DEFAULTS), DEFAULTS)
    bus = LocalBus()
    world = World(bus)
    try:
        world.load_world(load_world(os.path.join(PACKAGE, "worlds", "ddrive.world"),
                                    warn=lambda _text: None))
        xml = expand(os.path.join(PACKAGE, "urdf", "ddrive.urdf.xacro"),
                     {"config": os.path.join(PACKAGE, "config", "ddrive.yaml")})
        yaw = math.radians(yaw_degrees)
        world.spawn_urdf("ddrive", xml, START, quaternion_from_euler(0.0, 0.0, yaw))
        steps = int(round(1.0 / settings.rate / world.step_size))
        counter, along, sideways, drift, directions = FlipCounter(), [], 0.0, 0.0, []
        for tick in range(int(round(DURATION * settings.rate))):
            command = Twist()
            command.linear.x = commanded_speed(settings, tick / settings.rate)
            bus.publish(COMMANDS, command)
            for _ in range(steps):
                world.step()
            (x, y, _), q = world.pose("ddrive")
            matrix = quaternion_matrix(q)
            counter.update(matrix[2][2])
            s = x * math.cos(yaw) + y * math.sin(yaw)
            if along:
                speed = (s - along[-1]) * settings.rate
                if abs(speed) > 0.3:
                    directions.append(speed > 0)
            along.append(s)
            sideways = max(sideways, abs(-x * math.sin(yaw) + y * math.cos(yaw)))
            if abs(matrix[2][2]) > FLAT:
                error = math.atan2(matrix[1][0], matrix[0][0]) - yaw
                drift = max(drift, abs((error + math.pi / 2) % math.pi - math.pi / 2))
        reversals = sum(1 for a, b in zip(directions, directions[1:]) if a != b)
        return counter.flips, reversals, sideways, drift, (min(along), max(along))
    finally:
        world.close()


def test_the_flip_keeps_its_line_the_same_way_at_every_heading():
    runs = {heading: flip_run(heading) for heading in (0.0, 30.0, 45.0, 90.0)}
    for heading, (flips, reversals, sideways, drift, travel) in runs.items():
        summary = (f"yaw {heading:g}: {flips} flips, {reversals} reversals, "
                   f"{sideways:.3f} m sideways, {math.degrees(drift):.1f} deg off, "
                   f"travel {travel[0]:.2f}..{travel[1]:.2f} m")
        assert flips >= 4 and reversals >= 4, summary
        assert sideways < MAX_SIDEWAYS and drift < MAX_DRIFT, summary
        assert travel == pytest.approx(runs[0.0][4], abs=0.01), summary

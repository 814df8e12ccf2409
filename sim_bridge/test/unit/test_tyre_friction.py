"""Tyres grip the same at every heading (sim_bridge.tyre_friction): the same command gives
the same motion, in the robot's own starting frame, whichever way the robot faces in the
world. Before, pybullet's friction on the world's axes made a skid-steer turn and a hard
stop depend on the heading. Each case drives on an arc, stops hard and turns in place,
so the tyres both roll and slip."""
import math
import os

import pytest
from geometry_msgs.msg import Twist
from tf.transformations import euler_from_quaternion, quaternion_from_euler

from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec
from sim_bridge.world import World
from urdf_tools.xacro_loader import expand

from recording_bus import RecordingBus
from world_fixtures import DATA, run

HEADINGS = (0.0, 30.0, 45.0, 90.0)  # degrees
# (linear m/s, angular rad/s, seconds): an arc, a hard stop, a turn in place, a stop
ROUTINE = ((0.4, 0.5, 2.0), (0.0, 0.0, 0.5), (0.0, 1.0, 1.5), (0.0, 0.0, 0.5))
TOLERANCE = 0.01  # of the distance driven and of the angle turned


def drive(robot_file, yaw_degrees):
    """(forward, left, turned): where the routine leaves the robot, in the frame it started
    in (m, m, rad), from the simulator's true pose."""
    bus = RecordingBus()
    world = World(bus, ray_threads=1)
    try:
        world.add_sdf_model(ModelSpec("ground", True, links=[
            LinkSpec("link", collisions=[ShapeSpec("plane")])]))
        yaw = math.radians(yaw_degrees)
        world.spawn_urdf("robot", expand(os.path.join(DATA, robot_file), {}),
                         (1.0, -2.0, 0.1), quaternion_from_euler(0.0, 0.0, yaw))
        run(world, 0.5)  # settles on its wheels
        (x0, y0, _), q0 = world.pose("robot")
        yaw0 = euler_from_quaternion(q0)[2]
        turned, last = 0.0, yaw0
        for linear, angular, seconds in ROUTINE:
            twist = Twist()
            twist.linear.x, twist.angular.z = linear, angular
            bus.subscriptions["/cmd_vel"](twist)
            for _ in range(int(round(seconds / 0.05))):
                run(world, 0.05)
                now = euler_from_quaternion(world.pose("robot")[1])[2]
                turned += math.atan2(math.sin(now - last), math.cos(now - last))
                last = now
        (x1, y1, _), _ = world.pose("robot")
        dx, dy = x1 - x0, y1 - y0
        return (dx * math.cos(yaw0) + dy * math.sin(yaw0),
                -dx * math.sin(yaw0) + dy * math.cos(yaw0), turned)
    finally:
        world.close()


@pytest.mark.parametrize("robot_file", ["diff_bot.urdf.xacro", "skid_bot.urdf.xacro"])
def test_the_same_command_moves_a_robot_the_same_at_every_heading(robot_file):
    results = {heading: drive(robot_file, heading) for heading in HEADINGS}
    forward, left, turned = results[0.0]
    reach = math.hypot(forward, left)
    assert reach > 0.3 and abs(turned) > 1.0, f"the routine barely moved it: {results}"
    for heading, (f, l, t) in results.items():
        assert math.hypot(f - forward, l - left) <= TOLERANCE * reach, \
            f"at {heading} degrees it ended at ({f:.4f}, {l:.4f}) m, at 0 at " \
            f"({forward:.4f}, {left:.4f}) m"
        assert abs(t - turned) <= TOLERANCE * abs(turned), \
            f"at {heading} degrees it turned {t:.4f} rad, at 0 {turned:.4f} rad"


def test_tyres_with_a_very_high_mu_still_grip_without_creeping():
    """0.2 m/s for 5 s drives 1 m (within 3%, the start's acceleration included) whatever
    the tyres' mu, here 25 with heavy casters at mu 1 dragging, as a student's RB1 wrote
    them. (That student's robot, tried outside the repository, drove 0.53 m of 1 m with the
    first version of the tyre friction, whose linear zone grew with mu: 2 mu g dt =
    0.49 m/s; 0.96 m now. This robot drives 1 m with both versions: the test holds the
    requirement, the README the measurement.)"""
    grippy = "".join(f'<gazebo reference="{side}_wheel"><mu1>25</mu1><mu2>25</mu2></gazebo>'
                     for side in ("left", "right"))
    for robot_extra, label in (("", "mu 1"), (grippy, "mu 25")):
        bus = RecordingBus()
        world = World(bus, ray_threads=1)
        try:
            world.add_sdf_model(ModelSpec("ground", True, links=[
                LinkSpec("link", collisions=[ShapeSpec("plane")])]))
            xml = expand(os.path.join(DATA, "diff_bot.urdf.xacro"), {})
            if robot_extra:  # heavy casters that drag carry most of it, as the student's did
                xml = xml.replace("<mu1>0.0</mu1><mu2>0.0</mu2>", "<mu1>1.0</mu1><mu2>1.0</mu2>")
                xml = xml.replace('<mass value="0.1"/>', '<mass value="10.0"/>')
            world.spawn_urdf("robot", xml.replace("</robot>", robot_extra + "</robot>"),
                             (0.0, 0.0, 0.1))
            run(world, 0.5)
            (x0, y0, _), _ = world.pose("robot")
            twist = Twist()
            twist.linear.x = 0.2
            bus.subscriptions["/cmd_vel"](twist)
            run(world, 5.0)
            (x1, y1, _), _ = world.pose("robot")
            assert math.hypot(x1 - x0, y1 - y0) == pytest.approx(1.0, rel=0.03), label
        finally:
            world.close()


def _fast_against_reference(world, bus, commands, seconds_each):
    """Steps ``world`` through ``commands`` ((topic, linear, angular), each for
    ``seconds_each``), checking before every step that every robot's fast tyre forces equal
    the reference's to the last bit; returns which kinds of pair the contacts met."""
    import pybullet as pb
    met = set()
    for topic, linear, angular in commands:
        twist = Twist()
        twist.linear.x, twist.angular.z = linear, angular
        bus.subscriptions[topic](twist)
        for _ in range(int(round(seconds_each / world.step_size))):
            world._refresh_step_lists()
            for friction in world._frictions:
                contacts = pb.getContactPoints(bodyA=friction.body, physicsClientId=world.client)
                fast = friction.forces(contacts)
                assert fast == friction.reference_forces(contacts), \
                    f"at {world.now:.3f} s the fast tyre forces differ from the reference's"
                for pair in friction._pairs.values():
                    met.update(name for name in ("moving", "react", "isotropic")
                               if getattr(pair, name))
                    met.update(["anisotropic"] if not pair.isotropic else [])
                met.update(["forces"] if fast else [])
            world.step()
    return met


def test_the_fast_tyre_forces_equal_the_reference_at_every_step():
    """sim_bridge steps with TyreFriction.forces; reference_forces is the maths one contact
    at a time. They must agree exactly, every step: two robots driving onto a free plank
    (the other body moves and takes the opposite force) and into each other, and a robot
    whose tyres grip differently along and across (mu1 != mu2 with fdir1)."""
    bus = RecordingBus()
    world = World(bus, ray_threads=1)
    try:
        world.add_sdf_model(ModelSpec("ground", True, links=[
            LinkSpec("link", collisions=[ShapeSpec("plane")])]))
        world.add_sdf_model(ModelSpec("plank", False, links=[LinkSpec(
            "link", mass=3.0, inertia=(0.25, 0.25, 0.5),
            collisions=[ShapeSpec("box", size=(1.0, 1.0, 0.01))])]), (0.9, 0.0, 0.005))
        robot = expand(os.path.join(DATA, "diff_bot.urdf.xacro"), {})
        world.spawn_urdf("one", robot, (0.0, 0.0, 0.1))
        world.spawn_urdf("two", expand(os.path.join(DATA, "diff_bot.urdf.xacro"),
                                       {"namespace": "two"}),
                         (2.2, 0.05, 0.1), quaternion_from_euler(0.0, 0.0, 3.0), "two")
        burger = expand(os.path.join(DATA, "burger_like.urdf.xacro"), {})
        assert "<fdir1>" in burger and "<mu2>0.1</mu2>" in burger
        world.spawn_urdf("burger", burger.replace("<mu2>0.1</mu2>", "<mu2>0.6</mu2>", 1),
                         (0.0, 3.0, 0.05), quaternion_from_euler(0.0, 0.0, 0.3), "burger")
        run(world, 0.3)
        met = _fast_against_reference(world, bus, [
            ("/cmd_vel", 0.5, 0.1), ("/two/cmd_vel", 0.6, 0.0), ("/burger/cmd_vel", 0.2, 0.8),
            ("/burger/cmd_vel", -0.2, -1.5), ("/cmd_vel", -0.3, 0.0)], 1.0)
    finally:
        world.close()
    assert met >= {"forces", "moving", "react", "isotropic", "anisotropic"}, \
        f"the scene did not reach every kind of contact: {sorted(met)}"

"""World.advance: the steps no plugin needs are made by the physics alone, and nothing a
user can see differs from calling every plugin at every step. Two worlds with the same
robots (drives at their update rates, a laser, cameras, a range sensor, p3d, IMUs, joint
states, planar move) and the same commands at the same steps, one stepped by World.step,
the other by World.advance in batches of varied length: every message published, every
transform and every pose and joint state are the same, bit for bit (pybullet is
deterministic for the same calls in the same order)."""
import io
import itertools

import pybullet as pb
import pytest
from geometry_msgs.msg import Twist

from recording_bus import RecordingBus
from world_fixtures import DATA
from sim_bridge.plugins.base import NEVER, Plugin, UpdateSlots
from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec
from sim_bridge.world import World
from urdf_tools.xacro_loader import expand

STEPS = 1500  # 1.5 s at the fixture world's 1 ms step
COMMAND_CHANGES = (0, 433, 977)  # the steps before which the drives get a new command
RESET_AT = 1201  # the step before which the world is reset
# the batch lengths World.advance is asked for, in turn
BATCHES = (20, 7, 1, 13, 20, 3)
ROBOTS = (
    ("rb1_class", lambda: expand(f"{DATA}/diff_bot.urdf.xacro",
                                 {"laser_samples": "360", "laser_half_fov_degrees": "135"}),
     (0.0, 0.0, 0.0)),
    ("skid", lambda: expand(f"{DATA}/skid_bot.urdf.xacro", {}), (3.0, 0.0, 0.0)),
    ("sensors", lambda: expand(f"{DATA}/sensor_bot.urdf.xacro", {}), (-3.0, 0.0, 0.01)),
    ("gadget", lambda: open(f"{DATA}/gadget_bot.urdf", encoding="utf-8").read(),
     (0.0, 3.0, 0.05)),
    ("burger", lambda: expand(f"{DATA}/burger_like.urdf.xacro", {}), (0.0, -3.0, 0.05)),
)


# robots whose plugins all act at their update rates; the others act at every step
# (alone, the RB1-class robot's slots fall on the fewest steps: a slot off by one shows)
RB1_ALONE = ("rb1_class",)
RATE_GATED = ("rb1_class", "skid", "sensors")
EVERY_STEP = RATE_GATED + ("gadget", "burger")


class SerialisingBus(RecordingBus):
    """Keeps each message's bytes as it was published (plugins may reuse their message
    objects); every topic heard, or none."""

    def __init__(self, heard):
        super().__init__()
        self.heard = heard
        self.wire = []

    def publisher(self, topic, msg_class, queue_size=10, latch=False):
        handle = super().publisher(topic, msg_class, queue_size, latch)
        bus = self

        class Serialising:
            def publish(self, message):
                buffer = io.BytesIO()
                message.serialize(buffer)
                bus.wire.append((topic, buffer.getvalue()))

            def unregister(self):
                handle.unregister()

            shutdown = unregister
        return Serialising()

    def send_transforms(self, transforms):
        for transform in transforms:
            buffer = io.BytesIO()
            transform.serialize(buffer)
            self.wire.append(("/tf", buffer.getvalue()))

    def listened(self, publisher=None):
        return self.heard


def _world(heard, robots):
    bus = SerialisingBus(heard)
    world = World(bus, ray_threads=1)
    world.add_sdf_model(ModelSpec("ground", True, links=[
        LinkSpec("link", collisions=[ShapeSpec("plane")])]))
    for name, xml, position in ROBOTS:
        if name in robots:
            world.spawn_urdf(name, xml(), position)
    return world, bus


def _command(bus, change):
    twist = Twist()
    twist.linear.x, twist.angular.z = (0.3, 0.5) if change % 2 == 0 else (-0.2, -0.8)
    for topic, callback in bus.subscriptions.items():
        if topic.endswith("cmd_vel"):
            callback(twist)


def _drive(world, bus, advance):
    """Runs STEPS steps with the commands and the reset at their steps; by World.step, or
    by World.advance in BATCHES (never past the next event). Returns the batches made."""
    events = sorted(set(COMMAND_CHANGES) | {RESET_AT, STEPS})
    made, batches, sizes = 0, [], itertools.cycle(BATCHES)
    for event in events:
        while made < event:
            if advance:
                count = world.advance(min(next(sizes), event - made))
                batches.append(count)
            else:
                world.step()
                count = 1
            made += count
        if event in COMMAND_CHANGES:
            _command(bus, COMMAND_CHANGES.index(event))
        if event == RESET_AT:
            world.reset()
    return batches


def _state(world):
    """Every body's pose and velocity and every joint's state, as pybullet has them."""
    state = []
    for name, model in world.models.items():
        body = model.robot.id if model.robot is not None else model.body
        if body is None:
            continue
        state.append((name, pb.getBasePositionAndOrientation(body, physicsClientId=world.client),
                      pb.getBaseVelocity(body, physicsClientId=world.client)))
        for joint in range(pb.getNumJoints(body, physicsClientId=world.client)):
            state.append(pb.getJointState(body, joint, physicsClientId=world.client)[:2])
    return state


@pytest.mark.parametrize("robots", [RB1_ALONE, RATE_GATED, EVERY_STEP],
                         ids=["rb1_alone", "rate_gated", "all"])
@pytest.mark.parametrize("heard", [True, False], ids=["heard", "unheard"])
def test_advance_makes_the_same_world_and_messages_as_stepping(heard, robots):
    stepped, stepped_bus = _world(heard, robots)
    advanced, advanced_bus = _world(heard, robots)
    try:
        _drive(stepped, stepped_bus, advance=False)
        batches = _drive(advanced, advanced_bus, advance=True)
        assert advanced.now_ns == stepped.now_ns
        assert _state(advanced) == _state(stepped)
        assert advanced_bus.wire == stepped_bus.wire
        # the robots moved, and something was published (heard) or only /tf's absence
        rb1 = stepped.models["rb1_class"]
        assert pb.getBasePositionAndOrientation(rb1.robot.id,
                                                physicsClientId=stepped.client)[0][0] != 0.0
        if heard:
            topics = {topic for topic, _ in stepped_bus.wire}
            assert {"/scan", "/odom", "/tf"} <= topics, topics
        assert sum(batches) == STEPS
        # the rate-gated robots leave steps to the physics alone; with the planar move
        # (it sets the base's velocity at every step) every step calls the plugins
        assert (max(batches) > 1) == (robots != EVERY_STEP), batches
    finally:
        stepped.close()
        advanced.close()


@pytest.mark.parametrize("odometry_source", ["world", "encoder"])
def test_rate_gated_robot_is_stepped_in_batches_by_the_physics_alone(world, diff_bot_xml,
                                                                     odometry_source):
    """The bench's RB1-class robot (diff drive at 50 Hz, laser at 20 Hz): the plugins are
    called in the steps where one of them acts and in no other (the drive's slot, which
    falls at a step's start, its odometry and the laser's scans, at a step's end); with
    encoder odometry, which integrates the wheels at every step
    (gazebo_plugins/src/gazebo_ros_diff_drive.cpp:254-255), at every step."""
    model = world.spawn_urdf("bot", diff_bot_xml(odometry_source=odometry_source), (0, 0, 0))
    whole, acting = [], set()  # the start times of the steps calling the plugins, acting
    step = world.step

    def watched_step():
        whole.append(world.now_ns)
        return step()
    world.step = watched_step
    for plugin in model.plugins:
        for gate in (getattr(plugin, "slots", None), plugin.rate):
            if gate is None:
                continue

            def watched_due(now_ns, due=gate.due):
                answer = due(now_ns)
                if answer is not None and answer is not False:
                    acting.add(whole[-1])
                return answer
            gate.due = watched_due

    batches = [world.advance(20) for _ in range(200)]
    steps = sum(batches)
    if odometry_source == "world":
        assert set(whole) == acting, sorted(set(whole) ^ acting)[:10]
        # per 100 ms: 5 slots, 5 odometry messages, 2 scans (one of them on an odometry
        # step): 11 steps in 100
        assert abs(len(whole) - steps * 11 / 100) <= 3 and steps > 1000, (len(whole), steps)
        assert max(batches) >= 18
    else:
        assert batches == [1] * 200 and len(whole) == 200


def test_quiet_until_is_where_the_plugin_first_acts():
    """A plugin overriding neither hook never acts; one that overrides them acts at every
    step unless it says otherwise; the drive's update slots run exactly from the time
    quiet_until_ns names (Gazebo's float comparison, gazebo_plugins/src/
    gazebo_ros_diff_drive.cpp:269-271), for rates whose period is no whole number of
    nanoseconds as well."""
    class Idle(Plugin):
        def __init__(self):
            pass

    class Busy(Idle):
        def after_step(self, now_ns):
            pass

    assert Idle().quiet_until_ns(5, 1) == NEVER
    assert Busy().quiet_until_ns(5, 1) == 5
    for rate in (0.0, 1.0, 3.0, 7.0, 30.0, 50.0, 100.0, 333.0, 1000.0):
        slots = UpdateSlots(rate)
        assert slots.quiet_until_ns(123) == 123  # before its first call
        slots.due(0)
        for _ in range(3):
            quiet = slots.quiet_until_ns(0)
            last = slots.last_ns
            assert slots.due(quiet - 1) is None and slots.last_ns == last
            assert slots.due(quiet) is not None

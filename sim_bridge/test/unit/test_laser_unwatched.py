"""Sensors that measure only while their topic has a subscriber, as Noetic's
gazebo_ros_laser and gazebo_ros_gpu_laser (gazebo_ros_pkgs noetic-devel f9e1a46,
gazebo_plugins/src/gazebo_ros_laser.cpp:154-155: "sensor generation off by default";
:158-176: the sensor's scans are taken from the first /scan subscriber to the last;
gazebo_ros_gpu_laser.cpp:158, :165-181 the same): nothing is cast for nobody, and a
subscriber that comes later gets the scans at the times it would have had all along."""
import pytest

from sim_bridge.plugins.laser import Laser
from world_fixtures import run

SCAN_TOPIC = "/scan"
UNHEARD_SECONDS = 0.3
HEARD_SECONDS = 0.3


def _laser(world):
    return next(p for p in world.models["bot"].plugins if isinstance(p, Laser))


@pytest.mark.parametrize("filename", ["libgazebo_ros_laser.so", "libgazebo_ros_gpu_laser.so"])
def test_nothing_is_cast_while_nobody_listens_and_a_late_subscriber_keeps_the_slots(
        world, bus, diff_bot_xml, filename):
    world.spawn_urdf("bot", diff_bot_xml().replace("libgazebo_ros_laser.so", filename),
                     (0, 0, 0))
    laser = _laser(world)
    scans_cast = []
    measure = laser.measure
    laser.measure = lambda: scans_cast.append(world.now_ns) or measure()
    bus.unheard.add(SCAN_TOPIC)
    run(world, UNHEARD_SECONDS)
    assert SCAN_TOPIC not in bus.published and scans_cast == []

    bus.unheard.discard(SCAN_TOPIC)
    run(world, HEARD_SECONDS)
    stamps = [scan.header.stamp.to_nsec() for scan in bus.published[SCAN_TOPIC]]
    assert len(scans_cast) == len(stamps) >= 5  # the sensor's 20 Hz over 0.3 s

    # the slots a laser heard from the start has at the same times
    from recording_bus import RecordingBus
    from sim_bridge.world import World
    from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec
    heard_bus = RecordingBus()
    heard = World(heard_bus, ray_threads=1)
    try:
        heard.add_sdf_model(ModelSpec("ground", True, links=[
            LinkSpec("link", collisions=[ShapeSpec("plane")])]))
        heard.spawn_urdf("bot", diff_bot_xml().replace("libgazebo_ros_laser.so", filename),
                         (0, 0, 0))
        run(heard, UNHEARD_SECONDS + HEARD_SECONDS)
        all_along = [scan.header.stamp.to_nsec() for scan in heard_bus.published[SCAN_TOPIC]]
    finally:
        heard.close()
    assert stamps == [stamp for stamp in all_along if stamp >= stamps[0]]
    assert stamps[0] - UNHEARD_SECONDS * 1e9 <= 0.05e9  # the first slot once heard


def test_a_range_sensor_measures_only_while_heard_and_keeps_its_slots(world, bus):
    """gazebo_ros_range the same way (gazebo_plugins/src/gazebo_ros_range.cpp:220: the
    sensor off at load; :228-241: on from the first subscriber to the last): the sensor
    robot's sonar at 20 Hz casts nothing unheard, then reads at its slots."""
    from sim_bridge.plugins.range import Range
    from urdf_tools.xacro_loader import expand
    from world_fixtures import DATA
    import os
    world.spawn_urdf("bot", expand(os.path.join(DATA, "sensor_bot.urdf.xacro")), (0, 0, 0.01))
    sonar = next(p for p in world.models["bot"].plugins if isinstance(p, Range))
    topic = sonar.output.topic
    measured = []
    measure = sonar.measure
    sonar.measure = lambda: measured.append(world.now_ns) or measure()
    bus.unheard.add(topic)
    run(world, UNHEARD_SECONDS)
    assert topic not in bus.published and measured == []
    bus.unheard.discard(topic)
    run(world, HEARD_SECONDS)
    # the plugin sends one message object again and again, as upstream's: count them
    assert len(bus.published[topic]) == len(measured) >= 5
    assert all(later - earlier == 50_000_000  # its <update_rate> 20
               for earlier, later in zip(measured, measured[1:]))
    assert measured[0] - UNHEARD_SECONDS * 1e9 <= 50_000_000


def silent_then_heard_at_50_hz(world, bus, topic):
    """``topic`` unheard for UNHEARD_SECONDS: nothing published; then heard for
    HEARD_SECONDS: a message each 20 ms slot. The stamps heard."""
    bus.unheard.add(topic)
    run(world, UNHEARD_SECONDS)
    assert topic not in bus.published
    bus.unheard.discard(topic)
    run(world, HEARD_SECONDS)
    stamps = [message.header.stamp.to_nsec() for message in bus.published[topic]]
    assert len(stamps) >= 10
    assert all(later - earlier == 20_000_000 for earlier, later in zip(stamps, stamps[1:]))
    return stamps


def test_p3d_computes_only_while_heard_and_keeps_its_slots(world, bus):
    """gazebo_ros_p3d fills and publishes only while subscribed
    (gazebo_plugins/src/gazebo_ros_p3d.cpp:243): the gadget robot's 50 Hz ground truth of
    its pan link publishes nothing unheard (no noise drawn for nobody), then one message
    per 20 ms slot, stamped with its slot."""
    import os

    from sim_bridge.plugins.p3d import P3D
    from world_fixtures import DATA
    with open(os.path.join(DATA, "gadget_bot.urdf"), encoding="utf-8") as stream:
        world.spawn_urdf("bot", stream.read(), (0, 0, 0.05))
    truth = next(p for p in world.models["bot"].plugins if isinstance(p, P3D))
    stamps = silent_then_heard_at_50_hz(world, bus, truth.output.topic)
    assert stamps[0] - UNHEARD_SECONDS * 1e9 <= 20_000_000


def test_a_bumper_reports_only_while_heard(world, bus):
    """gazebo_ros_bumper's OnContact returns at once without subscribers
    (gazebo_plugins/src/gazebo_ros_bumper.cpp:142-143): a 50 Hz bumper plate publishes
    nothing unheard, then one message per 20 ms slot."""
    from sim_bridge.plugins.bumper import Bumper
    from test_bumper import robot
    world.spawn_urdf("bot", robot(), (0, 0, 0.11))
    plate = next(p for p in world.models["bot"].plugins if isinstance(p, Bumper))
    silent_then_heard_at_50_hz(world, bus, plate.output.topic)

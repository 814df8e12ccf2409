"""gazebo_ros_control's ``controlPeriod`` on pybullet.DIRECT (a 1 ms step): the controllers
update once a period, the hardware writes their last commands every step; checked on the
joint's true state.

Upstream: gazebo_ros_pkgs noetic-devel f9e1a46 gazebo_ros_control/src/
gazebo_ros_control_plugin.cpp ("plugin")."""
import pytest
from controller_manager_msgs.srv import LoadControllerRequest, SwitchControllerRequest
from std_msgs.msg import Float64

from recording_bus import RecordingBus
from sim_bridge.world import World
from test_ros_control_limits import CONTROLLERS, MANAGER, spin, spinner_urdf
from world_fixtures import run

NAMESPACE_TAG = "<robotNamespace>/spinner</robotNamespace>"


def spinner(kind, period, params=None, controller=None):
    """The spinner with ``<controlPeriod>period</controlPeriod>`` (None: no tag) and its
    ``kind`` controller (or ``controller``'s parameters) running."""
    configuration = controller or {"type": CONTROLLERS[kind][0], "joint": "spin"}
    bus = RecordingBus({"/spinner/controller": configuration, **(params or {})})
    world = World(bus, ray_threads=1)
    urdf = spinner_urdf(kind, limit='<limit effort="50" velocity="100"/>')
    if period is not None:
        urdf = urdf.replace(NAMESPACE_TAG, f"{NAMESPACE_TAG}<controlPeriod>{period}</controlPeriod>")
    model = world.spawn_urdf("spinner", urdf)
    assert bus.services[f"{MANAGER}/load_controller"](LoadControllerRequest("controller")).ok, \
        bus.warnings
    assert bus.services[f"{MANAGER}/switch_controller"](
        SwitchControllerRequest(start_controllers=["controller"], strictness=2)).ok
    return world, bus, model


def test_a_longer_control_period_is_named_and_the_effort_is_applied_every_step():
    """controlPeriod 0.01 s at a 1 ms step: "Desired controller update period (0.010000000 s)
    is slower than the gazebo simulation period (0.001000000 s)." (plugin:136-140); writeSim
    runs every step (plugin:256), so 1 N m on 0.1 kg m^2 gives 5 rad/s after 0.5 s. Before:
    the torque was written once a period and lasted one step: 0.5 rad/s."""
    world, bus, model = spinner("effort", 0.01)
    assert ("Desired controller update period (0.010000000 s) is slower than the gazebo "
            "simulation period (0.001000000 s).") in bus.warnings, bus.warnings
    bus.subscriptions["/spinner/controller/command"](Float64(1.0))
    run(world, 0.5)
    # the command is taken at the first update after it, within one period
    assert 4.9 <= spin(model)[1] <= 5.0 + 1e-6
    world.close()


def test_a_longer_control_period_updates_the_controllers_at_that_period():
    """The controllers update when the period has elapsed (plugin:225-252): an effort PID
    position controller's state, every 10th update, comes every 10 periods (0.1 s) and says
    the period; the position controller's step is the period too."""
    world, bus, model = spinner("effort", 0.01, controller={
        "type": "effort_controllers/JointPositionController", "joint": "spin",
        "pid": {"p": 20.0, "d": 2.0}})
    bus.subscriptions["/spinner/controller/command"](Float64(1.0))
    run(world, 1.0)
    states = bus.published["/spinner/controller/state"]
    assert len(states) == 10
    assert [(b.header.stamp - a.header.stamp).to_sec() for a, b in zip(states, states[1:])] == \
        pytest.approx([0.1] * 9)
    assert states[-1].time_step == pytest.approx(0.01)
    world.close()


def test_a_shorter_control_period_is_an_error_and_the_controllers_update_every_step():
    """controlPeriod 0.0005 s at a 1 ms step: "... is faster than the gazebo simulation
    period ..." (plugin:131-135), and the controllers update every step: a state every 10
    steps. No tag: the step, silently (plugin:142-147)."""
    world, bus, model = spinner("effort", 0.0005, controller={
        "type": "effort_controllers/JointPositionController", "joint": "spin",
        "pid": {"p": 20.0, "d": 2.0}})
    assert ("Desired controller update period (0.000500000 s) is faster than the gazebo "
            "simulation period (0.001000000 s).") in bus.warnings, bus.warnings
    run(world, 0.1)
    assert len(bus.published["/spinner/controller/state"]) == 10
    world.close()
    world, bus, model = spinner("effort", None)
    assert not [w for w in bus.warnings if "update period" in w]
    world.close()

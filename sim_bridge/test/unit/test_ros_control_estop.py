"""gazebo_ros_control's ``eStopTopic`` on pybullet.DIRECT: while a ``std_msgs/Bool`` true
is the last message, efforts and velocities are 0 and position joints hold; on release the
running controllers start over. Checked on the joint's true state.

Upstream: gazebo_ros_pkgs noetic-devel f9e1a46 gazebo_ros_control/src/
gazebo_ros_control_plugin.cpp ("plugin"), default_robot_hw_sim.cpp ("hw_sim"); ros_control
noetic-devel 633c374 controller_manager/src/controller_manager.cpp ("CM")."""
import pytest
from std_msgs.msg import Bool, Float64

from one_joint_robot import start_controllers
from recording_bus import RecordingBus
from sim_bridge.world import World
from test_ros_control_limits import CONTROLLERS, spin, spinner_urdf
from world_fixtures import run

NAMESPACE_TAG = "<robotNamespace>/spinner</robotNamespace>"
E_STOP = "/spinner/e_stop"  # <eStopTopic>e_stop</eStopTopic>, in the robot's namespace


def spinner(kind, joint_type="continuous", limit='<limit effort="50" velocity="2"/>'):
    bus = RecordingBus({"/spinner/controller": {"type": CONTROLLERS[kind][0], "joint": "spin"},
                        "/spinner/joint_state_controller": {
                            "type": "joint_state_controller/JointStateController",
                            "publish_rate": 100}})
    world = World(bus, ray_threads=1)
    urdf = spinner_urdf(kind, joint_type=joint_type, limit=limit).replace(
        NAMESPACE_TAG, f"{NAMESPACE_TAG}<eStopTopic>e_stop</eStopTopic>")
    model = world.spawn_urdf("spinner", urdf)
    start_controllers(bus, "spinner", "controller", "joint_state_controller")
    return world, bus, model


def command(bus, value):
    bus.subscriptions["/spinner/controller/command"](Float64(value))


def e_stop(bus, active):
    bus.subscriptions[E_STOP](Bool(active))


def test_the_emergency_stop_stops_a_velocity_joint_and_its_release_restarts_the_controller():
    """Velocity joints get 0 while it is on (hw_sim:359-368): a rotor at 1.5 rad/s stops;
    on release the running controllers are stopped and started (plugin:240-251, CM:70-78),
    and a JointVelocityController starts at 0: it stays still until commanded again.
    Before: eStopTopic was only named in a warning and the rotor went on."""
    world, bus, model = spinner("velocity")
    assert not [w for w in bus.warnings if "eStopTopic" in w]
    command(bus, 1.5)
    run(world, 0.2)
    assert spin(model)[1] == pytest.approx(1.5, abs=0.01)
    e_stop(bus, True)
    run(world, 0.2)
    assert spin(model)[1] == pytest.approx(0.0, abs=0.01)
    e_stop(bus, False)
    run(world, 0.2)
    assert spin(model)[1] == pytest.approx(0.0, abs=0.01)  # restarted at 0
    command(bus, 1.0)
    run(world, 0.2)
    assert spin(model)[1] == pytest.approx(1.0, abs=0.01)
    world.close()


def test_the_emergency_stop_holds_a_position_joint_where_it_was():
    """Position commands are the positions read when it began (hw_sim:287-300): a joint on
    its way to 1 rad at 2 rad/s stops where it was after 0.25 s; on release its controller
    starts from there (JointPositionController's start: the current position) and does not
    jump to the old command."""
    world, bus, model = spinner("position", joint_type="revolute",
                                limit='<limit lower="-3" upper="3" effort="50" velocity="2"/>')
    command(bus, 1.0)
    run(world, 0.25)
    held = spin(model)[0]  # what the next update reads
    assert 0.3 < held < 0.7
    e_stop(bus, True)
    run(world, 0.5)
    assert spin(model)[0] == pytest.approx(held, abs=1e-3)
    e_stop(bus, False)
    run(world, 0.5)
    assert spin(model)[0] == pytest.approx(held, abs=1e-3)
    command(bus, 1.0)
    run(world, 1.0)
    assert spin(model)[0] == pytest.approx(1.0, abs=1e-3)
    world.close()


def test_the_emergency_stop_gives_an_effort_joint_no_effort():
    """SetForce(0) while it is on (hw_sim:313-318): a rotor given 1 N m coasts at the speed
    it had (no friction), and joint_states says 0 N m."""
    world, bus, model = spinner("effort")
    command(bus, 1.0)
    run(world, 0.1)
    e_stop(bus, True)
    run(world, 0.01)
    speed = spin(model)[1]
    run(world, 0.2)
    assert spin(model)[1] == pytest.approx(speed, abs=1e-3)
    assert bus.last("/spinner/joint_states").effort[0] == 0.0
    world.close()

"""ros_controllers' PID position controllers on pybullet.DIRECT: the command clamped to the
URDF's limits, the error wrapped as the joint's type asks, ``<controller>/state``; checked on
the joint's true position.

Upstream: ros_controllers noetic-devel 678b92a effort_controllers/src/
joint_position_controller.cpp ("epc"), velocity_controllers/src/joint_position_controller.cpp
("vpc"), effort_controllers/src/joint_group_position_controller.cpp ("gpc"); ros/angles
angles.h (shortest_angular_distance_with_large_limits)."""
import math

import pytest
from control_msgs.msg import JointControllerState
from controller_manager_msgs.srv import LoadControllerRequest
from std_msgs.msg import Float64, Float64MultiArray

from one_joint_robot import one_joint_urdf, start_controllers
from recording_bus import RecordingBus
from sim_bridge.ros_control.angles import shortest_angular_distance_with_large_limits
from sim_bridge.world import World
from world_fixtures import run

MANAGER = "/spinner/controller_manager"
# a well-damped loop on the rotor's 0.1 kg m^2: p 20, d 2
GAINS = {"p": 20.0, "d": 2.0}
VELOCITY_GAINS = {"p": 5.0}


def spinner(controller, joint_type="revolute", limit='<limit lower="-1" upper="1" effort="50" '
            'velocity="10"/>', position=0.0, interface="effort", gains=None, axis="0 0 1"):
    """The world, the bus and the model at ``position``, ``controller`` (a type) running."""
    bus = RecordingBus({"/spinner/controller": {"type": controller, "joint": "spin",
                                                "pid": gains or GAINS},
                        "/spinner/joint_state_controller": {
                            "type": "joint_state_controller/JointStateController",
                            "publish_rate": 100}})
    world = World(bus, ray_threads=1)
    urdf = one_joint_urdf(interface, joint_type=joint_type, limit=limit, axis=axis)
    model = world.spawn_urdf("spinner", urdf, joints={"spin": position})
    start_controllers(bus, "spinner", "controller", "joint_state_controller")
    return world, bus, model


def effort(bus):
    """The effort the joint was last given (joint_states: an effort joint's applied command,
    hw_sim:281)."""
    return bus.last("/spinner/joint_states").effort[0]


def command(bus, value):
    bus.subscriptions["/spinner/controller/command"](Float64(value))


def spin(model):
    """The joint's true (position, velocity), from pybullet."""
    return model.robot.joint_position_velocity("spin")


EFFORT_POSITION = "effort_controllers/JointPositionController"


def test_a_command_beyond_the_urdf_limits_is_clamped_to_them():
    """enforceJointLimits (epc:253-267, applied each update, :179): a command of 3 rad on a
    revolute joint limited to [-2, 1.5] is 1.5, and the state's set_point says so: the rotor
    rests at the limit with no effort. Before, the PID pushed it against the joint's stop
    with p (3 - 1.5) = 30 N m."""
    world, bus, model = spinner(EFFORT_POSITION,
                                limit='<limit lower="-2" upper="1.5" effort="50" velocity="10"/>')
    command(bus, 3.0)
    run(world, 3.0)
    assert spin(model)[0] == pytest.approx(1.5, abs=0.01)
    assert abs(effort(bus)) < 0.1
    assert bus.last("/spinner/controller/state").set_point == 1.5
    command(bus, -5.0)
    run(world, 3.0)
    assert spin(model)[0] == pytest.approx(-2.0, abs=0.01)
    assert abs(effort(bus)) < 0.1
    world.close()


def test_a_prismatic_joints_command_is_clamped_and_its_error_is_the_difference():
    """Prismatic: clamped to [lower, upper] (epc:256-266), error = command - position
    (:195-198): 0.4 m within [-0.5, 0.5] is reached; 0.8 stops at 0.5. A horizontal slide of
    1 kg, p 100 and d 20: critically damped."""
    world, bus, model = spinner(EFFORT_POSITION, joint_type="prismatic", axis="1 0 0",
                                gains={"p": 100.0, "d": 20.0},
                                limit='<limit lower="-0.5" upper="0.5" effort="50" velocity="10"/>')
    command(bus, 0.4)
    run(world, 3.0)
    assert spin(model)[0] == pytest.approx(0.4, abs=0.005)
    command(bus, 0.8)
    run(world, 3.0)
    assert spin(model)[0] == pytest.approx(0.5, abs=0.005)
    assert abs(effort(bus)) < 0.5  # before: p (0.8 - 0.5) = 30 N against the stop
    world.close()


def test_a_continuous_joint_turns_the_short_way():
    """Continuous: error = shortest_angular_distance(position, command) (epc:191-194): from
    6.0 rad a command of 0.1 rad is 0.38 rad ahead, so the rotor settles at 0.1 + 2 pi; before,
    it unwound 5.9 rad back to 0.1."""
    world, bus, model = spinner(EFFORT_POSITION, joint_type="continuous",
                                limit='<limit effort="50" velocity="10"/>', position=6.0)
    command(bus, 0.1)
    run(world, 3.0)
    assert spin(model)[0] == pytest.approx(0.1 + 2 * math.pi, abs=0.01)
    state = bus.last("/spinner/controller/state")
    assert state.set_point == pytest.approx(0.1)  # the command itself, not unwrapped
    assert state.error == pytest.approx(0.1 + 2 * math.pi - spin(model)[0], abs=0.01)
    world.close()


@pytest.mark.parametrize("upper, expected", [(4.0, 2 * math.pi - 3.0), (3.2, -3.0)])
def test_a_revolute_joint_with_large_limits_takes_the_shorter_turn_the_limits_allow(upper,
                                                                                  expected):
    """Revolute: shortest_angular_distance_with_large_limits(position, command, lower, upper)
    (epc:182-190): from 3.0 rad a command of -3.0 rad is the same angle as 2 pi - 3.0 (0.28
    rad ahead); with limits [-4, 4] the rotor goes there, with [-4, 3.2] that turn would pass
    the upper limit and it goes the long way to -3.0. Before, it went to -3.0 both times."""
    world, bus, model = spinner(EFFORT_POSITION, position=3.0, limit=(
        f'<limit lower="-4" upper="{upper}" effort="50" velocity="10"/>'))
    command(bus, -3.0)
    run(world, 3.0)
    assert spin(model)[0] == pytest.approx(expected, abs=0.01)
    world.close()


def test_the_angle_functions_agree_with_the_documented_examples():
    """angles.h's own examples for shortest_angular_distance_with_large_limits: from 0 to
    10.5 pi within [-2 pi, 2 pi] is 0.5 pi; within [-2 pi, 0.1 pi] it is -1.5 pi."""
    assert shortest_angular_distance_with_large_limits(
        0.0, 10.5 * math.pi, -2 * math.pi, 2 * math.pi) == pytest.approx(0.5 * math.pi)
    assert shortest_angular_distance_with_large_limits(
        0.0, 10.5 * math.pi, -2 * math.pi, 0.1 * math.pi) == pytest.approx(-1.5 * math.pi)


def test_the_state_is_published_on_the_first_update_and_every_tenth():
    """``<controller>/state``, control_msgs/JointControllerState, when loop_count_ % 10 == 0
    (epc:219-244): at a 1 ms step, 0.1 s is 100 updates and 10 messages, the first stamped at
    the first update. Its fields: the clamped set point, the true position and velocity, the
    error, the period, the effort commanded and the gains (i_clamp is i_max). Before: no
    state topic."""
    gains = {"p": 20.0, "i": 0.5, "d": 2.0, "i_clamp": 0.3, "antiwindup": True}
    world, bus, model = spinner(EFFORT_POSITION, gains=gains)
    start_ns = world.now_ns
    command(bus, 5.0)
    truth = []  # the joint's true state as each update reads it, before its step
    for _ in range(round(0.1 / world.step_size)):
        truth.append(spin(model))
        world.step()
    messages = bus.published["/spinner/controller/state"]
    assert len(messages) == len(truth) // 10
    assert messages[0].header.stamp.to_nsec() == start_ns
    assert (messages[1].header.stamp - messages[0].header.stamp).to_nsec() == \
        round(10 * world.step_size * 1e9)
    last = messages[-1]
    assert isinstance(last, JointControllerState)
    assert last.set_point == 1.0  # 5.0 clamped to the upper limit
    assert (last.p, last.i, last.d, last.i_clamp, last.antiwindup) == (20.0, 0.5, 2.0, 0.3, True)
    assert last.time_step == pytest.approx(world.step_size)
    position, velocity = truth[10 * (len(messages) - 1)]
    assert (last.process_value, last.process_value_dot) == pytest.approx((position, velocity),
                                                                         abs=1e-9)
    assert last.error == pytest.approx(1.0 - position)
    # the effort commanded: computeCommand(error, dt) on the errors of every update so far
    errors = [1.0 - p for p, _ in truth[:10 * (len(messages) - 1) + 1]]
    dt = world.step_size
    assert last.command == pytest.approx(20.0 * errors[-1] + 0.5 * dt * sum(errors)
                                         + 2.0 * (errors[-1] - errors[-2]) / dt, rel=1e-6)
    world.close()


def test_the_group_position_controller_clamps_and_wraps_as_the_single_one():
    """gpc:145-171: each joint's command clamped to its URDF limits, the error by joint type:
    a continuous joint at 6.0 rad commanded to 0.1 rad settles at 0.1 + 2 pi (before: it
    unwound to 0.1)."""
    bus = RecordingBus({"/spinner/controller": {
        "type": "effort_controllers/JointGroupPositionController", "joints": ["spin"],
        "spin": {"pid": GAINS}}})
    world = World(bus, ray_threads=1)
    model = world.spawn_urdf("spinner", one_joint_urdf(
        "effort", joint_type="continuous", limit='<limit effort="50" velocity="10"/>'),
        joints={"spin": 6.0})
    start_controllers(bus, "spinner", "controller")
    bus.subscriptions["/spinner/controller/command"](Float64MultiArray(data=[0.1]))
    run(world, 3.0)
    assert spin(model)[0] == pytest.approx(0.1 + 2 * math.pi, abs=0.01)
    world.close()


def test_the_effort_velocity_controller_publishes_its_state():
    """effort_controllers/JointVelocityController's state (joint_velocity_controller.cpp:
    144-166): set point the commanded velocity, process value the true velocity,
    process_value_dot left 0. Before: no state topic."""
    world, bus, model = spinner("effort_controllers/JointVelocityController",
                                joint_type="continuous", limit='<limit effort="50" velocity="10"/>',
                                gains={"p": 2.0})
    command(bus, 1.0)
    run(world, 2.0)
    state = bus.last("/spinner/controller/state")
    assert state.set_point == 1.0
    assert state.process_value == pytest.approx(spin(model)[1], abs=1e-3)
    assert state.process_value_dot == 0.0
    assert state.error == pytest.approx(1.0 - state.process_value)
    world.close()


def test_joint_controller_state_has_control_msgs_layout():
    """compat's control_msgs/JointControllerState is control_msgs 1.5's: the md5sum of
    ros-controls/control_msgs control_msgs/msg/JointControllerState.msg (commit 0e5fd15)."""
    assert JointControllerState._md5sum == "987ad85e4756f3aef7f1e5e7fe0595d1"


VELOCITY_POSITION = "velocity_controllers/JointPositionController"


def test_the_velocity_position_controller_brings_a_velocity_joint_to_its_command():
    """velocity_controllers/JointPositionController (RC velocity_controllers/
    velocity_controllers_plugins.xml:9; vpc): the PID's output is the joint's velocity
    command (vpc:209-218), p 5: a first-order approach, within 1e-3 rad after 3 s; the
    command clamped to the URDF limits (vpc:254-268) and the state published (vpc:221-245).
    Before: the type was not emulated and the controller did not load."""
    world, bus, model = spinner(VELOCITY_POSITION, interface="velocity", gains=VELOCITY_GAINS)
    command(bus, 0.8)
    run(world, 0.2)  # one time constant (1/p): 63% of the way
    assert spin(model)[0] == pytest.approx(0.8 * (1 - math.exp(-1)), abs=0.01)
    run(world, 2.8)
    assert spin(model) == pytest.approx((0.8, 0.0), abs=1e-3)
    command(bus, 3.0)
    run(world, 3.0)
    assert spin(model)[0] == pytest.approx(1.0, abs=1e-3)
    state = bus.last("/spinner/controller/state")
    assert state.set_point == 1.0
    assert state.command == pytest.approx(5.0 * state.error)
    world.close()


def test_the_velocity_position_controller_needs_a_velocity_joint():
    """It claims a VelocityJointInterface (vpc:58): on an effort joint it does not load."""
    bus = RecordingBus({"/spinner/controller": {"type": VELOCITY_POSITION, "joint": "spin",
                                                "pid": VELOCITY_GAINS}})
    world = World(bus, ray_threads=1)
    world.spawn_urdf("spinner", one_joint_urdf(
        "effort", joint_type="revolute",
        limit='<limit lower="-1" upper="1" effort="50" velocity="10"/>'))
    assert not bus.services[f"{MANAGER}/load_controller"](LoadControllerRequest("controller")).ok
    assert any("VelocityJointInterface" in w for w in bus.warnings), bus.warnings
    world.close()

"""DefaultRobotHWSim's ``gazebo_ros_control/pid_gains/<joint>`` on pybullet.DIRECT: a
position or velocity joint with gains is driven by an effort from that PID, clamped to the
joint's effort limit; checked on the joint's true state.

Upstream: gazebo_ros_pkgs noetic-devel f9e1a46 gazebo_ros_control/src/default_robot_hw_sim.cpp
("hw_sim")."""
import math

import pytest
from std_msgs.msg import Float64

from one_joint_robot import one_joint_urdf, start_controllers
from recording_bus import RecordingBus
from sim_bridge.world import World
from world_fixtures import run

CONTROLLERS = {"position": "position_controllers/JointPositionController",
               "velocity": "velocity_controllers/JointVelocityController"}
GRAVITY = 9.81
# the pendulum: 1 kg at 0.5 m below a horizontal axis; its effort limit, 2 N m, holds it at
# most asin(2 / (1 * 9.81 * 0.5)) = 0.42 rad from hanging
BOB_MASS, ARM_LENGTH, EFFORT_LIMIT = 1.0, 0.5, 2.0


def bot_urdf(interface, axis, limit, mass=BOB_MASS, offset=-ARM_LENGTH, damping=0.0):
    """A link on a joint ``axis`` through the base, its mass ``offset`` along z from it."""
    return one_joint_urdf(interface, robot="bot", joint="joint", child="arm",
                          joint_type="revolute" if "lower" in limit else "continuous",
                          limit=limit, axis=axis, origin="0 0 1", mass=mass,
                          inertia=(0.1, 0.1, 0.1), centre_of_mass=f"0 0 {offset}",
                          dynamics=f'<dynamics damping="{damping}"/>')


def bot(interface, gains=None, axis="0 1 0", limit=f'<limit lower="-3" upper="3" '
        f'effort="{EFFORT_LIMIT}" velocity="10"/>', position=0.0, **urdf):
    params = {"/bot/controller": {"type": CONTROLLERS[interface], "joint": "joint"},
              "/bot/joint_state_controller": {
                  "type": "joint_state_controller/JointStateController", "publish_rate": 50}}
    if gains is not None:
        params["/bot/gazebo_ros_control/pid_gains/joint"] = gains
    bus = RecordingBus(params)
    world = World(bus, ray_threads=1)
    model = world.spawn_urdf("bot", bot_urdf(interface, axis, limit, **urdf),
                             joints={"joint": position})
    start_controllers(bus, "bot", "controller", "joint_state_controller")
    return world, bus, model


def command(bus, value):
    bus.subscriptions["/bot/controller/command"](Float64(value))


def joint(model):
    return model.robot.joint_position_velocity("joint")


def test_without_pid_gains_a_position_joint_lifts_what_its_effort_limit_cannot():
    """No pid_gains: SetPosition, no effort limit (hw_sim:320-326): the pendulum is lifted
    to 1 rad whatever its 2 N m limit."""
    world, bus, model = bot("position")
    command(bus, 1.0)
    run(world, 2.0)
    assert joint(model)[0] == pytest.approx(1.0, abs=1e-3)
    world.close()


def test_with_pid_gains_a_position_joint_is_driven_by_an_effort_within_its_limit():
    """pid_gains: POSITION_PID (hw_sim:216-233, :328-353), the effort clamped to the 2 N m
    limit: the pendulum stops where gravity's torque is 2 N m, asin(2 / (m g l)) = 0.42 rad,
    short of 1 rad; joint_states' effort is the applied 2 N m (GetForce, hw_sim:281). Before,
    the gains were not read and the joint reached 1 rad. (The saturated PID does not damp
    the swing: the joint's own damping, 2 N m s/rad, settles it.)"""
    world, bus, model = bot("position", gains={"p": 100.0, "d": 10.0}, damping=2.0)
    command(bus, 1.0)
    run(world, 5.0)
    position, velocity = joint(model)
    assert position == pytest.approx(math.asin(EFFORT_LIMIT / (BOB_MASS * GRAVITY * ARM_LENGTH)),
                                     abs=0.01)
    assert abs(velocity) < 1e-3
    assert bus.last("/bot/joint_states").effort[0] == pytest.approx(EFFORT_LIMIT)
    # within its strength, the PID brings it to the target (p 100: 1 mm of steady error per
    # 0.1 N m of load)
    command(bus, 0.2)
    run(world, 3.0)
    load = BOB_MASS * GRAVITY * ARM_LENGTH * math.sin(0.2)
    assert joint(model)[0] == pytest.approx(0.2 - load / 100.0, abs=1e-3)
    world.close()


def test_with_pid_gains_a_continuous_joint_takes_the_shortest_angle():
    """POSITION_PID's error for a continuous joint is shortest_angular_distance (hw_sim:
    340-342): on a vertical axis (no load) and no <limit> (no saturation), from 6.0 rad a
    command of 0.1 rad is reached at 0.1 + 2 pi; without gains the position motor unwinds it
    to 0.1."""
    for gains, expected in (({"p": 20.0, "d": 2.0}, 0.1 + 2 * math.pi), (None, 0.1)):
        world, bus, model = bot("position", gains=gains, axis="0 0 1", limit="", position=6.0)
        command(bus, 0.1)
        run(world, 3.0)
        assert joint(model)[0] == pytest.approx(expected, abs=0.01), gains
        world.close()


def test_with_pid_gains_a_velocity_joint_follows_through_the_pid():
    """VELOCITY_PID (hw_sim:370-380): effort = p (command - velocity); on a vertical axis
    with 0.1 kg m^2, p 0.1 is a first-order lag of I/p = 1 s: 1 - 1/e of 1 rad/s after 1 s.
    Without gains the velocity motor is at 1 rad/s at once."""
    world, bus, model = bot("velocity", gains={"p": 0.1}, axis="0 0 1", offset=0.0,
                            limit='<limit effort="50" velocity="10"/>')
    command(bus, 1.0)
    run(world, 1.0)
    assert joint(model)[1] == pytest.approx(1.0 - math.exp(-1.0), abs=0.01)
    world.close()
    world, bus, model = bot("velocity", axis="0 0 1", offset=0.0,
                            limit='<limit effort="50" velocity="10"/>')
    command(bus, 1.0)
    run(world, 0.01)
    assert joint(model)[1] == pytest.approx(1.0, abs=1e-3)
    world.close()


def test_pid_gains_without_p_leave_the_joint_set_directly_and_say_so():
    """Pid::init fails without a p gain (control_toolbox pid.cpp:113-119): the joint keeps
    SetPosition (hw_sim:222, :234-244) and lifts the pendulum; a warning names the gains."""
    world, bus, model = bot("position", gains={"d": 10.0})
    command(bus, 1.0)
    run(world, 2.0)
    assert joint(model)[0] == pytest.approx(1.0, abs=1e-3)
    assert any("/bot/gazebo_ros_control/pid_gains/joint" in w for w in bus.warnings), \
        bus.warnings
    world.close()

"""DefaultRobotHWSim's joint limits, on pybullet.DIRECT: what a command does to the joint
as the URDF's <limit> and the joint_limits parameters allow it, checked on the joint's true
velocity and position.

Upstream: gazebo_ros_pkgs noetic-devel f9e1a46 gazebo_ros_control/src/default_robot_hw_sim.cpp
("hw_sim"); ros_control noetic-devel 633c374 joint_limits_interface ("JLI")."""
import pytest
from controller_manager_msgs.srv import LoadControllerRequest, SwitchControllerRequest
from std_msgs.msg import Float64

from one_joint_robot import one_joint_urdf
from recording_bus import RecordingBus
from sim_bridge.world import World
from world_fixtures import run

MANAGER = "/spinner/controller_manager"
CONTROLLERS = {
    "velocity": ("velocity_controllers/JointVelocityController", "VelocityJointInterface"),
    "position": ("position_controllers/JointPositionController", "PositionJointInterface"),
    "effort": ("effort_controllers/JointEffortController", "EffortJointInterface"),
}


def spinner_urdf(interface, joint_type="continuous", limit='<limit effort="50" velocity="2.0"/>',
                 izz=0.1):
    """A rotor on a vertical axis (gravity does not turn it) on a base fixed to the world."""
    return one_joint_urdf(interface, joint_type=joint_type, limit=limit,
                          inertia=(0.6 * izz, 0.6 * izz, izz))


def spinner(interface, params=None, **urdf):
    """The world, the bus and the model, its controller for ``interface`` running."""
    bus = RecordingBus({"/spinner/controller": {"type": CONTROLLERS[interface][0], "joint": "spin"},
                        **(params or {})})
    world = World(bus, ray_threads=1)
    model = world.spawn_urdf("spinner", spinner_urdf(interface, **urdf))
    assert bus.services[f"{MANAGER}/load_controller"](LoadControllerRequest("controller")).ok, \
        bus.warnings
    assert bus.services[f"{MANAGER}/switch_controller"](
        SwitchControllerRequest(start_controllers=["controller"], strictness=2)).ok
    return world, bus, model


def command(bus, value):
    bus.subscriptions["/spinner/controller/command"](Float64(value))


def spin(model):
    """The joint's true (position, velocity), from pybullet."""
    return model.robot.joint_position_velocity("spin")


def test_a_velocity_command_is_clamped_to_the_urdf_velocity_limit():
    """VelocityJointSaturationHandle: ±<limit velocity> (JLI joint_limits_interface.h:425-455;
    registered from the URDF, hw_sim:418, :501-506; enforced every write, hw_sim:306)."""
    world, bus, model = spinner("velocity")
    command(bus, 10.0)
    run(world, 0.5)
    assert spin(model)[1] == pytest.approx(2.0, abs=0.02)  # was 10
    command(bus, -10.0)
    run(world, 0.5)
    assert spin(model)[1] == pytest.approx(-2.0, abs=0.02)
    world.close()


def test_a_joint_without_a_limit_has_no_effort_limit():
    """No <limit>: no limits registered and the effort limit is DBL_MAX (hw_sim:404,
    :428-429), which the velocity motor gets as its fmax (hw_sim:240): a heavy flywheel is at
    its commanded speed at once (it took 1000 N m before, 0.5 rad/s² for this one)."""
    world, bus, model = spinner("velocity", limit="", izz=2000.0)
    command(bus, 10.0)
    run(world, 0.05)
    assert spin(model)[1] == pytest.approx(10.0, abs=0.01)
    world.close()


@pytest.mark.parametrize("interface", ["velocity", "effort"])
def test_an_effort_limit_of_zero_leaves_the_joint_unmoved(interface):
    """effort="0" is a limit of 0 (JLI joint_limits_urdf.h:72-73; hw_sim:453-454): the
    velocity motor's fmax is 0 (hw_sim:240), an effort command is saturated to 0
    (EffortJointSaturationHandle, JLI :285-306). It was 1000 N m before."""
    world, bus, model = spinner(interface, limit='<limit effort="0" velocity="2.0"/>')
    command(bus, 1.0)
    run(world, 0.5)
    assert spin(model) == pytest.approx((0.0, 0.0), abs=1e-6)
    world.close()


def test_a_position_joint_moves_whatever_its_effort_limit():
    """Position joints are set kinematically (SetPosition, hw_sim:320-326): no effort limit
    applies, effort="0" included."""
    world, bus, model = spinner("position", joint_type="revolute",
                                limit='<limit lower="-3" upper="3" effort="0" velocity="2.0"/>')
    command(bus, 0.5)
    run(world, 1.0)
    assert spin(model)[0] == pytest.approx(0.5, abs=1e-3)
    world.close()


def test_a_position_command_moves_at_most_at_the_urdf_velocity():
    """PositionJointSaturationHandle: each write the command moves at most <limit velocity>·dt
    from the previous one, and stays within [lower, upper] (JLI joint_limits_interface.h:91-112;
    hw_sim:304, :494-499). A jump to 1 rad at 0.5 rad/s takes 2 s; 5 rad stops at upper 1.2."""
    world, bus, model = spinner("position", joint_type="revolute",
                                limit='<limit lower="-1.2" upper="1.2" effort="50" velocity="0.5"/>')
    command(bus, 1.0)
    run(world, 1.0)
    position, velocity = spin(model)
    assert position == pytest.approx(0.5, abs=0.02)  # was 1.0
    assert velocity == pytest.approx(0.5, abs=0.02)
    run(world, 1.5)
    assert spin(model)[0] == pytest.approx(1.0, abs=1e-3)
    command(bus, 5.0)
    run(world, 1.0)
    assert spin(model)[0] == pytest.approx(1.2, abs=1e-3)
    world.close()


def test_an_effort_joint_is_not_pushed_past_its_velocity_limit():
    """EffortJointSaturationHandle: above <limit velocity> the effort that would speed the
    joint up further is 0 (JLI joint_limits_interface.h:299-303); the rest of the time it is
    clamped to ±<limit effort> (:287-288). 5 N m on 0.1 kg m² is 50 rad/s²: 2 rad/s, then it
    coasts (it reached 25 rad/s before)."""
    world, bus, model = spinner("effort", limit='<limit effort="5" velocity="2.0"/>')
    command(bus, 100.0)  # saturated to 5 N m
    run(world, 0.02)
    assert spin(model)[1] == pytest.approx(1.0, abs=0.06)
    run(world, 0.5)
    assert 2.0 <= spin(model)[1] <= 2.06
    world.close()


def test_joint_limits_parameters_override_the_urdf():
    """<robotNamespace>/joint_limits/<joint> (JLI joint_limits_rosparam.h:75-169, read from
    the robot's namespace, hw_sim:69, :425-426) replaces the URDF's velocity limit and adds an
    acceleration limit (VelocityJointSaturationHandle, JLI :433-440): 4 rad/s² up to 1 rad/s."""
    limits = {"/spinner/joint_limits": {"spin": {
        "has_velocity_limits": True, "max_velocity": 1.0,
        "has_acceleration_limits": True, "max_acceleration": 4.0}}}
    world, bus, model = spinner("velocity", params=limits)
    command(bus, 10.0)
    run(world, 0.1)
    assert spin(model)[1] == pytest.approx(0.4, abs=0.01)
    run(world, 0.4)
    assert spin(model)[1] == pytest.approx(1.0, abs=0.01)
    world.close()


def test_limits_without_a_velocity_limit_refuse_the_controls_naming_the_joint():
    """A velocity or effort joint with limits but no velocity limit: the saturation handle
    throws "Cannot enforce limits for joint 'spin'. It has no velocity limits specification."
    (JLI joint_limits_interface.h:411-415) and the plugin does not load; the model does."""
    limits = {"/spinner/joint_limits/spin": {"has_effort_limits": True, "max_effort": 3.0}}
    bus = RecordingBus({"/spinner/controller": {
        "type": CONTROLLERS["velocity"][0], "joint": "spin"}, **limits})
    world = World(bus, ray_threads=1)
    world.spawn_urdf("spinner", spinner_urdf("velocity", limit=""))
    assert f"{MANAGER}/load_controller" not in bus.services
    assert any("Cannot enforce limits for joint 'spin'. It has no velocity limits "
               "specification." in w for w in bus.warnings), bus.warnings
    assert "spinner" in world.models
    world.close()


def test_joint_limits_parameters_replace_the_urdf_position_limits():
    """joint_limits/<joint>/has_position_limits with min_position and max_position replace
    the URDF's (JLI joint_limits_rosparam.h:97-114): [-0.5, 0.5] stops a 1 rad position
    command at 0.5 (the URDF allows ±3; PositionJointSaturationHandle, JLI
    joint_limits_interface.h:91-112)."""
    limits = {"/spinner/joint_limits/spin": {"has_position_limits": True, "min_position": -0.5,
                                             "max_position": 0.5}}
    world, bus, model = spinner("position", params=limits, joint_type="revolute",
                                limit='<limit lower="-3" upper="3" effort="50" velocity="2.0"/>')
    command(bus, 1.0)
    run(world, 1.5)
    assert spin(model)[0] == pytest.approx(0.5, abs=1e-3)
    world.close()


def test_joint_limits_max_effort_replaces_the_urdf_effort():
    """joint_limits/<joint>/has_effort_limits, max_effort (JLI joint_limits_rosparam.h:
    155-166) is the velocity motor's fmax (hw_sim:240, :453-454): 0.2 N m on a 2 kg m^2
    flywheel is 0.1 rad/s^2, 0.1 rad/s after 1 s toward a 1 rad/s command (the URDF's 50
    N m would reach it in 0.04 s)."""
    limits = {"/spinner/joint_limits/spin": {"has_effort_limits": True, "max_effort": 0.2}}
    world, bus, model = spinner("velocity", params=limits, izz=2.0)
    command(bus, 1.0)
    run(world, 1.0)
    assert spin(model)[1] == pytest.approx(0.1, abs=0.005)
    world.close()


def test_joint_limits_jerk_limits_are_read_and_used_by_no_handle():
    """has_jerk_limits, max_jerk are read (JLI joint_limits_rosparam.h:142-153) but no
    saturation handle uses them (joint_limits_interface.h:91-112, :285-306, :425-455): a
    velocity command is reached as without them."""
    limits = {"/spinner/joint_limits/spin": {"has_velocity_limits": True, "max_velocity": 2.0,
                                             "has_jerk_limits": True, "max_jerk": 0.001}}
    world, bus, model = spinner("velocity", params=limits)
    command(bus, 1.5)
    run(world, 0.1)
    assert spin(model)[1] == pytest.approx(1.5, abs=0.01)
    world.close()


def test_joint_limits_soft_limit_parameters_are_not_read_by_gazebo_ros_control():
    """DefaultRobotHWSim takes soft limits from the URDF's <safety_controller> only
    (hw_sim:408-421); joint_limits/<joint>/has_soft_limits, k_position, soft_lower_limit,
    soft_upper_limit (JLI joint_limits_rosparam.h:194-230) are never asked for: soft limits
    of [-0.1, 0.1] there leave a 1 rad command to reach 1 rad."""
    limits = {"/spinner/joint_limits/spin": {
        "has_soft_limits": True, "k_position": 10.0, "k_velocity": 10.0,
        "soft_lower_limit": -0.1, "soft_upper_limit": 0.1}}
    world, bus, model = spinner("position", params=limits, joint_type="revolute",
                                limit='<limit lower="-3" upper="3" effort="50" velocity="2.0"/>')
    command(bus, 1.0)
    run(world, 1.5)
    assert spin(model)[0] == pytest.approx(1.0, abs=1e-3)
    world.close()


SAFETY = '<safety_controller k_position="{k_position}" k_velocity="{k_velocity}" ' \
         'soft_lower_limit="-0.5" soft_upper_limit="0.5"/>'
HARD = '<limit lower="-1.2" upper="1.2" effort="50" velocity="2.0"/>'


@pytest.mark.parametrize("interface, value", [("position", 1.0), ("velocity", 1.0),
                                              ("effort", 5.0)])
def test_a_safety_controller_holds_the_joint_at_its_soft_limit(interface, value):
    """A URDF <safety_controller> (getSoftJointLimits, JLI joint_limits_urdf.h:84-97) makes
    DefaultRobotHWSim register the soft-limits handle of the joint's interface instead of the
    saturation handle (hw_sim:420-421, :456-482): the velocity allowed is -k_position times
    the distance past a soft limit, within ±max_velocity (JLI joint_limits_interface.h
    :203-219, :493-506); the position handle moves the command at most that far each write
    (:221-237), the velocity handle clamps the command to it (:516), the effort handle clamps
    the effort to -k_velocity times the velocity's excess (:379-391). A command past the soft
    upper limit 0.5 ends at 0.5 (before: at the command, or at the hard limit 1.2)."""
    world, bus, model = spinner(interface, joint_type="revolute",
                                limit=HARD + SAFETY.format(k_position=5.0, k_velocity=2.0))
    command(bus, value)
    run(world, 3.0)
    position, velocity = spin(model)
    assert position == pytest.approx(0.5, abs=0.01)
    assert velocity == pytest.approx(0.0, abs=0.02)
    world.close()


def test_inside_its_soft_limits_a_position_joint_moves_as_the_velocity_limit_allows():
    """Far from the soft limits the bound is ±max_velocity (the distance times k_position is
    larger): a step from 0 to -0.2 rad (0.3 rad inside the soft lower limit, 1.5 rad/s
    allowed there) takes 0.1 s at 2 rad/s, as the plain saturation would (passes with either
    handle: a check that the soft handle does not slow the joint where it should not)."""
    world, bus, model = spinner("position", joint_type="revolute",
                                limit=HARD + SAFETY.format(k_position=5.0, k_velocity=2.0))
    command(bus, -0.2)
    run(world, 0.05)
    assert -0.105 <= spin(model)[0] <= -0.07  # the command at -0.1, the joint a few ms behind
    run(world, 0.15)
    assert spin(model)[0] == pytest.approx(-0.2, abs=2e-3)
    world.close()


def test_a_safety_controller_without_k_velocity_is_a_urdf_error_naming_it():
    """urdfdom requires k_velocity (parseJointSafety); urdf_parser_py does too."""
    from urdf_tools.model import UrdfError, parse_urdf
    with pytest.raises(UrdfError, match="k_velocity"):
        parse_urdf(spinner_urdf("position", joint_type="revolute",
                                limit=HARD + '<safety_controller k_position="5"/>'))

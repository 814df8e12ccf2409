"""Which ``<transmission>`` elements gazebo_ros_control takes, on pybullet.DIRECT: ros_control's
TransmissionParser skips one without a ``<type>``, without a joint that names a
``<hardwareInterface>`` or without an ``<actuator>``, and DefaultRobotHWSim one with more than
one joint, each named; the rest of the robot is controlled. Checked on the joints' true state.

Upstream: ros_control noetic-devel 633c374 transmission_interface/src/transmission_parser.cpp
("parser"); gazebo_ros_pkgs noetic-devel f9e1a46 gazebo_ros_control/src/
default_robot_hw_sim.cpp ("hw_sim")."""
import pytest
from controller_manager_msgs.srv import LoadControllerRequest, SwitchControllerRequest
from std_msgs.msg import Float64

from recording_bus import RecordingBus
from sim_bridge.world import World
from world_fixtures import run

MANAGER = "/twin/controller_manager"
GOOD = """<transmission name="left_transmission">
    <type>transmission_interface/SimpleTransmission</type>
    <joint name="left"><hardwareInterface>hardware_interface/PositionJointInterface</hardwareInterface></joint>
    <actuator name="left_motor"><mechanicalReduction>1</mechanicalReduction></actuator>
  </transmission>"""


def twin_urdf(right_transmission, good=GOOD):
    """Two rotors on vertical axes, "left" and "right", each with its own transmission."""
    rotors = "".join(f"""
  <link name="{side}_rotor">
    <inertial><mass value="1"/><inertia ixx="0.06" ixy="0" ixz="0" iyy="0.06" iyz="0" izz="0.1"/></inertial>
  </link>
  <joint name="{side}" type="revolute">
    <parent link="base_link"/><child link="{side}_rotor"/><origin xyz="{y} 0 0.2"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="50" velocity="2"/>
  </joint>""" for side, y in (("left", 0.5), ("right", -0.5)))
    return f"""<?xml version="1.0"?>
<robot name="twin">
  <link name="world"/>
  <joint name="fixed" type="fixed"><parent link="world"/><child link="base_link"/></joint>
  <link name="base_link">
    <inertial><mass value="2"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
  </link>{rotors}
  {good}
  {right_transmission}
  <gazebo>
    <plugin name="gazebo_ros_control" filename="libgazebo_ros_control.so">
      <robotNamespace>/twin</robotNamespace>
    </plugin>
  </gazebo>
</robot>"""


def twin(right_transmission, good=GOOD):
    bus = RecordingBus({f"/twin/{side}_controller": {
        "type": "position_controllers/JointPositionController", "joint": side}
        for side in ("left", "right")})
    world = World(bus, ray_threads=1)
    model = world.spawn_urdf("twin", twin_urdf(right_transmission, good))
    return world, bus, model


def load(bus, name):
    return bus.services[f"{MANAGER}/load_controller"](LoadControllerRequest(name)).ok


def left_is_controlled(world, bus, model):
    """The well-formed transmission's joint is controlled: commanded to 0.5 rad, it is."""
    assert load(bus, "left_controller"), bus.warnings
    assert bus.services[f"{MANAGER}/switch_controller"](SwitchControllerRequest(
        start_controllers=["left_controller"], strictness=2)).ok
    bus.subscriptions["/twin/left_controller/command"](Float64(0.5))
    run(world, 1.0)
    assert model.robot.joint_position_velocity("left")[0] == pytest.approx(0.5, abs=1e-3)


LEFT_JOINT = ('<joint name="left"><hardwareInterface>hardware_interface/'
              'PositionJointInterface</hardwareInterface></joint>')
RIGHT_JOINT = ('<joint name="right"><hardwareInterface>hardware_interface/'
               'PositionJointInterface</hardwareInterface></joint>')
RIGHT_ACTUATOR = '<actuator name="right_motor"><mechanicalReduction>1</mechanicalReduction></actuator>'
SIMPLE = "<type>transmission_interface/SimpleTransmission</type>"


@pytest.mark.parametrize("body, messages", [
    (RIGHT_JOINT + RIGHT_ACTUATOR,  # parser:79-85
     ["No type element found in transmission 'right_transmission'."]),
    ("<type></type>" + RIGHT_JOINT + RIGHT_ACTUATOR,  # parser:86-91
     ["Skipping empty type element in transmission 'right_transmission'."]),
    (SIMPLE + RIGHT_JOINT,  # parser:102-108, :252-256
     ["Failed to load actuators for transmission 'right_transmission'."]),
    (SIMPLE + '<joint name="right"/>' + RIGHT_ACTUATOR,  # parser:170-175, :95-100
     ["No valid hardware interface element found in joint 'right'.",
      "Failed to load joints for transmission 'right_transmission'."]),
    # the hardware interface on the actuator only (the pre-Indigo form): the parser drops the
    # joint before DefaultRobotHWSim could fall back to the actuator's (hw_sim:105-116)
    (SIMPLE + '<joint name="right"/><actuator name="right_motor"><hardwareInterface>'
     'hardware_interface/PositionJointInterface</hardwareInterface></actuator>',
     ["Failed to load joints for transmission 'right_transmission'."]),
])
def test_a_transmission_the_parser_refuses_is_skipped_and_named(body, messages):
    """The transmission is skipped with its reason; the other joint is controlled, the
    skipped one has no handle (a controller naming it does not load). Before: the
    transmission was taken (or, without a hardwareInterface, the whole plugin refused)."""
    world, bus, model = twin(f'<transmission name="right_transmission">{body}</transmission>')
    for message in messages:
        assert message in bus.warnings, (message, bus.warnings)
    left_is_controlled(world, bus, model)
    assert not load(bus, "right_controller")
    assert any("'right'" in w and "no transmission" in w for w in bus.warnings), bus.warnings
    world.close()


def test_a_transmission_with_two_joints_is_skipped():
    """DefaultRobotHWSim takes one joint a transmission (hw_sim:97-103): a transmission of
    both joints is skipped, named, and neither joint is controlled through it. Before: both
    joints were taken."""
    both = f'<transmission name="both">{SIMPLE}{RIGHT_JOINT}{LEFT_JOINT}{RIGHT_ACTUATOR}</transmission>'
    world, bus, model = twin(both)
    assert ("Transmission both has more than one joint. Currently the default robot hardware "
            "simulation interface only supports one.") in bus.warnings, bus.warnings
    left_is_controlled(world, bus, model)  # through its own transmission
    assert not load(bus, "right_controller")
    world.close()


def test_a_bare_interface_name_is_deprecated_but_taken():
    """"PositionJointInterface" without its namespace works, with "Deprecated syntax, please
    prepend 'hardware_interface/' ..." (hw_sim:153-186)."""
    world, bus, model = twin("", good=GOOD.replace("hardware_interface/PositionJointInterface",
                                                   "PositionJointInterface"))
    assert ("Deprecated syntax, please prepend 'hardware_interface/' to 'PositionJointInterface' "
            "within the <hardwareInterface> tag in joint 'left'.") in bus.warnings, bus.warnings
    left_is_controlled(world, bus, model)
    world.close()


def test_with_every_transmission_skipped_the_manager_serves_no_joint():
    """Nothing left after the parser: Noetic's initSim takes no joint and the controller
    manager runs (hw_sim:72, :88-246); a controller of a skipped joint does not load."""
    world, bus, model = twin("", good=GOOD.replace(SIMPLE, ""))
    assert "No type element found in transmission 'left_transmission'." in bus.warnings
    assert not load(bus, "left_controller")
    run(world, 0.1)
    world.close()


def test_an_interface_in_another_namespace_refuses_the_controls():
    """Only "hardware_interface/<Name>" and "<Name>" are known (hw_sim:153-182): another
    name is "No matching hardware interface found for ..." and initSim fails, so there is no
    controller manager; the model loads. Before: the last path segment was taken."""
    world, bus, model = twin("", good=GOOD.replace("hardware_interface/PositionJointInterface",
                                                   "my_interfaces/PositionJointInterface"))
    assert f"{MANAGER}/load_controller" not in bus.services
    assert any("No matching hardware interface found for 'my_interfaces/PositionJointInterface'"
               in w for w in bus.warnings), bus.warnings
    assert "twin" in world.models
    world.close()

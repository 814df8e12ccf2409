"""The robot the ros_control unit tests drive: one controlled joint on a base fixed to the
world, its transmission and gazebo_ros_control, in the shapes the tests need (a rotor on a
vertical axis, which gravity does not turn; a pendulum, which it does)."""

INTERFACES = {"position": "PositionJointInterface", "velocity": "VelocityJointInterface",
              "effort": "EffortJointInterface"}


def one_joint_urdf(interface, robot="spinner", joint="spin", child="rotor",
                   joint_type="continuous", limit='<limit effort="50" velocity="2.0"/>',
                   axis="0 0 1", origin="0 0 0.2", mass=1.0, inertia=(0.06, 0.06, 0.1),
                   centre_of_mass="0 0 0", dynamics=""):
    """The URDF: ``joint`` (``joint_type``, ``limit`` and ``dynamics`` as written) turns
    ``child`` (``mass`` at ``centre_of_mass``, diagonal ``inertia``) about ``axis`` at
    ``origin`` above the base, through ``interface`` (position, velocity or effort), with
    the controls in ``/<robot>``."""
    ixx, iyy, izz = inertia
    return f"""<?xml version="1.0"?>
<robot name="{robot}">
  <link name="world"/>
  <joint name="fixed" type="fixed"><parent link="world"/><child link="base_link"/></joint>
  <link name="base_link">
    <collision><geometry><box size="0.2 0.2 0.1"/></geometry></collision>
    <inertial><mass value="2"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
  </link>
  <link name="{child}">
    <inertial><origin xyz="{centre_of_mass}"/><mass value="{mass}"/>
      <inertia ixx="{ixx}" ixy="0" ixz="0" iyy="{iyy}" iyz="0" izz="{izz}"/></inertial>
  </link>
  <joint name="{joint}" type="{joint_type}">
    <parent link="base_link"/><child link="{child}"/><origin xyz="{origin}"/><axis xyz="{axis}"/>
    {limit}{dynamics}
  </joint>
  <transmission name="{joint}_transmission">
    <type>transmission_interface/SimpleTransmission</type>
    <joint name="{joint}"><hardwareInterface>hardware_interface/{INTERFACES[interface]}</hardwareInterface></joint>
    <actuator name="{joint}_motor"><mechanicalReduction>1</mechanicalReduction></actuator>
  </transmission>
  <gazebo>
    <plugin name="gazebo_ros_control" filename="libgazebo_ros_control.so">
      <robotNamespace>/{robot}</robotNamespace>
    </plugin>
  </gazebo>
</robot>"""


def start_controllers(bus, robot, *names):
    """Loads the controllers ``names`` of ``/<robot>`` and starts them together, as
    controller_manager's spawner does; fails naming the simulator's warnings."""
    from controller_manager_msgs.srv import LoadControllerRequest, SwitchControllerRequest
    manager = f"/{robot}/controller_manager"
    for name in names:
        assert bus.services[f"{manager}/load_controller"](LoadControllerRequest(name)).ok, \
            bus.warnings
    assert bus.services[f"{manager}/switch_controller"](SwitchControllerRequest(
        start_controllers=list(names), strictness=2)).ok, bus.warnings

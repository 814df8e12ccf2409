"""A world's long step is stepped by pybullet in parts (sim_bridge.world.MAX_PHYSICS_STEP):
at 10 ms pybullet's joint motors let go under load where ODE's hold.

The robot is AgileX LIMO's layout (ugv_gazebo_sim's limo_description: its masses and
inertias, front wheels on steering hinges), on the ground in a world of 10 ms steps, as its
empty.world sets. Its front wheels' motors (SetParam("vel") of its drive plugin) hold them at
speed against an opposing effort each step (gazebo_ros_control's velocity PID, p = 1, on the
same joints), which their reaction on the hinges cancels: the body must not pitch."""
import math

import pybullet as pb
import pytest

from sim_bridge import world as world_module
from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec
from sim_bridge.world import World
from recording_bus import RecordingBus

STEP = 0.01  # s: limo_gazebo_sim/worlds/empty.world's <max_step_size>
WHEEL_SPEED = 6.7  # rad/s: 0.3 m/s on its 45 mm wheels
SECONDS = 3.0
PITCH_TOLERANCE = math.radians(1.0)


def _wheel(name, parent, xyz, mass, ixx, iyy):
    return f"""<link name="{name}"><inertial><mass value="{mass}"/><inertia ixx="{ixx}" ixy="0"
      ixz="0" iyy="{iyy}" iyz="0" izz="{ixx}"/></inertial>
      <collision><origin rpy="{math.pi / 2} 0 0" xyz="0 0.0225 0"/><geometry><cylinder
      radius="0.045" length="0.045"/></geometry></collision></link>
    <joint name="{name}_joint" type="continuous"><parent link="{parent}"/><child link="{name}"/>
      <origin xyz="{xyz}"/><axis xyz="0 1 0"/></joint>"""


def _hinge(name, xyz):
    return f"""<link name="{name}"><inertial><mass value="0.25"/><inertia ixx="0.00525" ixy="0"
      ixz="0" iyy="0.00035" iyz="0" izz="0.00525"/></inertial></link>
    <joint name="{name}_joint" type="revolute"><parent link="base_link"/><child link="{name}"/>
      <origin xyz="{xyz}"/><axis xyz="0 0 1"/><limit lower="-0.52" upper="0.52" effort="5"
      velocity="0.5"/><dynamics damping="1.0" friction="2.0"/></joint>"""


LIMO_LIKE = f"""<robot name="limo_like">
  <link name="base_link"><inertial><mass value="2.1557"/><inertia ixx="0.24" ixy="0" ixz="0"
    iyy="0.96" iyz="0" izz="0.96"/></inertial>
    <collision><geometry><box size="0.13 0.12 0.1"/></geometry></collision></link>
  {_hinge("left_hinge", "0.1 0.07 -0.101")}{_hinge("right_hinge", "0.1 -0.07 -0.101")}
  {_wheel("front_left", "left_hinge", "0 0 0", 0.25, 0.00525, 0.00035)}
  {_wheel("front_right", "right_hinge", "0 0 0", 0.25, 0.00525, 0.00035)}
  {_wheel("rear_left", "base_link", "-0.1 0.07 -0.101", 0.5, 0.01055, 0.00075)}
  {_wheel("rear_right", "base_link", "-0.1 -0.07 -0.101", 0.5, 0.01055, 0.00075)}
</robot>"""


def _greatest_pitch():
    world = World(RecordingBus(), step_size=STEP)
    try:
        world.add_sdf_model(ModelSpec("ground", True, links=[
            LinkSpec("link", collisions=[ShapeSpec("plane")])]))
        world.spawn_urdf("limo_like", LIMO_LIKE, (0, 0, 0.146))
        robot = world.model("limo_like").robot
        wheels = [f"{side}_joint" for side in ("front_left", "front_right", "rear_left",
                                                "rear_right")]
        for joint in wheels:  # what the drive plugin's SetParam("fmax"/"vel") sets
            pb.setJointMotorControl2(robot.id, robot.joint_index[joint], pb.VELOCITY_CONTROL,
                                     targetVelocity=WHEEL_SPEED, force=50.0,
                                     physicsClientId=world.client)
        greatest = 0.0
        for _ in range(round(SECONDS / STEP)):
            for joint in wheels[:2]:  # the velocity PID's effort toward 0 (p = 1)
                speed = pb.getJointState(robot.id, robot.joint_index[joint],
                                         physicsClientId=world.client)[1]
                world.set_step_joint_force("limo_like", joint, -speed)
            world.step()
            roll, pitch, _ = pb.getEulerFromQuaternion(world.pose("limo_like")[1])
            greatest = max(greatest, abs(pitch), abs(roll))
        return greatest
    finally:
        world.close()


def test_motors_hold_their_wheels_against_an_effort_at_10_ms():
    assert _greatest_pitch() < PITCH_TOLERANCE


def test_stepped_whole_pybullet_lets_go_and_the_robot_pitches(monkeypatch):
    """The reason for the parts: the same, with pybullet stepping 10 ms at once."""
    monkeypatch.setattr(world_module, "MAX_PHYSICS_STEP", 1.0)
    assert _greatest_pitch() > math.radians(10.0)

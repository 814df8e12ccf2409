"""Articulated SDF models, as Gazebo's model library and students' worlds hold them, built as
robots: a two-wheeled SDF robot with its diff drive plugin drives in ground truth; a
pendulum fixed to the world swings about the axis its joint gives, in the joint's frame or
the model's; joint limits and positions as written."""
import math

import pybullet as pb
import pytest
from geometry_msgs.msg import Twist

from sim_bridge.sdf_world import parse_model
from world_fixtures import run

ROVER = """<sdf version="1.6"><model name="rover"><pose>1 2 0.06 0 0 0</pose>
  <link name="chassis"><pose>0 0 0.05 0 0 0</pose>
    <inertial><mass>5</mass><inertia><ixx>0.02</ixx><iyy>0.05</iyy><izz>0.06</izz></inertia>
    </inertial>
    <collision name="c"><geometry><box><size>0.4 0.3 0.08</size></box></geometry></collision>
    <visual name="v"><geometry><box><size>0.4 0.3 0.08</size></box></geometry>
      <material><ambient>0 0 1 1</ambient><diffuse>0 0 1 1</diffuse></material></visual>
    <collision name="caster"><pose>-0.15 0 -0.05 0 0 0</pose><geometry><sphere>
      <radius>0.05</radius></sphere></geometry><surface><friction><ode><mu>0</mu><mu2>0</mu2>
      </ode></friction></surface></collision></link>
  <link name="left_wheel"><pose>0.1 0.18 0.0 -1.5707963 0 0</pose>
    <inertial><mass>0.5</mass><inertia><ixx>0.001</ixx><iyy>0.001</iyy><izz>0.002</izz>
    </inertia></inertial>
    <collision name="c"><geometry><cylinder><radius>0.06</radius><length>0.04</length>
    </cylinder></geometry></collision></link>
  <link name="right_wheel"><pose>0.1 -0.18 0.0 -1.5707963 0 0</pose>
    <inertial><mass>0.5</mass><inertia><ixx>0.001</ixx><iyy>0.001</iyy><izz>0.002</izz>
    </inertia></inertial>
    <collision name="c"><geometry><cylinder><radius>0.06</radius><length>0.04</length>
    </cylinder></geometry></collision></link>
  <joint name="left_wheel_hinge" type="revolute"><parent>chassis</parent>
    <child>left_wheel</child><axis><xyz>0 0 1</xyz></axis></joint>
  <joint name="right_wheel_hinge" type="revolute"><parent>chassis</parent>
    <child>right_wheel</child><axis><xyz>0 0 1</xyz></axis></joint>
  <plugin name="drive" filename="libgazebo_ros_diff_drive.so">
    <legacyMode>false</legacyMode>
    <leftJoint>left_wheel_hinge</leftJoint><rightJoint>right_wheel_hinge</rightJoint>
    <wheelSeparation>0.36</wheelSeparation><wheelDiameter>0.12</wheelDiameter>
    <wheelTorque>5</wheelTorque><commandTopic>cmd_vel</commandTopic>
    <odometryTopic>odom</odometryTopic><robotBaseFrame>chassis</robotBaseFrame>
  </plugin></model></sdf>"""

PENDULUM = """<sdf version="1.6"><model name="pendulum">
  <link name="post"><pose>0 0 1 0 0 0</pose><inertial><mass>1</mass></inertial></link>
  <joint name="fix" type="fixed"><parent>world</parent><child>post</child></joint>
  <link name="bob"><pose>0.5 0 1 0 0 BOB_YAW</pose>
    <inertial><mass>1</mass><inertia><ixx>0.001</ixx><iyy>0.001</iyy><izz>0.001</izz>
    </inertia></inertial>
    <collision name="c"><geometry><sphere><radius>0.05</radius></sphere></geometry></collision>
  </link>
  <joint name="swing" type="revolute"><parent>post</parent><child>bob</child>
    <pose>PIVOT 0 0 0</pose>
    <axis>AXIS<limit><lower>-2.5</lower><upper>2.5</upper><effort>10</effort>
      <velocity>10</velocity></limit></axis></joint>
</model></sdf>"""


def test_an_sdf_rover_drives_with_its_own_plugin(world, bus):
    world.add_sdf_model(parse_model(ROVER, "rover.sdf"))
    model = world.model("rover")
    assert model.robot is not None  # built as a robot, jointed
    run(world, 0.5)
    (x0, y0, _), _ = world.pose("rover")
    twist = Twist()
    twist.linear.x = 0.3
    # a world's model has no spawn request: the diff drive takes the model's name (Gazebo's)
    bus.subscriptions["/rover/cmd_vel"](twist)
    run(world, 2.0)
    (x1, y1, _), _ = world.pose("rover")
    assert x1 - x0 == pytest.approx(0.6, abs=0.08)
    assert abs(y1 - y0) < 0.03
    assert bus.last("/rover/odom").pose.pose.position.x == pytest.approx(x1, abs=0.01)


def pendulum(axis, turned=False):
    """The pendulum, its bob's frame turned 90 degrees about z (so the joint's frame is too)
    when ``turned``: the pivot is then 0.5 m along the bob's +y."""
    return (PENDULUM.replace("AXIS", axis)
            .replace("BOB_YAW", f"{math.pi / 2:.9f}" if turned else "0")
            .replace("PIVOT", "0 0.5 0" if turned else "-0.5 0 0"))


# each swings about the model's y axis: written in the joint's frame (its x, once turned),
# or in the model's
@pytest.mark.parametrize("xml", [
    pendulum("<xyz>0 1 0</xyz>"),
    pendulum("<xyz>1 0 0</xyz>", turned=True),
    pendulum("<xyz>0 1 0</xyz><use_parent_model_frame>true</use_parent_model_frame>",
             turned=True),
    pendulum("<xyz expressed_in='__model__'>0 1 0</xyz>", turned=True),
], ids=["joint frame", "turned joint frame", "use_parent_model_frame", "expressed_in"])
def test_a_pendulum_fixed_to_the_world_swings_about_its_axis(world, xml):
    world.add_sdf_model(parse_model(xml, "pendulum.sdf"))
    model = world.model("pendulum")
    lowest = math.inf
    for _ in range(60):
        run(world, 0.01)
        # the bob's centre (its URDF frame is the joint's, at the pivot)
        position = pb.getLinkState(model.robot.id, model.robot.link_index["bob"],
                                   physicsClientId=world.client)[0]
        assert abs(position[1]) < 1e-3  # swings in the x-z plane: about y
        # the bob stays 0.5 m from the pivot at (0, 0, 1)
        assert math.dist(position, (0, 0, 1)) == pytest.approx(0.5, abs=2e-3)
        lowest = min(lowest, position[2])
    assert lowest < 0.6  # it fell from level towards hanging
    post, _ = model.robot.link_pose("post")  # stays where the world fixes it
    assert post == pytest.approx((0.0, 0.0, 1.0), abs=1e-6)


def test_joint_limits_come_through(world):
    world.add_sdf_model(parse_model(pendulum("<xyz>0 1 0</xyz>"), "pendulum.sdf"))
    limit = world.model("pendulum").robot.model.joints["swing"].limit
    assert (limit.lower, limit.upper, limit.effort) == (-2.5, 2.5, 10.0)

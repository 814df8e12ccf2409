"""The joint rows of sim_bridge/README.md's plugin tables and doc/ros_control.md that had no
test of their own: joint_state_publisher's slots after a reset, a URDF <mimic> without the
mimic plugin, and the effort ros_control's readSim reports for a position joint. Each checks
the row's statement against pybullet's own joint state (issue 30: a test per row that can
fail)."""
import math
import re

import pybullet as pb
import pytest

from test_mimic_joint import gripper, position
from test_model_plugin_parameters import plugins, post, stamps_ms
from test_ros_control import arm, start
from world_fixtures import run

GRAVITY = 9.8  # m/s², the world's default
# arm_bot (test/data/arm_bot.urdf.xacro): what hangs on the lift joint, the upper arm and the
# finger, each (mass kg, its centre of mass's distance from the lift axis m)
LIFT_LOAD = ((0.3, 0.15), (0.05, 0.3 + 0.025))
LIFT_ANGLE = math.pi / 4  # rad from upright: the lever m g l sin(angle)


def test_joint_state_publisher_slots_start_again_at_a_reset(world, bus):
    """(reset): Noetic's world time goes back to 0 and the plugin's last_update_time_, now
    ahead of it, is set back to it (gazebo_plugins/src/gazebo_ros_joint_state_publisher.cpp:
    126-130); here time goes on and the slots restart from the reset: 100 Hz, a reset at
    45 ms, the next messages at 56 and 66 ms (the old slots would give 51, 61, 71), each with
    the joint where pybullet has it."""
    world.spawn_urdf("post", post(plugins()), namespace="/")
    run(world, 0.045)
    assert stamps_ms(bus, "/joint_states") == [11, 21, 31, 41]
    world.reset()
    run(world, 0.03)
    assert stamps_ms(bus, "/joint_states") == [11, 21, 31, 41, 56, 66]
    model = world.model("post")
    truth, _ = model.robot.joint_position_velocity("shoulder")
    assert bus.last("/joint_states").position[0] == pytest.approx(truth, abs=1e-6)


def test_a_urdf_mimic_without_the_plugin_is_ignored(world):
    """URDF <mimic> is not SDF: sdformat drops it and Gazebo moves the joint freely unless
    the mimic plugin drives it. The right finger written to mimic the left (x -1, +5 mm)
    stays where it is while the left moves to 30 mm, and an effort on it moves it alone
    (it would be at -25 mm were <mimic> obeyed)."""
    xml = re.sub(r"<gazebo>.*</gazebo>", "", gripper("unused"), flags=re.S)
    xml = xml.replace('<joint name="right_joint" type="prismatic">',
                      '<joint name="right_joint" type="prismatic">'
                      '<mimic joint="left_joint" multiplier="-1.0" offset="0.005"/>')
    assert "<mimic" in xml and "<plugin" not in xml
    model = world.spawn_urdf("gripper", xml, (0, 0, 0.03))
    left = model.robot.joint_index["left_joint"]
    pb.setJointMotorControl2(model.robot.id, left, pb.POSITION_CONTROL, targetPosition=0.03,
                             force=20, physicsClientId=world.client)
    run(world, 1.0)
    assert position(model, "left_joint") == pytest.approx(0.03, abs=1e-3)
    assert position(model, "right_joint") == pytest.approx(0.0, abs=1e-4)
    world.apply_joint_effort("right_joint", -0.5, duration_ns=int(0.05e9))
    run(world, 0.1)
    assert position(model, "right_joint") < -0.01  # pushed, free
    assert position(model, "left_joint") == pytest.approx(0.03, abs=1e-3)


def test_read_sim_effort_of_a_position_joint_is_the_motors_torque_holding_its_load():
    """readSim's effort is Joint::GetForce(0) (gazebo_ros_pkgs noetic-devel f9e1a46
    gazebo_ros_control/src/default_robot_hw_sim.cpp:281); here, for a position joint,
    pybullet's applied motor torque: the lift joint holding the arm 45 degrees from upright
    reports what pybullet applies, m g l sin(45 deg) = 0.42 N m of the arm and finger."""
    world, bus, model = arm(joints={"lift": LIFT_ANGLE})
    start(bus, "joint_state_controller")
    run(world, 0.5)
    message = bus.last("/arm_bot/joint_states")
    lift = model.robot.joint_index["lift"]
    applied = pb.getJointState(model.robot.id, lift, physicsClientId=world.client)[3]
    effort = message.effort[message.name.index("lift")]
    assert effort == pytest.approx(applied, rel=1e-3)
    lever = GRAVITY * sum(mass * arm_length for mass, arm_length in LIFT_LOAD)
    assert abs(effort) == pytest.approx(lever * math.sin(LIFT_ANGLE), rel=0.02)
    assert message.position[message.name.index("lift")] == pytest.approx(LIFT_ANGLE,
                                                                          abs=1e-3)
    world.close()

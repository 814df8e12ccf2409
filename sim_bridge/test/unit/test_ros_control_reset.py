"""gazebo_ros_control's Reset on pybullet.DIRECT: reset_world and reset_simulation start the
plugin's timers over and nothing else; the controllers go on with their last commands.

Upstream: gazebo_ros_pkgs noetic-devel f9e1a46 gazebo_ros_control/src/
gazebo_ros_control_plugin.cpp ("plugin")."""
import pytest
from controller_manager_msgs.srv import ListControllersRequest, SwitchControllerRequest
from std_msgs.msg import Float64, Float64MultiArray

from test_ros_control import MANAGER, GoalHandle, angles, arm, goal_to, start
from world_fixtures import run


def test_after_a_reset_a_position_controller_drives_the_joints_back_to_its_command():
    """Reset() only zeroes the plugin's last update and write times (plugin:261-266): the
    group position controller keeps its command, and the arm, put back at its spawn pose by
    the reset, returns to [0.6, -0.3]. Before, the controllers were started again from the
    reset pose and the arm stayed at [0, 0]."""
    world, bus, model = arm()
    start(bus, "arm_group_controller")
    bus.subscriptions["/arm_bot/arm_group_controller/command"](
        Float64MultiArray(data=[0.6, -0.3]))
    run(world, 1.5)
    assert angles(model, "pan", "lift") == pytest.approx([0.6, -0.3], abs=0.01)
    world.reset()
    assert angles(model, "pan", "lift") == pytest.approx([0.0, 0.0], abs=1e-6)  # the reset
    run(world, 1.5)
    assert angles(model, "pan", "lift") == pytest.approx([0.6, -0.3], abs=0.01)
    state = bus.services[f"{MANAGER}/list_controllers"](ListControllersRequest()).controller
    assert [(c.name, c.state) for c in state] == [("arm_group_controller", "running")]
    world.close()


def test_after_a_reset_a_trajectory_controller_holds_its_last_goal():
    """The trajectory controller is not restarted either: after its goal (pan 1.0, lift 0.5)
    it holds that, and a reset is followed by the arm going back there. Before: it held the
    reset pose."""
    world, bus, model = arm()
    start(bus, "arm_controller")
    on_goal, _ = bus.actions["/arm_bot/arm_controller/follow_joint_trajectory"]
    handle = GoalHandle(goal_to([1.0, 0.5], 1.0))
    on_goal(handle)
    run(world, 1.5)
    assert handle.status == "succeeded"
    world.reset()
    run(world, 1.5)
    assert angles(model, "pan", "lift") == pytest.approx([1.0, 0.5], abs=0.01)
    world.close()


def test_after_a_reset_a_joint_no_controller_commands_holds_its_reset_pose():
    """A position joint that no running controller commands holds where the reset put it
    (sim_bridge's rest command, see test_position_joints_hold_before_any_controller): the
    finger, spawned at 0.01 and moved by its controller, which was then stopped, stays at
    0.01 after the reset."""
    world, bus, model = arm(joints={"finger_joint": 0.01})
    start(bus, "finger_controller")
    bus.subscriptions["/arm_bot/finger_controller/command"](Float64(0.02))
    run(world, 1.0)
    assert bus.services[f"{MANAGER}/switch_controller"](SwitchControllerRequest(
        stop_controllers=["finger_controller"], strictness=2)).ok
    world.reset()
    run(world, 1.0)
    assert angles(model, "finger_joint")[0] == pytest.approx(0.01, abs=1e-3)
    world.close()


def test_after_a_reset_a_trajectory_is_sampled_the_whole_time_further_on():
    """The controllers' period after a reset is the time since time 0 (plugin:220, :264),
    and the trajectory controller's uptime advances by it (joint_trajectory_controller_impl.h:
    357-361): 1 s into a 4 s move of pan to 1.0 (0.25 there), a reset sends the trajectory
    about 1 s on, to 0.5, which pan reaches at once. Before: the trajectory went on from
    0.25."""
    world, bus, model = arm()
    start(bus, "arm_controller")
    on_goal, _ = bus.actions["/arm_bot/arm_controller/follow_joint_trajectory"]
    on_goal(GoalHandle(goal_to([1.0, 0.0], 4.0)))
    run(world, 1.0)
    assert angles(model, "pan")[0] == pytest.approx(0.25, abs=0.01)
    world.reset()
    run(world, 0.04)
    assert angles(model, "pan")[0] == pytest.approx(0.51, abs=0.02)
    world.close()

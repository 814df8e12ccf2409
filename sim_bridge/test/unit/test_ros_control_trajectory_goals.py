"""JointTrajectoryController's goal handling on pybullet.DIRECT, rows of ros_control.md that
had no test: an empty trajectory, joints named in another order, a point whose sizes
disagree, a cancel, the action feedback's rate. Checked on the joints' true positions.

Upstream: ros_controllers noetic-devel 678b92a joint_trajectory_controller/include/
joint_trajectory_controller/: joint_trajectory_controller_impl.h ("impl"),
init_joint_trajectory.h ("init")."""
import pytest
import yaml
from control_msgs.msg import FollowJointTrajectoryGoal, FollowJointTrajectoryResult
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint

import genpy
from test_ros_control import GoalHandle, angles, arm, goal_to, start
from world_fixtures import DATA, run

ACTION = "/arm_bot/arm_controller/follow_joint_trajectory"


def running_arm():
    world, bus, model = arm()
    start(bus, "arm_controller")
    on_goal, on_cancel = bus.actions[ACTION]
    return world, bus, model, on_goal, on_cancel


def test_an_empty_trajectory_holds_the_current_position_and_is_accepted():
    """No points: setHoldPosition, the goal accepted (impl:514-520): a goal to pan 1.0 in
    2 s, replaced after 1 s by an empty one, leaves the arm where it was then."""
    world, bus, model, on_goal, _ = running_arm()
    first = GoalHandle(goal_to([1.0, 0.0], 2.0))
    on_goal(first)
    run(world, 1.0)
    where = angles(model, "pan")[0]
    assert 0.3 < where < 0.7
    empty = GoalHandle(FollowJointTrajectoryGoal(trajectory=JointTrajectory(
        joint_names=["pan", "lift"])))
    on_goal(empty)
    assert empty.status != "rejected"
    assert first.status == "canceled"
    run(world, 1.5)
    assert angles(model, "pan")[0] == pytest.approx(where, abs=0.01)
    world.close()


def test_joints_in_another_order_are_mapped_by_name():
    """The message's joint order is mapped onto the controller's (init:64-85, :300-310):
    [lift, pan] = [0.3, -0.6] puts pan at -0.6 and lift at 0.3."""
    world, bus, model, on_goal, _ = running_arm()
    handle = GoalHandle(goal_to([0.3, -0.6], 1.0, joints=("lift", "pan")))
    on_goal(handle)
    run(world, 1.5)
    assert handle.status == "succeeded"
    assert angles(model, "pan", "lift") == pytest.approx([-0.6, 0.3], abs=0.01)
    world.close()


def test_a_point_whose_sizes_disagree_is_an_invalid_goal_with_noetics_words():
    """"Size mismatch in trajectory point position, velocity or acceleration data." →
    INVALID_GOAL with that string (init:395-397, :477-488; impl:548-552, :630-634). Before:
    our own words."""
    world, bus, model, on_goal, _ = running_arm()
    point = JointTrajectoryPoint(positions=[0.5, 0.2], velocities=[0.0],
                                 time_from_start=genpy.Duration(1.0))
    handle = GoalHandle(FollowJointTrajectoryGoal(trajectory=JointTrajectory(
        joint_names=["pan", "lift"], points=[point])))
    on_goal(handle)
    assert (handle.status, handle.result.error_code) == (
        "rejected", FollowJointTrajectoryResult.INVALID_GOAL)
    assert handle.result.error_string == \
        "Size mismatch in trajectory point position, velocity or acceleration data."
    run(world, 0.5)
    assert angles(model, "pan", "lift") == pytest.approx([0.0, 0.0], abs=1e-3)
    world.close()


def test_a_cancelled_goal_holds_where_the_arm_is():
    """cancelCB (impl:638-660): the goal canceled, the arm held where it was: pan stops
    half way on a 2 s move to 1.0."""
    world, bus, model, on_goal, on_cancel = running_arm()
    handle = GoalHandle(goal_to([1.0, 0.0], 2.0))
    on_goal(handle)
    run(world, 1.0)
    on_cancel(handle)
    assert handle.status == "canceled"
    where = angles(model, "pan")[0]
    run(world, 1.5)
    assert angles(model, "pan")[0] == pytest.approx(where, abs=0.02)
    assert where < 0.8
    world.close()


def test_feedback_comes_at_the_action_monitor_rate():
    """action_monitor_rate, 20 Hz by default (impl:224-226): 1 s of a goal gives 20 feedback
    messages; 5 Hz gives 5."""
    for rate, expected in ((None, 20), (5.0, 5)):
        params = None
        if rate is not None:
            with open(f"{DATA}/arm_bot_controllers.yaml", encoding="utf-8") as stream:
                controller = yaml.safe_load(stream)["arm_controller"]
            params = {"arm_controller": {**controller, "action_monitor_rate": rate}}
        world, bus, model = arm(params=params)
        start(bus, "arm_controller")
        on_goal, _ = bus.actions[ACTION]
        handle = GoalHandle(goal_to([1.0, 0.0], 2.0))
        on_goal(handle)
        run(world, 1.0)
        assert len(handle.feedback) == pytest.approx(expected, abs=1), rate
        world.close()

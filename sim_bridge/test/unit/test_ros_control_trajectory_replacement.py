"""JointTrajectoryController: how a new trajectory takes over, the tolerances, the stop
trajectory and ``query_state``, on pybullet.DIRECT, checked on the joints' true positions.

Upstream: ros_controllers noetic-devel 678b92a joint_trajectory_controller/include/
joint_trajectory_controller/: joint_trajectory_controller_impl.h ("impl"),
init_joint_trajectory.h ("init"), tolerances.h ("tol"), stop_trajectory_builder.h ("stop")."""
import pytest
import yaml
from control_msgs.msg import FollowJointTrajectoryResult, JointTolerance
from control_msgs.srv import QueryTrajectoryStateRequest
from controller_manager_msgs.srv import LoadControllerRequest

import genpy
from test_ros_control import MANAGER, GoalHandle, angles, arm, goal_to, start
from world_fixtures import DATA, run

ACTION = "/arm_bot/arm_controller/follow_joint_trajectory"
QUERY = "/arm_bot/arm_controller/query_state"
Result = FollowJointTrajectoryResult


def arm_controller(**changes):
    """arm_bot's arm_controller parameters with ``changes``."""
    with open(f"{DATA}/arm_bot_controllers.yaml", encoding="utf-8") as stream:
        controller = yaml.safe_load(stream)["arm_controller"]
    return {"arm_controller": {**controller, **changes}}


def running_arm(**changes):
    world, bus, model = arm(params=arm_controller(**changes) if changes else None)
    start(bus, "arm_controller")
    on_goal, on_cancel = bus.actions[ACTION]
    return world, bus, model, on_goal, on_cancel


def tolerance(joint, position=0.0, velocity=0.0, acceleration=0.0):
    return JointTolerance(name=joint, position=position, velocity=velocity,
                          acceleration=acceleration)


def test_a_new_trajectory_starts_from_the_desired_state_not_the_measured_one():
    """The bridge to a new trajectory starts from the current trajectory's (desired) state
    (init:416-419, :457-458): pan held at 0.5 and knocked to 0.2, then sent to 0.5 in 2 s,
    is back at 0.5 within 0.3 s (the command never left 0.5). Before: the new trajectory
    started from the measured 0.2 and crept back (0.25 after 0.3 s)."""
    world, bus, model, on_goal, _ = running_arm()
    on_goal(GoalHandle(goal_to([0.5, 0.0], 0.5)))
    run(world, 1.0)
    assert angles(model, "pan")[0] == pytest.approx(0.5, abs=0.01)
    model.robot.reset_joints({"pan": 0.2})
    world.step()  # the controller reads the knocked position
    handle = GoalHandle(goal_to([0.5, 0.0], 2.0))
    on_goal(handle)
    run(world, 0.3)
    assert angles(model, "pan")[0] == pytest.approx(0.5, abs=0.01)
    world.close()


def test_a_future_stamp_keeps_the_current_trajectory_until_it_starts():
    """A stamp 1 s ahead: the current trajectory (here, holding) runs until then, and the
    bridge starts there (init:417, :443-454): pan is still at 0 after 0.9 s and at 0.8 at
    2.1 s. Before: the arm set off at once (0.36 at 0.9 s)."""
    world, bus, model, on_goal, _ = running_arm()
    goal = goal_to([0.8, 0.0], 1.0)
    goal.trajectory.header.stamp = genpy.Time(0, world.now_ns + 1_000_000_000)
    handle = GoalHandle(goal)
    on_goal(handle)
    run(world, 0.9)
    assert angles(model, "pan")[0] == pytest.approx(0.0, abs=1e-3)
    run(world, 1.2)
    assert angles(model, "pan")[0] == pytest.approx(0.8, abs=0.01)
    assert handle.status == "succeeded"
    world.close()


def test_a_partial_goal_leaves_the_other_joints_on_their_trajectory():
    """allow_partial_joints_goal: the joints a goal leaves out keep their current trajectory
    (init:371-387, :512-513): pan on its way to 1.0 (2 s) goes on to 1.0 while a goal for
    lift alone brings lift back to 0; that goal succeeds once both are done (impl:457-466).
    Before: pan held where it was (0.5)."""
    world, bus, model, on_goal, _ = running_arm(allow_partial_joints_goal=True)
    first = GoalHandle(goal_to([1.0, 0.4], 2.0))
    on_goal(first)
    run(world, 1.0)
    partial = GoalHandle(goal_to([0.0], 0.5, joints=("lift",)))
    on_goal(partial)
    assert first.status == "canceled"
    run(world, 0.6)
    assert angles(model, "lift")[0] == pytest.approx(0.0, abs=0.01)
    assert 0.75 < angles(model, "pan")[0] < 0.9
    run(world, 0.7)
    assert angles(model, "pan", "lift") == pytest.approx([1.0, 0.0], abs=0.01)
    assert partial.status == "succeeded"
    world.close()


def test_after_a_path_tolerance_violation_the_goal_aborts_and_the_trajectory_goes_on():
    """A path tolerance left: the goal aborts with PATH_TOLERANCE_VIOLATED, "pan path error
    <e>" (impl:395-414), and the trajectory is not replaced: pan, slewed at its URDF
    velocity (pi rad/s) behind a trajectory to 2.0 in 0.3 s, goes on to 2.0. Before: held
    where it was at the abort (about 0.2)."""
    world, bus, model, on_goal, _ = running_arm()
    goal = goal_to([2.0, 0.0], 0.3)
    goal.path_tolerance = [tolerance("pan", position=0.05)]
    handle = GoalHandle(goal)
    on_goal(handle)
    run(world, 0.2)
    assert (handle.status, handle.result.error_code) == ("aborted",
                                                         Result.PATH_TOLERANCE_VIOLATED)
    assert handle.result.error_string.startswith("pan path error 0.")
    run(world, 1.0)
    assert angles(model, "pan")[0] == pytest.approx(2.0, abs=0.01)
    world.close()


def test_a_path_velocity_tolerance_is_checked_and_an_acceleration_one_never_fails():
    """The goal's velocity tolerances count (tol:211-222, :168-177): pan asked for 4 rad/s,
    slewed at pi, is outside a path velocity tolerance of 0.5 rad/s: aborted. The
    acceleration error is always 0 (impl:784): an acceleration tolerance of 1e-9 alone lets
    the same goal succeed. Before: only position tolerances were read (the first goal
    succeeded)."""
    world, bus, model, on_goal, _ = running_arm()
    goal = goal_to([2.0, 0.0], 0.5)
    goal.path_tolerance = [tolerance("pan", velocity=0.5)]
    handle = GoalHandle(goal)
    on_goal(handle)
    run(world, 1.5)
    assert (handle.status, handle.result.error_code) == ("aborted",
                                                         Result.PATH_TOLERANCE_VIOLATED)
    goal = goal_to([0.0, 0.0], 0.5)
    goal.path_tolerance = [tolerance("pan", acceleration=1e-9)]
    handle = GoalHandle(goal)
    on_goal(handle)
    run(world, 1.5)
    assert handle.status == "succeeded"
    world.close()


def test_a_negative_goal_time_tolerance_is_zero():
    """goal_time_tolerance < 0 is 0, not the parameter's goal_time (tol:263-266): a goal to
    2.0 in 0.3 s, which pan (pi rad/s at most) reaches at about 0.64 s, is aborted at its
    end with GOAL_TOLERANCE_VIOLATED, "pan goal error <e>" (impl:432-451); the same goal
    with goal_time_tolerance 0 takes constraints/goal_time (1 s) and succeeds. Before: the
    negative one took goal_time too and succeeded."""
    world, bus, model, on_goal, _ = running_arm()
    goal = goal_to([2.0, 0.0], 0.3)
    goal.goal_time_tolerance = genpy.Duration(-1.0)
    handle = GoalHandle(goal)
    on_goal(handle)
    run(world, 1.5)
    assert (handle.status, handle.result.error_code) == ("aborted",
                                                         Result.GOAL_TOLERANCE_VIOLATED)
    assert handle.result.error_string.startswith("pan goal error ")
    handle = GoalHandle(goal_to([0.0, 0.0], 0.3))
    on_goal(handle)
    run(world, 1.5)
    assert handle.status == "succeeded"
    world.close()


def test_stop_trajectory_duration_decelerates_a_cancelled_arm():
    """stop_trajectory_duration d > 0: a cancel stops along a quintic from the desired
    state (p, v) to the middle of the one from (p, v, 0) to (p, -v, 0) over 2 d (stop:97-139),
    which is 0.625 v d further: pan at 1 rad/s with d = 0.5 s stops 0.3125 rad beyond where it
    was cancelled. Before: not read; held at once (0 beyond)."""
    world, bus, model, on_goal, on_cancel = running_arm(stop_trajectory_duration=0.5)
    handle = GoalHandle(goal_to([2.0, 0.0], 2.0))
    on_goal(handle)
    run(world, 1.0)
    where = angles(model, "pan")[0]
    on_cancel(handle)
    assert handle.status == "canceled"
    run(world, 1.0)
    assert angles(model, "pan")[0] - where == pytest.approx(0.3125, abs=0.01)
    world.close()


def test_query_state_samples_the_trajectory_at_the_time_asked():
    """~query_state (control_msgs/QueryTrajectoryState, impl:303-305, :662-708): the
    trajectory followed, sampled at the request's time: 1 s into a 2 s linear move to
    [1.0, 0.4], [0.5, 0.2] at [0.5, 0.2] rad/s; a time before the trajectory (the controller
    started at 0.5 s, asked about 0.2 s) is an error. Before: no such service."""
    world, bus, model = arm()
    run(world, 0.5)
    start(bus, "arm_controller")
    on_goal, _ = bus.actions[ACTION]
    query = bus.services[QUERY]
    begin = world.now_ns
    on_goal(GoalHandle(goal_to([1.0, 0.4], 2.0)))
    answer = query(QueryTrajectoryStateRequest(time=genpy.Time(0, begin + 1_000_000_000)))
    assert list(answer.name) == ["pan", "lift"]
    assert list(answer.position) == pytest.approx([0.5, 0.2], abs=1e-3)
    assert list(answer.velocity) == pytest.approx([0.5, 0.2], abs=1e-3)
    assert list(answer.acceleration) == pytest.approx([0.0, 0.0])
    with pytest.raises(ValueError):
        query(QueryTrajectoryStateRequest(time=genpy.Time(0, 200_000_000)))
    world.close()


def test_a_controller_that_is_not_running_refuses_goals():
    """goalCB while the controller is loaded but not running: rejected with INVALID_GOAL
    (impl:571-579); the arm stays put. Before: accepted and, once started, followed."""
    world, bus, model = arm()
    assert bus.services[f"{MANAGER}/load_controller"](LoadControllerRequest("arm_controller")).ok
    on_goal, _ = bus.actions[ACTION]
    handle = GoalHandle(goal_to([0.5, 0.0], 0.5))
    on_goal(handle)
    assert (handle.status, handle.result.error_code) == ("rejected", Result.INVALID_GOAL)
    run(world, 1.0)
    assert angles(model, "pan")[0] == pytest.approx(0.0, abs=1e-3)
    with pytest.raises(ValueError):
        bus.services[QUERY](QueryTrajectoryStateRequest(time=genpy.Time(0, world.now_ns)))
    world.close()

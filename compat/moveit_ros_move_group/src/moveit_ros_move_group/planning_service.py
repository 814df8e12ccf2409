"""move_group's planning capabilities (MoveIt's MoveGroupMoveAction, MoveGroupPlanService,
MoveGroupQueryPlannersService, MoveGroupExecuteTrajectoryAction): requests turned into
plans of the OMPL pipeline on a snapshot of the monitored scene, and plans executed by the
trajectory execution manager. Every request is checked where it enters
(:mod:`validation`): one that fails is answered with MoveIt's code and a message naming the
cause, and nothing is planned or executed. Functions of the request, so tested without a
master."""
from __future__ import annotations

import logging
from typing import Callable, Optional, Tuple

from moveit_msgs.msg import (MotionPlanResponse, MoveGroupResult, MoveItErrorCodes as Codes,
                             PlannerInterfaceDescription, RobotTrajectory)
from moveit_msgs.srv import GetMotionPlanResponse, QueryPlannerInterfacesResponse

from moveit_core.planning_scene import SceneError
from moveit_core.time_parameterization import joint_trajectory
from moveit_planners_ompl.planner import PlanResult
from moveit_ros_move_group.conversions import robot_state
from moveit_ros_move_group.validation import Refused, check_plan_request, check_trajectory

PIPELINE = "ompl"
PLANNING_PLUGIN = "ompl_interface/OMPLPlanner"
# rospy shows the rosout.* loggers on the console and /rosout
LOG = logging.getLogger("rosout.move_group")


class Planning:
    """What the planning capabilities share: the context (model, current state), the scene
    monitor, the planner and, when execution is allowed, the execution manager."""

    def __init__(self, context, monitor, planner, executor=None):
        self.context, self.monitor, self.planner, self.executor = \
            context, monitor, planner, executor

    def _scene_for(self, request, diff=None):
        """The monitored scene with the goal's ``planning_scene_diff`` over it. A diff that
        cannot be applied is refused with FAILURE, the code MoveIt's move capability gives
        a planning pipeline that threw (move_action_capability.cpp, noetic-devel 7c0343f0,
        l. 182-186 and 214-218), naming the object."""
        scene = self.monitor.snapshot()
        if diff is not None and (diff.world.collision_objects or
                                 diff.robot_state.attached_collision_objects or
                                 diff.robot_state.joint_state.name):
            try:
                scene.apply(diff)
            except SceneError as error:
                raise Refused(Codes.FAILURE, f"planning_options.planning_scene_diff cannot be "
                              f"applied: {error} (nothing was planned)") from None
        return scene

    def plan(self, request, diff=None) -> PlanResult:
        return self.planner.plan(self._scene_for(request, diff), request)

    def _trajectory(self, result: PlanResult) -> RobotTrajectory:
        trajectory = RobotTrajectory()
        if result.ok:
            trajectory.joint_trajectory = joint_trajectory(result.timed, result.joints)
            trajectory.joint_trajectory.header.frame_id = self.context.model.model_frame
        return trajectory

    def _start_state(self, result: PlanResult):
        model = self.context.model
        start = model.complete(dict(self.monitor.current.positions(), **result.start))
        return robot_state(start, [j for j in model.joint_order if j in model.bounds])

    # --- plan_kinematic_path -----------------------------------------------------------

    def plan_service(self, request) -> GetMotionPlanResponse:
        try:
            check_plan_request(request.motion_plan_request, "motion_plan_request")
            result = self.plan(request.motion_plan_request)
        except Refused as refusal:
            result = self._refused("plan_kinematic_path", refusal)
        response = GetMotionPlanResponse()
        response.motion_plan_response = MotionPlanResponse(
            trajectory_start=self._start_state(result),
            group_name=request.motion_plan_request.group_name,
            trajectory=self._trajectory(result), planning_time=result.planning_time)
        response.motion_plan_response.error_code.val = result.code
        return response

    # --- the move_group action ---------------------------------------------------------

    def move(self, goal, feedback=None,
             preempted: Optional[Callable[[], bool]] = None) -> Tuple[MoveGroupResult, str]:
        """A MoveGroup goal planned (and executed unless plan only); the result and its
        text (MoveIt's). ``preempted()`` true once planning is done: the goal was
        preempted meanwhile and nothing is executed (PREEMPTED), as MoveIt's PlanExecution
        checks before it executes (plan_execution.cpp, noetic-devel 7c0343f0, l. 167-169,
        196-198, 229-233)."""
        request, options = goal.request, goal.planning_options
        execute = not options.plan_only
        if execute and self.executor is None:
            execute = False
        if execute and (request.start_state.joint_state.name or
                        request.start_state.attached_collision_objects):
            # MoveIt plans a motion it executes from where the robot is
            request.start_state.joint_state.name = []
            request.start_state.joint_state.position = []
        if feedback:
            feedback("PLANNING")
        try:
            check_plan_request(request)
            result = self.plan(request, options.planning_scene_diff)
        except Refused as refusal:
            result = self._refused("move_group", refusal)
        answer = MoveGroupResult(trajectory_start=self._start_state(result),
                                 planned_trajectory=self._trajectory(result),
                                 planning_time=result.planning_time if not execute else 0.0)
        answer.error_code.val = result.code
        if not result.ok:
            return answer, ("No motion plan found. No execution attempted."
                            if result.code in (Codes.PLANNING_FAILED, Codes.TIMED_OUT,
                                               Codes.INVALID_MOTION_PLAN) else result.message)
        if not execute:
            return answer, "Motion plan was computed succesfully."
        if preempted is not None and preempted():
            answer.error_code.val = Codes.PREEMPTED
            return answer, "preempted before execution: nothing was executed"
        if feedback:
            feedback("MONITOR")
        code, message = self.executor.execute(answer.planned_trajectory.joint_trajectory,
                                              preempted)
        answer.error_code.val = code
        return answer, "Solution was found and executed." if code == Codes.SUCCESS else message

    # --- execute_trajectory ------------------------------------------------------------

    def execute_trajectory(self, goal, preempted: Optional[Callable[[], bool]] = None
                           ) -> Tuple[int, str]:
        """An ExecuteTrajectory goal checked (:func:`validation.check_trajectory`) and
        executed; (MoveIt's code, what happened). ``preempted`` as for :meth:`move`."""
        if self.executor is None:
            return Codes.CONTROL_FAILED, ("trajectory execution is off "
                                          "(allow_trajectory_execution false, or no "
                                          "moveit_controller_manager)")
        try:
            check_trajectory(goal.trajectory, self.context.model.bounds,
                             self.planner.adapters.start_state_max_bounds_error)
        except Refused as refusal:
            result = self._refused("execute_trajectory", refusal)
            return result.code, result.message
        return self.executor.execute(goal.trajectory.joint_trajectory, preempted)

    @staticmethod
    def _refused(capability: str, refusal: Refused) -> PlanResult:
        LOG.warning("%s: request refused (%d): %s", capability, refusal.code, refusal.message)
        return PlanResult(refusal.code, refusal.message)

    # --- query_planner_interface -------------------------------------------------------

    def query_planners(self, _request) -> QueryPlannerInterfacesResponse:
        configs = self.planner.configs
        ids = configs.planner_ids()
        for group in self.context.model.groups:
            ids += [f"{group}[{name}]" for name in configs.group(group).planner_ids]
        return QueryPlannerInterfacesResponse(planner_interfaces=[PlannerInterfaceDescription(
            name=PLANNING_PLUGIN, pipeline_id=PIPELINE, planner_ids=ids)])


def action_text_status(code: int) -> str:
    """The action's end state for a MoveIt code (as MoveIt's action servers end them)."""
    if code == Codes.SUCCESS:
        return "succeeded"
    if code == Codes.PREEMPTED:
        return "preempted"
    return "aborted"

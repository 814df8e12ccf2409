"""The ``move_group`` node: reads what a MoveIt config package loads and serves MoveIt's
interfaces in its namespace.

Read once at start (move_group's private namespace unless said): the robot model
(``robot_description``, ``robot_description_semantic``, ``robot_description_kinematics``,
``robot_description_planning``), the OMPL pipeline's parameters (under
``planning_pipelines/<id>/`` as Noetic's Setup Assistant writes them, else directly under
``~`` as older configs do), trajectory execution (``allow_trajectory_execution``,
``moveit_controller_manager``, ``controller_list``, ``trajectory_execution/*``) and
``capabilities``/``disable_capabilities``.

Served (the node's namespace, as MoveIt's): actions ``move_group``, ``execute_trajectory``,
``pickup`` and ``place`` (moveit_commander waits for all four; pick and place are not
provided: their goals are aborted saying so); services ``compute_fk``, ``compute_ik``,
``plan_kinematic_path``, ``compute_cartesian_path``, ``get_planning_scene``,
``apply_planning_scene``, ``check_state_validity``, ``query_planner_interface``,
``clear_octomap``; the scene from ``planning_scene``, ``collision_object``,
``attached_collision_object``, ``planning_scene_world`` and ``joint_states``; published
``~monitored_planning_scene`` and ``~display_planned_path``; ``trajectory_execution_event``
"stop" stops execution."""
from __future__ import annotations

import sys
import threading
import traceback
from typing import Dict, List

import actionlib
import rospy
from moveit_msgs.msg import (DisplayTrajectory, ExecuteTrajectoryAction, ExecuteTrajectoryResult,
                             MoveGroupAction, MoveGroupFeedback, MoveGroupResult,
                             MoveItErrorCodes as Codes, PickupAction, PickupResult, PlaceAction,
                             PlaceResult)
from moveit_msgs.srv import (ApplyPlanningScene, GetCartesianPath, GetMotionPlan,
                             GetPlanningScene, GetPositionFK, GetPositionIK, GetStateValidity,
                             QueryPlannerInterfaces)
from sensor_msgs.msg import JointState
from std_msgs.msg import String
from std_srvs.srv import Empty

from moveit_core.planning_scene import PlanningScene
from moveit_planners_ompl.planner import AdapterSettings, OmplPlanner
from moveit_planners_ompl.planner_configs import PlannerConfigs
from moveit_ros_move_group import cartesian_path, kinematics_service, scene_service
from moveit_ros_move_group.context import ContextError, from_parameters
from moveit_ros_move_group.execution import ExecutionSettings, TrajectoryExecutionManager
from moveit_ros_move_group.planning_service import PLANNING_PLUGIN, Planning, action_text_status
from moveit_ros_move_group.scene_monitor import SceneMonitor

FAKE = "moveit_fake_controller_manager/MoveItFakeControllerManager"
SIMPLE = "moveit_simple_controller_manager/MoveItSimpleControllerManager"
# MoveIt's default capabilities and what each serves here
CAPABILITIES = {
    "move_group/MoveGroupMoveAction": "move_group",
    "move_group/MoveGroupExecuteTrajectoryAction": "execute_trajectory",
    "move_group/MoveGroupPlanService": "plan_kinematic_path",
    "move_group/MoveGroupKinematicsService": "compute_fk compute_ik",
    "move_group/MoveGroupCartesianPathService": "compute_cartesian_path",
    "move_group/MoveGroupQueryPlannersService": "query_planner_interface",
    "move_group/MoveGroupStateValidationService": "check_state_validity",
    "move_group/MoveGroupGetPlanningSceneService": "get_planning_scene",
    "move_group/ApplyPlanningSceneService": "apply_planning_scene",
    "move_group/ClearOctomapService": "clear_octomap",
    "move_group/MoveGroupPickPlaceAction": "pickup place",
}


def _private(name: str, default):
    return rospy.get_param(f"~{name}", default)


def pipeline_parameters() -> Dict:
    """The OMPL pipeline's parameters: ``~planning_pipelines/<id>`` (Noetic's layout) or
    ``~`` itself (older configs)."""
    pipelines = _private("planning_pipelines", {})
    if isinstance(pipelines, dict) and pipelines:
        chosen = _private("default_planning_pipeline", "ompl")
        parameters = pipelines.get(chosen) or next(iter(pipelines.values()))
    else:
        parameters = rospy.get_param("~", {})
    plugin = parameters.get("planning_plugin", PLANNING_PLUGIN) if isinstance(parameters, dict) \
        else PLANNING_PLUGIN
    if plugin != PLANNING_PLUGIN:
        # CHOMP, STOMP, Pilz: a config that chose one is planned with OMPL, and says so
        rospy.logwarn("planning_plugin '%s' is not one this move_group has: planning with "
                      "OMPL (%s) instead", plugin, PLANNING_PLUGIN)
    return parameters


def controller_manager():
    """The configured controller manager, or None (no execution), saying why."""
    plugin = _private("moveit_controller_manager", "")
    entries = _private("controller_list", [])
    if plugin == FAKE:
        from moveit_fake_controller_manager.manager import FakeControllerManager
        return FakeControllerManager(entries, float(_private(
            "fake_interpolating_controller_rate", 10.0)))
    if plugin == SIMPLE:
        from moveit_simple_controller_manager.manager import SimpleControllerManager
        return SimpleControllerManager(entries, float(_private(
            "trajectory_execution/controller_connection_timeout", 15.0)))
    if plugin:
        rospy.logerr("moveit_controller_manager '%s' is not one this move_group has (%s, %s): "
                     "trajectories will not be executed", plugin, FAKE, SIMPLE)
    else:
        rospy.logwarn("no moveit_controller_manager: trajectories will not be executed")
    return None


def publish_initial_states(manager, context) -> None:
    """The fake controllers' ``initial`` group states, published once, in one message (the
    topic is latched: a joint state publisher that subscribes later hears the last message
    only)."""
    values = {}
    for entry in _private("initial", []) or []:
        try:
            values.update(context.model.named_state(entry["group"], entry["pose"]))
        except (KeyError, TypeError, ValueError) as error:
            rospy.logerr("fake controllers: initial state %s cannot be used: %s", entry, error)
    if values:
        manager.publish(list(values), list(values.values()))


def main() -> int:
    rospy.init_node("move_group")
    try:
        context = from_parameters(rospy.get_param)
    except ContextError as error:
        rospy.logfatal("move_group cannot start: %s", error)
        return 1
    model = context.model
    rospy.Subscriber("joint_states", JointState, context.state.update, queue_size=25)
    monitor = SceneMonitor(PlanningScene(model), context.state)
    pipeline = pipeline_parameters()
    adapters = AdapterSettings(
        float(pipeline.get("start_state_max_bounds_error", 0.1)),
        float(pipeline.get("jiggle_fraction", _private("jiggle_fraction", 0.05))))
    planner = OmplPlanner(PlannerConfigs(pipeline), context.solver, adapters)
    executor = None
    if _private("allow_trajectory_execution", True):
        manager = controller_manager()
        if manager is not None:
            executor = TrajectoryExecutionManager(manager, ExecutionSettings(
                float(_private("trajectory_execution/allowed_execution_duration_scaling", 1.1)),
                float(_private("trajectory_execution/allowed_goal_duration_margin", 0.5)),
                float(_private("trajectory_execution/allowed_start_tolerance", 0.01)),
                bool(_private("trajectory_execution/execution_duration_monitoring", True))),
                context.state)
            if hasattr(manager, "publish"):
                publish_initial_states(manager, context)
    planning = Planning(context, monitor, planner, executor)
    monitor.start()
    display = rospy.Publisher("~display_planned_path", DisplayTrajectory, queue_size=10,
                              latch=True)
    if executor is not None:
        rospy.Subscriber("trajectory_execution_event", String,
                         lambda m: executor.stop() if m.data == "stop" else None)
    disabled = set(str(_private("disable_capabilities", "")).split())
    served: List = []

    def wanted(capability: str) -> bool:
        return capability not in disabled

    if wanted("move_group/MoveGroupKinematicsService"):
        served += [rospy.Service("compute_fk", GetPositionFK,
                                 lambda r: kinematics_service.compute_fk(context, r)),
                   rospy.Service("compute_ik", GetPositionIK,
                                 lambda r: kinematics_service.compute_ik(context, r, monitor))]
    if wanted("move_group/MoveGroupGetPlanningSceneService"):
        served.append(rospy.Service("get_planning_scene", GetPlanningScene,
                                    lambda r: scene_service.get_planning_scene(monitor, r)))
    if wanted("move_group/ApplyPlanningSceneService"):
        served.append(rospy.Service("apply_planning_scene", ApplyPlanningScene,
                                    lambda r: scene_service.apply_planning_scene(monitor, r)))
    if wanted("move_group/MoveGroupStateValidationService"):
        served.append(rospy.Service("check_state_validity", GetStateValidity,
                                    lambda r: scene_service.check_state_validity(monitor, r)))
    if wanted("move_group/ClearOctomapService"):
        served.append(rospy.Service("clear_octomap", Empty,
                                    lambda r: scene_service.clear_octomap(monitor, r)))
    if wanted("move_group/MoveGroupQueryPlannersService"):
        served.append(rospy.Service("query_planner_interface", QueryPlannerInterfaces,
                                    planning.query_planners))

    def shown(response_trajectory, start):
        if response_trajectory.joint_trajectory.points:
            display.publish(DisplayTrajectory(model_id=model.name, trajectory_start=start,
                                              trajectory=[response_trajectory]))

    def latest_state() -> None:
        """Before planning, the state of a joint_states message no older than the request
        (move_action_capability.cpp:67, plan_service_capability.cpp:58-59 on noetic-devel)."""
        if not context.state.wait_for(rospy.get_time(), model.variables):
            rospy.logwarn("Failed to fetch current robot state.")

    def plan_service(request):
        if request.motion_plan_request.start_state.is_diff:
            latest_state()
        response = planning.plan_service(request)
        shown(response.motion_plan_response.trajectory,
              response.motion_plan_response.trajectory_start)
        return response
    if wanted("move_group/MoveGroupPlanService"):
        served.append(rospy.Service("plan_kinematic_path", GetMotionPlan, plan_service))

    def cartesian(request):
        response = cartesian_path.compute_cartesian_path(context, monitor, request)
        shown(response.solution, response.start_state)
        return response
    if wanted("move_group/MoveGroupCartesianPathService"):
        served.append(rospy.Service("compute_cartesian_path", GetCartesianPath, cartesian))

    servers = []
    if wanted("move_group/MoveGroupMoveAction"):
        move_server = actionlib.SimpleActionServer("move_group", MoveGroupAction,
                                                   auto_start=False)

        def move(goal, handle):
            latest_state()
            result, text = planning.move(
                goal, lambda state: move_server.publish_feedback(MoveGroupFeedback(state=state)),
                lambda: move_server.current_goal != handle or
                move_server.is_preempt_requested())
            shown(result.planned_trajectory, result.trajectory_start)
            _finish(move_server, handle, result.error_code.val, result, text)
        move_server.register_goal_callback(lambda: _run(move_server, move, MoveGroupResult))
        move_server.register_preempt_callback(lambda: executor.stop() if executor else None)
        servers.append(move_server)
    if wanted("move_group/MoveGroupExecuteTrajectoryAction"):
        execute_server = actionlib.SimpleActionServer("execute_trajectory",
                                                      ExecuteTrajectoryAction, auto_start=False)

        def execute(goal, handle):
            code, text = planning.execute_trajectory(
                goal, lambda: execute_server.current_goal != handle or
                execute_server.is_preempt_requested())
            result = ExecuteTrajectoryResult()
            result.error_code.val = code
            _finish(execute_server, handle, code, result, text)
        execute_server.register_goal_callback(lambda: _run(execute_server, execute,
                                                           ExecuteTrajectoryResult))
        execute_server.register_preempt_callback(lambda: executor.stop() if executor else None)
        servers.append(execute_server)
    if wanted("move_group/MoveGroupPickPlaceAction"):
        for name, action, result_type in (("pickup", PickupAction, PickupResult),
                                          ("place", PlaceAction, PlaceResult)):
            servers.append(_not_provided(name, action, result_type))
    for server in servers:
        server.start()
    rospy.loginfo("move_group: robot '%s', model frame '%s', groups %s; execution %s; "
                  "serving %s and the actions %s", model.name, model.model_frame,
                  ", ".join(model.groups) or "none",
                  type(executor.manager).__name__ if executor else "off",
                  ", ".join(s.resolved_name for s in served),
                  ", ".join(s.action_server.ns for s in servers))
    rospy.loginfo("You can start planning now!")
    rospy.spin()
    return 0


def _run(server, handler, result_type) -> None:
    """Accepts the new goal and runs it in a thread of its own, so that a stop or a second
    goal is heard meanwhile. A goal still running is preempted first, its result saying
    PREEMPTED (-7) as MoveIt's capabilities end a preempted goal (setPreempted with the
    code: move_action_capability.cpp l. 89-90, execute_trajectory_action_capability.cpp
    l. 77-79, noetic-devel 7c0343f0); its thread stops before executing anything (the
    preempt callback has stopped an execution already running). The goal callback runs
    under the action server's lock, which _finish takes too: a goal ends once."""
    with server.action_server.lock:
        if server.is_active():
            server.current_goal.set_canceled(_result(result_type, Codes.PREEMPTED),
                                             "preempted by a newer goal")
        goal, handle = server.accept_new_goal(), server.current_goal

    def guarded():
        # a fault of ours must end the goal, not leave the client waiting for ever: with
        # FAILURE, as MoveIt's move capability answers a planning pipeline that threw
        # (move_action_capability.cpp l. 182-186, 214-218)
        try:
            handler(goal, handle)
        except Exception as error:  # pylint: disable=broad-except
            rospy.logerr("move_group: %s failed: %s\n%s", server.action_server.ns, error,
                         traceback.format_exc())
            with server.action_server.lock:
                if server.current_goal == handle and server.is_active():
                    server.set_aborted(_result(result_type, Codes.FAILURE),
                                       f"move_group failed: {type(error).__name__}: {error}")
    threading.Thread(target=guarded, daemon=True).start()


def _result(result_type, code: int):
    result = result_type()
    result.error_code.val = code
    return result


def _finish(server, handle, code: int, result, text: str) -> None:
    """Ends the goal ``handle`` unless a newer goal took its place (it was preempted)."""
    with server.action_server.lock:
        if server.current_goal != handle or not server.is_active():
            return
        status = action_text_status(code)
        if status == "succeeded":
            server.set_succeeded(result, text)
        elif status == "preempted":
            server.set_preempted(result, text)
        else:
            server.set_aborted(result, text)


def _not_provided(name: str, action, result_type):
    server = actionlib.SimpleActionServer(name, action, auto_start=False)

    def refuse():
        server.accept_new_goal()
        result = result_type()
        result.error_code.val = Codes.FAILURE
        server.set_aborted(result, f"{name} is not provided by this move_group (MoveIt's "
                                   "pick and place pipeline is not emulated)")
    server.register_goal_callback(refuse)
    return server


if __name__ == "__main__":
    sys.exit(main())

"""The ROS side of sim_bridge: gazebo_ros's node, topics and services around a World.

The node is named ``gazebo`` by the launch files, so its services are gazebo_ros's:
``/gazebo/spawn_urdf_model``, ``spawn_sdf_model``, ``delete_model``, ``get_model_state``,
``set_model_state``, ``set_model_configuration``, ``get_world_properties``,
``get_model_properties``, ``get_link_state``, ``set_link_state``,
``get_joint_properties``, ``set_joint_properties``, ``get_link_properties``,
``set_link_properties``, ``get_light_properties``, ``set_light_properties``,
``delete_light``, ``get_physics_properties``, ``set_physics_properties``, ``apply_body_wrench``,
``clear_body_wrenches``, ``apply_joint_effort``, ``clear_joint_forces``,
``pause_physics``, ``unpause_physics``, ``reset_simulation``, ``reset_world``; topics
``/clock``, ``/gazebo/model_states`` and ``/gazebo/link_states`` (the two published at
``~model_states_frequency``, and only while someone listens), ``/gazebo/performance_metrics``
(the real time factor and the sensors' rates, once a wall second while someone listens);
it subscribes
``/gazebo/set_model_state`` and ``/gazebo/set_link_state``, the services' requests as
messages, unanswered.

A request that cannot be done answers ``success: false`` with a ``status_message`` naming
the cause (``<Service>: ...``), and the node goes on; ``clear_body_wrenches`` and
``clear_joint_forces`` have no answer fields, so an unknown name there is a warning.

Pacing: the world's ``max_update_rate`` × step size is the real time factor the loop keeps
to (0: as fast as it can); ``~real_time_factor`` sets it at start, set_physics_properties
later, as Gazebo's real_time_update_rate.

Threads: the physics runs in the main thread, which alone touches pybullet. Service
calls arrive on rospy's threads and are handed to it through a queue (so a request
waits at most one step); subscriber callbacks only store the latest command.
"""
from __future__ import annotations

import math
import os
import queue
import subprocess
import sys
import threading
import time
from dataclasses import dataclass
from typing import Any, Callable, Dict, Optional, Sequence, Tuple

import numpy as np
import pybullet as pb
import rospy
from geometry_msgs.msg import Pose, Twist
from std_msgs.msg import ColorRGBA
from std_srvs.srv import Empty, EmptyResponse
from tf2_msgs.msg import TFMessage

from gazebo_msgs.msg import (LinkState, LinkStates, ModelState, ModelStates, PerformanceMetrics,
                             SensorPerformanceMetric)
from sim_bridge import one_simulator
from sim_bridge.plugins.base import Bus, PluginError
from sim_bridge.poses import quaternion_matrix
from sim_bridge import native_plugins
from sim_bridge.ros_publishing import ClockPublisher, batch_queued_writes, has_connections
from sim_bridge.sdf_world import SdfError, load_world, parse_light, parse_model
from sim_bridge.stop_signals import StopSignals, shut_rospy_down
from gazebo_msgs.srv import (ApplyBodyWrench, ApplyBodyWrenchResponse, ApplyJointEffort,
                            ApplyJointEffortResponse, BodyRequest, BodyRequestResponse,
                            DeleteLight, DeleteLightResponse, DeleteModel,
                            DeleteModelResponse, GetLightProperties,
                            GetLightPropertiesResponse, GetLinkProperties,
                            GetLinkPropertiesResponse, GetLinkState,
                            GetJointProperties, GetJointPropertiesResponse,
                            GetLinkStateResponse, GetModelProperties,
                            GetModelPropertiesResponse, GetModelState, GetModelStateResponse,
                            GetPhysicsProperties, GetPhysicsPropertiesResponse,
                            GetWorldProperties, GetWorldPropertiesResponse, JointRequest,
                            JointRequestResponse, SetLinkState, SetLinkStateResponse,
                            SetJointProperties, SetJointPropertiesResponse,
                            SetLightProperties, SetLightPropertiesResponse,
                            SetLinkProperties, SetLinkPropertiesResponse,
                            SetModelConfiguration, SetModelConfigurationResponse, SetModelState,
                            SetModelStateResponse, SetPhysicsProperties,
                            SetPhysicsPropertiesResponse, SpawnModel, SpawnModelResponse)
from sim_bridge.world import WORLD_FRAMES, SimError, World
from urdf_tools.model import UrdfError
from node_params import non_negative, parameter, positive, read, zero_or_at_least

# How long a service waits for the physics thread to take its request (wall seconds).
REQUEST_TIMEOUT = 30.0
# s: how often the physics loop lets rospy's threads run (see main)
THREAD_SWITCH_INTERVAL = 0.0005
# gzserver's exit status when its port is taken by another Gazebo
ALREADY_RUNNING_STATUS = 255
# gazebo_ros's queue for the set_model_state and set_link_state topics' messages
# (gazebo_ros_api_plugin.cpp:478, :486)
STATE_TOPIC_QUEUE = 10
# ~performance_metrics: how often it is published (wall seconds), each message measuring
# the real time factor over that span. Gazebo 11 sends its own (which gazebo_ros relays,
# gazebo_ros_api_plugin.cpp:230-253) from gazebo-classic's world, not read here: its
# period is unverified.
PERFORMANCE_PERIOD = 1.0
# its queue, gazebo_ros's (:413)
PERFORMANCE_QUEUE = 10
# sensor types that render frames: their metric carries an fps (gazebo_ros: -1 otherwise,
# :242-249)
CAMERA_TYPES = frozenset(("camera", "depth", "multicamera", "wideanglecamera"))
NO_FPS = -1.0
# get_joint_properties' type constants by URDF joint type (gazebo_msgs/GetJointProperties)
JOINT_TYPES = {"revolute": GetJointPropertiesResponse.REVOLUTE,
               "continuous": GetJointPropertiesResponse.CONTINUOUS,
               "prismatic": GetJointPropertiesResponse.PRISMATIC,
               "fixed": GetJointPropertiesResponse.FIXED}
# gazebo_msgs/ODEJointProperties' fields with no pybullet counterpart
ODE_JOINT_ONLY = ("erp", "cfm", "stop_erp", "stop_cfm", "fudge_factor")
# What a request gets once the simulator has been told to stop.
STOPPING = "the simulator is shutting down"
# While paused, /clock is repeated this often (wall seconds) for late subscribers.
PAUSED_CLOCK_PERIOD = 0.1
# Paced, the loop steps until it is this far (wall seconds) ahead of the wall clock, then
# sleeps until its time comes: every wake-up costs (at 2 ms, 500 a second, the paced
# simulator used twice the CPU its steps did); simulated time runs at most this far ahead.
PACE_BATCH = 0.01
# At most this many steps between two looks of the loop at its queue of service calls, at
# rospy's shutdown and at the clock (World.advance makes the steps no plugin needs by the
# physics alone): at full speed on a 1 ms step about 1 ms of wall time, so a call waits no
# longer than that for the physics.
MAX_BATCH_STEPS = 20


@dataclass
class Config:
    """The node's private parameters, read once (defaults and units in
    config/sim_bridge.yaml)."""

    # The slowest real time factor taken (besides 0): slower, one step's pacing sleep would
    # outlast a stop request (Ctrl-C is acted on between steps), and a factor like 1e-300
    # would ask time.sleep for more than it can wait. There is no highest: beyond what the
    # machine reaches (1e9 says so), the loop steps as fast as it can, as with 0.
    MIN_REAL_TIME_FACTOR = 0.001

    world_name: str = parameter("", expected="an SDF world file (empty: no world)")
    paused: bool = parameter(False, expected="true or false: start with physics paused")
    gui: bool = parameter(False, expected="true or false: show pybullet's window")
    real_time_factor: float = parameter(
        1.0, zero_or_at_least(MIN_REAL_TIME_FACTOR),
        expected=f"0 (as fast as it can) or a number of simulated seconds per wall second "
                 f"of at least {MIN_REAL_TIME_FACTOR:g}")
    seed: int = parameter(0, non_negative,
                          expected="a whole number >= 0 seeding the simulated noise")
    # 0: every step, as gazebo_ros publishes /clock unless pub_clock_frequency is set
    pub_clock_frequency: float = parameter(
        0.0, non_negative,
        expected="a rate in Hz of simulated time for /clock >= 0 (0: every step, as Gazebo)")
    model_states_frequency: float = parameter(
        50.0, positive,
        expected="a positive rate in Hz of simulated time for /gazebo/model_states")
    ray_threads: int = parameter(
        0, non_negative, expected="a whole number of threads for laser rays >= 0 (0: all cores)")
    # gzserver --verbose: the simulator's own notes (each model of the world, each plugin
    # with the parameters it runs with) at INFO; rospy's internal loggers stay at INFO
    verbose: bool = parameter(
        False, expected="true or false: log what the simulator loads (gzserver --verbose)")
    # false: no /gazebo services or topics (gazebo_ros's enable_ros_network); /clock stays
    enable_ros_network: bool = parameter(
        True, expected="true or false: offer the /gazebo services and topics")

    @classmethod
    def from_parameters(cls, overrides: Optional[Dict[str, Any]] = None) -> "Config":
        """Private parameters over the defaults, and ``overrides`` (the command line that
        gzserver was given; node_params.Given values name their option) over both.
        ParameterError (a ValueError) names the parameter, the value and what is expected."""
        return read(cls, rospy.get_param, "~", overrides)


class PhysicsThread:
    """Work for the physics thread, handed over from rospy's threads. The physics loop calls
    ``serve()`` between steps; ``call`` waits for the result, ``post`` does not. Once the
    loop has ended, ``close()`` answers what is still queued, and every later request, with
    an error instead of leaving the caller waiting."""

    def __init__(self):
        self.jobs: "queue.Queue" = queue.Queue()
        self.closed = False

    def post(self, work: Callable[[], Any]) -> None:
        if not self.closed:
            self.jobs.put(work)

    def call(self, work: Callable[[], Any]) -> Any:
        done = threading.Event()
        box: Dict[str, Any] = {}

        def job():
            try:
                if self.closed:
                    raise SimError(STOPPING)
                box["result"] = work()
            except Exception as error:  # handed back to the calling thread
                box["error"] = error
            finally:
                done.set()

        if self.closed:
            raise SimError(STOPPING)
        self.jobs.put(job)
        if not done.wait(REQUEST_TIMEOUT):
            raise SimError(f"the simulator did not take the request within "
                           f"{REQUEST_TIMEOUT:.0f} s")
        if "error" in box:
            raise box["error"]
        return box.get("result")

    def serve(self) -> None:
        # the usual case, asked every step: the queue's deque read without the queue's
        # lock (a job put meanwhile is served at the next step, as it would be with it)
        if not self.jobs.queue:
            return
        while True:
            try:
                job = self.jobs.get_nowait()
            except queue.Empty:
                return
            job()

    def close(self) -> None:
        """No more work: what is queued is answered with an error (``call``'s jobs check
        ``closed``; ``post``'s are dropped)."""
        self.closed = True
        self.serve()


class RosBus(Bus):
    """Bus for plugins, on rospy."""

    def __init__(self, physics: PhysicsThread, verbose: bool = False):
        self.physics = physics
        self.verbose = verbose
        self._tf = rospy.Publisher("/tf", TFMessage, queue_size=100)
        self._throttle: Dict[str, float] = {}

    def service(self, name, srv_class, handler):
        def serve(request):
            try:
                return self.physics.call(lambda: handler(request))
            except (SimError, PluginError, ValueError) as error:
                raise rospy.ServiceException(str(error))
        return rospy.Service(name, srv_class, serve)

    def action_server(self, name, action_class, on_goal, on_cancel):
        import actionlib  # only robots with trajectory controllers need it
        server = actionlib.ActionServer(
            name, action_class, lambda handle: self.physics.post(lambda: on_goal(handle)),
            lambda handle: self.physics.post(lambda: on_cancel(handle)), auto_start=False)
        server.start()
        return server

    def publisher(self, topic, msg_class, queue_size=10, latch=False):
        return rospy.Publisher(topic, msg_class, queue_size=queue_size, latch=latch)

    def subscriber(self, topic, msg_class, callback):
        return rospy.Subscriber(topic, msg_class, callback, queue_size=1)

    def send_transforms(self, transforms):
        self._tf.publish(TFMessage(transforms=list(transforms)))

    def listened(self, publisher=None):
        return has_connections(publisher or self._tf)

    def info(self, text):
        rospy.loginfo(text)

    def warn(self, text):
        rospy.logwarn(text)

    def debug(self, text):
        # Gazebo's --verbose prints the simulator's messages, not its middleware's: these
        # notes go out at INFO, and rospy's own loggers are never raised to DEBUG (they
        # print "Broken Pipe" each time a subscriber leaves)
        if self.verbose:
            rospy.loginfo(text)

    def warn_throttled(self, key, period, text):
        now = time.monotonic()
        if now - self._throttle.get(key, -math.inf) >= period:
            self._throttle[key] = now
            rospy.logwarn(text)

    def get_param(self, name, default=None):
        return rospy.get_param(name, default)


def search_tf_prefix(namespace: str, lookup) -> str:
    """What gazebo_ros's plugins prefix their frames with, for a model in ``namespace``;
    ``lookup(key)`` is a parameter's value or None. Noetic's GazeboRos reads it with
    tf::getPrefixParam (gazebo_ros_pkgs noetic-devel f9e1a46,
    gazebo_plugins/src/gazebo_ros_utils.cpp:87): a searchParam for ``tf_prefix`` from the
    namespace up to the root, "" when none is set. The namespace itself is no prefix (three
    robots spawned in tb3_0..tb3_2 without a tf_prefix all publish odom, as in Gazebo; the
    header's comment, gazebo_ros_utils.h:116, says otherwise, the code does not)."""
    parts = [part for part in namespace.split("/") if part]
    for depth in range(len(parts), -1, -1):
        value = lookup("/" + "/".join(parts[:depth] + ["tf_prefix"]))
        if value is not None:
            return str(value)
    return ""


def display_available() -> bool:
    display = os.environ.get("DISPLAY")
    if not display:
        return False
    return subprocess.run(["xdpyinfo", "-display", display], capture_output=True,
                          check=False).returncode == 0


def _pose_parts(pose: Pose):
    position = (pose.position.x, pose.position.y, pose.position.z)
    orientation = (pose.orientation.x, pose.orientation.y, pose.orientation.z,
                   pose.orientation.w)
    if orientation == (0.0, 0.0, 0.0, 0.0):  # an unset quaternion means no rotation
        orientation = (0.0, 0.0, 0.0, 1.0)
    return position, orientation


def _fill_pose(pose: Pose, position, orientation) -> None:
    pose.position.x, pose.position.y, pose.position.z = (float(v) for v in position)
    pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w = \
        (float(v) for v in orientation)


def _fill_twist(twist: Twist, linear, angular) -> None:
    twist.linear.x, twist.linear.y, twist.linear.z = (float(v) for v in linear)
    twist.angular.x, twist.angular.y, twist.angular.z = (float(v) for v in angular)


def _vector(message) -> tuple:
    return (message.x, message.y, message.z)


def _colour(message) -> tuple:
    return (message.r, message.g, message.b, message.a)


def _relative(position, orientation, linear, angular, frame):
    """A pose and twist in the world seen from ``frame`` = (position, orientation, linear,
    angular) of the frame: gazebo_ros's get_*_state (the twist is relative to the frame's
    origin, in its axes)."""
    frame_position, frame_orientation, frame_linear, frame_angular = frame
    inverse = pb.invertTransform(frame_position, frame_orientation)
    position, orientation = pb.multiplyTransforms(*inverse, position, orientation)
    rotation = quaternion_matrix(frame_orientation).T
    return (position, orientation, rotation @ (np.asarray(linear) - frame_linear),
            rotation @ (np.asarray(angular) - frame_angular))


class PerformanceMeter:
    """gazebo_ros's ``~performance_metrics`` (gazebo_ros_api_plugin.cpp:410-417,
    :230-253): the real time factor measured over the last ``period`` wall seconds
    (simulated time gone by over wall time gone by), and each sensor's update rate in
    simulated time (its ``<update_rate>``, or every step) and in wall time (that times the
    real time factor); a camera's fps is its wall rate, other sensors' -1."""

    def __init__(self, period: float = PERFORMANCE_PERIOD):
        self.period = period
        self._anchor: Optional[Tuple[float, int]] = None

    def restart(self) -> None:
        """The next measurement starts at the next sample (no one listened meanwhile)."""
        self._anchor = None

    def sample(self, world: World, wall: float) -> Optional[PerformanceMetrics]:
        """A message once ``period`` wall seconds have gone by since the last one (or
        since the first sample), else None."""
        if self._anchor is None:
            self._anchor = (wall, world.now_ns)
            return None
        anchor_wall, anchor_ns = self._anchor
        if wall - anchor_wall < self.period:
            return None
        factor = (world.now_ns - anchor_ns) / 1e9 / (wall - anchor_wall)
        self._anchor = (wall, world.now_ns)
        message = PerformanceMetrics(real_time_factor=factor)
        message.header.stamp = rospy.Time(nsecs=world.now_ns)
        for sensor in world.sensors():
            real_rate = sensor.rate * factor
            message.sensors.append(SensorPerformanceMetric(
                name=sensor.name, sim_update_rate=sensor.rate, real_update_rate=real_rate,
                fps=real_rate if sensor.type in CAMERA_TYPES else NO_FPS))
        return message


class SimBridgeNode:
    """gazebo_ros's interface over a World; ``run()`` is the physics loop."""

    def __init__(self, config: Config, world: World, physics: PhysicsThread):
        self.config = config
        self.world = world
        self.physics = physics
        self.clock_period_ns = int(1e9 / config.pub_clock_frequency) \
            if config.pub_clock_frequency > 0 else 0
        self.states_period_ns = int(1e9 / config.model_states_frequency) \
            if config.model_states_frequency > 0 else 0
        self._next_clock_ns = 0
        self._next_states_ns = 0
        self._pace_anchor = None
        self.model_states = None
        self.link_states = None
        self.performance_metrics = None
        self.performance = PerformanceMeter()
        self.clock: Optional[ClockPublisher] = None
        self._static_version = -1  # the world's scene_version the entries below are of
        self._static_entries: Dict[str, Tuple[Pose, Twist]] = {}

    # --- set-up -------------------------------------------------------------------------
    def advertise_clock(self) -> None:
        self.clock = ClockPublisher()

    def advertise(self) -> None:
        self.advertise_clock()
        self.model_states = rospy.Publisher("~model_states", ModelStates, queue_size=1)
        self.link_states = rospy.Publisher("~link_states", LinkStates, queue_size=1)
        self.performance_metrics = rospy.Publisher("~performance_metrics", PerformanceMetrics,
                                                   queue_size=PERFORMANCE_QUEUE)
        services = [
            ("spawn_urdf_model", SpawnModel, self._spawn_urdf),
            ("spawn_sdf_model", SpawnModel, self._spawn_sdf),
            ("delete_model", DeleteModel, self._delete),
            ("get_model_state", GetModelState, self._get_state),
            ("set_model_state", SetModelState, self._set_state),
            ("set_model_configuration", SetModelConfiguration, self._set_configuration),
            ("get_world_properties", GetWorldProperties, self._world_properties),
            ("get_model_properties", GetModelProperties, self._model_properties),
            ("get_link_state", GetLinkState, self._get_link_state),
            ("set_link_state", SetLinkState, self._set_link_state),
            ("get_joint_properties", GetJointProperties, self._get_joint_properties),
            ("set_joint_properties", SetJointProperties, self._set_joint_properties),
            ("get_link_properties", GetLinkProperties, self._get_link_properties),
            ("set_link_properties", SetLinkProperties, self._set_link_properties),
            ("get_light_properties", GetLightProperties, self._get_light_properties),
            ("set_light_properties", SetLightProperties, self._set_light_properties),
            ("delete_light", DeleteLight, self._delete_light),
            ("get_physics_properties", GetPhysicsProperties, self._get_physics),
            ("set_physics_properties", SetPhysicsProperties, self._set_physics),
            ("apply_body_wrench", ApplyBodyWrench, self._apply_wrench),
            ("clear_body_wrenches", BodyRequest, self._clear_wrenches),
            ("apply_joint_effort", ApplyJointEffort, self._apply_effort),
            ("clear_joint_forces", JointRequest, self._clear_efforts),
            ("pause_physics", Empty, self._pause),
            ("unpause_physics", Empty, self._unpause),
            ("reset_simulation", Empty, self._reset),
            ("reset_world", Empty, self._reset),
        ]
        self.services = [rospy.Service("~" + name, kind, self._guarded(handler, kind))
                         for name, kind, handler in services]
        # the services' topic forms: every message is a request with no answer, ten queued
        # as gazebo_ros subscribes them (gazebo_ros_api_plugin.cpp:474-490)
        self.state_topics = [
            rospy.Subscriber("~set_link_state", LinkState, self.on_set_link_state,
                             queue_size=STATE_TOPIC_QUEUE),
            rospy.Subscriber("~set_model_state", ModelState, self.on_set_model_state,
                             queue_size=STATE_TOPIC_QUEUE)]

    # --- requests: run in the physics thread ---------------------------------------------
    def _guarded(self, handler, kind):
        """Runs ``handler`` in the physics thread; a user's error becomes success=false with
        the cause, and the node goes on."""
        response_class = kind._response_class

        service = kind._type.split('/')[-1]

        def serve(request):
            try:
                return self.physics.call(lambda: handler(request))
            except (SimError, UrdfError, SdfError, PluginError, ValueError) as error:
                rospy.logerr(f"{service}: {error}")
                response = response_class()
                if hasattr(response, "success"):
                    response.success = False
                    response.status_message = f"{service}: {error}"
                    return response
                raise rospy.ServiceException(f"{service}: {error}")
        return serve

    def _posted(self, handler, kind, request) -> None:
        """Hands ``request`` to ``handler`` in the physics thread without waiting: a topic's
        message has no one to answer, so a request that cannot be done is logged, as
        gazebo_ros's setModelState and setLinkState log it."""
        service = kind._type.split('/')[-1]

        def work():
            try:
                handler(request)
            except (SimError, ValueError) as error:
                rospy.logerr(f"{service}: {error}")
        self.physics.post(work)

    def on_set_model_state(self, message) -> None:
        """``~set_model_state`` (gazebo_msgs/ModelState): set_model_state's request, no
        answer (updateModelState, gazebo_ros_api_plugin.cpp:1663-1669)."""
        self._posted(self._set_state, SetModelState,
                     SetModelState._request_class(model_state=message))

    def on_set_link_state(self, message) -> None:
        """``~set_link_state`` (gazebo_msgs/LinkState): set_link_state's request, no answer
        (updateLinkState, gazebo_ros_api_plugin.cpp:1918-1924)."""
        self._posted(self._set_link_state, SetLinkState,
                     SetLinkState._request_class(link_state=message))

    def _spawn(self, request, kind: str):
        light = parse_light(request.model_xml, f"light '{request.model_name}'") \
            if kind == "sdf" else None
        if light is not None:
            # named by the request, at its own <pose>: gazebo_ros renames the light
            # (gazebo_ros_api_plugin.cpp:2703) and puts no initial_pose into an SDF without
            # <model> or <world> (:2427-2435)
            light.name = request.model_name
            self.world.add_light(light)
            rospy.loginfo(f"spawned light '{request.model_name}'")
            return SpawnModelResponse(True, f"SpawnModel: Successfully spawned entity "
                                            f"'{request.model_name}'")
        position, orientation, _, _ = self.world.state_in_world(
            request.reference_frame, *_pose_parts(request.initial_pose), (0, 0, 0), (0, 0, 0))
        if kind == "urdf":
            self.world.spawn_urdf(request.model_name, request.model_xml, position, orientation,
                                  request.robot_namespace, source=f"model '{request.model_name}'",
                                  tf_prefix=self._tf_prefix(request.robot_namespace))
        else:
            spec = parse_model(request.model_xml, f"model '{request.model_name}'")
            if request.model_name:
                spec.name = request.model_name
            self.world.add_sdf_model(spec, position, orientation, request.robot_namespace)
        rospy.loginfo(f"spawned model '{request.model_name}'")
        return SpawnModelResponse(True, f"SpawnModel: Successfully spawned entity "
                                        f"'{request.model_name}'")

    @staticmethod
    def _tf_prefix(namespace: str) -> str:
        return search_tf_prefix(namespace, lambda key: rospy.get_param(key, None))

    def _spawn_urdf(self, request):
        return self._spawn(request, "urdf")

    def _spawn_sdf(self, request):
        return self._spawn(request, "sdf")

    def _delete(self, request):
        self.world.delete(request.model_name)
        return DeleteModelResponse(True, f"DeleteModel: successfully deleted model "
                                         f"'{request.model_name}'")

    def _get_state(self, request):
        position, orientation = self.world.pose(request.model_name)
        linear, angular = self.world.twist(request.model_name)
        if request.relative_entity_name not in WORLD_FRAMES:
            position, orientation, linear, angular = _relative(
                position, orientation, linear, angular,
                self.world.frame_state(request.relative_entity_name))
        response = GetModelStateResponse()
        response.header.stamp = rospy.Time(nsecs=self.world.now_ns)
        # the request's name as written, "" included (gazebo_ros_api_plugin.cpp:970)
        response.header.frame_id = request.relative_entity_name
        _fill_pose(response.pose, position, orientation)
        _fill_twist(response.twist, linear, angular)
        response.success = True
        response.status_message = "GetModelState: got properties"
        return response

    def _set_state(self, request):
        state = request.model_state
        position, orientation = _pose_parts(state.pose)
        linear = (state.twist.linear.x, state.twist.linear.y, state.twist.linear.z)
        angular = (state.twist.angular.x, state.twist.angular.y, state.twist.angular.z)
        self.world.set_state(state.model_name, *self.world.state_in_world(
            state.reference_frame, position, orientation, linear, angular))
        return SetModelStateResponse(True, "SetModelState: set model state done")

    def _set_configuration(self, request):
        if len(request.joint_names) != len(request.joint_positions):
            raise SimError("joint_names and joint_positions differ in length")
        self.world.set_joint_positions(request.model_name,
                                       dict(zip(request.joint_names, request.joint_positions)))
        return SetModelConfigurationResponse(True, "SetModelConfiguration: success")

    def _world_properties(self, _request):
        # the models in the world's order; rendering is always reported enabled
        # (gazebo_ros_api_plugin.cpp:1114-1115, :1122)
        return GetWorldPropertiesResponse(self.world.now, list(self.world.models), True, True,
                                          "GetWorldProperties: got properties")

    def _model_properties(self, request):
        properties = self.world.model_properties(request.model_name)
        return GetModelPropertiesResponse(
            parent_model_name=properties.parent_model_name,
            canonical_body_name=properties.canonical_body_name,
            body_names=list(properties.body_names), geom_names=list(properties.geom_names),
            joint_names=list(properties.joint_names),
            child_model_names=list(properties.child_model_names),
            is_static=properties.is_static, success=True,
            status_message="GetModelProperties: got properties")

    def _get_link_state(self, request):
        ref = self.world.find_link(request.link_name)
        position, orientation = self.world.link_pose(ref)
        linear, angular = self.world.link_twist(ref)
        if request.reference_frame not in WORLD_FRAMES:
            position, orientation, linear, angular = _relative(
                position, orientation, linear, angular,
                self.world.frame_state(request.reference_frame))
        response = GetLinkStateResponse(success=True, status_message="GetLinkState: got state")
        response.link_state.link_name = request.link_name
        response.link_state.reference_frame = request.reference_frame
        _fill_pose(response.link_state.pose, position, orientation)
        _fill_twist(response.link_state.twist, linear, angular)
        return response

    def _set_link_state(self, request):
        state = request.link_state
        ref = self.world.find_link(state.link_name)
        position, orientation = _pose_parts(state.pose)
        # the pose and the twist are given in the reference frame's axes
        self.world.set_link_state(ref, *self.world.state_in_world(
            state.reference_frame, position, orientation, _vector(state.twist.linear),
            _vector(state.twist.angular)))
        return SetLinkStateResponse(True, "SetLinkState: success")

    def _get_joint_properties(self, request):
        properties = self.world.joint_properties(request.joint_name)
        # the joint's own type (Noetic answers REVOLUTE for every joint, :1152-1153) and
        # damping (Noetic leaves it empty, :1155-1156)
        return GetJointPropertiesResponse(
            type=JOINT_TYPES.get(properties.type, GetJointPropertiesResponse.REVOLUTE),
            damping=list(properties.damping), position=list(properties.position),
            rate=list(properties.rate), success=True,
            status_message="GetJointProperties: got properties")

    def _set_joint_properties(self, request):
        config = request.ode_joint_config
        self.world.set_joint_properties(request.joint_name, config.damping, config.loStop,
                                        config.hiStop, config.fmax, config.vel)
        # ODE's constraint settings, which pybullet's joints do not have
        ignored = [name for name in ODE_JOINT_ONLY if getattr(config, name)]
        if ignored:
            rospy.logwarn(f"SetJointProperties: {', '.join(ignored)} not applied to joint "
                          f"'{request.joint_name}' (the solver is pybullet's, not ODE); "
                          "damping, hiStop, loStop, fmax and vel are")
        return SetJointPropertiesResponse(True, "SetJointProperties: properties set")

    def _get_link_properties(self, request):
        properties = self.world.link_properties(request.link_name)
        ixx, ixy, ixz, iyy, iyz, izz = properties.inertia
        response = GetLinkPropertiesResponse(
            gravity_mode=properties.gravity_mode, mass=properties.mass, ixx=ixx, ixy=ixy,
            ixz=ixz, iyy=iyy, iyz=iyz, izz=izz, success=True,
            status_message="GetLinkProperties: got properties")
        # the centre of mass in the link's frame; its orientation the identity, as Noetic
        # (gazebo_ros_api_plugin.cpp:1218-1224)
        _fill_pose(response.com, properties.com, (0.0, 0.0, 0.0, 1.0))
        return response

    def _set_link_properties(self, request):
        # com's orientation is not read, as Noetic's (:1419-1420)
        self.world.set_link_properties(
            request.link_name, _vector(request.com.position), request.gravity_mode,
            request.mass, (request.ixx, request.ixy, request.ixz, request.iyy, request.iyz,
                           request.izz))
        return SetLinkPropertiesResponse(True, "SetLinkProperties: properties set")

    def _get_light_properties(self, request):
        light = self.world.light(request.light_name)
        # Noetic's success leaves status_message empty (:1340)
        return GetLightPropertiesResponse(
            diffuse=ColorRGBA(*light.diffuse), attenuation_constant=light.attenuation_constant,
            attenuation_linear=light.attenuation_linear,
            attenuation_quadratic=light.attenuation_quadratic, success=True)

    def _set_light_properties(self, request):
        position, orientation = _pose_parts(request.pose)
        self.world.set_light(request.light_name, request.cast_shadows,
                             _colour(request.diffuse), _colour(request.specular),
                             request.attenuation_constant, request.attenuation_linear,
                             request.attenuation_quadratic, _vector(request.direction),
                             position, orientation)
        return SetLightPropertiesResponse(success=True)  # no status_message (:1396)

    def _delete_light(self, request):
        self.world.delete_light(request.light_name)
        return DeleteLightResponse(True, f"DeleteLight: {request.light_name} successfully "
                                         "deleted")

    def _get_physics(self, _request):
        properties = self.world.physics_properties()
        response = GetPhysicsPropertiesResponse(
            time_step=properties.time_step, pause=properties.paused,
            max_update_rate=properties.max_update_rate, success=True,
            status_message="GetPhysicsProperties: got properties")
        response.gravity.x, response.gravity.y, response.gravity.z = properties.gravity
        for name, value in properties.ode.items():
            setattr(response.ode_config, name, value)
        return response

    def _set_physics(self, request):
        self.world.set_physics(request.time_step, request.max_update_rate,
                               _vector(request.gravity))
        self._pace_anchor = None
        # pybullet's solver is not ODE: its settings are reported, not taken
        reported = self.world.physics_properties().ode
        asked = {name: getattr(request.ode_config, name) for name in reported}
        if any(asked.values()) and asked != reported:
            rospy.logwarn("SetPhysicsProperties: ode_config is not applied (the solver is "
                          "pybullet's, not ODE); time_step, max_update_rate and gravity are")
        return SetPhysicsPropertiesResponse(True, "physics engine updated")

    def _apply_wrench(self, request):
        wrench = request.wrench
        ref = self.world.apply_wrench(
            request.body_name, _vector(wrench.force), _vector(wrench.torque),
            request.reference_frame, _vector(request.reference_point),
            request.start_time.to_nsec(), request.duration.to_nsec())
        return ApplyBodyWrenchResponse(True, f"ApplyBodyWrench: wrench on '{ref.scoped}' "
                                             "scheduled")

    def _clear_wrenches(self, request):
        try:
            self.world.clear_wrenches(request.body_name)
        except SimError as error:  # no answer fields: gazebo_ros answers, and so do we
            rospy.logwarn(f"ClearBodyWrenches: {error}")
        return BodyRequestResponse()

    def _apply_effort(self, request):
        model, joint = self.world.apply_joint_effort(
            request.joint_name, request.effort, request.start_time.to_nsec(),
            request.duration.to_nsec())
        return ApplyJointEffortResponse(True, f"ApplyJointEffort: effort set on "
                                              f"'{model}::{joint}'")

    def _clear_efforts(self, request):
        try:
            self.world.clear_joint_efforts(request.joint_name)
        except SimError as error:
            rospy.logwarn(f"ClearJointForces: {error}")
        return JointRequestResponse()

    def _pause(self, _request):
        self.world.paused = True
        return EmptyResponse()

    def _unpause(self, _request):
        self.world.paused = False
        self._pace_anchor = None
        return EmptyResponse()

    def _reset(self, _request):
        self.world.reset()
        self._pace_anchor = None
        return EmptyResponse()

    # --- the loop -------------------------------------------------------------------------
    def _publish_clock(self) -> None:
        self.clock.publish(self.world.now_ns)

    @staticmethod
    def _states_message(message_class, entries):
        """A ModelStates or LinkStates from (name, position, orientation, linear, angular)."""
        message = message_class()
        for name, position, orientation, linear, angular in entries:
            pose, twist = Pose(), Twist()
            _fill_pose(pose, position, orientation)
            _fill_twist(twist, linear, angular)
            message.name.append(name)
            message.pose.append(pose)
            message.twist.append(twist)
        return message

    def _pose_twist(self, name: str) -> Tuple[Pose, Twist]:
        pose, twist = Pose(), Twist()
        _fill_pose(pose, *self.world.pose(name))
        _fill_twist(twist, *self.world.twist(name))
        return pose, twist

    def _publish_model_states(self) -> None:
        """Static models' entries are built once per scene: they do not move, and 40 of
        them cost ~0.4 ms a message to rebuild."""
        if self._static_version != self.world.scene_version:
            self._static_entries = {name: self._pose_twist(name)
                                    for name, model in self.world.models.items()
                                    if model.kind == "static"}
            self._static_version = self.world.scene_version
        message = ModelStates()
        for name in self.world.models:
            pose, twist = self._static_entries.get(name) or self._pose_twist(name)
            message.name.append(name)
            message.pose.append(pose)
            message.twist.append(twist)
        self.model_states.publish(message)

    def _publish_link_states(self) -> None:
        self.link_states.publish(self._states_message(LinkStates, self.world.link_states()))

    def _publish_performance(self) -> None:
        """As gazebo_ros: only while someone listens (:579-598)."""
        if self.performance_metrics is None:
            return
        if not has_connections(self.performance_metrics):
            self.performance.restart()
            return
        message = self.performance.sample(self.world, time.monotonic())
        if message is not None:
            self.performance_metrics.publish(message)

    def _pace(self) -> None:
        """Sleeps so that simulated time runs at real_time_factor times the wall clock."""
        factor = self.world.real_time_factor
        if factor <= 0:
            return
        wall = time.monotonic()
        if self._pace_anchor is None:
            self._pace_anchor = (wall, self.world.now_ns)
        anchor_wall, anchor_ns = self._pace_anchor
        ahead = anchor_wall + (self.world.now_ns - anchor_ns) / 1e9 / factor - wall
        if ahead > PACE_BATCH:
            self.clock.flush()   # the steps' times out before the wait, not after
            time.sleep(ahead)
        elif ahead < -0.5:  # far behind (a slow spell): do not race to catch up
            self._pace_anchor = None

    def _batch_steps(self, step_ns: int) -> int:
        """How many steps the world may make before the loop looks again (World.advance):
        up to MAX_BATCH_STEPS, ending where /clock at its own rate is due, and where
        model_states or link_states are while someone listens to them (unheard, their
        times only move on), and paced, no more than PACE_BATCH of wall time's worth."""
        now_ns = self.world.now_ns

        def steps_until(due_ns: int) -> int:  # the first step ending at or after due_ns
            return max(1, -(-(due_ns - now_ns) // step_ns))

        steps = MAX_BATCH_STEPS
        factor = self.world.real_time_factor
        if factor > 0:
            steps = min(steps, max(1, int(PACE_BATCH * factor * 1e9) // step_ns))
        if self.clock_period_ns > step_ns:
            steps = min(steps, steps_until(self._next_clock_ns))
        if self._states_listened():
            steps = min(steps, steps_until(self._next_states_ns))
        return steps

    def _states_listened(self) -> bool:
        return bool(self.model_states and has_connections(self.model_states) or
                    self.link_states and has_connections(self.link_states))

    def run(self, stop: StopSignals) -> None:
        """Steps and publishes until rospy shuts down or ``stop`` is requested."""
        self._publish_clock()
        # the next /clock one period after this one (a subscriber already listening saw the
        # start, then the first step, 1 ms apart, at a 250 Hz pub_clock_frequency)
        self._next_clock_ns = self.world.now_ns + self.clock_period_ns
        last_paused_clock = 0.0
        # looked up once: the loop below runs at every step (each lookup is tens of ns of
        # the few microseconds the loop adds to the physics)
        world, physics, is_shutdown = self.world, self.physics, rospy.is_shutdown
        while not is_shutdown() and not stop.requested:
            physics.serve()
            if world.paused:
                now = time.monotonic()
                if now - last_paused_clock > PAUSED_CLOCK_PERIOD:
                    self._publish_clock()
                    last_paused_clock = now
                self._publish_performance()
                self.clock.flush()
                time.sleep(0.002)
                continue
            step_ns = world.step_ns
            made = world.advance(self._batch_steps(step_ns))
            now_ns = world.now_ns
            if self.clock_period_ns <= step_ns:  # every step (Gazebo's default): each one's
                self.clock.publish_steps(now_ns - (made - 1) * step_ns, step_ns, made)
            elif now_ns >= self._next_clock_ns:  # a batch ends at the clock's next time
                self._publish_clock()
                self._next_clock_ns = now_ns + self.clock_period_ns
            if now_ns >= self._next_states_ns:
                # as gazebo_ros: only when someone listens (41 poses cost ~0.4 ms)
                if self.model_states and has_connections(self.model_states):
                    self._publish_model_states()
                if self.link_states and has_connections(self.link_states):
                    self._publish_link_states()
                self._next_states_ns = now_ns + self.states_period_ns
            self._publish_performance()
            self._pace()


def build_world(config: Config, bus: Bus, system_plugins: Sequence[str] = (),
                argv: Sequence[str] = ()) -> World:
    gui = config.gui and display_available()
    if config.gui and not gui:
        rospy.logwarn("gui is true but no display answers (DISPLAY unset or unreachable); "
                      "running headless")
    world = World(bus, gui=gui, seed=config.seed, ray_threads=config.ray_threads)
    if system_plugins:  # before the world, as gzserver loads them
        world.native.load_system_plugins(list(system_plugins), list(argv))
    if config.world_name:
        world.load_world(load_world(config.world_name))
        rospy.loginfo(f"loaded world {config.world_name}: {len(world.models)} models, "
                      f"step {world.step_size * 1000:g} ms")
        for name in world.models:
            bus.debug(f"world model '{name}'")
    world.real_time_factor = config.real_time_factor
    world.paused = config.paused
    return world


def main(overrides: Optional[Dict[str, Any]] = None) -> None:
    """The simulator node; ``overrides`` take precedence over its parameters (gazebo_ros's
    gzserver passes what its command line says)."""
    refused = one_simulator.refusal(one_simulator.resolved_node_name("gazebo"))
    if refused:
        print(f"sim_bridge cannot start: {refused}", file=sys.stderr)
        raise SystemExit(ALREADY_RUNNING_STATUS)
    # rospy's signal handling off: see sim_bridge.stop_signals
    rospy.init_node("gazebo", disable_signals=True)
    # Gazebo C++ plugins get roscpp, under a node name of their own (sim_bridge.native_plugins)
    native_plugins.use_ros(native_plugins.ROS_NODE_NAME)
    batch_queued_writes()  # see sim_bridge.ros_publishing
    # rospy's writer and reader threads get the interpreter at least this often while the
    # loop steps (Python's default, 5 ms, is 100 ms of simulated time at 20x real time:
    # /clock and incoming commands arrived that late, and a flip commanded that late failed)
    sys.setswitchinterval(THREAD_SWITCH_INTERVAL)
    stop = StopSignals().install()
    physics = PhysicsThread()
    overrides = dict(overrides or {})
    # gzserver -s: Gazebo system plugins, and the command line they are given
    system_plugins, argv = overrides.pop("system_plugins", ((), []))
    try:
        config = Config.from_parameters(overrides)
        world = build_world(config, RosBus(physics, config.verbose), system_plugins, argv)
    except (ValueError, SdfError) as error:
        rospy.logfatal(f"sim_bridge cannot start: {error}")
        raise SystemExit(1) from None
    node = SimBridgeNode(config, world, physics)
    if config.enable_ros_network:
        node.advertise()
    else:
        node.advertise_clock()
        rospy.loginfo("enable_ros_network is false: no /gazebo services or topics")
    rospy.loginfo(f"sim_bridge ready (real_time_factor {config.real_time_factor:g}, "
                  f"{'paused' if world.paused else 'running'})")
    try:
        node.run(stop)
    finally:
        physics.close()
        shut_rospy_down(stop.reason or "the simulator stopped")
        world.close()

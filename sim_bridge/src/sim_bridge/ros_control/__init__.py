"""``libgazebo_ros_control.so``: ros_control's controller manager, emulated.

Plugin parameters as gazebo_ros_control's: ``robotNamespace`` (where the controller manager
and the controllers live; without it, the spawn request's namespace (spawn_model sends
"/" at the top level), and for a model spawned with none the model's name, as
gazebo_ros_control's default), ``controlPeriod`` (seconds; default the physics step),
``robotParam`` (accepted; the spawned model's own description is used; ``legacyModeNS``,
which only Kinetic's plugin read, is a verbose note: sim_bridge.plugins.RETIRED_TAGS),
``robotSimType`` (DefaultRobotHWSim's behaviour; another class is named in a warning),
``eStopTopic`` (a ``std_msgs/Bool`` in the robot's namespace: while true, effort and
velocity commands are 0 and position joints hold where they were when it came; on release
the running controllers are stopped and started again, gazebo_ros_control_plugin.cpp:155-159,
:222-251, :307-310, default_robot_hw_sim.cpp:287-300, :315, :359-375; controller_manager.cpp:
70-78).

Joints are the ones with a ``<transmission>`` (see :mod:`.hardware`; a robot with none gets a
controller manager with no joint, as Noetic's). Controllers are
configured on the parameter server, under ``<namespace>/<name>`` with a ``type``, and loaded,
started, stopped and unloaded through controller_manager's services under
``<namespace>/controller_manager/`` — what ``rosrun controller_manager spawner`` calls — which
also lists the types (``list_controller_types``) and reloads the libraries
(``reload_controller_libraries``: nothing to reload, but refused while controllers are loaded,
as controller_manager.cpp:642-692). Types: see ``CONTROLLER_TYPES``.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Dict

from controller_manager_msgs.msg import ControllerState, HardwareInterfaceResources
from std_msgs.msg import Bool
from controller_manager_msgs.srv import (ListControllers, ListControllersResponse,
                                         ListControllerTypes, ListControllerTypesResponse,
                                         LoadController, LoadControllerResponse,
                                         ReloadControllerLibraries,
                                         ReloadControllerLibrariesResponse, SwitchController,
                                         SwitchControllerResponse, UnloadController,
                                         UnloadControllerResponse)

from sim_bridge.plugins.base import Plugin, PluginError, Rate, resolve_topic
from sim_bridge.ros_control.ackermann_steering_controller import AckermannSteeringController
from sim_bridge.ros_control.diff_drive_controller import DiffDriveController
from sim_bridge.ros_control.hardware import RobotHardware
from sim_bridge.ros_control.joint_controllers import (EffortController, EffortPositionController,
                                                      EffortVelocityController,
                                                      GroupEffortController,
                                                      GroupEffortPositionController,
                                                      GroupPositionController,
                                                      GroupVelocityController,
                                                      PositionController, VelocityController,
                                                      VelocityPositionController)
from sim_bridge.ros_control.joint_state_controller import JointStateController
from sim_bridge.ros_control.trajectory_controller import (EffortTrajectoryController,
                                                          PositionTrajectoryController,
                                                          VelocityTrajectoryController)

CONTROLLER_TYPES = {
    "joint_state_controller/JointStateController": JointStateController,
    "position_controllers/JointTrajectoryController": PositionTrajectoryController,
    "velocity_controllers/JointTrajectoryController": VelocityTrajectoryController,
    "effort_controllers/JointTrajectoryController": EffortTrajectoryController,
    "position_controllers/JointPositionController": PositionController,
    "velocity_controllers/JointVelocityController": VelocityController,
    "velocity_controllers/JointPositionController": VelocityPositionController,
    "effort_controllers/JointEffortController": EffortController,
    "effort_controllers/JointPositionController": EffortPositionController,
    "effort_controllers/JointVelocityController": EffortVelocityController,
    "position_controllers/JointGroupPositionController": GroupPositionController,
    "velocity_controllers/JointGroupVelocityController": GroupVelocityController,
    "effort_controllers/JointGroupEffortController": GroupEffortController,
    "effort_controllers/JointGroupPositionController": GroupEffortPositionController,
    "diff_drive_controller/DiffDriveController": DiffDriveController,
    "ackermann_steering_controller/AckermannSteeringController": AckermannSteeringController,
}
# ros_controllers' types (noetic-devel 678b92a joint_trajectory_controller/
# joint_trajectory_controller_plugins.xml, src/joint_trajectory_controller.cpp:69-95) whose
# hardware interface DefaultRobotHWSim never registers (only the effort, position and velocity
# joint interfaces, gazebo_ros_control default_robot_hw_sim.cpp:153-186): under Gazebo they
# load and their initRequest fails (ros_control 633c374 controller_interface/controller.h
# :108-115), so the controller is not loaded
UNREGISTERED_INTERFACES = {
    "pos_vel_controllers/JointTrajectoryController": "hardware_interface::PosVelJointInterface",
    "pos_vel_acc_controllers/JointTrajectoryController":
        "hardware_interface::PosVelAccJointInterface",
}
# list_controllers' claimed_resources name an interface by its C++ type, demangled
# (controller_interface/controller.h:124, :136; hardware_interface/internal/demangle_symbol.h)
INTERFACE_NAMES = {"position": "hardware_interface::PositionJointInterface",
                   "velocity": "hardware_interface::VelocityJointInterface",
                   "effort": "hardware_interface::EffortJointInterface"}


@dataclass
class ControllerIO:
    """What a controller may use: the bus, and names resolved in the robot's namespace."""

    bus: object
    namespace: str
    robot: object

    def topic(self, name: str) -> str:
        return resolve_topic(self.namespace, name)

    def param_path(self, controller: str, key: str) -> str:
        return resolve_topic(self.namespace, f"{controller}/{key}")


# the one controller loader's base class: list_controller_types names it beside each type
# (ros_control noetic-devel 633c374 controller_manager/src/controller_manager.cpp:51-53,
# :707-715)
CONTROLLER_BASE_CLASS = "controller_interface::ControllerBase"

# gazebo_ros_control's own RobotHWSim, the one every robot file names
DEFAULT_SIM_TYPE = "gazebo_ros_control/DefaultRobotHWSim"


@dataclass
class Loaded:
    controller: object
    type: str
    state: str = "initialized"  # then "running" or "stopped", as controller_manager says


def _duration(seconds: float) -> str:
    """A period as ros::Duration prints it: seconds, a point, nine digits of nanoseconds."""
    nanoseconds = int(round(seconds * 1e9))
    return f"{nanoseconds // 1_000_000_000}.{nanoseconds % 1_000_000_000:09d}"


class RosControl(Plugin):
    # gazebo_ros_control's own default: the model's name (see Plugin); an empty tag is the
    # top level. A robot spawned by spawn_model at the top level has "/" from the spawn
    # request, so its controller manager is /controller_manager, as in Gazebo.
    ABSENT_NAMESPACE_IS_MODEL = True

    def __init__(self, context, spec):
        super().__init__(context, spec)
        transmissions = context.robot.model.transmissions
        if not transmissions:
            # Noetic's parseTransmissionsFromURDF takes none as a success (plugin:300-304) and
            # DefaultRobotHWSim registers no joint: the controller manager serves none
            context.bus.warn(f"plugin '{spec.name}' (libgazebo_ros_control.so): model "
                             f"'{context.model_name}' has no <transmission>: its controller "
                             "manager serves no joint")
        self.hardware = RobotHardware(context, transmissions, self.namespace)
        self.param("robotParam")  # the spawned model's own description is used
        sim_type = self.param("robotSimType", DEFAULT_SIM_TYPE)
        if sim_type.strip() != DEFAULT_SIM_TYPE:
            context.bus.warn(f"plugin '{spec.name}': robotSimType '{sim_type}' is not emulated; "
                             f"{DEFAULT_SIM_TYPE}'s behaviour is used")
        # the emergency stop (plugin:155-159, :307-310): set by the topic, acted on each step
        self.e_stop = False
        self._e_stopped_last_update = False
        e_stop_topic = self.param("eStopTopic")
        if e_stop_topic:
            context.bus.subscriber(self.topic(e_stop_topic.strip()), Bool, self._on_e_stop)
        period = self.number("controlPeriod", context.step_size)
        # plugin:126-141: a period shorter than the step is an error (the controllers update
        # every step), a longer one a warning (they update at that period)
        if self.param("controlPeriod") is not None and period != context.step_size:
            log = context.bus.warn
            how = "faster" if period < context.step_size else "slower"
            log(f"Desired controller update period ({_duration(period)} s) is {how} than the "
                f"gazebo simulation period ({_duration(context.step_size)} s).")
        self.rate = Rate(1.0 / period if period > context.step_size else 0.0)
        # last_update_sim_time_ros_ and last_write_sim_time_ros_ (plugin:220, :227, :256-257):
        # the controllers' period is the time since their last update and writeSim's the
        # time since the last write; both start at time 0, and Reset sets them back to it.
        # Gazebo advances its time before WorldUpdateBegin (gazebo-classic World.cc:813-815,
        # read on the elysia-best/gazebo-classic mirror): the plugin's time is the end of
        # the step that before_step starts
        self.step_ns = int(round(context.step_size * 1e9))
        self.last_update_ns = 0
        self.last_write_ns = 0
        self.io = ControllerIO(context.bus, self.namespace, context.robot)
        self.controllers: Dict[str, Loaded] = {}
        self.now_ns = 0
        bus = context.bus
        base = self.topic("controller_manager")
        self.services = [
            bus.service(f"{base}/load_controller", LoadController, self._load),
            bus.service(f"{base}/unload_controller", UnloadController, self._unload),
            bus.service(f"{base}/switch_controller", SwitchController, self._switch),
            bus.service(f"{base}/list_controllers", ListControllers, self._list),
            bus.service(f"{base}/list_controller_types", ListControllerTypes, self._list_types),
            bus.service(f"{base}/reload_controller_libraries", ReloadControllerLibraries,
                        self._reload_libraries),
        ]

    # --- controller_manager's services (run in the physics thread) ----------------------
    def _load(self, request) -> LoadControllerResponse:
        name = request.name
        if name in self.controllers:
            self.context.bus.warn(f"controller_manager: '{name}' is loaded already")
            return LoadControllerResponse(False)
        path = resolve_topic(self.namespace, name)
        params = self.context.bus.get_param(path, None)
        if not isinstance(params, dict) or "type" not in params:
            self.context.bus.warn(f"controller_manager: cannot load '{name}': no parameter "
                                  f"'{path}/type' (load the controllers' yaml first)")
            return LoadControllerResponse(False)
        controller_class = CONTROLLER_TYPES.get(params["type"])
        if params["type"] in UNREGISTERED_INTERFACES:
            self.context.bus.warn(
                f"controller_manager: cannot load '{name}': This controller requires a "
                f"hardware interface of type '{UNREGISTERED_INTERFACES[params['type']]}'. Make "
                "sure this is registered in the hardware_interface::RobotHW class. "
                "(gazebo_ros_control's DefaultRobotHWSim registers the effort, position and "
                "velocity joint interfaces only)")
            return LoadControllerResponse(False)
        if controller_class is None:
            self.context.bus.warn(f"controller_manager: cannot load '{name}': type "
                                  f"'{params['type']}' is not emulated; known types: "
                                  f"{', '.join(sorted(CONTROLLER_TYPES))}")
            return LoadControllerResponse(False)
        try:
            controller = controller_class(name, params, self.hardware, self.io)
        except PluginError as error:
            self.context.bus.warn(f"controller_manager: cannot load '{name}': {error}")
            return LoadControllerResponse(False)
        self.controllers[name] = Loaded(controller, params["type"])
        self.context.bus.info(f"controller_manager: loaded '{name}' ({params['type']})")
        return LoadControllerResponse(True)

    def _unload(self, request) -> UnloadControllerResponse:
        loaded = self.controllers.get(request.name)
        if loaded is None or loaded.state == "running":
            why = "not loaded" if loaded is None else "running (stop it first)"
            self.context.bus.warn(f"controller_manager: cannot unload '{request.name}': {why}")
            return UnloadControllerResponse(False)
        loaded.controller.close()
        del self.controllers[request.name]
        return UnloadControllerResponse(True)

    def _switch(self, request) -> SwitchControllerResponse:
        strict = request.strictness == SwitchController._request_class.STRICT
        unknown = [n for n in list(request.start_controllers) + list(request.stop_controllers)
                   if n not in self.controllers]
        if unknown and strict:
            self.context.bus.warn(f"controller_manager: cannot switch: not loaded: {unknown}")
            return SwitchControllerResponse(False)
        starting = [n for n in request.start_controllers if n in self.controllers]
        stopping = [n for n in request.stop_controllers if n in self.controllers]
        # a commanded joint may have one running controller only
        busy = {j: n for n, c in self.controllers.items()
                if c.state == "running" and n not in stopping and c.controller.interface
                for j in c.controller.joints}
        for name in starting:
            controller = self.controllers[name].controller
            clash = [j for j in controller.joints if controller.interface and j in busy
                     and busy[j] != name]
            if clash:
                self.context.bus.warn(f"controller_manager: '{name}' would command "
                                      f"{clash}, which '{busy[clash[0]]}' commands")
                if strict:
                    return SwitchControllerResponse(False)
                starting.remove(name)
        for name in stopping:
            if self.controllers[name].state == "running":
                self.controllers[name].controller.stop(self.now_ns)
                self.controllers[name].state = "stopped"
        self.hardware.read()
        for name in starting:
            if self.controllers[name].state != "running":
                self.controllers[name].controller.start(self.now_ns)
                self.controllers[name].state = "running"
        return SwitchControllerResponse(True)

    def _list(self, _request) -> ListControllersResponse:
        states = []
        for name, loaded in self.controllers.items():
            controller = loaded.controller
            claimed = [HardwareInterfaceResources(INTERFACE_NAMES[interface], joints)
                       for interface, joints in controller.claimed()]
            states.append(ControllerState(name, loaded.state, loaded.type, claimed))
        return ListControllersResponse(states)

    def _list_types(self, _request) -> ListControllerTypesResponse:
        """listControllerTypesSrv (CM:695-719): every type the loader declares (pluginlib's
        declared classes, by name), each with the loader's base class."""
        types = sorted(CONTROLLER_TYPES)
        return ListControllerTypesResponse(types, [CONTROLLER_BASE_CLASS] * len(types))

    def _reload_libraries(self, request) -> ReloadControllerLibrariesResponse:
        """reloadControllerLibrariesSrv (CM:642-692): refused while any controller is loaded,
        unless ``force_kill``, which stops and unloads them all first. The types are Python
        classes here: nothing else to reload."""
        if self.controllers and not request.force_kill:
            self.context.bus.warn(f"controller_manager: Cannot reload controller libraries "
                                  f"because there are still {len(self.controllers)} controllers "
                                  "running")
            return ReloadControllerLibrariesResponse(False)
        if self.controllers:
            self.context.bus.info("controller_manager: Killing all running controllers")
            for name, loaded in list(self.controllers.items()):
                if loaded.state == "running":
                    loaded.controller.stop(self.now_ns)
                loaded.controller.close()
                del self.controllers[name]
        return ReloadControllerLibrariesResponse(True)

    # --- the step ---------------------------------------------------------------------------
    def _on_e_stop(self, message) -> None:
        self.e_stop = bool(message.data)

    def before_step(self, now_ns: int) -> None:
        """Update (plugin:211-258): when the control period has elapsed, readSim and the
        controllers' update (the running ones stopped and started again first when the
        emergency stop was released since the last update, plugin:233-251, CM:70-78);
        every step, writeSim with the commands they last gave (a torque lasts one pybullet
        step, as Gazebo's SetForce does) or the emergency stop's. Each gets the time since
        it last ran as its period (plugin:220, :230, :251, :256)."""
        self.now_ns = now_ns
        e_stop = self.e_stop
        gazebo_ns = now_ns + self.step_ns
        if self.rate.due(now_ns):
            period = (gazebo_ns - self.last_update_ns) / 1e9
            self.last_update_ns = gazebo_ns
            self.hardware.read()
            released = self._e_stopped_last_update and not e_stop
            self._e_stopped_last_update = e_stop
            for loaded in self.controllers.values():
                if loaded.state == "running":
                    if released:
                        loaded.controller.stop(now_ns)
                        loaded.controller.start(now_ns)
                    loaded.controller.update(now_ns, period)
        write_period = (gazebo_ns - self.last_write_ns) / 1e9
        self.last_write_ns = gazebo_ns
        self.hardware.write(write_period, e_stop=e_stop)

    def reset(self, now_ns: int) -> None:
        """After reset_world, reset_simulation or new joint positions: as Noetic's Reset
        (plugin:261-266), only the timers start over: the next step updates the controllers,
        which go on running with their last commands (a position-controlled arm is driven
        back to where it was commanded), with the time since time 0 as their period, and
        the next write likewise (Noetic sets both last times to 0 "to not pass negative
        update periods"). Joints no running controller commands hold where they now are, as
        after the spawn."""
        self.now_ns = now_ns
        self.rate.reset(now_ns)
        self.last_update_ns = 0
        self.last_write_ns = 0
        commanded = [joint for loaded in self.controllers.values()
                     if loaded.state == "running" and loaded.controller.interface
                     for joint in loaded.controller.joints]
        self.hardware.hold(keep=commanded)

    def close(self) -> None:
        for loaded in self.controllers.values():
            loaded.controller.close()  # ends a running trajectory's goal, saying why
        super().close()

"""controller_manager's services beyond the four spawner uses, on pybullet.DIRECT:
``list_controller_types`` and ``reload_controller_libraries``.

Upstream: ros_control noetic-devel 633c374 controller_manager/src/controller_manager.cpp
("CM")."""
import pytest
from controller_manager_msgs.srv import (ListControllersRequest, ListControllerTypes,
                                         ListControllerTypesRequest, LoadControllerRequest,
                                         ReloadControllerLibraries,
                                         ReloadControllerLibrariesRequest)
from std_msgs.msg import Float64

from test_ros_control import MANAGER, angles, arm, start
from world_fixtures import run

BASE_CLASS = "controller_interface::ControllerBase"


def test_list_controller_types_names_every_emulated_type_with_its_base_class():
    """listControllerTypesSrv (CM:57, :695-719): the loader's declared classes, each with the
    loader's base class, controller_interface::ControllerBase (CM:51-53). The types listed
    are the ones load_controller takes; one that is not listed is refused. Before: no such
    service."""
    world, bus, model = arm()
    response = bus.services[f"{MANAGER}/list_controller_types"](ListControllerTypesRequest())
    assert response.base_classes == [BASE_CLASS] * len(response.types)
    assert response.types == sorted(response.types)
    for kind in ("joint_state_controller/JointStateController",
                 "position_controllers/JointTrajectoryController",
                 "effort_controllers/JointPositionController",
                 "velocity_controllers/JointPositionController",
                 "diff_drive_controller/DiffDriveController"):
        assert kind in response.types
    assert "pos_vel_controllers/JointTrajectoryController" not in response.types
    bus.params["/arm_bot/pos_vel"] = {"type": "pos_vel_controllers/JointTrajectoryController",
                                      "joints": ["pan", "lift"]}
    assert not bus.services[f"{MANAGER}/load_controller"](LoadControllerRequest("pos_vel")).ok
    world.close()


def listed(bus):
    return [c.name for c in bus.services[f"{MANAGER}/list_controllers"](
        ListControllersRequest()).controller]


def test_reload_controller_libraries_is_refused_while_controllers_are_loaded():
    """reloadControllerLibrariesSrv (CM:642-658): with a controller loaded (running or not)
    and no force_kill, ok is false, "Cannot reload controller libraries because there are
    still N controllers running", and the controllers go on: the finger still follows its
    command. Before: no such service."""
    world, bus, model = arm()
    start(bus, "finger_controller")
    assert bus.services[f"{MANAGER}/load_controller"](
        LoadControllerRequest("joint_state_controller")).ok
    reload = bus.services[f"{MANAGER}/reload_controller_libraries"]
    assert not reload(ReloadControllerLibrariesRequest(force_kill=False)).ok
    assert any("Cannot reload controller libraries because there are still 2 controllers "
               "running" in w for w in bus.warnings), bus.warnings
    assert listed(bus) == ["finger_controller", "joint_state_controller"]
    bus.subscriptions["/arm_bot/finger_controller/command"](Float64(0.02))
    run(world, 1.0)
    assert angles(model, "finger_joint")[0] == pytest.approx(0.02, abs=1e-3)
    world.close()


def test_reload_controller_libraries_with_force_kill_stops_and_unloads_every_controller():
    """force_kill: the running controllers are stopped and every controller unloaded
    (CM:660-679), then ok; a controller can be loaded again and commands the joint. Without
    controllers the reload is ok at once."""
    world, bus, model = arm()
    reload = bus.services[f"{MANAGER}/reload_controller_libraries"]
    assert reload(ReloadControllerLibrariesRequest(force_kill=False)).ok
    start(bus, "finger_controller")
    assert reload(ReloadControllerLibrariesRequest(force_kill=True)).ok
    assert listed(bus) == []
    assert "/arm_bot/finger_controller/command" in bus.closed  # its subscriber is gone
    start(bus, "finger_controller")
    bus.subscriptions["/arm_bot/finger_controller/command"](Float64(0.015))
    run(world, 1.0)
    assert angles(model, "finger_joint")[0] == pytest.approx(0.015, abs=1e-3)
    world.close()


def test_the_services_have_controller_manager_msgs_layouts():
    """compat's controller_manager_msgs/ListControllerTypes and ReloadControllerLibraries
    are ros_control's (md5sums of controller_manager_msgs/srv/*.srv at 633c374)."""
    assert ListControllerTypes._md5sum == "c1d4cd11aefa9f97ba4aeb5b33987f4e"
    assert ReloadControllerLibraries._md5sum == "40e8c411fd1797d2e2c486018f846040"

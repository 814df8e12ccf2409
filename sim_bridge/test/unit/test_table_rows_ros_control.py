"""The rows of doc/ros_control.md that say what sim_bridge does not emulate and had no test:
control_toolbox's Pid ``publish_state`` and DiffDriveController's dynamic_reconfigure
server. Each checks that nothing is offered for them (issue 30: a test per row that can
fail, here if they come to be offered without their rows changing)."""
from test_ros_control import arm, start
from test_ros_control_diff_drive import CONTROLLER, diff_bot
from world_fixtures import run

PID_NAMESPACES = ("/arm_bot/effort_group_controller/pan/pid",
                  "/arm_bot/effort_group_controller/lift/pid")


def test_a_pids_publish_state_is_not_read():
    """control_toolbox's Pid advertises <pid ns>/state (control_msgs/PidState) when
    publish_state is true (control_toolbox noetic-devel de05a5c src/pid.cpp:141-147):
    not read here; the controller loads and runs, and nothing goes out under its gains."""
    pid = {"p": 40.0, "i": 0.0, "d": 2.0, "publish_state": True}
    world, bus, _ = arm("EffortJointInterface", params={"effort_group_controller": {
        "type": "effort_controllers/JointGroupPositionController", "joints": ["pan", "lift"],
        "pan": {"pid": pid}, "lift": {"pid": pid}}})
    start(bus, "effort_group_controller")
    run(world, 0.05)
    assert not [t for t in bus.advertised if t.startswith(PID_NAMESPACES)]
    world.close()


def test_the_diff_drive_controllers_dynamic_reconfigure_is_not_offered():
    """DiffDriveController starts a dynamic_reconfigure server in its namespace
    (ros_controllers noetic-devel 678b92a diff_drive_controller/src/
    diff_drive_controller.cpp:358-386): not emulated, so no set_parameters service and no
    parameter_descriptions or parameter_updates topics."""
    world, bus, _ = diff_bot()
    under = [name for name in list(bus.services) + bus.advertised
             if name.startswith(CONTROLLER + "/")]
    assert under and not [name for name in under if "parameter" in name]
    world.close()

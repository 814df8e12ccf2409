"""xs_sdk_sim's motors, tick by tick, on the px100's own motor config and modes
(interbotix_xsarm_control/config): what upstream's xs_sdk_sim does with each command
(interbotix_ros_core noetic 172841f, interbotix_xs_sdk/scripts/xs_sdk_sim: 20 Hz l. 19;
the 300 ms threshold l. 21; round(ms / 1000 * 20 + 1) waypoints l. 209-213; command / 20
and command / 2000 a tick l. 457-466; the linkage l. 219-236), and the driver's refusals
(src/xs_sdk_obj.cpp l. 71, 73, 146, 239)."""
import math
import os

import pytest
import rospkg

from xs_sdk_emulation import configs
from xs_sdk_emulation.gripper_linkage import finger_distance, horn_angle
from xs_sdk_emulation.simulated_motors import TIMER_HZ, CommandError, SimulatedMotors

CONTROL = rospkg.RosPack().get_path("interbotix_xsarm_control")
ARM = ["waist", "shoulder", "elbow", "wrist_angle"]


@pytest.fixture
def config():
    return configs.read(os.path.join(CONTROL, "config", "px100.yaml"),
                        os.path.join(CONTROL, "config", "modes.yaml"))


@pytest.fixture
def motors(config):
    return SimulatedMotors(config)


def positions(motors, names):
    got_names, values = motors.tick()
    return [values[got_names.index(n)] for n in names]


def test_joints_start_at_their_sleep_positions_fingers_after_the_motors(motors):
    names, values = motors.tick()
    assert names == ARM + ["gripper", "left_finger", "right_finger"]
    assert values[:5] == [0, -1.88, 1.5, 0.8, 0]
    # horn 14 mm, arm 24 mm at angle 0: sqrt(24^2 - 14^2) mm from the horn's centre
    assert values[5] == pytest.approx(math.sqrt(0.024 ** 2 - 0.014 ** 2))
    assert values[6] == -values[5]


def test_a_group_command_takes_the_profiles_moving_time_in_even_steps(motors):
    """modes.yaml: the arm's time profile is 2000 ms: 41 waypoints, one a 20 Hz tick, from
    where the joint is (the first tick holds it) to the goal at tick 41 = 2.0 s."""
    motors.write_group("arm", [0.5, 0.0, 0.0, 0.0])
    waist = [positions(motors, ["waist"])[0] for _ in range(41)]
    assert waist[0] == pytest.approx(0.0)
    assert waist[20] == pytest.approx(0.25)
    assert waist[39] < 0.5 and waist[40] == pytest.approx(0.5)
    assert len(waist) / TIMER_HZ == pytest.approx(2.05)
    assert positions(motors, ["waist"]) == pytest.approx([0.5])


def test_a_moving_time_of_300_ms_or_less_is_one_tick(motors):
    motors.set_register("group", "arm", "Profile_Velocity", 300)
    motors.write_joint("elbow", -0.4)
    assert positions(motors, ["elbow"]) == pytest.approx([-0.4])


def test_the_profile_registers_read_back_per_joint(motors):
    motors.set_register("group", "arm", "Profile_Velocity", 1500)
    assert motors.get_register("group", "arm", "Profile_Velocity") == [1500] * 4
    assert motors.get_register("single", "waist", "Profile_Acceleration") == [300]
    # other registers are accepted and mean nothing without motors, as upstream's
    motors.set_register("single", "waist", "Position_P_Gain", 800)
    assert motors.get_register("single", "waist", "Position_P_Gain") == []


def test_the_gripper_in_pwm_mode_turns_command_over_2000_a_tick_until_told_0(motors):
    motors.write_joint("gripper", 250)
    for tick in range(1, 4):
        gripper, left, right = positions(motors, ["gripper", "left_finger", "right_finger"])
        assert gripper == pytest.approx(tick * 250 / 2000)
        assert left == pytest.approx(finger_distance(gripper, 0.014, 0.024)) and right == -left
    motors.write_joint("gripper", 0)
    held = positions(motors, ["gripper"])
    assert positions(motors, ["gripper"]) == held


def test_velocity_and_linear_position_modes(motors):
    motors.set_operating_modes("single", "waist", "velocity", "velocity", 0, 0)
    motors.write_joint("waist", 1.0)
    assert positions(motors, ["waist"]) == pytest.approx([1.0 / TIMER_HZ])
    motors.set_operating_modes("single", "gripper", "linear_position", "time", 0, 0)
    motors.write_joint("gripper", 0.06)
    gripper, left = positions(motors, ["gripper", "left_finger"])
    assert left == pytest.approx(0.03)
    assert gripper == pytest.approx(horn_angle(0.06, 0.014, 0.024))
    assert finger_distance(gripper, 0.014, 0.024) == pytest.approx(0.03)


def test_robot_info_answers_as_the_driver(motors):
    limits = {"waist": (-3.14, 3.14, 3.14), "shoulder": (-1.9, 1.8, 3.14),
              "elbow": (-2.1, 1.6, 3.14), "wrist_angle": (-1.7, 2.1, 3.14),
              "left_finger": (0.015, 0.037, 1.0)}
    arm = motors.robot_info("group", "arm", limits)
    assert (arm["mode"], arm["profile_type"], arm["num_joints"]) == ("position", "time", 4)
    assert arm["joint_names"] == ARM and arm["joint_ids"] == [1, 2, 3, 4]
    assert arm["joint_sleep_positions"] == [0, -1.88, 1.5, 0.8]
    assert arm["joint_state_indices"] == [0, 1, 2, 3] and arm["name"] == ["arm"]
    gripper = motors.robot_info("single", "gripper", limits)
    # the gripper answers for its left finger
    assert gripper["mode"] == "pwm" and gripper["joint_names"] == ["left_finger"]
    assert gripper["joint_state_indices"] == [5]
    assert gripper["joint_lower_limits"] == [0.015] and gripper["joint_upper_limits"] == [0.037]
    assert motors.robot_info("group", "all", None)["name"] == ["all", "arm"]


@pytest.mark.parametrize("call, words", [
    (lambda m: m.write_group("arm", [0.1, 0.2]),
     "Number of commands (2) does not match the number of joints in group 'arm' (4)"),
    (lambda m: m.write_group("legs", [0.1]), "The 'legs' joint/group does not exist"),
    (lambda m: m.write_joint("wrist_rotate", 0.1), "The 'wrist_rotate' joint/group does not"),
    (lambda m: m.write_joint("waist", float("nan")), "a command for 'waist' is not finite"),
    (lambda m: m.robot_info("sngle", "waist", None), "Invalid command for argument 'cmd_type'"),
    (lambda m: m.set_operating_modes("group", "arm", "torque", "time", 0, 0),
     "Invalid command for argument 'mode' ('torque')"),
])
def test_bad_commands_are_refused_naming_why_and_nothing_moves(motors, call, words):
    before = motors.tick()
    with pytest.raises(CommandError, match=words.replace("(", r"\(").replace(")", r"\)")):
        call(motors)
    assert motors.tick() == before


def test_a_broken_motor_config_is_named(tmp_path):
    broken = tmp_path / "px100.yaml"
    broken.write_text("joint_order: [waist, shoulder]\nsleep_positions: [0]\n"
                      "joint_state_publisher: {topic_name: joint_states}\n"
                      "motors: {waist: {ID: 1}, shoulder: {ID: 2}}\n")
    with pytest.raises(configs.ConfigError, match="Length of joint_order list \\(2\\) does not "
                                                  "match length of sleep_positions list \\(1\\)"):
        configs.read(str(broken), str(tmp_path / "none.yaml"))
    with pytest.raises(configs.ConfigError, match="was not found"):
        configs.read(str(tmp_path / "missing.yaml"), "")


def test_on_the_simulated_arm_the_fingers_stop_at_their_limits(config):
    """With the fingers' limits (the simulator's end stops) a PWM command holds them at the
    limit instead of turning the horn on past it (where the linkage would close them again)."""
    motors = SimulatedMotors(config, finger_limits={"left_finger": (0.015, 0.037)})
    motors.write_joint("gripper", 250)
    for _ in range(40):
        left, right = positions(motors, ["left_finger", "right_finger"])
        assert 0.015 <= left <= 0.037 and right == -left
    assert left == pytest.approx(0.037)
    motors.write_joint("gripper", -250)
    for _ in range(40):
        left = positions(motors, ["left_finger"])[0]
    assert left == pytest.approx(0.015)
    # without the limits (upstream's simulated driver) the horn turns on
    free = SimulatedMotors(config)
    free.write_joint("gripper", 250)
    fingers = [positions(free, ["left_finger"])[0] for _ in range(40)]
    assert max(fingers) > 0.037 and fingers[-1] < max(fingers)

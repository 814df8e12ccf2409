"""interbotix_xs_msgs' definitions have upstream's md5sums (Interbotix/interbotix_ros_core
noetic 172841f, interbotix_ros_xseries/interbotix_xs_msgs), so Interbotix's own nodes and
scripts built against the real package talk to the driver here."""
import importlib
import os

# computed by genmsg from upstream's msg/ and srv/ files at that commit
UPSTREAM = {
    "JointGroupCommand": "fa54c229b7238fc905e59a51a526f379",
    "JointSingleCommand": "79b74399c9cdcc4c0be32d540424ed2e",
    "JointTemps": "2c3b043513eb09ccdff55ab4d97383c3",
    "JointTrajectoryCommand": "039c1a8f9200d555267cf39243b5e969",
    "MotorGains": "7c362297bf8bae149936ba71305f3900",
    "OperatingModes": "cb68bef3d517c840b0a5cc0f73d64e36",
    "Reboot": "229067e7bfb48bf403b702d5f7f1ee93",
    "RegisterValues": "27940ff80d633a7a6df113cf798c0f70",
    "RobotInfo": "873f2223b25122251d4d3641d8411cf6",
    "TorqueEnable": "023452ade9f3d4979c75bd4e0d60f0c9",
}


def generated_md5sums(package: str, folder: str):
    found = {}
    for kind in ("msg", "srv"):
        module = importlib.import_module(f"{package}.{kind}")
        for file_name in sorted(os.listdir(os.path.join(folder, kind))):
            name = file_name[:-len(kind) - 1]
            found[name] = getattr(module, name)._md5sum  # pylint: disable=protected-access
    return found


def test_every_definition_has_upstreams_md5sum():
    here = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    assert generated_md5sums("interbotix_xs_msgs", here) == UPSTREAM


def test_robot_info_answers_in_upstreams_field_order():
    from interbotix_xs_msgs.srv import RobotInfoResponse
    assert RobotInfoResponse.__slots__ == [
        "mode", "profile_type", "joint_names", "joint_ids", "joint_lower_limits",
        "joint_upper_limits", "joint_velocity_limits", "joint_sleep_positions",
        "joint_state_indices", "num_joints", "name"]

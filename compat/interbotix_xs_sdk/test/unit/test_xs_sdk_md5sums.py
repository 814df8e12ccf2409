"""interbotix_xs_sdk's own definitions, as the driver had them before interbotix_xs_msgs
(Interbotix/interbotix_ros_core b9b20da, 2021-11-05, interbotix_ros_xseries/interbotix_xs_sdk):
md5sums equal upstream's. All but RobotInfo equal interbotix_xs_msgs' (its answer gained a
'name' field), so scripts of either time reach the same driver's topics."""
import interbotix_xs_sdk.msg
import interbotix_xs_sdk.srv

UPSTREAM = {
    "JointGroupCommand": "fa54c229b7238fc905e59a51a526f379",
    "JointSingleCommand": "79b74399c9cdcc4c0be32d540424ed2e",
    "JointTrajectoryCommand": "039c1a8f9200d555267cf39243b5e969",
    "MotorGains": "7c362297bf8bae149936ba71305f3900",
    "OperatingModes": "cb68bef3d517c840b0a5cc0f73d64e36",
    "Reboot": "229067e7bfb48bf403b702d5f7f1ee93",
    "RegisterValues": "27940ff80d633a7a6df113cf798c0f70",
    "RobotInfo": "7a389566d99903aa71839d0052c9a055",
    "TorqueEnable": "023452ade9f3d4979c75bd4e0d60f0c9",
}


def test_every_definition_has_upstreams_md5sum():
    """Every class genpy generated for the package, against upstream's."""
    generated = {name: kind._md5sum  # pylint: disable=protected-access
                 for module in (interbotix_xs_sdk.msg, interbotix_xs_sdk.srv)
                 for name, kind in vars(module).items()
                 if hasattr(kind, "_md5sum") and not name.endswith(("Request", "Response"))}
    assert generated == UPSTREAM


def test_the_drivers_topics_take_either_packages_commands():
    import interbotix_xs_msgs.msg
    for name in ("JointGroupCommand", "JointSingleCommand", "JointTrajectoryCommand"):
        assert (getattr(interbotix_xs_sdk.msg, name)._md5sum  # pylint: disable=protected-access
                == getattr(interbotix_xs_msgs.msg, name)._md5sum)  # pylint: disable=protected-access

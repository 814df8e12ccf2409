"""turtlesim's messages and services have upstream's md5sums (turtlesim 0.10.2, ros_tutorials
noetic-devel db63288), so nodes built against the real turtlesim talk to this one."""
import importlib
import os

# computed by genmsg from upstream's turtlesim/msg/*.msg and turtlesim/srv/*.srv
# (what `rosmsg md5 turtlesim/Pose` answers on a ROS noetic machine)
MESSAGES = {
    "Color": "353891e354491c51aabe32df673fb446",
    "Pose": "863b248d5016ca62ea2e895ae5265cf9",
}
SERVICES = {
    "Kill": "c1f3d28f1b044c871e6eff2e9fc3c667",
    "SetPen": "9f452acce566bf0c0954594f69a8e41b",
    "Spawn": "0b2d2e872a8e2887d5ed626f2bf2c561",
    "TeleportAbsolute": "a130bc60ee6513855dc62ea83fcc5b20",
    "TeleportRelative": "9d5c2dcd348ac8f76ce2a4307bd63a13",
}


def test_every_definition_has_upstreams_md5sum():
    """Each file in msg/ and srv/, as generated, against upstream's md5sum (a definition
    added here without one, or one missing, shows in the difference)."""
    package = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    generated = {}
    for kind in ("msg", "srv"):
        module = importlib.import_module(f"turtlesim.{kind}")
        for file_name in sorted(os.listdir(os.path.join(package, kind))):
            name = file_name[:-len(kind) - 1]
            generated[name] = getattr(module, name)._md5sum
    assert generated == {**MESSAGES, **SERVICES}


def test_field_order_and_types_as_upstream():
    from turtlesim.msg import Pose
    from turtlesim.srv import SetPenRequest, SpawnRequest
    assert Pose.__slots__ == ["x", "y", "theta", "linear_velocity", "angular_velocity"]
    assert Pose._slot_types == ["float32"] * 5
    assert SetPenRequest._slot_types == ["uint8"] * 5
    assert SpawnRequest.__slots__ == ["x", "y", "theta", "name"]

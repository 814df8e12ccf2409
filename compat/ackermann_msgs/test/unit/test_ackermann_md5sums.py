"""ackermann_msgs: both messages have upstream's md5sums (ros-drivers/ackermann_msgs 1.0.2,
Noetic's release, master 843a483), so drivers and controllers built against the real package
(ackermann_steering_controller's users, Hunter 2's and LIMO's nodes) talk to this one."""
import importlib
import os

import pytest

# computed by genmsg from upstream's msg/*.msg at 843a483 (std_msgs/Header from Debian's
# std_msgs); AckermannDriveStamped's is the one `rostopic info` shows on any Noetic machine
MESSAGES = {
    "AckermannDrive": "3512e91b48d69674a0e86fadf1ea8231",
    "AckermannDriveStamped": "1fd5d7f58889cefd44d29f6653240d0c",
}


@pytest.mark.parametrize("name", sorted(MESSAGES))
def test_message_md5sum_equals_upstream(name):
    message = getattr(importlib.import_module("ackermann_msgs.msg"), name)
    assert message._md5sum == MESSAGES[name]


def test_every_definition_is_checked():
    package = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    defined = {name[:-len(".msg")] for name in os.listdir(os.path.join(package, "msg"))}
    assert defined == set(MESSAGES)

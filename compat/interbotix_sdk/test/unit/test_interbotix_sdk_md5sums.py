"""The 2020 SDK's definitions (Interbotix/interbotix_ros_arms cb9f5fe, interbotix_sdk/msg and
srv) with upstream's md5sums, computed by genmsg from those files."""
import interbotix_sdk.msg
import interbotix_sdk.srv

UPSTREAM = {
    "JointCommands": "306931a8f4b928ea86b21d23c7e4f90e",
    "SingleCommand": "6d45868a3dac16da3c97708e8cdbf2c6",
    "FirmwareGains": "1a3c17ff4352d3a3bf5d6c64d4bd58a6",
    "OperatingModes": "585951edcc6006e2034f68a456aad669",
    "RegisterValues": "c4b094ee6f4751519e444f39591c55e1",
    "RobotInfo": "8cbf67af7802be3e000262518104df12",
}


def test_every_definition_has_upstreams_md5sum():
    generated = {name: kind._md5sum  # pylint: disable=protected-access
                 for module in (interbotix_sdk.msg, interbotix_sdk.srv)
                 for name, kind in vars(module).items()
                 if hasattr(kind, "_md5sum") and not name.endswith(("Request", "Response"))}
    assert generated == UPSTREAM


def test_the_constants_are_upstreams():
    from interbotix_sdk.srv import OperatingModesRequest, RegisterValuesRequest
    assert (OperatingModesRequest.ARM_JOINTS_AND_GRIPPER, OperatingModesRequest.ARM_JOINTS,
            OperatingModesRequest.GRIPPER, OperatingModesRequest.SINGLE_JOINT) == (1, 2, 3, 4)
    assert RegisterValuesRequest.SINGLE_MOTOR == 4

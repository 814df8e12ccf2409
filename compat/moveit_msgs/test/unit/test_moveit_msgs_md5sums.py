"""moveit_msgs, and the two packages it builds on that Debian lacks (octomap_msgs,
object_recognition_msgs): every message, service and action message has upstream's md5sum,
so moveit_commander scripts and nodes built against the real packages talk to ours and the
other way round."""
import importlib

import pytest

# md5sums of upstream's definitions, computed by genmsg (actions expanded by actionlib_msgs'
# genaction) from moveit_msgs 0.11.4 (master, 9756797), octomap_msgs 0.3.5 (master, dcaaf62)
# and object_recognition_msgs 0.4.1 (noetic-devel, d55acd8)
UPSTREAM = {
    "moveit_msgs/AllowedCollisionEntry": "90d1ae1850840724bb043562fe3285fc",
    "moveit_msgs/AllowedCollisionMatrix": "aedce13587eef0d79165a075659c1879",
    "moveit_msgs/ApplyPlanningScene": "d4d1599e0b6f71a6a8a10cb34780619c",
    "moveit_msgs/AttachedCollisionObject": "30199ef516f64c8bc1edb1084ce4584e",
    "moveit_msgs/BoundingVolume": "22db94010f39e9198032cb4a1aeda26e",
    "moveit_msgs/CartesianPoint": "d3c213cdb4382c43adbff1f2dd2cf669",
    "moveit_msgs/CartesianTrajectory": "4886769850ce858fcceba546fd5c793b",
    "moveit_msgs/CartesianTrajectoryPoint": "e996ea294f646e6911b3e85e624f5acf",
    "moveit_msgs/ChangeControlDimensions": "35b43a24f32e4654e4afa7596399fc3c",
    "moveit_msgs/ChangeDriftDimensions": "0d34c8d563fea2efff65829c37132a15",
    "moveit_msgs/CheckIfRobotStateExistsInWarehouse": "3b47364b81dd44f643fa67c9cd127486",
    "moveit_msgs/CollisionObject": "dbba710596087da521c07564160dfccb",
    "moveit_msgs/ConstraintEvalResult": "093643083d24f6488cb5a868bd47c090",
    "moveit_msgs/Constraints": "cfd22a10c51e0dc2b28d98772d2b55d5",
    "moveit_msgs/ContactInformation": "116228ca08b0c286ec5ca32a50fdc17b",
    "moveit_msgs/CostSource": "abb7e013237dacaaa8b97e704102f908",
    "moveit_msgs/DeleteRobotStateFromWarehouse": "dab44354403f811c40b84964e068219c",
    "moveit_msgs/DisplayRobotState": "61c4e677a6fbbc83f0d5d9df2be85e3c",
    "moveit_msgs/DisplayTrajectory": "41936b74e168ba754279ae683ce3f121",
    "moveit_msgs/ExecuteKnownTrajectory": "af7da309bb25223035a7cfa762b8d4cd",
    "moveit_msgs/ExecuteTrajectoryAction": "add56f6df2e6f2ee8830e030d0953807",
    "moveit_msgs/ExecuteTrajectoryActionFeedback": "12232ef97486c7962f264c105aae2958",
    "moveit_msgs/ExecuteTrajectoryActionGoal": "36f350977c67bc94e8cd408452bad0f0",
    "moveit_msgs/ExecuteTrajectoryActionResult": "2a052ef9772722c8338e057a61e60639",
    "moveit_msgs/ExecuteTrajectoryFeedback": "af6d3a99f0fbeb66d3248fa4b3e675fb",
    "moveit_msgs/ExecuteTrajectoryGoal": "054c09e62210d7faad2f9fffdad07b57",
    "moveit_msgs/ExecuteTrajectoryResult": "6a39f41e4bc445a437e9a0cabdd5ef5c",
    "moveit_msgs/GenericTrajectory": "d68b5c73072efa2012238a77e49c2c58",
    "moveit_msgs/GetCartesianPath": "c54b9430d97ea6816e0f7c7ffd3779b8",
    "moveit_msgs/GetMotionPlan": "110dffa73f82b9b8644f525e7fbd9fc4",
    "moveit_msgs/GetMotionSequence": "243a84075af66e089234ba5a76e27602",
    "moveit_msgs/GetPlannerParams": "1b56b530c1107c60f0c9173e631d7bf5",
    "moveit_msgs/GetPlanningScene": "65cf69d3e7a0342e16374024d4eeef65",
    "moveit_msgs/GetPositionFK": "640cee2210976d68ab32b7aac3c1858e",
    "moveit_msgs/GetPositionIK": "efb729a4de517c3ff2c8a1e540017b30",
    "moveit_msgs/GetRobotStateFromWarehouse": "5daf0b8853a0f1d96bf6cfb173c42a3d",
    "moveit_msgs/GetStateValidity": "06ea62db671e4dbf878eaca241db51ad",
    "moveit_msgs/Grasp": "e26c8fb64f589c33c5d5e54bd7b5e4cb",
    "moveit_msgs/GraspPlanning": "070c8271d3c801e18f8ccc63ac094cd1",
    "moveit_msgs/GripperTranslation": "b53bc0ad0f717cdec3b0e42dec300121",
    "moveit_msgs/JointConstraint": "c02a15146bec0ce13564807805b008f0",
    "moveit_msgs/JointLimits": "8ca618c7329ea46142cbc864a2efe856",
    "moveit_msgs/KinematicSolverInfo": "cc048557c0f9795c392dd80f8bb00489",
    "moveit_msgs/LinkPadding": "b3ea75670df55c696fedee97774d5947",
    "moveit_msgs/LinkScale": "19faf226446bfb2f645a4da6f2a56166",
    "moveit_msgs/ListRobotStatesInWarehouse": "dc02fa289e68670e9d392985a0235ee6",
    "moveit_msgs/LoadMap": "93a4bc4c60dc17e2a69e3fcaaa25d69d",
    "moveit_msgs/MotionPlanDetailedResponse": "af67c260a61067b3866c6bbc624021cc",
    "moveit_msgs/MotionPlanRequest": "83f3d7b1d47a538f7659e0de9dae7980",
    "moveit_msgs/MotionPlanResponse": "a70717537b7bfcf24e0dbd4d2ab1fd34",
    "moveit_msgs/MotionSequenceItem": "605a152161827d49a0abacf6c6544d1e",
    "moveit_msgs/MotionSequenceRequest": "5a79e4928bfada4fbc57882982ac6e58",
    "moveit_msgs/MotionSequenceResponse": "6c3d81f7909577545c3c382f38a163e2",
    "moveit_msgs/MoveGroupAction": "33225407c32b189345eec6893a5a0da3",
    "moveit_msgs/MoveGroupActionFeedback": "12232ef97486c7962f264c105aae2958",
    "moveit_msgs/MoveGroupActionGoal": "b7138704cefd43a8dd9758d697350b85",
    "moveit_msgs/MoveGroupActionResult": "7f1341e9f8cc6a2ed67dc4bd2603cf59",
    "moveit_msgs/MoveGroupFeedback": "af6d3a99f0fbeb66d3248fa4b3e675fb",
    "moveit_msgs/MoveGroupGoal": "ce7f9820670af166b2faa14c475891b0",
    "moveit_msgs/MoveGroupResult": "ac331f62a649edf9d73f5f8b656cec65",
    "moveit_msgs/MoveGroupSequenceAction": "0d3375f4fb59ed3ba86fa746e5d8e219",
    "moveit_msgs/MoveGroupSequenceActionFeedback": "12232ef97486c7962f264c105aae2958",
    "moveit_msgs/MoveGroupSequenceActionGoal": "d7913633827d440f696e171ce1c63e4a",
    "moveit_msgs/MoveGroupSequenceActionResult": "fcc171c506bf19ef72745d79ea2511bc",
    "moveit_msgs/MoveGroupSequenceFeedback": "af6d3a99f0fbeb66d3248fa4b3e675fb",
    "moveit_msgs/MoveGroupSequenceGoal": "18fa4c5968e8aa606b4722c12ab25cca",
    "moveit_msgs/MoveGroupSequenceResult": "3e3d83067566e443fa885c9428941f17",
    "moveit_msgs/MoveItErrorCodes": "d6cfe51b76ea17850d7116c666a7d0f1",
    "moveit_msgs/ObjectColor": "ec3bd6f103430e64b2ae706a67d8488e",
    "moveit_msgs/OrientationConstraint": "183479d9281e5b4f23dc584f711d8a64",
    "moveit_msgs/OrientedBoundingBox": "da3bd98e7cb14efa4141367a9d886ee7",
    "moveit_msgs/PickupAction": "8ade6f7e811da205c80db4348b91b199",
    "moveit_msgs/PickupActionFeedback": "12232ef97486c7962f264c105aae2958",
    "moveit_msgs/PickupActionGoal": "83bb430d120a16fadf2ea3aad239f1d1",
    "moveit_msgs/PickupActionResult": "189540b296d28419d294a1ba0f5dde17",
    "moveit_msgs/PickupFeedback": "af6d3a99f0fbeb66d3248fa4b3e675fb",
    "moveit_msgs/PickupGoal": "3a71f6f9bc6e640594ce6a411ccfe764",
    "moveit_msgs/PickupResult": "703f433082edbf20e2dc7aa026df9abf",
    "moveit_msgs/PlaceAction": "a251d4a0c56193b6e1b76a1ca20de499",
    "moveit_msgs/PlaceActionFeedback": "12232ef97486c7962f264c105aae2958",
    "moveit_msgs/PlaceActionGoal": "3f3419319ea8d2af4e18a600962d0cf5",
    "moveit_msgs/PlaceActionResult": "4fbc563d1316531e4a08f29bf6b7ba2c",
    "moveit_msgs/PlaceFeedback": "af6d3a99f0fbeb66d3248fa4b3e675fb",
    "moveit_msgs/PlaceGoal": "b5ff24625cebec440c18cd2e1d833764",
    "moveit_msgs/PlaceLocation": "7b53f032c68481686026c3e9223d0713",
    "moveit_msgs/PlaceResult": "7f9bf644e9dcd62bf446decc8d1a556c",
    "moveit_msgs/PlannerInterfaceDescription": "3b93afb00ba165a83730c4eb03cd1ab7",
    "moveit_msgs/PlannerParams": "cebdf4927996b9026bcf59a160d64145",
    "moveit_msgs/PlanningOptions": "3134e041c806c7c2ff59948db4d57835",
    "moveit_msgs/PlanningScene": "acfc50bcfd6c7b978066bfa7c786002c",
    "moveit_msgs/PlanningSceneComponents": "bc993e784476960b918b6e7ad5bb58ce",
    "moveit_msgs/PlanningSceneWorld": "79457311445f53d410ab4e3781de8447",
    "moveit_msgs/PositionConstraint": "c83edf208d87d3aa3169f47775a58e6a",
    "moveit_msgs/PositionIKRequest": "cb7c3615ee4d29d023dfdc5950af0504",
    "moveit_msgs/QueryPlannerInterfaces": "5876081117e7cad85cc165e937798753",
    "moveit_msgs/RenameRobotStateInWarehouse": "073dc05c3fd313b947cea483c25c46b0",
    "moveit_msgs/RobotState": "968156f4aa4cb4018f1f2293eebcea8f",
    "moveit_msgs/RobotTrajectory": "dfa9556423d709a3729bcef664bddf67",
    "moveit_msgs/SaveMap": "93a4bc4c60dc17e2a69e3fcaaa25d69d",
    "moveit_msgs/SaveRobotStateToWarehouse": "6e80fdee0b8efd0e265bd085def4d166",
    "moveit_msgs/SetPlannerParams": "14bebee5d4d53a2df94b7f146d3eb2ff",
    "moveit_msgs/TrajectoryConstraints": "a8fd55b45c3918e857080ca125d29e9c",
    "moveit_msgs/UpdatePointcloudOctomap": "82b89aaa2577411dc97de3a584f0ee5d",
    "moveit_msgs/VisibilityConstraint": "62cda903bfe31ff2e5fcdc3810d577ad",
    "moveit_msgs/WorkspaceParameters": "d639a834e7b1f927e9f1d6c30e920016",
    "object_recognition_msgs/GetObjectInformation": "dd7d344324fd86c32836f4fe1bc7b322",
    "object_recognition_msgs/ObjectInformation": "921ec39f51c7b927902059cf3300ecde",
    "object_recognition_msgs/ObjectRecognitionAction": "7d8979a0cf97e5078553ee3efee047d2",
    "object_recognition_msgs/ObjectRecognitionActionFeedback": "aae20e09065c3809e8a8e87c4c8953fd",
    "object_recognition_msgs/ObjectRecognitionActionGoal": "195eff91387a5f42dbd13be53431366b",
    "object_recognition_msgs/ObjectRecognitionActionResult": "1ef766aeca50bc1bb70773fc73d4471d",
    "object_recognition_msgs/ObjectRecognitionFeedback": "d41d8cd98f00b204e9800998ecf8427e",
    "object_recognition_msgs/ObjectRecognitionGoal": "49bea2f03a1bba0ad05926e01e3525fa",
    "object_recognition_msgs/ObjectRecognitionResult": "868e41288f9f8636e2b6c51f1af6aa9c",
    "object_recognition_msgs/ObjectType": "ac757ec5be1998b0167e7efcda79e3cf",
    "object_recognition_msgs/RecognizedObject": "f92c4cb29ba11f26c5f7219de97e900d",
    "object_recognition_msgs/RecognizedObjectArray": "bad6b1546b9ebcabb49fb3b858d78964",
    "object_recognition_msgs/Table": "39efebc7d51e44bd2d72f2df6c7823a2",
    "object_recognition_msgs/TableArray": "d1c853e5acd0ed273eb6682dc01ab428",
    "octomap_msgs/BoundingBoxQuery": "93aa3d73b866f04880927745f4aab303",
    "octomap_msgs/GetOctomap": "be9d2869d24fe40d6bc21ac21f6bb2c5",
    "octomap_msgs/Octomap": "9a45536b45c5e409cd49f04bb2d9999f",
    "octomap_msgs/OctomapWithPose": "20b380aca6a508a657e95526cddaf618",
}


def _class(name):
    package, kind = name.split("/")
    for module in ("msg", "srv"):
        try:
            return getattr(importlib.import_module(f"{package}.{module}"), kind)
        except (ImportError, AttributeError):
            continue
    raise AssertionError(f"{name} is not generated")


@pytest.mark.parametrize("name", sorted(UPSTREAM))
def test_md5sum_is_upstreams(name):
    assert _class(name)._md5sum == UPSTREAM[name]


def test_every_definition_is_checked():
    """A message added to the package without its upstream md5sum here fails."""
    import os
    here = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    compat = os.path.dirname(here)
    found = set()
    for package in ("moveit_msgs", "octomap_msgs", "object_recognition_msgs"):
        for folder, ext in (("msg", ".msg"), ("srv", ".srv")):
            path = os.path.join(compat, package, folder)
            if os.path.isdir(path):
                found |= {f"{package}/{f[:-len(ext)]}" for f in os.listdir(path) if f.endswith(ext)}
    assert found <= set(UPSTREAM)
    # actions: the seven messages genaction makes of each
    actions = {n for n in UPSTREAM if n.endswith("Action")}
    assert {"moveit_msgs/MoveGroupAction", "moveit_msgs/ExecuteTrajectoryAction"} <= actions

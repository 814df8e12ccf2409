"""gazebo_ros.spawn_model's arguments against Noetic's script (gazebo_ros_pkgs noetic-devel
f9e1a46, gazebo_ros/scripts/spawn_model; gazebo_ros/src/gazebo_ros/gazebo_interface.py):
defaults, what each argument puts in the requests and in which order, with no master (the
service proxies are stand-ins). sim_bridge/README.md has the table."""
import math

import pytest

from gazebo_ros import spawn_model
from gazebo_ros.spawn_model import (SpawnError, package_to_model, parse_arguments,
                                    read_description)


def test_the_defaults_are_noetics():
    """-reference_frame '' (:62), -gazebo_namespace /gazebo (:65), -x ... -Y 0 (:72-77),
    -J none (:78), -unpause, -package_to_model, -b off (:69, :80, :82)."""
    args = parse_arguments(["-urdf", "-param", "robot_description", "-model", "r"])
    assert args.reference_frame == "" and args.gazebo_namespace == "/gazebo"
    assert (args.x, args.y, args.z, args.R, args.P, args.Y) == (0, 0, 0, 0, 0, 0)
    assert args.J == [] and not args.unpause and not args.package_to_model and not args.b
    assert args.robot_namespace is None  # this node's namespace, resolved at the spawn


@pytest.mark.parametrize("argv", [
    ["-param", "d", "-model", "r"],                     # neither -urdf nor -sdf (:52)
    ["-urdf", "-sdf", "-param", "d", "-model", "r"],    # both
    ["-urdf", "-model", "r"],                           # no source (:55)
    ["-urdf", "-file", "f", "-param", "d", "-model", "r"],  # two sources
    ["-urdf", "-param", "d"],                           # no -model (:61)
])
def test_a_format_a_source_and_a_model_are_required(argv):
    with pytest.raises(SystemExit):
        parse_arguments(argv)


def test_package_to_model_rewrites_mesh_filenames_alone():
    """-package_to_model: <mesh filename="package://..."> becomes model:// (:155-163);
    nothing else does (before: every package:// in the text)."""
    xml = ("<robot name='r'><link name='a'><visual><geometry>"
           "<mesh filename=\"package://pkg/meshes/a.dae\" scale='1 1 1'/></geometry></visual>"
           "<collision><geometry><mesh scale='1 1 1' filename='package://pkg/a.stl'/>"
           "</geometry></collision></link><gazebo><plugin name='p' filename='libx.so'>"
           "<file>package://pkg/config.yaml</file></plugin></gazebo></robot>")
    converted = package_to_model(xml)
    assert 'filename="model://pkg/meshes/a.dae"' in converted
    assert "filename='model://pkg/a.stl'" in converted
    assert "<file>package://pkg/config.yaml</file>" in converted


def test_a_database_model_is_an_include_of_its_model_uri():
    """-database NAME: the template with <uri>model://NAME</uri> (:41-48, :137-139)."""
    args = parse_arguments(["-sdf", "-database", "cafe_table", "-model", "t"])
    assert "<uri>model://cafe_table</uri>" in read_description(args)


def test_an_empty_file_is_refused(tmp_path):
    """An empty file: exit 1 (:126-128)."""
    empty = tmp_path / "empty.urdf"
    empty.write_text("")
    args = parse_arguments(["-urdf", "-file", str(empty), "-model", "r"])
    with pytest.raises(SpawnError, match="is empty"):
        read_description(args)


class Proxy:
    """A service proxy that records its calls and answers ``answer``."""

    def __init__(self, calls, name, answer=None):
        self.calls, self.name, self.answer = calls, name, answer

    def __call__(self, *request):
        self.calls.append((self.name, request))
        return self.answer


class Answer:
    def __init__(self, success=True, status_message="ok"):
        self.success, self.status_message = success, status_message


@pytest.fixture
def services(monkeypatch, tmp_path):
    calls = []
    answers = {}

    def answering_proxy(service, kind, timeout):
        return Proxy(calls, service, answers.get(service, Answer()))

    monkeypatch.setattr(spawn_model, "answering_proxy", answering_proxy)
    monkeypatch.setattr(spawn_model.rospy, "get_namespace", lambda: "/team/")
    monkeypatch.setattr(spawn_model.rospy, "loginfo", lambda *a, **k: None)
    urdf = tmp_path / "r.urdf"
    urdf.write_text("<robot name='r'><link name='a'/></robot>")
    return calls, answers, str(urdf)


def test_spawn_then_joints_then_unpause_with_noetics_arguments(services):
    """The spawn request: model, the XML, robot_namespace (this node's namespace,
    :67), the pose from -x..-Y with quaternion_from_euler(R, P, Y) (:172-178) and
    -reference_frame (:182-189); then -J through set_model_configuration(model, "", names,
    positions) (:194-203); then -unpause (:205-214)."""
    calls, _, urdf = services
    args = parse_arguments(["-urdf", "-file", urdf, "-model", "r", "-x", "1", "-y", "2",
                            "-z", "3", "-Y", str(math.pi / 2), "-reference_frame", "table",
                            "-J", "j1", "0.5", "-J", "j2", "-1", "-unpause"])
    spawn_model.spawn(args)
    assert [name for name, _ in calls] == ["/gazebo/spawn_urdf_model",
                                           "/gazebo/set_model_configuration",
                                           "/gazebo/unpause_physics"]
    model, xml, namespace, pose, frame = calls[0][1]
    assert (model, namespace, frame) == ("r", "/team/", "table")
    assert "<link name='a'/>" in xml
    assert (pose.position.x, pose.position.y, pose.position.z) == (1, 2, 3)
    q = pose.orientation
    assert (q.x, q.y, q.z, q.w) == pytest.approx((0, 0, math.sqrt(0.5), math.sqrt(0.5)))
    assert calls[1][1] == ("r", "", ["j1", "j2"], [0.5, -1.0])


def test_sdf_robot_namespace_and_gazebo_namespace_as_given(services):
    """-sdf calls spawn_sdf_model (:186-189) under -gazebo_namespace (:65-66);
    -robot_namespace as given (:67)."""
    calls, _, urdf = services
    args = parse_arguments(["-sdf", "-file", urdf, "-model", "m", "-robot_namespace", "/r1",
                            "-gazebo_namespace", "/sim"])
    spawn_model.spawn(args)
    assert calls[0][0] == "/sim/spawn_sdf_model" and calls[0][1][2] == "/r1"


def test_a_refused_spawn_fails_with_the_simulators_message(services):
    """success false: "Spawn service failed. Exiting." and exit 1 (:190-192); here the
    simulator's status message is what the error says. No -J call follows."""
    calls, answers, urdf = services
    answers["/gazebo/spawn_urdf_model"] = Answer(False, "SpawnModel: a model named 'r' "
                                                        "exists already")
    args = parse_arguments(["-urdf", "-file", urdf, "-model", "r", "-J", "j", "1"])
    with pytest.raises(SpawnError, match="exists already"):
        spawn_model.spawn(args)
    assert [name for name, _ in calls] == ["/gazebo/spawn_urdf_model"]


def test_a_joint_value_that_is_not_a_number_is_named(services):
    """Noetic converts -J values with float() when it parses them (:86-88) and dies with a
    ValueError's traceback; here the cause is said, exit 1 as there."""
    _, _, urdf = services
    args = parse_arguments(["-urdf", "-file", urdf, "-model", "r", "-J", "j", "up"])
    with pytest.raises(SpawnError, match="-J takes a joint name and a number"):
        spawn_model.spawn(args)


class LatchedTopic:
    """Stands in for rospy.Subscriber on a latched topic: hands the subscriber, as it is
    made, the messages already published there (their data)."""

    def __init__(self, published):
        self.published, self.topics = published, []

    def __call__(self, topic, kind, callback):
        self.topics.append((topic, kind))
        for data in self.published:
            callback(kind(data))


@pytest.mark.parametrize("published", [["<robot name='old'/>", "<robot name='r'/>"], []])
def test_topic_takes_the_latest_string_or_names_the_topic_after_timeout(monkeypatch,
                                                                         published):
    """-topic is not Noetic's (its script has no such argument, :52-83): the latest
    std_msgs/String on the topic is the description, waited for up to -timeout; none, the
    topic is named."""
    from std_msgs.msg import String
    subscriber = LatchedTopic(published)
    monkeypatch.setattr(spawn_model.rospy, "Subscriber", subscriber)
    args = parse_arguments(["-urdf", "-topic", "robot_description_topic", "-model", "r",
                            "-timeout", "0.05"])
    if published:
        assert read_description(args) == published[-1]
    else:
        with pytest.raises(SpawnError, match="nothing was published on "
                                             "robot_description_topic"):
            read_description(args)
    assert subscriber.topics == [("robot_description_topic", String)]


def test_a_parameter_not_set_is_waited_for_then_named(monkeypatch):
    """Noetic's rospy.get_param raises KeyError at once (:132); here -param waits up to
    -timeout for the parameter (a launch file may set it after starting spawn_model), then
    names it."""
    monkeypatch.setattr(spawn_model.rospy, "has_param", lambda name: False)
    args = parse_arguments(["-urdf", "-param", "robot_description", "-model", "r",
                            "-timeout", "0.05"])
    with pytest.raises(SpawnError, match="parameter robot_description is not set"):
        read_description(args)

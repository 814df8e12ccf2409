"""Every parameter of gazebo_plugins' camera utilities as Noetic reads it (gazebo_ros_pkgs
noetic-devel f9e1a46, gazebo_plugins/src/gazebo_ros_camera_utils.cpp, gazebo_ros_camera.cpp):
topics and their defaults, the plugin's updateRate against the sensor's, the lens
parameters CameraInfo carries, and the tags read to no effect (sim_bridge/README.md, the
camera's table)."""
import math

import pytest

from test_camera import CAMERA_HEIGHT, HEIGHT, HFOV, WIDTH, robot, scene, stereo_rig  # noqa: F401
from world_fixtures import run

FOCAL = WIDTH / (2 * math.tan(HFOV / 2))


def stamps_ms(bus, topic):
    return [round(m.header.stamp.to_nsec() / 1e6) for m in bus.published.get(topic, [])]


def spawn(world, plugin="", **changes):
    xml = robot(plugin)
    for old, new in changes.items():
        xml = xml.replace(old, new)
    world.spawn_urdf("cam_bot", xml, (0, 0, CAMERA_HEIGHT))


def test_the_plugins_update_rate_never_exceeds_the_sensors(world, bus):
    """OnNewFrame runs at the sensor's <update_rate> and publishes a frame when at least
    1/updateRate s have passed since the last (gazebo_ros_camera.cpp:109-116), the last
    starting at 0 (common::Time()): a plugin asking 30 Hz of a 10 Hz sensor publishes each
    frame from 0.1 s on, 10 Hz (before: 30 Hz; the frame of the first step, 1 ms after the
    last's 0, is too early)."""
    spawn(world, "<updateRate>30</updateRate>")
    run(world, 0.55)
    assert stamps_ms(bus, "/front/image_raw") == [100, 200, 300, 400, 500]
    # one CameraInfo with each image (the plugin reuses its message: only the last stamp
    # stays in the recording)
    assert len(bus.published["/front/camera_info"]) == 5


def test_a_plugin_rate_that_does_not_divide_the_sensors_takes_the_next_frame(world, bus):
    """4 Hz of a 10 Hz sensor: the last message's time starts at 0 (common::Time()), and a
    frame goes out once 0.25 s have passed since the last: the frames at 0.3, 0.6 and
    0.9 s, 3.3 Hz (gazebo_ros_camera.cpp:116, :130; before: 4 Hz at 0.001, 0.25, 0.5...)."""
    spawn(world, "<updateRate>4</updateRate>")
    run(world, 1.05)
    assert stamps_ms(bus, "/front/image_raw") == [300, 600, 900]


def test_a_stereo_heads_frames_are_throttled_alike(scene, bus):
    """gazebo_ros_multicamera.cpp:116, :130: each head's utilities apply the plugin's rate
    to the sensor's frames."""
    xml = stereo_rig(0.1).replace("<cameraName>stereo</cameraName>",
                                  "<cameraName>stereo</cameraName><updateRate>4</updateRate>")
    scene.spawn_urdf("cam_bot", xml, (0, 0, CAMERA_HEIGHT))
    run(scene, 1.05)
    assert stamps_ms(bus, "/stereo/left/image_raw") == [300, 600, 900]
    assert stamps_ms(bus, "/stereo/right/image_raw") == [300, 600, 900]
    assert len(bus.published["/stereo/right/camera_info"]) == 3


def test_topic_names_as_written_under_the_camera_name(world, bus):
    """imageTopicName and cameraInfoTopicName (gazebo_ros_camera_utils.cpp:124-135) are
    relative to <robotNamespace>/<cameraName> (:288), an absolute one stays absolute."""
    spawn(world, "<imageTopicName>colour</imageTopicName>"
                 "<cameraInfoTopicName>/rig/info</cameraInfoTopicName>")
    run(world, 0.01)
    assert bus.last("/front/colour").encoding == "rgb8"
    assert bus.last("/rig/info").width == WIDTH
    assert not [t for t in bus.published if t.endswith(("image_raw", "camera_info"))]


def test_without_a_camera_name_the_topics_are_the_namespaces(world, bus):
    """cameraName defaults to empty (gazebo_ros_camera_utils.cpp:137-140): the node handle
    is <robotNamespace>/ (:288), the topics /image_raw and /camera_info."""
    spawn(world, **{"<cameraName>front</cameraName>": ""})
    run(world, 0.01)
    assert bus.last("/image_raw").width == WIDTH
    assert bus.last("/camera_info").width == WIDTH


def test_the_principal_point_and_focal_length_written_are_camera_infos(world, bus):
    """Cx, Cy and focalLength as written (gazebo_ros_camera_utils.cpp:167-189), into K and
    P (:586-618); CxPrime is read and goes nowhere (:159-165, :504-505); a focal length
    that disagrees with width / (2 tan(hfov/2)) is kept, with Gazebo's warning (:517-536)."""
    spawn(world, "<Cx>70.5</Cx><Cy>61.25</Cy><focalLength>150</focalLength>"
                 "<CxPrime>12</CxPrime><hackBaseline>0.1</hackBaseline>")
    run(world, 0.01)
    info = bus.last("/front/camera_info")
    assert list(info.K) == [150.0, 0, 70.5, 0, 150.0, 61.25, 0, 0, 1]
    assert list(info.P) == pytest.approx([150.0, 0, 70.5, -15.0, 0, 150.0, 61.25, 0,
                                          0, 0, 1, 0])
    assert list(info.R) == [1, 0, 0, 0, 1, 0, 0, 0, 1]
    (warning,) = [w for w in bus.warnings if "focalLength" in w]
    assert "inconsistent" in warning and f"{FOCAL:g}" in warning
    assert not [w for w in bus.warnings if "does not read" in w]


def test_a_focal_length_that_agrees_is_taken_without_a_warning(world, bus):
    spawn(world, f"<focalLength>{FOCAL!r}</focalLength>")
    run(world, 0.01)
    assert bus.last("/front/camera_info").K[0] == pytest.approx(FOCAL)
    assert not [w for w in bus.warnings if "focalLength" in w]


def test_the_distortion_coefficients_in_plumb_bobs_order(world, bus):
    """D = {k1, k2, t1, t2, k3} (gazebo_ros_camera_utils.cpp:577-584)."""
    spawn(world, "<distortionK1>0.1</distortionK1><distortionK2>0.2</distortionK2>"
                 "<distortionK3>0.3</distortionK3><distortionT1>0.4</distortionT1>"
                 "<distortionT2>0.5</distortionT2>")
    run(world, 0.01)
    assert list(bus.last("/front/camera_info").D) == [0.1, 0.2, 0.4, 0.5, 0.3]


@pytest.mark.parametrize("auto, expected", [("true", [0.01, 0.02, 0.04, 0.05, 0.03]),
                                            ("false", [0.9, 0, 0, 0, 0])])
def test_auto_distortion_takes_the_sensors_coefficients(world, bus, auto, expected):
    """autoDistortion (default false, gazebo_ros_camera_utils.cpp:240-246): true replaces
    the plugin's coefficients with the sensor's <distortion> k1 k2 p1 p2 k3 (:559-575;
    before: not read, named as a tag the plugin does not read)."""
    spawn(world, f"<autoDistortion>{auto}</autoDistortion><distortionK1>0.9</distortionK1>",
          **{"</clip>": "</clip><distortion><k1>0.01</k1><k2>0.02</k2><k3>0.03</k3>"
                        "<p1>0.04</p1><p2>0.05</p2></distortion>"})
    run(world, 0.01)
    assert list(bus.last("/front/camera_info").D) == pytest.approx(expected)
    assert not [w for w in bus.warnings if "does not read" in w]


def test_the_tags_read_to_no_effect_are_not_named_as_unread(world, bus):
    """borderCrop (:248-254) and triggerTopicName (:128-130) are parameters of the camera
    utilities; they change nothing for gazebo_ros_camera (no distorted image here; no
    trigger, CanTriggerCamera() is false, :375-378) and are not warned about (before:
    "does not read")."""
    spawn(world, "<borderCrop>false</borderCrop><triggerTopicName>shoot</triggerTopicName>")
    run(world, 0.01)
    assert not [w for w in bus.warnings if "does not read" in w]
    assert "/front/shoot" not in bus.subscriptions
    assert bus.last("/front/image_raw").width == WIDTH
    assert HEIGHT == bus.last("/front/image_raw").height

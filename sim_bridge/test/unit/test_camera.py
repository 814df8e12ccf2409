"""gazebo_ros_camera on the simulator's scene: what the image shows is where the world has it
(a red crate ahead, a green one to the left, the floor below), CameraInfo is Gazebo's, and
nothing is rendered while nobody listens."""
import math

import numpy as np
import pytest

from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec
from world_fixtures import run

WIDTH, HEIGHT, HFOV = 160, 120, 1.2
CAMERA_HEIGHT = 0.5  # m: the camera link's centre above the floor


def robot(plugin="", sensor_extra="", image_format="R8G8B8"):
    """A box on the floor with a camera 0.1 m ahead of its centre, looking along +x."""
    return f"""<robot name="cam_bot"><link name="base">
      <inertial><mass value="5"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0"
        izz="0.1"/></inertial>
      <collision><geometry><box size="0.2 0.2 {2 * CAMERA_HEIGHT}"/></geometry></collision>
    </link>
    <gazebo reference="base"><sensor type="camera" name="front_camera">
      <pose>0.1 0 0 0 0 0</pose><update_rate>10</update_rate>{sensor_extra}
      <camera><horizontal_fov>{HFOV}</horizontal_fov>
        <image><width>{WIDTH}</width><height>{HEIGHT}</height><format>{image_format}</format>
        </image><clip><near>0.05</near><far>50</far></clip></camera>
      <plugin name="camera_controller" filename="libgazebo_ros_camera.so">
        <cameraName>front</cameraName><frameName>camera_optical</frameName>{plugin}
      </plugin></sensor></gazebo></robot>"""


def crate(name, x, y, rgba):
    box = dict(size=(0.5, 0.5, 1.0), rgba=rgba)
    return ModelSpec(name, True, pose=(x, y, 0.5, 0, 0, 0), links=[LinkSpec(
        "link", collisions=[ShapeSpec("box", **box)], visuals=[ShapeSpec("box", **box)])])


@pytest.fixture
def scene(world):
    world.add_sdf_model(crate("red", 3.0, 0.0, (1, 0, 0, 1)))
    world.add_sdf_model(crate("green", 3.0, 1.5, (0, 1, 0, 1)))
    return world


def camera_of(world):
    (camera,) = [p for p in world.model("cam_bot").plugins if type(p).__name__ == "Camera"]
    return camera


def test_the_image_shows_the_world_where_it_is(scene, bus):
    scene.spawn_urdf("cam_bot", robot(), (0, 0, CAMERA_HEIGHT))
    run(scene, 0.15)
    image = bus.last("/front/image_raw")
    assert (image.width, image.height, image.encoding) == (WIDTH, HEIGHT, "rgb8")
    assert image.header.frame_id == "camera_optical"
    assert image.header.stamp.to_sec() == pytest.approx(0.1, abs=0.002)  # simulated time
    pixels = np.frombuffer(image.data, np.uint8).reshape(HEIGHT, WIDTH, 3).astype(int)
    red = (pixels[:, :, 0] > 150) & (pixels[:, :, 1] < 80) & (pixels[:, :, 2] < 80)
    green = (pixels[:, :, 1] > 150) & (pixels[:, :, 0] < 80) & (pixels[:, :, 2] < 80)
    focal = WIDTH / (2 * math.tan(HFOV / 2))
    # the red crate's face (x 2.75 m, 2.65 ahead of the camera) spans y -0.25..0.25 m
    columns = np.nonzero(red.any(axis=0))[0]
    half_width = 0.25 / 2.65 * focal
    assert columns.min() == pytest.approx(WIDTH / 2 - half_width, abs=2)
    assert columns.max() == pytest.approx(WIDTH / 2 + half_width, abs=2)
    # the green crate is on the left (+y) of the image; nothing green on the right half
    assert green[:, : WIDTH // 2].sum() > 50 and green[:, WIDTH // 2:].sum() == 0
    # the crate's top edge, 0.5 m above the camera: no red above it
    assert not red[: HEIGHT // 2 - int(0.5 / 2.65 * focal) - 2].any()


def test_depth_is_the_distance_along_the_axis(scene):
    scene.spawn_urdf("cam_bot", robot(), (0, 0, CAMERA_HEIGHT))
    _, depth = camera_of(scene).capture()
    assert depth[HEIGHT // 2, WIDTH // 2] == pytest.approx(2.65, abs=0.02)


def test_camera_info_is_gazebos(world, bus):
    world.spawn_urdf("cam_bot", robot("<hackBaseline>0.07</hackBaseline>"
                                      "<distortionK1>0.1</distortionK1>"),
                     (0, 0, CAMERA_HEIGHT))
    run(world, 0.15)
    info = bus.last("/front/camera_info")
    focal = WIDTH / (2 * math.tan(HFOV / 2))
    assert info.K == pytest.approx([focal, 0, (WIDTH + 1) / 2, 0, focal, (HEIGHT + 1) / 2,
                                    0, 0, 1])
    assert info.P[3] == pytest.approx(-focal * 0.07)
    assert info.distortion_model == "plumb_bob" and info.D[0] == pytest.approx(0.1)
    assert info.header.stamp == bus.last("/front/image_raw").header.stamp


def test_nothing_is_rendered_while_nobody_listens(world, bus):
    bus.unheard.update({"/front/image_raw", "/front/camera_info"})
    world.spawn_urdf("cam_bot", robot(), (0, 0, CAMERA_HEIGHT))
    run(world, 0.3)
    assert not bus.published.get("/front/image_raw")


def test_mono_and_bgr_images_and_the_sensor_rate(scene, bus):
    scene.spawn_urdf("cam_bot", robot(image_format="B8G8R8"), (0, 0, CAMERA_HEIGHT))
    run(scene, 0.35)
    images = bus.published["/front/image_raw"]
    assert len(images) == 4  # 10 Hz: at 0, 0.1, 0.2 and 0.3 s
    image = images[-1]
    pixels = np.frombuffer(image.data, np.uint8).reshape(HEIGHT, WIDTH, 3)
    assert image.encoding == "bgr8" and pixels[HEIGHT // 2, WIDTH // 2, 2] > 150  # red last


def test_noise_is_drawn_around_the_true_intensity(scene):
    scene.spawn_urdf("cam_bot", robot(sensor_extra=""), (0, 0, CAMERA_HEIGHT))
    clean, _ = camera_of(scene).capture()
    camera_of(scene).view.noise_stddev = 0.05
    noisy, _ = camera_of(scene).capture()
    difference = noisy.astype(float) - clean.astype(float)
    inside = (clean > 20) & (clean < 235)  # away from clipping at 0 and 255
    assert difference[inside].std() == pytest.approx(0.05 * 255, rel=0.1)
    assert abs(difference[inside].mean()) < 1.0


@pytest.mark.parametrize("camera, words", [
    ("<horizontal_fov>4</horizontal_fov>", "<horizontal_fov> 4.0 is not between 0 and pi"),
    ("<image><format>BAYER_RGGB8</format></image>", "image format 'BAYER_RGGB8'"),
    ("<image><width>100000</width><height>100000</height></image>", "MAX_PIXELS"),
])
def test_a_camera_that_cannot_render_is_left_out_naming_why(world, bus, camera, words):
    xml = robot().replace(robot().split("<camera>")[1].split("</camera>")[0], camera)
    world.spawn_urdf("cam_bot", xml, (0, 0, CAMERA_HEIGHT))
    assert "cam_bot" in world.models
    assert any(words in w and "not loaded" in w for w in bus.warnings), bus.warnings


OPENNI, DEPTH_CAMERA = "libgazebo_ros_openni_kinect.so", "libgazebo_ros_depth_camera.so"


def kinect(cutoff="", plugin_file=OPENNI):
    """The camera robot with a depth sensor and a depth plugin (the openni one unless
    ``plugin_file`` says) instead."""
    return robot(plugin=cutoff).replace('type="camera"', 'type="depth"').replace(
        "libgazebo_ros_camera.so", plugin_file).replace(
        "<cameraName>front</cameraName>", "<cameraName>kinect</cameraName>")


@pytest.mark.parametrize("plugin_file", [OPENNI, DEPTH_CAMERA])
def test_a_depth_cameras_image_and_info_are_on_image_raw_and_camera_info(world, bus,
                                                                         plugin_file):
    """Both depth plugins set ir/image_raw and ir/camera_info when the tags are absent
    (gazebo_plugins/src/gazebo_ros_openni_kinect.cpp:79-82,
    gazebo_plugins/src/gazebo_ros_depth_camera.cpp:92-95), and then call
    GazeboRosCameraUtils::Load, which sets image_raw and camera_info unconditionally
    before reading the tags (gazebo_plugins/src/gazebo_ros_camera_utils.cpp:124, :132):
    Noetic's image and info arrive on <cameraName>/image_raw and <cameraName>/camera_info
    (before: ir/image_raw, ir/camera_info)."""
    world.spawn_urdf("cam_bot", kinect(plugin_file=plugin_file), (0, 0, CAMERA_HEIGHT))
    run(world, 0.15)
    assert bus.last("/kinect/image_raw").encoding == "rgb8"
    assert bus.last("/kinect/camera_info").K[0] == pytest.approx(
        WIDTH / (2 * math.tan(HFOV / 2)))
    assert bus.last("/kinect/depth/image_raw").encoding == "32FC1"
    assert not [t for t in bus.published if "/ir/" in t]


FAR_FACE = 7.0  # m: the far crate's near face, beyond the openni plugin's 5 m cut


def far_depth(world, bus, plugin_file, cutoff=""):
    """The depth at the image's centre, of a crate whose face is 6.9 m ahead of the camera,
    from the depth image and from the point cloud."""
    world.add_sdf_model(crate("far", FAR_FACE + 0.25, 0.0, (1, 0, 0, 1)))
    world.spawn_urdf("cam_bot", kinect(cutoff, plugin_file), (0, 0, CAMERA_HEIGHT))
    run(world, 0.15)
    depth = np.frombuffer(bus.last("/kinect/depth/image_raw").data, np.float32).reshape(
        HEIGHT, WIDTH)
    points = np.frombuffer(bus.last("/kinect/points").data, np.dtype(
        {"names": ["z"], "formats": ["<f4"], "offsets": [8], "itemsize": 32})).reshape(
        HEIGHT, WIDTH)
    return depth[HEIGHT // 2, WIDTH // 2], points["z"][HEIGHT // 2, WIDTH // 2]


def test_the_depth_camera_plugin_has_no_far_cutoff(world, bus):
    """libgazebo_ros_depth_camera.so reads no pointCloudCutoffMax: its depth image keeps
    every depth above pointCloudCutoff (gazebo_plugins/src/gazebo_ros_depth_camera.cpp:762),
    its cloud likewise (:675). A crate 6.9 m ahead is measured (before: NaN beyond 5 m); a
    <pointCloudCutoffMax> written is named as a tag the plugin does not read."""
    image, cloud = far_depth(world, bus, DEPTH_CAMERA,
                             "<pointCloudCutoffMax>0.9</pointCloudCutoffMax>")
    assert image == pytest.approx(FAR_FACE - 0.1, abs=0.05)
    assert cloud == pytest.approx(FAR_FACE - 0.1, abs=0.05)
    (warning,) = [w for w in bus.warnings if "does not read" in w]
    assert "<pointCloudCutoffMax>" in warning


def test_the_openni_plugin_cuts_at_5_m(world, bus):
    """libgazebo_ros_openni_kinect.so reads pointCloudCutoffMax, 5 m by default
    (gazebo_plugins/src/gazebo_ros_openni_kinect.cpp:105-108), and leaves NaN at and beyond
    it in the depth image (:454-455) and the cloud (:361-362)."""
    image, cloud = far_depth(world, bus, OPENNI)
    assert np.isnan(image) and np.isnan(cloud)


def test_a_depth_camera_measures_the_world_in_its_optical_frame(scene, bus):
    scene.spawn_urdf("cam_bot", kinect(), (0, 0, CAMERA_HEIGHT))
    run(scene, 0.15)
    for topic in ("image_raw", "camera_info", "depth/camera_info"):
        assert bus.last(f"/kinect/{topic}").header.frame_id == "camera_optical"
    depth_message = bus.last("/kinect/depth/image_raw")
    assert depth_message.encoding == "32FC1"
    depth = np.frombuffer(depth_message.data, np.float32).reshape(HEIGHT, WIDTH)
    assert depth[HEIGHT // 2, WIDTH // 2] == pytest.approx(2.65, abs=0.02)
    assert np.isnan(depth[0, WIDTH // 2])  # nothing within 5 m above the crates
    cloud = bus.last("/kinect/points")
    assert (cloud.height, cloud.width, cloud.point_step) == (HEIGHT, WIDTH, 32)
    points = np.frombuffer(cloud.data, np.dtype({"names": ["x", "y", "z", "rgb"],
                                                 "formats": ["<f4"] * 4,
                                                 "offsets": [0, 4, 8, 16], "itemsize": 32}))
    points = points.reshape(HEIGHT, WIDTH)
    # the rgb field's bytes are the R8G8B8 image's in its order, red first, so red is the
    # lowest byte of the little-endian word (gazebo_plugins/src/
    # gazebo_ros_openni_kinect.cpp:379-386); before: PCL's order, blue lowest
    colour = points["rgb"].view(np.uint32)
    r, g, b = colour & 255, colour >> 8 & 255, colour >> 16 & 255
    assert not (colour >> 24).any()
    red = (r > 150) & (g < 80) & (b < 80)
    green = (g > 150) & (r < 80) & (b < 80)
    # the crates' faces 2.65 m ahead: the red one at optical x -0.25..0.25 m, the green one
    # (world y 1.25..1.75 m, on the camera's left) at optical x -1.75..-1.25 m; y down
    assert points["z"][red] == pytest.approx(2.65, abs=0.03)
    assert -0.27 < points["x"][red].min() < -0.2 and 0.2 < points["x"][red].max() < 0.27
    face = green & (np.abs(points["z"] - 2.65) < 0.03)
    assert -1.77 < points["x"][face].min() < -1.7 and -1.3 < points["x"][face].max() < -1.23
    assert -0.52 < points["y"][red].min() < -0.45 and 0.45 < points["y"][red].max() < 0.52


def test_depth_beyond_the_cutoff_is_nan(scene, bus):
    # the nearest thing seen is the floor at the bottom row, 0.97 m along the axis
    scene.spawn_urdf("cam_bot", kinect("<pointCloudCutoffMax>0.9</pointCloudCutoffMax>"),
                     (0, 0, CAMERA_HEIGHT))
    run(scene, 0.15)
    depth = np.frombuffer(bus.last("/kinect/depth/image_raw").data, np.float32)
    assert np.isnan(depth).all()


def test_a_camera_too_costly_to_watch_at_real_time_says_so_at_spawn(world, bus):
    big = robot().replace(f"<width>{WIDTH}</width><height>{HEIGHT}</height>",
                          "<width>1920</width><height>1080</height>").replace(
        "<update_rate>10</update_rate>", "<update_rate>30</update_rate>")
    world.spawn_urdf("cam_bot", big, (0, 0, CAMERA_HEIGHT))
    (warning,) = [w for w in bus.warnings if "renders" in w]
    assert "1920 x 1080 images at 30 Hz" in warning and "x real time" in warning
    bus.warnings.clear()
    world.delete("cam_bot")
    world.spawn_urdf("cam_bot", robot(), (0, 0, CAMERA_HEIGHT))  # 160 x 120 at 10 Hz
    assert not [w for w in bus.warnings if "renders" in w]


def stereo_rig(baseline, third_camera=""):
    """The camera robot with a multicamera sensor: two heads ``baseline`` apart along y
    (left at +y, as REP 103 has the left), looking along +x."""
    def head(name, y):
        return f"""<camera name="{name}"><pose>0 {y} 0 0 0 0</pose>
          <horizontal_fov>{HFOV}</horizontal_fov>
          <image><width>{WIDTH}</width><height>{HEIGHT}</height><format>R8G8B8</format>
          </image><clip><near>0.05</near><far>50</far></clip></camera>"""
    cameras = head("left", baseline / 2) + head("right", -baseline / 2) + third_camera
    return robot().replace('type="camera"', 'type="multicamera"').replace(
        "libgazebo_ros_camera.so", "libgazebo_ros_multicamera.so").replace(
        "<cameraName>front</cameraName>",
        f"<cameraName>stereo</cameraName><hackBaseline>{baseline}</hackBaseline>").replace(
        robot().split("<camera>")[1].split("</camera>")[0], "").replace(
        "<camera></camera>", cameras)


def red_columns(image):
    pixels = np.frombuffer(image.data, np.uint8).reshape(HEIGHT, WIDTH, 3).astype(int)
    red = (pixels[:, :, 0] > 150) & (pixels[:, :, 1] < 80) & (pixels[:, :, 2] < 80)
    columns = np.nonzero(red.any(axis=0))[0]
    return columns.min(), columns.max()


def test_a_stereo_rig_sees_the_crate_with_the_disparity_its_baseline_gives(scene, bus):
    baseline = 0.5
    scene.spawn_urdf("cam_bot", stereo_rig(baseline), (0, 0, CAMERA_HEIGHT))
    run(scene, 0.15)
    left, right = bus.last("/stereo/left/image_raw"), bus.last("/stereo/right/image_raw")
    assert left.header.stamp == right.header.stamp  # one shutter
    assert left.header.frame_id == right.header.frame_id == "camera_optical"
    focal = WIDTH / (2 * math.tan(HFOV / 2))
    half_width = 0.25 / 2.65 * focal
    # the crate (y -0.25..0.25 m, 2.65 m ahead) seen from y = +-0.25 m: shifted by
    # f * 0.25 / 2.65 to the right in the left image and to the left in the right one
    shift = 0.25 / 2.65 * focal
    for image, sign in ((left, 1), (right, -1)):
        low, high = red_columns(image)
        assert low == pytest.approx(WIDTH / 2 - half_width + sign * shift, abs=2)
        assert high == pytest.approx(WIDTH / 2 + half_width + sign * shift, abs=2)
    assert bus.last("/stereo/left/camera_info").P[3] == 0.0
    assert bus.last("/stereo/right/camera_info").P[3] == pytest.approx(-focal * baseline)


def test_a_multicamera_head_named_neither_left_nor_right_publishes_nothing(scene, bus):
    middle = stereo_rig(0.1).split('<camera name="left">')[1].split("</camera>")[0]
    scene.spawn_urdf("cam_bot", stereo_rig(0.1, f'<camera name="middle">{middle}</camera>'),
                     (0, 0, CAMERA_HEIGHT))
    run(scene, 0.15)
    assert any("camera 'middle' is named neither left nor right" in w for w in bus.warnings)
    assert sorted(t for t in bus.published if t.startswith("/stereo")) == [
        "/stereo/left/camera_info", "/stereo/left/image_raw", "/stereo/right/camera_info",
        "/stereo/right/image_raw"]


def test_a_deleted_camera_closes_its_topics(scene, bus):
    scene.spawn_urdf("cam_bot", stereo_rig(0.1), (0, 0, CAMERA_HEIGHT))
    scene.spawn_urdf("kinect_bot", kinect(), (0, 2, CAMERA_HEIGHT))
    scene.delete("cam_bot")
    scene.delete("kinect_bot")
    assert {"/stereo/left/image_raw", "/stereo/right/camera_info", "/kinect/points",
            "/kinect/depth/image_raw"} <= set(bus.closed)


@pytest.mark.parametrize("tf_prefix, frame_id", [("", ""), ("p", "p/")])
def test_a_camera_without_frame_name_stamps_an_empty_frame(world, bus, tf_prefix, frame_id):
    """No <frameName>: GazeboRosCameraUtils only logs "defaults to /world" and leaves its
    frame_name_ empty (gazebo_plugins/src/gazebo_ros_camera_utils.cpp:146-149), then
    tf::resolve(tf_prefix, "") makes it "" or "<prefix>/" (:298): the image, its info and a
    depth camera's cloud carry that frame (before: world)."""
    world.spawn_urdf("cam_bot", robot().replace("<frameName>camera_optical</frameName>", ""),
                     (0, 0, CAMERA_HEIGHT), tf_prefix=tf_prefix)
    world.spawn_urdf("kinect_bot", kinect().replace(
        "<frameName>camera_optical</frameName>", ""), (0, 2, CAMERA_HEIGHT),
        tf_prefix=tf_prefix)
    run(world, 0.15)
    for topic in ("/front/image_raw", "/front/camera_info", "/kinect/points",
                  "/kinect/depth/image_raw"):
        assert bus.last(topic).header.frame_id == frame_id, topic


def stamps_ms(bus, topic):
    return [round(m.header.stamp.to_sec() * 1000) for m in bus.published.get(topic, [])]


@pytest.mark.parametrize("plugin_file", [OPENNI, DEPTH_CAMERA])
def test_a_depth_plugins_update_rate_throttles_its_infos_not_its_frames(world, bus,
                                                                       plugin_file):
    """OnNewDepthFrame and OnNewImageFrame publish every frame of the sensor (10 Hz here)
    whatever the plugin's updateRate (gazebo_plugins/src/gazebo_ros_openni_kinect.cpp:
    194-273, gazebo_ros_depth_camera.cpp:278-327, :446-483); the camera infos go out once
    at least 1/updateRate s (0.5 s here) have passed since each last did
    (gazebo_ros_camera_utils.cpp:679-686, gazebo_ros_openni_kinect.cpp:474-493). Before:
    every topic at the plugin's 2 Hz."""
    world.spawn_urdf("cam_bot", kinect("<updateRate>2</updateRate>", plugin_file),
                     (0, 0, CAMERA_HEIGHT))
    run(world, 1.05)
    frames = [1] + list(range(100, 1001, 100))  # the sensor's first frame at the first step
    for topic in ("image_raw", "depth/image_raw", "points"):
        assert stamps_ms(bus, f"/kinect/{topic}") == frames
    # the infos' last times start at 0 (gazebo_ros_camera_utils.cpp:53,
    # gazebo_ros_openni_kinect.cpp:55, gazebo_ros_depth_camera.cpp:56)
    for topic in ("camera_info", "depth/camera_info"):
        assert stamps_ms(bus, f"/kinect/{topic}") == [500, 1000]


def cloud_of(world, bus, plugin_file, plugin="", image_format="R8G8B8"):
    world.add_sdf_model(crate("red", 3.0, 0.0, (1, 0, 0, 1)))
    world.spawn_urdf("cam_bot", kinect(plugin, plugin_file).replace(
        "<format>R8G8B8</format>", f"<format>{image_format}</format>"), (0, 0, CAMERA_HEIGHT))
    run(world, 0.15)
    return bus.last("/kinect/points")


@pytest.mark.parametrize("plugin_file, dense", [(OPENNI, False), (DEPTH_CAMERA, True)])
def test_a_cloud_is_dense_unless_a_point_is_cut_off(world, bus, plugin_file, dense):
    """is_dense starts true and turns false at the first point cut off to NaN
    (gazebo_plugins/src/gazebo_ros_depth_camera.cpp:641, :684;
    gazebo_ros_openni_kinect.cpp:333, :375). The openni plugin cuts the sky beyond 5 m;
    the depth camera plugin keeps every depth above 0.4 m, and the nearest thing here (the
    floor) is 0.97 m away, so its cloud is dense. Before: never dense."""
    cloud = cloud_of(world, bus, plugin_file)
    assert cloud.is_dense is dense


@pytest.mark.parametrize("image_format, red_byte", [("R8G8B8", 0), ("B8G8R8", 2)])
def test_the_clouds_colour_bytes_are_the_images(world, bus, image_format, red_byte):
    """The rgb field's first three bytes are the image's pixel bytes in the image's order
    (gazebo_plugins/src/gazebo_ros_depth_camera.cpp:692-698), the fourth 0: the red
    crate's red is the first byte from an R8G8B8 camera and the third from a B8G8R8 one,
    the other two 0. Before: PCL's order (blue, green, red) for both."""
    cloud = cloud_of(world, bus, DEPTH_CAMERA, image_format=image_format)
    raw = np.frombuffer(cloud.data, np.uint8).reshape(HEIGHT, WIDTH, 32)
    centre = raw[HEIGHT // 2, WIDTH // 2, 16:20]
    assert centre[red_byte] > 150
    assert [int(centre[i]) for i in range(4) if i != red_byte] == [0, 0, 0]


@pytest.mark.parametrize("plugin_file", [OPENNI, DEPTH_CAMERA])
def test_use_depth_16uc1_format_publishes_millimetres(world, bus, plugin_file):
    """useDepth16UC1Format true: a 16UC1 depth image of millimetres, 0 where the 32-bit one
    has NaN (gazebo_plugins/src/gazebo_ros_depth_camera.cpp:136-140, :744-775;
    gazebo_ros_openni_kinect.cpp:110-114, :429-468). The red crate's face 2.65 m ahead
    reads about 2650; the sky, beyond the openni plugin's 5 m, reads 0. Before: 32FC1
    whatever the tag said."""
    cloud_of(world, bus, plugin_file, "<useDepth16UC1Format>true</useDepth16UC1Format>")
    message = bus.last("/kinect/depth/image_raw")
    assert (message.encoding, message.step) == ("16UC1", 2 * WIDTH)
    depth = np.frombuffer(message.data, np.uint16).reshape(HEIGHT, WIDTH)
    assert int(depth[HEIGHT // 2, WIDTH // 2]) == pytest.approx(2650, abs=20)
    if plugin_file == OPENNI:
        assert depth[0, WIDTH // 2] == 0

"""``<sensor type="camera">`` with ``libgazebo_ros_camera.so``, ``<sensor type="depth">`` with
``libgazebo_ros_openni_kinect.so`` or ``libgazebo_ros_depth_camera.so``, ``<sensor
type="multicamera">`` with ``libgazebo_ros_multicamera.so``: images of the simulator's scene
(:class:`DepthCamera` says what the depth cameras add, :class:`MultiCamera` what a stereo
rig is).

From the sensor, as Gazebo reads it: ``<pose>`` (in the link's frame; the camera looks
along the sensor frame's +x, +z up), ``<update_rate>`` (Hz of simulated time; 0 every step),
``<camera>`` ``<horizontal_fov>`` (rad, 1.047), ``<image>`` ``<width>`` (320), ``<height>``
(240), ``<format>`` (R8G8B8: rgb8; B8G8R8: bgr8; L8: mono8), ``<clip>`` ``<near>`` (0.1)
``<far>`` (100), ``<noise>`` gaussian mean and stddev on intensities from 0 to 1 (drawn from
the world's seeded generator). From the plugin, as gazebo_plugins' camera utilities read
them: ``cameraName`` (empty), ``imageTopicName`` (image_raw), ``cameraInfoTopicName``
(camera_info), ``frameName`` (empty, as upstream leaves it; the model's tf_prefix
applied), ``updateRate`` (0: every frame of the sensor; else a frame once at least
1/updateRate s have passed since the last published, so never above the sensor's rate),
``hackBaseline`` (0), ``focalLength``, ``Cx``, ``Cy``, ``CxPrime`` (0: computed),
``distortionK1`` ``K2`` ``K3`` ``T1`` ``T2`` (0), ``autoDistortion`` (false: true takes the
sensor's ``<distortion>`` coefficients), ``borderCrop`` and ``triggerTopicName`` (read, no
effect). Topics are ``<robotNamespace>/<cameraName>/<topic>``.

CameraInfo is Gazebo's: f = width / (2 tan(hfov / 2)) on both axes (square pixels),
cx = (width + 1) / 2, cy = (height + 1) / 2, P's fourth column -f * hackBaseline, plumb_bob
distortion with the five coefficients as written (the image itself is not distorted).

The image is rendered on the CPU by pybullet's TinyRenderer from the simulator's own scene
(the visuals with their Gazebo colours and meshes), from the link's true pose, and only
while someone subscribes to the image or its camera info, as Gazebo's camera is active only
then: a 640 x 480 frame costs about 60 ms on the 2-core VM, 320 x 240 about 15.
Stamps are simulated time.
"""
from __future__ import annotations

import copy
import dataclasses
import math
from typing import Optional, Tuple

import numpy as np
import pybullet as pb
from sensor_msgs.msg import CameraInfo, Image, PointCloud2, PointField
from std_msgs.msg import Header

from sim_bridge.plugins.base import (Plugin, PluginError, Rate, SensorPlugin, Throttle,
                                     element_pose, stamp)

# Gazebo's image formats sim_bridge renders → (ROS encoding, channels)
FORMATS = {"R8G8B8": ("rgb8", 3), "RGB_INT8": ("rgb8", 3), "B8G8R8": ("bgr8", 3),
           "BGR_INT8": ("bgr8", 3), "L8": ("mono8", 1), "L_INT8": ("mono8", 1)}
# the most pixels one camera may have: a 4K frame; each is rendered on the CPU
MAX_PIXELS = 3840 * 2160
# rendering cost on the 2-core VM, about 0.2 us a pixel (320 x 240: 15 ms, 640 x 480: 60 ms)
SECONDS_PER_PIXEL = 0.2e-6
# a camera that would take more than this share of each simulated second to render while
# watched is named at spawn with what it costs (TurtleBot3 waffle's 1920 x 1080 depth camera
# at 30 Hz ran the simulator at 0.02 x real time, silently)
COSTLY_SHARE = 0.5
# a point of PCL's PointXYZRGB as gazebo_plugins lays it out: x y z, 4 bytes free, rgb
POINT_XYZRGB = np.dtype({"names": ["x", "y", "z", "rgb"],
                         "formats": [np.float32] * 4, "offsets": [0, 4, 8, 16],
                         "itemsize": 32})


def _number(element, path: str, default: float, sensor: str) -> float:
    text = element.findtext(path) if element is not None else None
    if text is None or not text.strip():
        return default
    try:
        value = float(text)
    except ValueError:
        raise PluginError(f"sensor '{sensor}': <{path}> '{text}' is not a number") from None
    if not math.isfinite(value):
        raise PluginError(f"sensor '{sensor}': <{path}> '{text}' is not a finite number")
    return value


class CameraView:
    """What a ``<camera>`` element describes: the image's size, the lens and the clip
    planes; renders the scene of a pybullet client from a pose."""

    def __init__(self, camera, name: str):
        """``camera``: the ``<camera>`` element; ``name``: the sensor's, for messages."""
        self.width = int(_number(camera, "image/width", 320, name))
        self.height = int(_number(camera, "image/height", 240, name))
        if self.width < 1 or self.height < 1 or self.width * self.height > MAX_PIXELS:
            raise PluginError(f"sensor '{name}': an image of {self.width} x {self.height} "
                              f"pixels; sim_bridge renders 1 to {MAX_PIXELS} (MAX_PIXELS)")
        self.hfov = _number(camera, "horizontal_fov", 1.047, name)
        if not 0 < self.hfov < math.pi:
            raise PluginError(f"sensor '{name}': <horizontal_fov> {self.hfov} is not between "
                              "0 and pi radians")
        self.near = _number(camera, "clip/near", 0.1, name)
        self.far = _number(camera, "clip/far", 100.0, name)
        if not 0 < self.near < self.far:
            raise PluginError(f"sensor '{name}': needs 0 < clip near < clip far (got "
                              f"{self.near}, {self.far})")
        image_format = (camera.findtext("image/format") or "R8G8B8").strip()
        if image_format not in FORMATS:
            raise PluginError(f"sensor '{name}': image format '{image_format}' is not one "
                              f"sim_bridge renders ({', '.join(FORMATS)})")
        self.encoding, self.channels = FORMATS[image_format]
        noise = camera.find("noise")
        self.noise_mean = _number(noise, "mean", 0.0, name)
        self.noise_stddev = _number(noise, "stddev", 0.0, name)
        # square pixels: the vertical field of view that the horizontal one implies
        vfov = 2.0 * math.atan(math.tan(self.hfov / 2.0) * self.height / self.width)
        self.projection = pb.computeProjectionMatrixFOV(math.degrees(vfov),
                                                        self.width / self.height,
                                                        self.near, self.far)
        self.focal_length = self.width / (2.0 * math.tan(self.hfov / 2.0))

    def render(self, client: int, position, orientation) -> Tuple[np.ndarray, np.ndarray]:
        """(RGB image, height x width x 3 uint8; depth along the optical axis in metres,
        height x width, +inf where nothing is within the clip planes) seen from the pose."""
        rotation = np.array(pb.getMatrixFromQuaternion(orientation)).reshape(3, 3)
        eye = np.asarray(position, dtype=float)
        view = pb.computeViewMatrix(eye.tolist(), (eye + rotation[:, 0]).tolist(),
                                    rotation[:, 2].tolist())
        _, _, rgba, buffer, _ = pb.getCameraImage(
            self.width, self.height, view, self.projection, renderer=pb.ER_TINY_RENDERER,
            flags=pb.ER_NO_SEGMENTATION_MASK, physicsClientId=client)
        rgb = np.asarray(rgba, dtype=np.uint8).reshape(self.height, self.width, 4)[:, :, :3]
        buffer = np.asarray(buffer, dtype=float).reshape(self.height, self.width)
        # OpenGL's depth buffer (0 at near, 1 at far) back to metres along the axis
        with np.errstate(divide="ignore"):
            depth = self.far * self.near / (self.far - (self.far - self.near) * buffer)
        depth[buffer >= 1.0] = np.inf
        return rgb, depth


class Camera(SensorPlugin):
    EMPTY_NAMESPACE_IS_MODEL = True  # GazeboRosCameraUtils reads it by GetRobotNamespace

    """gazebo_ros_camera: sensor_msgs/Image and CameraInfo of a ``camera`` sensor."""

    # the topics' defaults (the depth cameras' differ)
    IMAGE_TOPIC = "image_raw"
    INFO_TOPIC = "camera_info"
    # the plugin's <updateRate> throttles the sensor's frames (gazebo_ros_camera,
    # gazebo_ros_multicamera); the depth cameras keep their own rule
    PLUGIN_RATE_THROTTLES_FRAMES = True

    def __init__(self, context, spec, sensor, head: Optional["Head"] = None):
        """``head``: one camera of a multicamera sensor; None for the sensor's one
        ``<camera>``."""
        super().__init__(context, spec, sensor)
        element = sensor.element.find("camera") if head is None else head.element
        if element is None:
            raise PluginError(f"sensor '{sensor.name}' of type {sensor.type} needs a <camera> "
                              "element")
        self.view = CameraView(element, sensor.name)
        if head is not None:  # the head's <pose> is in the sensor's frame
            self.sensor_position, self.sensor_orientation = pb.multiplyTransforms(
                self.sensor_position, self.sensor_orientation, head.position,
                head.orientation, physicsClientId=context.client)
        plugin_rate = self.number("updateRate", 0.0)
        sensor_rate = _number(sensor.element, "update_rate", 0.0, sensor.name)
        if self.PLUGIN_RATE_THROTTLES_FRAMES:
            # the sensor renders at its <update_rate>; GazeboRosCamera::OnNewFrame publishes a
            # frame when at least 1/updateRate s have passed since the last it published
            # (gazebo_plugins/src/gazebo_ros_camera.cpp:116, :130; the period from
            # gazebo_ros_camera_utils.cpp:151-157, :441-444; gazebo_ros_multicamera.cpp:116,
            # :130): never faster than the sensor, and a rate that does not divide the
            # sensor's takes the next frame after each period
            self.rate = Rate(sensor_rate)
            self.throttle = Throttle(plugin_rate)
            rate = sensor_rate if plugin_rate <= 0 else (
                plugin_rate if sensor_rate <= 0 else min(plugin_rate, sensor_rate))
        else:
            # the depth cameras: every frame of the sensor (OnNewDepthFrame and
            # OnNewImageFrame check no rate, gazebo_plugins/src/gazebo_ros_openni_kinect.cpp:
            # 194-273, gazebo_ros_depth_camera.cpp:278-327, :446-483); the plugin's
            # updateRate throttles their camera infos alone (DepthCamera)
            rate = sensor_rate
            self.rate = Rate(sensor_rate)
            self.throttle = Throttle(0.0)
        self.plugin_rate = plugin_rate
        frames = rate if rate > 0 else 1.0 / context.step_size  # a second of simulated time
        frame_seconds = self.view.width * self.view.height * SECONDS_PER_PIXEL
        if frames * frame_seconds > COSTLY_SHARE:
            context.bus.warn(
                f"model '{context.model_name}': sensor '{sensor.name}' renders "
                f"{self.view.width} x {self.view.height} images at {frames:g} Hz on the CPU, "
                f"about {1000 * frame_seconds:.0f} ms each: while someone watches it the "
                f"simulator runs at about {min(1.0, 1.0 / (frames * frame_seconds)):.2g} x real "
                "time (nothing is rendered while nobody does). A smaller <image> or a lower "
                "<update_rate> keeps it near real time")
        # no <frameName>: GazeboRosCameraUtils logs "defaults to /world" and leaves its frame
        # empty (gazebo_plugins/src/gazebo_ros_camera_utils.cpp:146-149); tf::resolve of ""
        # is "" or "<tf_prefix>/" (:298)
        self.frame_id = self.frame(self.param("frameName", ""))
        camera_name = (self.param("cameraName", "") or "") + (head.suffix if head else "")
        self.camera_name = camera_name.strip("/")
        # read by GazeboRosCameraUtils::Load and of no effect here: the trigger topic serves
        # only the triggered cameras (CanTriggerCamera() is false for these,
        # gazebo_ros_camera_utils.cpp:128-130, :358, :375-378); borderCrop crops Gazebo's
        # distorted image (:248-254, :553-556), and the image here is not distorted
        self.param("triggerTopicName", "image_trigger")
        self.flag("borderCrop", True)
        self.info = self._camera_info(None if head is None else head.baseline, element)
        self.image_out = self.publisher("imageTopicName", self.IMAGE_TOPIC, Image)
        self.info_out = self.publisher("cameraInfoTopicName", self.INFO_TOPIC, CameraInfo)

    def publisher(self, tag: str, default: str, msg_class):
        """A publisher on the topic the parameter ``tag`` names, under the camera's name."""
        return self.context.bus.publisher(
            self.topic(self._join(self.camera_name, self.param(tag, default))), msg_class,
            queue_size=2)

    @staticmethod
    def _join(camera_name: str, topic: Optional[str]) -> str:
        topic = topic or ""
        if topic.startswith("/") or not camera_name:
            return topic
        return f"{camera_name}/{topic}"

    def _camera_info(self, baseline: Optional[float], camera=None) -> CameraInfo:
        """Gazebo's CameraInfo (gazebo_plugins/src/gazebo_ros_camera_utils.cpp:503-618);
        ``baseline`` overrides ``hackBaseline`` (a stereo head's); ``camera`` is the
        ``<camera>`` element, whose ``<distortion>`` ``autoDistortion`` takes."""
        view = self.view
        focal = self.number("focalLength", 0.0)
        if focal == 0:
            focal = view.focal_length
        elif not math.isclose(focal, view.focal_length, rel_tol=0.0, abs_tol=1e-6):
            # ignition::math::equal's tolerance, 1e-6 (gazebo_ros_camera_utils.cpp:524-535)
            self.context.bus.warn(
                f"model '{self.context.model_name}': plugin '{self.spec.name}' "
                f"({self.spec.filename}): <focalLength> {focal:g} is inconsistent with the "
                f"image's width {view.width} and horizontal_fov {view.hfov:g}: width / (2 "
                f"tan(hfov / 2)) is {view.focal_length:g}; CameraInfo carries {focal:g}, as "
                "in Gazebo")
        self.number("CxPrime", 0.0)  # read by gazebo_plugins and never put into CameraInfo
        cx = self.number("Cx", 0.0) or (view.width + 1.0) / 2.0
        cy = self.number("Cy", 0.0) or (view.height + 1.0) / 2.0
        if baseline is None:
            baseline = self.number("hackBaseline", 0.0)
        info = CameraInfo()
        info.header.frame_id = self.frame_id
        info.width, info.height = view.width, view.height
        info.distortion_model = "plumb_bob"
        # D = {k1, k2, t1, t2, k3} (gazebo_ros_camera_utils.cpp:580-584)
        info.D = [self.number(f"distortion{name}", 0.0) for name in ("K1", "K2", "T1", "T2",
                                                                      "K3")]
        if self.flag("autoDistortion", False):
            # the sensor's own <distortion> k1 k2 p1 p2 k3 replace the plugin's (:559-575)
            distortion = camera.find("distortion") if camera is not None else None
            info.D = [_number(distortion, name, 0.0, self.spec.name)
                      for name in ("k1", "k2", "p1", "p2", "k3")]
        info.K = [focal, 0.0, cx, 0.0, focal, cy, 0.0, 0.0, 1.0]
        info.R = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]
        info.P = [focal, 0.0, cx, -focal * baseline, 0.0, focal, cy, 0.0, 0.0, 0.0, 1.0, 0.0]
        return info

    def capture(self) -> Tuple[np.ndarray, np.ndarray]:
        """(the image as published, height x width x channels uint8; depth in metres)."""
        rgb, depth = self.view.render(self.context.client, *self.sensor_pose())
        view = self.view
        if view.noise_stddev > 0 or view.noise_mean != 0:
            noisy = rgb / 255.0 + self.context.rng.normal(view.noise_mean, view.noise_stddev,
                                                          rgb.shape)
            rgb = np.clip(np.round(noisy * 255.0), 0, 255).astype(np.uint8)
        if view.encoding == "bgr8":
            rgb = rgb[:, :, ::-1]
        elif view.encoding == "mono8":  # ITU-R 601 luma, as Ogre's L8
            rgb = np.round(rgb @ np.array([0.299, 0.587, 0.114]))[:, :, None].astype(np.uint8)
        return np.ascontiguousarray(rgb), depth

    def active(self) -> bool:
        return self.context.bus.listened(self.image_out) or \
            self.context.bus.listened(self.info_out)

    def reset(self, now_ns: int) -> None:
        self.rate.reset(now_ns)

    def quiet_until_ns(self, now_ns: int, step_ns: int) -> int:
        return self.rate.quiet_until_ns()  # after_step asks the rate first

    def after_step(self, now_ns: int) -> None:
        if not self.rate.due(now_ns) or not self.active() or not self.throttle.ready(now_ns):
            return
        self.throttle.mark(now_ns)
        pixels, depth = self.capture()
        self.publish(now_ns, pixels, depth)

    def publish(self, now_ns: int, pixels: np.ndarray, depth: np.ndarray) -> None:
        header_stamp = stamp(now_ns)
        self.image_out.publish(self.image(header_stamp, pixels, self.view.encoding))
        self.info_out.publish(self.info_message(header_stamp))

    def info_message(self, header_stamp) -> CameraInfo:
        """The CameraInfo stamped, a message of its own (one published is never changed)."""
        message = copy.copy(self.info)
        message.header = Header(stamp=header_stamp, frame_id=self.info.header.frame_id)
        return message

    def image(self, header_stamp, pixels: np.ndarray, encoding: str) -> Image:
        image = Image()
        image.header.stamp, image.header.frame_id = header_stamp, self.frame_id
        image.height, image.width = pixels.shape[:2]
        image.encoding = encoding
        image.step = pixels.shape[1] * pixels.shape[2] * pixels.dtype.itemsize
        image.data = pixels.tobytes()
        return image


# the depth plugin with a far cutoff: gazebo_ros_openni_kinect reads pointCloudCutoffMax
# (gazebo_plugins/src/gazebo_ros_openni_kinect.cpp:105); gazebo_ros_depth_camera reads none
# and keeps every depth above pointCloudCutoff (gazebo_ros_depth_camera.cpp:675, :762)
CUTOFF_MAX_PLUGIN = "libgazebo_ros_openni_kinect.so"
# useDepth16UC1Format: millimetres in an unsigned 16-bit pixel (REP 118), so 65.535 m at most
MILLIMETRES_PER_METRE = 1000.0
MAX_DEPTH_16UC1 = 2 ** 16


class DepthCamera(Camera):
    """gazebo_ros_openni_kinect and gazebo_ros_depth_camera on a ``depth`` sensor: the
    camera's image and info (on ``image_raw`` and ``camera_info`` by default: both plugins
    set ``ir/...`` and then GazeboRosCameraUtils::Load sets these unconditionally,
    gazebo_plugins/src/gazebo_ros_camera_utils.cpp:124, :132), the depth image
    (``depthImageTopicName``, depth/image_raw: 32FC1, metres along the optical axis, NaN
    at or below ``pointCloudCutoff`` (0.4 m) and, for the openni plugin alone, at or beyond
    ``pointCloudCutoffMax`` (5 m); +inf where nothing is within the far clip; 16UC1
    millimetres with ``useDepth16UC1Format``) with its info
    (``depthImageCameraInfoTopicName``, depth/camera_info), and the organised point cloud
    (``pointCloudTopicName``, points: x y z rgb in the optical frame, x right, y down, z
    ahead; NaN where the depth image has none; dense unless a point is NaN; the colour
    bytes in the image's order), as gazebo_plugins fills them (a pixel's ray through
    (width - 1) / 2). Images, depth images and clouds go out at every frame of the sensor;
    the plugin's ``updateRate`` throttles the two infos alone. Noetic's
    gazebo_ros_depth_camera publishes no info at all (its PublishCameraInfo is never called,
    gazebo_plugins/src/gazebo_ros_depth_camera.cpp:477, gazebo_ros_pkgs issue #1174): that
    fault is not copied, both plugins publish them as the openni one does."""

    PLUGIN_RATE_THROTTLES_FRAMES = False

    def __init__(self, context, spec, sensor):
        super().__init__(context, spec, sensor)
        self.cutoff = self.number("pointCloudCutoff", 0.4)
        self.cutoff_max = (self.number("pointCloudCutoffMax", 5.0)
                           if spec.filename == CUTOFF_MAX_PLUGIN else np.inf)
        # sdformat's Get<bool> (gazebo_plugins/src/gazebo_ros_openni_kinect.cpp:110-114,
        # gazebo_ros_depth_camera.cpp:136-140)
        self.depth_16uc1 = self.flag("useDepth16UC1Format", False)
        # each info goes out once at least 1/updateRate s of sensor time have passed since
        # it last did (gazebo_plugins/src/gazebo_ros_camera_utils.cpp:679-686,
        # gazebo_ros_openni_kinect.cpp:474-493), each on its own clock
        self.info_throttle = Throttle(self.plugin_rate)
        self.depth_info_throttle = Throttle(self.plugin_rate)
        self.depth_out = self.publisher("depthImageTopicName", "depth/image_raw", Image)
        self.depth_info_out = self.publisher("depthImageCameraInfoTopicName",
                                             "depth/camera_info", CameraInfo)
        self.points_out = self.publisher("pointCloudTopicName", "points", PointCloud2)
        view = self.view
        # each pixel's ray, per metre of depth, in the optical frame (Gazebo's angles)
        columns = (np.arange(view.width) - 0.5 * (view.width - 1)) / view.focal_length
        rows = (np.arange(view.height) - 0.5 * (view.height - 1)) / view.focal_length
        self.ray_x, self.ray_y = np.meshgrid(columns, rows)

    def active(self) -> bool:
        listened = self.context.bus.listened
        return super().active() or any(listened(out) for out in (
            self.depth_out, self.depth_info_out, self.points_out))

    def depth_image(self, depth: np.ndarray) -> np.ndarray:
        """32-bit metres, NaN outside the cutoffs (no far one but the openni plugin's)."""
        inside = depth > self.cutoff
        if np.isfinite(self.cutoff_max):
            inside &= depth < self.cutoff_max
        return np.where(inside, depth, np.nan).astype(np.float32)

    def depth_message(self, header_stamp, depth: np.ndarray) -> Image:
        """The depth image as published: 32FC1 metres, or with useDepth16UC1Format 16UC1
        millimetres (the 32-bit metres times 1000, the fraction dropped as C++'s conversion
        does) and 0 where the 32-bit image has NaN (gazebo_plugins/src/
        gazebo_ros_depth_camera.cpp:737-775, gazebo_ros_openni_kinect.cpp:429-468). A depth
        of MAX_DEPTH_16UC1 mm or more (nothing seen: +inf) does not fit 16 bits, where
        C++'s conversion is undefined; here it is 0, REP 118's "no reading"."""
        metres = self.depth_image(depth)
        if not self.depth_16uc1:
            return self.image(header_stamp, metres[:, :, None], "32FC1")
        millimetres = np.floor(metres.astype(np.float64) * MILLIMETRES_PER_METRE)
        valid = np.isfinite(millimetres) & (millimetres < MAX_DEPTH_16UC1)
        fixed = np.where(valid, millimetres, 0.0).astype(np.uint16)
        return self.image(header_stamp, fixed[:, :, None], "16UC1")

    def points(self, header_stamp, pixels: np.ndarray, depth: np.ndarray) -> PointCloud2:
        metres = self.depth_image(depth)
        cloud = np.zeros((self.view.height, self.view.width), dtype=POINT_XYZRGB)
        cloud["x"], cloud["y"], cloud["z"] = self.ray_x * metres, self.ray_y * metres, metres
        # the rgb field's first three bytes are the published image's pixel bytes in their
        # order (a mono pixel thrice), the fourth 0 (gazebo_plugins/src/
        # gazebo_ros_depth_camera.cpp:692-713, gazebo_ros_openni_kinect.cpp:379-400): an
        # R8G8B8 camera's cloud has red in the lowest byte, where PCL reads blue
        rgb = pixels if pixels.shape[2] == 3 else np.repeat(pixels, 3, axis=2)
        colour = np.zeros((self.view.height, self.view.width, 4), dtype=np.uint8)
        colour[:, :, :3] = rgb
        cloud["rgb"] = colour.view(np.float32)[:, :, 0]
        message = PointCloud2()
        message.header.stamp, message.header.frame_id = header_stamp, self.frame_id
        message.height, message.width = cloud.shape
        message.fields = [PointField(name, offset, PointField.FLOAT32, 1)
                          for name, offset in (("x", 0), ("y", 4), ("z", 8), ("rgb", 16))]
        message.is_bigendian = False
        message.point_step = POINT_XYZRGB.itemsize
        message.row_step = POINT_XYZRGB.itemsize * cloud.shape[1]
        # true unless a point is NaN, cut off (gazebo_plugins/src/
        # gazebo_ros_depth_camera.cpp:641, :684; gazebo_ros_openni_kinect.cpp:333, :375)
        message.is_dense = not bool(np.isnan(metres).any())
        message.data = cloud.tobytes()
        return message

    def publish(self, now_ns: int, pixels: np.ndarray, depth: np.ndarray) -> None:
        header_stamp = stamp(now_ns)
        listened = self.context.bus.listened
        self.image_out.publish(self.image(header_stamp, pixels, self.view.encoding))
        self.depth_out.publish(self.depth_message(header_stamp, depth))
        if listened(self.points_out):
            self.points_out.publish(self.points(header_stamp, pixels, depth))
        for out, throttle in ((self.info_out, self.info_throttle),
                              (self.depth_info_out, self.depth_info_throttle)):
            if listened(out) and throttle.ready(now_ns):
                throttle.mark(now_ns)
                out.publish(self.info_message(header_stamp))


@dataclasses.dataclass
class Head:
    """One ``<camera name="...">`` of a multicamera sensor: its element, its ``<pose>`` in
    the sensor's frame, the suffix of its camera name and its CameraInfo baseline."""
    element: object
    position: Tuple[float, float, float]
    orientation: Tuple[float, float, float, float]
    suffix: str
    baseline: float


class MultiCamera(Plugin):
    EMPTY_NAMESPACE_IS_MODEL = True  # GazeboRosCameraUtils reads it by GetRobotNamespace

    """gazebo_ros_multicamera on a ``multicamera`` sensor, as gazebo_plugins does it: a
    camera whose name contains ``left`` publishes under ``<cameraName>/left`` with a
    baseline of 0, one whose name contains ``right`` under ``<cameraName>/right`` with the
    plugin's ``hackBaseline`` in its CameraInfo (P's fourth column, -f * baseline); the
    others publish nothing (a warning names them). Each ``<camera>`` has its own ``<pose>``
    in the sensor's frame, image and lens; all share the sensor's rate and ``frameName``
    and are taken at the same step, as the plugin synchronises their shutters."""

    def __init__(self, context, spec, sensor):
        super().__init__(context, spec)
        baseline = self.number("hackBaseline", 0.0)
        self.cameras = []
        for element in sensor.element.findall("camera"):
            name = element.get("name", "")
            side = "left" if "left" in name else "right" if "right" in name else None
            if side is None:
                context.bus.warn(f"model '{context.model_name}': sensor '{sensor.name}': camera "
                                 f"'{name}' is named neither left nor right, so "
                                 "gazebo_ros_multicamera publishes nothing of it; ignored")
                continue
            position, orientation = element_pose(
                element, f"sensor '{sensor.name}': camera '{name}'")
            head = Head(element, position, orientation, f"/{side}",
                        baseline if side == "right" else 0.0)
            self.cameras.append(Camera(context, spec, sensor, head))
        if not self.cameras:
            raise PluginError(f"sensor '{sensor.name}' of type multicamera has no <camera> "
                              "named left or right")

    def reset(self, now_ns: int) -> None:
        for camera in self.cameras:
            camera.reset(now_ns)

    def quiet_until_ns(self, now_ns: int, step_ns: int) -> int:
        return min(camera.quiet_until_ns(now_ns, step_ns) for camera in self.cameras)

    def after_step(self, now_ns: int) -> None:
        for camera in self.cameras:
            camera.after_step(now_ns)

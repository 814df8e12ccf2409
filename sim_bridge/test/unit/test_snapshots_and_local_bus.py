"""Headless pictures (sim_bridge.snapshots) and the in-process bus (sim_bridge.local_bus)."""
import shutil

import numpy as np
import pytest
from geometry_msgs.msg import Twist

from sim_bridge.local_bus import LocalBus
from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec
from sim_bridge.snapshots import render, write_gif, write_ppm
from sim_bridge.world import World
from world_fixtures import run


def test_a_red_box_is_drawn_red_in_the_middle_of_the_picture():
    world = World(LocalBus())
    try:
        world.add_sdf_model(ModelSpec("box", True, links=[LinkSpec(
            "link", collisions=[ShapeSpec("box", size=(0.5, 0.5, 0.5))],
            visuals=[ShapeSpec("box", size=(0.5, 0.5, 0.5), rgba=(1, 0, 0, 1))])]))
        picture = render(world.client, eye=(3, 0, 0), target=(0, 0, 0), width=64, height=48)
    finally:
        world.close()
    assert picture.shape == (48, 64, 3) and picture.dtype == np.uint8
    red, green, blue = (picture[22:26, 30:34, channel].astype(int) for channel in range(3))
    assert (red > 2 * green + 40).all() and (red > 2 * blue + 40).all()
    corner = picture[0, 0].astype(int)
    assert not (corner[0] > 2 * corner[1] + 40)  # the corner is background, not box


def test_ppm_frames_become_a_looping_gif(tmp_path):
    if shutil.which("convert") is None:
        pytest.skip("ImageMagick is not installed")
    frames = []
    for index, colour in enumerate([(255, 0, 0), (0, 0, 255)]):
        frames.append(str(tmp_path / f"{index}.ppm"))
        write_ppm(frames[-1], np.full((8, 12, 3), colour, dtype=np.uint8))
    with open(frames[0], "rb") as stream:
        assert stream.read(11) == b"P6 12 8 255"
    write_gif(frames, str(tmp_path / "out.gif"), frame_seconds=0.1)
    assert (tmp_path / "out.gif").read_bytes()[:6] == b"GIF89a"


def test_the_local_bus_carries_commands_to_the_drive_plugin(diff_bot_xml):
    bus = LocalBus()
    world = World(bus, ray_threads=1)
    try:
        world.add_sdf_model(ModelSpec("ground", True, links=[
            LinkSpec("link", collisions=[ShapeSpec("plane")])]))
        world.spawn_urdf("bot", diff_bot_xml(), (0, 0, 0.01))
        heard = []
        bus.subscriber("/odom", None, heard.append)
        forward = Twist()
        forward.linear.x = 0.5
        bus.publish("/cmd_vel", forward)
        run(world, 2.0)
        assert world.pose("bot")[0][0] > 0.8  # 0.5 m/s for 2 s, minus the start
        assert heard and heard[-1].twist.twist.linear.x == pytest.approx(0.5, abs=0.05)
    finally:
        world.close()

"""<heightmap> terrain in a world file, as Gazebo 11's ODE builds it (gazebo 11.10.2,
gazebo/physics/HeightmapShape.cc, gazebo/common/ImageHeightmap.cc,
gazebo/physics/ode/ODEHeightmapShape.cc; see sim_bridge.heightmap): a ball dropped on it
rests at the height the image gives, a ray cast down and a laser's beams meet it, the
image's first row lies along +y and its first column along -x, and an image that is not
square with a side of 2^n+1 is refused with Gazebo's error. The PNG files are written
here (PNG's encoding, zlib and the five row filters; no image library is needed)."""
import math
import struct
import zlib

import numpy as np
import pytest

from sim_bridge.heightmap import grid_heights, image_levels, read_png, sampling_of
from sim_bridge.sdf_world import LinkSpec, ModelSpec, ShapeSpec, load_world, parse_model
from sim_bridge.world import World
from world_fixtures import run

SIDE = 33  # pixels: 2^5 + 1
SIZE = (16.0, 16.0, 2.0)  # m: 0.5 m a pixel, 2 m the brightest grey
POS_Z = 0.5  # m: <pos> z, ODE's offset of every height
LOW, HIGH = 64, 255  # the ground's and the plateau's grey
PLATEAU = slice(2, 13)  # the image's rows and columns 2-12: its top-left corner
BALL_RADIUS = 0.1


def write_png(path, pixels, filters=(0,)):
    """An 8-bit PNG of ``pixels`` ((rows, columns) grey or (rows, columns, 3) RGB), row r
    filtered with ``filters[r % len(filters)]`` (PNG spec 9.2: None, Sub, Up, Average,
    Paeth)."""
    pixels = np.asarray(pixels, dtype=np.uint8)
    channels = 1 if pixels.ndim == 2 else pixels.shape[2]
    rows = pixels.reshape(pixels.shape[0], -1).astype(int)
    encoded, previous = [], np.zeros(rows.shape[1], dtype=int)
    for index, row in enumerate(rows):
        kind = filters[index % len(filters)]
        left = np.concatenate([np.zeros(channels, dtype=int), row[:-channels]])
        corner = np.concatenate([np.zeros(channels, dtype=int), previous[:-channels]])
        if kind == 0:
            guess = np.zeros_like(row)
        elif kind == 1:
            guess = left
        elif kind == 2:
            guess = previous
        elif kind == 3:
            guess = (left + previous) // 2
        else:
            estimate = left + previous - corner
            to_left, to_up = abs(estimate - left), abs(estimate - previous)
            to_corner = abs(estimate - corner)
            guess = np.where((to_left <= to_up) & (to_left <= to_corner), left,
                             np.where(to_up <= to_corner, previous, corner))
        encoded.append(bytes([kind]) + ((row - guess) % 256).astype(np.uint8).tobytes())
        previous = row

    def chunk(kind, body):
        return (struct.pack(">I", len(body)) + kind + body
                + struct.pack(">I", zlib.crc32(kind + body)))

    colour = 0 if channels == 1 else 2
    header = struct.pack(">IIBBBBB", pixels.shape[1], pixels.shape[0], 8, colour, 0, 0, 0)
    with open(path, "wb") as stream:
        stream.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header)
                     + chunk(b"IDAT", zlib.compress(b"".join(encoded))) + chunk(b"IEND", b""))


def plateau_image(side=SIDE):
    grey = np.full((side, side), LOW, dtype=np.uint8)
    grey[PLATEAU, PLATEAU] = HIGH
    return grey


def world_file(folder, uri, size=SIZE, extra=""):
    path = folder / "terrain.world"
    path.write_text(f"""<sdf version="1.6"><world name="w">
  <model name="terrain"><static>true</static><link name="link">
    <collision name="collision"><geometry><heightmap><uri>{uri}</uri>
      <size>{' '.join(map(str, size))}</size><pos>0 0 {POS_Z}</pos>{extra}</heightmap>
    </geometry></collision>
    <visual name="visual"><geometry><heightmap><uri>{uri}</uri>
      <size>{' '.join(map(str, size))}</size><pos>0 0 {POS_Z}</pos>
      <texture><diffuse>file://media/materials/textures/dirt_diffusespecular.png</diffuse>
        <normal>file://media/materials/textures/flat_normal.png</normal><size>1</size>
      </texture><use_terrain_paging>false</use_terrain_paging></heightmap></geometry></visual>
  </link></model></world></sdf>""")
    return str(path)


@pytest.fixture
def terrain(bus, tmp_path):
    """A world of the plateau terrain alone (no ground plane)."""
    write_png(tmp_path / "plateau.png", plateau_image())
    simulated = World(bus, ray_threads=1)
    simulated.load_world(load_world(world_file(tmp_path, "plateau.png"), warn=bus.warn))
    yield simulated
    simulated.close()


def drop_ball(world, name, x, y, z=4.0):
    world.add_sdf_model(ModelSpec(name, False, pose=(x, y, z, 0, 0, 0), links=[LinkSpec(
        "link", collisions=[ShapeSpec("sphere", radius=BALL_RADIUS)], mass=0.5,
        inertia=(0.002, 0.002, 0.002))]))


HIGH_Z = POS_Z + SIZE[2]  # the plateau: the brightest grey is size.z high
LOW_Z = POS_Z + SIZE[2] * LOW / HIGH


@pytest.mark.parametrize("x, y, ground", [
    (-4.5, 4.5, HIGH_Z),   # the image's top-left: -x, +y
    (4.5, -4.5, LOW_Z),
    (4.5, 4.5, LOW_Z),     # where the plateau would be if the rows ran along -y
    (-4.5, -4.5, LOW_Z),   # ... or the columns along +x
])
def test_a_ball_rests_at_the_height_the_image_gives(terrain, bus, x, y, ground):
    drop_ball(terrain, "ball", x, y)
    run(terrain, 2.0)
    position = terrain.pose("ball")[0]
    assert position[2] == pytest.approx(ground + BALL_RADIUS, abs=0.015)
    assert position[:2] == pytest.approx((x, y), abs=0.01)  # flat there: it stays
    assert not bus.warnings


def test_a_ray_down_reads_the_terrain(terrain):
    """What lasers cast through (World.cast_rays) meets the terrain: rays straight down
    from 5 m at the plateau, the ground and across the ramp between them (the plateau's
    edge pixel, column 12 at x = -2, to column 13 at x = -1.5, bilinear)."""
    origins = [(-4.5, 4.5), (4.5, -4.5), (-1.75, 4.5)]
    expected = [HIGH_Z, LOW_Z, (HIGH_Z + LOW_Z) / 2]
    for (x, y), height in zip(origins, expected):
        distance = terrain.cast_rays((x, y, 5.0), np.array([[0.0, 0.0, -1.0]]), 0.0, 10.0)
        assert 5.0 - distance[0] == pytest.approx(height, abs=0.01)


def test_a_laser_sees_the_plateaus_side(terrain, bus):
    """A robot on the low ground 3 m east of the plateau's side (x = -2 to -1.5, the
    ramp between the plateau's last column and the ground's first), its laser 0.3 m up
    looking west: the beam meets the ramp where it is 0.3 m above the ground."""
    robot = f"""<robot name="scout"><link name="base"><inertial><mass value="5"/>
      <inertia ixx="0.05" ixy="0" ixz="0" iyy="0.05" iyz="0" izz="0.05"/></inertial>
      <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link>
      <gazebo reference="base"><sensor type="ray" name="scanner">
        <pose>0 0 0.2 0 0 {math.pi}</pose><update_rate>20</update_rate>
        <ray><scan><horizontal><samples>3</samples><min_angle>-0.05</min_angle>
        <max_angle>0.05</max_angle></horizontal></scan>
        <range><min>0.1</min><max>10</max></range></ray>
        <plugin name="p" filename="libgazebo_ros_laser.so"><topicName>scan</topicName>
          <frameName>base</frameName></plugin></sensor></gazebo></robot>"""
    terrain.spawn_urdf("scout", robot, (1.5, 4.5, LOW_Z + 0.15))
    run(terrain, 1.0)
    (x, _, z), _ = terrain.pose("scout")
    beam_height = z + 0.2 - LOW_Z  # above the ground
    ramp_x = -1.5 - 0.5 * beam_height / (HIGH_Z - LOW_Z)  # where the ramp is that high
    assert bus.last("/scan").ranges[1] == pytest.approx(x - ramp_x, abs=0.02)


def test_the_image_sampled_as_gazebo_samples_it():
    """ImageHeightmap::FillHeightMap (gazebo/common/ImageHeightmap.cc:66-107) with
    HeightmapShape::Init's count and scale (HeightmapShape.cc:239-257): 2 samples a pixel
    make 2·3 − 2 + 1 = 5 vertices a side, the ones between pixels the bilinear mix; the
    brightest pixel (128 here) is size.z high; a negative size.z turns h into 1 − h."""
    levels = np.array([[0, 128, 0], [0, 0, 0], [64, 0, 0]], dtype=np.uint8)
    heights = grid_heights(levels, 128 / 255, 3.0, 2)
    assert heights.shape == (5, 5)
    assert heights[0] == pytest.approx([0, 1.5, 3.0, 1.5, 0], abs=1e-6)
    assert heights[1, 1] == pytest.approx(0.75, abs=1e-6)  # the mean of 0, 3, 0, 0
    assert heights[4, 0] == pytest.approx(1.5, abs=1e-6)
    assert grid_heights(levels, 128 / 255, -3.0, 2)[0, 2] == pytest.approx(1 - 3.0, abs=1e-6)
    assert grid_heights(np.zeros((3, 3), np.uint8), 0.0, 3.0, 2).max() == 0.0


def test_a_colour_image_is_read_by_its_blue_byte():
    """Gazebo 11 on a little-endian machine reads the first byte of each pixel in
    FreeImage's memory, which keeps BGR order (ImageHeightmap.cc:86-91), and
    Image::MaxColor's R(), the blue of the pixel with the greatest r+g+b
    (gazebo/common/Image.cc:345-367, Pixel's BGR swap)."""
    pixels = np.zeros((3, 3, 3), dtype=np.uint8)
    pixels[0, 0] = (255, 0, 10)   # r+g+b 265, the brightest: its blue, 10, is the top
    pixels[1, 1] = (0, 0, 200)    # r+g+b 200: higher blue, not the brightest
    levels, brightest = image_levels(pixels)
    assert levels[0, 0] == 10 and levels[1, 1] == 200
    assert brightest == pytest.approx(10 / 255)


@pytest.mark.parametrize("filters", [(0,), (1,), (2,), (3,), (4,), (0, 1, 2, 3, 4)])
def test_png_rows_filtered_every_way_read_back(tmp_path, filters):
    rng = np.random.default_rng(7)
    pixels = rng.integers(0, 256, (9, 9, 3), dtype=np.uint8)
    write_png(tmp_path / "p.png", pixels, filters)
    assert (read_png(str(tmp_path / "p.png")) == pixels).all()
    grey = rng.integers(0, 256, (9, 9), dtype=np.uint8)
    write_png(tmp_path / "g.png", grey, filters)
    assert (read_png(str(tmp_path / "g.png"))[:, :, 0] == grey).all()


@pytest.mark.parametrize("shape", [(32, 32), (33, 17)])
def test_an_image_not_square_of_side_2n_plus_1_is_refused_with_gazebos_error(
        bus, tmp_path, shape):
    """HeightmapShape.cc:195-201: "Heightmap data size must be square, with a size of
    2^n+1"; the terrain is left out, the world loads (a ball dropped there falls)."""
    write_png(tmp_path / "bad.png", np.zeros(shape, dtype=np.uint8))
    messages = []
    spec = load_world(world_file(tmp_path, "bad.png"), warn=messages.append)
    (message,) = messages
    assert "Heightmap data size must be square, with a size of 2^n+1" in message
    assert f"{shape[1]} x {shape[0]}" in message and "bad.png" in message
    simulated = World(bus, ray_threads=1)
    simulated.load_world(spec)
    drop_ball(simulated, "ball", 0.0, 0.0, 1.0)
    run(simulated, 0.5)
    assert simulated.pose("ball")[0][2] < 0.0
    simulated.close()


def test_model_and_file_uris_are_found(bus, tmp_path, monkeypatch):
    """model://NAME/... through GAZEBO_MODEL_PATH, file:// with an absolute path."""
    textures = tmp_path / "models" / "hills" / "materials" / "textures"
    textures.mkdir(parents=True)
    write_png(textures / "plateau.png", plateau_image())
    monkeypatch.setenv("GAZEBO_MODEL_PATH", str(tmp_path / "models"))
    for uri in ("model://hills/materials/textures/plateau.png",
                f"file://{textures / 'plateau.png'}"):
        messages = []
        simulated = World(bus, ray_threads=1)
        simulated.load_world(load_world(world_file(tmp_path, uri), warn=messages.append))
        assert not messages
        distance = simulated.cast_rays((-4.5, 4.5, 5.0), np.array([[0.0, 0.0, -1.0]]), 0, 10)
        assert 5.0 - distance[0] == pytest.approx(HIGH_Z, abs=0.01)
        simulated.close()


@pytest.mark.parametrize("text, sampling, error", [
    (None, 2, False), ("1", 1, False), ("4", 4, False), ("3", 2, True), ("0", 2, True)])
def test_sampling_is_a_power_of_two_else_two(text, sampling, error):
    """HeightmapShape.cc:179-193."""
    value, message = sampling_of(text)
    assert value == sampling and (message is not None) == error


def test_pos_x_and_y_do_not_move_the_collision(bus, tmp_path):
    """ODE takes pos z alone (ODEHeightmapShape.cc:113-125); Gazebo draws the terrain
    shifted by pos x and y (gazebo/rendering/Heightmap.cc:565-572) and collides where ODE
    put it: the plateau stays at the image's top-left, and a warning says so."""
    write_png(tmp_path / "plateau.png", plateau_image())
    path = world_file(tmp_path, "plateau.png")
    with open(path) as stream:
        text = stream.read().replace(f"<pos>0 0 {POS_Z}</pos>", f"<pos>3 0 {POS_Z}</pos>", 1)
    with open(path, "w") as stream:
        stream.write(text)
    messages = []
    simulated = World(bus, ray_threads=1)
    simulated.load_world(load_world(path, warn=messages.append))
    (message,) = messages
    assert "<pos> x and y (3, 0)" in message
    distance = simulated.cast_rays((-4.5, 4.5, 5.0), np.array([[0.0, 0.0, -1.0]]), 0, 10)
    assert 5.0 - distance[0] == pytest.approx(HIGH_Z, abs=0.01)
    simulated.close()


def test_a_spawned_terrain_model_is_static_without_saying_so(world, tmp_path):
    """spawn_sdf_model's path: a model with a heightmap collision and no <static> stays
    where it is, as Gazebo makes its link static (gazebo/physics/Link.cc:695-696); a ball
    rests on it."""
    write_png(tmp_path / "plateau.png", plateau_image())
    model = parse_model(f"""<sdf version="1.6"><model name="hills"><pose>0 0 1 0 0 0</pose>
      <link name="link"><collision name="c"><geometry><heightmap>
        <uri>file://{tmp_path / 'plateau.png'}</uri><size>{' '.join(map(str, SIZE))}</size>
      </heightmap></geometry></collision></link></model></sdf>""", "hills.sdf")
    assert model.static
    world.add_sdf_model(model)
    drop_ball(world, "ball", -4.5, 4.5, 5.0)
    run(world, 2.0)
    assert world.pose("hills")[0] == pytest.approx((0, 0, 1))
    assert world.pose("ball")[0][2] == pytest.approx(1 + SIZE[2] + BALL_RADIUS, abs=0.015)

"""``<heightmap>`` terrain as Gazebo 11's ODE makes it, as a pybullet height field.

Gazebo 11.10.2 (gazebo-classic, Debian's import of the release tarball, tag
upstream/11.10.2+dfsg 4dce643; the Noetic era's Gazebo) reads a heightmap this way:

- the image (``<uri>``, ``model://``, ``file://`` or relative) must be square with a side
  of 2^n+1 pixels, else "Heightmap data size must be square, with a size of 2^n+1"
  (gazebo/physics/HeightmapShape.cc:195-201). Gazebo carries on in an undefined state
  after that error (its own tests of such worlds are commented out,
  test/integration/heightmap.cc:284-311); here the terrain is left out, with the error;
- ``<sampling>`` (default 2, a power of 2, else an error and 2: HeightmapShape.cc:179-193)
  samples per pixel: the grid is ``side·s − s + 1`` vertices a side (:239-240), each the
  bilinear mix of the four pixels around it, read as the first byte of each pixel in
  memory over 255 (gazebo/common/ImageHeightmap.cc:66-94): the grey level of a grey or
  palette image, FreeImage's blue byte of a colour one on a little-endian machine;
- heights are those fractions times |size.z| / the image's brightest value
  (HeightmapShape.cc:246-257; ``Image::MaxColor``, the pixel with the greatest r+g+b,
  gazebo/common/Image.cc:345-367): the brightest pixel is size.z high, black is 0; a
  negative size.z turns each height h into 1 − h (ImageHeightmap.cc:96-100);
- ODE builds the field size.x by size.y metres centred on the collision's origin, the
  heights offset by pos.z (gazebo/physics/ode/ODEHeightmapShape.cc:113-125), turned so
  that the image's first row lies along +y and its first column along −x (the field's
  rows along ODE's local z, turned a quarter about x, :134-161). pos.x and pos.y move
  Gazebo's drawing of the terrain (gazebo/rendering/Heightmap.cc:565-572) and not its
  collision: here the collision is where ODE puts it, and a warning says so;
- a link with a heightmap collision is static (gazebo/physics/Link.cc:695-696).

pybullet's height field centres itself on the middle of its lowest and highest heights;
the body is placed that much higher. Bullet cuts each grid cell into two triangles, as ODE
does; the diagonal may differ, which moves a point inside a cell by at most the cell's
bend (a bilinear image sampled twice a pixel bends little). Images are read by
:func:`read_png` (PNG only, 8 bits a channel: Gazebo 11 reads 16-bit images wrongly and
also takes JPEG and BMP, which need an image library this workspace does not have).

pybullet builds a large field slowly (shape and body, measured on the 2-core VM): 1.0 s for
the 257 × 257 vertices of a 129-pixel image at Gazebo's default sampling of 2, 3.1 s for a
257-pixel image's 513 × 513, 12 s for a 513-pixel image's 1025 × 1025.
"""
from __future__ import annotations

import os
import struct
import zlib
from dataclasses import dataclass
from typing import Optional, Sequence, Tuple

import numpy as np

# HeightmapShape.cc:179: samples per pixel when <sampling> is absent or not a power of 2
DEFAULT_SAMPLING = 2
# ImageHeightmap.cc:86-91: a byte's fraction of full height
FULL_BYTE = 255.0

_PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
# bytes per pixel of an 8-bit PNG by colour type (PNG spec 11.2.2): grey, RGB, palette,
# grey and alpha, RGBA
_PNG_CHANNELS = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}


class HeightmapError(ValueError):
    """A heightmap Gazebo would not build; the message says why in Gazebo's words."""


def read_png(path: str) -> np.ndarray:
    """The pixels of an 8-bit, non-interlaced PNG file as an (rows, columns, channels)
    uint8 array, the top row first (PNG's order, as FreeImage's raw bits with top-down
    set, gazebo/common/Image.cc GetDataImpl)."""
    with open(path, "rb") as stream:
        data = stream.read()
    if not data.startswith(_PNG_SIGNATURE):
        raise HeightmapError("is not a PNG image (sim_bridge reads heightmaps from PNG "
                             "files; Gazebo 11 also reads JPEG and BMP)")
    offset, header, compressed = len(_PNG_SIGNATURE), None, []
    while offset + 8 <= len(data):
        length, kind = struct.unpack(">I4s", data[offset:offset + 8])
        body = data[offset + 8:offset + 8 + length]
        offset += 12 + length  # length, type, data, CRC
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            compressed.append(body)
        elif kind == b"IEND":
            break
    if header is None or not compressed:
        raise HeightmapError("is not a complete PNG image (no header or no pixel data)")
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in _PNG_CHANNELS or interlace:
        raise HeightmapError(
            f"is a PNG of {depth} bits a channel, colour type {colour}"
            f"{', interlaced' if interlace else ''}; sim_bridge reads 8-bit, non-interlaced "
            "PNG heightmaps (Gazebo 11 reads a 16-bit one's low bytes)")
    channels = _PNG_CHANNELS[colour]
    try:
        raw = np.frombuffer(zlib.decompress(b"".join(compressed)), dtype=np.uint8)
    except zlib.error as error:
        raise HeightmapError(f"is a damaged PNG image ({error})") from None
    stride = width * channels
    if raw.size < height * (stride + 1):
        raise HeightmapError("is a truncated PNG image")
    rows = raw[:height * (stride + 1)].reshape(height, stride + 1)
    return _unfilter(rows, channels).reshape(height, width, channels)


def _unfilter(rows: np.ndarray, channels: int) -> np.ndarray:
    """PNG's five row filters undone (PNG spec 9.2), row by row."""
    height, width = rows.shape[0], rows.shape[1] - 1
    out = np.zeros((height, width), dtype=np.uint8)
    previous = np.zeros(width, dtype=np.int32)
    for index in range(height):
        kind, line = rows[index, 0], rows[index, 1:].astype(np.int32)
        if kind == 0:
            current = line
        elif kind == 1:  # Sub: the same channel's byte of the pixel to the left
            current = _running_sum(line, channels)
        elif kind == 2:  # Up
            current = (line + previous) & 0xFF
        elif kind in (3, 4):  # Average, Paeth: each byte depends on the one just made
            current = line.copy()
            for byte in range(width):
                left = current[byte - channels] if byte >= channels else 0
                up = previous[byte]
                if kind == 3:
                    guess = (left + up) // 2
                else:
                    corner = previous[byte - channels] if byte >= channels else 0
                    guess = _paeth(left, up, corner)
                current[byte] = (line[byte] + guess) & 0xFF
        else:
            raise HeightmapError(f"is a damaged PNG image (row filter {kind})")
        out[index] = current
        previous = current
    return out


def _running_sum(line: np.ndarray, channels: int) -> np.ndarray:
    """Sub's byte-wise running sum modulo 256 along each channel."""
    by_channel = line.reshape(-1, channels)
    return (np.cumsum(by_channel, axis=0) & 0xFF).reshape(-1)


def _paeth(left: int, up: int, corner: int) -> int:
    estimate = left + up - corner
    to_left, to_up, to_corner = abs(estimate - left), abs(estimate - up), abs(estimate - corner)
    if to_left <= to_up and to_left <= to_corner:
        return left
    return up if to_up <= to_corner else corner


def image_levels(pixels: np.ndarray) -> Tuple[np.ndarray, float]:
    """(the byte each pixel is read as, as an (rows, columns) array; the brightest value
    as a fraction of 255) as Gazebo 11 reads them on a little-endian machine: the first
    byte of a pixel in FreeImage's memory (the grey level; the blue byte of a colour image,
    FreeImage keeping BGR order), and Image::MaxColor's R(), which holds that same byte of
    the pixel with the greatest r+g+b, the first found from the bottom row up (FreeImage's
    row order; a strict '>' keeps the first)."""
    channels = pixels.shape[2]
    if channels >= 3:  # RGB, RGBA: blue
        levels = pixels[:, :, 2]
        brightness = pixels[:, :, :3].astype(np.int32).sum(axis=2)
    else:  # grey, palette index, grey and alpha (FreeImage makes it RGBA, all grey)
        levels = pixels[:, :, 0]
        brightness = levels.astype(np.int32)
    bottom_up = np.flipud(brightness).reshape(-1)
    brightest = int(np.argmax(bottom_up))
    return levels, float(np.flipud(levels).reshape(-1)[brightest]) / FULL_BYTE


def grid_heights(levels: np.ndarray, brightest: float, size_z: float,
                 sampling: int) -> np.ndarray:
    """The (vertices, vertices) heights ODE is given, row 0 the image's top row
    (ImageHeightmap::FillHeightMap, gazebo/common/ImageHeightmap.cc:66-107, with
    HeightmapShape::Init's vertex count and z scale, HeightmapShape.cc:239-257)."""
    side = levels.shape[0]
    count = side * sampling - sampling + 1
    scale_z = 1.0 if brightest == 0.0 else abs(size_z) / brightest
    steps = np.arange(count) / float(sampling)
    low = np.floor(steps).astype(int)
    high = np.minimum(np.ceil(steps).astype(int), side - 1)
    frac = steps - low
    value = levels.astype(np.float64) / FULL_BYTE
    # along x within rows low and high, then between the rows (the upstream order)
    row_low = value[low][:, low] - (value[low][:, low] - value[low][:, high]) * frac
    row_high = value[high][:, low] - (value[high][:, low] - value[high][:, high]) * frac
    heights = (row_low - (row_low - row_high) * frac[:, None]) * scale_z
    if size_z < 0:
        heights = 1.0 - heights
    return heights.astype(np.float32).astype(np.float64)


@dataclass
class Heightmap:
    """A terrain ready for pybullet: ``heights`` (vertices × vertices, row 0 along +y,
    column 0 along −x, pos.z included), the field's size in x and y."""

    heights: np.ndarray
    size: Tuple[float, float, float]
    pos: Tuple[float, float, float]
    sampling: int
    image: str

    def shape_arguments(self) -> dict:
        """pybullet's createCollisionShape arguments for a GEOM_HEIGHTFIELD (the caller
        adds the type): its rows run along +y, so the grid's rows go in reversed."""
        count = self.heights.shape[0]
        spacing = (self.size[0] / (count - 1), self.size[1] / (count - 1), 1.0)
        return dict(meshScale=list(spacing),
                    heightfieldData=self.heights[::-1].reshape(-1).tolist(),
                    numHeightfieldRows=count, numHeightfieldColumns=count)

    def centre_height(self) -> float:
        """How far up pybullet's field must be placed for its heights to be the ones given:
        it centres itself between its lowest and highest."""
        return float(self.heights.min() + self.heights.max()) / 2.0


def _vector(text: Optional[str], default: Sequence[float], what: str) -> Tuple[float, ...]:
    if text is None or not text.strip():
        return tuple(float(v) for v in default)
    try:
        values = tuple(float(v) for v in text.split())
    except ValueError:
        values = ()
    if len(values) != 3 or not all(np.isfinite(values)):
        raise HeightmapError(f"<{what}> '{text.strip()}' is not 3 finite numbers")
    return values


def sampling_of(text: Optional[str]) -> Tuple[int, Optional[str]]:
    """<sampling> as HeightmapShape::Load takes it (:179-193): absent, 2; 0 or not a power
    of 2, Gazebo's error and 2. Returns (sampling, the error or None)."""
    if text is None or not text.strip():
        return DEFAULT_SAMPLING, None
    try:
        value = int(text.strip())
    except ValueError:
        value = 0
    if value <= 0 or value & (value - 1):
        return DEFAULT_SAMPLING, (f"<sampling> '{text.strip()}': Heightmap sampling value "
                                  "must be a power of 2. The default value of 2 will be used "
                                  "instead.")
    return value, None


def load_heightmap(element, path: str) -> Tuple[Heightmap, list]:
    """The ``<heightmap>`` element's terrain from the image at ``path`` (already resolved);
    (terrain, notes): the notes are Gazebo's errors it builds the terrain after (a bad
    <sampling>, pos x or y). Raises HeightmapError for what Gazebo cannot build."""
    if not os.path.isfile(path):
        raise HeightmapError("is not found (Unable to find heightmap)")
    pixels = read_png(path)
    rows, columns = pixels.shape[:2]
    if rows != columns or rows < 2 or (rows - 1) & (rows - 2):
        raise HeightmapError(f"is {columns} x {rows} pixels: Heightmap data size must be "
                             "square, with a size of 2^n+1")
    size = _vector(element.findtext("size"), (1.0, 1.0, 1.0), "size")  # heightmap_shape.sdf
    pos = _vector(element.findtext("pos"), (0.0, 0.0, 0.0), "pos")
    sampling, note = sampling_of(element.findtext("sampling"))
    notes = [note] if note else []
    if pos[0] or pos[1]:
        notes.append(f"<pos> x and y ({pos[0]:g}, {pos[1]:g}) move Gazebo's drawing of the "
                     "terrain, not its collision (ODE takes pos z alone): the terrain "
                     "collides at the collision's origin, as in Gazebo")
    levels, brightest = image_levels(pixels)
    heights = grid_heights(levels, brightest, size[2], sampling) + pos[2]
    return Heightmap(heights, size, pos, sampling, path), notes


__all__ = ["DEFAULT_SAMPLING", "Heightmap", "HeightmapError", "grid_heights", "image_levels",
           "load_heightmap", "read_png", "sampling_of"]

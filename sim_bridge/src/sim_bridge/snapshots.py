"""Pictures of a world without a screen: pybullet's software renderer (TinyRenderer) draws
the visuals from a camera, and ImageMagick's ``convert`` turns the frames into a GIF.
Works in a DIRECT (headless) client: no display, no OpenGL."""
from __future__ import annotations

import os
import shutil
import subprocess
from typing import Sequence

import numpy as np
import pybullet as pb


def render(client: int, eye: Sequence[float], target: Sequence[float], width: int = 480,
           height: int = 270, fov_degrees: float = 50.0) -> np.ndarray:
    """The view from ``eye`` towards ``target`` (z up) as an height x width x 3 uint8 array."""
    view = pb.computeViewMatrix(list(eye), list(target), [0, 0, 1], physicsClientId=client)
    projection = pb.computeProjectionMatrixFOV(fov_degrees, width / height, 0.05, 50.0,
                                               physicsClientId=client)
    _, _, rgba, _, _ = pb.getCameraImage(width, height, view, projection,
                                         renderer=pb.ER_TINY_RENDERER,
                                         shadow=0, lightDirection=[1, -1, 2],
                                         physicsClientId=client)
    return np.reshape(np.asarray(rgba, dtype=np.uint8), (height, width, 4))[:, :, :3]


def write_ppm(path: str, rgb: np.ndarray) -> None:
    """Writes an RGB array as a binary PPM (a format every image tool reads)."""
    height, width, _ = rgb.shape
    with open(path, "wb") as stream:
        stream.write(f"P6 {width} {height} 255\n".encode())
        stream.write(np.ascontiguousarray(rgb, dtype=np.uint8).tobytes())


def write_gif(frames: Sequence[str], path: str, frame_seconds: float, colours: int = 64) -> None:
    """Joins image files into a looping GIF with ImageMagick (RuntimeError when missing)."""
    convert = shutil.which("convert")
    if convert is None:
        raise RuntimeError("ImageMagick's 'convert' is needed to write a GIF (apt: imagemagick)")
    delay = max(1, int(round(frame_seconds * 100)))  # GIF delays are in 1/100 s
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    subprocess.run([convert, "-delay", str(delay), "-loop", "0", *frames, "-colors",
                    str(colours), "-layers", "Optimize", path], check=True)

"""Reading rviz screenshots by geometry: where a point of the world lands in the picture
under a saved Orbit view (rviz's OrbitViewController::updateCamera: the camera at
``focal + distance * (cos yaw cos pitch, sin yaw cos pitch, sin pitch)`` looking at the focal
point, z up; Ogre's default vertical field of view, 45 degrees), where the 3D view sits in
the window (its background colour's bounding box), and which pixels have a colour."""
from __future__ import annotations

import math
import subprocess
from typing import Callable, Optional, Tuple

import numpy as np
import yaml

FIELD_OF_VIEW_Y = math.pi / 4   # Ogre::Camera's default FOVy, which rviz keeps


def image(path: str) -> np.ndarray:
    """The picture as an (h, w, 3) array of 0-255 integers."""
    size = subprocess.run(["identify", "-format", "%w %h", path], capture_output=True,
                          text=True, check=True).stdout.split()
    width, height = int(size[0]), int(size[1])
    raw = subprocess.run(["convert", path, "-depth", "8", "rgb:-"], capture_output=True,
                         check=True).stdout
    return np.frombuffer(raw, dtype=np.uint8).reshape(height, width, 3).astype(int)


# a column of the 3D view is mostly its background (scene objects cover its lower part, not
# its upper); widgets have a few such pixels
VIEW_BACKGROUND_SHARE = 0.2
# a row of the window's own light grey, uniform across the view's columns, borders the view
BORDER_BRIGHTNESS = 180
BORDER_SPREAD = 8


def view_rect(picture: np.ndarray, background=(48, 48, 48)) -> Tuple[int, int, int, int]:
    """(left, top, width, height) of the 3D view: the columns its background colour fills a
    good share of, and the rows between the window's light rows above and below it."""
    filled = np.all(picture == np.array(background), axis=2)
    columns = np.nonzero(filled.mean(axis=0) > VIEW_BACKGROUND_SHARE)[0]
    left, right = int(columns.min()), int(columns.max())
    band = picture[:, left:right + 1].mean(axis=2)
    border = (band.min(axis=1) > BORDER_BRIGHTNESS) & \
        (band.max(axis=1) - band.min(axis=1) < BORDER_SPREAD)
    inside = int(np.argmax(filled[:, left:right + 1].mean(axis=1)))
    top = inside
    while top > 0 and not border[top - 1]:
        top -= 1
    bottom = inside
    while bottom + 1 < len(border) and not border[bottom + 1]:
        bottom += 1
    return left, top, right - left + 1, bottom - top + 1


def mask(picture: np.ndarray, test: Callable[[np.ndarray, np.ndarray, np.ndarray], np.ndarray],
         rect: Optional[Tuple[int, int, int, int]] = None) -> np.ndarray:
    """The pixels for which ``test(red, green, blue)`` holds (within ``rect`` when given)."""
    selected = test(picture[..., 0], picture[..., 1], picture[..., 2])
    if rect is not None:
        left, top, width, height = rect
        inside = np.zeros_like(selected)
        inside[top:top + height, left:left + width] = True
        selected &= inside
    return selected


def share_near(selected: np.ndarray, point, radius: float) -> float:
    """The share of the pixels within ``radius`` of ``point`` (x, y) that are selected."""
    rows, columns = np.mgrid[0:selected.shape[0], 0:selected.shape[1]]
    disc = (columns - point[0]) ** 2 + (rows - point[1]) ** 2 < radius ** 2
    return float(selected[disc].mean()) if disc.any() else 0.0


def centroid(selected: np.ndarray) -> Optional[Tuple[float, float]]:
    ys, xs = np.nonzero(selected)
    return (float(xs.mean()), float(ys.mean())) if len(xs) else None


class OrbitView:
    """The saved rviz/Orbit view of an rviz config (its Views: Current)."""

    def __init__(self, config_path: str):
        with open(config_path, encoding="utf-8") as stream:
            current = yaml.safe_load(stream)["Visualization Manager"]["Views"]["Current"]
        assert current["Class"] == "rviz/Orbit", current
        self.distance = float(current["Distance"])
        self.yaw = float(current["Yaw"])
        self.pitch = float(current["Pitch"])
        focal = current["Focal Point"]
        self.focal = np.array([float(focal["X"]), float(focal["Y"]), float(focal["Z"])])

    def project(self, point, rect: Tuple[int, int, int, int]) -> Tuple[float, float]:
        """Pixel (x, y) of a world point (in the fixed frame) in a view at ``rect``."""
        left, top, width, height = rect
        eye = self.focal + self.distance * np.array([
            math.cos(self.yaw) * math.cos(self.pitch), math.sin(self.yaw) * math.cos(self.pitch),
            math.sin(self.pitch)])
        forward = (self.focal - eye) / np.linalg.norm(self.focal - eye)
        right = np.cross(forward, [0.0, 0.0, 1.0])
        right /= np.linalg.norm(right)
        up = np.cross(right, forward)
        offset = np.asarray(point, dtype=float) - eye
        depth = offset @ forward
        half_height = math.tan(FIELD_OF_VIEW_Y / 2)
        x = (offset @ right) / (depth * half_height * width / height)
        y = (offset @ up) / (depth * half_height)
        return left + (x + 1) / 2 * width, top + (1 - y) / 2 * height

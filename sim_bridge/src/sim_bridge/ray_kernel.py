"""The compiled laser kernel (``ray_kernel.c``), loaded with ctypes, and the rows it reads.

The kernel casts all rays of one scan from their common origin against shapes packed as
rows of :data:`STRIDE` doubles (see the C file for the layout). It is built by the catkin
build (sim_bridge/CMakeLists.txt) as ``libsim_bridge_rays.so`` in the devel (or install)
space's ``lib/``; :func:`load` finds it through ``CMAKE_PREFIX_PATH`` (which the
workspace's setup.bash sets) and then the dynamic loader's own search. When it is not
there, :func:`load` says why and the caller falls back to the numpy reference
(:mod:`sim_bridge.ray_caster`), which gives the same distances, slower.

:func:`rows` packs :class:`~sim_bridge.ray_caster.Primitive` shapes, :func:`planes` the
planes of the hulls among them (a hull's row names its first plane and how many it has;
the planes stay in the shape's frame); :class:`PlacedShapes` re-places a moving model's
shapes from its links' frames with a few array operations, so that the shapes of every
robot are placed once per simulated time stamp, for all lasers.
"""
from __future__ import annotations

import ctypes
import os
from typing import Optional, Sequence, Tuple

import numpy as np

from sim_bridge.ray_caster import Primitive

LIBRARY = "libsim_bridge_rays.so"
# the row layout and calling convention shared with ray_kernel.c
STRIDE = 17
VERSION = 2
KIND_CODES = {"box": 0, "cylinder": 1, "sphere": 2, "plane": 3, "hull": 4}
KIND, CENTRE, ROTATION, DIMS, BOUND = 0, slice(1, 4), slice(4, 13), slice(13, 16), 16

_DOUBLES = ctypes.POINTER(ctypes.c_double)


def _dims_and_bound(kind: str, dims: Sequence[float]) -> Tuple[Tuple[float, float, float], float]:
    """The row's dimensions (half sizes, radius and half length, radius) and the radius of
    the shape's bounding sphere about its centre (planes: inf, never culled)."""
    if kind == "box":
        half = tuple(float(v) / 2.0 for v in dims)
        return half, float(np.linalg.norm(half))
    if kind == "cylinder":
        radius, half_length = float(dims[0]), float(dims[1]) / 2.0
        return (radius, half_length, 0.0), float(np.hypot(radius, half_length))
    if kind == "sphere":
        return (float(dims[0]), 0.0, 0.0), float(dims[0])
    if kind == "plane":
        return (0.0, 0.0, 0.0), np.inf
    raise ValueError(f"no analytic ray casting for {kind}")


def rows(primitives: Sequence[Primitive], first_plane: int = 0) -> np.ndarray:
    """The kernel's rows for shapes placed in the world: (len(primitives), STRIDE); the
    hulls' planes are :func:`planes` ``(primitives)`` placed from ``first_plane`` on."""
    packed = np.zeros((len(primitives), STRIDE))
    for row, primitive in zip(packed, primitives):
        transform = np.asarray(primitive.transform, dtype=float)
        row[KIND] = KIND_CODES[primitive.kind]
        row[CENTRE] = transform[:3, 3]
        row[ROTATION] = transform[:3, :3].ravel()
        if primitive.kind == "hull":
            row[DIMS] = (first_plane, len(primitive.planes), 0.0)
            row[BOUND] = float(primitive.dims[0])
            first_plane += len(primitive.planes)
        else:
            row[DIMS], row[BOUND] = _dims_and_bound(primitive.kind, primitive.dims)
    return packed


def planes(primitives: Sequence[Primitive]) -> np.ndarray:
    """The planes of the hulls among ``primitives``, in their order: (P, 4)."""
    stacked = [p.planes for p in primitives if p.kind == "hull"]
    return np.vstack(stacked) if stacked else np.zeros((0, 4))


class PlacedShapes:
    """A moving model's shapes, each fixed in one of its frames (``frame_of[i]`` indexes
    the frames given to :meth:`place`), ``local`` (S, 4, 4) placing it in that frame.
    ``shapes``: each one's kind and dims (and planes) as a Primitive (its transform unused);
    its hulls' planes are :attr:`planes`, to be put from ``first_plane`` on."""

    def __init__(self, shapes: Sequence[Primitive], local: np.ndarray,
                 frame_of: Sequence[int], first_plane: int = 0):
        self.template = rows(shapes, first_plane)
        self.planes = planes(shapes)
        self.local = np.asarray(local, dtype=float).reshape(-1, 4, 4)
        self.frame_of = np.asarray(frame_of, dtype=int)

    def __len__(self):
        return len(self.template)

    def place(self, frames: np.ndarray, out: np.ndarray) -> None:
        """Writes the rows of the shapes for frames (F, 4, 4) in the world into ``out``."""
        if not len(self.template):
            return
        world = np.matmul(np.asarray(frames)[self.frame_of], self.local)
        out[:] = self.template
        out[:, CENTRE] = world[:, :3, 3]
        out[:, ROTATION] = world[:, :3, :3].reshape(-1, 9)


class Kernel:
    """The loaded library: :meth:`cast` one scan."""

    def __init__(self, library: ctypes.CDLL, path: str):
        self.path = path
        self._cast = library.sbr_cast
        self._cast.restype = ctypes.c_int
        self._cast.argtypes = [_DOUBLES, ctypes.c_int, _DOUBLES, _DOUBLES, _DOUBLES,
                               ctypes.c_int, ctypes.c_double, ctypes.c_double, _DOUBLES]

    def cast(self, shapes: np.ndarray, origin: Sequence[float], directions: np.ndarray,
             near: float, far: float, planes: Optional[np.ndarray] = None) -> np.ndarray:
        """Distances from ``origin`` along unit ``directions`` (N, 3) to the first surface
        of ``shapes`` (rows) between ``near`` and ``far``; inf where there is none.
        ``planes``: the hulls' planes the rows index (:func:`planes`)."""
        shapes = np.ascontiguousarray(shapes, dtype=float)
        hulls = shapes[:, KIND] == KIND_CODES["hull"] if len(shapes) else np.zeros(0, bool)
        planes = np.ascontiguousarray(np.zeros((0, 4)) if planes is None else planes,
                                      dtype=float)
        first, count = DIMS.start, DIMS.start + 1
        if hulls.any() and (shapes[hulls, first] + shapes[hulls, count]).max() > len(planes):
            raise ValueError("a hull's row names planes beyond those given")
        origin = np.ascontiguousarray(origin, dtype=float)
        directions = np.ascontiguousarray(directions, dtype=float)
        out = np.empty(len(directions))
        status = self._cast(shapes.ctypes.data_as(_DOUBLES), len(shapes),
                            planes.ctypes.data_as(_DOUBLES),
                            origin.ctypes.data_as(_DOUBLES), directions.ctypes.data_as(_DOUBLES),
                            len(directions), float(near), float(far),
                            out.ctypes.data_as(_DOUBLES))
        if status != 0:
            raise MemoryError(f"the ray kernel could not get memory for {len(shapes)} shapes")
        return out


def _candidates() -> list:
    """Where the catkin build puts the library: <prefix>/lib of every CMAKE_PREFIX_PATH entry
    (devel and install spaces), then the loader's own search (LD_LIBRARY_PATH)."""
    prefixes = [p for p in os.environ.get("CMAKE_PREFIX_PATH", "").split(os.pathsep) if p]
    return [os.path.join(prefix, "lib", LIBRARY) for prefix in prefixes] + [LIBRARY]


_loaded: Optional[Tuple[Optional[Kernel], str]] = None


def load() -> Tuple[Optional[Kernel], str]:
    """(the kernel, its path) or (None, why not); looked for once per process."""
    global _loaded
    if _loaded is None:
        _loaded = _load()
    return _loaded


def _load() -> Tuple[Optional[Kernel], str]:
    errors = []
    for candidate in _candidates():
        if os.sep in candidate and not os.path.exists(candidate):
            continue
        try:
            library = ctypes.CDLL(candidate)
        except OSError as error:
            errors.append(str(error))
            continue
        try:
            stride = library.sbr_stride()
        except AttributeError:
            errors.append(f"{candidate} has no sbr_stride: not sim_bridge's ray kernel")
            continue
        if stride != STRIDE:
            errors.append(f"{candidate} packs {stride} numbers a shape, this module {STRIDE}: "
                          "rebuild the workspace (make)")
            continue
        version = library.sbr_version() if hasattr(library, "sbr_version") else 1
        if version != VERSION:
            errors.append(f"{candidate} is the kernel's version {version}, this module "
                          f"calls version {VERSION}: rebuild the workspace (make)")
            continue
        return Kernel(library, candidate), candidate
    return None, (f"{LIBRARY} not found ({'; '.join(errors) or 'not built'}); build the "
                  "workspace (make) for the compiled ray kernel")


__all__ = ["Kernel", "PlacedShapes", "STRIDE", "load", "planes", "rows"]

"""Mesh files as Gazebo reads them, turned into files pybullet can load.

Gazebo Classic reads Collada (``.dae``), STL (binary and ASCII) and Wavefront OBJ meshes.
pybullet reads OBJ and binary STL only, and badly otherwise (measured with pybullet 3.2.7):

- a Collada file is not read at all;
- an ASCII STL crashes the process (segmentation fault) as a collision shape, and is an
  empty shape in a URDF;
- a missing file refuses the whole URDF; an empty or garbled OBJ or STL becomes a shape
  with nothing in it, without a word: a robot whose collision mesh is garbage falls
  through the floor.

So every mesh is checked here before pybullet sees it, and what pybullet cannot read is
converted, with trimesh (pycollada as its Collada reader), into a Wavefront OBJ in metres:

- Collada's ``<asset><unit meter="...">`` is applied to the whole mesh, node translations
  included, as Gazebo's ColladaLoader does (``mesh->Scale(meter)``);
- Collada's ``<up_axis>`` is read and, as in Gazebo Classic and RViz, **not** applied: the
  vertices are taken in the link's frame as written, whatever the axis says (Gazebo's
  loader never parses it, gazebo-classic issue #1305; RViz neither, rviz issue #1045). A
  ``Y_UP`` file that looks right in Gazebo and RViz looks the same here;
- node transforms (``<matrix>``, ``<translate>``, ``<rotate>``, ``<scale>``) are applied;
  each placed geometry of the file's scene is its own OBJ object (``o``), which pybullet
  makes its own convex hull when the mesh is a moving body's collision (one hull of the
  whole file would fill in what lies between the parts; Gazebo collides with the
  triangles); materials and textures are left out (the URDF's or SDF's colour shows);
- the URDF ``scale`` attribute or SDF ``<scale>`` is not baked in: the caller passes it on
  to pybullet as for any mesh.

Converted files are cached in a folder outside the repository (:func:`cache_folder`),
named by a hash of the source file's real path, size and modification time, so a second
spawn, or the next run of the simulator, loads the OBJ without converting again, and an
edited source file is converted anew. Files are written under a temporary name and
renamed, so two simulators converting the same file at once do not see half a file.

A file that cannot be read raises :class:`MeshError`, whose message says why (no such
file, empty, not a mesh, a format sim_bridge does not read); what to do about it (leave a
visual out, fall back to other collision shapes) is the caller's decision. This module
knows nothing of ROS: trimesh is imported only when a file has to be converted.
"""
from __future__ import annotations

import hashlib
import os
import struct
import tempfile
import xml.etree.ElementTree as ET
from typing import List, Tuple

import numpy as np

# Bumped when the conversion's output changes, so that old cached files are not used.
CONVERTER_VERSION = "2"
READ_FORMATS = "OBJ, STL and Collada (.dae)"
_BINARY_STL_HEADER = 80
_BINARY_STL_TRIANGLE = 50


class MeshError(ValueError):
    """A mesh file that cannot be read; the message says why (not which file: the caller
    names the file, the link and what it does instead)."""


def cache_folder() -> str:
    """Where converted meshes are kept: ``$ROS_HOME/sim_bridge/meshes`` when ROS_HOME is
    set, else ``$XDG_CACHE_HOME/sim_bridge/meshes`` (``~/.cache/sim_bridge/meshes``)."""
    ros_home = os.environ.get("ROS_HOME")
    if ros_home:
        return os.path.join(ros_home, "sim_bridge", "meshes")
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(base, "sim_bridge", "meshes")


def loadable_file(path: str) -> str:
    """The file pybullet should load for the mesh file ``path``: ``path`` itself when it is
    an OBJ or a binary STL, else a Wavefront OBJ in metres converted from it (Collada, ASCII
    STL), from the cache when it is there. Raises :class:`MeshError` saying why the file
    cannot be read."""
    size = _check_file(path)
    extension = os.path.splitext(path)[1].lower()
    if extension == ".obj":
        _check_obj(path)
        return path
    if extension == ".stl":
        if _is_binary_stl(path, size):
            return path
        if not _is_ascii_stl(path):
            raise MeshError("is not an STL file (neither binary nor ASCII STL)")
        return _cached_conversion(path, "stl")
    if extension == ".dae":
        return _cached_conversion(path, "dae")
    raise MeshError(f"is a '{extension or 'extensionless'}' file; sim_bridge reads "
                    f"{READ_FORMATS} meshes, as Gazebo does")


def bounds(path: str) -> Tuple[np.ndarray, np.ndarray]:
    """(lower corner, upper corner) of the mesh file ``path``'s vertices, in metres (a
    Collada file's unit applied), before any URDF or SDF scale. Raises :class:`MeshError`
    as :func:`loadable_file`."""
    vertices = _vertices(loadable_file(path))
    if len(vertices) == 0:
        raise MeshError("has no vertices")
    return vertices.min(axis=0), vertices.max(axis=0)


def collada_unit_and_up_axis(path: str) -> Tuple[float, str]:
    """A Collada file's ``<asset><unit meter>`` (1.0 when absent) and ``<up_axis>``
    (``Y_UP``, COLLADA's default, when absent)."""
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as error:
        raise MeshError(f"is not well-formed XML ({error}), so not a Collada file") from None
    except OSError as error:
        raise MeshError(f"cannot be read ({error.strerror})") from None
    if _local(root.tag) != "COLLADA":
        raise MeshError(f"is not a Collada file (its top element is <{_local(root.tag)}>)")
    meter, up_axis = 1.0, "Y_UP"
    for child in root:
        if _local(child.tag) != "asset":
            continue
        for item in child:
            if _local(item.tag) == "unit" and item.get("meter"):
                try:
                    meter = float(item.get("meter"))
                except ValueError:
                    raise MeshError(f"has <unit meter=\"{item.get('meter')}\">, not a "
                                    "number") from None
            elif _local(item.tag) == "up_axis" and (item.text or "").strip():
                up_axis = item.text.strip()
    if not meter > 0:
        raise MeshError(f"has <unit meter=\"{meter:g}\">; it must be positive")
    return meter, up_axis


# --- checks ---------------------------------------------------------------------------
def collision_fallback(remaining: int, boxes: List[str]) -> str:
    """What stands in for a link's unreadable collision meshes, said in the warning:
    ``remaining`` other collision shapes, else the bounding boxes described in ``boxes``."""
    if remaining:
        return f"the link keeps its {remaining} other collision shape" \
               f"{'s' if remaining > 1 else ''}"
    if boxes:
        return "it is replaced by the bounding box of the link's visual mesh " + ", ".join(boxes)
    return ("the link has no other collision shape and no readable visual mesh: it has no "
            "collision shape (it keeps its inertial)")


def _check_file(path: str) -> int:
    """The size of ``path`` when it is a non-empty readable file; MeshError otherwise."""
    if not os.path.exists(path):
        raise MeshError("does not exist")
    if not os.path.isfile(path):
        raise MeshError("is not a file")
    try:
        with open(path, "rb") as stream:
            stream.read(1)
    except OSError as error:
        raise MeshError(f"cannot be read ({error.strerror})") from None
    size = os.path.getsize(path)
    if size == 0:
        raise MeshError("is empty")
    return size


def _check_obj(path: str) -> None:
    """An OBJ pybullet can use has vertices (``v``) and faces (``f``)."""
    vertices = faces = False
    with open(path, "rb") as stream:
        for line in stream:
            start = line.lstrip()[:2]
            vertices = vertices or start == b"v " or start == b"v\t"
            faces = faces or start == b"f " or start == b"f\t"
            if vertices and faces:
                return
    raise MeshError("is not a Wavefront OBJ mesh (no vertices and faces in it)")


def _is_binary_stl(path: str, size: int) -> bool:
    if size < _BINARY_STL_HEADER + 4:
        return False
    with open(path, "rb") as stream:
        stream.seek(_BINARY_STL_HEADER)
        (count,) = struct.unpack("<I", stream.read(4))
    return count > 0 and size == _BINARY_STL_HEADER + 4 + count * _BINARY_STL_TRIANGLE


def _is_ascii_stl(path: str) -> bool:
    with open(path, "rb") as stream:
        head = stream.read(4096)
    return head.lstrip().lower().startswith(b"solid") and b"facet" in head.lower()


# --- conversion and its cache ---------------------------------------------------------
def _cache_key(path: str) -> str:
    real = os.path.realpath(path)
    status = os.stat(real)
    text = f"{real}\0{status.st_size}\0{status.st_mtime_ns}\0{CONVERTER_VERSION}"
    return hashlib.sha256(text.encode()).hexdigest()[:24]


def _writable_cache_folder() -> str:
    folder = cache_folder()
    try:
        os.makedirs(folder, exist_ok=True)
        if os.access(folder, os.W_OK):
            return folder
    except OSError:
        pass
    # a read-only home: a folder of this user's in the temporary directory
    folder = os.path.join(tempfile.gettempdir(), f"sim_bridge-meshes-{os.getuid()}")
    os.makedirs(folder, exist_ok=True)
    return folder


def _cached_conversion(path: str, kind: str) -> str:
    folder = _writable_cache_folder()
    stem = os.path.splitext(os.path.basename(path))[0]
    target = os.path.join(folder, f"{stem}-{_cache_key(path)}.obj")
    if os.path.isfile(target) and os.path.getsize(target) > 0:
        return target
    _convert(path, kind, target)
    return target


def _convert(path: str, kind: str, target: str) -> None:
    """Converts the mesh file ``path`` (``kind`` dae or stl) into a Wavefront OBJ in
    metres at ``target``."""
    meter = collada_unit_and_up_axis(path)[0] if kind == "dae" else 1.0
    try:
        import trimesh
    except ImportError:
        raise MeshError("needs converting, and the Python package trimesh is missing "
                        "(tools/requirements.txt; run make)") from None
    try:
        # a scene, not one mesh: each placed geometry stays its own OBJ object, which
        # pybullet makes its own convex hull in a moving body's collision shape
        scene = trimesh.load(path, file_type=kind, force="scene", process=False)
    except ImportError as error:  # pycollada, trimesh's Collada reader
        raise MeshError(f"needs converting, and a Python package is missing ({error}; "
                        "tools/requirements.txt, run make)") from None
    except Exception as error:  # pycollada's and trimesh's errors have no common base
        raise MeshError(f"cannot be read as {'Collada' if kind == 'dae' else 'STL'} "
                        f"({type(error).__name__}: {error})") from None
    parts = [part for part in scene.dump()
             if isinstance(part, trimesh.Trimesh) and len(part.faces) > 0]
    if not parts:
        raise MeshError("has no triangles in it")
    lines = [f"# {path} in metres, converted by sim_bridge (mesh_files.py)\n"]
    first_vertex = 1  # OBJ's indices count from 1 over the whole file
    for number, part in enumerate(parts):
        lines.append(f"o part_{number}\n")
        vertices = np.asarray(part.vertices, dtype=float) * meter
        faces = np.asarray(part.faces, dtype=np.int64) + first_vertex
        lines += [f"v {x:.9g} {y:.9g} {z:.9g}\n" for x, y, z in vertices]
        lines += [f"f {a} {b} {c}\n" for a, b, c in faces]
        first_vertex += len(vertices)
    folder = os.path.dirname(target)
    handle, temporary = tempfile.mkstemp(suffix=".obj.part", dir=folder)
    try:
        with os.fdopen(handle, "w") as stream:
            stream.writelines(lines)
        os.replace(temporary, target)
    except BaseException:
        if os.path.exists(temporary):
            os.unlink(temporary)
        raise


def _vertices(path: str) -> np.ndarray:
    """The vertices of an OBJ or binary STL file (what :func:`loadable_file` returns)."""
    if path.lower().endswith(".stl"):
        return stl_vertices(path)
    rows = []
    with open(path, "rb") as stream:
        for line in stream:
            parts = line.split()
            if len(parts) >= 4 and parts[0] == b"v":
                rows.append([float(v) for v in parts[1:4]])
    return np.asarray(rows, dtype=float).reshape(-1, 3)


def stl_vertices(path: str) -> np.ndarray:
    """The corners of a binary STL file's triangles (N, 3)."""
    with open(path, "rb") as stream:
        data = stream.read()
    count = struct.unpack_from("<I", data, _BINARY_STL_HEADER)[0]
    records = np.frombuffer(data, dtype=np.dtype([
        ("normal", "<f4", 3), ("corners", "<f4", (3, 3)), ("attribute", "<u2")]),
        count=count, offset=_BINARY_STL_HEADER + 4)
    return records["corners"].reshape(-1, 3).astype(float)


def _local(tag: str) -> str:
    """An XML tag without its namespace."""
    return tag.rsplit("}", 1)[-1]

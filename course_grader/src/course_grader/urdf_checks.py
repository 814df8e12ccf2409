"""Task 1's requirements read from the submission's URDF, without a master: link and joint
names, where the wheels, casters and laser are (the laser upside down), 25 kg in all, and as
supporting evidence the body's and wheels' sizes, each inertia against its shape's formula
and the casters' friction."""
from __future__ import annotations

import glob
import math
import os
from typing import Dict, List, Optional, Tuple

import numpy as np

from course_grader.results import Check
from urdf_tools import UrdfError, inertia, load_urdf
from urdf_tools.kinematics import link_transform, matrix_rpy
from urdf_tools.model import RobotModel
from urdf_tools.xacro_loader import load as load_xacro


def find_urdf(package_dir: str, relative: str) -> Optional[str]:
    """The guide's file, else the one .urdf or .xacro under ``urdf/``."""
    wanted = os.path.join(package_dir, relative)
    if os.path.isfile(wanted):
        return wanted
    found = sorted(glob.glob(os.path.join(package_dir, "urdf", "*.urdf")) +
                   glob.glob(os.path.join(package_dir, "urdf", "*.xacro")))
    return found[0] if found else None


def read(path: str) -> RobotModel:
    return load_xacro(path) if path.endswith(".xacro") else load_urdf(path)


def _close(a, b, tolerance: float) -> bool:
    return bool(np.allclose(np.asarray(a, float), np.asarray(b, float), rtol=tolerance,
                            atol=tolerance))


def _fmt(values) -> str:
    return "(" + ", ".join(f"{v:.4g}" for v in values) + ")"


def names(model: RobotModel, spec: Dict) -> List[Check]:
    """The guide's link names (what rviz shows), and its joint names (which the guide's
    item does not ask: the course file reports them as a note)."""
    checks = []
    for kind, wanted, have in (("link", spec["links"], model.links),
                               ("joint", spec["joints"], model.joints)):
        missing = [n for n in wanted if n not in have]
        checks.append(Check(f"{kind} names", not missing,
                            f"{len(wanted)} {kind}s named as the guide" if not missing else
                            f"{kind}s not named as the guide: {missing} (the URDF's: "
                            f"{sorted(have)})"))
    return checks


def _offset(model: RobotModel, parent: str, link: str) -> Optional[np.ndarray]:
    try:
        return link_transform(model, parent, link)
    except (UrdfError, KeyError):
        return None


def _places(spec: Dict) -> Dict[str, List[float]]:
    """Each part the guide places (by the name it gives it) and its place from the body."""
    return {**spec["positions"], spec["laser"]["link"]: spec["laser"]["xyz"]}


def part_link(model: RobotModel, spec: Dict, part: str) -> Optional[str]:
    """The link that is the guide's ``part`` (a wheel, a caster, the laser): the link of the
    guide's name, else the link at the guide's place for it. The guide lists places, not
    names: a right wheel named ``wheel_r`` where the guide puts the right wheel is it."""
    if part in model.links:
        return part
    body, xyz = spec["body"]["link"], _places(spec).get(part)
    if xyz is None or body not in model.links:
        return None
    for link in sorted(model.links):
        transform = _offset(model, body, link) if link != body else None
        if transform is not None and _close(transform[:3, 3], xyz, spec["tolerance"]):
            return link
    return None


def placements(model: RobotModel, spec: Dict) -> List[Check]:
    """Wheels, casters and laser where the guide puts them (from base_link), whatever their
    names (``part_link``), the laser rolled upside down, base_link the right height above
    base_footprint."""
    tolerance = spec["tolerance"]
    checks = []
    body = spec["body"]["link"]
    for part, xyz in _places(spec).items():
        link = part_link(model, spec, part)
        transform = _offset(model, body, link) if link is not None else None
        if transform is None:
            checks.append(Check(f"{part} position", False,
                                f"{part}: no link named so, and none at the guide's place "
                                f"{_fmt(xyz)} m from {body}"))
            continue
        at = transform[:3, 3]
        named = part if link == part else f"{part} (link '{link}')"
        checks.append(Check(f"{part} position", _close(at, xyz, tolerance),
                            f"{named} at {_fmt(at)} m (guide {_fmt(xyz)})"))
    laser_link = part_link(model, spec, spec["laser"]["link"])
    laser = _offset(model, body, laser_link) if laser_link is not None else None
    if laser is not None:
        roll = math.degrees(abs(matrix_rpy(laser[:3, :3])[0]))
        upside_down = abs(laser[2, 2] + 1.0) < tolerance   # the laser's z points down
        checks.append(Check("laser upside down", upside_down,
                            f"laser roll {roll:.1f} deg (guide {spec['laser']['roll']:g})"))
    footprint = _offset(model, "base_footprint", body) if body in model.links and \
        "base_footprint" in model.links else None
    if footprint is not None:
        height = footprint[2, 3]
        checks.append(Check("base_link height", _close(height, spec["footprint_height"], tolerance),
                            f"base_link {height:.4g} m above base_footprint "
                            f"(guide {spec['footprint_height']:g})"))
    return checks


def _only_geometry(model: RobotModel, link: str):
    shapes = model.links[link].collisions or model.links[link].visuals
    return shapes[0] if shapes else None


def _formula(link, shape) -> Optional[Tuple[float, float, float]]:
    geometry, mass = shape.geometry, link.inertial.mass
    if geometry.kind == "sphere":
        return inertia.solid_sphere(mass, geometry.radius)
    if geometry.kind == "cylinder":
        roll, pitch = shape.origin.rpy[0], shape.origin.rpy[1]
        axis = "y" if abs(abs(roll) - math.pi / 2) < 1e-3 else (
            "x" if abs(abs(pitch) - math.pi / 2) < 1e-3 else "z")
        return inertia.solid_cylinder(mass, geometry.radius, geometry.length, axis)
    if geometry.kind == "box":
        return inertia.solid_box(mass, *geometry.size)
    return None


def total_mass(model: RobotModel, spec: Dict) -> Check:
    """The robot's mass, every link's summed: the guide's 25 kg (scored: the simulator
    drives what the URDF weighs)."""
    mass = model.total_mass()
    return Check("total mass", _close(mass, spec["total_mass"], spec["tolerance"]),
                 f"{mass:.4g} kg in all (guide {spec['total_mass']:g})")


def supporting(model: RobotModel, spec: Dict) -> List[Check]:
    """Sizes, inertia formulas, caster friction: evidence beside the items."""
    tolerance = spec["tolerance"]
    checks = []
    body = spec["body"]
    shape = _only_geometry(model, body["link"]) if body["link"] in model.links else None
    if shape is not None and shape.geometry.kind == "cylinder":
        size = (2 * shape.geometry.radius, shape.geometry.length)
        checks.append(Check("body size", _close(size, (body["diameter"], body["height"]), tolerance),
                            f"body cylinder {size[0]:.4g} m wide, {size[1]:.4g} m tall "
                            f"(guide {body['diameter']:g} x {body['height']:g})"))
    else:
        checks.append(Check("body size", False, f"{body['link']} is not a cylinder"))
    for wheel in spec["wheels"]["links"]:
        shape = _only_geometry(model, wheel) if wheel in model.links else None
        ok = shape is not None and shape.geometry.kind == "cylinder"
        diameter = 2 * shape.geometry.radius if ok else float("nan")
        checks.append(Check(f"{wheel} diameter", ok and _close(diameter, spec["wheels"]["diameter"], tolerance),
                            f"{wheel} {diameter:.4g} m across (guide {spec['wheels']['diameter']:g})"))
    wrong = []
    for link in model.links.values():
        shape = _only_geometry(model, link.name)
        if link.inertial is None or shape is None:
            continue
        expected = _formula(link, shape)
        got = (link.inertial.ixx, link.inertial.iyy, link.inertial.izz)
        if expected is None or not np.allclose(got, expected, rtol=spec["inertia_tolerance"],
                                               atol=1e-12):
            wrong.append(f"{link.name} {_fmt(got)} vs {_fmt(expected) if expected else 'no formula'}")
    checks.append(Check("inertia formulas", not wrong,
                        "every inertia equals its shape's formula" if not wrong
                        else "inertia off: " + "; ".join(wrong)))
    for caster in spec["casters"]["links"]:
        props = model.gazebo_properties(caster) if caster in model.links else {}
        mu = (props.get("mu1"), props.get("mu2"))
        try:
            ok = all(float(v) == spec["casters"]["friction"] for v in mu)
        except (TypeError, ValueError):
            ok = False
        checks.append(Check(f"{caster} friction", ok, f"{caster} mu1 {mu[0]}, mu2 {mu[1]} "
                                                       f"(guide {spec['casters']['friction']:g})"))
    return checks


def wheel_joints(model: RobotModel, spec: Dict) -> Check:
    """The wheels' joints turn (continuous or revolute)."""
    kinds = {}
    for part in spec["wheels"]["links"]:
        wheel = part_link(model, spec, part) or part
        joint = model.parent_joint(wheel) if wheel in model.links else None
        kinds[wheel] = (joint.name, joint.type) if joint else (None, "missing")
    ok = all(kind in ("continuous", "revolute") for _, kind in kinds.values())
    return Check("wheel joints movable", ok,
                 ", ".join(f"{name or wheel} {kind}" for wheel, (name, kind) in kinds.items()))

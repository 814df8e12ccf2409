"""Hypothesis strategies for the fuzz tier: robot descriptions generated from scratch and
the workspace's own descriptions mutated, plus the tier's Hypothesis profiles.

Shared by ``urdf_tools/test/fuzz`` and ``sim_bridge/test/fuzz`` (whose conftest puts this
folder on ``sys.path``). Nothing here knows what a correct answer is: the tests check that
each case ends in a model or in the reader's documented error with a message.

Profiles (``register_profiles``): ``fuzz`` for ``make test`` (a bounded number of examples
per test, derandomized so that a run is repeatable, no example database), ``fuzz-long``
when ``FUZZ_LONG=1`` (many more examples, random, failures kept in ``.hypothesis/`` at the
repository's root, ignored by git). ``FUZZ_EXAMPLES=N`` sets the short profile's count.
"""
from __future__ import annotations

import functools
import glob
import os
import re
import subprocess
import xml.etree.ElementTree as ET
from typing import Callable, List, Optional, Sequence, Tuple

from hypothesis import HealthCheck, settings
from hypothesis import strategies as st

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
LONG = os.environ.get("FUZZ_LONG", "") not in ("", "0")


def register_profiles() -> None:
    """``fuzz`` (make test) or ``fuzz-long`` (FUZZ_LONG=1), loaded at once."""
    common = dict(deadline=None, print_blob=True,
                  suppress_health_check=list(HealthCheck))
    settings.register_profile("fuzz", derandomize=True, database=None,
                              max_examples=int(os.environ.get("FUZZ_EXAMPLES", "0") or 0) or 100,
                              **common)
    from hypothesis.database import DirectoryBasedExampleDatabase
    settings.register_profile("fuzz-long", derandomize=False,
                              database=DirectoryBasedExampleDatabase(
                                  os.path.join(REPO, ".hypothesis", "examples")),
                              max_examples=int(os.environ.get("FUZZ_EXAMPLES", "0") or 0) or 5000,
                              **common)
    settings.load_profile("fuzz-long" if LONG else "fuzz")


def examples(short: int, long: int) -> settings:
    """A test's own example count: ``short`` in make test, ``long`` with FUZZ_LONG=1;
    FUZZ_EXAMPLES overrides both."""
    forced = int(os.environ.get("FUZZ_EXAMPLES", "0") or 0)
    return settings(max_examples=forced or (long if LONG else short))


# --- the words the mutations use --------------------------------------------------------

# Numbers and texts that break readers: zero, negative, the largest and smallest doubles,
# beyond them, not numbers, empty, the wrong count, words, unicode, very long.
EXTREMES = ("0", "-0", "-1", "1", "1e308", "-1e308", "1e-308", "5e-324", "1e999", "-1e999",
            "nan", "NaN", "-nan", "inf", "-inf", "Infinity", "", " ", "abc", "0x10", "1,5",
            "1 2", "1 2 3", "1 2 3 4", "0 0 0", "nan 0 0", "1e308 1e308 1e308", "-1 -1 -1",
            "true", "false", "99999999999999999999999", "1" + "0" * 400, "1e+", "--1",
            "\u00e9\u4e2d\U0001F600", "\u202e", "\x01", "a" * 5000, "0 " * 2000, "1_0",
            "\t1\n", "model://", "package://", "package://nope/x.dae", "file:///dev/zero",
            "/dev/null", "/", "..", "world", "base_link", "j0", "l0")
TAGS = ("robot", "link", "joint", "visual", "collision", "inertial", "geometry", "box",
        "cylinder", "sphere", "mesh", "origin", "mass", "inertia", "parent", "child", "axis",
        "limit", "dynamics", "material", "color", "texture", "gazebo", "plugin", "sensor",
        "transmission", "mu1", "mu2", "kp", "kd", "fdir1", "selfCollide", "self_collide",
        "gravity", "turnGravityOff", "minDepth", "ray", "scan", "horizontal", "vertical",
        "samples", "min_angle", "max_angle", "range", "min", "max", "update_rate", "imu",
        "noise", "pose", "actuator", "hardwareInterface", "mechanicalReduction", "type",
        "safety_controller", "calibration", "mimic", "model", "include", "uri", "static",
        "size", "radius", "length", "normal", "scale", "surface", "friction", "ode", "mu",
        "world", "physics", "max_step_size", "name", "leftJoint", "rightJoint",
        "wheelDiameter", "wheelSeparation", "jointName", "bodyName",
        "{urn:x}ns", "\u00e9t\u00e9")
ATTRIBUTES = ("name", "type", "link", "xyz", "rpy", "size", "radius", "length", "filename",
              "scale", "value", "ixx", "ixy", "ixz", "iyy", "iyz", "izz", "lower", "upper",
              "effort", "velocity", "damping", "friction", "reference", "rgba", "joint",
              "multiplier", "offset", "version")

PLUGIN_FILES = ("libgazebo_ros_diff_drive.so", "libgazebo_ros_skid_steer_drive.so",
                "libgazebo_ros_joint_state_publisher.so", "libgazebo_ros_p3d.so",
                "libgazebo_ros_planar_move.so", "libgazebo_ros_control.so",
                "libgazebo_ros_imu.so", "libhector_gazebo_ros_imu.so",
                "libhector_gazebo_ros_gps.so", "libgazebo_ros_laser.so",
                "libgazebo_ros_gpu_laser.so", "libgazebo_ros_imu_sensor.so",
                "libgazebo_ros_mystery.so", "", "lib.so")
# the parameters the emulated plugins read (grep of sim_bridge's plugins), and Gazebo's
JOINT_PARAMS = ("leftJoint", "rightJoint", "leftFrontJoint", "rightFrontJoint",
                "leftRearJoint", "rightRearJoint", "jointName")
PLUGIN_PARAMS = JOINT_PARAMS + (
    "bodyName", "topicName", "frameName", "frameId", "commandTopic", "odometryTopic",
    "odometryFrame", "robotBaseFrame", "odometrySource", "robotNamespace", "updateRate",
    "updateRateHZ", "updatePeriod", "odometryRate", "wheelSeparation", "wheelDiameter",
    "wheelTorque", "wheelAcceleration", "torque", "publishOdomTF", "publishWheelTF",
    "publishWheelJointState", "publishTf", "broadcastTF", "legacyMode", "gaussianNoise",
    "xyzOffset", "rpyOffset", "serviceName", "referenceLatitude", "referenceLongitude",
    "referenceHeading", "referenceAltitude", "velocityTopicName", "biasTopicName",
    "covariance_x", "covariance_y", "covariance_yaw", "cmdTimeout", "controlPeriod",
    "robotParam", "robotSimType", "alwaysOn", "rosDebugLevel", "eStopTopic")
SURFACE_TAGS = ("mu1", "mu2", "kp", "kd", "minDepth", "fdir1", "material", "selfCollide",
                "gravity", "turnGravityOff", "maxVel", "maxContacts", "dampingFactor")
MATERIALS = ("Gazebo/Black", "Gazebo/Orange", "Gazebo/Nope", "", "Gazebo/", "Gazebo/Red ")


# --- seeds: the workspace's own descriptions -------------------------------------------

def _tracked(*patterns: str) -> List[str]:
    try:
        out = subprocess.run(["git", "ls-files", *patterns], cwd=REPO, check=True,
                             capture_output=True, text=True).stdout.split()
    except (OSError, subprocess.CalledProcessError):  # not a git checkout: walk the tree
        out = [os.path.relpath(p, REPO) for pattern in patterns
               for p in glob.glob(os.path.join(REPO, "**", pattern), recursive=True)]
    return sorted(os.path.join(REPO, p) for p in out)


@functools.lru_cache(maxsize=None)
def urdf_seeds() -> Tuple[Tuple[str, str], ...]:
    """(file, URDF text) of every URDF and top-level xacro the workspace tracks, expanded
    with its default arguments (xacros that need arguments or fail are skipped)."""
    from urdf_tools.xacro_loader import expand
    seeds = []
    for path in _tracked("*.urdf", "*.xacro"):
        if path.endswith(".xacro") and (os.sep + "inc" + os.sep in path
                                        or not re.search(r"<robot", open(path).read())):
            continue
        try:
            text = expand(path) if path.endswith(".xacro") else open(path, encoding="utf-8").read()
            ET.fromstring(text)
        except Exception:  # an include-only xacro: not a seed
            continue
        seeds.append((os.path.relpath(path, REPO), text))
    return tuple(seeds)


@functools.lru_cache(maxsize=None)
def sdf_seeds() -> Tuple[Tuple[str, str], ...]:
    """(file, text) of every .sdf and .world the workspace tracks."""
    return tuple((os.path.relpath(p, REPO), open(p, encoding="utf-8").read())
                 for p in _tracked("*.sdf", "*.world"))


# --- mutations of an ElementTree --------------------------------------------------------

def _elements(root: ET.Element) -> List[Tuple[Optional[ET.Element], ET.Element]]:
    """(parent, element) of every element, the root's parent None."""
    found = [(None, root)]
    for parent in root.iter():
        found.extend((parent, child) for child in parent)
    return found


def _pick(data, items: Sequence, label: str):
    return items[data.draw(st.integers(0, len(items) - 1), label=label)]


def value_text(data, label: str = "value") -> str:
    """A text for an attribute or element: an extreme, a plain number, or any unicode."""
    kind = data.draw(st.integers(0, 9), label=f"{label} kind")
    if kind < 6:
        return data.draw(st.sampled_from(EXTREMES), label=label)
    if kind < 8:
        numbers = data.draw(st.lists(st.floats(allow_nan=True, allow_infinity=True, width=64),
                                     min_size=1, max_size=4), label=label)
        return " ".join(repr(n) for n in numbers)
    return data.draw(st.text(max_size=40), label=label)


def _drop_element(data, root):
    pairs = [(p, e) for p, e in _elements(root) if p is not None]
    if pairs:
        parent, element = _pick(data, pairs, "drop")
        parent.remove(element)


def _duplicate_element(data, root):
    import copy
    pairs = [(p, e) for p, e in _elements(root) if p is not None]
    if pairs:
        parent, element = _pick(data, pairs, "duplicate")
        copies = data.draw(st.sampled_from((1, 2, 20)), label="copies")
        index = list(parent).index(element)
        for _ in range(copies):
            parent.insert(index, copy.deepcopy(element))


def _drop_attribute(data, root):
    with_attributes = [e for _, e in _elements(root) if e.attrib]
    if with_attributes:
        element = _pick(data, with_attributes, "element")
        del element.attrib[_pick(data, sorted(element.attrib), "attribute")]


def _set_attribute(data, root):
    element = _pick(data, [e for _, e in _elements(root)], "element")
    names = sorted(element.attrib) or list(ATTRIBUTES)
    if data.draw(st.booleans(), label="new attribute"):
        names = list(ATTRIBUTES)
    element.set(_pick(data, names, "attribute"), value_text(data))


def _set_text(data, root):
    """An element's text replaced; mostly a leaf's (a number, a name, a URI)."""
    everything = [e for _, e in _elements(root)]
    leaves = [e for e in everything if len(e) == 0 and (e.text or "").strip()]
    element = _pick(data, leaves if leaves and data.draw(st.integers(0, 3)) else everything,
                    "element")
    element.text = value_text(data)


def _rename(data, root):
    element = _pick(data, [e for _, e in _elements(root)], "element")
    element.tag = data.draw(st.sampled_from(TAGS), label="tag")


def _move(data, root):
    pairs = [(p, e) for p, e in _elements(root) if p is not None]
    if not pairs:
        return
    parent, element = _pick(data, pairs, "move")
    parent.remove(element)
    hosts = [e for _, e in _elements(root)]
    _pick(data, hosts, "new parent").append(element)


def _swap_values(data, root):
    """Two attributes' values exchanged (a joint's parent and child, a size and a name)."""
    slots = [(e, a) for _, e in _elements(root) for a in sorted(e.attrib)]
    if len(slots) >= 2:
        (e1, a1), (e2, a2) = _pick(data, slots, "first"), _pick(data, slots, "second")
        e1.attrib[a1], e2.attrib[a2] = e2.attrib[a2], e1.attrib[a1]


NEST_TAGS = ("link", "visual", "geometry", "gazebo", "plugin", "sensor", "model", "a")
_NEST = re.compile(r"<fuzznest(\d+)_(\w+)(?: />|/>|>)|</fuzznest(\d+)_(\w+)>")


def _nest(data, root):
    """An element wrapped in many levels of another element (written as a placeholder that
    :func:`_unnest` expands in the text: ElementTree writes recursively)."""
    pairs = [(p, e) for p, e in _elements(root) if p is not None]
    if not pairs:
        return
    parent, element = _pick(data, pairs, "nest")
    depth = data.draw(st.sampled_from((3, 50, 300, 3000)), label="depth")
    tag = data.draw(st.sampled_from(NEST_TAGS), label="tag")
    index = list(parent).index(element)
    parent.remove(element)
    outer = ET.Element(f"fuzznest{depth}_{tag}")
    outer.append(element)
    parent.insert(index, outer)


def _unnest(text: str) -> str:
    def expand(match):
        if match.group(1):
            depth, tag = int(match.group(1)), match.group(2)
            opening = f"<{tag}>" * depth
            return opening + f"</{tag}>" * depth if match.group(0).endswith("/>") else opening
        return f"</{match.group(4)}>" * int(match.group(3))
    return _NEST.sub(expand, text)


def _many_links(data, root):
    """A chain of links on joints hung from an existing link: huge counts."""
    links = [e.get("name") for e in root.findall("link") if e.get("name")]
    if not links:
        return
    count = data.draw(st.sampled_from((2, 30, 999, 1001, 5000)), label="count")
    joint_type = data.draw(st.sampled_from(("fixed", "continuous", "revolute")), label="type")
    parent = _pick(data, links, "hang from")
    for i in range(count):
        name = f"fz{i}"
        link = ET.SubElement(root, "link", name=name)
        inertial = ET.SubElement(link, "inertial")
        ET.SubElement(inertial, "mass", value="0.01")
        ET.SubElement(inertial, "inertia", ixx="1e-6", ixy="0", ixz="0", iyy="1e-6", iyz="0",
                      izz="1e-6")
        joint = ET.SubElement(root, "joint", name=f"fzj{i}", type=joint_type)
        ET.SubElement(joint, "parent", link=parent)
        ET.SubElement(joint, "child", link=name)
        ET.SubElement(joint, "origin", xyz="0 0 0.01")
        if joint_type == "revolute":
            ET.SubElement(joint, "limit", lower="-1", upper="1", effort="1", velocity="1")
        parent = name


def _unicode_name(data, root):
    named = [e for _, e in _elements(root) if e.get("name") is not None]
    if named:
        element = _pick(data, named, "element")
        kind = data.draw(st.integers(0, 3), label="name kind")
        element.set("name", ("n" * 100000) if kind == 0 else data.draw(st.text(max_size=30)))


def _gazebo_block(data, root):
    """A generated <gazebo> block appended: a surface, a plugin or a sensor."""
    links = [e.get("name", "") for e in root.findall("link")] or ["base_link"]
    joints = [e.get("name", "") for e in root.findall("joint")] or ["j0"]
    root.append(gazebo_element(data, links, joints))


MUTATIONS: Tuple[Callable, ...] = (
    _drop_element, _duplicate_element, _drop_attribute, _set_attribute, _set_text, _rename,
    _move, _swap_values, _nest, _many_links, _unicode_name, _gazebo_block)
# those that make sense inside a <gazebo> block alone
GAZEBO_MUTATIONS: Tuple[Callable, ...] = (
    _drop_element, _duplicate_element, _drop_attribute, _set_attribute, _set_text, _rename,
    _move, _swap_values, _nest, _unicode_name)


def mutate_text(data, text: str) -> str:
    """Text-level damage after serialising: truncated, a span cut or doubled, garbage."""
    if data.draw(st.integers(0, 9), label="text damaged") >= 2 or not text:
        return text
    kind = data.draw(st.integers(0, 4), label="text damage")
    at = data.draw(st.integers(0, len(text)), label="at")
    if kind == 0:
        return text[:at]
    if kind == 1:
        end = data.draw(st.integers(at, min(len(text), at + 200)), label="end")
        return text[:at] + text[end:]
    if kind == 2:
        end = data.draw(st.integers(at, min(len(text), at + 200)), label="end")
        return text[:end] + text[at:end] + text[end:]
    if kind == 3:
        return text[:at] + data.draw(st.text(max_size=20), label="garbage") + text[at:]
    return text + ("x" * 200000 if data.draw(st.booleans(), label="long line") else "<a/>")


def mutated(data, text: str, mutations: Sequence[Callable] = MUTATIONS,
            within: Optional[str] = None, max_mutations: int = 4) -> str:
    """``text`` parsed, mutated 0..max_mutations times and written again (possibly damaged).
    ``within`` restricts the mutations to the subtrees of that tag (e.g. ``gazebo``)."""
    try:
        root = ET.fromstring(text)
    except ET.ParseError:  # generated with a character XML forbids: only the text is damaged
        return mutate_text(data, text) if within is None else text
    count = data.draw(st.integers(0, max_mutations), label="mutations")
    for _ in range(count):
        target = root
        if within is not None:
            blocks = root.findall(f".//{within}")
            if not blocks:
                break
            target = _pick(data, blocks, within)
        _pick(data, mutations, "mutation")(data, target)
    out = _unnest(ET.tostring(root, encoding="unicode"))
    return mutate_text(data, out) if within is None else out


# --- descriptions generated from scratch ------------------------------------------------

def number(data, label: str = "number") -> str:
    """Mostly a plausible number, sometimes an extreme."""
    if data.draw(st.integers(0, 9), label=f"{label} sane") < 8:
        return repr(data.draw(st.floats(0.01, 2.0), label=label))
    return value_text(data, label)


def numbers(data, count: int, label: str) -> str:
    if data.draw(st.integers(0, 9), label=f"{label} sane") < 8:
        return " ".join(repr(v) for v in data.draw(
            st.lists(st.floats(-1.0, 1.0), min_size=count, max_size=count), label=label))
    return value_text(data, label)


def _geometry(data, parent: ET.Element) -> None:
    geometry = ET.SubElement(parent, "geometry")
    kind = data.draw(st.sampled_from(("box", "cylinder", "sphere", "mesh", "none", "two")),
                     label="shape")
    if kind in ("box", "two"):
        ET.SubElement(geometry, "box", size=" ".join(number(data, "side") for _ in range(3)))
    if kind in ("cylinder", "two"):
        ET.SubElement(geometry, "cylinder", radius=number(data, "radius"),
                      length=number(data, "length"))
    if kind == "sphere":
        ET.SubElement(geometry, "sphere", radius=number(data, "radius"))
    if kind == "mesh":
        ET.SubElement(geometry, "mesh", filename=data.draw(st.sampled_from((
            os.path.join(REPO, "sim_bridge/test/data/box_cm_zup.dae"),
            "package://sim_bridge/test/data/box_mm_yup.dae", "package://nope/a.stl",
            "file:///nonexistent.dae", "", "/dev/null", REPO)), label="mesh"),
            scale=numbers(data, 3, "scale"))


def _origin(data, parent: ET.Element) -> None:
    if data.draw(st.booleans(), label="origin"):
        ET.SubElement(parent, "origin", xyz=numbers(data, 3, "xyz"), rpy=numbers(data, 3, "rpy"))


def _sensor(data, links: Sequence[str]) -> ET.Element:
    kind = data.draw(st.sampled_from(("ray", "gpu_ray", "imu", "camera", "")), label="sensor")
    sensor = ET.Element("sensor", type=kind, name=data.draw(st.sampled_from(("s", "laser", ""))))
    ET.SubElement(sensor, "pose").text = numbers(data, 6, "pose")
    ET.SubElement(sensor, "update_rate").text = number(data, "rate")
    if kind in ("ray", "gpu_ray"):
        scan = ET.SubElement(ET.SubElement(sensor, "ray"), "scan")
        for direction in ("horizontal", "vertical")[:data.draw(st.integers(1, 2))]:
            block = ET.SubElement(scan, direction)
            ET.SubElement(block, "samples").text = data.draw(st.sampled_from(
                ("1", "2", "360", "720", "10001", "0", "-5", "360.5", "nan", "1e9", "abc")),
                label="samples")
            ET.SubElement(block, "resolution").text = number(data, "resolution")
            ET.SubElement(block, "min_angle").text = numbers(data, 1, "min")
            ET.SubElement(block, "max_angle").text = numbers(data, 1, "max")
        ranges = ET.SubElement(sensor.find("ray"), "range")
        ET.SubElement(ranges, "min").text = number(data, "min range")
        ET.SubElement(ranges, "max").text = number(data, "max range")
        ET.SubElement(ranges, "resolution").text = number(data, "range resolution")
        noise = ET.SubElement(sensor.find("ray"), "noise")
        ET.SubElement(noise, "type").text = "gaussian"
        ET.SubElement(noise, "mean").text = number(data, "mean")
        ET.SubElement(noise, "stddev").text = number(data, "stddev")
    for _ in range(data.draw(st.integers(0, 2), label="sensor plugins")):
        sensor.append(_plugin(data, links, []))
    return sensor


def _plugin(data, links: Sequence[str], joints: Sequence[str]) -> ET.Element:
    plugin = ET.Element("plugin", name=data.draw(st.sampled_from(("p", "drive", ""))),
                        filename=data.draw(st.sampled_from(PLUGIN_FILES), label="plugin"))
    for _ in range(data.draw(st.integers(0, 8), label="params")):
        tag = data.draw(st.sampled_from(PLUGIN_PARAMS), label="param")
        if tag in JOINT_PARAMS and joints and data.draw(st.booleans()):
            text = _pick(data, list(joints), "joint")
        elif tag == "bodyName" and data.draw(st.booleans()):
            text = _pick(data, list(links), "link")
        else:
            text = number(data, tag) if data.draw(st.booleans()) else value_text(data, tag)
        ET.SubElement(plugin, tag).text = text
    return plugin


def gazebo_element(data, links: Sequence[str], joints: Sequence[str]) -> ET.Element:
    """A <gazebo> block: a link's surface, a sensor, a model plugin, or a joint's tags."""
    kind = data.draw(st.sampled_from(("surface", "sensor", "plugin", "joint", "robot",
                                      "unknown ref")), label="gazebo")
    block = ET.Element("gazebo")
    if kind in ("surface", "sensor"):
        block.set("reference", _pick(data, list(links), "link"))
    elif kind == "joint" and joints:
        block.set("reference", _pick(data, list(joints), "joint"))
        ET.SubElement(block, data.draw(st.sampled_from(("provideFeedback", "stopCfm",
                                                        "preserveFixedJoint"))),
                      ).text = "true"
    elif kind == "unknown ref":
        block.set("reference", value_text(data, "reference"))
    if kind == "surface":
        for _ in range(data.draw(st.integers(0, 5), label="surface tags")):
            tag = data.draw(st.sampled_from(SURFACE_TAGS), label="surface tag")
            text = (data.draw(st.sampled_from(MATERIALS)) if tag == "material"
                    else numbers(data, 3, tag) if tag == "fdir1"
                    else number(data, tag))
            if data.draw(st.booleans(), label="as attribute"):
                ET.SubElement(block, tag, value=text)
            else:
                ET.SubElement(block, tag).text = text
    elif kind == "sensor":
        block.append(_sensor(data, links))
    elif kind in ("plugin", "robot"):
        if kind == "robot":
            ET.SubElement(block, data.draw(st.sampled_from(("self_collide", "static")))).text = \
                data.draw(st.sampled_from(("true", "false", "1", "")))
        block.append(_plugin(data, links, joints))
    return block


@st.composite
def generated_urdf(draw) -> str:
    """A robot from scratch: a tree of links (inertials, visuals, collisions) on joints of
    every type, <gazebo> blocks with surfaces, plugins and sensors, transmissions."""
    data = _Drawer(draw)
    count = draw(st.integers(1, 8), label="links")
    robot = ET.Element("robot", name=draw(st.sampled_from(("fuzz", "", "r\u00e9"))))
    links = [f"l{i}" for i in range(count)]
    if draw(st.integers(0, 9)) == 0:
        links[0] = "world"
    for name in links:
        link = ET.SubElement(robot, "link", name=name)
        if name == "world":
            continue
        if draw(st.integers(0, 9), label="has inertial") < 8:
            inertial = ET.SubElement(link, "inertial")
            _origin(data, inertial)
            ET.SubElement(inertial, "mass", value=number(data, "mass"))
            moments = {key: number(data, key) if key in ("ixx", "iyy", "izz")
                       else (numbers(data, 1, key)) for key in
                       ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")}
            ET.SubElement(inertial, "inertia", **moments)
        for tag in ("visual", "collision"):
            for _ in range(draw(st.integers(0, 2), label=tag)):
                shape = ET.SubElement(link, tag)
                _origin(data, shape)
                _geometry(data, shape)
    joints = []
    for i in range(1, count):
        joint_type = draw(st.sampled_from(("fixed", "continuous", "revolute", "prismatic",
                                           "floating", "planar", "ball", "")), label="type")
        name = f"j{i - 1}"
        joints.append(name)
        joint = ET.SubElement(robot, "joint", name=name, type=joint_type)
        parent = draw(st.integers(0, i - 1), label="parent") \
            if draw(st.integers(0, 19)) else draw(st.integers(0, count - 1))
        ET.SubElement(joint, "parent", link=links[parent])
        ET.SubElement(joint, "child", link=links[i])
        _origin(data, joint)
        if draw(st.booleans(), label="axis"):
            ET.SubElement(joint, "axis", xyz=numbers(data, 3, "axis"))
        if joint_type in ("revolute", "prismatic") or draw(st.integers(0, 4)) == 0:
            if draw(st.integers(0, 9)):
                ET.SubElement(joint, "limit", lower=numbers(data, 1, "lower"),
                              upper=number(data, "upper"), effort=number(data, "effort"),
                              velocity=number(data, "velocity"))
        if draw(st.booleans(), label="dynamics"):
            ET.SubElement(joint, "dynamics", damping=number(data, "damping"),
                          friction=number(data, "friction"))
    for _ in range(draw(st.integers(0, 4), label="gazebo blocks")):
        robot.append(gazebo_element(data, links, joints))
    for _ in range(draw(st.integers(0, 2), label="transmissions")):
        transmission = ET.SubElement(robot, "transmission", name=draw(st.sampled_from(("t", ""))))
        ET.SubElement(transmission, "type").text = \
            "transmission_interface/SimpleTransmission"
        joint = ET.SubElement(transmission, "joint",
                              name=draw(st.sampled_from(joints + ["nope", ""])))
        ET.SubElement(joint, "hardwareInterface").text = draw(st.sampled_from((
            "hardware_interface/EffortJointInterface", "PositionJointInterface",
            "hardware_interface/VelocityJointInterface", "nope", "")))
        if draw(st.booleans()):
            actuator = ET.SubElement(transmission, "actuator", name="a")
            ET.SubElement(actuator, "mechanicalReduction").text = number(data, "reduction")
    return ET.tostring(robot, encoding="unicode")


class _Drawer:
    """``data.draw`` for the helpers above, inside an ``st.composite``."""

    def __init__(self, draw):
        self.draw = draw


@st.composite
def urdf_case(draw, mutate: bool = True) -> Tuple[str, str]:
    """(what it is, URDF text): a workspace description or a generated one, mutated."""
    data = _Drawer(draw)
    seeds = urdf_seeds()
    if draw(st.booleans(), label="seed or generated"):
        label, text = seeds[draw(st.integers(0, len(seeds) - 1), label="seed")]
    else:
        label, text = "generated", draw(generated_urdf())
    if mutate:
        text = mutated(data, text)
    return label, text


# --- SDF: worlds and models -------------------------------------------------------------

INCLUDE_URIS = ("model://ground_plane", "model://sun", "model://cardboard_box",
                "model://warehouse_walls", "model://nope", "model://", "", "model://self",
                "model://loop_a", "model://deep_0", "model://mutant", "model://../models/self",
                "file:///dev/null", "/etc", "..", "models/self", "model://ground_plane/x")


def _include(data, root):
    """An <include> of a model that exists, one that does not, one that includes itself."""
    hosts = [e for _, e in _elements(root) if e.tag in ("world", "model", "sdf")] or [root]
    include = ET.SubElement(_pick(data, hosts, "host"), "include")
    ET.SubElement(include, "uri").text = data.draw(st.sampled_from(INCLUDE_URIS), label="uri")
    if data.draw(st.booleans(), label="named"):
        ET.SubElement(include, "name").text = value_text(data, "name")
    if data.draw(st.booleans(), label="posed"):
        ET.SubElement(include, "pose").text = numbers(data, 6, "pose")
    if data.draw(st.booleans(), label="static"):
        ET.SubElement(include, "static").text = value_text(data, "static")


# where SDF readers read numbers and names: (host tag, path of the element to add)
SDF_SLOTS = (("collision", "surface/friction/ode/mu"), ("collision", "pose"),
             ("visual", "material/diffuse"), ("visual", "material/ambient"),
             ("visual", "material/script/name"), ("visual", "pose"), ("link", "pose"),
             ("link", "inertial/mass"), ("link", "inertial/pose"),
             ("link", "inertial/inertia/ixx"), ("model", "pose"), ("model", "static"),
             ("geometry", "box/size"), ("geometry", "cylinder/radius"),
             ("geometry", "sphere/radius"), ("geometry", "plane/normal"),
             ("geometry", "plane/size"), ("geometry", "mesh/uri"), ("geometry", "mesh/scale"),
             ("world", "gravity"), ("world", "physics/max_step_size"))


def _sdf_slot(data, root):
    """A value where a reader reads one (mu, a colour, a pose, a size), given an extreme."""
    slots = [(e, path) for _, e in _elements(root) for host, path in SDF_SLOTS if e.tag == host]
    if not slots:
        return
    element, path = _pick(data, slots, "slot")
    for step in path.split("/"):
        found = element.find(step)
        element = found if found is not None else ET.SubElement(element, step)
    element.text = value_text(data, path)


SDF_MUTATIONS: Tuple[Callable, ...] = (_sdf_slot, _sdf_slot, _sdf_slot, 
    _drop_element, _duplicate_element, _drop_attribute, _set_attribute, _set_text, _rename,
    _move, _swap_values, _nest, _unicode_name, _include, _include, _set_text, _set_text)


def _model_sdf(name: str, body: str = "") -> str:
    return (f'<sdf version="1.6"><model name="{name}"><static>true</static>'
            '<link name="link"><collision name="c"><geometry><box><size>1 1 1</size></box>'
            f'</geometry></collision></link>{body}</model></sdf>')


def _include_text(uri: str) -> str:
    return f"<include><uri>{uri}</uri></include>"


@st.composite
def sdf_case(draw, world: bool) -> Tuple[str, str, dict]:
    """(seed, text, files): a world (``world``) or a model, mutated; ``files`` are model
    folders under ``models/`` for the world's includes: one that includes itself, a cycle
    of two, a chain deeper than sim_bridge follows, and a mutated copy of a seed model."""
    data = _Drawer(draw)
    seeds = [s for s in sdf_seeds() if ("<world" in s[1]) == world]
    label, text = seeds[draw(st.integers(0, len(seeds) - 1), label="seed")]
    text = mutated(data, text, SDF_MUTATIONS)
    files = {}
    if world:
        models = [s for s in sdf_seeds() if "<world" not in s[1]]
        mutant = mutated(data, models[draw(st.integers(0, len(models) - 1))][1], SDF_MUTATIONS)
        files = {
            "models/self/model.sdf": _model_sdf("self", _include_text("model://self")),
            "models/loop_a/model.sdf": _model_sdf("loop_a", _include_text("model://loop_b")),
            "models/loop_b/model.sdf": _model_sdf("loop_b", _include_text("model://loop_a")),
            "models/mutant/model.sdf": mutant,
            "models/mutant/model.config": draw(st.sampled_from((
                "<model><sdf>model.sdf</sdf></model>", "<model><sdf>../self/model.sdf</sdf>",
                "<model><sdf>nope.sdf</sdf></model>", "<model><sdf/></model>", "garbage<",
                "<model><sdf>/dev/null</sdf></model>"))),
        }
        depth = 20
        for i in range(depth):
            inner = _include_text(f"model://deep_{i + 1}") if i + 1 < depth else ""
            files[f"models/deep_{i}/model.sdf"] = _model_sdf(f"deep_{i}", inner)
    return label, text, files

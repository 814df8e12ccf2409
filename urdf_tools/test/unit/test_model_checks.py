"""urdf_tools.model's own checks on top of urdf_parser_py: physically impossible values are
refused naming the link and the value, odd ones are warned about, the size limits hold,
urdf_parser_py's refusals and stderr chatter come out as our messages, and line breaks do
not matter."""
import logging
import xml.etree.ElementTree as ET

import numpy
import pytest

from urdf_tools import inertia
from urdf_tools.kinematics import rpy_matrix
from urdf_tools.model import (MAX_DESCRIPTION_BYTES, MAX_JOINTS, MAX_LINKS, UrdfError,
                              load_urdf, parse_urdf)

SOURCE = "checked.urdf"
UNIT_INERTIA = "<inertia ixx='1' ixy='0' ixz='0' iyy='1' iyz='0' izz='1'/>"


def inertial(mass, tensor=UNIT_INERTIA):
    return f"<inertial><mass value='{mass}'/>{tensor}</inertial>"


def robot(base="", wheel="", joint_type="continuous", extra=""):
    """A base and a wheel on a joint; ``base`` and ``wheel`` are the links' contents."""
    limit = "<limit lower='-1' upper='1' effort='1' velocity='1'/>"
    return (f"<robot name='r'><link name='base'>{base}</link><link name='wheel'>{wheel}</link>"
            f"<joint name='axle' type='{joint_type}'><parent link='base'/><child link='wheel'/>"
            f"{limit}</joint>{extra}</robot>")


def shape(geometry):
    return f"<collision><geometry>{geometry}</geometry></collision>"


def refusal(text):
    with pytest.raises(UrdfError) as error:
        parse_urdf(text, SOURCE)
    message = str(error.value)
    assert message.startswith(f"{SOURCE}: ")
    return message


@pytest.mark.parametrize("text, value", [
    (robot(wheel=inertial(-0.5)), "-0.5"),
    (robot(wheel=inertial(0, "<inertia ixx='0' ixy='0' ixz='0' iyy='0' iyz='0' izz='0'/>")),
     "0 kg"),
    (robot(wheel=inertial(0), joint_type="prismatic"), "0 kg"),
    (robot(wheel=shape("<box size='0.1 0 0.1'/>")), "0.1 0 0.1"),
    (robot(wheel=shape("<box size='0.1 0.1 -0.1'/>")), "0.1 0.1 -0.1"),
    (robot(wheel=shape("<cylinder radius='0' length='0.1'/>")), "radius '0'"),
    (robot(wheel=shape("<cylinder radius='0.1' length='-2'/>")), "length '-2'"),
    (robot(wheel=shape("<sphere radius='-0.3'/>")), "radius '-0.3'"),
])
def test_physically_impossible_values_are_refused_naming_the_link_and_the_value(text, value):
    message = refusal(text)
    assert "'wheel'" in message and value in message


def test_a_massless_link_that_moves_is_accepted_when_something_fixed_to_it_weighs():
    # Gazebo lumps links on fixed joints into their parent before dropping massless links.
    text = robot(wheel=inertial(0), extra=(
        "<link name='tyre'>" + inertial(0.2) + "</link><joint name='rim' type='fixed'>"
        "<parent link='wheel'/><child link='tyre'/></joint>"))
    model = parse_urdf(text, SOURCE)
    assert model.links["wheel"].inertial.mass == 0.0


def test_a_massless_link_on_a_fixed_joint_or_at_the_root_is_not_refused():
    model = parse_urdf(robot(wheel=inertial(0), joint_type="fixed"), SOURCE)
    assert model.joints["axle"].type == "fixed" and not model.warnings
    root_massless = parse_urdf(robot(base=inertial(0), wheel=inertial(1)), SOURCE)
    assert [w for w in root_massless.warnings if "'base'" in w and "0 kg" in w]


@pytest.mark.parametrize("where, text", [
    ("mass", robot(wheel=inertial("nan"))),
    ("inertia", robot(wheel=inertial(1, UNIT_INERTIA.replace("izz='1'", "izz='inf'")))),
    ("origin", robot(wheel="<visual><origin xyz='0 -inf 0'/><geometry><sphere radius='1'/>"
                           "</geometry></visual>")),
    ("axis", robot().replace("</joint>", "<axis xyz='0 nan 1'/></joint>")),
    ("limit", robot().replace("velocity='1'", "velocity='inf'")),
    ("rgba", robot(extra="<material name='m'><color rgba='1 nan 0 1'/></material>")),
    ("size", robot(wheel=shape("<box size='1 1 1e999'/>"))),
])
def test_numbers_that_are_not_finite_are_refused_wherever_they_are(where, text):
    message = refusal(text)
    assert where in message and "finite" in message


def test_an_inertia_that_is_not_positive_definite_is_warned_about_not_refused(caplog):
    # ixy = 2 with unit moments: the principal moments are 1 - 2, 1 and 1 + 2
    skewed = UNIT_INERTIA.replace("ixy='0'", "ixy='2'")
    with caplog.at_level(logging.WARNING, logger="urdf_tools.model"):
        model = parse_urdf(robot(wheel=inertial(1, skewed)), SOURCE)
    assert model.links["wheel"].inertial.ixy == 2.0
    (warning,) = model.warnings
    assert "'wheel'" in warning and "positive definite" in warning
    assert warning in caplog.messages


def test_a_rotated_solid_box_tensor_is_not_warned_about():
    # a real body's tensor seen from a tilted frame has products of inertia, and is fine
    ixx, iyy, izz = inertia.solid_box(2.0, 0.1, 0.4, 0.9)
    rotation = rpy_matrix(0.3, -0.7, 1.1)
    tensor = rotation @ numpy.diag([ixx, iyy, izz]) @ rotation.T
    element = ("<inertia " + " ".join(f"{key}='{float(tensor[i][j])!r}'" for key, (i, j) in {
        "ixx": (0, 0), "ixy": (0, 1), "ixz": (0, 2), "iyy": (1, 1), "iyz": (1, 2),
        "izz": (2, 2)}.items()) + "/>")
    model = parse_urdf(robot(wheel=inertial(2.0, element)), SOURCE)
    assert model.links["wheel"].inertial.ixy == pytest.approx(tensor[0][1])
    assert model.warnings == []


def chain(links, joints=None):
    joints = links - 1 if joints is None else joints
    return ("<robot name='c'>" + "".join(f"<link name='l{i}'/>" for i in range(links))
            + "".join(f"<joint name='j{i}' type='fixed'><parent link='l{i % links}'/>"
                      f"<child link='l{(i + 1) % links}'/></joint>" for i in range(joints))
            + "</robot>")


def test_the_link_and_joint_limits():
    assert len(parse_urdf(chain(MAX_LINKS), SOURCE).links) == MAX_LINKS
    message = refusal(chain(MAX_LINKS + 1))
    assert f"{MAX_LINKS + 1} links" in message and str(MAX_LINKS) in message
    message = refusal(chain(MAX_LINKS, joints=MAX_JOINTS + 1))
    assert f"{MAX_JOINTS + 1} joints" in message and str(MAX_JOINTS) in message


def padded(text, filler, characters):
    """``text`` with a comment of ``characters`` copies of ``filler`` in it."""
    return text.replace("<robot name='r'>", f"<robot name='r'><!--{filler * characters}-->")


def test_the_description_size_limit_counts_bytes():
    small = robot()
    comment = len("<!---->")
    at_limit = padded(small, "x", MAX_DESCRIPTION_BYTES - len(small) - comment)
    assert len(at_limit.encode()) == MAX_DESCRIPTION_BYTES
    assert parse_urdf(at_limit, SOURCE).name == "r"
    message = refusal(at_limit.replace("<!--", "<!--x"))
    assert str(MAX_DESCRIPTION_BYTES) in message
    # 'é' is two bytes: fewer characters than the limit, more bytes
    wide = padded(small, "\u00e9", MAX_DESCRIPTION_BYTES // 2)
    assert len(wide) < MAX_DESCRIPTION_BYTES < len(wide.encode())
    assert str(MAX_DESCRIPTION_BYTES) in refusal(wide)


def test_a_file_over_the_size_limit_is_refused(tmp_path):
    path = tmp_path / "huge.urdf"
    path.write_text(padded(robot(), "x", MAX_DESCRIPTION_BYTES), encoding="utf-8")
    with pytest.raises(UrdfError) as error:
        load_urdf(str(path))
    assert str(error.value).startswith(str(path)) and str(MAX_DESCRIPTION_BYTES) in str(error.value)


@pytest.mark.parametrize("text, words", [
    (robot().replace(" effort='1'", ""), ["joint 'axle' limit", "'effort'"]),
    (robot(wheel=shape("<box size='1 x 1'/>")), ["link 'wheel' collision 0", "'1 x 1'", "'x'"]),
    (robot(wheel=shape("<cone radius='1'/>")), ["link 'wheel' collision 0", "<cone>"]),
    (robot(wheel=inertial("heavy")), ["link 'wheel' inertial mass", "'heavy'"]),
    (robot(wheel="<inertial><mass value='1'/></inertial>"), ["'wheel'", "<inertia>"]),
    (robot(wheel="<visual><geometry><box size='1 1 1'/></geometry><material/></visual>"),
     ["link 'wheel' visual 0 material", "'name'"]),
    (robot().replace("<parent link='base'/>", "<parent/>"), ["joint 'axle'", "<parent link"]),
])
def test_what_urdf_parser_py_refuses_is_named_in_our_words(text, words):
    message = refusal(text)
    assert all(word in message for word in words), message
    assert "ParseError" not in message


def test_urdf_parser_py_says_nothing_on_stderr_its_remarks_are_warnings(capfd):
    text = robot(wheel="<inertial><mass value='1'/>" + UNIT_INERTIA + "<colour/></inertial>")
    model = parse_urdf(text, SOURCE)
    assert "colour" not in capfd.readouterr().err
    (warning,) = model.warnings
    assert warning.startswith(f"{SOURCE}: link 'wheel' inertial") and "<colour>" in warning


def test_a_transmission_without_an_actuator_is_read_as_ros_control_reads_it():
    # urdf_parser_py would refuse the whole robot; gazebo_ros_control reads the joint
    text = robot(extra="<transmission name='t'><type>transmission_interface/"
                       "SimpleTransmission</type><joint name='axle'><hardwareInterface>"
                       "hardware_interface/VelocityJointInterface</hardwareInterface></joint>"
                       "</transmission>")
    (transmission,) = parse_urdf(text, SOURCE).transmissions
    assert transmission.joints == ("axle",)
    assert transmission.hardware_interfaces == ("hardware_interface/VelocityJointInterface",)


def many_links_with_line_breaks(count):
    lines = ["<robot name='long'>", "<material name='grey'>",
             "<color rgba='0.5 0.5 0.5 1'/>", "</material>"]
    for i in range(count):
        lines += [f"<link name='segment_{i}'>", "<visual>", f"<origin xyz='0 0 {i * 0.1}'/>",
                  "<geometry>", f"<box size='0.1 0.2 {0.3 + i}'/>", "</geometry>",
                  "<material name='grey'/>", "</visual>", "<inertial>",
                  f"<mass value='{1 + i}'/>", UNIT_INERTIA, "</inertial>", "</link>"]
        if i:
            lines += [f"<joint name='hinge_{i}' type='revolute'>",
                      f"<parent link='segment_{i - 1}'/>", f"<child link='segment_{i}'/>",
                      "<axis xyz='0 1 0'/>", "<limit lower='-1' upper='1' effort='2' velocity='3'/>",
                      "</joint>"]
    lines += ["<gazebo reference='segment_0'>", "<mu1>0.3</mu1>", "</gazebo>", "</robot>"]
    return lines


def test_a_description_on_one_line_longer_than_8_kb_reads_as_with_line_breaks():
    lines = many_links_with_line_breaks(40)
    one_line = "".join(lines)
    assert "\n" not in one_line and len(one_line) > 8 * 1024
    flat = parse_urdf(one_line, SOURCE)
    broken = parse_urdf("\n".join(lines), SOURCE)
    assert len(flat.links) == 40
    assert (flat.links, flat.joints, flat.materials) == \
        (broken.links, broken.joints, broken.materials)
    assert [(ref, ET.tostring(e).strip()) for ref, e in flat.gazebo] == \
        [(ref, ET.tostring(e).replace(b"\n", b"").strip()) for ref, e in broken.gazebo]
    assert flat.gazebo_properties("segment_0") == {"mu1": "0.3"}

"""Task 1's URDF checks read places, not names (issue 31): wheels, casters and laser named
otherwise but where the guide puts them are those parts; a part misnamed and misplaced loses
its place once (the names are a note, not a scored part)."""
import os

import pytest

from course_grader import course as course_file
from course_grader.urdf_checks import names, part_link, placements, wheel_joints
from urdf_tools import parse_urdf

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
SOLUTION = os.path.join(REPO, "my_rb1_description", "urdf", "my_rb1_robot.urdf")
OTHER_NAMES = {"right_wheel": "wheel_r", "left_wheel": "wheel_l", "front_caster": "caster_f",
               "back_caster": "caster_b", "front_laser": "hokuyo"}


@pytest.fixture(scope="module")
def rb1():
    return course_file.load("rb1")


def urdf(renames=(), replace=()):
    with open(SOLUTION, encoding="utf-8") as stream:
        text = stream.read()
    for old, new in renames:
        text = text.replace(f'"{old}"', f'"{new}"')
    for old, new in replace:
        assert old in text, old
        text = text.replace(old, new)
    return parse_urdf(text, "test")


def test_parts_named_otherwise_are_found_where_the_guide_puts_them(rb1):
    model = urdf(OTHER_NAMES.items())
    assert {part: part_link(model, rb1.urdf, part) for part in OTHER_NAMES} == OTHER_NAMES
    checks = placements(model, rb1.urdf)
    assert all(c.passed for c in checks), [c.evidence for c in checks if not c.passed]
    assert any("right_wheel (link 'wheel_r') at" in c.evidence for c in checks)
    assert wheel_joints(model, rb1.urdf).passed


def test_link_names_are_a_note_and_a_misnamed_misplaced_part_loses_its_place_once(rb1):
    model = urdf([("right_wheel", "wheel_r")],
                 [('<origin xyz="0.0 -0.2 -0.15" rpy="0 0 0"/>',
                   '<origin xyz="0.05 -0.2 -0.15" rpy="0 0 0"/>')])
    item = next(i for i in rb1.items if i.id == "display_links_tf")
    link_names = next(c for c in names(model, rb1.urdf) if c.name == "link names")
    assert not link_names.passed and item.rubric.is_note(link_names.name)
    failed = [c for c in placements(model, rb1.urdf) if not c.passed]
    assert [c.name for c in failed] == ["right_wheel position"]
    assert "no link named so, and none at the guide's place" in failed[0].evidence

"""The SRDF reader: every element a Setup-Assistant file holds, and srdfdom's tolerance
(an element naming what the robot lacks is left out with a warning, the rest read)."""
import os

import pytest

from moveit_core.srdf import SrdfError, parse_srdf
from urdf_tools import load_urdf

DATA = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "data")


def read(name):
    with open(os.path.join(DATA, name), encoding="utf-8") as stream:
        return stream.read()


def test_px100_groups_states_end_effector_and_disabled_pairs():
    srdf = parse_srdf(read("px100.srdf"), load_urdf(os.path.join(DATA, "px100.urdf")))
    assert srdf.warnings == []
    arm = srdf.groups["interbotix_arm"]
    assert arm.joints == ("waist", "shoulder", "elbow", "wrist_angle", "ee_arm",
                          "gripper_bar", "ee_gripper")
    assert srdf.groups["interbotix_gripper"].links == ("px100/left_finger_link",
                                                       "px100/right_finger_link")
    sleep = srdf.group_state("interbotix_arm", "Sleep")
    assert sleep.values == {"elbow": (1.5,), "shoulder": (-1.88,), "waist": (0.0,),
                            "wrist_angle": (0.8,)}
    (eef,) = srdf.end_effectors
    assert (eef.name, eef.parent_link, eef.group, eef.parent_group) == (
        "interbotix_gripper", "px100/ee_gripper_link", "interbotix_gripper", "")
    assert [(d.link1, d.link2, d.reason) for d in srdf.disabled_collisions][0] == (
        "px100/base_link", "px100/shoulder_link", "Adjacent")
    assert len(srdf.disabled_collisions) == 9


def test_chains_subgroups_and_the_virtual_joint():
    srdf = parse_srdf(read("six_axis_arm.srdf"), load_urdf(os.path.join(DATA, "six_axis_arm.urdf")))
    assert srdf.groups["manipulator"].chains == (("base_link", "tool0"),)
    assert srdf.groups["arm_by_parts"].subgroups == ("wrist",)
    (virtual,) = srdf.virtual_joints
    assert (virtual.name, virtual.type, virtual.parent_frame, virtual.child_link) == (
        "virtual_joint", "fixed", "world", "base_link")


def test_what_names_nothing_is_left_out_with_a_warning_and_the_rest_is_read():
    text = read("px100.srdf").replace(
        '<joint name="ee_gripper"/>', '<joint name="ee_gripper"/><link name="px100/ar_tag_link"/>'
    ).replace('value="0.8"', 'value="high"').replace(
        "</robot>", '<disable_collisions link1="px100/ar_tag_link" link2="px100/base_link"/>'
                    '<group_state name="Up" group="no_such_group"/><end_effector name="e"/>'
                    '<passive_joint name="caster"/></robot>')
    srdf = parse_srdf(text, load_urdf(os.path.join(DATA, "px100.urdf")), "px100.srdf")
    said = "\n".join(srdf.warnings)
    assert "group 'interbotix_arm' names link 'px100/ar_tag_link', which the robot lacks" in said
    assert "joint 'wrist_angle' has value 'high', not numbers" in said
    assert "<disable_collisions> names link 'px100/ar_tag_link'" in said
    assert "group state 'Up' is of group 'no_such_group'" in said
    assert "<end_effector> without 'parent_link', 'group' left out" in said
    assert "<passive_joint> names joint 'caster'" in said
    assert all(w.startswith("px100.srdf: ") for w in srdf.warnings)
    assert len(srdf.warnings) == 6
    # the rest stands
    assert srdf.groups["interbotix_arm"].links == ()
    assert "wrist_angle" not in srdf.group_state("interbotix_arm", "Sleep").values
    assert len(srdf.disabled_collisions) == 9


@pytest.mark.parametrize("text, cause", [
    ("<robot name='x'><group></robot>", "not an SRDF document"),
    ("<launch/>", "the root element is <launch>"),
    ("", "not an SRDF document"),
])
def test_a_document_that_cannot_be_read_names_why(text, cause):
    with pytest.raises(SrdfError, match=cause):
        parse_srdf(text, source="semantic.srdf")

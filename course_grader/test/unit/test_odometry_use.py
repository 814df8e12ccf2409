"""Odometry use judged by behaviour (issue 31): the robot geared down through its drive
plugin's wheelDiameter, as Noetic's plugins read it, and the geared-down turn read as a
teaching assistant reads a turn by odometry or by the clock; a check that cannot settle it
marks the item for review."""
import os
import xml.etree.ElementTree as ElementTree

import pytest

from course_grader import course as course_file
from course_grader.measures import Rotation
from course_grader.odometry_use import CannotGearDown, gear_down, judge
from course_grader.results import Check, judge as judge_item

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
ROBOT = """<robot name="r">
  <link name="base_link"/>
  <gazebo>
    <plugin name="drive" filename="{plugin}">
      <leftJoint>l</leftJoint><rightJoint>r</rightJoint>{tags}
    </plugin>
  </gazebo>
  <gazebo reference="base_link"><material>Gazebo/Grey</material></gazebo>
</robot>"""
DIFF = "libgazebo_ros_diff_drive.so"


def robot(tags="", plugin=DIFF):
    return ROBOT.format(plugin=plugin, tags=tags)


def diameter_of(xml):
    plugin = ElementTree.fromstring(xml).find("gazebo/plugin")
    return float(plugin.findtext("wheelDiameter"))


def test_our_rb1_is_geared_down_by_its_written_diameter():
    with open(os.path.join(REPO, "my_rb1_description", "urdf", "my_rb1_robot.urdf")) as file:
        geared = gear_down(file.read(), 2.0)
    assert (geared.plugin, geared.diameter, geared.geared) == (DIFF, 0.05, 0.1)
    assert diameter_of_rb1(geared.xml) == pytest.approx(0.1)
    assert "0.05 m made 0.1 m" in geared.describe()


def diameter_of_rb1(xml):
    drive = next(p for p in ElementTree.fromstring(xml).iter("plugin")
                 if p.get("filename") == DIFF)
    return float(drive.findtext("wheelDiameter"))


def test_a_plugin_relying_on_the_default_diameter_gets_noetics_default_geared():
    # gazebo_ros_diff_drive.cpp:100, gazebo_ros_skid_steer_drive.cpp:152: 0.15 m
    for plugin in (DIFF, "libgazebo_ros_skid_steer_drive.so"):
        geared = gear_down(robot(plugin=plugin), 3.0)
        assert geared.diameter == 0.15
        assert diameter_of(geared.xml) == pytest.approx(0.45)


def test_world_odometry_written_or_not_is_geared_and_encoder_odometry_is_not():
    assert gear_down(robot("<odometrySource>world</odometrySource>"), 2.0)
    # a name Noetic's map does not hold falls back on its default, world (:105-107)
    assert gear_down(robot("<odometrySource>1</odometrySource>"), 2.0)
    with pytest.raises(CannotGearDown, match="odometrySource encoder"):
        gear_down(robot("<odometrySource> encoder </odometrySource>"), 2.0)


@pytest.mark.parametrize("xml, cause", [
    (robot(plugin="libgazebo_ros_planar_move.so"), "no drive plugin"),
    (robot().replace("</robot>", '<gazebo><plugin filename="libgazebo_ros_diff_drive.so"/>'
                                 "</gazebo></robot>"), "more than one"),
    (robot("<wheelDiameter>big</wheelDiameter>"), "'big' is not a number"),
    ("<robot><link", "does not parse"),
])
def test_a_robot_that_cannot_be_geared_down_says_why(xml, cause):
    with pytest.raises(CannotGearDown, match=cause):
        gear_down(xml, 2.0)


def test_a_factor_must_slow():
    with pytest.raises(ValueError):
        gear_down(robot(), 1.0)


FREE = Rotation(-90, -89.7, "done", answered_at=4.0, stopped_at=3.9)


def test_a_turn_by_odometry_still_reaches_the_angle_taking_longer():
    slowed = Rotation(-45, -44.7, "done", answered_at=6.0, stopped_at=5.5)
    passed, evidence = judge(FREE, 3.7, slowed, 5.5, 2.0, 5.0)
    assert passed
    assert "turns by odometry" in evidence
    assert "turned -44.7 in 5.5 s" in evidence and "turned -89.7 deg in truth in 3.7 s" in evidence
    assert "gives -44.9 by odometry, -22.4 by the clock" in evidence


def test_a_turn_by_the_clock_stops_near_its_share():
    slowed = Rotation(-45, -22.9, "done", answered_at=2.2, stopped_at=2.1)
    passed, evidence = judge(FREE, 3.7, slowed, 2.1, 2.0, 5.0)
    assert not passed
    assert "turns by the clock" in evidence and "near 1/2 of the angle" in evidence


def test_a_node_that_overshoots_by_odometry_overshoots_alike_geared_down():
    """A service that turns 1.069 times the request by its odometry (the rotate_overshoots
    fixture) turns by odometry: the free turn's share is what the slowed one is held to."""
    free = Rotation(-90, -96.2, "done", answered_at=4.0, stopped_at=3.9)
    slowed = Rotation(-45, -47.9, "done", answered_at=6.0, stopped_at=5.8)
    assert judge(free, 3.9, slowed, 5.8, 2.0, 5.0)[0]
    assert not judge(free, 3.9, Rotation(-45, -24.3, "", 2.0, 2.0), 2.0, 2.0, 5.0)[0]


def test_a_slowed_turn_neither_way_fails_naming_its_error():
    slowed = Rotation(-45, -35.0, "done", answered_at=4.0, stopped_at=4.0)
    passed, evidence = judge(FREE, 3.7, slowed, 4.0, 2.0, 5.0)
    assert not passed and "neither as by odometry nor as by the clock (+9.9 deg" in evidence


def test_a_check_asking_for_review_marks_the_item_and_says_why():
    item = next(i for i in course_file.load("rb1").items if i.id == "rotate_uses_odom")
    settled = judge_item(item, [Check("turns by /odom", True, "turned by odometry")])
    unsettled = judge_item(item, [Check.from_dict({
        "name": "turns by /odom", "passed": True, "evidence": "subscribes",
        "review": "not judged by behaviour: encoder odometry"})])
    assert settled.mark == "" and settled.awarded == 1.0
    assert unsettled.mark == "review" and unsettled.awarded == 1.0
    assert unsettled.review == ["turns by /odom: not judged by behaviour: encoder odometry"]

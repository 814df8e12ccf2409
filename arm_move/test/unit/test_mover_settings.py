"""The mover's and planner's settings read as the mover reads them (node_params, no
master): config/mover.yaml gives the dataclasses' defaults, and what arm.launch's arguments
hand over (text) is converted or refused naming the parameter, the value and what is
expected."""
import os

import pytest
import yaml

from arm_move.mover import MoverSettings
from arm_move.planner import CollisionSettings, PlannerSettings, settings_from
from node_params import ParameterError

YAML = os.path.join(os.path.dirname(__file__), "..", "..", "config", "mover.yaml")


def packaged():
    with open(YAML) as stream:
        return yaml.safe_load(stream)


def test_packaged_yaml_gives_the_defaults():
    values = packaged()
    assert settings_from(PlannerSettings, values, "~") == PlannerSettings()
    assert settings_from(CollisionSettings, values, "~") == CollisionSettings()
    assert settings_from(MoverSettings, values, "~") == MoverSettings()


def test_driver_timeout_as_roslaunch_hands_it_over():
    # <param name="action_timeout" value="$(arg driver_timeout)"/>: driver_timeout:=2.5
    # arrives as 2.5, :=2e1 as the text '2e1'
    assert settings_from(MoverSettings, dict(packaged(), action_timeout="2e1"),
                         "~").action_timeout == 20.0


@pytest.mark.parametrize("cls, name, value, says", [
    (MoverSettings, "action_timeout", "abc",
     "~action_timeout: 'abc' is not a number; expected wall seconds > 0 to wait for the "
     "controllers' action servers at start-up (arm.launch's driver_timeout)"),
    (MoverSettings, "action_timeout", 0, "~action_timeout: 0 is not positive"),
    (PlannerSettings, "seed", 0, "~seed: 0 is not between 1 and 4294967295"),
    (PlannerSettings, "velocity_scaling", 1.5, "~velocity_scaling: 1.5 is not in (0, 1]"),
    (PlannerSettings, "goal_count", "six", "~goal_count: 'six' is not a whole number"),
    (CollisionSettings, "collision_padding", "nan",
     "~collision_padding: 'nan' is not a finite number"),
])
def test_bad_settings_are_named(cls, name, value, says):
    with pytest.raises(ParameterError) as raised:
        settings_from(cls, dict(packaged(), **{name: value}), "~")
    assert says in str(raised.value)

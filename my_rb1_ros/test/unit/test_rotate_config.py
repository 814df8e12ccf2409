"""rotate_service's settings read as the node reads them (node_params, no master): the
packaged yaml gives the dataclass's defaults, and values a user can type are converted or
refused naming the parameter, the value and what is expected."""
import os

import pytest
import yaml

from my_rb1_ros.rotate_service import Config
from node_params import ParameterError

YAML = os.path.join(os.path.dirname(__file__), "..", "..", "config", "rotate_service.yaml")


def params(**values):
    return lambda name, default: values.get(name.lstrip("~"), default)


def test_packaged_yaml_holds_every_setting_and_the_same_defaults():
    with open(YAML) as stream:
        packaged = yaml.safe_load(stream)
    assert sorted(packaged) == sorted(Config().__dict__)
    assert Config.from_parameters(params(**packaged)) == Config()


def test_text_from_roslaunch_is_converted():
    config = Config.from_parameters(params(control_rate="25", max_degrees="720.0",
                                           odom_timeout="1e1"))
    assert (config.control_rate, config.max_degrees, config.odom_timeout) == (25.0, 720, 10.0)


@pytest.mark.parametrize("name, value, says", [
    ("control_rate", "abc", "~control_rate: 'abc' is not a number; expected the control"),
    ("control_rate", 0, "~control_rate: 0 is not positive; expected"),
    ("odom_timeout", "nan", "~odom_timeout: 'nan' is not a finite number"),
    ("max_degrees", 90.5, "~max_degrees: 90.5 is not a whole number"),
    ("time_slack", 0.5, "~time_slack: 0.5 is less than 1; expected a factor >= 1"),
    ("min_angular_speed", 2.0, "~min_angular_speed: 2.0 is more than ~max_angular_speed (0.8)"),
])
def test_bad_values_are_named(name, value, says):
    with pytest.raises(ParameterError) as raised:
        Config.from_parameters(params(**{name: value}))
    assert says in str(raised.value)

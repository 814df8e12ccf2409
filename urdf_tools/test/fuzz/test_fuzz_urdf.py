"""Fuzz: urdf_tools.model.parse_urdf on generated and mutated descriptions ends in a
RobotModel or a UrdfError naming the source and a cause; never another exception or a hang."""
from hypothesis import given

from description_fuzz import examples, generated_urdf, urdf_case
from fuzz_checks import check_refusal, time_limit
from urdf_tools.model import RobotModel, UrdfError, parse_urdf

SOURCE = "fuzz.urdf"


def parse(text):
    try:
        with time_limit():
            model = parse_urdf(text, SOURCE)
    except Exception as error:  # anything but UrdfError fails check_refusal
        check_refusal(error, (UrdfError,), SOURCE, text)
        return None
    assert isinstance(model, RobotModel)
    # what the simulator asks of every model it gets
    assert model.links and model.root() in model.links
    return model


@examples(600, 20000)
@given(urdf_case())
def test_mutated_descriptions(case):
    parse(case[1])


@examples(400, 10000)
@given(generated_urdf())
def test_generated_descriptions(text):
    parse(text)

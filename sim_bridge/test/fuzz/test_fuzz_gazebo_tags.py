"""Fuzz: sim_bridge.gazebo_tags.read_gazebo_tags on robots whose <gazebo> blocks are
generated and mutated ends in GazeboTags or a UrdfError naming the source and a cause."""
from hypothesis import given
from hypothesis import strategies as st

from description_fuzz import GAZEBO_MUTATIONS, examples, generated_urdf, mutated, urdf_seeds
from fuzz_checks import check_refusal, time_limit
from sim_bridge.gazebo_tags import GazeboTags, read_gazebo_tags
from urdf_tools.model import UrdfError, parse_urdf

SOURCE = "fuzz_gazebo.urdf"


class _Data:
    def __init__(self, draw):
        self.draw = draw


@st.composite
def gazebo_case(draw):
    """A robot that parses, its <gazebo> blocks mutated (the rest left alone)."""
    seeds = [s for s in urdf_seeds() if "<gazebo" in s[1]]
    if draw(st.booleans()):
        text = seeds[draw(st.integers(0, len(seeds) - 1), label="seed")][1]
    else:
        text = draw(generated_urdf())
    return mutated(_Data(draw), text, GAZEBO_MUTATIONS, within="gazebo", max_mutations=6)


def read(text):
    try:
        with time_limit():
            model = parse_urdf(text, SOURCE)
    except UrdfError:
        return  # the URDF reader's fuzz covers this
    try:
        with time_limit():
            tags = read_gazebo_tags(model)
    except Exception as error:
        check_refusal(error, (UrdfError,), SOURCE, text)
        return
    assert isinstance(tags, GazeboTags)
    for plugin in tags.plugins + [p for s in tags.sensors for p in s.plugins]:
        assert plugin.filename


@examples(600, 20000)
@given(gazebo_case())
def test_mutated_gazebo_blocks(text):
    read(text)

"""Fuzz: sim_bridge.sdf_world's readers on mutated worlds and models (the workspace's own
as seeds; <include>s of model:// URIs that exist, that do not, that include themselves)
end in a WorldSpec / ModelSpec or an SdfError naming the file and a cause."""
from hypothesis import given

from description_fuzz import examples, sdf_case
from fuzz_checks import check_refusal, time_limit
from world_folder import written_world
from sim_bridge import sdf_world
from sim_bridge.sdf_world import ModelSpec, SdfError, WorldSpec

SOURCE = "fuzz.sdf"


@examples(600, 20000)
@given(sdf_case(world=False))
def test_mutated_models(case):
    _, text, _ = case
    try:
        with time_limit():
            spec = sdf_world.parse_model(text, SOURCE, warn=lambda text: None)
    except Exception as error:
        check_refusal(error, (SdfError,), SOURCE, text)
        return
    assert isinstance(spec, ModelSpec) and spec.name


@examples(300, 10000)
@given(sdf_case(world=True))
def test_mutated_worlds(case):
    _, text, files = case
    with written_world(text, files, "fuzz_sdf_", keep_model_path=False) as (folder, world_file):
        try:
            with time_limit():
                spec = sdf_world.load_world(world_file, warn=lambda text: None)
        except Exception as error:
            # the file refused may be the world or a model it includes: all under folder,
            # or the model library's
            named = folder if folder in str(error) else "/"
            check_refusal(error, (SdfError,), named, text)
            return
        assert isinstance(spec, WorldSpec)

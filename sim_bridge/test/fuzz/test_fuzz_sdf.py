"""Fuzz: sim_bridge.sdf_world's readers on mutated worlds and models (the workspace's own
as seeds; <include>s of model:// URIs that exist, that do not, that include themselves)
end in a WorldSpec / ModelSpec or an SdfError naming the file and a cause."""
import os
import shutil
import tempfile

from hypothesis import given

from description_fuzz import examples, sdf_case
from fuzz_checks import check_refusal, time_limit
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
    folder = tempfile.mkdtemp(prefix="fuzz_sdf_")
    saved = os.environ.get("GAZEBO_MODEL_PATH")
    try:
        for relative, content in files.items():
            path = os.path.join(folder, relative)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w", encoding="utf-8", errors="surrogatepass") as stream:
                stream.write(content)
        world_file = os.path.join(folder, "fuzz.world")
        with open(world_file, "w", encoding="utf-8", errors="surrogatepass") as stream:
            stream.write(text)
        os.environ["GAZEBO_MODEL_PATH"] = os.path.join(folder, "models")
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
    finally:
        if saved is None:
            os.environ.pop("GAZEBO_MODEL_PATH", None)
        else:
            os.environ["GAZEBO_MODEL_PATH"] = saved
        shutil.rmtree(folder, ignore_errors=True)

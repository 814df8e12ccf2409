"""Fuzz: the spawn path on pybullet.DIRECT, in a separate worker process (spawn_worker.py,
through spawn_client.py): generated and mutated URDF robots (World.spawn_urdf), SDF models
(sdf_world.parse_model, World.add_sdf_model) and worlds (sdf_world.load_world,
World.load_world) end in a model that steps, or in SimError / UrdfError / SdfError naming a
cause, with nothing left behind in pybullet; never another exception, a crash (a signal)
or a hang. Findings are also written to test_results/fuzz/."""
from hypothesis import given
from hypothesis import strategies as st

from description_fuzz import EXTREMES, examples, generated_urdf, sdf_case, urdf_case

DOCUMENTED = ("SimError", "UrdfError", "SdfError")
NAME = "fuzz"


@st.composite
def pose(draw):
    """Mostly just above the ground; sometimes extremes (World checks them)."""
    if draw(st.integers(0, 9)):
        return [0.0, 0.0, draw(st.sampled_from((0.0, 0.1, 1.0)))], [0.0, 0.0, 0.0, 1.0]
    values = st.one_of(st.floats(allow_nan=True, allow_infinity=True),
                       st.sampled_from((0.0, 1e300, -1e300, 3.5e38)))
    return (draw(st.lists(values, min_size=3, max_size=3)),
            draw(st.lists(values, min_size=4, max_size=4)))


def check(answer, case):
    shown = case["text"] if len(case["text"]) < 2000 else case["text"][:2000] + " ..."
    assert answer["outcome"] in ("model", "refused"), (
        f"{answer['outcome']}: {answer.get('type', '')} {answer['message']}\n"
        f"{answer.get('traceback', '') or answer.get('stderr', '')}\ninput:\n{shown}")
    if answer["outcome"] == "refused":
        assert answer["type"] in DOCUMENTED, answer
        assert answer["message"].strip(), f"{answer['type']} without a message:\n{shown}"
    assert not answer.get("leaked"), (
        f"{answer['leaked']} pybullet bodies left behind after {answer['outcome']} "
        f"({answer.get('message', '')}):\n{shown}")


def spawn(spawner, kind, text, where, files=None):
    position, orientation = where
    case = {"kind": kind, "text": text, "name": NAME, "position": position,
            "orientation": orientation, "files": files or {}}
    check(spawner.run(case), case)


@examples(500, 5000)
@given(urdf_case(), pose())
def test_spawn_mutated_urdf(spawner, case, where):
    spawn(spawner, "urdf", case[1], where)


@examples(500, 5000)
@given(generated_urdf(), pose())
def test_spawn_generated_urdf(spawner, text, where):
    spawn(spawner, "urdf", text, where)


@examples(400, 3000)
@given(sdf_case(world=False), pose())
def test_spawn_sdf_models(spawner, case, where):
    spawn(spawner, "sdf", case[1], where)


@examples(80, 1000)
@given(sdf_case(world=True))
def test_load_worlds(spawner, case):
    spawn(spawner, "world", case[1], ([0, 0, 0], [0, 0, 0, 1]), case[2])

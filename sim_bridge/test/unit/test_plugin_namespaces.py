"""Where a spawned model's plugins live, as gazebo_ros's spawn service places them: the
request's namespace goes to every plugin that names none; a plugin's own <robotNamespace>
is kept ("/" the top level); an empty one is read as the request's."""
import pytest

from world_fixtures import run


@pytest.mark.parametrize("own,spawned_in,topics_under", [
    ("", "/r1", "/r1"),          # the tag is there but empty: the request's
    ("/", "/r1", ""),            # the top level, whatever the request says
    ("/team_a", "/r1", "/team_a"),
    ("team_a", "", "/team_a"),
    ("/team_a", "/", "/team_a"),  # spawn_model at the top level sends "/"
])
def test_a_plugins_own_namespace_is_kept(world, bus, diff_bot_xml, own, spawned_in,
                                         topics_under):
    world.spawn_urdf("bot", diff_bot_xml(namespace=own), position=(0, 0, 0.1),
                     namespace=spawned_in)
    run(world, 0.1)
    assert f"{topics_under}/cmd_vel" in bus.subscriptions, sorted(bus.subscriptions)
    assert f"{topics_under}/scan" in bus.published, sorted(bus.published)

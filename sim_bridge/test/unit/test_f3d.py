"""gazebo_ros_f3d: the wrench published is the one that moves the link (its momentum
changes by the published force times the time it acted), in world axes with the torque
about the centre of mass; nothing once the wrench is over; a lumped link is refused as
Gazebo's model has no such link."""
import numpy as np
import pytest

from world_fixtures import run

SECOND = 1_000_000_000
MASS = 4.0


def probe(body="hull", frame=""):
    """A 4 kg box with a sensor mast on a fixed joint (lumped into the hull, as Gazebo
    does) and the f3d plugin on ``body``."""
    return f"""<robot name="probe">
      <link name="hull"><inertial><mass value="{MASS}"/><inertia ixx="0.1" ixy="0" ixz="0"
        iyy="0.1" iyz="0" izz="0.1"/></inertial>
        <collision><geometry><box size="0.4 0.4 0.2"/></geometry></collision></link>
      <joint name="mast_mount" type="fixed"><parent link="hull"/><child link="mast"/>
        <origin xyz="0 0 0.3"/></joint>
      <link name="mast"><inertial><mass value="0.001"/><inertia ixx="1e-6" ixy="0" ixz="0"
        iyy="1e-6" iyz="0" izz="1e-6"/></inertial></link>
      <gazebo><plugin name="f3d" filename="libgazebo_ros_f3d.so">
        <bodyName>{body}</bodyName><topicName>hull_force</topicName>{frame}
      </plugin></gazebo></robot>"""


@pytest.fixture
def weightless(world):
    world.set_physics(world.step_size, world.max_update_rate, (0.0, 0.0, 0.0))
    return world


def vector(v):
    return np.array([v.x, v.y, v.z])


def test_the_published_wrench_is_the_one_that_moves_the_link(weightless, bus):
    weightless.spawn_urdf("probe", probe(), (0, 0, 2))
    run(weightless, 0.05)
    assert not vector(bus.last("/hull_force").wrench.force).any()
    # 3 N along x, pushed 0.1 m to the left of the centre of mass: 0.3 N m about -z
    weightless.apply_wrench("probe::hull", (3.0, 0, 0), (0, 0, 0), reference_point=(0, 0.1, 0),
                            duration_ns=SECOND // 5)
    published = []
    for _ in range(int(0.3 / weightless.step_size)):
        weightless.step()
        published.append(bus.last("/hull_force"))
    pushing = [m for m in published if vector(m.wrench.force).any()]
    force = vector(pushing[0].wrench.force)
    assert force == pytest.approx((3.0, 0, 0))
    assert vector(pushing[0].wrench.torque) == pytest.approx((0, 0, -0.3))
    # the momentum the body (hull and mast) gained is the force published times the time it
    # acted: a message stamped t reports the step starting at t, and the first step's went
    # out before the request came (as in Gazebo, where requests wait for the next step)
    step = weightless.step_size
    gained = (MASS + 0.001) * weightless.twist("probe")[0][0]
    assert gained == pytest.approx(3.0 * 0.2, rel=1e-9)
    assert all(vector(m.wrench.force) == pytest.approx((3.0, 0, 0)) for m in pushing)
    assert len(pushing) * step == pytest.approx(0.2 - step)
    assert not vector(published[-1].wrench.force).any()  # over
    assert published[-1].header.frame_id == "world"
    assert published[-1].header.stamp.to_sec() == pytest.approx(weightless.now_ns / 1e9)


def test_frame_name_is_only_the_header(weightless, bus):
    weightless.spawn_urdf("probe", probe(frame="<frameName>hull</frameName>"), (0, 0, 2))
    weightless.set_state("probe", (0, 0, 2), (0, 0, 0.7071068, 0.7071068))  # turned 90 deg
    weightless.apply_wrench("probe::hull", (1.0, 0, 0), (0, 0, 0), duration_ns=SECOND)
    run(weightless, 0.01)
    message = bus.last("/hull_force")
    assert message.header.frame_id == "hull"
    assert vector(message.wrench.force) == pytest.approx((1.0, 0, 0))  # world axes still


def test_a_lumped_link_is_refused_naming_its_holder(weightless, bus):
    weightless.spawn_urdf("probe", probe(body="mast"), (0, 0, 2))
    assert "probe" in weightless.models
    (warning,) = [w for w in bus.warnings if "libgazebo_ros_f3d.so" in w]
    assert "'mast' is lumped into link 'hull' by fixed joint 'mast_mount'" in warning
    assert "not loaded" in warning

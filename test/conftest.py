"""Fixtures shared by the workspace-level tests: paths, a private master, a virtual screen."""
import contextlib
import os
import subprocess
import sys

import pytest
import rosgraph

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(REPO, "tools"))

import headless  # noqa: E402  (tools/ is not a package; it is put on the path above)

MASTER_START_LIMIT = 30   # s (wall): roscore answering on a busy 2-core machine
MASTER_STOP_LIMIT = 20    # s (wall): roscore ended after SIGTERM
MASTER_POLL = 0.05        # s (wall) between asking whether the master answers


@pytest.fixture(scope="session")
def repo():
    return REPO


@pytest.fixture
def results_dir(request):
    """A folder under test_results/ for this test's logs and pictures."""
    path = os.path.join(REPO, "test_results", "e2e", request.node.name.replace("/", "_"))
    os.makedirs(path, exist_ok=True)
    return path


@pytest.fixture
def ros_env(results_dir):
    """Environment for roslaunch: a master on a free port, logs under results_dir."""
    with headless.private_master(os.path.join(results_dir, "ros_home")) as env:
        yield env


@pytest.fixture
def screen_env(ros_env):
    """ros_env plus a fresh Xvfb display, rendering in software."""
    with headless.virtual_display() as display:
        env = dict(ros_env, DISPLAY=display, LIBGL_ALWAYS_SOFTWARE="1")
        yield env


def master_online(env) -> bool:
    """True when the master of ``env`` answers (asked in this process: no rosnode start-up)."""
    return rosgraph.Master("/e2e_master_check", master_uri=env["ROS_MASTER_URI"]).is_online()


@contextlib.contextmanager
def running_master(env):
    """A roscore on the port of ``env``'s ROS_MASTER_URI until the block ends."""
    port = env["ROS_MASTER_URI"].rsplit(":", 1)[1]
    core = subprocess.Popen(["roscore", "-p", port], env=env, stdout=subprocess.DEVNULL,
                            stderr=subprocess.STDOUT, start_new_session=True)
    try:
        headless.wait_until(lambda: master_online(env), MASTER_START_LIMIT, "the master",
                            MASTER_POLL)
        yield env
    finally:
        core.terminate()
        core.wait(timeout=MASTER_STOP_LIMIT)


@pytest.fixture
def master(ros_env):
    """ros_env with a roscore running on its port (for nodes started by hand)."""
    with running_master(ros_env):
        yield ros_env


@pytest.fixture(scope="module")
def module_master(tmp_path_factory):
    """One roscore for a whole test module (its start and stop cost about 2 s a test)."""
    ros_home = str(tmp_path_factory.mktemp("module_master"))
    with headless.private_master(ros_home) as env, running_master(env):
        yield env


@pytest.fixture
def shared_master(module_master, results_dir):
    """The module's roscore, as if new to each test: its logs in the test's results_dir, and
    every parameter the test set (``_name:=value``, a launch file's) deleted after it, so
    that no test sees another's settings. A node that died stays registered until the next
    of its name replaces it, as on any master."""
    server = rosgraph.Master("/e2e_parameter_cleaner", master_uri=module_master["ROS_MASTER_URI"])
    before = set(server.getParamNames())
    yield dict(module_master, ROS_HOME=os.path.join(results_dir, "ros_home"))
    for name in set(server.getParamNames()) - before:
        server.deleteParam(name)

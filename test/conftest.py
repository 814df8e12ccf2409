"""Fixtures shared by the workspace-level tests: paths, a private master, a virtual screen."""
import os
import subprocess
import sys

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(REPO, "tools"))

import headless  # noqa: E402  (tools/ is not a package; it is put on the path above)


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


@pytest.fixture
def master(ros_env):
    """ros_env with a roscore running on its port (for nodes started by hand)."""
    port = ros_env["ROS_MASTER_URI"].rsplit(":", 1)[1]
    core = subprocess.Popen(["roscore", "-p", port], env=ros_env, stdout=subprocess.DEVNULL,
                            stderr=subprocess.STDOUT, start_new_session=True)
    try:
        headless.wait_until(lambda: subprocess.run(["rosnode", "list"], env=ros_env,
                                                   capture_output=True, check=False).returncode == 0,
                            30, "the master")
        yield ros_env
    finally:
        core.terminate()
        core.wait(timeout=20)

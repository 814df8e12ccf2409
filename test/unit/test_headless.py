"""tools/headless.py: a launch whose rviz died of a signal is started again, nothing else is."""
import contextlib
import os
import sys

import pytest
from roslaunch import nodeprocess

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))), "tools"))
import headless  # noqa: E402  (tools/ is not a package)


def death_line(name, exit_code, required):
    """What roslaunch prints for a dead node: the process's own description of its end
    (nodeprocess.LocalProcess) inside the process monitor's line for it (pmon)."""
    process = nodeprocess.LocalProcess("run", "rviz", name, ["/usr/lib/rviz/rviz"], {}, False)
    process.pid, process.exit_code = 42, exit_code
    description = process.get_exit_description()
    if required:
        return "=" * 80 + f"REQUIRED process [{name}] has died!\n{description}\n"
    return f"\x1b[31m[{name}] {description}\x1b[0m"     # printerrlog colours it red


@pytest.mark.parametrize("required", [True, False])
def test_a_signal_death_is_recognised_required_or_not(required):
    assert headless.died_of_signal(death_line("rviz-4", -6, required), "rviz")


@pytest.mark.parametrize("name,exit_code,node", [
    ("rviz-4", 1, "rviz"),          # an error exit, not a crash
    ("rviz-4", 0, "rviz"),
    ("rqt_gui-2", -11, "rviz"),     # another node
    ("rviz2-3", -6, "rviz"),
])
def test_other_deaths_are_not_an_rviz_crash(name, exit_code, node):
    assert not headless.died_of_signal(death_line(name, exit_code, True), node)
    assert not headless.died_of_signal(death_line(name, exit_code, False), node)


class FakeLaunch:
    def __init__(self, output):
        self._output = output

    def output(self):
        return self._output


def fake_roslaunch(outputs, logs):
    @contextlib.contextmanager
    def start(arguments, env, log_path):
        logs.append(log_path)
        yield FakeLaunch(outputs[len(logs) - 1])
    return start


def test_a_crash_starts_the_launch_again_with_its_own_log(monkeypatch, capsys):
    logs = []
    crashed = death_line("rviz-4", -6, True)
    monkeypatch.setattr(headless, "roslaunch", fake_roslaunch([crashed, crashed, ""], logs))

    def body(launch):
        if launch.output():
            raise RuntimeError("roslaunch exited early")
        return "picture"

    assert headless.run_while_node_lives(["p", "x.launch"], {}, "/r/a.log", body) == "picture"
    assert logs == ["/r/a.log", "/r/a-2.log", "/r/a-3.log"]
    assert capsys.readouterr().out.count("rviz died of a signal") == 2


def test_any_other_failure_is_raised_at_once(monkeypatch):
    logs = []
    monkeypatch.setattr(headless, "roslaunch", fake_roslaunch(
        [death_line("rviz-4", 1, True)], logs))

    def body(launch):
        raise RuntimeError("roslaunch exited early")

    with pytest.raises(RuntimeError):
        headless.run_while_node_lives(["p", "x.launch"], {}, "/r/a.log", body)
    assert logs == ["/r/a.log"]


def test_the_last_crash_is_raised(monkeypatch):
    logs = []
    crashed = death_line("rviz-4", -6, False)
    monkeypatch.setattr(headless, "roslaunch", fake_roslaunch([crashed] * 3, logs))

    def body(launch):
        raise headless.WaitTimeout("timed out waiting for a window titled 'RViz'")

    with pytest.raises(headless.WaitTimeout):
        headless.run_while_node_lives(["p", "x.launch"], {}, "/r/a.log", body)
    assert len(logs) == headless.RVIZ_STARTS


def test_launch_processes_are_the_launch_and_everything_under_it():
    """What launch_window matches a window's owner against: children and grandchildren."""
    import subprocess
    tree = subprocess.Popen(["bash", "-c", "sleep 60 & (sleep 61 & wait) & wait"],
                            start_new_session=True)
    stranger = subprocess.Popen(["sleep", "62"])
    try:
        launch = headless.Launch(tree, os.devnull)

        def sleeps(found):
            return sorted(c for c in found.values() if c.startswith("sleep"))

        # until both children have exec'd sleep: a child forked but not yet exec'd still
        # reads "bash -c ..." (four processes with one sleep failed a fresh-clone run)
        commands = headless.wait_until(
            lambda: (lambda found: found if sleeps(found) == ["sleep 60", "sleep 61"]
                     else None)(headless.launch_processes(launch)), 10, "the tree to start")
        assert tree.pid in commands and stranger.pid not in commands
        assert len(commands) == 4, commands    # bash, its subshell, the two sleeps
    finally:
        os.killpg(tree.pid, 9)
        stranger.kill()
        tree.wait()
        stranger.wait()


def test_the_virtual_screen_does_not_reset_when_its_last_client_leaves():
    """Xvfb resets itself when its last client leaves unless -noreset, and refuses a client
    that connects meanwhile (a window opened just after the last one closed). A reset
    clears the root window's properties: one set by a client that then left must stay."""
    import subprocess
    import time
    with headless.virtual_display(64, 48) as display:
        env = dict(os.environ, DISPLAY=display)
        subprocess.run(["xprop", "-root", "-f", "SIM_BRIDGE_MARK", "8s", "-set",
                        "SIM_BRIDGE_MARK", "kept"], env=env, check=True, timeout=20)
        time.sleep(0.5)   # a reset, if any, follows the client's exit at once
        read = subprocess.run(["xprop", "-root", "SIM_BRIDGE_MARK"], env=env,
                              capture_output=True, text=True, check=True, timeout=20)
    assert '"kept"' in read.stdout, read.stdout

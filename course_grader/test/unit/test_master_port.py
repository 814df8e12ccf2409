"""course_grader.master_port: a reserved port is nobody else's until released, in this
process or another, and is drawn where outgoing connections do not draw theirs."""
import fcntl
import os
import socket
import subprocess
import sys

import pytest

from course_grader import master_port
from course_grader.master_port import PortReservation


def test_held_ports_are_never_handed_out_twice():
    held = [PortReservation() for _ in range(50)]
    try:
        assert len({r.port for r in held}) == 50
    finally:
        for reservation in held:
            reservation.release()


def test_a_port_is_drawn_below_the_kernels_ephemeral_range():
    with open(master_port.EPHEMERAL_RANGE, encoding="ascii") as stream:
        first_ephemeral = int(stream.read().split()[0])
    with PortReservation() as reservation:
        assert master_port.LOWEST <= reservation.port < first_ephemeral


def test_another_process_skips_a_held_port(monkeypatch):
    with PortReservation() as reservation:
        # the other process may draw only this port: it must give up, not take it
        code = ("import sys; from course_grader import master_port as m\n"
                f"m._below_ephemeral = lambda: range({reservation.port}, {reservation.port + 1})\n"
                "m.ATTEMPTS = 5\n"
                "try:\n    m.PortReservation()\nexcept RuntimeError as e:\n"
                "    print(e); sys.exit(3)\n")
        other = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                               timeout=30, check=False)
        assert other.returncode == 3, other.stderr
        assert "no free port" in other.stdout
    # released: the same draw succeeds
    monkeypatch.setattr(master_port, "_below_ephemeral",
                        lambda: range(reservation.port, reservation.port + 1))
    with PortReservation() as again:
        assert again.port == reservation.port


def test_a_port_a_server_listens_on_is_skipped(monkeypatch):
    with socket.socket() as server:
        server.bind(("127.0.0.1", 0))
        server.listen()
        busy = server.getsockname()[1]
        monkeypatch.setattr(master_port, "_below_ephemeral", lambda: range(busy, busy + 1))
        monkeypatch.setattr(master_port, "ATTEMPTS", 5)
        with pytest.raises(RuntimeError, match="no free port"):
            PortReservation()
    # not left locked by the failed tries
    with open(os.path.join(master_port.RESERVATIONS, str(busy)), "a", encoding="ascii") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)


def test_a_scenario_refuses_a_master_that_is_not_its_own(tmp_path, monkeypatch):
    """Another run's master on the scenario's port (here one in this test's process) answers
    the grader's first call; the scenario stops there, naming it, instead of running the
    guide's launch files among that run's nodes."""
    import threading
    import xmlrpc.server
    from course_grader import ros_run

    foreign = xmlrpc.server.SimpleXMLRPCServer(("127.0.0.1", 0), logRequests=False)
    foreign.register_function(lambda caller: [1, "", os.getpid()], "getPid")
    threading.Thread(target=foreign.serve_forever, daemon=True).start()
    port = foreign.server_address[1]

    class Taken:
        def __init__(self):
            self.port = port

        def release(self):
            pass
    monkeypatch.setattr(ros_run, "PortReservation", Taken)
    # roscore finds the port taken and gives up, as the real one does
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    (bin_dir / "roscore").write_text("#!/bin/sh\necho 'port in use' >&2\nexit 1\n")
    (bin_dir / "roscore").chmod(0o755)
    env = dict(os.environ, PATH=f"{bin_dir}:{os.environ['PATH']}")
    try:
        with ros_run.Session(env, str(tmp_path / "logs"), {"startup": 5.0, "stop": 2.0}) as session:
            with pytest.raises(ros_run.RunError, match=f"another run's ROS master answers on port {port}"):
                session.start_master()
    finally:
        foreign.shutdown()

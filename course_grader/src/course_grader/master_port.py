"""A port for a private ROS master that no other run on this machine takes meanwhile.

Asking the kernel for a free port (``bind`` to port 0) and closing the socket before
``roscore -p`` binds it left two ways to lose it: the kernel may hand the same number to
the next ``bind`` to port 0 (another grading starting its roscore at the same moment), and
an outgoing connection (ROS opens many) may take it as its local port, since port-0 binds
draw from the same ephemeral range. A graded solution whose roscore met another
grading's master ran its launch files on that master, and the other run's nodes of the
same names replaced its own (make test's hw3 solution lost a step item so, once).

So a port here is drawn below the kernel's ephemeral range (``ip_local_port_range``) and
held, for as long as the run needs it, by an advisory lock on a file named after it in
:data:`RESERVATIONS`: every user of this module on the machine skips a held port.
"""
from __future__ import annotations

import errno
import fcntl
import os
import random
import socket
from typing import Optional, TextIO

RESERVATIONS = "/tmp/.ros-master-ports"
EPHEMERAL_RANGE = "/proc/sys/net/ipv4/ip_local_port_range"
LOWEST = 20000            # above the well-known and most registered services' ports
ATTEMPTS = 200


def _below_ephemeral() -> range:
    try:
        with open(EPHEMERAL_RANGE, encoding="ascii") as stream:
            first = int(stream.read().split()[0])
    except (OSError, ValueError, IndexError):
        first = 32768         # Linux's default first ephemeral port
    return range(LOWEST, max(LOWEST + 1000, first))


def _bindable(port: int) -> bool:
    with socket.socket() as sock:
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            sock.bind(("127.0.0.1", port))
        except OSError:
            return False
    return True


class PortReservation:
    """A port held until :meth:`release` (or the end of a ``with`` block, or of the
    process: the kernel drops the lock with the file)."""

    def __init__(self) -> None:
        os.makedirs(RESERVATIONS, exist_ok=True)
        candidates = _below_ephemeral()
        self._lock: Optional[TextIO] = None
        for _ in range(ATTEMPTS):
            port = random.choice(candidates)
            lock = open(os.path.join(RESERVATIONS, str(port)), "a",  # pylint: disable=consider-using-with
                        encoding="ascii")
            try:
                fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except OSError as error:
                lock.close()
                if error.errno in (errno.EAGAIN, errno.EACCES):
                    continue
                raise
            if _bindable(port):
                self.port, self._lock = port, lock
                return
            lock.close()
        raise RuntimeError(f"no free port for a ROS master in {candidates.start}-"
                           f"{candidates.stop - 1} after {ATTEMPTS} tries")

    def release(self) -> None:
        if self._lock is not None:
            self._lock.close()
            self._lock = None

    def __enter__(self) -> "PortReservation":
        return self

    def __exit__(self, *exc) -> None:
        self.release()

"""What every fuzz case must end in: a result, or the documented error with a message that
names something; never another exception, and never longer than a time limit."""
from __future__ import annotations

import contextlib
import signal
from typing import Iterator, Tuple, Type

# The longest one case may take in-process before it counts as a hang (s). The slowest
# legitimate case, a 1000-link chain, takes about 0.2 s to parse.
CASE_SECONDS = 20


class Hang(Exception):
    """A case ran longer than CASE_SECONDS."""


@contextlib.contextmanager
def time_limit(seconds: float = CASE_SECONDS) -> Iterator[None]:
    """Raises Hang in the main thread when the block runs longer than ``seconds``."""
    def expired(signum, frame):
        raise Hang(f"the case ran longer than {seconds} s")
    previous = signal.signal(signal.SIGALRM, expired)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def check_refusal(error: BaseException, documented: Tuple[Type[BaseException], ...],
                  source: str, text: str) -> None:
    """``error`` must be one of ``documented`` and say something: non-empty, naming the
    source it was given (urdf_tools and sim_bridge start their messages with it)."""
    shown = text if len(text) < 3000 else text[:1500] + " ... " + text[-1500:]
    assert isinstance(error, documented), \
        f"{type(error).__name__}: {error!r} is not {documented} for input:\n{shown}"
    message = str(error).strip()
    assert message, f"{type(error).__name__} without a message for input:\n{shown}"
    assert source in message and len(message) > len(source) + 3, \
        f"the message {message!r} does not name the source {source!r} and a cause"

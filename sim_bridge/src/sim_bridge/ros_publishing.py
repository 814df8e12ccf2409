"""Publishing from the simulator's loop at the rate it steps, without rospy's hand-off cost.

Two things of rospy's cost the simulator more than its physics did (measured, see the
README's "Speed"):

- A publisher with a ``queue_size`` hands every message to a writer thread per subscriber
  (rospy's ``QueuedConnection``) and then calls ``time.sleep(0)`` to give that thread the
  interpreter at once: about 90 µs per message per subscriber (260 µs with three), where
  writing the bytes costs 5. /clock alone is published 250 times a simulated second.
  :func:`batch_queued_writes` replaces that connection class, in this process only, by one
  that writes the message into the socket at once when the socket takes it without
  waiting, and otherwise queues it and returns (:class:`BatchedConnection`). The queue
  keeps its ``queue_size`` (the oldest message dropped when full), so a subscriber that
  stops reading costs the simulator nothing; a ``queue_size=None`` publisher would block
  the loop on that subscriber's socket instead.
- With ``use_sim_time`` set, rospy subscribes every node to /clock, the simulator
  included: it received each of its own 250 messages a second to learn what it already
  knew. :class:`OwnClock` drops that subscription and sets rospy's time directly.
- Building, then serialising, a ``Clock`` message and its ``rospy.Time`` 250 times a
  simulated second cost more than writing it (about 13 µs a message against 9 for the
  write, profiled at full speed). :class:`ClockPublisher` packs its 8 bytes itself and
  hands them to the publisher's connections as rospy would (:func:`publish_serialized`).
- At every step (Gazebo's default), each /clock write wakes every subscriber's process:
  16-19 µs a message on the development VM, 1000 times a simulated second, more than the
  rest of the ROS side. :class:`ClockPublisher` therefore writes the steps' messages of up
  to ``COALESCE`` wall seconds in one write, each message whole and in order (TCPROS frames
  follow one another in a stream), so a subscriber still receives every step's time, in
  order, at most ``COALESCE`` later, and is woken once for them. A step that takes longer
  than that (a slow scene) writes its message at once, and the loop writes what is pending
  before it sleeps (paced) or pauses (:meth:`ClockPublisher.flush`).
- What the loop asks at every step must not take rospy's locks: whether a topic has
  subscribers is read from the publisher's list of connections (:func:`has_connections`,
  0.1 us against 0.5 for ``get_num_connections``), and rospy's time is made without
  ``rospy.Time``'s argument checks (:func:`ros_time`, 0.1 us against 0.6).
"""
from __future__ import annotations

import math
import socket
import struct
import time
from typing import Callable, List, Optional

import rospy
import rospy.impl.simtime
import rospy.rostime
import rospy.topics
from rosgraph_msgs.msg import Clock
from rospy.impl.tcpros_pubsub import QueuedConnection

# A rosgraph_msgs/Clock on the wire: TCPROS's length prefix (8), then secs and nsecs
CLOCK_WIRE = struct.Struct("<III")
NS_PER_S = 1_000_000_000
# wall seconds of /clock messages written together (see the module's notes): a real-time
# step's length, so a subscriber at full speed wakes about as often as at real time
COALESCE = 0.001


class BatchedConnection(QueuedConnection):
    """rospy's queued connection, where a message goes straight into the subscriber's
    socket when it can: when nothing of this connection is queued or being written and
    the socket takes the message without waiting (``MSG_DONTWAIT``). Otherwise, as rospy's,
    it is queued for the connection's writer thread, which sends it in order (what part of
    a message the socket took at once, the writer sends the rest of first), without
    yielding the interpreter on every message. The bytes and their order on the wire are
    rospy's; a subscriber that stops reading fills its socket, and from then on its
    messages wait in the queue (the oldest dropped beyond ``queue_size``) while the
    simulator goes on.

    Why: handing each message to the writer thread made every message a hand-over of the
    interpreter between two threads (the writer wakes, waits for the interpreter, gives it
    back to send, takes it again): /clock alone is 250 messages a simulated second."""

    def __init__(self, connection, queue_size):
        # set before rospy's __init__ starts the writer thread, which reads them
        self._rest = b""  # what the socket did not take of a message sent at once
        self._writing = False  # the writer thread is sending what it took from the queue
        super().__init__(connection, queue_size)

    def write_data(self, data):
        with self._lock:
            # an error the writer thread met is raised here, as rospy's class does
            if self._error:
                error, self._error = self._error, None
                raise error
            if not (self._queue or self._rest or self._writing):
                sent = self._send_at_once(data)
                if sent == len(data):
                    return True
                if sent:
                    self._rest = data[sent:]
                    self._cond_data_available.notify()
                    return True
            if self._queue_size > 0 and len(self._queue) == self._queue_size:
                del self._queue[0]
            self._queue.append(data)
            self._cond_data_available.notify()
        return True

    def _send_at_once(self, data) -> int:
        """Bytes of ``data`` the socket took without waiting (0 when it would wait, or on an
        error, which the writer thread then meets and reports as rospy's does)."""
        transport = self._connection
        sock = getattr(transport, "socket", None)
        # a socket with a timeout would wait for room before sending, whatever the flag
        if sock is None or transport.done or sock.gettimeout():
            return 0
        try:
            sent = sock.send(data, socket.MSG_DONTWAIT)
        except OSError:
            return 0
        transport.stat_bytes += sent
        if sent == len(data):
            transport.stat_num_msg += 1
        return sent

    def _run(self):
        """rospy's writer loop, sending a message's rest first and saying while it writes."""
        while not self._connection.done:
            with self._lock:
                while not (self._queue or self._rest) and not self._connection.done:
                    self._cond_data_available.wait()
                queue = ([self._rest] if self._rest else []) + self._queue
                self._rest, self._queue = b"", []
                self._writing = bool(queue)
            for data in queue:
                try:
                    self._connection.write_data(data)
                except Exception as error:  # rospy's: raised at the next write_data
                    with self._lock:
                        self._error = error
            with self._lock:
                self._writing = False


def batch_queued_writes() -> None:
    """Every publisher with a queue_size created after this, in this process, queues
    without yielding (rospy looks the class up when a subscriber connects)."""
    rospy.topics.QueuedConnection = BatchedConnection


def ros_time(secs: int, nsecs: int) -> rospy.Time:
    """``rospy.Time(secs, nsecs)`` for whole, normalised values (0 <= nsecs < 1e9), made
    without the constructor's checks: the same object, in a sixth of the time."""
    now = rospy.Time.__new__(rospy.Time)
    now.secs, now.nsecs = secs, nsecs
    return now


def has_connections(publisher: rospy.Publisher) -> bool:
    """Whether ``publisher`` has a subscriber now: ``get_num_connections() > 0`` without its
    lock (reading a list's length is atomic in CPython; a subscriber that comes or goes
    meanwhile is seen at the next call, as it would be a moment later with the lock)."""
    impl = publisher.impl
    return impl is not None and bool(impl.connections)


class OwnClock:
    """rospy's time in the simulator, set by the simulator instead of read from /clock."""

    def __init__(self):
        subscription = getattr(rospy.impl.simtime, "_clock_sub", None)
        self.simulated = subscription is not None  # use_sim_time was set at init_node
        if subscription is not None:
            subscription.unregister()
            rospy.impl.simtime._clock_sub = None

    def set(self, now: rospy.Time) -> None:
        """rospy's ``_set_rostime`` without its checks, and waking the threads that wait for
        simulated time (rospy.sleep, Rate, Timer) only when there are any: its lock and
        notify cost about 3 us of the 13 a /clock message took. A thread that begins to
        wait just after the check is woken by the next message, or by its own wait's
        timeout, as with rospy's."""
        if self.simulated:
            rospy.rostime._rostime_current = now
            condition = rospy.rostime._rostime_cond
            if getattr(condition, "_waiters", True):  # CPython keeps them in a deque
                with condition:
                    condition.notify_all()


def publish_serialized(publisher: rospy.Publisher, data: bytes) -> None:
    """What rospy's ``Publisher.publish`` does once it has serialised a message, for ``data``
    serialised already (TCPROS's length prefix included): under the publisher's lock, the
    same bytes to every connection in order, its statistics counted, and a connection that
    fails closed. For messages without a header (rospy numbers headers, not these)."""
    impl = publisher.impl
    if impl is None:
        raise rospy.ROSException("publish() to an unregistered() handle")
    broken = []
    impl.acquire()
    try:
        if impl.closed:
            if not rospy.is_shutdown():
                raise rospy.ROSException("publish() to a closed topic")
            return
        impl.seq += 1
        for connection in impl.connections:
            try:
                connection.write_data(data)
            except Exception:  # rospy's: a connection that cannot be written is closed
                broken.append(connection)
        impl.message_data_sent += len(data)
    finally:
        impl.release()
    for connection in broken:
        try:
            connection.close()
        except Exception:  # rospy's: closing a broken connection may fail too
            pass


class ClockPublisher:
    """/clock, published from the loop without a message object and written in batches of
    up to ``coalesce`` wall seconds (see the module's notes), and rospy's own time in this
    process set to match at every step (:class:`OwnClock`)."""

    def __init__(self, queue_size: int = 10, coalesce: float = COALESCE,
                 wall: Callable[[], float] = time.monotonic):
        self.own_clock = OwnClock()
        self.publisher = rospy.Publisher("/clock", Clock, queue_size=queue_size)
        self.coalesce, self.wall = coalesce, wall
        self._pending: List[bytes] = []   # packed messages not written yet, in order
        self._first = 0.0      # wall time the first of them was published
        self._last: Optional[float] = None   # wall time of the previous publish

    def publish(self, now_ns: int) -> None:
        """This step's time: rospy's at once, the message written with the others of the
        batch, or at once when the next step would end past the batch's ``coalesce``."""
        self.publish_steps(now_ns, 1, 1)

    def publish_steps(self, first_ns: int, step_ns: int, count: int) -> None:
        """The times of ``count`` steps made together (``World.advance``), ``step_ns``
        apart from ``first_ns``: a message each, in order, written as ``count`` calls of
        :meth:`publish` at this wall time would write them (the first by its own step's
        wall length, the others a step of no wall time after it); rospy's time is the
        last."""
        last_ns = first_ns + (count - 1) * step_ns
        secs, nsecs = divmod(last_ns, NS_PER_S)
        self.own_clock.set(ros_time(secs, nsecs))
        wall = self.wall()
        # the wall time since the last publish; unknown for the first, written at once
        step = math.inf if self._last is None else wall - self._last
        self._last = wall
        if not has_connections(self.publisher):
            self._pending.clear()
            return
        pack, pending = CLOCK_WIRE.pack, self._pending
        if count == 1:
            self._add(pack(8, secs, nsecs), wall, step)
            return
        # the times counted on from the first (one division, not one a message)
        secs, nsecs = divmod(first_ns, NS_PER_S)
        self._add(pack(8, secs, nsecs), wall, step)
        if not pending:  # the first went out: the others start a batch now
            self._first = wall
        for _ in range(count - 1):
            nsecs += step_ns
            if nsecs >= NS_PER_S:
                secs, nsecs = secs + nsecs // NS_PER_S, nsecs % NS_PER_S
            pending.append(pack(8, secs, nsecs))
        if wall - self._first >= self.coalesce:
            self.flush()

    def _add(self, message: bytes, wall: float, step: float) -> None:
        """One packed message pending; all pending written when the next step, as long as
        this one, would end past the batch's ``coalesce``."""
        if not self._pending:
            self._first = wall
        self._pending.append(message)
        if wall + step - self._first >= self.coalesce:
            self.flush()

    def flush(self) -> None:
        """Writes what is pending, in one write per connection."""
        if self._pending:
            data = b"".join(self._pending)
            self._pending.clear()
            publish_serialized(self.publisher, data)

"""sim_bridge.ros_publishing.BatchedConnection on a real socket pair, no master: messages go
straight into a socket that has room, in order; a reader that stops never blocks the
writer, and what it reads afterwards is whole messages in order (the part of a message a
full socket took is completed before anything else)."""
import socket
import struct
import threading
import time

import pytest

from sim_bridge.ros_publishing import BatchedConnection

QUEUE_SIZE = 3
MESSAGE_BYTES = 50_000  # a few of these fill a socket's buffer
WRITE_LIMIT = 0.2  # s: longer than this, write_data waited on the socket


class Transport:
    """The part of rospy's TCPROSTransport that QueuedConnection uses, counting the writes
    its writer thread makes."""

    def __init__(self, sock):
        self.socket = sock
        self.done = False
        self.stat_bytes = self.stat_num_msg = 0
        self.thread_writes = 0
        self.endpoint_id = "test_reader"

    def fileno(self):  # rospy polls a topic's connections
        return self.socket.fileno()

    cleanup_cb = None

    def set_cleanup_callback(self, callback):
        self.cleanup_cb = callback

    def write_data(self, data):
        self.thread_writes += 1
        self.socket.sendall(data)
        self.stat_bytes += len(data)
        self.stat_num_msg += 1

    def close(self):
        self.done = True
        self.cleanup_cb(self)


def frame(number, size):
    """A TCPROS-like frame: length, then the number and padding."""
    body = struct.pack("<I", number) + bytes(size - 4)
    return struct.pack("<I", len(body)) + body


def read_frames(sock, timeout):
    """Numbers of the whole frames read until nothing arrives for ``timeout``."""
    sock.settimeout(timeout)
    data = b""
    try:
        while True:
            chunk = sock.recv(1 << 20)
            if not chunk:
                break
            data += chunk
    except socket.timeout:
        pass
    numbers = []
    while data:
        (length,) = struct.unpack_from("<I", data)
        assert len(data) >= 4 + length, "a message was cut short"
        body = data[4:4 + length]
        assert body[4:] == bytes(length - 4), "a message's bytes were mixed with another's"
        numbers.append(struct.unpack_from("<I", body)[0])
        data = data[4 + length:]
    return numbers


def connection():
    writer, reader = socket.socketpair()
    transport = Transport(writer)
    return BatchedConnection(transport, QUEUE_SIZE), transport, reader


def test_a_socket_with_room_gets_each_message_at_once_in_order():
    queued, transport, reader = connection()
    try:
        for number in range(100):
            queued.write_data(frame(number, 100))
        assert read_frames(reader, 0.5) == list(range(100))
        assert transport.thread_writes == 0, "messages went through the writer thread"
        assert transport.stat_num_msg == 100
    finally:
        transport.close()
        reader.close()


def test_a_reader_that_stops_never_blocks_and_then_reads_whole_messages_in_order():
    queued, transport, reader = connection()
    try:
        slowest = 0.0
        for number in range(200):  # far more than the socket holds
            started = time.monotonic()
            queued.write_data(frame(number, MESSAGE_BYTES))
            slowest = max(slowest, time.monotonic() - started)
        assert slowest < WRITE_LIMIT, f"write_data waited {slowest:.3f} s for the reader"
        numbers = read_frames(reader, 1.0)
        assert numbers == sorted(numbers) and len(set(numbers)) == len(numbers)
        assert numbers[-1] == 199, "the newest message was not delivered"
        assert 0 < transport.thread_writes, "a full socket never handed over to the writer"
    finally:
        transport.close()
        reader.close()


def test_the_writer_thread_ends_when_the_connection_closes():
    queued, transport, reader = connection()
    transport.close()
    queued._thread.join(timeout=5)
    reader.close()
    assert not queued._thread.is_alive()


def test_the_packed_clock_is_rospys_serialisation_of_the_same_time():
    import io

    import rospy
    from rosgraph_msgs.msg import Clock
    from rospy.msg import serialize_message

    from sim_bridge.ros_publishing import CLOCK_WIRE, NS_PER_S
    for now_ns in (0, 1, NS_PER_S - 1, NS_PER_S, 123_456_789_012, (2 ** 32 - 1) * NS_PER_S):
        buffer = io.BytesIO()
        serialize_message(buffer, 1, Clock(clock=rospy.Time(nsecs=now_ns)))
        assert CLOCK_WIRE.pack(8, *divmod(now_ns, NS_PER_S)) == buffer.getvalue(), now_ns


def test_publish_serialized_writes_every_connection_in_order_and_drops_a_broken_one():
    """rospy's real publisher implementation (no master needed to hold connections)."""
    from rosgraph_msgs.msg import Clock
    from rospy.topics import _PublisherImpl

    from sim_bridge.ros_publishing import publish_serialized

    class Handle:  # what rospy.Publisher is to publish_serialized: its impl
        impl = _PublisherImpl("/clock_test", Clock)

    class Broken:  # a connection whose peer went away: rospy's transports raise on write
        endpoint_id = "gone"
        closed = False
        cleanup_cb = None
        ends = socket.socketpair()  # rospy polls every connection's file descriptor

        def fileno(self):
            return self.ends[0].fileno()

        def write_data(self, data):
            raise OSError("broken pipe")

        def set_cleanup_callback(self, callback):
            self.cleanup_cb = callback

        def close(self):  # as rospy's transports: closing calls the topic back
            self.closed = True
            self.cleanup_cb(self)

    good, good_transport, good_reader = connection()
    broken = Broken()
    try:
        Handle.impl.add_connection(broken)
        Handle.impl.add_connection(good)
        for number in range(5):
            publish_serialized(Handle, frame(number, 12))
        assert read_frames(good_reader, 0.5) == list(range(5))
        assert Handle.impl.message_data_sent == 5 * 16
        assert broken.closed and Handle.impl.connections == [good]
    finally:
        good_transport.close()
        good_reader.close()
        Handle.impl.close()
        for end in Broken.ends:
            end.close()


class FakeWall:
    """A wall clock the test moves."""

    def __init__(self):
        self.now = 100.0

    def __call__(self):
        return self.now


def clock_publisher(monkeypatch, wall):
    """sim_bridge's ClockPublisher on rospy's real publisher implementation with one
    connection to a socket the test reads (no master)."""
    from rosgraph_msgs.msg import Clock
    from rospy.topics import _PublisherImpl

    from sim_bridge import ros_publishing

    class Handle:
        def __init__(self, *args, **kwargs):
            self.impl = _PublisherImpl("/clock_coalesced", Clock)

    monkeypatch.setattr(ros_publishing.rospy, "Publisher", Handle)
    publisher = ros_publishing.ClockPublisher(wall=wall)
    queued, transport, reader = connection()
    publisher.publisher.impl.add_connection(queued)
    return publisher, transport, reader


def clock_times(sock, timeout):
    """(nanoseconds of each /clock frame read, how many recv calls returned data) until
    nothing arrives for ``timeout``."""
    sock.settimeout(timeout)
    data, reads = b"", 0
    try:
        while True:
            chunk = sock.recv(1 << 20)
            if not chunk:
                break
            data, reads = data + chunk, reads + 1
    except socket.timeout:
        pass
    times = []
    while len(data) >= 12:
        length, secs, nsecs = struct.unpack_from("<III", data)
        assert length == 8
        times.append(secs * 1_000_000_000 + nsecs)
        data = data[12:]
    assert data == b""
    return times, reads


def test_fast_steps_clocks_go_out_together_every_one_in_order(monkeypatch):
    """At full speed (40 us a step) the steps of about COALESCE of wall time go out in one
    write, each whole and in order; flush writes the rest (before the loop sleeps or
    pauses)."""
    from sim_bridge.ros_publishing import COALESCE
    wall = FakeWall()
    publisher, transport, reader = clock_publisher(monkeypatch, wall)
    steps = [step * 1_000_000 for step in range(1, 61)]
    try:
        for step in steps:
            wall.now += 40e-6
            publisher.publish(step)
        written, _ = clock_times(reader, 0.3)
        assert written == steps[:len(written)]     # a prefix, in order
        batch = COALESCE / 40e-6
        assert 60 - batch <= len(written) < 60
        # the first at once (no step measured yet), then a write per batch: not 60
        assert transport.stat_num_msg <= 1 + len(written) / (batch - 1)
        publisher.flush()
        assert written + clock_times(reader, 0.3)[0] == steps
    finally:
        transport.close()


@pytest.mark.parametrize("step_ns", [1_000_000, 4_166_667, 333_333_334])
def test_steps_made_together_each_get_their_clock_in_order(monkeypatch, step_ns):
    """World.advance's batches: publish_steps writes each step's time, as one publish a
    step would, across whole seconds too (at 1 ms, pybullet's 1/240 s, a 3 Hz step);
    rospy's time is the last one's."""
    wall = FakeWall()
    publisher, transport, reader = clock_publisher(monkeypatch, wall)
    first = 999 * step_ns + 7
    times = [first + k * step_ns for k in range(40)]
    rospy_times = []
    publisher.own_clock.set = rospy_times.append
    try:
        for start, count in ((0, 1), (1, 6), (7, 20), (27, 13)):
            wall.now += 40e-6 * count
            publisher.publish_steps(times[start], step_ns, count)
            assert rospy_times[-1].to_nsec() == times[start + count - 1]
        publisher.flush()
        assert clock_times(reader, 0.3)[0] == times
    finally:
        transport.close()


@pytest.mark.parametrize("batch_wall", [0.0004, 0.01], ids=["full_speed", "paced"])
def test_steps_made_together_are_written_as_one_publish_a_step_writes_them(monkeypatch,
                                                                          batch_wall):
    """The same writes, message for message, as a publish per step at the batch's wall
    time, whether the wall moves 10 ms between batches (paced: a batch's first message
    goes out with what was pending) or 0.4 ms (full speed: batches together up to
    COALESCE)."""
    writes = {}
    for way in ("steps", "one_by_one"):
        wall = FakeWall()
        publisher, transport, reader = clock_publisher(monkeypatch, wall)
        flush = publisher.flush
        written = writes[way] = []

        def recorded(flush=flush, publisher=publisher, written=written):
            written.append(len(publisher._pending))
            flush()
        publisher.flush = recorded
        try:
            for batch in range(12):
                wall.now += batch_wall
                first = batch * 10 * 1_000_000
                if way == "steps":
                    publisher.publish_steps(first, 1_000_000, 10)
                else:
                    for step in range(10):
                        publisher.publish(first + step * 1_000_000)
            publisher.flush()
        finally:
            transport.close()
    assert writes["steps"] == writes["one_by_one"]
    assert sum(writes["steps"]) == 120


def test_a_slow_step_writes_its_clock_at_once(monkeypatch):
    """A step longer than COALESCE (a heavy scene) does not wait for the next one."""
    wall = FakeWall()
    publisher, transport, reader = clock_publisher(monkeypatch, wall)
    try:
        for step in range(1, 4):
            wall.now += 0.002
            publisher.publish(step * 1_000_000)
            assert clock_times(reader, 0.2)[0] == [step * 1_000_000]
    finally:
        transport.close()


def test_without_subscribers_nothing_is_kept_and_rospy_time_still_follows(monkeypatch):
    import rospy
    wall = FakeWall()
    publisher, transport, reader = clock_publisher(monkeypatch, wall)
    transport.close()      # the only subscriber went away
    publisher.publish(5_000_000)
    publisher.flush()
    assert publisher._pending == []


def test_ros_time_is_rospys_time_of_the_same_seconds():
    """The loop's cheap rospy.Time equals, hashes, serialises and reads as the checked one."""
    import rospy

    from sim_bridge.ros_publishing import ros_time
    for secs, nsecs in ((0, 0), (12, 999_999_999), (4_000_000_000, 1)):
        made, checked = ros_time(secs, nsecs), rospy.Time(secs, nsecs)
        assert type(made) is rospy.Time
        assert made == checked and hash(made) == hash(checked)
        assert made.to_nsec() == checked.to_nsec() and made.to_sec() == checked.to_sec()


def test_has_connections_says_what_get_num_connections_says():
    """On rospy's real publisher implementation: none, one, none again after its close."""
    from rosgraph_msgs.msg import Clock
    from rospy.topics import _PublisherImpl

    from sim_bridge.ros_publishing import has_connections

    class Handle:  # what rospy.Publisher is to has_connections: its impl
        impl = _PublisherImpl("/connections_test", Clock)

        def get_num_connections(self):
            return self.impl.get_num_connections()

    handle = Handle()
    queued, transport, reader = connection()
    try:
        assert not has_connections(handle) and handle.get_num_connections() == 0
        handle.impl.add_connection(queued)
        assert has_connections(handle) and handle.get_num_connections() == 1
        transport.close()
        assert not has_connections(handle) and handle.get_num_connections() == 0
        Handle.impl = None  # an unregistered publisher
        assert not has_connections(handle)
    finally:
        reader.close()

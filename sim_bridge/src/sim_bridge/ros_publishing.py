"""Publishing from the simulator's loop at the rate it steps, without rospy's hand-off cost.

Two things of rospy's cost the simulator more than its physics did (measured, see the
README's "Speed"):

- A publisher with a ``queue_size`` hands every message to a writer thread per subscriber
  (rospy's ``QueuedConnection``) and then calls ``time.sleep(0)`` to give that thread the
  interpreter at once: about 90 µs per message per subscriber (260 µs with three), where
  writing the bytes costs 5. /clock alone is published 250 times a simulated second.
  :func:`batch_queued_writes` replaces that connection class, in this process only, by one
  that queues the message and returns: the writer thread sends what has gathered when the
  loop next sleeps or the interpreter switches threads (every 5 ms at most). The queue
  keeps its ``queue_size`` (the oldest message dropped when full), so a subscriber that
  stops reading costs the simulator nothing; a ``queue_size=None`` publisher would block
  the loop on that subscriber's socket instead.
- With ``use_sim_time`` set, rospy subscribes every node to /clock, the simulator
  included: it received each of its own 250 messages a second to learn what it already
  knew. :class:`OwnClock` drops that subscription and sets rospy's time directly.
"""
from __future__ import annotations

import rospy
import rospy.impl.simtime
import rospy.rostime
import rospy.topics
from rospy.impl.tcpros_pubsub import QueuedConnection


class BatchedConnection(QueuedConnection):
    """rospy's queued connection, without yielding the interpreter on every message."""

    def write_data(self, data):
        with self._lock:
            # an error the writer thread met is raised here, as rospy's class does
            if self._error:
                error, self._error = self._error, None
                raise error
            if self._queue_size > 0 and len(self._queue) == self._queue_size:
                del self._queue[0]
            self._queue.append(data)
            self._cond_data_available.notify()
        return True


def batch_queued_writes() -> None:
    """Every publisher with a queue_size created after this, in this process, queues
    without yielding (rospy looks the class up when a subscriber connects)."""
    rospy.topics.QueuedConnection = BatchedConnection


class OwnClock:
    """rospy's time in the simulator, set by the simulator instead of read from /clock."""

    def __init__(self):
        subscription = getattr(rospy.impl.simtime, "_clock_sub", None)
        self.simulated = subscription is not None  # use_sim_time was set at init_node
        if subscription is not None:
            subscription.unregister()
            rospy.impl.simtime._clock_sub = None

    def set(self, now: rospy.Time) -> None:
        if self.simulated:
            rospy.rostime._set_rostime(now)

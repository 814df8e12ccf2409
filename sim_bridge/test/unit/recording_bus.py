"""A Bus for tests: records what plugins publish, and lets a test call their subscribers."""
from sim_bridge.plugins.base import Bus


class _Handle:
    def __init__(self, bus, topic):
        self.bus, self.topic = bus, topic

    def publish(self, message):
        self.bus.published.setdefault(self.topic, []).append(message)

    def unregister(self):
        self.bus.closed.append(self.topic)

    shutdown = unregister


class RecordingBus(Bus):
    def __init__(self, params=None):
        self.published = {}
        self.advertised = []  # every topic a publisher was opened on, in order
        self.subscriptions = {}
        self.warnings = []
        self.debugs = []  # what verbose:=true would print
        self.closed = []
        self.params = params or {}
        self.services = {}
        self.actions = {}
        self.unheard = set()  # topics nobody listens to ("/tf" included); all heard by default

    def publisher(self, topic, msg_class, queue_size=10, latch=False):
        self.advertised.append(topic)
        return _Handle(self, topic)

    def subscriber(self, topic, msg_class, callback):
        self.subscriptions[topic] = callback
        return _Handle(self, topic)

    def service(self, name, srv_class, handler):
        self.services[name] = handler
        return _Handle(self, name)

    def action_server(self, name, action_class, on_goal, on_cancel):
        self.actions[name] = (on_goal, on_cancel)
        return _Handle(self, name)

    def send_transforms(self, transforms):
        self.published.setdefault("/tf", []).extend(transforms)

    def listened(self, publisher=None):
        return (publisher.topic if publisher is not None else "/tf") not in self.unheard

    def info(self, text):
        pass

    def warn(self, text):
        self.warnings.append(text)

    def warn_throttled(self, key, period, text):
        self.warnings.append(text)

    def debug(self, text):
        self.debugs.append(text)

    def get_param(self, name, default=None):
        return self.params.get(name, default)

    def last(self, topic):
        return self.published[topic][-1]

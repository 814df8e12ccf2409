"""make soak: the simulator started and stopped 50 times in a row, each stop within 2 s of
SIGINT, none left running (test/e2e/test_simulator_stops.py's check; make test runs it 12
times, each of its four states three times). Fifty gives a race that shows once in many stops
(the /clock publish deadlock sim_bridge.stop_signals fixed) more chances to show."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                "e2e"))
from test_simulator_stops import check_starts_and_stops  # noqa: E402  (in test/e2e)

CYCLES = 50


def test_fifty_starts_and_stops_each_end_within_two_seconds(master, repo, results_dir):
    check_starts_and_stops(master, repo, results_dir, CYCLES)

"""Runs spawn cases in spawn_worker.py, a separate process, so that a crash of pybullet
(a signal nothing in-process can catch) or a hang is caught and reported with the case
that caused it; the worker is then started again for the next case.

Every crash, hang and unexpected exception is also written to test_results/fuzz/ (the
case's text, and a .json with what happened), so that a long run's findings survive it.
"""
from __future__ import annotations

import json
import os
import select
import signal
import subprocess
import sys
import time
from typing import Optional

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
FINDINGS = os.path.join(REPO, "test_results", "fuzz")
WORKER = os.path.join(HERE, "spawn_worker.py")
# the longest one spawn case may take (s): a 1000-link robot loads and steps in a few
CASE_SECONDS = float(os.environ.get("FUZZ_CASE_SECONDS", "60"))
START_SECONDS = 60.0


class SpawnClient:
    def __init__(self) -> None:
        self.process: Optional[subprocess.Popen] = None
        self.buffer = b""
        self.cases = 0
        self.restarts = 0
        self.findings = 0
        # outcome -> count; "model (pose not finite)" for a model whose pose after the
        # worker's steps is NaN or inf (reported in the summary, not a failure: extreme but
        # finite masses and stiffnesses are accepted and may blow up in pybullet)
        self.outcomes: dict = {}
        self.started = time.monotonic()
        os.makedirs(FINDINGS, exist_ok=True)
        self.log_path = os.path.join(FINDINGS, "spawn_worker.log")

    # --- the worker ---------------------------------------------------------------------
    def _start(self) -> None:
        self.log = open(self.log_path, "wb")
        self.process = subprocess.Popen([sys.executable, WORKER], stdin=subprocess.PIPE,
                                        stdout=subprocess.PIPE, stderr=self.log,
                                        start_new_session=True)
        self.buffer = b""
        ready = self._answer(START_SECONDS)
        if not isinstance(ready, dict) or "ready" not in ready:
            raise RuntimeError(f"the spawn worker did not start: {ready}; see {self.log_path}")

    def _stop(self) -> None:
        if self.process is None:
            return
        if self.process.poll() is None:
            os.killpg(self.process.pid, signal.SIGKILL)
        self.process.wait()
        for stream in (self.process.stdin, self.process.stdout):
            try:
                stream.close()
            except OSError:
                pass
        self.log.close()
        self.process = None

    def close(self) -> None:
        """Stops the worker and writes test_results/fuzz/spawn_summary.txt."""
        with open(os.path.join(FINDINGS, "spawn_summary.txt"), "w", encoding="utf-8") as out:
            out.write(f"{self.cases} spawn cases in {time.monotonic() - self.started:.1f} s, "
                      f"{self.restarts} worker restarts\n")
            for outcome, count in sorted(self.outcomes.items()):
                out.write(f"  {outcome}: {count}\n")
        if self.process is not None and self.process.poll() is None:
            self.process.stdin.close()
            try:
                self.process.wait(5)
            except subprocess.TimeoutExpired:
                pass
        self._stop()

    def _answer(self, timeout: float):
        """The worker's next line as JSON; "hang" after ``timeout``; "exit" when it died."""
        end = time.monotonic() + timeout
        fd = self.process.stdout.fileno()
        while b"\n" not in self.buffer:
            left = end - time.monotonic()
            if left <= 0:
                return "hang"
            ready, _, _ = select.select([fd], [], [], left)
            if ready:
                chunk = os.read(fd, 1 << 16)
                if not chunk:
                    return "exit"
                self.buffer += chunk
        line, _, self.buffer = self.buffer.partition(b"\n")
        return json.loads(line)

    def _log_tail(self) -> str:
        self.log.flush()
        with open(self.log_path, "rb") as stream:
            stream.seek(max(0, os.path.getsize(self.log_path) - 3000))
            return stream.read().decode("utf-8", "replace")

    # --- cases --------------------------------------------------------------------------
    def run(self, case: dict, timeout: float = CASE_SECONDS) -> dict:
        """The worker's answer for ``case``; a crash or a hang as {"outcome": "crash" or
        "hang", ...} after the worker is restarted."""
        if self.process is None or self.process.poll() is not None:
            if self.process is not None:
                self._stop()
            self._start()
        self.cases += 1
        try:
            self.process.stdin.write((json.dumps(case) + "\n").encode("utf-8", "surrogatepass"))
            self.process.stdin.flush()
            answer = self._answer(timeout)
        except BrokenPipeError:
            answer = "exit"
        if answer in ("hang", "exit"):
            if answer == "exit":
                code = self.process.wait()
                what = (f"signal {signal.Signals(-code).name}" if code < 0
                        else f"exit status {code}")
                answer = {"outcome": "crash", "message": f"the worker died ({what})",
                          "stderr": self._log_tail()}
            else:
                answer = {"outcome": "hang",
                          "message": f"no answer within {timeout:.0f} s",
                          "stderr": self._log_tail()}
            self._stop()
            self.restarts += 1
        outcome = answer["outcome"]
        if outcome == "model" and not answer.get("finite", True):
            outcome = "model (pose not finite)"
            self.record(case, dict(answer, outcome="nonfinite"))
        elif outcome == "refused":
            outcome = f"refused ({answer.get('type')})"
        self.outcomes[outcome] = self.outcomes.get(outcome, 0) + 1
        if answer["outcome"] in ("crash", "hang", "unexpected"):
            self.record(case, answer)
        return answer

    def record(self, case: dict, answer: dict) -> str:
        """Writes a finding to test_results/fuzz/: the case and the answer."""
        self.findings += 1
        stem = os.path.join(FINDINGS, f"{answer['outcome']}-{os.getpid()}-{self.findings}")
        with open(stem + ".json", "w", encoding="utf-8") as stream:
            json.dump({"case": case, "answer": answer}, stream, indent=1,
                      ensure_ascii=True)
        return stem

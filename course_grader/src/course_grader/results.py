"""What grading found: each item's points awarded, the figure measured (evidence), the
pictures that show it (a screenshot, plots of the measured motion) and, on a failure, the
log lines that explain it; totals. No ROS here."""
from __future__ import annotations

from dataclasses import asdict, dataclass, field
from typing import Dict, Iterable, List, Optional, Tuple

from course_grader.course import Course, Item


@dataclass
class Check:
    """One measured condition: passed or not, and what was measured (one line)."""

    name: str
    passed: bool
    evidence: str

    def __post_init__(self):
        self.passed = bool(self.passed)   # numpy's bool_ is not JSON
        self.evidence = str(self.evidence)

    @staticmethod
    def from_dict(data: Dict) -> "Check":
        return Check(str(data["name"]), bool(data["passed"]), str(data["evidence"]))


@dataclass
class Figure:
    """A picture for the report: a file in the report's folder (``file``, a name relative to
    it), or, when there is none, why (``missing``)."""

    title: str
    file: str = ""
    caption: str = ""
    missing: str = ""

    @staticmethod
    def from_dict(data: Dict) -> "Figure":
        return Figure(str(data["title"]), str(data.get("file", "")),
                      str(data.get("caption", "")), str(data.get("missing", "")))


@dataclass
class Killed:
    """A process of a scenario still running after its stop, killed (SIGKILL) by its tag:
    its pid and command line (shortened)."""

    pid: int
    command: str


@dataclass
class ItemResult:
    item: Item
    awarded: float
    checks: List[Check] = field(default_factory=list)
    notes: List[str] = field(default_factory=list)   # supporting evidence, not scored
    log: List[str] = field(default_factory=list)     # lines explaining a failure
    seconds: float = 0.0                             # wall time of the scenario
    figures: List[Figure] = field(default_factory=list)
    killed: List[Killed] = field(default_factory=list)   # the scenario's leftovers, not scored

    @property
    def passed(self) -> bool:
        return self.awarded >= self.item.points

    def evidence(self) -> str:
        measured = "; ".join(c.evidence for c in self.checks) or "not measured"
        if not self.killed:
            return measured
        pids = ", ".join(str(k.pid) for k in self.killed)
        return (f"{measured}; {len(self.killed)} process(es) still running after the "
                f"scenario's stop were killed (pid {pids})")


def judge(item: Item, checks: Iterable[Check], notes: Iterable[str] = (),
          log: Iterable[str] = (), seconds: float = 0.0) -> ItemResult:
    """All-or-nothing: the item's points when it has checks and every one passed."""
    checks = list(checks)
    awarded = item.points if checks and all(c.passed for c in checks) else 0.0
    failed = awarded < item.points
    return ItemResult(item, awarded, checks, list(notes), list(log) if failed else [], seconds)


def failed_item(item: Item, reason: str, log: Iterable[str] = (),
                seconds: float = 0.0) -> ItemResult:
    """An item that could not be measured (no build, no launch): 0 points, the reason."""
    return ItemResult(item, 0.0, [Check("ran", False, reason)], [], list(log), seconds)


@dataclass
class Report:
    course: Course
    submission: str
    results: List[ItemResult]
    build: Optional[str] = None      # one line on the submission's build
    seconds: float = 0.0             # wall time of the whole grading
    notes: List[str] = field(default_factory=list)
    figures: List[Figure] = field(default_factory=list)   # of no one item (why none)

    @property
    def awarded(self) -> float:
        return sum(r.awarded for r in self.results)

    @property
    def possible(self) -> float:
        return sum(r.item.points for r in self.results)

    def result(self, item_id: str) -> ItemResult:
        for result in self.results:
            if result.item.id == item_id:
                return result
        raise KeyError(item_id)

    def all_figures(self) -> List[Tuple[Optional[str], Figure]]:
        """(item id or None, figure) for every figure, items' in the items' order."""
        return ([(r.item.id, f) for r in self.results for f in r.figures]
                + [(None, f) for f in self.figures])

    def to_dict(self) -> Dict:
        return {
            "course": self.course.name,
            "submission": self.submission,
            "awarded": round(self.awarded, 4),
            "possible": round(self.possible, 4),
            "seconds": round(self.seconds, 1),
            "build": self.build,
            "notes": self.notes,
            "items": [{
                "id": r.item.id, "task": r.item.task, "title": r.item.title,
                "points": r.item.points, "awarded": r.awarded, "evidence": r.evidence(),
                "checks": [asdict(c) for c in r.checks], "notes": r.notes, "log": r.log,
                "seconds": round(r.seconds, 1),
                "figures": [f.file for f in r.figures if f.file],
            } for r in self.results],
            "figures": [dict(asdict(f), item=item) for item, f in self.all_figures()],
            "scenarios": self.scenarios(),
        }

    def scenarios(self) -> List[Dict]:
        """One entry per scenario graded, in the items' order: its wall time and the
        processes killed after its stop (a node that ignored the stop, say)."""
        entries: Dict[str, Dict] = {}
        for r in self.results:
            entries.setdefault(r.item.scenario, {
                "scenario": r.item.scenario, "seconds": round(r.seconds, 1),
                "killed": [asdict(k) for k in r.killed]})
        return list(entries.values())

"""What grading found: each item's points awarded, the figure measured (evidence), the
pictures that show it (a screenshot, plots of the measured motion) and, on a failure, the
log lines that explain it; totals. No ROS here."""
from __future__ import annotations

from dataclasses import asdict, dataclass, field
from typing import Dict, Iterable, List, Optional, Tuple

from course_grader import rubric
from course_grader.course import Course, Item


@dataclass
class Check:
    """One measured condition: passed or not, and what was measured (one line);
    ``value``, when the check measured a quantity (an error in degrees, a distance), is the
    figure the item's scale reads; ``review``, when set, why a teaching assistant should
    look at it (what the measurement could not settle)."""

    name: str
    passed: bool
    evidence: str
    value: Optional[float] = None
    review: str = ""

    def __post_init__(self):
        self.passed = bool(self.passed)   # numpy's bool_ is not JSON
        self.evidence = str(self.evidence)
        self.value = None if self.value is None else float(self.value)

    @staticmethod
    def from_dict(data: Dict) -> "Check":
        value = data.get("value")
        return Check(str(data["name"]), bool(data["passed"]), str(data["evidence"]),
                     None if value is None else float(value), str(data.get("review", "")))


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
    # what the rubric made of the checks (see rescore)
    parts: List[Tuple[str, float]] = field(default_factory=list)
    deducted: List[Tuple[str, float, str]] = field(default_factory=list)  # rule, points, why
    review: List[str] = field(default_factory=list)      # why a teaching assistant should look
    beyond: List[str] = field(default_factory=list)      # checks beyond the guide's sentence
    # a fault of the grading platform, not of the submission: nothing scored against it
    platform: str = ""

    @property
    def passed(self) -> bool:
        return self.awarded >= self.item.points

    @property
    def mark(self) -> str:
        """"platform", "review" or "" (the table's and the CSV's mark)."""
        return "platform" if self.platform else ("review" if self.review else "")

    def rescore(self) -> "ItemResult":
        """Scores the checks by the item's rubric: its parts' mean share of the points,
        less its deductions, never below 0; nothing measured scores nothing."""
        scored = rubric.score(self.item.rubric, self.checks)
        self.parts, self.review, self.beyond = scored.parts, scored.review, scored.notes
        self.deducted = [(d.rule, d.points, evidence) for d, evidence in scored.deducted]
        taken = sum(points for _, points, _ in self.deducted)
        self.awarded = round(max(0.0, self.item.points * scored.share - taken), 4)
        return self

    def evidence(self) -> str:
        measured = "; ".join(c.evidence for c in self.checks) or "not measured"
        if not self.killed:
            return measured
        pids = ", ".join(str(k.pid) for k in self.killed)
        return (f"{measured}; {len(self.killed)} process(es) still running after the "
                f"scenario's stop were killed (pid {pids})")


def judge(item: Item, checks: Iterable[Check], notes: Iterable[str] = (),
          log: Iterable[str] = (), seconds: float = 0.0) -> ItemResult:
    """The item scored by its rubric (see ItemResult.rescore); the log is kept only when
    points were lost."""
    result = ItemResult(item, 0.0, list(checks), list(notes), [], seconds).rescore()
    if not result.passed:
        result.log = list(log)
    return result


def failed_item(item: Item, reason: str, log: Iterable[str] = (),
                seconds: float = 0.0, notes: Iterable[str] = ()) -> ItemResult:
    """An item that could not be measured (no build, no launch): 0 points, the reason."""
    return ItemResult(item, 0.0, [Check("ran", False, reason)], list(notes), list(log),
                      seconds)


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
        """Points of the items graded; an item the platform kept from being graded is not
        counted against the student."""
        return sum(r.item.points for r in self.results if not r.platform)

    @property
    def incomplete(self) -> bool:
        """Some item could not be graded for a fault of the platform, not the submission."""
        return any(r.platform for r in self.results)

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
            "incomplete": self.incomplete,
            "items": [{
                "id": r.item.id, "task": r.item.task, "title": r.item.title,
                "guide": r.item.rubric.guide,
                "points": r.item.points, "awarded": r.awarded, "mark": r.mark,
                "evidence": r.evidence(),
                "checks": [asdict(c) for c in r.checks],
                "parts": [{"check": name, "share": round(share, 4)} for name, share in r.parts],
                "scale": r.item.rubric.scale.describe() if r.item.rubric.scale else None,
                "deductions": [{"rule": rule, "points": points, "evidence": evidence}
                               for rule, points, evidence in r.deducted],
                "review": r.review, "platform": r.platform, "beyond_the_guide": r.beyond,
                "notes": r.notes, "log": r.log,
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

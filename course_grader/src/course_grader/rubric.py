"""How an item's checks become points, as the course file declares it beside the item: the
guide's sentence the item implements (``guide``), which checks go beyond that sentence and
are reported as notes with their figures (``notes``), the deductions the course declares
with their weights (``deductions``), and, for an item measured as an error, the scale that
turns the error into a share of the points (``scale``). No ROS here.

An item's scored checks are its parts (several links, several requested angles): each part
scores 1 when it passed, or its share on the scale when it measured a quantity, and the
item gets its points times the mean of its parts, less its deductions (never below 0). A
part whose figure lies near one of the scale's bounds marks the item "review", as does a
check that says what its measurement could not settle (its ``review``): a teaching
assistant decides with the evidence shown.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Dict, Iterable, List, Optional, Tuple

# a figure within this share of a scale's bound (of the scale's span, for a bound of 0) is
# close enough to it for a teaching assistant to look
REVIEW_SHARE = 0.2


@dataclass(frozen=True)
class Scale:
    """Full marks for a figure at or below ``full``, none at or beyond ``none``, linear
    between (an error: smaller is better)."""

    full: float
    none: float
    unit: str = ""

    def __post_init__(self):
        if not 0 <= self.full < self.none:
            raise ValueError(f"a scale needs 0 <= full < none (got full {self.full}, none "
                             f"{self.none})")

    def share(self, value: float) -> float:
        value = abs(value)
        if value <= self.full:
            return 1.0
        if value >= self.none:
            return 0.0
        return (self.none - value) / (self.none - self.full)

    def near_bound(self, value: float) -> bool:
        """Within REVIEW_SHARE of a bound (of the span above a bound of 0: a figure of
        exactly 0, inside the square say, is no case for review)."""
        value = abs(value)
        if self.full == 0 and 0 < value <= REVIEW_SHARE * self.none:
            return True
        return any(abs(value - bound) <= REVIEW_SHARE * bound
                   for bound in (self.full, self.none) if bound > 0)

    def describe(self) -> str:
        unit = f" {self.unit}" if self.unit else ""
        return f"full marks within {self.full:g}{unit}, none beyond {self.none:g}{unit}, linear between"


@dataclass(frozen=True)
class Deduction:
    """Points the course takes off an item when a named check fails: a requirement the
    guide states elsewhere than in the item's sentence, declared with its weight."""

    check: str      # the check's name (a check whose name starts with it)
    points: float
    rule: str       # the course's words for what it deducts, quoting the guide

    def matches(self, name: str) -> bool:
        return name.startswith(self.check)


@dataclass(frozen=True)
class Rubric:
    guide: str = ""                       # the guide's sentence the item implements
    notes: Tuple[str, ...] = ()           # checks (by name's start) reported, not scored
    deductions: Tuple[Deduction, ...] = ()
    scale: Optional[Scale] = None

    def is_note(self, name: str) -> bool:
        return any(name.startswith(prefix) for prefix in self.notes)

    def deduction(self, name: str) -> Optional[Deduction]:
        return next((d for d in self.deductions if d.matches(name)), None)


def parse(item: Dict[str, Any], where: str) -> Rubric:
    """An item's rubric from its course-file entry; ``where`` names it in errors."""
    scale = item.get("scale")
    deductions = []
    for entry in item.get("deductions", []):
        unknown = set(entry) - {"check", "points", "rule"}
        if unknown or not {"check", "points", "rule"} <= set(entry):
            raise ValueError(f"{where}: a deduction needs check, points and rule (got "
                             f"{sorted(entry)})")
        deductions.append(Deduction(str(entry["check"]), float(entry["points"]),
                                    str(entry["rule"])))
    if scale is not None:
        unknown = set(scale) - {"full", "none", "unit"}
        if unknown:
            raise ValueError(f"{where}: scale has unknown keys {sorted(unknown)}")
        scale = Scale(float(scale["full"]), float(scale["none"]), str(scale.get("unit", "")))
    return Rubric(guide=str(item.get("guide", "")),
                  notes=tuple(str(n) for n in item.get("notes", [])),
                  deductions=tuple(deductions), scale=scale)


@dataclass
class Scored:
    """What the rubric made of an item's checks."""

    share: float                                   # of the item's points, before deductions
    parts: List[Tuple[str, float]] = field(default_factory=list)      # (check name, share)
    deducted: List[Tuple[Deduction, str]] = field(default_factory=list)   # (rule, evidence)
    review: List[str] = field(default_factory=list)    # why a TA should look
    notes: List[str] = field(default_factory=list)     # checks beyond the sentence


def score(rubric: Rubric, checks: Iterable[Any]) -> Scored:
    """Scores ``checks`` (each with name, passed, evidence and an optional ``value``, the
    figure the scale reads)."""
    scored = Scored(0.0)
    for check in checks:
        deduction = rubric.deduction(check.name)
        if deduction is not None:
            if not check.passed:
                scored.deducted.append((deduction, check.evidence))
            continue
        if rubric.is_note(check.name):
            scored.notes.append(f"{'pass' if check.passed else 'FAIL'} (not scored: beyond "
                                f"the guide's sentence): {check.evidence}")
            continue
        if getattr(check, "review", ""):
            scored.review.append(f"{check.name}: {check.review}")
        value = getattr(check, "value", None)
        if rubric.scale is not None and value is not None:
            share = rubric.scale.share(value)
            if rubric.scale.near_bound(value):
                scored.review.append(f"{check.name}: {abs(value):.3g}{rubric.scale.unit and ' '}"
                                     f"{rubric.scale.unit} is near the scale's bound "
                                     f"({rubric.scale.describe()})")
        else:
            share = 1.0 if check.passed else 0.0
        scored.parts.append((check.name, share))
    if scored.parts:
        scored.share = sum(share for _, share in scored.parts) / len(scored.parts)
    return scored

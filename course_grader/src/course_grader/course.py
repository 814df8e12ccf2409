"""A course's grading guide read from ``config/<course>.yaml``: its packages, commands,
items with their points, the checks' numbers and the time limits."""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Any, Dict, List, Tuple

import yaml

CONFIG_DIR = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))), "config")


class CourseError(ValueError):
    """A course name or file that cannot be used; the message names it and why."""


@dataclass(frozen=True)
class Item:
    """One graded item of the guide: points for one thing the student must show."""

    id: str
    task: int
    title: str
    points: float
    scenario: str


@dataclass
class Course:
    name: str
    title: str
    packages: List[str]
    commands: Dict[str, Tuple[str, str]]
    items: List[Item]
    limits: Dict[str, float]
    checks: Dict[str, Dict[str, Any]]
    urdf: Dict[str, Any]
    source: str = ""

    @property
    def total_points(self) -> float:
        return sum(item.points for item in self.items)

    def scenarios(self) -> List[str]:
        """Scenario names in the order their first item appears in the guide."""
        seen: List[str] = []
        for item in self.items:
            if item.scenario not in seen:
                seen.append(item.scenario)
        return seen

    def items_of(self, scenario: str) -> List[Item]:
        return [item for item in self.items if item.scenario == scenario]


def available() -> List[str]:
    return sorted(os.path.splitext(name)[0] for name in os.listdir(CONFIG_DIR)
                  if name.endswith(".yaml"))


def load(name: str) -> Course:
    """The course called ``name`` (``config/<name>.yaml``)."""
    path = os.path.join(CONFIG_DIR, f"{name}.yaml")
    if not os.path.isfile(path):
        raise CourseError(f"no course '{name}': known courses are {', '.join(available())} "
                          f"(files in {CONFIG_DIR})")
    return parse(path)


def parse(path: str) -> Course:
    with open(path, encoding="utf-8") as stream:
        data = yaml.safe_load(stream)
    try:
        items = [Item(id=str(i["id"]), task=int(i["task"]), title=str(i["title"]),
                      points=float(i["points"]), scenario=str(i["scenario"]))
                 for i in data["items"]]
        course = Course(name=str(data["name"]), title=str(data["title"]),
                        packages=[str(p) for p in data["packages"]],
                        commands={k: (str(v[0]), str(v[1])) for k, v in data["commands"].items()},
                        items=items, limits={k: float(v) for k, v in data["limits"].items()},
                        checks=dict(data.get("checks", {})), urdf=dict(data.get("urdf", {})),
                        source=path)
    except (KeyError, TypeError, ValueError, IndexError) as error:
        raise CourseError(f"{path}: malformed course file ({type(error).__name__}: {error})") \
            from error
    ids = [item.id for item in items]
    if len(set(ids)) != len(ids):
        raise CourseError(f"{path}: item ids repeat: {ids}")
    return course

"""Test fixtures made from the workspace's own solutions: a solution's packages copied, then
edited the way a student's submission differs (``Replace`` a text, ``Insert`` or ``Copy`` a
file, ``Rename``, ``Chmod``, move a block), with the points each item must get (``Fault``).
An edit that no longer applies (its text is gone or repeated) raises ``FixtureError``: the
solution changed and the fixture table must follow. Used by rb1_fault_fixtures and
hw3_fixtures."""
from __future__ import annotations

import os
import shutil
from dataclasses import dataclass
from typing import Dict, Optional, Tuple


class FixtureError(RuntimeError):
    """An edit that no longer applies to the solution; the message names it."""


@dataclass(frozen=True)
class Replace:
    """In ``path`` (relative to the submission), the one occurrence of ``old`` becomes
    ``new``; ``new_file``: ``new`` is read from that file in FILES instead."""

    path: str
    old: str
    new: str = ""
    new_file: str = ""


@dataclass(frozen=True)
class Insert:
    """A file of FILES inserted into ``path`` just before the one occurrence of ``before``."""

    path: str
    before: str
    source: str


@dataclass(frozen=True)
class Copy:
    """A file of FILES written into the submission at ``path``."""

    source: str
    path: str


@dataclass(frozen=True)
class Delete:
    path: str


@dataclass(frozen=True)
class ReplaceAll:
    """Every occurrence (at least one) of ``old`` in ``path`` becomes ``new``."""

    path: str
    old: str
    new: str


@dataclass(frozen=True)
class Rename:
    """The file ``path`` moves to ``new_path`` (both relative to the submission)."""

    path: str
    new_path: str


@dataclass(frozen=True)
class Chmod:
    path: str
    mode: int


@dataclass(frozen=True)
class MoveBlock:
    """In ``path``, the text from the one ``start`` through the first ``end`` after it is
    moved to just before the one ``before``."""

    path: str
    start: str
    end: str
    before: str


@dataclass(frozen=True)
class Fault:
    what: str
    edits: Tuple
    scores: Dict[str, float]   # item id -> points it must get; items not named: full marks
    scenarios: Tuple[str, ...]
    scenario_limit: Optional[float] = None
    # the platform's fault, not the student's: every item graded is marked "platform" (its
    # points, 0, left out of the possible) and the grade is "incomplete"
    platform: bool = False

    def expected(self, items) -> Dict[str, float]:
        """Points per item of ``items`` (course Items) this fault must get."""
        return {item.id: self.scores.get(item.id, item.points) for item in items}


def nothing_for(items) -> Dict[str, float]:
    return {item: 0.0 for item in items}


def read_file(files: str, name: str) -> str:
    with open(os.path.join(files, name), encoding="utf-8") as stream:
        return stream.read()


def apply(folder: str, edit, files: str) -> None:
    """Makes ``edit`` in the submission in ``folder``; ``files``: where Copy and Insert
    find their files."""
    path = os.path.join(folder, edit.path)
    if isinstance(edit, Copy):
        shutil.copyfile(os.path.join(files, edit.source), path)
        return
    if not os.path.isfile(path):
        raise FixtureError(f"{edit.path} is not in the solution")
    if isinstance(edit, Delete):
        os.remove(path)
    elif isinstance(edit, Rename):
        os.rename(path, os.path.join(folder, edit.new_path))
    elif isinstance(edit, Chmod):
        os.chmod(path, edit.mode)
    else:
        with open(path, encoding="utf-8") as stream:
            text = stream.read()
        with open(path, "w", encoding="utf-8") as stream:
            stream.write(_edited(text, edit, files))


def _edited(text: str, edit, files: str) -> str:
    """``text`` after a text edit (MoveBlock, ReplaceAll, Insert or Replace)."""
    if isinstance(edit, MoveBlock):
        if text.count(edit.start) != 1 or text.count(edit.before) != 1:
            raise FixtureError(f"{edit.path}: the block's start or its new place is not there "
                               f"once: {edit.start!r}, {edit.before!r}")
        begin = text.index(edit.start)
        end = text.index(edit.end, begin) + len(edit.end)
        block, text = text[begin:end], text[:begin] + text[end:]
        return text.replace(edit.before, block + edit.before)
    if isinstance(edit, ReplaceAll):
        if edit.old not in text:
            raise FixtureError(f"{edit.path}: the text the fixture changes is gone: {edit.old!r}")
        return text.replace(edit.old, edit.new)
    if isinstance(edit, Insert):
        old, new = edit.before, read_file(files, edit.source) + edit.before
    else:
        old, new = edit.old, read_file(files, edit.new_file) if edit.new_file else edit.new
    count = text.count(old)
    if count != 1:
        raise FixtureError(f"{edit.path}: the text the fixture changes occurs {count} times, "
                           f"not once: {old!r}")
    return text.replace(old, new)


def make(folder: str, sources, edits, files: str,
         left_out: Tuple[str, ...] = ("__pycache__", "doc")) -> str:
    """``sources`` (package folders) copied into ``folder`` (created; it must not exist),
    without the folders named in ``left_out``, then ``edits`` made; returns ``folder``."""
    os.makedirs(folder)
    for source in sources:
        shutil.copytree(source, os.path.join(folder, os.path.basename(source)),
                        ignore=shutil.ignore_patterns(*left_out))
    for edit in edits:
        apply(folder, edit, files)
    return folder

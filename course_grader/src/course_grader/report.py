"""The grading report: a plain-text table for the terminal, Markdown (with the pictures:
rviz's screenshot and the plots of the measured motion, files beside it) and JSON (which
lists those files) for a gradebook."""
from __future__ import annotations

import json
import os
import textwrap
from typing import List

from course_grader.results import Figure, Report

# columns of the terminal table: item, points, awarded, evidence
EVIDENCE_WIDTH = 70
LOG_LINES_SHOWN = 8


def _points(value: float) -> str:
    return f"{value:g}"


def _awarded(result) -> str:
    """Points awarded, with the item's mark: "1.6 review", "0 platform"."""
    return _points(result.awarded) + (f" {result.mark}" if result.mark else "")


def table(report: Report) -> str:
    """The terminal table (a mark after the points: review, platform), then each item's
    deductions and reasons for review, and each failed item's log lines."""
    rows = [(f"{r.item.task}. {r.item.title}", _points(r.item.points), _awarded(r),
             r.evidence()) for r in report.results]
    width = max([len("item")] + [len(row[0]) for row in rows])
    column = max([len("awarded")] + [len(row[2]) for row in rows])
    lines = [f"{'item':<{width}}  points  {'awarded':<{column}}  evidence",
             f"{'-' * width}  ------  {'-' * column}  {'-' * EVIDENCE_WIDTH}"]
    for name, points, awarded, evidence in rows:
        wrapped = textwrap.wrap(evidence, EVIDENCE_WIDTH) or [""]
        lines.append(f"{name:<{width}}  {points:>6}  {awarded:<{column}}  {wrapped[0]}")
        lines += [f"{'':<{width}}  {'':>6}  {'':<{column}}  {more}" for more in wrapped[1:]]
    lines.append(f"{'total':<{width}}  {_points(report.possible):>6}  "
                 f"{_points(report.awarded):<{column}}"
                 + ("  incomplete: a platform fault kept items from being graded"
                    if report.incomplete else ""))
    for result in report.results:
        said = ([f"  - deducted {_points(points)}: {rule}: {why}"
                 for rule, points, why in result.deducted]
                + [f"  - review: {why}" for why in result.review]
                + ([f"  - platform: {result.platform}"] if result.platform else []))
        if said:
            lines += ["", f"'{result.item.title}':", *said]
    for result in report.results:
        if result.log:
            lines.append("")
            lines.append(f"why '{result.item.title}' failed:")
            lines += [f"  | {line}" for line in result.log[-LOG_LINES_SHOWN:]]
    return "\n".join(lines)


def markdown(report: Report) -> str:
    out: List[str] = [f"# {report.course.title}: grading report", "",
                      f"- submission: `{report.submission}`",
                      f"- awarded: **{_points(report.awarded)} of {_points(report.possible)}**"
                      + (" (incomplete: a platform fault kept items from being graded)"
                         if report.incomplete else ""),
                      f"- grading took {report.seconds:.0f} s"]
    if report.build:
        out.append(f"- build: {report.build}")
    out += [f"- {note}" for note in report.notes]
    out += [f"- {f.title}: {f.missing}" for f in report.figures if not f.file]
    out += ["", "| task | item | points | awarded | evidence |", "|---|---|---|---|---|"]
    for r in report.results:
        evidence = r.evidence().replace("|", "\\|")
        out.append(f"| {r.item.task} | {r.item.title} | {_points(r.item.points)} | "
                   f"{_awarded(r)} | {evidence} |")
    for r in report.results:
        out += ["", f"## {r.item.task}. {r.item.title} ({_points(r.awarded)} of "
                    f"{_points(r.item.points)})", "", f"> {r.item.rubric.guide}", ""]
        if r.item.rubric.scale:
            out.append(f"- scale: {r.item.rubric.scale.describe()}")
        shares = dict(r.parts)
        for c in r.checks:
            share = shares.get(c.name)
            scored = "" if share is None or share in (0.0, 1.0) else f" ({share:.0%} of its part)"
            out.append(f"- {'pass' if c.passed else 'FAIL'}: {c.name}: {c.evidence}{scored}")
        out += [f"- deducted {_points(points)}: {rule}: {why}" for rule, points, why in r.deducted]
        out += [f"- **review**: {why}" for why in r.review]
        out += [f"- **platform**: {r.platform}"] if r.platform else []
        out += [f"- note: {note}" for note in r.beyond + r.notes]
        out += [f"- killed after the scenario's stop: pid {k.pid}: `{k.command}`"
                for k in r.killed]
        for figure in r.figures:
            out += _figure(figure)
        if r.log:
            out += ["", "```", *r.log, "```"]
    return "\n".join(out) + "\n"


def _figure(figure: Figure) -> List[str]:
    """A picture embedded (its file is beside report.md), or why there is none."""
    if not figure.file:
        return [f"- no picture ({figure.title}): {figure.missing}"]
    lines = ["", f"![{_alt(figure.title)}]({figure.file})"]
    return lines + (["", f"*{figure.caption}*"] if figure.caption else [])


def _alt(text: str) -> str:
    return text.replace("[", "(").replace("]", ")")


def write(report: Report, folder: str) -> List[str]:
    """Writes report.md and report.json into ``folder``; returns their paths."""
    os.makedirs(folder, exist_ok=True)
    md_path = os.path.join(folder, "report.md")
    json_path = os.path.join(folder, "report.json")
    with open(md_path, "w", encoding="utf-8") as stream:
        stream.write(markdown(report))
    with open(json_path, "w", encoding="utf-8") as stream:
        json.dump(report.to_dict(), stream, indent=2)
        stream.write("\n")
    return [md_path, json_path]

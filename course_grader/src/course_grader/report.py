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


def table(report: Report) -> str:
    """The terminal table, then each failed item's log lines."""
    rows = [(f"{r.item.task}. {r.item.title}", _points(r.item.points), _points(r.awarded),
             r.evidence()) for r in report.results]
    width = max([len("item")] + [len(row[0]) for row in rows])
    lines = [f"{'item':<{width}}  points  awarded  evidence",
             f"{'-' * width}  ------  -------  {'-' * EVIDENCE_WIDTH}"]
    for name, points, awarded, evidence in rows:
        wrapped = textwrap.wrap(evidence, EVIDENCE_WIDTH) or [""]
        lines.append(f"{name:<{width}}  {points:>6}  {awarded:>7}  {wrapped[0]}")
        lines += [f"{'':<{width}}  {'':>6}  {'':>7}  {more}" for more in wrapped[1:]]
    lines.append(f"{'total':<{width}}  {_points(report.possible):>6}  "
                 f"{_points(report.awarded):>7}")
    for result in report.results:
        if result.log:
            lines.append("")
            lines.append(f"why '{result.item.title}' failed:")
            lines += [f"  | {line}" for line in result.log[-LOG_LINES_SHOWN:]]
    return "\n".join(lines)


def markdown(report: Report) -> str:
    out: List[str] = [f"# {report.course.title}: grading report", "",
                      f"- submission: `{report.submission}`",
                      f"- awarded: **{_points(report.awarded)} of {_points(report.possible)}**",
                      f"- grading took {report.seconds:.0f} s"]
    if report.build:
        out.append(f"- build: {report.build}")
    out += [f"- {note}" for note in report.notes]
    out += [f"- {f.title}: {f.missing}" for f in report.figures if not f.file]
    out += ["", "| task | item | points | awarded | evidence |", "|---|---|---|---|---|"]
    for r in report.results:
        evidence = r.evidence().replace("|", "\\|")
        out.append(f"| {r.item.task} | {r.item.title} | {_points(r.item.points)} | "
                   f"{_points(r.awarded)} | {evidence} |")
    for r in report.results:
        out += ["", f"## {r.item.task}. {r.item.title} ({_points(r.awarded)} of "
                    f"{_points(r.item.points)})", ""]
        out += [f"- {'pass' if c.passed else 'FAIL'}: {c.name}: {c.evidence}" for c in r.checks]
        out += [f"- note: {note}" for note in r.notes]
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

"""``rosrun course_grader grade COURSE PATH [--out DIR] [--only SCENARIO ...]``: grades a
submission (a folder, or a local git repository as committed), prints the table and
writes report.md and report.json into DIR (default: a new temporary folder).

Several PATHs (or any of --jobs, --shard, --csv, --limit): grades them in parallel, one
child process each, and writes one CSV of scores (course_grader.batch)."""
from __future__ import annotations

import argparse
import math
import sys
import tempfile

from course_grader import course as course_file
from course_grader import batch, grader, report
from course_grader.submission import SubmissionError


def positive_seconds(text: str) -> float:
    """An argparse type: a finite number of seconds above 0 (0, a negative number, NaN or
    infinity would make every limit fire at once or never)."""
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and value > 0):
        raise argparse.ArgumentTypeError(f"must be a positive number of seconds, got {text}")
    return value


def positive_count(text: str) -> int:
    """An argparse type: a whole number of at least 1."""
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be a whole number of at least 1, got {text}")
    return value


def parse_args(argv):
    return build_parser().parse_args(argv)


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="grade", description=__doc__.split("\n\n")[0])
    parser.add_argument("course", help=f"the course ({', '.join(course_file.available())})")
    parser.add_argument("path", nargs="+",
                        help="the submission: a folder or a local git repository; several: "
                             "graded in parallel, one CSV of scores")
    parser.add_argument("--out", help="folder for report.md, report.json, the build and logs "
                                      "(several submissions: one subfolder each) "
                                      "(default: a new temporary folder)")
    parser.add_argument("--only", nargs="+", metavar="SCENARIO",
                        help="run only these scenarios (their items alone are graded); "
                             f"each course's: {course_file.scenario_summary()}")
    parser.add_argument("--scenario-limit", type=positive_seconds, metavar="SECONDS",
                        help="wall-clock limit of one scenario, after which its processes are "
                             "killed and its items score 0 (default: the course's limits.scenario)")
    parser.add_argument("--scenario-jobs", type=positive_count, default=1, metavar="N",
                        help="scenarios of one submission run at once, each in its own "
                             "simulation (default: %(default)s)")
    parser.add_argument("--platform", default=grader.PLATFORM_SETUP,
                        help="setup.bash of the platform built alone (default: %(default)s)")
    parser.add_argument("--jobs", type=positive_count,
                        help="submissions graded at once (default: the number of cores)")
    parser.add_argument("--shard", metavar="I/N",
                        help="grade only shard I of N (1-based) of the sorted paths: "
                             "every N-th from the I-th")
    parser.add_argument("--csv", metavar="FILE",
                        help="the scores, one row per submission (default: OUT/scores.csv)")
    parser.add_argument("--limit", type=positive_seconds, metavar="SECONDS",
                        help="wall-clock limit per submission, after which it is killed "
                             "(default: from the course's limits)")
    parser.add_argument("--summary", action="store_true", default=None,
                        help="after a batch, the class per item: full, part and no marks, "
                             "the mean, the items marked review or platform")
    return parser


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(sys.argv[1:] if argv is None else argv)
    try:
        course = course_file.load(args.course)
        if args.scenario_limit is not None:
            course.limits["scenario"] = args.scenario_limit
        unknown = sorted(set(args.only or []) - set(course.scenarios()))
        if unknown:
            raise course_file.CourseError(f"unknown scenario(s) {unknown}; the course has "
                                          f"{course.scenarios()}")
        out = args.out or tempfile.mkdtemp(prefix=f"grade_{course.name}_")
        if batch.wanted(args):
            return batch.main(parser, args, course, out)
        result = grader.grade(course, args.path[0], out, args.platform,
                              progress=lambda line: print(f"grade: {line}", flush=True),
                              scenarios=args.only, scenario_jobs=args.scenario_jobs)
    except (course_file.CourseError, SubmissionError, batch.BatchError) as error:
        print(f"grade: {error}", file=sys.stderr)
        return 2
    print()
    print(report.table(result))
    print()
    for path in report.write(result, out):
        print(f"grade: report written: {path}")
    print(f"grade: {result.awarded:g} of {result.possible:g} points in {result.seconds:.0f} s")
    return 0

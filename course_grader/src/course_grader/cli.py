"""``rosrun course_grader grade COURSE PATH [--out DIR] [--only SCENARIO ...]``: grades a
submission (a folder, or a local git repository as committed), prints the table and
writes report.md and report.json into DIR (default: a new temporary folder)."""
from __future__ import annotations

import argparse
import sys
import tempfile

from course_grader import course as course_file
from course_grader import grader, report
from course_grader.submission import SubmissionError


def parse_args(argv):
    parser = argparse.ArgumentParser(prog="grade", description=__doc__.split("\n\n")[0])
    parser.add_argument("course", help=f"the course ({', '.join(course_file.available())})")
    parser.add_argument("path", help="the submission: a folder or a local git repository")
    parser.add_argument("--out", help="folder for report.md, report.json, the build and logs "
                                      "(default: a new temporary folder)")
    parser.add_argument("--only", nargs="+", metavar="SCENARIO",
                        help="run only these scenarios (their items alone are graded)")
    parser.add_argument("--scenario-limit", type=float, metavar="SECONDS",
                        help="wall-clock limit of one scenario, after which its processes are "
                             "killed and its items score 0 (default: the course's limits.scenario)")
    parser.add_argument("--platform", default=grader.PLATFORM_SETUP,
                        help="setup.bash of the platform built alone (default: %(default)s)")
    return parser.parse_args(argv)


def main(argv=None) -> int:
    args = parse_args(sys.argv[1:] if argv is None else argv)
    try:
        course = course_file.load(args.course)
        if args.scenario_limit is not None:
            course.limits["scenario"] = args.scenario_limit
        unknown = sorted(set(args.only or []) - set(course.scenarios()))
        if unknown:
            raise course_file.CourseError(f"unknown scenario(s) {unknown}; the course has "
                                          f"{course.scenarios()}")
        out = args.out or tempfile.mkdtemp(prefix=f"grade_{course.name}_")
        result = grader.grade(course, args.path, out, args.platform,
                              progress=lambda line: print(f"grade: {line}", flush=True),
                              scenarios=args.only)
    except (course_file.CourseError, SubmissionError) as error:
        print(f"grade: {error}", file=sys.stderr)
        return 2
    print()
    print(report.table(result))
    print()
    for path in report.write(result, out):
        print(f"grade: report written: {path}")
    print(f"grade: {result.awarded:g} of {result.possible:g} points in {result.seconds:.0f} s")
    return 0

"""``python3 -m course_grader COURSE PATH ...``: the grade command (course_grader.cli), as
the batch runs it for each submission."""
import sys

from course_grader.cli import main

sys.exit(main())

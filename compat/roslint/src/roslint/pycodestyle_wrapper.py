"""pycodestyle as roslint runs it (``python -m roslint.pycodestyle_wrapper FILE...``): PEP 8
with ROS's 120-character lines (roslint noetic 0.12.0 ``src/roslint/pycodestyle_wrapper.py``
l. 4). The checker is Debian's ``python3-pycodestyle``; without it the run says what to install.
"""
import sys

# pycodestyle_wrapper.py l. 4
MAX_LINE_LENGTH = 120
MISSING = ("roslint: pycodestyle is not installed, so nothing was linted. Install it "
           "(Debian/Ubuntu: apt-get install python3-pycodestyle; PyPI: pip install pycodestyle) "
           "and run again.")


def main(argv):
    try:
        import pycodestyle
    except ImportError:
        print(MISSING, file=sys.stderr)
        return 1
    pycodestyle.MAX_LINE_LENGTH = MAX_LINE_LENGTH
    sys.argv = argv
    try:
        pycodestyle._main()
    except SystemExit as done:
        return done.code
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

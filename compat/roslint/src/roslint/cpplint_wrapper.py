"""cpplint as roslint runs it (``python -m roslint.cpplint_wrapper FILE...``): Google's checker
with the ROS C++ style guide's departures, as roslint noetic 0.12.0's
``src/roslint/cpplint_wrapper.py`` makes them:

- lines up to 120 characters (l. 42);
- ``runtime/references`` off (l. 182): ROS code passes outputs by non-const reference;
- include order and ``readability/streams`` not checked (l. 115-119);
- braces as ROS writes them, each of a new scope's ``{`` and ``}`` on a line of its own
  (l. 86-112), in place of Google's brace rules (l. 123-127);
- access specifiers at the class's own indentation (l. 131-137);
- ROS's ``do { ... } while (c);`` not an empty loop (l. 142-179);
- header guards named after the path below ``include/`` or below the package
  (``PKG_FILE_H``, l. 72-82), not Google's path-from-the-repository with a trailing ``_``.

The checker itself is Debian's ``cpplint`` (1.6.1, the same checks as roslint's bundled copy);
without it the run stops and says what to install, so ``make roslint_<pkg>`` never passes
silently.
"""
import os
import re
import sys

# cpplint_wrapper.py l. 42: the ROS C++ style guide's line length
LINE_LENGTH = 120
# l. 182: the one category roslint filters off on its command line
COMMAND_LINE_FILTERS = "-runtime/references"
# l. 119 and l. 127: categories whose Google rules ROS does not follow
SILENCED_CATEGORIES = frozenset((
    "build/include_order", "build/include_alpha", "readability/streams",
    "readability/braces", "whitespace/braces"))
# l. 137: Google indents public:/private: by one space; ROS does not
SILENCED_MESSAGE = re.compile(r".*should be indented \+1 space inside")
MISSING = ("roslint: cpplint is not installed, so nothing was linted. Install it "
           "(Debian/Ubuntu: apt-get install cpplint; PyPI: pip install cpplint) and run again.")


def _ros_header_guard(filename):
    """The guard ROS style asks for: the path below the nearest ``include`` folder or package
    root (a folder holding package.xml), upper case, separators as ``_``."""
    parts = []
    head = os.path.abspath(filename)
    while True:
        head, tail = os.path.split(head)
        parts.insert(0, tail)
        if not tail or os.path.basename(head) == "include" or \
                os.path.exists(os.path.join(head, "package.xml")):
            break
    return re.sub(r"[^A-Za-z0-9]", "_", "_".join(p for p in parts if p)).upper()


def _install(cpplint):
    """Patch Debian's cpplint module in place with the ROS rules (its checks look each other
    up as module globals, so replacing them here changes what ProcessFile runs)."""
    report = cpplint.Error

    def filtered(filename, linenum, category, confidence, message):
        if category in SILENCED_CATEGORIES or SILENCED_MESSAGE.match(message):
            return
        report(filename, linenum, category, confidence, message)

    def ros_braces(filename, clean_lines, linenum, error):
        line = clean_lines.elided[linenum]
        opening, closing = line.find("{"), line.rfind("}")
        if opening >= 0 and closing > opening:
            return  # a one-line body or initialiser holds both
        if opening >= 0 and line[:opening].strip():
            before = line[:opening]
            if "=" not in before and not before.rstrip().endswith(("(", ",", "return")):
                report(filename, linenum, "whitespace/braces", 4,
                       "when starting a new scope, { should be on a line by itself")
        if closing >= 0:
            after = line[closing + 1:].strip()
            if line[:closing].strip() or (after and not re.match(r"^[;,)]*$", after)):
                report(filename, linenum, "whitespace/braces", 4, "} should be on a line by itself")

    empty_block_body = cpplint.CheckEmptyBlockBody

    def ros_empty_block_body(filename, clean_lines, linenum, error):
        def keep_do_while(fname, number, category, confidence, message):
            previous = clean_lines.elided[linenum - 1] if linenum else ""
            if category == "whitespace/empty_loop_body" and previous.rstrip().endswith("}"):
                return
            error(fname, number, category, confidence, message)
        empty_block_body(filename, clean_lines, linenum, keep_do_while)

    cpplint.Error = filtered
    cpplint.CheckBraces = ros_braces
    cpplint.CheckEmptyBlockBody = ros_empty_block_body
    cpplint.GetHeaderGuardCPPVariable = _ros_header_guard


def main(argv):
    try:
        import cpplint
    except ImportError:
        print(MISSING, file=sys.stderr)
        return 1
    _install(cpplint)
    sys.argv = [argv[0], f"--linelength={LINE_LENGTH}", f"--filter={COMMAND_LINE_FILTERS}"] + argv[1:]
    try:
        cpplint.main()
    except SystemExit as done:
        return done.code
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

"""roslint_add_test's runner (``python -m roslint.test_wrapper RESULT_XML COMMAND...``): runs the
lint command (``make roslint_<pkg>``), echoes what it printed and writes one JUnit test case,
failed with the linters' output when the command failed, as roslint noetic 0.12.0's
``scripts/test_wrapper`` does (suite ``roslint``, class ``roslint.LintCheck``, the case named
after the command's last word)."""
import os
import subprocess
import sys
import xml.etree.ElementTree as ET


def main(argv):
    if len(argv) < 3:
        print("usage: python -m roslint.test_wrapper RESULT_XML COMMAND...", file=sys.stderr)
        return 2
    result_file, command = argv[1], argv[2:]
    run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    sys.stderr.write(run.stdout)
    failed = run.returncode != 0
    suite = ET.Element("testsuite", name="roslint", tests="1", failures=str(int(failed)),
                       errors="0")
    case = ET.SubElement(suite, "testcase", name=command[-1], classname="roslint.LintCheck")
    if failed:
        ET.SubElement(case, "failure", message="One or more linter errors was reported.",
                      type="").text = run.stdout
    else:
        case.set("status", "run")
    os.makedirs(os.path.dirname(os.path.abspath(result_file)), exist_ok=True)
    ET.ElementTree(suite).write(result_file, encoding="UTF-8", xml_declaration=True)
    return int(failed)


if __name__ == "__main__":
    sys.exit(main(sys.argv))

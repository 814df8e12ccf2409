"""roslint's linters as its macros run them (``python -m roslint.<wrapper>``): ROS C++ style
passes and Google's brace style, long lines and Google's header guards fail (roslint noetic
0.12.0 cpplint_wrapper.py l. 42, 72-82, 86-112, 131-137, 182); Python lines to 120 characters
(pycodestyle_wrapper.py l. 4); a missing linter fails the run saying what to install; the test
wrapper writes roslint_add_test's JUnit result (scripts/test_wrapper)."""
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest

SYSTEM_PYTHON = "/usr/bin/python3"  # what the macros run: catkin's PYTHON_EXECUTABLE
SOURCE = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "src")

ROS_STYLE_HEADER = """\
// Copyright 2026 Workspace maintainers
#ifndef PKG_THING_H
#define PKG_THING_H

namespace pkg
{
class Thing
{
public:
  void fill(int& out);
};
}  // namespace pkg

#endif  // PKG_THING_H
"""
ROS_STYLE_SOURCE = """\
// Copyright 2026 Workspace maintainers
#include <pkg/thing.h>

namespace pkg
{
void Thing::fill(int& out)
{
  if (out > 0)
  {
    out = 1;
  }
  else
  {
    out = 2;
  }
  do
  {
    out--;
  }
  while (out > 0);
}
}  // namespace pkg
"""
GOOGLE_STYLE_SOURCE = """\
// Copyright 2026 Workspace maintainers
namespace pkg {
int twice(int x) {
  if (x > 0) {
    return 2 * x;
  } else {
    return 0;
  }
}
}  // namespace pkg
"""


def lint(wrapper, *files, cwd=None, environment=None):
    env = dict(os.environ, **{"PYTHONPATH": SOURCE, **(environment or {})})
    return subprocess.run([SYSTEM_PYTHON, "-m", f"roslint.{wrapper}", *files], cwd=cwd, env=env,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


@pytest.fixture
def package(tmp_path):
    """A package folder: package.xml and include/pkg, where ROS's header guards start."""
    (tmp_path / "package.xml").write_text("<package/>")
    (tmp_path / "include" / "pkg").mkdir(parents=True)
    (tmp_path / "src").mkdir()
    return tmp_path


def test_ros_style_cpp_passes(package):
    (package / "include" / "pkg" / "thing.h").write_text(ROS_STYLE_HEADER)
    (package / "src" / "thing.cpp").write_text(ROS_STYLE_SOURCE)
    run = lint("cpplint_wrapper", "include/pkg/thing.h", "src/thing.cpp", cwd=package)
    assert run.returncode == 0, run.stdout
    assert "Total errors" not in run.stdout


def test_google_braces_and_long_lines_fail(package):
    long_line = "int x = 0;" + " " * 100 + "// " + "y" * 10
    (package / "src" / "bad.cpp").write_text(GOOGLE_STYLE_SOURCE + long_line + "\n")
    run = lint("cpplint_wrapper", "src/bad.cpp", cwd=package)
    assert run.returncode == 1
    # namespace, function, if and else each open a scope on a line of code
    assert run.stdout.count("{ should be on a line by itself") == 4, run.stdout
    assert "} should be on a line by itself" in run.stdout
    assert "Lines should be <= 120 characters long" in run.stdout
    assert "Total errors found: 6" in run.stdout


def test_lines_of_120_pass(package):
    line = "int x = 0;" + " " * (120 - len("int x = 0;") - len("// z")) + "// z"
    assert len(line) == 120
    (package / "src" / "wide.cpp").write_text("// Copyright 2026 Workspace maintainers\n" + line + "\n")
    assert lint("cpplint_wrapper", "src/wide.cpp", cwd=package).returncode == 0


def test_google_header_guard_fails(package):
    header = ROS_STYLE_HEADER.replace("PKG_THING_H", "PKG_INCLUDE_PKG_THING_H_")
    (package / "include" / "pkg" / "thing.h").write_text(header)
    run = lint("cpplint_wrapper", "include/pkg/thing.h", cwd=package)
    assert run.returncode == 1
    assert "#ifndef header guard has wrong style, please use: PKG_THING_H" in run.stdout


def test_missing_cpplint_says_what_to_install(package):
    (package / "src" / "thing.cpp").write_text(ROS_STYLE_SOURCE)
    blocker = package / "blocker"
    blocker.mkdir()
    (blocker / "cpplint.py").write_text("raise ImportError('not installed here')\n")
    run = lint("cpplint_wrapper", "src/thing.cpp", cwd=package,
               environment={"PYTHONPATH": f"{blocker}{os.pathsep}{SOURCE}"})
    assert run.returncode == 1
    assert "cpplint is not installed, so nothing was linted" in run.stdout


def test_python_lines_to_120(tmp_path):
    (tmp_path / "ok.py").write_text("x = '" + "a" * 114 + "'\n")
    (tmp_path / "long.py").write_text("x = '" + "a" * 115 + "'\n")
    assert lint("pycodestyle_wrapper", "ok.py", cwd=tmp_path).returncode == 0
    run = lint("pycodestyle_wrapper", "long.py", cwd=tmp_path)
    assert run.returncode == 1 and "E501 line too long (121 > 120 characters)" in run.stdout


@pytest.mark.parametrize("passes", [True, False])
def test_test_wrapper_writes_junit(tmp_path, passes):
    result = tmp_path / "results" / "roslint-pkg.xml"
    command = ["true" if passes else "false", "roslint_pkg"]
    run = subprocess.run([SYSTEM_PYTHON, "-m", "roslint.test_wrapper", str(result), *command],
                         env=dict(os.environ, PYTHONPATH=SOURCE))
    assert run.returncode == (0 if passes else 1)
    suite = ET.parse(result).getroot()
    assert (suite.tag, suite.get("name"), suite.get("tests")) == ("testsuite", "roslint", "1")
    assert suite.get("failures") == ("0" if passes else "1")
    case = suite.find("testcase")
    assert (case.get("name"), case.get("classname")) == ("roslint_pkg", "roslint.LintCheck")
    assert (case.find("failure") is None) == passes

"""The ``config`` argument of urdf/ddrive.urdf.xacro reaches load_yaml as a value, never as
expression text: a quote-laden argument (once it closed the string in
``${load_yaml('$(arg config)')}`` and ran as Python) is a file name that cannot be read,
and nothing it says is run. xacro is run as the launch files run it (one argument)."""
import os
import subprocess
import sys

import pytest
import rospkg

PACKAGE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
XACRO_FILE = os.path.join(PACKAGE, "urdf", "ddrive.urdf.xacro")
# the xacro command the launch files call ($(find xacro)/xacro)
XACRO = os.path.join(rospkg.RosPack().get_path("xacro"), "xacro")
# how long xacro may take on this file (it takes well under a second)
XACRO_TIMEOUT = 60


def payloads(marker):
    """Arguments meant to run ``touch marker``: the first closes the quoted string of the
    old pattern and reaches os.system past xacro's restricted builtins (the control test
    shows it ran); the issue's, with statements; an expression of its own."""
    system = ("[c for c in ().__class__.__base__.__subclasses__() if c.__name__ == "
              "'_wrap_close'][0].__init__.__globals__['system']")
    return [f"'+str({system}('touch {marker}'))+'",
            f"x'); __import__('os').system('touch {marker}'); ('",
            f"${{__import__('os').system('touch {marker}')}}"]


def run_xacro(path, argument):
    return subprocess.run([sys.executable, XACRO, path, f"config:={argument}"],
                          capture_output=True, text=True, timeout=XACRO_TIMEOUT, check=False)


@pytest.mark.parametrize("which", [0, 1, 2])
def test_a_crafted_config_argument_is_a_file_name_and_runs_nothing(tmp_path, which):
    marker = tmp_path / "pwned"
    argument = payloads(marker)[which]
    result = run_xacro(XACRO_FILE, argument)
    assert result.returncode != 0
    assert "No such file or directory" in result.stderr
    # the file name, as given (xacro takes one pair of surrounding single quotes off a
    # property's value: its way of writing a string)
    assert argument.strip("'") in result.stderr
    assert not marker.exists()


def test_the_old_pattern_ran_the_argument(tmp_path):
    """The check above can see the fault: the same argument through the pattern the file
    had creates the marker."""
    marker = tmp_path / "pwned"
    old = tmp_path / "old.xacro"
    old.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
                   '<xacro:arg name="config" default="none.yaml"/>'
                   "<xacro:property name=\"c\" value=\"${load_yaml('$(arg config)')}\"/>"
                   '<link name="${c}"/></robot>')
    result = run_xacro(str(old), payloads(marker)[0])
    assert marker.exists(), result.stderr


def test_a_config_file_given_as_argument_is_read(tmp_path):
    default = os.path.join(PACKAGE, "config", "ddrive.yaml")
    copy = tmp_path / "copy of it.yaml"  # a space and no quote trouble
    copy.write_text(open(default, encoding="utf-8").read())
    result = run_xacro(XACRO_FILE, str(copy))
    assert result.returncode == 0, result.stderr
    assert run_xacro(XACRO_FILE, default).stdout == result.stdout

"""The ``config`` argument of urdf/px100.urdf.xacro reaches load_yaml as a value, never as
expression text (urdf_tools.xacro_arguments says why): a quote-laden argument is a file
name that cannot be read, and nothing it says is run; a real file given so is read."""
import os

import pytest

from urdf_tools.xacro_arguments import crafted_arguments, run_xacro, runs_nothing

PACKAGE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
XACRO_FILE = os.path.join(PACKAGE, "urdf", "px100.urdf.xacro")
DEFAULT_CONFIG = os.path.join(PACKAGE, "config", "px100.yaml")


@pytest.mark.parametrize("which", [0, 1, 2])
def test_a_crafted_config_argument_is_a_file_name_and_runs_nothing(tmp_path, which):
    marker = str(tmp_path / "pwned")
    runs_nothing(XACRO_FILE, "config", crafted_arguments(marker)[which], marker)


def test_a_config_file_given_as_argument_is_read(tmp_path):
    copy = tmp_path / "copy of it.yaml"  # a space and no quote trouble
    copy.write_text(open(DEFAULT_CONFIG, encoding="utf-8").read())
    result = run_xacro(XACRO_FILE, "config", str(copy))
    assert result.returncode == 0, result.stderr
    assert run_xacro(XACRO_FILE, "config", DEFAULT_CONFIG).stdout == result.stdout

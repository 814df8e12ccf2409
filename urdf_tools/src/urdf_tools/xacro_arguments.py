"""Checks that a xacro file hands a launch argument to its expressions as a value.

A file that writes ``${load_yaml('$(arg config)')}`` pastes the argument into expression
text: an argument with a quote in it closes the string and runs as Python (shown: a file
created through ``config:=...``). Written as a property's value
(``<xacro:property name="config_file" value="$(arg config)"/>``, then
``${load_yaml(config_file)}``) it is a file name whatever it says. The description tests
of the packages that take such an argument run xacro as their launch files do, with the
arguments below, and check nothing ran.
"""
from __future__ import annotations

import os
import subprocess
import sys
from typing import List

import rospkg

# how long xacro may take on a robot file (it takes well under a second)
XACRO_TIMEOUT = 60


def crafted_arguments(marker: str) -> List[str]:
    """Arguments meant to run ``touch marker``: the first closes the quoted string of the
    old pattern and reaches os.system past xacro's restricted builtins; one with
    statements; an expression of its own."""
    system = ("[c for c in ().__class__.__base__.__subclasses__() if c.__name__ == "
              "'_wrap_close'][0].__init__.__globals__['system']")
    return [f"'+str({system}('touch {marker}'))+'",
            f"x'); __import__('os').system('touch {marker}'); ('",
            f"${{__import__('os').system('touch {marker}')}}"]


def run_xacro(path: str, argument: str, value: str) -> subprocess.CompletedProcess:
    """xacro as the launch files call it ($(find xacro)/xacro), with ``argument:=value``."""
    xacro = os.path.join(rospkg.RosPack().get_path("xacro"), "xacro")
    return subprocess.run([sys.executable, xacro, path, f"{argument}:={value}"],
                          capture_output=True, text=True, timeout=XACRO_TIMEOUT, check=False)


def runs_nothing(path: str, argument: str, value: str, marker: str) -> None:
    """Asserts that ``value`` is taken as a file name that cannot be read (named in the
    error, as given but for the one pair of surrounding single quotes xacro takes off a
    property's value) and that the marker file was not created."""
    result = run_xacro(path, argument, value)
    assert result.returncode != 0, result.stdout[-500:]
    assert "No such file or directory" in result.stderr, result.stderr[-1000:]
    assert value.strip("'") in result.stderr, result.stderr[-1000:]
    assert not os.path.exists(marker), f"{value!r} ran"

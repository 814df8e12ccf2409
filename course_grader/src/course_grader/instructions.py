"""What a submission's own README tells its user to type, so that the grader runs the
submission as its author says and as the assignment tells students: the ``rosrun`` and
``roslaunch`` lines of its READMEs (in code blocks or inline), the arguments they type
after the guide's launch file (``use_fake:=true``), and, where the guide's command passes
an argument the submission's launch file does not declare (``flip:=true``), the node that
starts that part by hand instead. No ROS here."""
from __future__ import annotations

import os
import re
import shlex
from typing import Iterable, List, Optional

README_NAMES = re.compile(r"^readme(\.(md|markdown|rst|txt))?$", re.IGNORECASE)
# a command as a README shows it: at a line's start (after a prompt) or in backticks
COMMAND = re.compile(r"(?:^|`|\$\s*)\s*((?:rosrun|roslaunch)\s+[^`\n]+)", re.MULTILINE)


def readme_texts(folders: Iterable[str]) -> List[str]:
    """The READMEs directly in ``folders`` (a submission's root, its packages), read."""
    texts = []
    for folder in folders:
        if not folder or not os.path.isdir(folder):
            continue
        for name in sorted(os.listdir(folder)):
            path = os.path.join(folder, name)
            if README_NAMES.match(name) and os.path.isfile(path):
                with open(path, encoding="utf-8", errors="replace") as stream:
                    texts.append(stream.read())
    return texts


def commands(texts: Iterable[str]) -> List[List[str]]:
    """Every ``rosrun``/``roslaunch`` command the texts give, split as a shell splits it
    (a trailing comment dropped)."""
    found = []
    for text in texts:
        for match in COMMAND.finditer(text):
            line = match.group(1).split(" #")[0].strip()
            try:
                words = shlex.split(line)
            except ValueError:
                continue
            if len(words) >= 3:
                found.append(words)
    return found


def arg_name(arg: str) -> str:
    """A roslaunch argument's name: ``flip`` of ``flip:=true``."""
    return arg.split(":=")[0]


def readme_args(texts: Iterable[str], package: str, launch_file: str,
                guide_args: Iterable[str], real_robot_args: Iterable[str] = ()) -> List[str]:
    """The arguments a README types after ``roslaunch package launch_file`` beyond the
    guide's own (``guide_args``), so that the launch file runs as its author runs it
    (``use_fake:=true``). The README's lines for that launch file are read in order,
    passing over those that select the real robot (``real_robot_args``) or set one of the
    guide's arguments otherwise; those that type all the guide's arguments come first.
    Empty when the README runs it with the guide's arguments alone (a plain line among
    others, ``display.launch`` beside ``display.launch gui:=false``) or not at all."""
    guide = list(guide_args)
    guide_values = {arg_name(a): a for a in guide}
    real = set(real_robot_args)
    lines = []
    for words in commands(texts):
        if words[:3] != ["roslaunch", package, launch_file]:
            continue
        args = [w for w in words[3:] if ":=" in w]
        if real & set(args) or any(arg_name(a) in guide_values and a != guide_values[arg_name(a)]
                                   for a in args):
            continue
        lines.append(args)
    preferred = [args for args in lines if set(guide) <= set(args)] or lines
    extras = [[a for a in args if arg_name(a) not in guide_values] for args in preferred]
    if not extras or any(not e for e in extras):
        return []
    return extras[0]


def node_started_by_hand(texts: Iterable[str], package: str, word: str,
                         runnable: Iterable[str]) -> Optional[str]:
    """The node of ``package`` that starts the part named ``word`` by hand: the one the
    README runs (``rosrun package node`` with ``word`` in the node's name), else the one
    of ``runnable`` (the package's nodes rosrun can run) whose name holds ``word``."""
    runnable = list(runnable)
    for words in commands(texts):
        if words[0] == "rosrun" and words[1] == package and word in words[2]:
            return words[2]
    named = [node for node in runnable if word in node]
    return named[0] if named else None

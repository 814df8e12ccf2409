"""A submission made ready to run: its packages found (in a folder, or in the committed
state of a local git repository), copied into a temporary catkin workspace, built there on
top of the platform alone (``.ws/platform``, never the workspace's own course packages), and
the environment its launch files run in."""
from __future__ import annotations

import os
import re
import shutil
import subprocess
from dataclasses import dataclass, field
from typing import Dict, List, Optional

# folders never searched for packages (build output, version control)
SKIPPED_DIRS = {".git", "build", "devel", "install", "logs", ".catkin_tools", "__pycache__"}
# environment variables a catkin workspace sets; cleared before the overlay is sourced
CATKIN_VARIABLES = ("ROS_PACKAGE_PATH", "CMAKE_PREFIX_PATH", "LD_LIBRARY_PATH",
                    "PKG_CONFIG_PATH", "ROSLISP_PACKAGE_DIRECTORIES", "ROS_ROOT", "ROS_ETC_DIR",
                    "ROS_MASTER_URI", "ROS_HOME", "ROS_NAMESPACE")
BUILD_LOG_LINES = 15   # the compiler's last lines kept as evidence
BUILD_ERROR_LINES = 8  # lines of the first error message (a compiler's, CMake's) in the evidence
# a line that starts an error message: gcc/clang 'file:line:col: error:', 'CMake Error at',
# 'Error:'
# CMake's words for a package find_package did not find (catkin's COMPONENTS and
# find_package(X REQUIRED) alike); the log's lines are joined first, as CMake wraps them
NOT_FOUND = re.compile(r'package configuration file provided by "([A-Za-z0-9_]+)"')
ERROR_START = re.compile(r"(^|:\s*)(fatal )?error\b|^CMake Error\b|^Error\b", re.IGNORECASE)


class SubmissionError(RuntimeError):
    """The submission cannot be graded at all; the message says why."""


@dataclass
class Staged:
    """The submission copied into ``workspace/src``; ``missing``: packages not found."""

    workspace: str
    found: Dict[str, str] = field(default_factory=dict)   # package -> where it was found
    missing: List[str] = field(default_factory=list)
    revision: Optional[str] = None                         # git commit graded, if a repository
    root: str = ""                                         # the submission's folder (or checkout)


@dataclass
class Build:
    ok: bool
    summary: str
    log_tail: List[str]
    log_path: str
    # packages the build's find_package looked for and CMake did not find, in log order
    not_found: List[str] = field(default_factory=list)


def _package_name(package_xml: str) -> Optional[str]:
    with open(package_xml, encoding="utf-8", errors="replace") as stream:
        match = re.search(r"<name>\s*([^<\s]+)\s*</name>", stream.read())
    return match.group(1) if match else None


def find_packages(root: str, wanted: List[str]) -> Dict[str, str]:
    """The folders under ``root`` whose package.xml names one of ``wanted`` (first found,
    shallowest first)."""
    found: Dict[str, str] = {}
    for folder, dirs, files in sorted(os.walk(root), key=lambda entry: entry[0].count(os.sep)):
        dirs[:] = [d for d in dirs if d not in SKIPPED_DIRS]
        if "package.xml" in files and not os.path.exists(os.path.join(folder, "CATKIN_IGNORE")):
            name = _package_name(os.path.join(folder, "package.xml"))
            if name in wanted and name not in found:
                found[name] = folder
    return found


def _is_git_repository(path: str) -> bool:
    return os.path.isdir(os.path.join(path, ".git")) or (
        os.path.isfile(os.path.join(path, "HEAD")) and os.path.isdir(os.path.join(path, "objects")))


def stage(path: str, packages: List[str], workspace: str) -> Staged:
    """Copies the submission's ``packages`` into ``workspace/src``. A git repository is
    graded as committed (HEAD), a folder as it is."""
    path = os.path.abspath(path)
    if not os.path.isdir(path):
        raise SubmissionError(f"submission '{path}' is not a folder or a git repository")
    source, revision = path, None
    if _is_git_repository(path):
        source = os.path.join(workspace, "checkout")
        clone = subprocess.run(["git", "clone", "--quiet", "--no-hardlinks", path, source],
                               capture_output=True, text=True, check=False)
        if clone.returncode != 0:
            raise SubmissionError(f"git clone of '{path}' failed: {clone.stderr.strip()}")
        revision = subprocess.run(["git", "-C", source, "rev-parse", "HEAD"], capture_output=True,
                                  text=True, check=False).stdout.strip() or None
    staged = Staged(workspace=workspace, revision=revision, root=source)
    staged.found = find_packages(source, packages)
    staged.missing = [p for p in packages if p not in staged.found]
    os.makedirs(os.path.join(workspace, "src"), exist_ok=True)
    for name, folder in staged.found.items():
        shutil.copytree(folder, os.path.join(workspace, "src", name), symlinks=True,
                        ignore=shutil.ignore_patterns(*SKIPPED_DIRS))
    return staged


def clean_environment(base: Dict[str, str]) -> Dict[str, str]:
    """``base`` without any catkin workspace sourced (ours included) and with no display."""
    env = {k: v for k, v in base.items()
           if k not in CATKIN_VARIABLES and k not in ("DISPLAY", "PWD", "OLDPWD")}
    python_path = [p for p in env.get("PYTHONPATH", "").split(os.pathsep)
                   if p and "/devel/lib/" not in p and "/install/lib/" not in p]
    env["PYTHONPATH"] = os.pathsep.join(python_path)
    env["PATH"] = os.pathsep.join(["/usr/bin", "/bin", env.get("PATH", "")])
    return env


def sourced(setup_bash: str, base: Dict[str, str]) -> Dict[str, str]:
    """The environment after ``source setup_bash`` in ``base``."""
    if not os.path.isfile(setup_bash):
        raise SubmissionError(f"{setup_bash} does not exist (the platform is built by "
                              "'make' in the workspace: tools/setup.sh)")
    result = subprocess.run(["bash", "-c", f"source '{setup_bash}' && env -0"], env=base,
                            capture_output=True, check=False)
    if result.returncode != 0:
        raise SubmissionError(f"source {setup_bash} failed: {result.stderr.decode()[-500:]}")
    pairs = (entry.split("=", 1) for entry in result.stdout.decode().split("\0") if "=" in entry)
    return {key: value for key, value in pairs}


def build(workspace: str, platform_env: Dict[str, str], limit: float, log_path: str) -> Build:
    """``catkin_make`` in ``workspace`` with the platform sourced; the log's last lines."""
    command = ["catkin_make", "-C", workspace, "-DPYTHON_EXECUTABLE=/usr/bin/python3"]
    with open(log_path, "w", encoding="utf-8") as log:
        try:
            code = subprocess.run(command, cwd=workspace, env=platform_env, stdout=log,
                                  stderr=subprocess.STDOUT, timeout=limit,
                                  check=False).returncode
        except subprocess.TimeoutExpired:
            code = None
    with open(log_path, encoding="utf-8", errors="replace") as log:
        lines = [line.rstrip("\n") for line in log]
    tail = lines[-BUILD_LOG_LINES:]
    if code == 0:
        return Build(True, "catkin_make: ok", tail, log_path)
    reason = f"timed out after {limit:.0f} s" if code is None else f"exit status {code}"
    error = first_error(lines)
    return Build(False, f"catkin_make failed ({reason})" + (f": {error}" if error else "")
                 + f"; log {log_path}", tail, log_path, packages_not_found(lines))


def packages_not_found(lines: List[str]) -> List[str]:
    """The packages a build log's find_package did not find, each once, in log order."""
    found = NOT_FOUND.findall(" ".join(line.strip() for line in lines))
    return list(dict.fromkeys(found))


def first_error(lines: List[str]) -> Optional[str]:
    """The first error message in a build log with its continuation lines (indented; CMake
    puts blank lines inside one), at most BUILD_ERROR_LINES, joined into one line; None when
    no line starts an error."""
    for index, line in enumerate(lines):
        if ERROR_START.search(line.strip()):
            message = [line.strip()]
            for more in lines[index + 1:]:
                if len(message) == BUILD_ERROR_LINES or (more.strip() and not more[:1].isspace()):
                    break
                if more.strip():
                    message.append(more.strip())
            return " ".join(message)
    return None


def resolves_inside(env: Dict[str, str], packages: List[str], workspace: str) -> List[str]:
    """Packages that ``rospack find`` does not resolve inside ``workspace/src`` (so would be
    someone else's): one sentence each; empty when all are the submission's."""
    wrong = []
    src = os.path.realpath(os.path.join(workspace, "src"))
    for name in packages:
        found = sourced_find(env, name)
        if not os.path.realpath(found).startswith(src + os.sep):
            wrong.append(f"{name} resolves to '{found or 'nothing'}', not the submission's")
    return wrong


def sourced_find(env: Dict[str, str], package: str) -> str:
    """``rospack find package`` in ``env`` ('' when it is not found)."""
    return subprocess.run(["rospack", "find", package], env=env, capture_output=True, text=True,
                          check=False).stdout.strip()

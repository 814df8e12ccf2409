"""ME495 homework 3's files, checked without a simulation: the folders and launch files the
homework names, and the robot's description as it asks for it (a xacro that reads its
numbers from a yaml with ``load_yaml``, the Gazebo-specific parts in a ``.gazebo`` file it
includes, expanding to a URDF with the diff drive plugin and, on every link that is drawn,
a collision and an inertial). The xacro is expanded in the submission's own environment,
so ``$(find diff_drive)`` is the submission's."""
from __future__ import annotations

import glob
import os
import re
import subprocess
from typing import Callable, Dict, List, Optional

from course_grader.probe_tools import check
from urdf_tools import UrdfError, parse_urdf

# a xacro file's name in a launch file (the robot it loads)
XACRO_NAME = re.compile(r"([\w.-]+\.xacro)\b")
GAZEBO_FILE = re.compile(r".*\.gazebo(\.xacro)?$")


def _files(folder: str, pattern: str) -> List[str]:
    return sorted(glob.glob(os.path.join(folder, "**", pattern), recursive=True))


def _read(path: str) -> str:
    with open(path, encoding="utf-8", errors="replace") as stream:
        return stream.read()


def _relative(paths: List[str], root: str) -> str:
    return ", ".join(os.path.relpath(p, root) for p in paths) or "none"


def layout(ddrive: Optional[str], arm: Optional[str], spec: Dict) -> List[Dict]:
    """The folders and files the homework names, in each package."""
    checks = []
    if ddrive is None:
        checks.append(check("diff_drive present", False, "the submission has no diff_drive"))
    else:
        missing = [f for f in spec["ddrive_folders"] if not os.path.isdir(os.path.join(ddrive, f))]
        checks.append(check("diff_drive's folders", not missing,
                            f"diff_drive has {', '.join(spec['ddrive_folders'])}" if not missing
                            else f"diff_drive lacks the folder(s) {', '.join(missing)}"))
        runnable = runnable_nodes(ddrive)
        checks.append(check("a node in nodes/", bool(runnable),
                            f"nodes/: {', '.join(runnable)}" if runnable
                            else "no file in diff_drive/nodes that rosrun can run (executable, "
                                 "or installed by catkin_install_python)"))
        checks.append(_files_present("diff_drive", ddrive, spec["ddrive_files"]))
    if arm is None:
        checks.append(check("arm_move present", False, "the submission has no arm_move"))
    else:
        checks.append(_files_present("arm_move", arm, spec["arm_files"]))
    return checks


# the files catkin_install_python installs (with a relay in devel that runs them, so they run
# without the executable bit): its PROGRAMS, up to its DESTINATION
INSTALL_PYTHON = re.compile(r"catkin_install_python\s*\(\s*PROGRAMS\s+(.*?)\s*DESTINATION",
                            re.DOTALL | re.IGNORECASE)


def runnable_nodes(package: str) -> List[str]:
    """The files of ``package``'s nodes/ that ``rosrun`` runs: executable, or installed by
    ``catkin_install_python`` (whose devel relay runs a script without the executable bit;
    a student's README says ``rosrun``, and it runs)."""
    nodes = os.path.join(package, "nodes")
    if not os.path.isdir(nodes):
        return []
    text = _cmake_text(package)
    relayed = {os.path.normpath(p) for group in INSTALL_PYTHON.findall(text)
               for p in group.split()}
    return [name for name in sorted(os.listdir(nodes))
            if os.path.isfile(os.path.join(nodes, name))
            and (os.access(os.path.join(nodes, name), os.X_OK)
                 or os.path.normpath(f"nodes/{name}") in relayed)]


# a C++ node: add_executable's target, which catkin builds into the devel space where rosrun
# finds it by that name (``${PROJECT_NAME}`` in it is the project's name)
ADD_EXECUTABLE = re.compile(r"\badd_executable\s*\(\s*([^\s)]+)", re.IGNORECASE)
PROJECT = re.compile(r"\bproject\s*\(\s*([^\s)]+)", re.IGNORECASE)


def built_nodes(package: str) -> List[str]:
    """The executables ``package``'s CMakeLists.txt builds (``add_executable``): C++ nodes,
    which ``rosrun`` runs by their target names."""
    text = _cmake_text(package)
    if not text:
        return []
    project = PROJECT.search(text)
    name = project.group(1) if project else os.path.basename(os.path.normpath(package))
    return sorted({target.replace("${PROJECT_NAME}", name)
                   for target in ADD_EXECUTABLE.findall(text)})


def _cmake_text(package: str) -> str:
    """``package``'s CMakeLists.txt without its comments ("" when it has none)."""
    cmake = os.path.join(package, "CMakeLists.txt")
    return re.sub(r"#[^\n]*", "", _read(cmake)) if os.path.isfile(cmake) else ""


def _files_present(package: str, folder: str, files: List[str]) -> Dict:
    missing = [f for f in files if not os.path.isfile(os.path.join(folder, f))]
    return check(f"{package}'s files", not missing,
                 f"{package} has {', '.join(files)}" if not missing
                 else f"{package} lacks {', '.join(missing)}")


def robot_xacro(ddrive: str, launch_file: str) -> Optional[str]:
    """The xacro that ``launch_file`` loads (by name), else the one that declares a
    ``<robot`` and is not included by another."""
    xacros = _files(os.path.join(ddrive, "urdf"), "*.xacro")
    launch = os.path.join(ddrive, "launch", launch_file)
    if os.path.isfile(launch):
        named = set(XACRO_NAME.findall(_read(launch)))
        for path in xacros:
            if os.path.basename(path) in named:
                return path
    included = {os.path.basename(n) for p in xacros
                for n in re.findall(r"xacro:include[^>]*filename=\"([^\"]+)\"", _read(p))}
    tops = [p for p in xacros if "<robot" in _read(p) and os.path.basename(p) not in included]
    return tops[0] if tops else None


def expand_in(env: Dict[str, str], timeout: float) -> Callable[[str], str]:
    """A function that expands a xacro file with ``xacro`` run in ``env``."""
    def expand(path: str) -> str:
        done = subprocess.run(["xacro", path], env=env, capture_output=True, text=True,
                              timeout=timeout, check=False)
        if done.returncode != 0:
            raise UrdfError(f"xacro {os.path.basename(path)} failed: "
                            f"{done.stderr.strip()[-400:]}")
        return done.stdout
    return expand


def description(ddrive: Optional[str], spec: Dict, launch_file: str,
                expand: Callable[[str], str]) -> List[Dict]:
    """The xacro + yaml + .gazebo checks on diff_drive."""
    if ddrive is None:
        return [check("diff_drive present", False, "the submission has no diff_drive")]
    urdf_dir = os.path.join(ddrive, "urdf")
    xacros = _files(urdf_dir, "*.xacro")
    loaders = [p for p in xacros if "load_yaml(" in _read(p)]
    yamls = _files(os.path.join(ddrive, "config"), "*.yaml")
    checks = [check("a xacro reads a yaml", bool(loaders) and bool(yamls),
                    f"load_yaml in {_relative(loaders, ddrive)}; config yaml: "
                    f"{_relative(yamls, ddrive)}")]
    gazebo = [p for p in _files(urdf_dir, "*") if GAZEBO_FILE.match(p) and os.path.isfile(p)]
    including = [p for p in xacros if any(os.path.basename(g) in _read(p) for g in gazebo)
                 and "xacro:include" in _read(p)]
    checks.append(check("a .gazebo file the xacro includes", bool(gazebo) and bool(including),
                        f".gazebo: {_relative(gazebo, ddrive)}; included by "
                        f"{_relative(including, ddrive)}"))
    top = robot_xacro(ddrive, launch_file)
    if top is None:
        checks.append(check("the robot's xacro expands", False, "no top-level xacro in urdf/"))
        return checks
    try:
        model = parse_urdf(expand(top), os.path.basename(top))
    except (UrdfError, OSError, subprocess.TimeoutExpired) as error:
        checks.append(check("the robot's xacro expands", False, str(error)))
        return checks
    plugins = [p.get("filename", "") for _, block in model.gazebo for p in block.iter("plugin")]
    checks.append(check("the diff drive plugin", spec["drive_plugin"] in plugins,
                        f"{os.path.basename(top)} expands with plugins "
                        f"{', '.join(plugins) or 'none'}"))
    drawn = [link for link in model.links.values() if link.visuals]
    bare = [link.name for link in drawn if not link.collisions or link.inertial is None]
    checks.append(check("every drawn link has collision and inertial", bool(drawn) and not bare,
                        f"{len(drawn)} drawn links, all with collision and inertial" if not bare
                        else f"without collision or inertial: {', '.join(bare)}"))
    return checks


def run(course, scenario: str, context) -> Dict:
    """The layout scenario's runner (named in config/me495_hw3.yaml)."""
    del scenario
    spec = course.checks["layout"]
    src = os.path.join(context.workspace, "src")
    ddrive = os.path.join(src, "diff_drive") if "diff_drive" in context.staged.found else None
    arm = os.path.join(src, "arm_move") if "arm_move" in context.staged.found else None
    launch_file = course.checks["world"]["launch"][1]
    return {"checks": {
        "layout": layout(ddrive, arm, spec),
        "xacro_yaml_gazebo": description(ddrive, spec, launch_file,
                                         expand_in(context.env, spec["xacro_timeout"])),
    }}

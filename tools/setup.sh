#!/usr/bin/env bash
# Sets up the workspace on a fresh machine and rebuilds it; safe to run again.
#
#   1. checks the platform (Debian bookworm, Ubuntu 22.04 or 24.04);
#   2. installs the ROS 1 Debian packages and tools that are missing (nothing when none is);
#   3. makes .venv from the system interpreter and installs tools/requirements.txt
#      (again only when that file changed);
#   4. builds the catkin workspace in .ws/ (the repository is linked as .ws/src/<repo>,
#      the classic ~/catkin_ws/src/<repo> layout) with the system interpreter, and beside it
#   5. builds the platform alone (sim_bridge, urdf_tools, node_params, compat/, courses/,
#      course_grader; no course solution) into .ws/platform/, its own build and devel
#      spaces: what course_grader overlays a student's submission on.
#
# Everything prints one line per step so that a second run shows that it did nothing.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# shellcheck source=tools/platform.sh
source "$repo/tools/platform.sh"

check_platform

# --- 2. Debian packages ---------------------------------------------------------------
# What each group is for: ROS 1 runtime and build, message bindings (Python) and their CMake
# configs (lib*-msgs-dev, for packages that generate messages), rostest's CMake config (so
# that `catkin_make run_tests` runs the packages' add_rostest tests), the robot tools,
# headless rviz, the venv; what course packages build against (C++ nodes: roscpp, tf, urdf and
# the message headers; Python nodes: tf.transformations); what robot packages' launch files
# start and their CMakeLists find (tf's and tf2_ros's static_transform_publisher, nodelet,
# topic_tools' relay and throttle, rviz and robot_state_publisher as C++ libraries,
# tf_conversions for students' movers); what Gazebo's C++ plugin API is built on
# (compat/gazebo_dev: the real sdformat 12 and ignition-math6) and sim_bridge's plugin host
# (a pybind11 module); what robot packages' other build dependencies stand on: Debian's
# dynamic_reconfigure (.cfg generation, dynparam, the C++ and Python servers), the linters
# compat/roslint runs (cpplint, pycodestyle), TinyXML (compat/control_toolbox's Pid::initXml),
# TinyXML2 (the SRDF reader of compat/moveit_core's C++ side), googletest (its gtests) and
# random_numbers (the generator MoveIt's RobotState signatures name).
apt_packages=(
  catkin catkin-lint python3-catkin-pkg ros-message-generation ros-message-runtime
  python3-genpy python3-genmsg cmake make g++
  ros-core rosout rosbash python3-rospy python3-roslaunch python3-rostest python3-rosunit
  python3-actionlib python3-tf2-ros python3-tf2-geometry-msgs python3-wstool
  ros-std-msgs ros-std-srvs ros-geometry-msgs ros-sensor-msgs ros-nav-msgs
  ros-visualization-msgs ros-trajectory-msgs ros-actionlib-msgs ros-rosgraph-msgs ros-tf2-msgs
  python3-std-msgs python3-std-srvs python3-geometry-msgs python3-sensor-msgs python3-nav-msgs
  python3-visualization-msgs python3-trajectory-msgs python3-actionlib-msgs python3-rosgraph-msgs
  python3-tf2-msgs python3-rospkg
  libstd-msgs-dev libgeometry-msgs-dev libtrajectory-msgs-dev libactionlib-msgs-dev
  ros-shape-msgs python3-shape-msgs libshape-msgs-dev
  librostest-dev
  python3-tf libroscpp-dev liburdf-dev libtf-dev libtf2-ros-dev libtf2-geometry-msgs-dev
  libsensor-msgs-dev libnav-msgs-dev libstd-srvs-dev libroslib-dev python3-pyqt5
  python3-python-qt-binding libdiagnostic-msgs-dev python3-diagnostic-msgs
  ros-robot-state-publisher joint-state-publisher joint-state-publisher-gui rviz
  liburdfdom-tools
  tf-tools tf2-tools libnodeletlib-tools python3-nodelet libnodeletlib-dev topic-tools
  python3-topic-tools libtopic-tools-dev librviz-dev librobot-state-publisher-dev
  python3-tf-conversions libros-rosgraph-msgs-dev libactionlib-dev python3-pykdl
  xvfb xauth x11-utils xdotool imagemagick
  python3-venv python3-pip
  libsdformat-dev libignition-math-dev pybind11-dev python3-dev
  libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure cpplint
  python3-pycodestyle libtinyxml-dev libtinyxml2-dev libgtest-dev googletest librandom-numbers-dev
  libeigen-stl-containers-dev
  pluginlib-dev libclass-loader-dev libtf2-kdl-dev libtf2-eigen-dev libtf-conversions-dev
  liblapack-dev
)
# apt and the headers below write where only root may
as_root=()
[ "$(id -u)" -eq 0 ] || as_root=(sudo)
missing=()
for pkg in "${apt_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: Debian packages: all ${#apt_packages[@]} present"
else
  echo "setup: Debian packages: installing ${#missing[@]}: ${missing[*]}"
  if [ ${#as_root[@]} -gt 0 ] && ! command -v sudo >/dev/null; then
    echo "setup: need root or sudo to install Debian packages" >&2; exit 1
  fi
  "${as_root[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${as_root[@]}" apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
  echo "setup: Debian packages: done"
fi

# Debian's pluginlib-dev is ROS 2's pluginlib (5.2.1, found by ROS 1 packages' exports through
# rospack): it lacks Noetic's <pluginlib/*.h> headers, which ROS 1 plugins (IKFast plugins,
# rviz and controller plugins) include. They go where the compiler looks by itself.
ros1_headers=/usr/local/include/pluginlib
if ! diff -rq "$repo/tools/ros1_headers/pluginlib" "$ros1_headers" >/dev/null 2>&1; then
  "${as_root[@]}" install -D -m 644 -t "$ros1_headers" "$repo"/tools/ros1_headers/pluginlib/*.h
  echo "setup: pluginlib's ROS 1 headers: installed in $ros1_headers"
fi

# --- 3. the virtual environment -------------------------------------------------------
venv="$repo/.venv"
requirements="$repo/tools/requirements.txt"
stamp="$venv/.requirements.sha256"
want=$(sha256sum "$requirements" | cut -d' ' -f1)
if [ ! -x "$venv/bin/python3" ] || [ "$(readlink -f "$venv/bin/python3")" != "$(readlink -f /usr/bin/python3)" ]; then
  rm -rf "$venv"
  /usr/bin/python3 -m venv --system-site-packages "$venv"
  echo "setup: venv: created $venv from /usr/bin/python3"
fi
if [ "$(cat "$stamp" 2>/dev/null)" = "$want" ]; then
  echo "setup: venv: requirements up to date"
else
  echo "setup: venv: installing tools/requirements.txt"
  rm -f "$venv/bin/xacro"  # the link made below: pip must not write through it
  "$venv/bin/python3" -m pip install --quiet --disable-pip-version-check -r "$requirements" 2>&1 \
    | grep -v "is ignored: it is neither a file nor a directory" || true
  "$venv/bin/python3" -c "import pybullet, xacro, ompl, fcl, pytest" 2>/dev/null \
    || { echo "setup: venv: the pinned packages do not import" >&2; exit 1; }
  echo "$want" > "$stamp"
fi
# The venv's `xacro` command is PyPI's, which finds packages through ROS 2's ament index; the
# workspace's (compat/xacro, rospkg's $(find)) takes its place on PATH.
ln -sfn "$repo/compat/xacro/xacro" "$venv/bin/xacro"

# --- 4. and 5. the two catkin builds, side by side ---------------------------------------
# 4: the whole workspace in .ws/ (the repository linked as .ws/src/<repo>, the classic
# ~/catkin_ws/src/<repo> layout). 5: the platform alone in .ws/platform/: its own source
# space, .ws/platform/src, holding links to the platform's packages only (catkin's devel
# space puts its source space on ROS_PACKAGE_PATH: with the whole repository there,
# `rospack find my_rb1_ros` would still find ours), and its own build and devel spaces; a
# platform package that depends on a course solution fails there. Each build's CMake
# configure runs on one core for half a minute: started together they share the two
# (80 s one after the other, measured on a fresh clone).
ws="$repo/.ws"
mkdir -p "$ws/src"
link="$ws/src/$(basename "$repo")"
[ -L "$link" ] || ln -s ../.. "$link"
platform_ws="$ws/platform"
mkdir -p "$platform_ws/src"
platform_links=(sim_bridge urdf_tools node_params course_grader compat courses)
for name in "${platform_links[@]}"; do
  if [ -e "$repo/$name" ]; then
    [ -L "$platform_ws/src/$name" ] || ln -s "../../../$name" "$platform_ws/src/$name"
  else
    rm -f "$platform_ws/src/$name"
  fi
done
platform_count=$(find -L "$platform_ws/src" -name package.xml -not -path '*/test/*' | wc -l)
# The system interpreter first, whatever pyenv or conda put on PATH.
export PATH="/usr/bin:/bin:$PATH"
log="$ws/catkin_make.log"
platform_log="$platform_ws/catkin_make.log"
# then catkin's `tests` target: the packages' C++ gtest executables (tools/run_tests.py
# runs them in the unit tier)
(cd "$ws" && catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3 -DPython3_EXECUTABLE=/usr/bin/python3 -DCATKIN_ENABLE_TESTING=ON \
   >"$log" 2>&1 && make -C build tests >>"$log" 2>&1) &
workspace_build=$!
(cd "$platform_ws" && catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3 -DPython3_EXECUTABLE=/usr/bin/python3 \
   -DCATKIN_ENABLE_TESTING=OFF >"$platform_log" 2>&1) &
platform_build=$!
workspace_ok=0; wait "$workspace_build" || workspace_ok=$?
platform_ok=0; wait "$platform_build" || platform_ok=$?
if [ "$workspace_ok" -eq 0 ]; then
  echo "setup: catkin build: ok ($(ls -d "$repo"/*/package.xml "$repo"/compat/*/package.xml "$repo"/courses/*/package.xml | wc -l) packages; log $log)"
else
  tail -n 40 "$log" >&2
  echo "setup: catkin build failed; the whole log is $log" >&2
  exit 1
fi
if [ "$platform_ok" -eq 0 ]; then
  echo "setup: platform build: ok ($platform_count packages, no course solution; log $platform_log)"
else
  tail -n 40 "$platform_log" >&2
  echo "setup: platform build failed; the whole log is $platform_log" >&2
  exit 1
fi

# --- 6. byte-compiled Python ------------------------------------------------------------
# Machines that set PYTHONDONTWRITEBYTECODE (this one does) compile every module anew in
# every process: importing moveit_msgs' generated classes alone took 1.6 s a node. Python
# still reads byte code that is there, so it is written once here (messages, the devel
# spaces' shims, the packages' sources; __pycache__ is git-ignored).
shopt -s nullglob
compiled=("$ws/devel/lib/python3/dist-packages" "$platform_ws/devel/lib/python3/dist-packages"
          "$repo"/*/src "$repo"/compat/*/src "$repo"/courses/*/src "$repo/tools")
shopt -u nullglob
/usr/bin/python3 -m compileall -q -j 0 "${compiled[@]}" >/dev/null
echo "setup: byte code: ok"

# The workspace's environment: `source tools/env.bash` after `make` (or any make target).
#
# - the system interpreter and the venv's tools (xacro, pytest) come first on PATH, ahead
#   of pyenv or conda, so `python3` is /usr/bin/python3 with the venv's packages;
# - the venv's site-packages are on PYTHONPATH too, because catkin's relay scripts start
#   nodes with /usr/bin/python3 directly (pybullet and ompl live in the venv);
# - the catkin devel space is sourced, so roslaunch and rosrun find every package.
_ws_repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [ ! -f "$_ws_repo/.ws/devel/setup.bash" ]; then
  echo "tools/env.bash: the workspace is not built yet; run 'make' in $_ws_repo first" >&2
  return 1 2>/dev/null || exit 1
fi
export PATH="$_ws_repo/.venv/bin:/usr/bin:/bin:$PATH"
# shellcheck disable=SC1091
source "$_ws_repo/.ws/devel/setup.bash"
_ws_site=$("$_ws_repo/.venv/bin/python3" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
export PYTHONPATH="$_ws_site${PYTHONPATH:+:$PYTHONPATH}"
export WORKSPACE_REPO="$_ws_repo"
unset _ws_repo _ws_site

# Platform facts shared by the set-up and run scripts (sourced, not run).

# Stops with a message unless this is a platform whose own packages carry ROS 1.
# OS_RELEASE names another os-release file (the tests use it).
check_platform() {
  local id="" codename="" release="${OS_RELEASE:-/etc/os-release}"
  if [ -r "$release" ]; then
    id=$(. "$release" && echo "${ID:-}")
    codename=$(. "$release" && echo "${VERSION_CODENAME:-}")
  fi
  case "$id/$codename" in
    debian/bookworm|ubuntu/jammy|ubuntu/noble) ;;
    *)
      cat >&2 <<EOF
setup: unsupported platform '${id:-unknown} ${codename:-unknown}'.
This workspace uses the ROS 1 packages that the distribution itself ships under /usr:
supported are Debian 12 (bookworm), Ubuntu 22.04 (jammy) and Ubuntu 24.04 (noble).
EOF
      exit 1
      ;;
  esac
}

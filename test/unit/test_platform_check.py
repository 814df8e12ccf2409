"""tools/platform.sh: the set-up runs on the supported platforms and stops elsewhere."""
import os
import subprocess

import pytest

PLATFORM_SH = os.path.join(os.path.dirname(__file__), "..", "..", "tools", "platform.sh")


def check(tmp_path, os_release):
    release = tmp_path / "os-release"
    release.write_text(os_release)
    return subprocess.run(["bash", "-c", f'source "{PLATFORM_SH}" && check_platform && echo ok'],
                          env=dict(os.environ, OS_RELEASE=str(release)),
                          capture_output=True, text=True, check=False)


@pytest.mark.parametrize("os_release", [
    "ID=debian\nVERSION_CODENAME=bookworm\n",
    "ID=ubuntu\nVERSION_CODENAME=jammy\n",
    "ID=ubuntu\nVERSION_CODENAME=noble\n",
])
def test_supported_platforms_pass(tmp_path, os_release):
    result = check(tmp_path, os_release)
    assert result.returncode == 0 and result.stdout.strip() == "ok", result.stderr


def test_another_platform_stops_saying_what_is_supported(tmp_path):
    result = check(tmp_path, "ID=fedora\nVERSION_CODENAME=\n")
    assert result.returncode != 0
    assert "unsupported platform 'fedora" in result.stderr
    assert "Debian 12 (bookworm)" in result.stderr and "Ubuntu 22.04" in result.stderr

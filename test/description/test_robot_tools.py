"""What robot packages' launch files start and their CMakeLists find, from Debian, installed
by make (tools/setup.sh): tf's and tf2_ros's static_transform_publisher, nodelet, topic_tools,
rviz and robot_state_publisher as CMake packages, tf_conversions for Python movers."""
import subprocess

import pytest


@pytest.mark.parametrize("package, executable", [
    ("tf", "static_transform_publisher"), ("tf2_ros", "static_transform_publisher"),
    ("nodelet", "nodelet"), ("topic_tools", "relay"), ("topic_tools", "throttle"),
])
def test_launch_files_find_the_node(package, executable):
    found = subprocess.run(["rosrun", "--prefix", "echo", package, executable],
                           capture_output=True, text=True, timeout=60, check=False)
    assert found.returncode == 0, found.stderr


def test_cmake_finds_the_packages(tmp_path):
    (tmp_path / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.0.2)\nproject(probe)\n"
        "find_package(catkin REQUIRED COMPONENTS rviz robot_state_publisher topic_tools "
        "nodelet tf tf2_ros)\n")
    configured = subprocess.run(["cmake", "-S", str(tmp_path), "-B", str(tmp_path / "build"),
                                 "-DPYTHON_EXECUTABLE=/usr/bin/python3"],
                                capture_output=True, text=True, timeout=120, check=False)
    assert configured.returncode == 0, configured.stdout[-2000:] + configured.stderr[-2000:]


def test_python_movers_import_tf_conversions():
    imported = subprocess.run(["python3", "-c", "import tf_conversions.posemath as pm; "
                               "print(pm.toMsg(pm.fromTf(((1, 2, 3), (0, 0, 0, 1)))).position.x)"],
                              capture_output=True, text=True, timeout=60, check=False)
    assert imported.returncode == 0 and imported.stdout.strip() == "1.0", imported.stderr

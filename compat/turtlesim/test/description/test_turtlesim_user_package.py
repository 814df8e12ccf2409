"""A student's package that builds against turtlesim as the beginner tutorials have it
(``find_package(catkin REQUIRED COMPONENTS roscpp turtlesim)``, ``#include
<turtlesim/Pose.h>``, ``turtlesim::Spawn``) configures and compiles against this one."""
import subprocess

CMAKELISTS = """\
cmake_minimum_required(VERSION 3.0.2)
project(turtle_student)
find_package(catkin REQUIRED COMPONENTS geometry_msgs roscpp turtlesim)
catkin_package()
include_directories(${catkin_INCLUDE_DIRS})
add_executable(turtle_student src/turtle_student.cpp)
target_link_libraries(turtle_student ${catkin_LIBRARIES})
"""
PACKAGE_XML = """\
<?xml version="1.0"?>
<package format="2">
  <name>turtle_student</name>
  <version>0.0.1</version>
  <description>A student's package using turtlesim's messages and services.</description>
  <maintainer email="student@example.org">Student</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
  <depend>geometry_msgs</depend>
  <depend>roscpp</depend>
  <depend>turtlesim</depend>
</package>
"""
SOURCE = """\
#include <string>

#include <geometry_msgs/Twist.h>
#include <ros/ros.h>
#include <turtlesim/Color.h>
#include <turtlesim/Kill.h>
#include <turtlesim/Pose.h>
#include <turtlesim/SetPen.h>
#include <turtlesim/Spawn.h>
#include <turtlesim/TeleportAbsolute.h>
#include <turtlesim/TeleportRelative.h>

int main()
{
  turtlesim::Pose pose;
  pose.x = 1.0f;
  pose.linear_velocity = 2.0f;
  turtlesim::Spawn spawn;
  spawn.request.name = "leo";
  turtlesim::SetPen pen;
  pen.request.width = 3;
  static_assert(sizeof(pose.theta) == 4, "float32");
  const char* md5 = ros::message_traits::MD5Sum<turtlesim::Pose>::value();
  return std::string(md5) == "863b248d5016ca62ea2e895ae5265cf9" ? 0 : 1;
}
"""


def test_a_cpp_package_finds_turtlesim_and_builds(tmp_path):
    package = tmp_path / "src" / "turtle_student"
    (package / "src").mkdir(parents=True)
    (package / "CMakeLists.txt").write_text(CMAKELISTS)
    (package / "package.xml").write_text(PACKAGE_XML)
    (package / "src" / "turtle_student.cpp").write_text(SOURCE)
    build = tmp_path / "build"
    configure = subprocess.run(
        ["cmake", "-S", str(package), "-B", str(build), "-DPYTHON_EXECUTABLE=/usr/bin/python3",
         f"-DCATKIN_DEVEL_PREFIX={tmp_path / 'devel'}"],
        capture_output=True, text=True, timeout=300, check=False)
    assert configure.returncode == 0, configure.stdout[-3000:] + configure.stderr[-3000:]
    compiled = subprocess.run(["make", "-C", str(build)], capture_output=True, text=True,
                              timeout=300, check=False)
    assert compiled.returncode == 0, compiled.stdout[-3000:] + compiled.stderr[-3000:]
    built = tmp_path / "devel" / "lib" / "turtle_student" / "turtle_student"
    assert subprocess.run([str(built)], timeout=30, check=False).returncode == 0, \
        "the generated header's md5sum is not upstream's"

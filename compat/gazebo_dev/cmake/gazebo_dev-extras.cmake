# gazebo_dev's catkin exports, as the real gazebo_dev's: find_package(catkin COMPONENTS
# gazebo_dev) gives Gazebo's include dirs, library dirs and libraries through catkin_*.
find_package(gazebo REQUIRED QUIET)
list(APPEND gazebo_dev_INCLUDE_DIRS ${GAZEBO_INCLUDE_DIRS})
list(APPEND gazebo_dev_LIBRARY_DIRS ${GAZEBO_LIBRARY_DIRS})
list(APPEND gazebo_dev_LIBRARIES ${GAZEBO_LIBRARIES})
set(CMAKE_CXX_FLAGS "${CMAKE_CXX_FLAGS} ${GAZEBO_CXX_FLAGS}")

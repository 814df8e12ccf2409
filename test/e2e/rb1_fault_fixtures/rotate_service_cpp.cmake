# The rotate service as a C++ node (rotate_service.cpp), built by catkin_make against the
# distribution's roscpp (Debian: libroscpp-dev, libnav-msgs-dev, libtf2-dev); the package's
# find_package(catkin ...) names roscpp, geometry_msgs, nav_msgs and tf2 (the fixture's edit).
include_directories(${catkin_INCLUDE_DIRS})
add_executable(rotate_service src/rotate_service.cpp)
add_dependencies(rotate_service ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})
target_link_libraries(rotate_service ${catkin_LIBRARIES})
install(TARGETS rotate_service RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

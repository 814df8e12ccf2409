# roslint's CMake macros with upstream's names and arguments (ros/roslint noetic 0.12.0,
# cmake/roslint-extras.cmake.em): every package that finds roslint gets them. Each linter
# call adds a POST_BUILD command to the target roslint_<package>, which the target roslint
# depends on; `make roslint_<package>` lints, and fails when a linter reports anything.
# The linters run from the devel/install space's Python package `roslint`. Upstream's rely
# on ${CATKIN_ENV}'s PYTHONPATH, which is the one of the workspace's first configure: with
# /opt/ros sourced it holds roslint; here a fresh workspace's first configure has none, so
# the commands name roslint's Python folder themselves.
if(_ROSLINT_EXTRAS_INCLUDED_)
  return()
endif()
set(_ROSLINT_EXTRAS_INCLUDED_ TRUE)
get_filename_component(_ROSLINT_PYTHONPATH
  "${roslint_DIR}/../../../${CATKIN_GLOBAL_PYTHON_DESTINATION}" ABSOLUTE)
set(_ROSLINT_PYTHON ${CMAKE_COMMAND} -E env "PYTHONPATH=${_ROSLINT_PYTHONPATH}"
    ${PYTHON_EXECUTABLE})

# roslint_<package> and the overall roslint target, made once (roslint-extras.cmake.em l. 15-27)
macro(_roslint_create_targets)
  if(NOT TARGET roslint)
    add_custom_target(roslint)
  endif()
  if(NOT TARGET roslint_${PROJECT_NAME})
    add_custom_target(roslint_${PROJECT_NAME})
    add_dependencies(roslint roslint_${PROJECT_NAME})
  endif()
endmacro()

# roslint_custom(linter lintopts FILE...): run `linter lintopts FILE...` in the package's
# source folder when roslint_<package> is built (l. 29-44); no file is a warning
function(roslint_custom linter lintopts)
  if("${ARGN}" STREQUAL "")
    message(WARNING "roslint: no files provided for command")
  else()
    _roslint_create_targets()
    add_custom_command(TARGET roslint_${PROJECT_NAME} POST_BUILD
                       WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
                       COMMAND ${CATKIN_ENV} ${linter} ${lintopts} ${ARGN} VERBATIM)
  endif()
endfunction()

# roslint_cpp([FILE...]): cpplint with ROS's settings; no file lints every .cpp, .h and .hpp
# below the package (l. 46-56); ROSLINT_CPP_CMD and ROSLINT_CPP_OPTS override as upstream's
function(roslint_cpp)
  set(_files ${ARGN})
  if("${_files}" STREQUAL "")
    file(GLOB_RECURSE _files *.cpp *.h *.hpp)
  endif()
  if(NOT DEFINED ROSLINT_CPP_CMD)
    set(ROSLINT_CPP_CMD ${_ROSLINT_PYTHON} -m roslint.cpplint_wrapper)
  endif()
  roslint_custom("${ROSLINT_CPP_CMD}" "${ROSLINT_CPP_OPTS}" ${_files})
endfunction()

# roslint_python([FILE...]): pycodestyle with 120-character lines; no file lints every .py
# below the package (l. 58-68); ROSLINT_PYTHON_CMD and ROSLINT_PYTHON_OPTS override
function(roslint_python)
  set(_files ${ARGN})
  if("${_files}" STREQUAL "")
    file(GLOB_RECURSE _files *.py)
  endif()
  if(NOT DEFINED ROSLINT_PYTHON_CMD)
    set(ROSLINT_PYTHON_CMD ${_ROSLINT_PYTHON} -m roslint.pycodestyle_wrapper)
  endif()
  roslint_custom("${ROSLINT_PYTHON_CMD}" "${ROSLINT_PYTHON_OPTS}" ${_files})
endfunction()

# roslint_add_test(): `make run_tests` runs `make roslint_<package>` as a test whose JUnit
# result is roslint-<package>.xml (l. 70-76)
function(roslint_add_test)
  _roslint_create_targets()
  catkin_run_tests_target("roslint" "package" "roslint-${PROJECT_NAME}.xml"
    COMMAND "${CATKIN_ENV} ${CMAKE_COMMAND} -E env PYTHONPATH=${_ROSLINT_PYTHONPATH} ${PYTHON_EXECUTABLE} -m roslint.test_wrapper ${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/roslint-${PROJECT_NAME}.xml make roslint_${PROJECT_NAME}"
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endfunction()

// rviz_visual_tools' deprecation macro (noetic-devel 3.9.1 include/rviz_visual_tools/deprecation.h
// defines RVIZ_VISUAL_TOOLS_DEPRECATED): code that marks its own functions with it builds.
#pragma once

#define RVIZ_VISUAL_TOOLS_DEPRECATED __attribute__((deprecated))

// MoveIt's forward-declaration macros (moveit_core/macros/include/moveit/macros/class_forward.h, noetic-devel):
// MOVEIT_CLASS_FORWARD(C) declares class C and its pointer typedefs (CPtr, CConstPtr, ...), MOVEIT_STRUCT_FORWARD the
// same for a struct.
#pragma once

#include <moveit/macros/declare_ptr.h>

#define MOVEIT_CLASS_FORWARD(C)                                                                                        \
  class C;                                                                                                             \
  MOVEIT_DECLARE_PTR(C, C)

#define MOVEIT_STRUCT_FORWARD(C)                                                                                       \
  struct C;                                                                                                            \
  MOVEIT_DECLARE_PTR(C, C)

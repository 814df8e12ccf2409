// MoveIt's smart-pointer typedef macros (moveit_core/macros/include/moveit/macros/declare_ptr.h, noetic-devel):
// MOVEIT_DECLARE_PTR(Name, Type) gives NamePtr, NameConstPtr, NameWeakPtr, NameConstWeakPtr, NameUniquePtr and
// NameConstUniquePtr on std:: pointers; MOVEIT_DECLARE_PTR_MEMBER(Type) gives the same names inside a class.
#pragma once

#include <memory>

#define MOVEIT_DECLARE_PTR(Name, Type)                                                                                 \
  typedef std::shared_ptr<Type> Name##Ptr;                                                                             \
  typedef std::shared_ptr<const Type> Name##ConstPtr;                                                                  \
  typedef std::weak_ptr<Type> Name##WeakPtr;                                                                           \
  typedef std::weak_ptr<const Type> Name##ConstWeakPtr;                                                                \
  typedef std::unique_ptr<Type> Name##UniquePtr;                                                                       \
  typedef std::unique_ptr<const Type> Name##ConstUniquePtr

#define MOVEIT_DECLARE_PTR_MEMBER(Type)                                                                                \
  typedef std::shared_ptr<Type> Ptr;                                                                                   \
  typedef std::shared_ptr<const Type> ConstPtr;                                                                        \
  typedef std::weak_ptr<Type> WeakPtr;                                                                                 \
  typedef std::weak_ptr<const Type> ConstWeakPtr;                                                                      \
  typedef std::unique_ptr<Type> UniquePtr;                                                                             \
  typedef std::unique_ptr<const Type> ConstUniquePtr

// MoveIt's MoveItErrorCode (moveit_core/utils/include/moveit/utils/moveit_error_code.h, noetic-devel 7c0343f0): a
// moveit_msgs::MoveItErrorCodes that converts to bool (true only for SUCCESS), compares with an int code and prints as
// the code's name. In moveit_core as upstream's (library moveit_utils).
#pragma once

#include <ostream>
#include <string>

#include <moveit_msgs/MoveItErrorCodes.h>

namespace moveit
{
namespace core
{
class MoveItErrorCode : public moveit_msgs::MoveItErrorCodes
{
public:
  /** the code's name as in moveit_msgs/MoveItErrorCodes ("SUCCESS", "PLANNING_FAILED" ...); 0 is "NOT INITIALIZED",
      a code the message does not define "UNKNOWN" */
  static const char* toString(const moveit_msgs::MoveItErrorCodes& error_code);

  MoveItErrorCode(int code = 0)  // NOLINT(google-explicit-constructor): converts from a code, as MoveIt's
  {
    val = code;
  }
  MoveItErrorCode(const moveit_msgs::MoveItErrorCodes& code)  // NOLINT(google-explicit-constructor)
  {
    val = code.val;
  }
  explicit operator bool() const
  {
    return val == moveit_msgs::MoveItErrorCodes::SUCCESS;
  }
  explicit operator std::string() const
  {
    return toString(*this);
  }
  bool operator==(const int c) const
  {
    return val == c;
  }
  bool operator!=(const int c) const
  {
    return val != c;
  }
};

std::ostream& operator<<(std::ostream& out, const MoveItErrorCode& e);
}  // namespace core
}  // namespace moveit

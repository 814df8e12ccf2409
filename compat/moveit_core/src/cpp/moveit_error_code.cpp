#include <moveit/utils/moveit_error_code.h>

namespace moveit
{
namespace core
{
const char* MoveItErrorCode::toString(const moveit_msgs::MoveItErrorCodes& error_code)
{
  using Codes = moveit_msgs::MoveItErrorCodes;
  switch (error_code.val)
  {
    case 0:
      return "NOT INITIALIZED";
    case Codes::SUCCESS:
      return "SUCCESS";
    case Codes::FAILURE:
      return "FAILURE";
    case Codes::PLANNING_FAILED:
      return "PLANNING_FAILED";
    case Codes::INVALID_MOTION_PLAN:
      return "INVALID_MOTION_PLAN";
    case Codes::MOTION_PLAN_INVALIDATED_BY_ENVIRONMENT_CHANGE:
      return "MOTION_PLAN_INVALIDATED_BY_ENVIRONMENT_CHANGE";
    case Codes::CONTROL_FAILED:
      return "CONTROL_FAILED";
    case Codes::UNABLE_TO_AQUIRE_SENSOR_DATA:
      return "UNABLE_TO_AQUIRE_SENSOR_DATA";
    case Codes::TIMED_OUT:
      return "TIMED_OUT";
    case Codes::PREEMPTED:
      return "PREEMPTED";
    case Codes::START_STATE_IN_COLLISION:
      return "START_STATE_IN_COLLISION";
    case Codes::START_STATE_VIOLATES_PATH_CONSTRAINTS:
      return "START_STATE_VIOLATES_PATH_CONSTRAINTS";
    case Codes::GOAL_IN_COLLISION:
      return "GOAL_IN_COLLISION";
    case Codes::GOAL_VIOLATES_PATH_CONSTRAINTS:
      return "GOAL_VIOLATES_PATH_CONSTRAINTS";
    case Codes::GOAL_CONSTRAINTS_VIOLATED:
      return "GOAL_CONSTRAINTS_VIOLATED";
    case Codes::INVALID_GROUP_NAME:
      return "INVALID_GROUP_NAME";
    case Codes::INVALID_GOAL_CONSTRAINTS:
      return "INVALID_GOAL_CONSTRAINTS";
    case Codes::INVALID_ROBOT_STATE:
      return "INVALID_ROBOT_STATE";
    case Codes::INVALID_LINK_NAME:
      return "INVALID_LINK_NAME";
    case Codes::INVALID_OBJECT_NAME:
      return "INVALID_OBJECT_NAME";
    case Codes::FRAME_TRANSFORM_FAILURE:
      return "FRAME_TRANSFORM_FAILURE";
    case Codes::COLLISION_CHECKING_UNAVAILABLE:
      return "COLLISION_CHECKING_UNAVAILABLE";
    case Codes::ROBOT_STATE_STALE:
      return "ROBOT_STATE_STALE";
    case Codes::SENSOR_INFO_STALE:
      return "SENSOR_INFO_STALE";
    case Codes::COMMUNICATION_FAILURE:
      return "COMMUNICATION_FAILURE";
    case Codes::NO_IK_SOLUTION:
      return "NO_IK_SOLUTION";
    default:
      return "UNKNOWN";
  }
}

std::ostream& operator<<(std::ostream& out, const MoveItErrorCode& e)
{
  return out << MoveItErrorCode::toString(e);
}
}  // namespace core
}  // namespace moveit

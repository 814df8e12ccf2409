// moveit::core::MoveItErrorCode as MoveIt's (moveit_error_code.h, noetic-devel 7c0343f0): true only for SUCCESS,
// compares with codes, prints the code's name; planning_interface::MoveItErrorCode is the same class. Linked into
// the rostest's checking node (test/rostest/move_group_interface_check.cpp), whose main runs them.
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <moveit/move_group_interface/move_group_interface.h>

using moveit::core::MoveItErrorCode;
using Codes = moveit_msgs::MoveItErrorCodes;

TEST(MoveItErrorCode, IsTrueOnlyForSuccess)
{
  EXPECT_TRUE(static_cast<bool>(MoveItErrorCode(Codes::SUCCESS)));
  for (int code : { 0, static_cast<int>(Codes::FAILURE), static_cast<int>(Codes::PLANNING_FAILED),
                    static_cast<int>(Codes::NO_IK_SOLUTION), static_cast<int>(Codes::PREEMPTED) })
    EXPECT_FALSE(static_cast<bool>(MoveItErrorCode(code))) << code;
}

TEST(MoveItErrorCode, ComparesWithCodes)
{
  Codes message;
  message.val = Codes::PLANNING_FAILED;
  const MoveItErrorCode code(message);
  EXPECT_TRUE(code == Codes::PLANNING_FAILED);
  EXPECT_FALSE(code == Codes::SUCCESS);
  EXPECT_TRUE(code != Codes::SUCCESS);
  EXPECT_EQ(code.val, -1);
  // the default is 0, which is no code at all
  EXPECT_EQ(MoveItErrorCode().val, 0);
}

TEST(MoveItErrorCode, NamesItsCode)
{
  EXPECT_STREQ(MoveItErrorCode::toString(MoveItErrorCode(Codes::SUCCESS)), "SUCCESS");
  EXPECT_STREQ(MoveItErrorCode::toString(MoveItErrorCode(Codes::GOAL_IN_COLLISION)), "GOAL_IN_COLLISION");
  EXPECT_STREQ(MoveItErrorCode::toString(MoveItErrorCode(Codes::NO_IK_SOLUTION)), "NO_IK_SOLUTION");
  EXPECT_STREQ(MoveItErrorCode::toString(MoveItErrorCode()), "NOT INITIALIZED");
  EXPECT_STREQ(MoveItErrorCode::toString(MoveItErrorCode(12345)), "UNKNOWN");
  std::ostringstream out;
  out << MoveItErrorCode(Codes::TIMED_OUT);
  EXPECT_EQ(out.str(), "TIMED_OUT");
  EXPECT_EQ(static_cast<std::string>(MoveItErrorCode(Codes::COMMUNICATION_FAILURE)), "COMMUNICATION_FAILURE");
}

TEST(MoveItErrorCode, OldNameIsTheSameClass)
{
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
  const moveit::planning_interface::MoveItErrorCode code = moveit::core::MoveItErrorCode(Codes::SUCCESS);
#pragma GCC diagnostic pop
  EXPECT_TRUE(static_cast<bool>(code));
  // a Plan starts empty
  EXPECT_TRUE(moveit::planning_interface::MoveGroupInterface::Plan().trajectory_.joint_trajectory.points.empty());
}

// robot_trajectory::RobotTrajectory against MoveIt noetic-devel's semantics (robot_trajectory.cpp), on the six-axis
// fixture arm (test/data) and the px100 with its continuous gripper joint: a moveit_msgs::RobotTrajectory as
// move_group returns it set over a reference state and written back (positions, velocities, accelerations, efforts,
// times; joints outside the group kept from the reference); durations between stamps and from the start; the
// joint filter; suffix, prefix, insert, append, reverse (velocities negated, durations between the same waypoints),
// clear, copies shallow and deep; unwind of a continuous joint; the state at a time as the linear blend of its two
// waypoints; path_length as the sum of joint-space distances. IterativeParabolicTimeParameterization against the
// Python move_group's timing of the same path (iptp_expected.py: compat/moveit_core's time_parameterization, checked
// against upstream's loops) and against the limits themselves.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <memory>
#include <sstream>

#include <moveit/robot_model/robot_model.h>
#include <moveit/robot_state/conversions.h>
#include <moveit/robot_state/robot_state.h>
#include <moveit/robot_trajectory/robot_trajectory.h>
#include <moveit/trajectory_processing/iterative_time_parameterization.h>
#include <moveit/trajectory_processing/trajectory_tools.h>
#include <urdf/model.h>

namespace
{
constexpr double EXACT = 1e-12;
const std::vector<std::string> ARM = { "shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                                       "wrist_1_joint",      "wrist_2_joint",       "wrist_3_joint" };
constexpr std::size_t POINTS = 5;
constexpr double STEP = 0.25;        // s between the points of the test trajectory
constexpr double STAMP = 100.0;      // s, the header stamp: durations are differences, the first one from it

std::string read(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

moveit::core::RobotModelPtr load(const std::string& urdf_name, const std::string& srdf_name)
{
  auto urdf = std::make_shared<urdf::Model>();
  if (!urdf->initString(read("data/" + urdf_name + ".urdf")))
    return nullptr;
  auto srdf = std::make_shared<srdf::Model>();
  if (!srdf->initString(*urdf, read("data/" + srdf_name + ".srdf")))
    return nullptr;
  return std::make_shared<moveit::core::RobotModel>(urdf, srdf);
}

// POINTS points of the arm: joint j at 0.1 * (i + 1) * (j + 1), velocities, accelerations and efforts distinct
moveit_msgs::RobotTrajectory armTrajectory()
{
  moveit_msgs::RobotTrajectory message;
  message.joint_trajectory.header.stamp = ros::Time(STAMP);
  message.joint_trajectory.joint_names = ARM;
  for (std::size_t i = 0; i < POINTS; ++i)
  {
    trajectory_msgs::JointTrajectoryPoint point;
    for (std::size_t j = 0; j < ARM.size(); ++j)
    {
      point.positions.push_back(0.1 * (i + 1) * (j + 1));
      point.velocities.push_back(0.01 * (i + 1) + j);
      point.accelerations.push_back(-0.02 * (i + 1) - j);
      point.effort.push_back(0.5 * j);
    }
    // uneven steps: the second segment is twice as long
    point.time_from_start = ros::Duration(STEP * i + (i >= 2 ? STEP : 0.0));
    message.joint_trajectory.points.push_back(point);
  }
  return message;
}

class ArmTrajectory : public ::testing::Test
{
protected:
  void SetUp() override
  {
    model_ = load("six_axis_arm", "six_axis_arm");
    ASSERT_TRUE(model_);
    reference_ = std::make_shared<moveit::core::RobotState>(model_);
    reference_->setToDefaultValues();
  }
  moveit::core::RobotModelPtr model_;
  moveit::core::RobotStatePtr reference_;
};
}  // namespace

TEST_F(ArmTrajectory, aMessageRoundTripsThroughTheTrajectory)
{
  const moveit_msgs::RobotTrajectory message = armTrajectory();
  robot_trajectory::RobotTrajectory trajectory(model_, "manipulator");
  EXPECT_EQ(trajectory.getGroupName(), "manipulator");
  EXPECT_TRUE(trajectory.empty());
  trajectory.setRobotTrajectoryMsg(*reference_, message);
  ASSERT_EQ(trajectory.getWayPointCount(), POINTS);
  // the first duration is from the header stamp; each next one the difference of time_from_start
  EXPECT_NEAR(trajectory.getWayPointDurationFromPrevious(0), 0.0, EXACT);
  EXPECT_NEAR(trajectory.getWayPointDurationFromPrevious(2), 2 * STEP, 1e-9);
  EXPECT_NEAR(trajectory.getDuration(), STEP * (POINTS - 1) + STEP, 1e-9);
  EXPECT_NEAR(trajectory.getWayPointDurationFromStart(3), 4 * STEP, 1e-9);
  EXPECT_NEAR(trajectory.getWayPointDurationFromStart(99), trajectory.getDuration(), EXACT);   // past the end
  EXPECT_NEAR(trajectory.getAverageSegmentDuration(), trajectory.getDuration() / POINTS, EXACT);
  for (std::size_t i = 0; i < POINTS; ++i)
    for (std::size_t j = 0; j < ARM.size(); ++j)
      EXPECT_NEAR(trajectory.getWayPoint(i).getVariablePosition(ARM[j]), 0.1 * (i + 1) * (j + 1), EXACT);
  EXPECT_NEAR(trajectory.getLastWayPoint().getVariablePosition("elbow_joint"), 1.5, EXACT);
  EXPECT_NEAR(trajectory.getFirstWayPoint().getVariablePosition("elbow_joint"), 0.3, EXACT);

  moveit_msgs::RobotTrajectory back;
  trajectory.getRobotTrajectoryMsg(back);
  EXPECT_EQ(back.joint_trajectory.joint_names, ARM);
  EXPECT_EQ(back.joint_trajectory.header.frame_id, model_->getModelFrame());
  ASSERT_EQ(back.joint_trajectory.points.size(), POINTS);
  for (std::size_t i = 0; i < POINTS; ++i)
  {
    const auto& a = message.joint_trajectory.points[i];
    const auto& b = back.joint_trajectory.points[i];
    for (std::size_t j = 0; j < ARM.size(); ++j)
    {
      EXPECT_NEAR(a.positions[j], b.positions[j], EXACT);
      EXPECT_NEAR(a.velocities[j], b.velocities[j], EXACT);
      EXPECT_NEAR(a.accelerations[j], b.accelerations[j], EXACT);
      EXPECT_NEAR(a.effort[j], b.effort[j], EXACT);
    }
    EXPECT_NEAR(a.time_from_start.toSec(), b.time_from_start.toSec(), 1e-9);
  }
  // the joint filter keeps the named joints, in the group's order
  trajectory.getRobotTrajectoryMsg(back, { "wrist_1_joint", "shoulder_pan_joint" });
  EXPECT_EQ(back.joint_trajectory.joint_names, std::vector<std::string>({ "shoulder_pan_joint", "wrist_1_joint" }));
  EXPECT_NEAR(back.joint_trajectory.points[1].positions[1], 0.2 * 4, EXACT);
}

TEST_F(ArmTrajectory, aPointNamingSomeJointsKeepsTheReferenceForTheOthers)
{
  moveit_msgs::RobotTrajectory message;
  message.joint_trajectory.joint_names = { "elbow_joint" };
  trajectory_msgs::JointTrajectoryPoint point;
  point.positions = { 0.7 };
  message.joint_trajectory.points.push_back(point);
  reference_->setVariablePosition("wrist_2_joint", 0.4);
  robot_trajectory::RobotTrajectory trajectory(model_);
  EXPECT_EQ(trajectory.getGroupName(), "");
  trajectory.setRobotTrajectoryMsg(*reference_, message);
  ASSERT_EQ(trajectory.getWayPointCount(), 1u);
  EXPECT_NEAR(trajectory.getWayPoint(0).getVariablePosition("elbow_joint"), 0.7, EXACT);
  EXPECT_NEAR(trajectory.getWayPoint(0).getVariablePosition("wrist_2_joint"), 0.4, EXACT);
  // no velocities given: none written back (an incomplete set is dropped)
  moveit_msgs::RobotTrajectory back;
  trajectory.getRobotTrajectoryMsg(back);
  EXPECT_EQ(back.joint_trajectory.joint_names.size(), ARM.size());
  EXPECT_TRUE(back.joint_trajectory.points[0].velocities.empty());
  EXPECT_TRUE(back.joint_trajectory.points[0].accelerations.empty());
  // the start state given as a message goes over the reference first
  moveit_msgs::RobotState start;
  start.joint_state.name = { "wrist_3_joint" };
  start.joint_state.position = { -0.9 };
  trajectory.setRobotTrajectoryMsg(*reference_, start, message);
  EXPECT_NEAR(trajectory.getWayPoint(0).getVariablePosition("wrist_3_joint"), -0.9, EXACT);
}

TEST_F(ArmTrajectory, waypointsAreAddedInsertedAppendedAndCleared)
{
  robot_trajectory::RobotTrajectory trajectory(model_, "manipulator");
  auto state = std::make_shared<moveit::core::RobotState>(*reference_);
  state->setVariablePosition("elbow_joint", 1.0);
  trajectory.addSuffixWayPoint(*reference_, 0.0).addSuffixWayPoint(state, 0.5);
  auto first = std::make_shared<moveit::core::RobotState>(*reference_);
  first->setVariablePosition("elbow_joint", -1.0);
  trajectory.addPrefixWayPoint(first, 0.0);
  trajectory.setWayPointDurationFromPrevious(1, 0.3);
  ASSERT_EQ(trajectory.getWayPointCount(), 3u);
  EXPECT_NEAR(trajectory.getFirstWayPoint().getVariablePosition("elbow_joint"), -1.0, EXACT);
  EXPECT_NEAR(trajectory.getDuration(), 0.8, EXACT);
  auto middle = std::make_shared<moveit::core::RobotState>(*reference_);
  middle->setVariablePosition("elbow_joint", 0.5);
  trajectory.insertWayPoint(2, middle, 0.1);
  EXPECT_NEAR(trajectory.getWayPoint(2).getVariablePosition("elbow_joint"), 0.5, EXACT);
  EXPECT_NEAR(trajectory.getWayPointDurationFromStart(2), 0.4, EXACT);
  // waypoints are shared by pointer; a deep copy owns its own
  EXPECT_EQ(trajectory.getLastWayPointPtr(), state);
  robot_trajectory::RobotTrajectory shallow(trajectory);
  robot_trajectory::RobotTrajectory deep(trajectory, true);
  state->setVariablePosition("elbow_joint", 2.0);
  EXPECT_NEAR(shallow.getLastWayPoint().getVariablePosition("elbow_joint"), 2.0, EXACT);
  EXPECT_NEAR(deep.getLastWayPoint().getVariablePosition("elbow_joint"), 1.0, EXACT);
  // append [1, 3) of deep with 0.2 s added to its first duration
  trajectory.append(deep, 0.2, 1, 3);
  ASSERT_EQ(trajectory.getWayPointCount(), 6u);
  EXPECT_NEAR(trajectory.getWayPointDurationFromPrevious(4), 0.3 + 0.2, EXACT);
  EXPECT_NEAR(trajectory.getWayPoint(5).getVariablePosition("elbow_joint"), 0.5, EXACT);
  trajectory.swap(deep);
  EXPECT_EQ(trajectory.getWayPointCount(), 4u);
  EXPECT_EQ(deep.getWayPointCount(), 6u);
  trajectory.clear();
  EXPECT_TRUE(trajectory.empty());
  EXPECT_NEAR(trajectory.getDuration(), 0.0, EXACT);
  moveit_msgs::RobotTrajectory none;
  trajectory.getRobotTrajectoryMsg(none);
  EXPECT_TRUE(none.joint_trajectory.joint_names.empty());
}

TEST_F(ArmTrajectory, reverseNegatesVelocitiesAndKeepsEachDurationBetweenItsWaypoints)
{
  robot_trajectory::RobotTrajectory trajectory(model_, "manipulator");
  trajectory.setRobotTrajectoryMsg(*reference_, armTrajectory());
  const double duration = trajectory.getDuration();
  std::vector<double> durations(trajectory.getWayPointDurations().begin(), trajectory.getWayPointDurations().end());
  trajectory.reverse();
  EXPECT_NEAR(trajectory.getDuration(), duration, 1e-9);
  for (std::size_t i = 0; i < POINTS; ++i)
  {
    const int j = static_cast<int>(POINTS - 1 - i);
    EXPECT_NEAR(trajectory.getWayPoint(i).getVariablePosition("elbow_joint"), 0.3 * (j + 1), EXACT);
    const int elbow = model_->getVariableIndex("elbow_joint");
    EXPECT_NEAR(trajectory.getWayPoint(i).getVariableVelocity(elbow), -(0.01 * (j + 1) + 2), EXACT);
  }
  // the segment that took 2 STEP (between points 1 and 2) lies between reversed points 2 and 3
  EXPECT_NEAR(trajectory.getWayPointDurationFromPrevious(3), durations[2], EXACT);
  EXPECT_NEAR(trajectory.getWayPointDurationFromPrevious(0), durations[0], EXACT);
}

TEST_F(ArmTrajectory, theStateAtATimeBlendsItsTwoWaypointsAndPathLengthSumsDistances)
{
  robot_trajectory::RobotTrajectory trajectory(model_, "manipulator");
  trajectory.setRobotTrajectoryMsg(*reference_, armTrajectory());
  auto state = std::make_shared<moveit::core::RobotState>(*reference_);
  // 0.5 s is halfway through the long segment from point 1 (0.25 s) to point 2 (0.75 s)
  ASSERT_TRUE(trajectory.getStateAtDurationFromStart(0.5, state));
  for (std::size_t j = 0; j < ARM.size(); ++j)
    EXPECT_NEAR(state->getVariablePosition(ARM[j]), 0.5 * (0.2 + 0.3) * (j + 1), 1e-9);
  int before = -1, after = -1;
  double blend = -1.0;
  trajectory.findWayPointIndicesForDurationAfterStart(0.5, before, after, blend);
  EXPECT_EQ(before, 1);
  EXPECT_EQ(after, 2);
  EXPECT_NEAR(blend, 0.5, 1e-9);
  trajectory.findWayPointIndicesForDurationAfterStart(-1.0, before, after, blend);
  EXPECT_EQ(before, 0);
  EXPECT_EQ(after, 0);
  // past the end: the last waypoint
  ASSERT_TRUE(trajectory.getStateAtDurationFromStart(10.0, state));
  EXPECT_NEAR(state->getVariablePosition("wrist_3_joint"), 0.1 * POINTS * 6, 1e-9);
  // consecutive points differ by 0.1 * (j + 1) in joint j; RobotState::distance sums the joints' distances (upstream's
  // robot_state.cpp distance: each active joint's, added), so each segment is 0.1 * (1 + ... + 6)
  const double segment = 0.1 * (1 + 2 + 3 + 4 + 5 + 6);
  EXPECT_NEAR(robot_trajectory::path_length(trajectory), segment * (POINTS - 1), 1e-9);
  robot_trajectory::RobotTrajectory none(model_);
  EXPECT_FALSE(none.getStateAtDurationFromStart(0.0, state));
}

TEST(ContinuousTrajectory, unwindMakesAContinuousJointContinuous)
{
  moveit::core::RobotModelPtr model = load("interbotix_px100_gazebo", "interbotix_px100");
  ASSERT_TRUE(model);
  const moveit::core::JointModel* gripper = model->getJointModel("gripper");
  ASSERT_TRUE(gripper);
  ASSERT_EQ(model->getContinuousJointModels().size(), 1u);
  moveit::core::RobotState state(model);
  state.setToDefaultValues();
  robot_trajectory::RobotTrajectory trajectory(model);
  // turning on through +pi: 3.0, -3.0 (= 3.28), -2.0 (= 4.28)
  for (double value : { 3.0, -3.0, -2.0 })
  {
    state.setVariablePosition("gripper", value);
    trajectory.addSuffixWayPoint(state, 0.1);
  }
  trajectory.unwind();
  EXPECT_NEAR(trajectory.getWayPoint(0).getVariablePosition("gripper"), 3.0, EXACT);
  EXPECT_NEAR(trajectory.getWayPoint(1).getVariablePosition("gripper"), -3.0 + 2 * M_PI, EXACT);
  EXPECT_NEAR(trajectory.getWayPoint(2).getVariablePosition("gripper"), -2.0 + 2 * M_PI, EXACT);
  // from a state two turns on, the whole trajectory is two turns on
  robot_trajectory::RobotTrajectory again(model);
  for (double value : { 3.0, -3.0 })
  {
    state.setVariablePosition("gripper", value);
    again.addSuffixWayPoint(state, 0.1);
  }
  moveit::core::RobotState turned(model);
  turned.setToDefaultValues();
  turned.setVariablePosition("gripper", 3.0 + 4 * M_PI);
  again.unwind(turned);
  EXPECT_NEAR(again.getWayPoint(0).getVariablePosition("gripper"), 3.0 + 4 * M_PI, 1e-9);
  EXPECT_NEAR(again.getWayPoint(1).getVariablePosition("gripper"), -3.0 + 6 * M_PI, 1e-9);
}

namespace
{
// the Python timing of the waypoints (rows of the group's variables): times, then velocities and accelerations by
// waypoint
std::vector<std::vector<double>> pythonTiming(const moveit::core::JointModelGroup* group,
                                              const std::vector<std::vector<double>>& waypoints, double velocity_scaling,
                                              double acceleration_scaling)
{
  const std::string path = "/tmp/moveit_core_cpp_iptp_path.txt";
  {
    std::ofstream out(path);
    out << std::setprecision(17) << velocity_scaling << " " << acceleration_scaling << "\n";
    for (const std::string& variable : group->getVariableNames())
    {
      const moveit::core::VariableBounds& b = group->getParentModel().getVariableBounds(variable);
      out << (b.velocity_bounded_ ? b.max_velocity_ : 0.0) << " ";
    }
    out << "\n";
    for (const std::string& variable : group->getVariableNames())
    {
      const moveit::core::VariableBounds& b = group->getParentModel().getVariableBounds(variable);
      out << (b.acceleration_bounded_ ? b.max_acceleration_ : 0.0) << " ";
    }
    out << "\n";
    for (const auto& waypoint : waypoints)
    {
      for (double value : waypoint)
        out << value << " ";
      out << "\n";
    }
  }
  std::vector<std::vector<double>> rows;
  FILE* pipe = popen(("python3 cpp/iptp_expected.py " + path).c_str(), "r");
  if (!pipe)
    return rows;
  std::string text;
  char buffer[4096];
  while (fgets(buffer, sizeof(buffer), pipe))
    text += buffer;
  pclose(pipe);
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line))
  {
    std::istringstream numbers(line);
    std::vector<double> row;
    double x;
    while (numbers >> x)
      row.push_back(x);
    rows.push_back(row);
  }
  return rows;
}
}  // namespace

TEST_F(ArmTrajectory, iterativeParabolicTimingIsMoveGroupsAndKeepsTheLimits)
{
  // a path as a Cartesian plan gives it: many close waypoints, one long jump, a reversal
  const moveit::core::JointModelGroup* group = model_->getJointModelGroup("manipulator");
  ASSERT_TRUE(group);
  std::vector<std::vector<double>> waypoints;
  for (int i = 0; i < 12; ++i)
    waypoints.push_back({ 0.05 * i, -0.02 * i, 0.1 * std::sin(0.3 * i), 0.0, 0.4 * (i == 7 ? 1 : 0), 0.01 * i * i });
  const double velocity_scaling = 0.5;
  const double acceleration_scaling = 0.3;
  robot_trajectory::RobotTrajectory trajectory(model_, group);
  for (const auto& waypoint : waypoints)
  {
    moveit::core::RobotState state(*reference_);
    state.setJointGroupPositions(group, waypoint);
    trajectory.addSuffixWayPoint(state, 0.0);
  }
  trajectory_processing::IterativeParabolicTimeParameterization iptp;
  ASSERT_TRUE(iptp.computeTimeStamps(trajectory, velocity_scaling, acceleration_scaling));
  const std::vector<std::vector<double>> expected =
      pythonTiming(group, waypoints, velocity_scaling, acceleration_scaling);
  ASSERT_EQ(expected.size(), 1 + 2 * waypoints.size());
  const std::vector<int>& idx = group->getVariableIndexList();
  moveit_msgs::RobotTrajectory message;
  trajectory.getRobotTrajectoryMsg(message);
  ASSERT_EQ(message.joint_trajectory.points.size(), waypoints.size());
  for (std::size_t i = 0; i < waypoints.size(); ++i)
  {
    EXPECT_NEAR(trajectory.getWayPointDurationFromStart(i), expected[0][i], 1e-9) << "waypoint " << i;
    const auto& point = message.joint_trajectory.points[i];
    ASSERT_EQ(point.velocities.size(), idx.size());
    ASSERT_EQ(point.accelerations.size(), idx.size());
    for (std::size_t j = 0; j < idx.size(); ++j)
    {
      EXPECT_NEAR(trajectory.getWayPoint(i).getVariableVelocity(idx[j]), expected[1 + i][j], 1e-9);
      EXPECT_NEAR(point.velocities[j], expected[1 + i][j], 1e-9);
      // upstream asks the first waypoint for velocities per variable, after writing the first one's: its other
      // variables start at velocity 0 with acceleration 0 (iptp:277-292); the Python pipeline computes them all
      const double acceleration = i == 0 && j > 0 ? 0.0 : expected[1 + waypoints.size() + i][j];
      EXPECT_NEAR(point.accelerations[j], acceleration, 1e-9) << "waypoint " << i << " joint " << j;
    }
  }
  // the limits themselves: no segment faster than the scaled speed limit
  for (std::size_t i = 1; i < waypoints.size(); ++i)
    for (std::size_t j = 0; j < idx.size(); ++j)
    {
      const moveit::core::VariableBounds& b = model_->getVariableBounds(group->getVariableNames()[j]);
      const double limit = (b.velocity_bounded_ ? b.max_velocity_ : 1.0) * velocity_scaling;
      EXPECT_LE(std::fabs(waypoints[i][j] - waypoints[i - 1][j]) / trajectory.getWayPointDurationFromPrevious(i),
                limit + 1e-9);
    }
  // a trajectory without a group is refused; an empty one is trivially timed
  robot_trajectory::RobotTrajectory whole(model_);
  whole.addSuffixWayPoint(*reference_, 0.0).addSuffixWayPoint(*reference_, 0.0);
  EXPECT_FALSE(iptp.computeTimeStamps(whole));
  robot_trajectory::RobotTrajectory none(model_, group);
  EXPECT_TRUE(iptp.computeTimeStamps(none));
  EXPECT_TRUE(trajectory_processing::isTrajectoryEmpty(moveit_msgs::RobotTrajectory()));
  EXPECT_EQ(trajectory_processing::trajectoryWaypointCount(message), waypoints.size());
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}

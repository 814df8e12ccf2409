// moveit_core's C++ RobotModel, RobotState and conversions on the six-axis fixture arm and the px100 (test/data,
// copies of test/fixtures/moveit_ws's six_axis_arm and of compat/interbotix_xsarm_descriptions' px100):
// groups, variables and bounds against the SRDF and URDF; forward kinematics of every link against urdf_tools'
// Python FK (fk_expected.py) for 100 random states to 1e-9 m; setFromIK round trips (FK -> IK from another seed ->
// FK) for 100 random states to 1e-6 m; RobotState message round trips.
#include <gtest/gtest.h>

#include <cstdio>
#include <iomanip>
#include <fstream>
#include <memory>
#include <sstream>

#include <moveit/kinematic_constraints/utils.h>
#include <moveit/robot_model/robot_model.h>
#include <moveit/robot_state/conversions.h>
#include <moveit/robot_state/robot_state.h>
#include <urdf/model.h>

namespace
{
// The accuracies the brief asks for: FK against urdf_tools, IK round trip
constexpr double FK_TOLERANCE = 1e-9;
constexpr double IK_TOLERANCE = 1e-6;
constexpr int STATE_COUNT = 100;
// Seconds a single setFromIK may take on this 2-core machine
constexpr double IK_TIMEOUT = 2.0;
// Seeds for the random number generators: the same states on every run
constexpr unsigned int FK_SEED = 42;
constexpr unsigned int IK_SEED = 7;

std::string read(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

moveit::core::RobotModelPtr load(const std::string& name, urdf::ModelInterfaceSharedPtr* urdf_out = nullptr)
{
  auto urdf = std::make_shared<urdf::Model>();
  if (!urdf->initString(read("data/" + name + ".urdf")))
    return nullptr;
  auto srdf = std::make_shared<srdf::Model>();
  if (!srdf->initString(*urdf, read("data/" + name + ".srdf")))
    return nullptr;
  if (urdf_out)
    *urdf_out = urdf;
  return std::make_shared<moveit::core::RobotModel>(urdf, srdf);
}

void checkFK(const std::string& name)
{
  moveit::core::RobotModelPtr model = load(name);
  ASSERT_TRUE(model);
  random_numbers::RandomNumberGenerator rng(FK_SEED);
  std::vector<moveit::core::RobotState> states;
  const std::string states_path = "/tmp/moveit_core_cpp_fk_states_" + name + ".txt";
  const std::string links_path = "/tmp/moveit_core_cpp_fk_links_" + name + ".txt";
  {
    std::ofstream out(states_path);
    for (int i = 0; i < STATE_COUNT; ++i)
    {
      moveit::core::RobotState state(model);
      state.setToRandomPositions(rng);
      state.update();
      for (const moveit::core::JointModel* joint : model->getSingleDOFJointModels())
        out << joint->getName() << "=" << std::setprecision(17) << state.getVariablePosition(joint->getName())
            << " ";
      out << "\n";
      states.push_back(state);
    }
    std::ofstream links(links_path);
    for (const std::string& link : model->getLinkModelNames())
      links << link << "\n";
  }
  const std::string command = "python3 cpp/fk_expected.py data/" + name + ".urdf " + model->getRootLinkName() + " " +
                              states_path + " " + links_path;
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_TRUE(pipe);
  std::size_t compared = 0;
  double worst = 0.0;
  for (const moveit::core::RobotState& state : states)
    for (const moveit::core::LinkModel* link : model->getLinkModels())
    {
      double expected[12];
      for (double& v : expected)
        ASSERT_EQ(fscanf(pipe, "%lf", &v), 1) << "urdf_tools gave too few poses: " << command;
      const Eigen::Isometry3d root = state.getGlobalLinkTransform(model->getRootLink());
      const Eigen::Isometry3d pose = root.inverse() * state.getGlobalLinkTransform(link);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c)
        {
          const double got = c < 3 ? pose.linear()(r, c) : pose.translation()(r);
          worst = std::max(worst, std::fabs(got - expected[r * 4 + c]));
          EXPECT_NEAR(got, expected[r * 4 + c], FK_TOLERANCE) << name << " link " << link->getName();
        }
      ++compared;
    }
  EXPECT_EQ(pclose(pipe), 0);
  EXPECT_EQ(compared, STATE_COUNT * model->getLinkModelCount());
  std::cout << name << ": " << compared << " link poses, worst difference " << worst << std::endl;
}

void checkIK(const std::string& name, const std::string& group_name, const std::string& tip)
{
  moveit::core::RobotModelPtr model = load(name);
  ASSERT_TRUE(model);
  const moveit::core::JointModelGroup* group = model->getJointModelGroup(group_name);
  ASSERT_TRUE(group);
  random_numbers::RandomNumberGenerator rng(IK_SEED);
  int solved = 0;
  double worst = 0.0;
  for (int i = 0; i < STATE_COUNT; ++i)
  {
    moveit::core::RobotState goal(model);
    goal.setToDefaultValues();
    goal.setToRandomPositions(group, rng);
    goal.update();
    const Eigen::Isometry3d target = goal.getGlobalLinkTransform(tip);
    moveit::core::RobotState state(model);
    state.setToDefaultValues();
    state.setToRandomPositions(group, rng);
    ASSERT_TRUE(state.setFromIK(group, target, tip, IK_TIMEOUT)) << name << " state " << i;
    state.update();
    const Eigen::Isometry3d reached = state.getGlobalLinkTransform(tip);
    const double position_error = (reached.translation() - target.translation()).norm();
    const double angle_error = Eigen::AngleAxisd(reached.linear().transpose() * target.linear()).angle();
    worst = std::max(worst, position_error);
    EXPECT_LT(position_error, IK_TOLERANCE) << name << " state " << i;
    EXPECT_LT(angle_error, IK_TOLERANCE) << name << " state " << i;
    EXPECT_TRUE(state.satisfiesBounds(group));
    ++solved;
  }
  EXPECT_EQ(solved, STATE_COUNT);
  std::cout << name << ": " << solved << " IK round trips, worst position error " << worst << " m" << std::endl;
}
}  // namespace

TEST(RobotModel, SixAxisArmGroupsAgainstSrdfAndUrdf)
{
  urdf::ModelInterfaceSharedPtr urdf;
  moveit::core::RobotModelPtr model = load("six_axis_arm", &urdf);
  ASSERT_TRUE(model);
  EXPECT_EQ(model->getName(), urdf->getName());
  // The fixture's URDF has its own root link "world" (fixed to base_link): the SRDF's virtual joint to base_link is
  // skipped, as MoveIt skips a virtual joint whose child is not the URDF's root (robot_model.cpp, noetic-devel)
  EXPECT_EQ(model->getRootLinkName(), urdf->getRoot()->name);
  EXPECT_EQ(model->getModelFrame(), urdf->getRoot()->name);
  EXPECT_EQ(model->getRootJointName(), "ASSUMED_FIXED_ROOT_JOINT");
  const std::vector<std::string> expected_groups = { "manipulator", "wrist", "arm_by_parts" };
  for (const std::string& g : expected_groups)
    EXPECT_TRUE(model->hasJointModelGroup(g)) << g;
  const moveit::core::JointModelGroup* arm = model->getJointModelGroup("manipulator");
  ASSERT_TRUE(arm);
  const std::vector<std::string> joints = { "shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                                            "wrist_1_joint",      "wrist_2_joint",       "wrist_3_joint" };
  EXPECT_EQ(arm->getActiveJointModelNames(), joints);
  EXPECT_EQ(arm->getVariableNames(), joints);
  EXPECT_EQ(arm->getVariableCount(), joints.size());
  EXPECT_TRUE(arm->isChain());
  EXPECT_TRUE(arm->hasLinkModel("tool0"));
  for (const std::string& j : joints)
  {
    const urdf::JointConstSharedPtr uj = urdf->getJoint(j);
    const moveit::core::VariableBounds& b = model->getVariableBounds(j);
    if (uj->type == urdf::Joint::CONTINUOUS)
      EXPECT_FALSE(b.position_bounded_) << j;
    else
    {
      EXPECT_DOUBLE_EQ(b.min_position_, uj->limits->lower) << j;
      EXPECT_DOUBLE_EQ(b.max_position_, uj->limits->upper) << j;
    }
    EXPECT_DOUBLE_EQ(b.max_velocity_, uj->limits->velocity) << j;
  }
  const moveit::core::JointModelGroup* parts = model->getJointModelGroup("arm_by_parts");
  ASSERT_TRUE(parts);
  EXPECT_EQ(parts->getVariableNames(), joints);
  EXPECT_TRUE(parts->isSubgroup("wrist"));
  std::map<std::string, double> ready;
  ASSERT_TRUE(arm->getVariableDefaultPositions("ready", ready));
  EXPECT_DOUBLE_EQ(ready["shoulder_lift_joint"], 0.4);
  EXPECT_DOUBLE_EQ(ready["elbow_joint"], 0.8);
  EXPECT_FALSE(arm->getVariableDefaultPositions("no_such_state", ready));
  moveit::core::RobotState state(model);
  state.setToDefaultValues();
  ASSERT_TRUE(state.setToDefaultValues(arm, "ready"));
  EXPECT_DOUBLE_EQ(state.getVariablePosition("wrist_1_joint"), 0.3);
}

// The link that moves a frame: up across fixed joints, and given a group with joints, across the joints the group does
// not move (robot_model.cpp l. 1280-1315 on noetic-devel). The chain group "manipulator" holds tool0's fixed joint:
// tool0 still goes up to wrist_3_link; the group "wrist" moves none of forearm_link's parent joints: up to the root.
TEST(RobotModel, RigidlyConnectedParentLinks)
{
  moveit::core::RobotModelPtr model = load("six_axis_arm", nullptr);
  ASSERT_TRUE(model);
  const moveit::core::LinkModel* tool = model->getLinkModel("tool0");
  Eigen::Isometry3d to_parent;
  const moveit::core::LinkModel* parent = moveit::core::RobotModel::getRigidlyConnectedParentLinkModel(
      tool, to_parent, model->getJointModelGroup("manipulator"));
  ASSERT_TRUE(parent);
  EXPECT_EQ(parent->getName(), "wrist_3_link");
  EXPECT_TRUE(to_parent.isApprox(tool->getJointOriginTransform()));
  EXPECT_EQ(moveit::core::RobotModel::getRigidlyConnectedParentLinkModel(tool, to_parent)->getName(), "wrist_3_link");
  const moveit::core::LinkModel* above = moveit::core::RobotModel::getRigidlyConnectedParentLinkModel(
      model->getLinkModel("forearm_link"), to_parent, model->getJointModelGroup("wrist"));
  ASSERT_TRUE(above);
  EXPECT_EQ(above->getName(), model->getRootLinkName());
}

TEST(RobotModel, Px100GroupsAndEndEffector)
{
  urdf::ModelInterfaceSharedPtr urdf;
  moveit::core::RobotModelPtr model = load("px100", &urdf);
  ASSERT_TRUE(model);
  model->printModelInfo(std::cout);
  ASSERT_TRUE(model->hasJointModelGroup("interbotix_arm"));
  const moveit::core::JointModelGroup* arm = model->getJointModelGroup("interbotix_arm");
  EXPECT_EQ(arm->getVariableCount(), 4u);
  EXPECT_TRUE(arm->isChain());
  for (const std::string& v : arm->getVariableNames())
  {
    const moveit::core::VariableBounds& b = model->getVariableBounds(v);
    EXPECT_DOUBLE_EQ(b.min_position_, urdf->getJoint(v)->limits->lower) << v;
    EXPECT_DOUBLE_EQ(b.max_position_, urdf->getJoint(v)->limits->upper) << v;
  }
  EXPECT_FALSE(model->getEndEffectors().empty());
  std::vector<std::string> tips;
  arm->getEndEffectorTips(tips);
  EXPECT_EQ(tips.size(), 1u);
}

TEST(RobotState, ForwardKinematicsMatchesUrdfTools)
{
  checkFK("six_axis_arm");
  checkFK("px100");
}

TEST(RobotState, SetFromIKRoundTrip)
{
  checkIK("six_axis_arm", "manipulator", "tool0");
  moveit::core::RobotModelPtr px100 = load("px100");
  ASSERT_TRUE(px100);
  std::vector<std::string> tips;
  px100->getJointModelGroup("interbotix_arm")->getEndEffectorTips(tips);
  ASSERT_EQ(tips.size(), 1u);
  checkIK("px100", "interbotix_arm", tips.front());
}

TEST(RobotState, MessageRoundTripAndBounds)
{
  moveit::core::RobotModelPtr model = load("six_axis_arm");
  ASSERT_TRUE(model);
  random_numbers::RandomNumberGenerator rng(FK_SEED);
  for (int i = 0; i < STATE_COUNT; ++i)
  {
    moveit::core::RobotState a(model);
    a.setToRandomPositions(rng);
    EXPECT_TRUE(a.satisfiesBounds());
    moveit_msgs::RobotState msg;
    moveit::core::robotStateToRobotStateMsg(a, msg);
    EXPECT_EQ(msg.joint_state.name.size(), model->getSingleDOFJointModels().size());
    moveit::core::RobotState b(model);
    b.setToDefaultValues();
    ASSERT_TRUE(moveit::core::robotStateMsgToRobotState(msg, b));
    for (std::size_t v = 0; v < model->getVariableCount(); ++v)
      EXPECT_DOUBLE_EQ(a.getVariablePosition(v), b.getVariablePosition(v));
  }
  moveit::core::RobotState s(model);
  s.setToDefaultValues();
  const moveit::core::VariableBounds& b = model->getVariableBounds("elbow_joint");
  s.setVariablePosition("elbow_joint", b.max_position_ + 1.0);
  EXPECT_FALSE(s.satisfiesBounds());
  s.enforceBounds();
  EXPECT_TRUE(s.satisfiesBounds());
  EXPECT_DOUBLE_EQ(s.getVariablePosition("elbow_joint"), b.max_position_);
}

TEST(KinematicConstraints, GoalConstraintsFromStateAndPose)
{
  moveit::core::RobotModelPtr model = load("six_axis_arm");
  ASSERT_TRUE(model);
  moveit::core::RobotState state(model);
  state.setToDefaultValues();
  state.setToDefaultValues("manipulator", "ready");
  const moveit::core::JointModelGroup* arm = model->getJointModelGroup("manipulator");
  const moveit_msgs::Constraints joint_goal = kinematic_constraints::constructGoalConstraints(state, arm, 0.01);
  ASSERT_EQ(joint_goal.joint_constraints.size(), 6u);
  EXPECT_EQ(joint_goal.joint_constraints[2].joint_name, "elbow_joint");
  EXPECT_DOUBLE_EQ(joint_goal.joint_constraints[2].position, 0.8);
  geometry_msgs::PoseStamped pose;
  pose.header.frame_id = "world";
  pose.pose.position.x = 0.3;
  pose.pose.orientation.w = 1.0;
  const moveit_msgs::Constraints pose_goal = kinematic_constraints::constructGoalConstraints("tool0", pose, 0.002, 0.02);
  ASSERT_EQ(pose_goal.position_constraints.size(), 1u);
  ASSERT_EQ(pose_goal.orientation_constraints.size(), 1u);
  EXPECT_DOUBLE_EQ(pose_goal.position_constraints[0].constraint_region.primitives[0].dimensions[0], 0.002);
  EXPECT_DOUBLE_EQ(pose_goal.orientation_constraints[0].absolute_z_axis_tolerance, 0.02);
  EXPECT_EQ(kinematic_constraints::countIndividualConstraints(pose_goal), 2u);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}

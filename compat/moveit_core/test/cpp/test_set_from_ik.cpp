// RobotState::setFromIK's two paths on the six-axis fixture arm (test/data):
// - no solver allocated for the group (getSolverInstance() null): the KDL fallback still answers, the tip's FK within
//   1e-6 of the pose (the model's FK is checked against urdf_tools' in test_robot_model), and the validity callback
//   can refuse every solution;
// - a solver installed with setSolverAllocators (a recording stub with its joints in reverse order, so that the
//   bijection matters): setFromIK calls it as robot_state.cpp's setFromIK does on noetic-devel (l. 1603-1832): the pose
//   in the solver's base frame at the current state, a frame rigidly attached to the solver's tip turned into the
//   tip's pose, the seed from the state in the solver's order, the group's default timeout when none is given, the
//   consistency limits passed on, the validity callback seeing the group's order, and the answer set through the
//   bijection.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <memory>
#include <sstream>

#include <moveit/robot_model/robot_model.h>
#include <moveit/robot_state/robot_state.h>
#include <urdf/model.h>

namespace
{
constexpr double IK_TOLERANCE = 1e-6;     // m and rad: the fallback's promise
constexpr double SAME = 1e-12;            // values passed through unchanged
constexpr int ROUND_TRIPS = 20;
constexpr double KDL_TIMEOUT = 2.0;       // s, generous on a shared 2-core machine
constexpr double GROUP_TIMEOUT = 0.123;   // s: a kinematics_solver_timeout
constexpr double SEARCH_RESOLUTION = 0.01;
constexpr unsigned int SEED = 11;
const char GROUP[] = "manipulator";
// the stub solves from the shoulder, so that the base frame's transform depends on the state
const char STUB_BASE[] = "shoulder_link";
const char STUB_TIP[] = "wrist_3_link";
const char ATTACHED_TIP[] = "tool0";  // fixed to wrist_3_link

std::string read(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

moveit::core::RobotModelPtr loadArm()
{
  auto urdf = std::make_shared<urdf::Model>();
  if (!urdf->initString(read("data/six_axis_arm.urdf")))
    return nullptr;
  auto srdf = std::make_shared<srdf::Model>();
  if (!srdf->initString(*urdf, read("data/six_axis_arm.srdf")))
    return nullptr;
  return std::make_shared<moveit::core::RobotModel>(urdf, srdf);
}

Eigen::Isometry3d toEigen(const geometry_msgs::Pose& p)
{
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
  t.linear() = Eigen::Quaterniond(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z)
                   .normalized()
                   .toRotationMatrix();
  return t;
}

void expectSamePose(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, double tolerance)
{
  EXPECT_LT((a.translation() - b.translation()).norm(), tolerance);
  EXPECT_LT(Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle(), tolerance);
}

// Records what it is asked and answers `answer` (its own joint order) after the solution callback accepts it
class RecordingSolver : public kinematics::KinematicsBase
{
public:
  bool initialize(const moveit::core::RobotModel& model, const std::string& group, const std::string& base,
                  const std::vector<std::string>& tips, double search_resolution) override
  {
    storeValues(model, group, base, tips, search_resolution);
    names_ = model.getJointModelGroup(group)->getVariableNames();
    std::reverse(names_.begin(), names_.end());
    return true;
  }
  bool getPositionIK(const geometry_msgs::Pose&, const std::vector<double>&, std::vector<double>&,
                     moveit_msgs::MoveItErrorCodes&, const kinematics::KinematicsQueryOptions&) const override
  {
    return false;
  }
  bool searchPositionIK(const geometry_msgs::Pose& pose, const std::vector<double>& seed, double timeout,
                        std::vector<double>& solution, moveit_msgs::MoveItErrorCodes& code,
                        const kinematics::KinematicsQueryOptions& options) const override
  {
    return searchPositionIK(pose, seed, timeout, std::vector<double>(), solution, IKCallbackFn(), code, options);
  }
  bool searchPositionIK(const geometry_msgs::Pose& pose, const std::vector<double>& seed, double timeout,
                        const std::vector<double>& limits, std::vector<double>& solution,
                        moveit_msgs::MoveItErrorCodes& code,
                        const kinematics::KinematicsQueryOptions& options) const override
  {
    return searchPositionIK(pose, seed, timeout, limits, solution, IKCallbackFn(), code, options);
  }
  bool searchPositionIK(const geometry_msgs::Pose& pose, const std::vector<double>& seed, double timeout,
                        std::vector<double>& solution, const IKCallbackFn& callback,
                        moveit_msgs::MoveItErrorCodes& code,
                        const kinematics::KinematicsQueryOptions& options) const override
  {
    return searchPositionIK(pose, seed, timeout, std::vector<double>(), solution, callback, code, options);
  }
  bool searchPositionIK(const geometry_msgs::Pose& pose, const std::vector<double>& seed, double timeout,
                        const std::vector<double>& limits, std::vector<double>& solution,
                        const IKCallbackFn& callback, moveit_msgs::MoveItErrorCodes& code,
                        const kinematics::KinematicsQueryOptions&) const override
  {
    ++calls;
    pose_ = pose;
    seed_ = seed;
    timeout_ = timeout;
    limits_ = limits;
    code.val = moveit_msgs::MoveItErrorCodes::SUCCESS;
    if (callback)
      callback(pose, answer, code);
    if (code.val != moveit_msgs::MoveItErrorCodes::SUCCESS)
      return false;
    solution = answer;
    return true;
  }
  bool getPositionFK(const std::vector<std::string>&, const std::vector<double>&,
                     std::vector<geometry_msgs::Pose>&) const override
  {
    return false;
  }
  const std::vector<std::string>& getJointNames() const override
  {
    return names_;
  }
  const std::vector<std::string>& getLinkNames() const override
  {
    return tip_frames_;
  }

  std::vector<double> answer;
  mutable int calls = 0;
  mutable geometry_msgs::Pose pose_;
  mutable std::vector<double> seed_, limits_;
  mutable double timeout_ = 0.0;

private:
  std::vector<std::string> names_;
};

// The stub installed in the group as RobotModelLoader installs a plugin
std::shared_ptr<RecordingSolver> installStub(const moveit::core::RobotModelPtr& model)
{
  auto stub = std::make_shared<RecordingSolver>();
  EXPECT_TRUE(stub->initialize(*model, GROUP, STUB_BASE, { STUB_TIP }, SEARCH_RESOLUTION));
  model->getJointModelGroup(GROUP)->setSolverAllocators(
      [stub](const moveit::core::JointModelGroup*) -> kinematics::KinematicsBasePtr { return stub; });
  model->getJointModelGroup(GROUP)->setDefaultIKTimeout(GROUP_TIMEOUT);
  return stub;
}
}  // namespace

TEST(SetFromIK, KdlFallbackWithoutASolver)
{
  moveit::core::RobotModelPtr model = loadArm();
  ASSERT_TRUE(model);
  const moveit::core::JointModelGroup* group = model->getJointModelGroup(GROUP);
  ASSERT_FALSE(group->getSolverInstance());
  random_numbers::RandomNumberGenerator rng(SEED);
  for (int i = 0; i < ROUND_TRIPS; ++i)
  {
    moveit::core::RobotState goal(model);
    goal.setToDefaultValues();
    goal.setToRandomPositions(group, rng);
    goal.update();
    const Eigen::Isometry3d target = goal.getGlobalLinkTransform(ATTACHED_TIP);
    moveit::core::RobotState state(model);
    state.setToDefaultValues();
    // no tip given: the group's end-effector tip, else its last link (tool0 here)
    ASSERT_TRUE(state.setFromIK(group, target, KDL_TIMEOUT)) << "state " << i;
    state.update();
    expectSamePose(state.getGlobalLinkTransform(ATTACHED_TIP), target, IK_TOLERANCE);
    EXPECT_TRUE(state.satisfiesBounds(group));
  }

  // a validity callback refusing everything: no answer, the state untouched
  moveit::core::RobotState goal(model);
  goal.setToDefaultValues();
  goal.setToRandomPositions(group, rng);
  goal.update();
  moveit::core::RobotState state(model);
  state.setToDefaultValues();
  const std::vector<double> before(state.getVariablePositions(),
                                   state.getVariablePositions() + model->getVariableCount());
  int asked = 0;
  const double short_timeout = 0.05;
  EXPECT_FALSE(state.setFromIK(group, goal.getGlobalLinkTransform(ATTACHED_TIP), ATTACHED_TIP, short_timeout,
                               [&asked](moveit::core::RobotState*, const moveit::core::JointModelGroup*,
                                        const double*) { return ++asked, false; }));
  EXPECT_GT(asked, 0);
  for (std::size_t i = 0; i < before.size(); ++i)
    EXPECT_EQ(state.getVariablePositions()[i], before[i]);
}

TEST(SetFromIK, CallsTheGroupsSolverAsMoveItDoes)
{
  moveit::core::RobotModelPtr model = loadArm();
  ASSERT_TRUE(model);
  std::shared_ptr<RecordingSolver> stub = installStub(model);
  const moveit::core::JointModelGroup* group = model->getJointModelGroup(GROUP);
  ASSERT_EQ(group->getSolverInstance().get(), stub.get());
  EXPECT_DOUBLE_EQ(stub->getDefaultTimeout(), GROUP_TIMEOUT);   // setDefaultIKTimeout reaches the solver
  ASSERT_EQ(group->getKinematicsSolverJointBijection().size(), group->getVariableCount());

  random_numbers::RandomNumberGenerator rng(SEED);
  moveit::core::RobotState state(model), answer_state(model);
  state.setToDefaultValues();
  state.setToRandomPositions(group, rng);
  state.update();
  answer_state.setToDefaultValues();
  answer_state.setToRandomPositions(group, rng);
  std::vector<double> current, wanted;
  state.copyJointGroupPositions(group, current);
  answer_state.copyJointGroupPositions(group, wanted);
  // the stub answers in its own (reversed) order
  stub->answer.assign(wanted.rbegin(), wanted.rend());

  // a pose of tool0, which is fixed to the stub's tip wrist_3_link
  Eigen::Isometry3d target = Eigen::Isometry3d::Identity();
  target.translation() = Eigen::Vector3d(0.3, -0.2, 0.5);
  target.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Isometry3d base = state.getGlobalLinkTransform(STUB_BASE);
  const Eigen::Isometry3d tool_in_wrist =
      state.getGlobalLinkTransform(STUB_TIP).inverse() * state.getGlobalLinkTransform(ATTACHED_TIP);
  const std::vector<double> limits = { 0.1, 0.2, 0.3, 0.4, 0.5, 0.6 };

  std::vector<double> seen;
  ASSERT_TRUE(state.setFromIK(group, target, ATTACHED_TIP, limits, 0.0,
                              [&seen, group](moveit::core::RobotState*, const moveit::core::JointModelGroup* g,
                                             const double* values) {
                                EXPECT_EQ(g, group);
                                seen.assign(values, values + g->getVariableCount());
                                return true;
                              }));
  EXPECT_EQ(stub->calls, 1);   // one search: no attempts of setFromIK's own
  // the pose: in the base frame at the state's values, for the solver's tip
  expectSamePose(toEigen(stub->pose_), base.inverse() * target * tool_in_wrist.inverse(), SAME * 1e3);
  // the seed: the state's values in the solver's order
  ASSERT_EQ(stub->seed_.size(), current.size());
  for (std::size_t i = 0; i < current.size(); ++i)
    EXPECT_NEAR(stub->seed_[i], current[current.size() - 1 - i], SAME);
  EXPECT_DOUBLE_EQ(stub->timeout_, GROUP_TIMEOUT);
  EXPECT_EQ(stub->limits_, limits);
  // the callback saw the answer in the group's order; the state holds it
  ASSERT_EQ(seen.size(), wanted.size());
  std::vector<double> result;
  state.copyJointGroupPositions(group, result);
  for (std::size_t i = 0; i < wanted.size(); ++i)
  {
    EXPECT_NEAR(seen[i], wanted[i], SAME);
    EXPECT_NEAR(result[i], wanted[i], SAME);
  }

  // a timeout given is passed on; a refused answer leaves the state as it was
  const double timeout = 0.7;
  moveit::core::RobotState other(model);
  other.setToDefaultValues();
  std::vector<double> untouched;
  other.copyJointGroupPositions(group, untouched);
  EXPECT_FALSE(other.setFromIK(group, target, ATTACHED_TIP, timeout,
                               [](moveit::core::RobotState*, const moveit::core::JointModelGroup*, const double*) {
                                 return false;
                               }));
  EXPECT_DOUBLE_EQ(stub->timeout_, timeout);
  std::vector<double> after;
  other.copyJointGroupPositions(group, after);
  EXPECT_EQ(after, untouched);

  // no tip given: the solver's tip; a frame not rigidly attached to it is refused
  other.update();
  const Eigen::Isometry3d other_base = other.getGlobalLinkTransform(STUB_BASE);
  EXPECT_TRUE(other.setFromIK(group, target));
  expectSamePose(toEigen(stub->pose_), other_base.inverse() * target, SAME * 1e3);
  const int calls = stub->calls;
  EXPECT_FALSE(other.setFromIK(group, target, "forearm_link"));
  EXPECT_EQ(stub->calls, calls);
}

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}

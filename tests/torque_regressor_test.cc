// The joint-torque regressor (massprops/dynamics/torque_regressor.h) against the recursive
// Newton–Euler algorithm, which computes the torques another way (the bodies' forces summed
// before they are carried to the joints): Y·π must equal the RNEA's τ to round-off at random
// states of real arms of ../shared/corpus (URDF and SDF), and each inertial column of Y must be
// the RNEA's τ of that one unit parameter (linearity, column by column).
#include "massprops/dynamics/torque_regressor.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "dynamics_test_support.h"
#include "massprops/dynamics/inverse_dynamics.h"
#include "shared_data.h"

namespace massprops {
namespace {

using test_support::V;

// Arms and limbs of the corpus: a 7-joint arm with its gripper's prismatic fingers (Panda), a
// 6-joint arm (UR5), the iiwa 14 as URDF and as SDF, and a humanoid (H1) on a fixed pelvis.
const char* const kCorpusArms[] = {
    "example-robot-data/robots/panda_description/urdf/panda.urdf",
    "example-robot-data/robots/ur_description/urdf/ur5_robot.urdf",
    "drake-models/iiwa_description/urdf/iiwa14_no_collision.urdf",
    "drake-models/iiwa_description/sdf/iiwa14_no_collision.sdf",
    "unitree_ros/robots/h1_description/urdf/h1.urdf",
};

KinematicTree CorpusTree(const std::string& file) {
  const ReadResult read = ReadModelFile(test_support::SharedDir() + "/corpus/" + file);
  EXPECT_TRUE(read.ok()) << file;
  const KinematicTreeResult made = MakeKinematicTree(read.models.at(0));
  EXPECT_TRUE(made.tree.has_value()) << file << ": " << made.error;
  return made.tree.value();
}

struct State {
  Eigen::VectorXd q, dq, ddq;
};

State RandomState(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> any(-2, 2);
  State s{Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n)};
  for (int i = 0; i < n; ++i) {
    s.q(i) = any(rng);
    s.dq(i) = any(rng);
    s.ddq(i) = 3 * any(rng);
  }
  return s;
}

TEST(TorqueRegressorTest, RegressorTimesParametersIsTheRneaOnCorpusArms) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus");
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  for (const char* file : kCorpusArms) {
    SCOPED_TRACE(file);
    KinematicTree tree = CorpusTree(file);
    ASSERT_GE(tree.size(), 6);
    for (JointFriction& f : tree.friction) f = {unit(rng), unit(rng), unit(rng) - 0.5, unit(rng)};
    const RegressorOptions options{true, true};
    const Eigen::VectorXd pi = RegressorParameters(tree, options);
    double worst = 0;
    for (int k = 0; k < 50; ++k) {
      const State s = RandomState(rng, tree.size());
      const Eigen::VectorXd tau = CalcInverseDynamics(tree, s.q, s.dq, s.ddq);
      const Eigen::MatrixXd Y = CalcTorqueRegressor(tree, s.q, s.dq, s.ddq, options);
      worst =
          std::max(worst, (Y * pi - tau).lpNorm<Eigen::Infinity>() / tau.lpNorm<Eigen::Infinity>());
    }
    EXPECT_LT(worst, 1e-13);
  }
}

TEST(TorqueRegressorTest, EachInertialColumnIsTheRneaOfThatUnitParameter) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus");
  std::mt19937_64 rng(12);
  const KinematicTree tree = CorpusTree(kCorpusArms[0]);
  const int n = tree.size();
  const State s = RandomState(rng, n);
  const Eigen::MatrixXd Y = CalcTorqueRegressor(tree, s.q, s.dq, s.ddq, {false, false});
  ASSERT_EQ(Y.cols(), 10 * n);
  for (int k = 0; k < 10 * n; ++k) {
    Eigen::VectorXd unit = Eigen::VectorXd::Zero(10 * n);
    unit(k) = 1;
    const Eigen::VectorXd column = CalcInverseDynamics(tree, unit, s.q, s.dq, s.ddq);
    EXPECT_LT((Y.col(k) - column).lpNorm<Eigen::Infinity>(),
              1e-13 * (1 + column.lpNorm<Eigen::Infinity>()))
        << "column " << k;
  }
}

// A body's columns are zero in the rows of joints not on its way to the base: the Panda's
// fingers (two prismatic joints on the hand) do not load each other.
TEST(TorqueRegressorTest, ABodyLoadsOnlyTheJointsOnItsWayToTheBase) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus");
  std::mt19937_64 rng(13);
  const KinematicTree tree = CorpusTree(kCorpusArms[0]);
  const State s = RandomState(rng, tree.size());
  const Eigen::MatrixXd Y = CalcTorqueRegressor(tree, s.q, s.dq, s.ddq, {false, false});
  for (int body = 0; body < tree.size(); ++body) {
    std::vector<bool> on_path(static_cast<std::size_t>(tree.size()), false);
    for (int j = body; j >= 0; j = tree.bodies[static_cast<std::size_t>(j)].parent)
      on_path[static_cast<std::size_t>(j)] = true;
    for (int row = 0; row < tree.size(); ++row) {
      if (on_path[static_cast<std::size_t>(row)]) continue;
      EXPECT_EQ(Y.row(row).segment<10>(10 * body).norm(), 0) << row << " " << body;
    }
  }
}

// The friction and armature columns are q̇, sign(q̇), 1 and q̈ in their joint's row only.
TEST(TorqueRegressorTest, FrictionColumnsAreVelocitySignOneAndAcceleration) {
  const KinematicTree tree = test_support::TreeOf(
      "<robot name='two'><link name='base'/><link name='a'/><link name='b'/>" +
      test_support::JointXml("ja", "revolute", "base", "a", "xyz='0 0 0'", "0 0 1") +
      test_support::JointXml("jb", "prismatic", "a", "b", "xyz='1 0 0'", "1 0 0") + "</robot>");
  const RegressorOptions options{true, true};
  ASSERT_EQ(CountRegressorColumns(tree, options), 20 + 6 + 2);
  const Eigen::MatrixXd Y =
      CalcTorqueRegressor(tree, V({0.1, 0.2}), V({-3, 0}), V({5, 7}), options);
  Eigen::MatrixXd expected(2, 8);
  expected << -3, -1, 1, 0, 0, 0, 5, 0,  //
      0, 0, 0, 0, 0, 1, 0, 7;
  EXPECT_EQ(Y.rightCols(8), expected);
  const std::vector<std::string> names = RegressorColumnNames(tree, options);
  ASSERT_EQ(names.size(), 28u);
  EXPECT_EQ(names[0], "a.m");
  EXPECT_EQ(names[9], "a.izz");
  EXPECT_EQ(names[13], "b.mz");
  EXPECT_EQ(names[20], "ja.viscous");
  EXPECT_EQ(names[25], "jb.offset");
  EXPECT_EQ(names[27], "jb.armature");
}

TEST(TorqueRegressorTest, AWrongSizedOutputThrows) {
  const KinematicTree tree = test_support::TreeOf(
      "<robot name='one'><link name='base'/><link name='a'/>" +
      test_support::JointXml("ja", "revolute", "base", "a", "xyz='0 0 0'", "0 0 1") + "</robot>");
  Eigen::MatrixXd Y(1, 10);
  EXPECT_THROW(CalcTorqueRegressor(tree, V({0}), V({0}), V({0}), RegressorOptions{}, Y),
               std::invalid_argument);
}

}  // namespace
}  // namespace massprops

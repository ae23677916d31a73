// Base parameters by pivoted QR (massprops/analysis/identifiability.h) on synthetic data: random
// states of small robots whose base parameters are known in closed form (Khalil and Dombre,
// "Modeling, Identification and Control of Robots", 2002, §12.4: a link on a horizontal axis has
// 3, the planar two-link arm 6, with ZZ1 + l1²·M2 and MX1 + l1·M2 regrouped), matrices whose
// dependencies are written by hand, and a fit through the base parameters on noisy torques.
#include "massprops/analysis/identifiability.h"

#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "dynamics_test_support.h"
#include "massprops/dynamics/torque_regressor.h"

namespace massprops {
namespace {

using test_support::InertialXml;
using test_support::JointXml;

const std::string kMoments = "ixx='0.03' iyy='0.11' izz='0.12' ixy='0.004' ixz='0.002' iyz='0.001'";

struct Data {
  Eigen::MatrixXd W;
  std::vector<std::string> names;
};

// The stacked regressor of `samples` random states; joints listed in `still` never move.
Data RandomData(const KinematicTree& tree, const RegressorOptions& options, int samples,
                std::mt19937_64& rng, const std::set<int>& still = {}) {
  std::uniform_real_distribution<double> any(-2, 2);
  const int n = tree.size();
  Eigen::MatrixXd q(samples, n), dq(samples, n), ddq(samples, n);
  for (int k = 0; k < samples; ++k) {
    for (int j = 0; j < n; ++j) {
      const bool moves = still.count(j) == 0;
      q(k, j) = moves ? any(rng) : 0.3;
      dq(k, j) = moves ? any(rng) : 0;
      ddq(k, j) = moves ? any(rng) : 0;
    }
  }
  return {StackTorqueRegressor(tree, q, dq, ddq, options), RegressorColumnNames(tree, options)};
}

std::set<std::string> BaseNames(const Identifiability& id) {
  std::set<std::string> names;
  for (const BaseParameter& b : id.base) names.insert(b.name);
  return names;
}

// One link on a horizontal axis (y, gravity −z): τ = Iyy·q̈ − g·(mx·cos q + mz·sin q), so the
// data see Iyy (about the axis), mx and mz and nothing else; friction adds its 3 columns.
TEST(IdentifiabilityTest, ALinkOnAHorizontalAxisHasThreeBaseParameters) {
  const KinematicTree tree = test_support::TreeOf(
      "<robot name='p'><link name='base'/><link name='arm'>" +
      InertialXml("0.4 0 0.1", 2, kMoments) + "</link>" +
      JointXml("hinge", "continuous", "base", "arm", "xyz='0 0 1'", "0 1 0") + "</robot>");
  std::mt19937_64 rng(31);
  const Data inertial = RandomData(tree, {false, false}, 50, rng);
  const Identifiability id = AnalyzeIdentifiability(inertial.W, inertial.names);
  EXPECT_EQ(id.rank, 3);
  EXPECT_EQ(BaseNames(id), (std::set<std::string>{"arm.iyy", "arm.mx", "arm.mz"}));
  for (const BaseParameter& b : id.base) EXPECT_TRUE(b.terms.empty()) << b.ToString();
  EXPECT_EQ(id.unidentified.size(), 7u);
  EXPECT_TRUE(UnexcitedLinks(id, inertial.names).empty());
  const Data with_friction = RandomData(tree, {true, false}, 50, rng);
  EXPECT_EQ(AnalyzeIdentifiability(with_friction.W, with_friction.names).rank, 6);
}

// The planar two-link arm (axes z, gravity −y): 6 base parameters, and the forearm's mass
// regroups into the upper arm's: τ depends on M2 only through ZZ1 + l1²·M2 and MX1 + l1·M2, so
// v = e(fore.m) − l1·e(upper.mx) − l1²·e(upper.izz) is in the null space of W.
TEST(IdentifiabilityTest, PlanarTwoLinkArmRegroupsTheForearmMass) {
  const double l1 = 0.8;
  KinematicTree tree = test_support::TreeOf(
      "<robot name='elbow'><link name='base'/><link name='upper'>" +
      InertialXml("0.35 0.02 0", 3, kMoments) + "</link><link name='fore'>" +
      InertialXml("0.3 -0.01 0.05", 2, kMoments) + "</link>" +
      JointXml("shoulder", "revolute", "base", "upper", "xyz='0 0 0'", "0 0 1") +
      JointXml("elbow", "revolute", "upper", "fore", "xyz='0.8 0 0'", "0 0 1") + "</robot>");
  tree.gravity_base = Eigen::Vector3d(0, -9.81, 0);
  std::mt19937_64 rng(32);
  const Data data = RandomData(tree, {false, false}, 100, rng);
  const Identifiability id = AnalyzeIdentifiability(data.W, data.names);
  EXPECT_EQ(id.rank, 6);
  const auto column = [&](const std::string& name) {
    return static_cast<Eigen::Index>(std::find(data.names.begin(), data.names.end(), name) -
                                     data.names.begin());
  };
  Eigen::VectorXd v = Eigen::VectorXd::Zero(data.W.cols());
  v(column("fore.m")) = 1;
  v(column("upper.mx")) = -l1;
  v(column("upper.izz")) = -l1 * l1;
  EXPECT_LT((data.W * v).norm(), 1e-12 * data.W.norm());
  // W·π = W_base·β for any π, β = base_from_full·π.
  std::uniform_real_distribution<double> any(-1, 1);
  Eigen::VectorXd pi(data.W.cols());
  for (Eigen::Index i = 0; i < pi.size(); ++i) pi(i) = any(rng);
  Eigen::MatrixXd W_base(data.W.rows(), id.rank);
  for (int i = 0; i < id.rank; ++i)
    W_base.col(i) = data.W.col(id.base[static_cast<std::size_t>(i)].column);
  EXPECT_LT((data.W * pi - W_base * (id.base_from_full * pi)).norm(), 1e-12 * (data.W * pi).norm());
}

// Hand-made columns: c = 2·a + 3·b, so rank 2 whichever two pivots are taken; an all-zero
// column is unidentified; orthogonal columns of norms 10 and 1 have condition 10.
TEST(IdentifiabilityTest, HandMadeDependenciesAndConditionNumber) {
  Eigen::MatrixXd W(4, 4);
  W << 10, 0, 20, 0,  //
      0, 1, 3, 0,     //
      0, 0, 0, 0,     //
      0, 0, 0, 0;
  const Identifiability id = AnalyzeIdentifiability(W, {"a", "b", "c", "z"});
  EXPECT_EQ(id.rank, 2);
  EXPECT_EQ(id.unidentified, std::vector<int>{3});
  // Whatever pivots are chosen, β reproduces W·π for any π.
  const Eigen::Vector4d pi(1.5, -2, 0.25, 7);
  Eigen::MatrixXd W_base(4, id.rank);
  for (int i = 0; i < id.rank; ++i)
    W_base.col(i) = W.col(id.base[static_cast<std::size_t>(i)].column);
  EXPECT_LT((W * pi - W_base * (id.base_from_full * pi)).norm(), 1e-13);
  // The condition number is that of W_base's own SVD (a second computation).
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(W_base);
  EXPECT_NEAR(id.condition_number, svd.singularValues()(0) / svd.singularValues()(1), 1e-12);
  // Orthogonal columns: condition = ratio of norms.
  Eigen::MatrixXd O(3, 2);
  O << 10, 0, 0, 1, 0, 0;
  EXPECT_NEAR(AnalyzeIdentifiability(O, {"a", "b"}).condition_number, 10, 1e-12);
  EXPECT_THROW(AnalyzeIdentifiability(O, {"a"}), std::invalid_argument);
}

// A vertical axis (gravity along it) that never moves: its link's columns are all zero.
TEST(IdentifiabilityTest, ALinkWhoseJointNeverMovesUnderAVerticalAxisIsUnexcited) {
  const KinematicTree tree = test_support::TreeOf(
      "<robot name='two'><link name='base'/><link name='swing'>" +
      InertialXml("0.4 0 0", 2, kMoments) + "</link><link name='turntable'>" +
      InertialXml("0.1 0.1 0", 1, kMoments) + "</link>" +
      JointXml("swing_joint", "continuous", "base", "swing", "xyz='0 0 1'", "0 1 0") +
      JointXml("turn_joint", "continuous", "base", "turntable", "xyz='1 0 0'", "0 0 1") +
      "</robot>");
  std::mt19937_64 rng(33);
  const Data data = RandomData(tree, {false, false}, 40, rng, {tree.FindJoint("turn_joint")});
  const Identifiability id = AnalyzeIdentifiability(data.W, data.names);
  EXPECT_EQ(UnexcitedLinks(id, data.names), std::vector<std::string>{"turntable"});
}

// Least squares through the base columns recovers the true base parameters from torques with
// noise: β̂ within 5 standard errors of β = base_from_full·π_true (the standard error from
// σ²·(W_baseᵀW_base)⁻¹, the noise σ known).
TEST(IdentifiabilityTest, BaseParametersAreRecoveredFromNoisyTorques) {
  KinematicTree tree = test_support::TreeOf(
      "<robot name='elbow'><link name='base'/><link name='upper'>" +
      InertialXml("0.35 0.02 0", 3, kMoments) + "</link><link name='fore'>" +
      InertialXml("0.3 -0.01 0.05", 2, kMoments) + "</link>" +
      JointXml("shoulder", "revolute", "base", "upper", "xyz='0 0 0'", "0 1 0") +
      JointXml("elbow", "revolute", "upper", "fore", "xyz='0.8 0 0'", "0 1 0") + "</robot>");
  std::mt19937_64 rng(34);
  const RegressorOptions options{true, false};
  for (JointFriction& f : tree.friction) f = {0.2, 0.5, -0.1, 0};
  const Data data = RandomData(tree, options, 2000, rng);
  const Identifiability id = AnalyzeIdentifiability(data.W, data.names);
  const Eigen::VectorXd pi = RegressorParameters(tree, options);
  const double sigma = 0.01;
  std::normal_distribution<double> noise(0, sigma);
  Eigen::VectorXd tau = data.W * pi;
  for (Eigen::Index i = 0; i < tau.size(); ++i) tau(i) += noise(rng);
  Eigen::MatrixXd W_base(data.W.rows(), id.rank);
  for (int i = 0; i < id.rank; ++i)
    W_base.col(i) = data.W.col(id.base[static_cast<std::size_t>(i)].column);
  const Eigen::VectorXd beta_hat = W_base.colPivHouseholderQr().solve(tau);
  const Eigen::VectorXd beta = id.base_from_full * pi;
  const Eigen::MatrixXd covariance = sigma * sigma * (W_base.transpose() * W_base).inverse();
  for (int i = 0; i < id.rank; ++i) {
    EXPECT_LT(std::abs(beta_hat(i) - beta(i)), 5 * std::sqrt(covariance(i, i)))
        << id.base[static_cast<std::size_t>(i)].ToString();
  }
}

}  // namespace
}  // namespace massprops

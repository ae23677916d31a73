// The physically consistent identification (massprops/analysis/identify.h) on synthetic truth:
// the three-joint arm of testdata/identify/arm3.urdf is the file (the prior); a "true" arm with
// other masses, centers of mass and tensors (kTrue below) and joint friction makes the torques
// (CalcInverseDynamics, the RNEA, not the regressor) along a sum of sinusoids, with seeded
// Gaussian noise. Every expected value comes from the true arm: its base parameters B·π_true
// (B from the identifiability analysis of the same data).
#include "massprops/analysis/identify.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "exciting_motion.h"
#include "massprops/dynamics/inverse_dynamics.h"
#include "massprops/io/model_reader.h"

namespace massprops {
namespace {

KinematicTree FileArm() {
  const ReadResult read =
      ReadModelFile(std::string(MASSPROPS_TESTDATA_DIR) + "/identify/arm3.urdf");
  EXPECT_TRUE(read.ok() && read.models.size() == 1);
  const KinematicTreeResult made = MakeKinematicTree(read.models.at(0));
  EXPECT_TRUE(made.tree.has_value()) << made.error;
  return made.tree.value();
}

Eigen::Matrix3d Inertia(double xx, double yy, double zz, double xy, double xz, double yz) {
  Eigen::Matrix3d I;
  I << xx, xy, xz, xy, yy, yz, xz, yz, zz;
  return I;
}

// The true arm: each body's mass, center of mass and central inertia differ from the file's
// (arm3.urdf: 2, 1.5, 1 kg) by 10-30%; `forearm_point` makes the forearm a near point mass (a
// payload: central inertia 1e-7 kg·m², on the edge of what a body can have).
KinematicTree TrueArm(bool forearm_point = false) {
  KinematicTree tree = FileArm();
  tree.bodies[0].pi_BBo_B =
      MakeInertialParameters(2.4, {0.01, -0.01, 0.06}, Inertia(0.012, 0.011, 0.006, 0, 0, 0));
  tree.bodies[1].pi_BBo_B = MakeInertialParameters(1.8, {0.23, 0.005, 0.01},
                                                   Inertia(0.003, 0.026, 0.025, 0.0004, 0.0003, 0));
  tree.bodies[2].pi_BBo_B =
      forearm_point
          ? MakeInertialParameters(0.9, {0.3, 0, 0.01}, Inertia(1e-7, 1e-7, 1e-7, 0, 0, 0))
          : MakeInertialParameters(0.8, {0.17, 0.005, -0.01},
                                   Inertia(0.0008, 0.012, 0.0115, 0.0002, 0, 0.0001));
  tree.friction = {{0.2, 0.1, 0.02, 0}, {0.3, 0.15, -0.05, 0}, {0.1, 0.05, 0.01, 0}};
  return tree;
}

// N samples at 100 Hz of exciting_motion.h's sum of three sines per joint with its analytic
// velocities and accelerations, and τ of `truth` plus Gaussian noise (σ = noise N·m,
// std::mt19937 seeded).
OrderedTrajectory Simulate(const KinematicTree& truth, int N, double noise, unsigned seed) {
  const int n = truth.size();
  OrderedTrajectory data = test_support::SumOfSines(test_support::ExcitingMotion(), n, N);
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0, noise);
  for (int k = 0; k < N; ++k) {
    const Eigen::VectorXd tau = CalcInverseDynamics(
        truth, data.q.row(k).transpose(), data.dq.row(k).transpose(), data.ddq.row(k).transpose());
    for (int j = 0; j < n; ++j) data.tau(k, j) = tau[j] + gauss(rng);
  }
  return data;
}

TEST(IdentifyTest, LogCholeskyRoundTripsAValidBodyAndItsJacobianIsExact) {
  const InertialParameters pi = MakeInertialParameters(
      1.8, {0.23, 0.005, 0.01}, Inertia(0.003, 0.026, 0.025, 0.0004, 0.0003, 0));
  const LogCholeskyParameters theta = LogCholeskyFromInertialParameters(pi);
  EXPECT_LT((InertialParametersFromLogCholesky(theta) - pi).norm(), 1e-13);
  // The exact Jacobian against central differences (hand-derived check: error O(h²)).
  const Eigen::Matrix<double, 10, 10> D = InertialParametersFromLogCholeskyJacobian(theta);
  const double h = 1e-6;
  for (int k = 0; k < 10; ++k) {
    LogCholeskyParameters plus = theta, minus = theta;
    plus[k] += h;
    minus[k] -= h;
    const InertialParameters fd =
        (InertialParametersFromLogCholesky(plus) - InertialParametersFromLogCholesky(minus)) /
        (2 * h);
    EXPECT_LT((D.col(k) - fd).norm(), 1e-8 * (1 + fd.norm())) << "column " << k;
  }
}

// Rucker and Wensing (RA-L 2022): every θ gives J = U·Uᵀ ≻ 0, a body that can exist.
TEST(IdentifyTest, EveryLogCholeskyPointIsAConsistentBody) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> any(-2, 2);
  for (int i = 0; i < 200; ++i) {
    LogCholeskyParameters theta;
    for (int k = 0; k < 10; ++k) theta[k] = any(rng);
    EXPECT_TRUE(IsConsistentBody(InertialParametersFromLogCholesky(theta), 1e-9)) << i;
  }
  // An invalid body (central Izz above Ixx + Iyy) is not, and is moved to a consistent one.
  const InertialParameters bad =
      MakeInertialParameters(1, {0.1, 0, 0}, Inertia(0.001, 0.001, 0.01, 0, 0, 0));
  EXPECT_FALSE(IsConsistentBody(bad));
  EXPECT_TRUE(
      IsConsistentBody(InertialParametersFromLogCholesky(LogCholeskyFromInertialParameters(bad))));
}

TEST(IdentifyTest, RecoversTheTrueArmsBaseParametersConsistently) {
  const KinematicTree file = FileArm();
  const KinematicTree truth = TrueArm();
  const OrderedTrajectory data = Simulate(truth, 1000, 0.02, 51);
  IdentifyOptions options;
  options.validation_fraction = 0.3;
  const IdentifyResult r = Identify(file, data, options);
  EXPECT_EQ(r.training_samples, 700);
  EXPECT_EQ(r.validation_samples, 300);
  // Expected: B·π_true, the true arm's own parameters with its friction.
  const Eigen::VectorXd beta_true =
      r.identifiability.base_from_full * RegressorParameters(truth, options.regressor);
  ASSERT_EQ(r.base_identified.size(), beta_true.size());
  for (Eigen::Index i = 0; i < beta_true.size(); ++i) {
    const double tolerance = 5 * r.base_standard_error[i] + 1e-3 * std::abs(beta_true[i]);
    EXPECT_NEAR(r.base_identified[i], beta_true[i], tolerance)
        << r.identifiability.base[static_cast<std::size_t>(i)].ToString();
    EXPECT_NEAR(r.base_least_squares[i], beta_true[i], 5 * r.base_standard_error[i]);
  }
  for (const BodyEstimate& b : r.bodies) EXPECT_TRUE(b.identified_consistent) << b.link;
  for (int j = 0; j < file.size(); ++j) {
    EXPECT_LE(r.rms_identified[j], r.rms_least_squares[j] * 1.02 + 1e-4) << j;
    // The noise is 0.02 N·m: the fit explains everything else; the file's values do not.
    EXPECT_LT(r.rms_identified[j], 0.025) << j;
    EXPECT_GT(r.rms_file[j], 2 * r.rms_identified[j]) << j;
  }
  EXPECT_TRUE(r.unexcited_links.empty());
}

// A payload-like forearm (central inertia 1e-7 kg·m²) with noisier torques: least squares gives
// it a central inertia no body has; the consistent fit cannot.
TEST(IdentifyTest, LeastSquaresBreaksAPointMassTheConsistentFitDoesNot) {
  const KinematicTree file = FileArm();
  const KinematicTree truth = TrueArm(true);
  const OrderedTrajectory data = Simulate(truth, 600, 0.05, 3);
  const IdentifyResult r = Identify(file, data);
  EXPECT_GE(r.inconsistent_least_squares_links, 1);
  EXPECT_FALSE(r.bodies[2].least_squares_consistent);
  for (const BodyEstimate& b : r.bodies) EXPECT_TRUE(b.identified_consistent) << b.link;
  for (int j = 0; j < file.size(); ++j) {
    EXPECT_LE(r.rms_identified[j], r.rms_least_squares[j] * 1.02 + 1e-4) << j;
  }
}

TEST(IdentifyTest, JointsMissingOnEitherSideAreNamed) {
  const KinematicTree file = FileArm();
  JointTrajectory data;
  data.joints = {"shoulder_yaw", "elbow", "gripper"};
  data.time = Eigen::VectorXd::LinSpaced(10, 0, 0.09);
  data.q = data.dq = data.ddq = data.tau = Eigen::MatrixXd::Zero(10, 3);
  const OrderedTrajectory ordered = OrderTrajectory(file, data);
  EXPECT_FALSE(ordered.ok());
  EXPECT_NE(ordered.error.find("joint 'shoulder_pitch' of the model has no columns in the data"),
            std::string::npos)
      << ordered.error;
  EXPECT_NE(ordered.error.find("joint 'gripper' in the data is not a moving joint of the model"),
            std::string::npos)
      << ordered.error;
  data.joints = {"elbow", "shoulder_pitch", "shoulder_yaw"};
  data.q.col(0).setConstant(3);  // elbow
  const OrderedTrajectory reordered = OrderTrajectory(file, data);
  ASSERT_TRUE(reordered.ok()) << reordered.error;
  EXPECT_EQ(reordered.q(0, 2), 3);  // the elbow is the tree's third joint
  EXPECT_EQ(reordered.q(0, 0), 0);
}

// No motion and no gravity: the data see nothing (rank 0), every link is unexcited and the fit
// keeps the file's values (the prior is the only term).
TEST(IdentifyTest, DataThatSeeNothingKeepTheFilesValues) {
  KinematicTree file = FileArm();
  file.gravity_base.setZero();
  OrderedTrajectory still;
  still.q = still.dq = still.ddq = still.tau = Eigen::MatrixXd::Zero(20, 3);
  IdentifyOptions options;
  options.regressor.friction = false;
  const IdentifyResult r = Identify(file, still, options);
  EXPECT_EQ(r.identifiability.rank, 0);
  EXPECT_EQ(r.unexcited_links, (std::vector<std::string>{"shoulder", "upper_arm", "forearm"}));
  EXPECT_EQ(r.least_squares, r.file);
  EXPECT_LT((r.identified - r.file).norm(), 1e-12 * r.file.norm());
}

TEST(IdentifyTest, BadOptionsThrow) {
  const KinematicTree file = FileArm();
  const OrderedTrajectory data = Simulate(file, 20, 0, 1);
  IdentifyOptions options;
  options.validation_fraction = 0.95;
  EXPECT_THROW(Identify(file, data, options), std::invalid_argument);
}

}  // namespace

// The standard errors of the consistent estimate (IdentifyResult::mass_standard_error,
// com_standard_error) against the Monte Carlo spread they predict: the planar arm of
// testdata/identify/planar_arm.urdf as the file, a true arm with the values of
// tools/make_identify_csv.py (m1 2.3 kg, lc1 0.22 m, I1 0.05 kg·m²; m2 1.0 kg, lc2 0.24 m,
// I2 0.012 kg·m²), the same trajectory and 12 noise seeds (σ = 0.05 N·m). The sample standard
// deviation of 12 draws is within [0.59, 1.41] of the true one with 95% probability (χ² with 11
// degrees of freedom), and the reported error varies a little from seed to seed: their mean
// must be within a factor 2 of the spread (observed: 0.78 to 0.95 of it).
TEST(IdentifyTest, StandardErrorsMatchTheSpreadOverNoiseSeeds) {
  const ReadResult read =
      ReadModelFile(std::string(MASSPROPS_TESTDATA_DIR) + "/identify/planar_arm.urdf");
  ASSERT_TRUE(read.ok() && read.models.size() == 1);
  const KinematicTreeResult made = MakeKinematicTree(read.models.at(0));
  ASSERT_TRUE(made.tree.has_value()) << made.error;
  const KinematicTree& file = *made.tree;
  // Central inertia about y (the joint axis, -y) as the URDF writes it; ixx, izz kept plausible.
  const KinematicTree truth = test_support::TruePlanarArm(file);
  constexpr int kSeeds = 12;
  std::vector<Eigen::VectorXd> values;  // per seed: m, cx, cy, cz of each body
  Eigen::VectorXd reported = Eigen::VectorXd::Zero(8);
  for (int seed = 0; seed < kSeeds; ++seed) {
    const OrderedTrajectory data = Simulate(truth, 800, 0.05, 100 + static_cast<unsigned>(seed));
    const IdentifyResult r = Identify(file, data, IdentifyOptions{});
    ASSERT_EQ(r.mass_standard_error.size(), 2);
    // The principal moments' errors (identify_uncertainty_test holds their propagation to random
    // draws; the forearm's two equal moments make each one's spread over seeds ill-defined here).
    ASSERT_EQ(r.principal_moments_standard_error.cols(), 2);
    EXPECT_TRUE(r.principal_moments_standard_error.allFinite());
    EXPECT_GE(r.principal_moments_standard_error.minCoeff(), 0);
    Eigen::VectorXd v(8);
    for (int b = 0; b < 2; ++b) {
      const InertialParameters& pi = r.bodies[static_cast<std::size_t>(b)].identified;
      v[4 * b] = pi[0];
      v.segment<3>(4 * b + 1) = pi.segment<3>(1) / pi[0];
      reported[4 * b] += r.mass_standard_error[b] / kSeeds;
      reported.segment<3>(4 * b + 1) += r.com_standard_error.col(b) / kSeeds;
    }
    values.push_back(v);
  }
  Eigen::VectorXd mean = Eigen::VectorXd::Zero(8), spread = Eigen::VectorXd::Zero(8);
  for (const Eigen::VectorXd& v : values) mean += v / kSeeds;
  for (const Eigen::VectorXd& v : values) spread += (v - mean).cwiseAbs2() / (kSeeds - 1);
  spread = spread.cwiseSqrt();
  // Moved by the noise (the values mix with the data's combinations m1·lc1 + m2·l1, m2·lc2,
  // ...): the upper arm's cx, cz and the forearm's mass, cx, cz.
  for (int i : {1, 3, 4, 5, 7}) {
    EXPECT_LT(reported[i], 2 * spread[i]) << i << ": " << reported[i] << " vs " << spread[i];
    EXPECT_GT(reported[i], 0.5 * spread[i]) << i << ": " << reported[i] << " vs " << spread[i];
  }
  // The upper arm's mass is in no combination the data determine: the prior holds it (first
  // order: no spread); the fits scatter by the solver's stopping tolerance in that flat
  // direction, below 1e-3 of the 2 kg (docs/identify.md).
  EXPECT_LT(reported[0], 2e-3);
  EXPECT_LT(spread[0], 2e-3);
  // y is out of the arm's plane: nothing moves it.
  EXPECT_LT(reported[2] + reported[6] + spread[2] + spread[6], 1e-6);
}

}  // namespace massprops

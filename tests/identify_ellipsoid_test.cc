// The bounding-ellipsoid condition of identification (massprops/analysis/identify_ellipsoid.h):
// its parametrization against independent computations (central differences, the condition
// tr(Q⁻¹(Σ + m(c − x0)(c − x0)ᵀ)) <= m of Wensing, Kim and Slotine, RA-L 2018, written out from
// the center of mass here), a uniform box against its hand-worked minimum-volume ellipsoid, and
// the fit on the planar two-link arm with box geometry (testdata/identify/planar_arm_boxes.urdf)
// against the same fit without the bound.
#include "massprops/analysis/identify_ellipsoid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "exciting_motion.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/analysis/identify.h"
#include "massprops/dynamics/inverse_dynamics.h"
#include "massprops/io/model_reader.h"

namespace massprops {
namespace {

// A URDF of one body of 1 kg on a revolute joint about z, whose <collision> holds `collision`.
std::string OneBodyRobot(const std::string& collision) {
  return "<robot name='r'><link name='base'/><link name='body'><inertial><mass value='1'/>"
         "<inertia ixx='1e-3' iyy='1e-3' izz='1e-3' ixy='0' ixz='0' iyz='0'/></inertial>"
         "<collision>" +
         collision +
         "</collision></link>"
         "<joint name='j' type='revolute'><parent link='base'/><child link='body'/>"
         "<axis xyz='0 0 1'/><limit lower='-1' upper='1' effort='1' velocity='1'/></joint></robot>";
}

Eigen::Matrix3d Inertia(double xx, double yy, double zz, double xy, double xz, double yz) {
  Eigen::Matrix3d I;
  I << xx, xy, xz, xy, yy, yz, xz, yz, zz;
  return I;
}

// An ellipsoid with semi-axes `semi` along the columns of R, centered at x0.
BoundingEllipsoid Ellipsoid(const Eigen::Vector3d& x0, const Eigen::Matrix3d& R,
                            const Eigen::Vector3d& semi) {
  BoundingEllipsoid e;
  e.x0 = x0;
  e.Q_inverse = R * semi.cwiseAbs2().cwiseInverse().asDiagonal() * R.transpose();
  return e;
}

Eigen::Matrix3d Turned() {
  return (Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(-0.3, Eigen::Vector3d(1, 1, 0).normalized()))
      .toRotationMatrix();
}

// The condition written from the definitions, not from the library's pseudo-inertia: c = h/m,
// the central inertia I_c = I_o − m·(|c|²·1 − c·cᵀ) (parallel axes), Σ = ½·tr(I_c)·1 − I_c, and
// tr(Q⁻¹·(Σ + m·d·dᵀ)) / m with d = c − x0.
double HandRatio(const InertialParameters& pi, const BoundingEllipsoid& e) {
  const double m = pi[0];
  const Eigen::Vector3d c = pi.segment<3>(1) / m;
  const Eigen::Matrix3d I_o = Inertia(pi[4], pi[6], pi[9], pi[5], pi[7], pi[8]);
  const Eigen::Matrix3d I_c =
      I_o - m * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
  const Eigen::Matrix3d Sigma = 0.5 * I_c.trace() * Eigen::Matrix3d::Identity() - I_c;
  const Eigen::Vector3d d = c - e.x0;
  return (e.Q_inverse * (Sigma + m * d * d.transpose())).trace() / m;
}

// A uniform solid box a × b × c of mass m, centered at p, its edges along R's columns: central
// inertia m/12·diag(b² + c², a² + c², a² + b²) in the box's frame (any mechanics text, e.g.
// Beer and Johnston's table of mass moments of inertia), re-expressed by R.
InertialParameters UniformBox(double m, const Eigen::Vector3d& size, const Eigen::Vector3d& p,
                              const Eigen::Matrix3d& R) {
  const Eigen::Vector3d s2 = size.cwiseAbs2();
  const Eigen::Matrix3d I_box =
      m / 12 * Eigen::Vector3d(s2[1] + s2[2], s2[0] + s2[2], s2[0] + s2[1]).asDiagonal();
  return MakeInertialParameters(m, p, R * I_box * R.transpose());
}

TEST(IdentifyEllipsoidTest, RoundTripsABodyInsideAndItsJacobianIsExact) {
  const BoundingEllipsoid e =
      Ellipsoid({0.2, 0.01, -0.03}, Turned(), Eigen::Vector3d(0.3, 0.1, 0.08));
  // A uniform box well inside: half the ellipsoid's semi-axes, off-center by a little.
  const InertialParameters pi = UniformBox(1.5, Eigen::Vector3d(0.3, 0.1, 0.08),
                                           e.x0 + Eigen::Vector3d(0.02, 0.01, 0), Turned());
  ASSERT_LT(HandRatio(pi, e), kEllipsoidPriorRatio);
  const EllipsoidParameters theta = EllipsoidParametersFromInertialParameters(pi, e);
  EXPECT_LT((InertialParametersFromEllipsoidParameters(theta, e) - pi).norm(), 1e-13 * pi.norm());
  // Against central differences (error O(h²)), here and at another point.
  for (const EllipsoidParameters& at :
       {theta,
        EllipsoidParameters(
            (EllipsoidParameters() << 0.3, -1, 0.5, 2, -0.7, 1.5, 0.2, -2, 0.9, 3).finished())}) {
    const Eigen::Matrix<double, 10, 10> D =
        InertialParametersFromEllipsoidParametersJacobian(at, e);
    const double h = 1e-6;
    for (int k = 0; k < 10; ++k) {
      EllipsoidParameters plus = at, minus = at;
      plus[k] += h;
      minus[k] -= h;
      const InertialParameters fd = (InertialParametersFromEllipsoidParameters(plus, e) -
                                     InertialParametersFromEllipsoidParameters(minus, e)) /
                                    (2 * h);
      EXPECT_LT((D.col(k) - fd).norm(), 1e-8 * (1 + fd.norm())) << "column " << k;
    }
  }
}

// Every θ is a density inside E: 1 000 seeded draws, each coordinate in [−3, 3] (so v reaches
// e³ ≈ 20 and w comes within 0.1% of the boundary, and the mass spans e^±6).
TEST(IdentifyEllipsoidTest, EveryPointIsABodyInsideItsEllipsoid) {
  const BoundingEllipsoid e =
      Ellipsoid({-0.1, 0.2, 0.05}, Turned(), Eigen::Vector3d(0.25, 0.04, 0.12));
  std::mt19937 rng(2018);
  std::uniform_real_distribution<double> any(-3, 3);
  double largest = 0;
  for (int i = 0; i < 1000; ++i) {
    EllipsoidParameters theta;
    for (int k = 0; k < 10; ++k) theta[k] = any(rng);
    const InertialParameters pi = InertialParametersFromEllipsoidParameters(theta, e);
    const double ratio = HandRatio(pi, e);
    largest = std::max(largest, ratio);
    EXPECT_LE(ratio, 1 + 1e-12) << i;
    EXPECT_TRUE(IsConsistentBody(pi, 1e-9)) << i;
    EXPECT_NEAR(pi[0], std::exp(2 * theta[0]), 1e-12 * pi[0]) << i;  // m = e^{2α}
    EXPECT_NEAR(EllipsoidRatioOf(pi, e), ratio, 1e-9) << i;
  }
  EXPECT_GT(largest, 0.9);  // the draws reach near the boundary, not only its middle
}

// The minimum-volume ellipsoid of a box a × b × c has semi-axes √3/2·(a, b, c) along its edges
// (hand: by symmetry it is axis-aligned; volume ∝ s1·s2·s3 with the corner (a/2, b/2, c/2) on
// it, Σ (a_i/2)²/s_i² = 1, least when each term is 1/3). A uniform box's Σ = m/12·diag(a², b², c²)
// then gives tr(Q⁻¹Σ)/m = Σ_i (a_i²/12)/(3a_i²/4) = 3 · 1/9 = 1/3 exactly.
TEST(IdentifyEllipsoidTest, AUniformBoxLiesInsideItsBoundingEllipsoid) {
  const Eigen::Vector3d size(0.4, 0.1, 0.06), p(0.3, -0.05, 0.02);
  const Eigen::Matrix3d R = Turned();
  const InertialParameters box = UniformBox(2.5, size, p, R);
  const BoundingEllipsoid hand = Ellipsoid(p, R, std::sqrt(3.0) / 2 * size);
  EXPECT_NEAR(HandRatio(box, hand), 1.0 / 3, 1e-12);
  EXPECT_NEAR(EllipsoidRatioOf(box, hand), 1.0 / 3, 1e-12);
  // The same box as a link's collision geometry, read from URDF: BodyBoundingEllipsoids'
  // ellipsoid (Khachiyan's, stopped near the least volume and grown to hold every corner).
  const Eigen::Vector3d rpy = R.eulerAngles(2, 1, 0).reverse();  // roll, pitch, yaw
  char origin[200];
  std::snprintf(origin, sizeof origin, "<origin xyz='%.17g %.17g %.17g' rpy='%.17g %.17g %.17g'/>",
                p[0], p[1], p[2], rpy[0], rpy[1], rpy[2]);
  const std::string urdf =
      OneBodyRobot(std::string(origin) + "<geometry><box size='0.4 0.1 0.06'/></geometry>");
  const ReadResult read = ReadModelString(urdf, "box.urdf");
  ASSERT_TRUE(read.ok() && read.models.size() == 1);
  const KinematicTreeResult made = MakeKinematicTree(read.models[0]);
  ASSERT_TRUE(made.tree.has_value()) << made.error;
  const std::vector<std::optional<BoundingEllipsoid>> found =
      BodyBoundingEllipsoids(read.models[0], *made.tree);
  ASSERT_EQ(found.size(), 1u);
  ASSERT_TRUE(found[0].has_value());
  EXPECT_LT((found[0]->x0 - p).norm(), 1e-3 * size.norm());
  // Q⁻¹ within 2% of the hand ellipsoid's (Khachiyan's tolerance: within a few per mille of the
  // least volume), and the box's ratio within 2% of 1/3.
  EXPECT_LT((found[0]->Q_inverse - hand.Q_inverse).norm(), 0.02 * hand.Q_inverse.norm());
  EXPECT_NEAR(EllipsoidRatioOf(box, *found[0]), 1.0 / 3, 0.02 / 3);
  // Every corner of the box is inside it.
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d s((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1);
    const Eigen::Vector3d d = p + R * (0.5 * s.cwiseProduct(size)) - found[0]->x0;
    EXPECT_LE(d.dot(found[0]->Q_inverse * d), 1 + 1e-9) << k;
  }
}

// A prior outside its ellipsoid is contracted about x0: a uniform box of twice the size (ratio
// 4 · 1/3, above) in the hand ellipsoid of the box, moved to ratio 0.99 by k = √(0.99 / (4/3)):
// its mass kept, its center of mass x0 + k·(c − x0), its central second moment k²·Σ.
TEST(IdentifyEllipsoidTest, APriorOutsideIsContractedAboutTheCenter) {
  const Eigen::Vector3d size(0.4, 0.1, 0.06), x0(0.3, -0.05, 0.02);
  const BoundingEllipsoid hand =
      Ellipsoid(x0, Eigen::Matrix3d::Identity(), std::sqrt(3.0) / 2 * size);
  const Eigen::Vector3d c = x0 + Eigen::Vector3d(0.01, 0.005, 0);
  const InertialParameters big = UniformBox(2.5, 2 * size, c, Eigen::Matrix3d::Identity());
  const double r = HandRatio(big, hand);  // 4/3 + d·Q⁻¹·d
  EXPECT_GT(r, 4.0 / 3);
  const InertialParameters moved = InertialParametersFromEllipsoidParameters(
      EllipsoidParametersFromInertialParameters(big, hand), hand);
  const double k = std::sqrt(0.99 / r);
  const InertialParameters expected =
      UniformBox(2.5, 2 * k * size, x0 + k * (c - x0), Eigen::Matrix3d::Identity());
  EXPECT_LT((moved - expected).norm(), 1e-12 * expected.norm());
  EXPECT_NEAR(HandRatio(moved, hand), 0.99, 1e-12);
}

// A welded link's geometry counts, posed through its fixed joint; a welded frame without mass or
// geometry adds nothing; a welded link with mass and no geometry makes the body's unknown, as does
// a mesh that is not read.
TEST(IdentifyEllipsoidTest, WeldedLinksGeometryCountsAndUnknownGeometryIsNone) {
  const auto arm = [](const std::string& welded) {
    return "<robot name='r'><link name='base'/><link name='arm'><inertial><mass value='1'/>"
           "<inertia ixx='1e-3' iyy='1e-3' izz='1e-3' ixy='0' ixz='0' iyz='0'/></inertial>"
           "<collision><origin xyz='0.1 0 0'/><geometry><box size='0.2 0.04 0.04'/></geometry>"
           "</collision></link>" +
           welded +
           "<joint name='j' type='revolute'><parent link='base'/><child link='arm'/>"
           "<axis xyz='0 0 1'/><limit lower='-1' upper='1' effort='1' velocity='1'/></joint>"
           "<joint name='w' type='fixed'><parent link='arm'/><child link='tool'/>"
           "<origin xyz='0.2 0 0' rpy='0 1.5707963267948966 0'/></joint></robot>";
  };
  const auto ellipsoid = [](const std::string& urdf) {
    const ReadResult read = ReadModelString(urdf, "arm.urdf");
    EXPECT_TRUE(read.ok() && read.models.size() == 1);
    const KinematicTreeResult made = MakeKinematicTree(read.models.at(0));
    EXPECT_TRUE(made.tree.has_value()) << made.error;
    return BodyBoundingEllipsoids(read.models.at(0), *made.tree).at(0);
  };
  // The tool: a 0.1 m cube whose center is 0.05 m beyond the flange along the tool's z, which
  // the rpy turns onto the arm's x: its far corners are at x = 0.3 in the arm's frame.
  const std::optional<BoundingEllipsoid> with_tool = ellipsoid(
      arm("<link name='tool'><collision><origin xyz='0 0 0.05'/><geometry><box size='0.1 0.1 0.1'/>"
          "</geometry></collision></link>"));
  ASSERT_TRUE(with_tool.has_value());
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d s((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1);
    const Eigen::Vector3d arm_corner =
        Eigen::Vector3d(0.1, 0, 0) + s.cwiseProduct(Eigen::Vector3d(0.1, 0.02, 0.02));
    const Eigen::Vector3d tool_corner = Eigen::Vector3d(0.25, 0, 0) + 0.05 * s;
    for (const Eigen::Vector3d& corner : {arm_corner, tool_corner}) {
      const Eigen::Vector3d d = corner - with_tool->x0;
      EXPECT_LE(d.dot(with_tool->Q_inverse * d), 1 + 1e-9) << corner.transpose();
    }
  }
  const std::optional<BoundingEllipsoid> frame_only = ellipsoid(arm("<link name='tool'/>"));
  ASSERT_TRUE(frame_only.has_value());
  EXPECT_NEAR(frame_only->x0.x(), 0.1, 1e-3);  // the arm's box alone, centered at x = 0.1
  EXPECT_FALSE(ellipsoid(arm("<link name='tool'><inertial><mass value='0.3'/><inertia ixx='1e-4' "
                             "iyy='1e-4' izz='1e-4' ixy='0' ixz='0' iyz='0'/></inertial></link>"))
                   .has_value());
  EXPECT_FALSE(ellipsoid(arm("<link name='tool'><visual><geometry><mesh filename='tool.stl'/>"
                             "</geometry></visual></link>"))
                   .has_value());
}

// A mesh read through MakeLinkPointsFunction: testdata/mesh/box_ascii.stl, the 0.1 × 0.2 × 0.3 m
// box with a corner at its origin (mesh_loader_test), scaled by 3 along x: a 0.3 × 0.2 × 0.3 box
// centered at (0.15, 0.1, 0.15), whose hand ellipsoid has semi-axes √3/2 times its sides (above).
// Without a points function the mesh is not read: no ellipsoid.
TEST(IdentifyEllipsoidTest, AMeshIsReadThroughThePointsFunction) {
  const std::string urdf =
      OneBodyRobot("<geometry><mesh filename='" + std::string(MASSPROPS_TESTDATA_DIR) +
                   "/mesh/box_ascii.stl' scale='3 1 1'/></geometry>");
  const ReadResult read = ReadModelString(urdf, "mesh.urdf");
  ASSERT_TRUE(read.ok() && read.models.size() == 1);
  const KinematicTreeResult made = MakeKinematicTree(read.models[0]);
  ASSERT_TRUE(made.tree.has_value()) << made.error;
  MeshResolveOptions resolve;
  const std::optional<BoundingEllipsoid> found =
      BodyBoundingEllipsoids(read.models[0], *made.tree, MakeLinkPointsFunction(resolve)).at(0);
  ASSERT_TRUE(found.has_value());
  const Eigen::Vector3d size(0.3, 0.2, 0.3);
  const BoundingEllipsoid hand = Ellipsoid(Eigen::Vector3d(0.15, 0.1, 0.15),
                                           Eigen::Matrix3d::Identity(), std::sqrt(3.0) / 2 * size);
  EXPECT_LT((found->x0 - hand.x0).norm(), 1e-3 * size.norm());
  EXPECT_LT((found->Q_inverse - hand.Q_inverse).norm(), 0.02 * hand.Q_inverse.norm());
  EXPECT_FALSE(BodyBoundingEllipsoids(read.models[0], *made.tree).at(0).has_value());
}

// ---------------------------------------------------------------- the fit

struct PlanarArm {
  Model model;
  KinematicTree file;
  std::vector<std::optional<BoundingEllipsoid>> ellipsoids;
};

PlanarArm ReadPlanarArm() {
  PlanarArm arm;
  const ReadResult read =
      ReadModelFile(std::string(MASSPROPS_TESTDATA_DIR) + "/identify/planar_arm_boxes.urdf");
  EXPECT_TRUE(read.ok() && read.models.size() == 1);
  arm.model = read.models.at(0);
  const KinematicTreeResult made = MakeKinematicTree(arm.model);
  EXPECT_TRUE(made.tree.has_value()) << made.error;
  arm.file = *made.tree;
  arm.ellipsoids = BodyBoundingEllipsoids(arm.model, arm.file);
  return arm;
}

// N samples of exciting_motion.h's trajectory at 100 Hz, τ of `truth` by the RNEA plus seeded
// Gaussian noise σ.
OrderedTrajectory Simulate(const KinematicTree& truth, int N, double noise, unsigned seed) {
  OrderedTrajectory data =
      test_support::SumOfSines(test_support::ExcitingMotion(), truth.size(), N);
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0, noise);
  for (int k = 0; k < N; ++k) {
    const Eigen::VectorXd tau = CalcInverseDynamics(
        truth, data.q.row(k).transpose(), data.dq.row(k).transpose(), data.ddq.row(k).transpose());
    for (int j = 0; j < truth.size(); ++j) data.tau(k, j) = tau[j] + gauss(rng);
  }
  return data;
}

// The boxes' ellipsoids hold the file's values and the true arm (hand ratios below 1: the
// header of planar_arm_boxes.urdf); the fit with the bound is consistent, inside each ellipsoid,
// and predicts the held-out torques as well as the fit without it (within 3%).
TEST(IdentifyEllipsoidTest, PlanarArmFitStaysInsideItsBoxesAndPredictsAsWell) {
  const PlanarArm arm = ReadPlanarArm();
  ASSERT_EQ(arm.ellipsoids.size(), 2u);
  ASSERT_TRUE(arm.ellipsoids[0].has_value() && arm.ellipsoids[1].has_value());
  const KinematicTree truth = test_support::TruePlanarArm(arm.file);
  for (int b = 0; b < 2; ++b) {
    EXPECT_LT(HandRatio(truth.bodies[b].pi_BBo_B, *arm.ellipsoids[b]), 1) << b;
    EXPECT_LT(HandRatio(arm.file.bodies[b].pi_BBo_B, *arm.ellipsoids[b]), 1) << b;
  }
  const OrderedTrajectory data = Simulate(truth, 800, 0.05, 2018);
  IdentifyOptions bounded;
  bounded.ellipsoids = arm.ellipsoids;
  IdentifyOptions off = bounded;
  off.geometry_bound = false;
  const IdentifyResult with = Identify(arm.file, data, bounded);
  const IdentifyResult without = Identify(arm.file, data, off);
  EXPECT_EQ(with.geometry_bound_links, 2);
  EXPECT_EQ(without.geometry_bound_links, 0);
  for (int b = 0; b < 2; ++b) {
    const BodyEstimate& e = with.bodies[static_cast<std::size_t>(b)];
    EXPECT_TRUE(e.geometry_bound) << b;
    EXPECT_TRUE(e.identified_consistent) << b;
    EXPECT_LE(HandRatio(e.identified, *arm.ellipsoids[b]), 1) << b;
    EXPECT_NEAR(e.identified_ellipsoid_ratio, HandRatio(e.identified, *arm.ellipsoids[b]), 1e-9);
    EXPECT_FALSE(without.bodies[static_cast<std::size_t>(b)].geometry_bound) << b;
  }
  for (int j = 0; j < 2; ++j) {
    EXPECT_LT(with.rms_identified[j], 1.03 * without.rms_identified[j]) << j;
    EXPECT_LT(with.rms_identified[j], 1.2 * 0.05) << j;  // about the noise σ = 0.05 N·m
  }
  std::printf(
      "held-out RMS with the bound %.6g %.6g, without %.6g %.6g; ratios %.4g %.4g; "
      "%d and %d iterations\n",
      with.rms_identified[0], with.rms_identified[1], without.rms_identified[0],
      without.rms_identified[1], with.bodies[0].identified_ellipsoid_ratio,
      with.bodies[1].identified_ellipsoid_ratio, with.solver_iterations, without.solver_iterations);
}

// Both ellipsoids shrunk to 0.45 of their size about their centers (Q⁻¹ / 0.45²: every ratio
// grows by 1/0.45² ≈ 4.9), so that the true arm and least squares lie outside (hand ratios
// above 1, counted). The planar data do not see the out-of-plane spread (y), so a body inside
// still fits them: the bounded fit is consistent, inside both, and predicts the held-out
// torques within 3% of the free fit (measured: the same to 1e-5 N·m).
TEST(IdentifyEllipsoidTest, ShrunkEllipsoidsCountLeastSquaresOutsideAndTheFitStaysInside) {
  const PlanarArm arm = ReadPlanarArm();
  const KinematicTree truth = test_support::TruePlanarArm(arm.file);
  const OrderedTrajectory data = Simulate(truth, 800, 0.05, 2018);
  IdentifyOptions options;
  options.ellipsoids = arm.ellipsoids;
  for (std::optional<BoundingEllipsoid>& e : options.ellipsoids) e->Q_inverse /= 0.45 * 0.45;
  const IdentifyResult r = Identify(arm.file, data, options);
  IdentifyOptions off = options;
  off.geometry_bound = false;
  const IdentifyResult free_fit = Identify(arm.file, data, off);
  EXPECT_EQ(r.least_squares_outside_geometry_links, 2);
  for (int b = 0; b < 2; ++b) {
    const BoundingEllipsoid& e = *options.ellipsoids[static_cast<std::size_t>(b)];
    const BodyEstimate& body = r.bodies[static_cast<std::size_t>(b)];
    EXPECT_GT(HandRatio(truth.bodies[static_cast<std::size_t>(b)].pi_BBo_B, e), 1) << b;
    EXPECT_GT(HandRatio(body.least_squares, e), 1) << b;
    EXPECT_FALSE(body.least_squares_within_geometry) << b;
    EXPECT_LE(HandRatio(body.identified, e), 1) << b;
    EXPECT_TRUE(body.identified_consistent) << b;
  }
  for (int j = 0; j < 2; ++j) EXPECT_LT(r.rms_identified[j], 1.03 * free_fit.rms_identified[j]);
}

// A forearm ellipsoid too small for the true forearm: a ball of radius s = 3 cm around its true
// center of mass, 0.24 m from the elbow. Hand: the data determine its first moment
// ∫x dm = m2·lc2 = 0.24 kg·m and its inertia about the elbow axis ∫(x² + z²) dm = I2 + m2·lc2² =
// 0.0696 kg·m² (base parameters of the planar arm: Khalil and Dombre 2002, §12.4), so
// ∫|p − x0|² dm >= 0.0696 − 2·0.24·0.24 + 0.24²·m = 0.0576·m − 0.0456, which the condition
// (tr(Q⁻¹·...) <= m: ∫|p − x0|² dm <= m·s²) allows only for m <= 0.804 kg; but a center of mass
// inside the ball, c = 0.24/m within 0.03 of 0.24, needs m >= 0.889 kg. No body inside meets
// the data: least squares lies outside (counted); the bounded fit does not, and pays for it in
// held-out torque error (measured: 0.150 and 0.102 N·m against 0.053 and 0.050 without it).
TEST(IdentifyEllipsoidTest, AnEllipsoidTooSmallForTheTruthBindsTheFit) {
  const PlanarArm arm = ReadPlanarArm();
  const KinematicTree truth = test_support::TruePlanarArm(arm.file);
  const OrderedTrajectory data = Simulate(truth, 800, 0.05, 2018);
  IdentifyOptions options;
  options.ellipsoids = {std::nullopt, Ellipsoid({0.24, 0, 0}, Eigen::Matrix3d::Identity(),
                                                Eigen::Vector3d::Constant(0.03))};
  EXPECT_GT(HandRatio(truth.bodies[1].pi_BBo_B, *options.ellipsoids[1]), 1);
  const IdentifyResult r = Identify(arm.file, data, options);
  EXPECT_EQ(r.geometry_bound_links, 1);
  EXPECT_FALSE(r.bodies[0].geometry_bound);
  ASSERT_TRUE(r.bodies[1].geometry_bound);
  EXPECT_FALSE(r.bodies[1].least_squares_within_geometry);
  EXPECT_EQ(r.least_squares_outside_geometry_links, 1);
  EXPECT_GT(r.bodies[1].least_squares_ellipsoid_ratio, 1);
  EXPECT_LE(HandRatio(r.bodies[1].identified, *options.ellipsoids[1]), 1);
  EXPECT_GT(r.bodies[1].identified[0], 0);
  // Not asked: that it is a consistent body to IsConsistentBody's tolerance. Here the fit ends at
  // a point mass (J singular, the edge of consistency), whose coordinates are at infinity
  // (docs/identify.md, "Caveats").
  IdentifyOptions off = options;
  off.geometry_bound = false;
  const IdentifyResult free_fit = Identify(arm.file, data, off);
  EXPECT_GT(r.rms_identified.norm(), free_fit.rms_identified.norm());
  std::printf(
      "too small: held-out RMS %.6g %.6g (without the bound %.6g %.6g), least squares "
      "ratio %.4g, identified %.4g\n",
      r.rms_identified[0], r.rms_identified[1], free_fit.rms_identified[0],
      free_fit.rms_identified[1], r.bodies[1].least_squares_ellipsoid_ratio,
      r.bodies[1].identified_ellipsoid_ratio);
}

}  // namespace
}  // namespace massprops

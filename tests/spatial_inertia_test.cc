// Tests of SpatialInertia<T>. Expected values are hand-derived (parallel-axis theorem, particle
// sums, the two-particle reduced-mass formula) or textbook (box, sphere), cited per test.

#include "massprops/core/spatial_inertia.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

#include "test_shapes.h"

namespace massprops {
namespace {

using test_support::RandomRotation;

using M = SpatialInertia<double>;
using G = UnitInertia<double>;
using I3 = RotationalInertia<double>;
using V = Vector3<double>;
constexpr double kEps = std::numeric_limits<double>::epsilon();

TEST(SpatialInertiaTest, DefaultIsNaNAndSetNaNMakesNaN) {
  EXPECT_TRUE(M().IsNaN());
  EXPECT_TRUE(M::NaN().IsNaN());
  M m = M::MakeUnitary();
  EXPECT_FALSE(m.IsNaN());
  m.SetNaN();
  EXPECT_TRUE(m.IsNaN());
  EXPECT_FALSE(m.IsPhysicallyValid());
}

TEST(SpatialInertiaTest, ConstructorStoresMassComAndUnitInertia) {
  const G G_SP = G::SolidSphere(1).ShiftFromCenterOfMass(V(-1, 0, 0));
  const M m(2.0, V(1, 0, 0), G_SP);
  EXPECT_EQ(m.get_mass(), 2.0);
  EXPECT_EQ(m.get_com(), V(1, 0, 0));
  EXPECT_EQ(m.get_unit_inertia(), G_SP);
  EXPECT_EQ(m.CalcComMoment(), V(2, 0, 0));
  EXPECT_EQ(m.CalcRotationalInertia(), I3(0.8, 2.8, 2.8));  // 2·(0.4, 1.4, 1.4).
}

TEST(SpatialInertiaTest, MakeFromCentralInertiaAppliesTheParallelAxisTheorem) {
  // Solid sphere, m = 2, r = 1: central 2/5·m·r² = 0.8 (textbook). Center of mass at (0, 0, 3)
  // from P: I_P = 0.8 + m·(|c|²·1 − c·cᵀ) = (0.8 + 18, 0.8 + 18, 0.8) (hand-derived).
  const M m = M::MakeFromCentralInertia(2, V(0, 0, 3), I3(0.8, 0.8, 0.8));
  EXPECT_TRUE(m.CalcRotationalInertia().IsNearlyEqualTo(I3(18.8, 18.8, 0.8), 4 * kEps));
  EXPECT_TRUE(m.IsPhysicallyValid());
  // Products appear off the axes: c = (1, 2, 0), m = 1, central zero (a particle):
  // Ixy = −m·x·y = −2.
  const M particle = M::MakeFromCentralInertia(1, V(1, 2, 0), I3(0, 0, 0));
  EXPECT_EQ(particle.CalcRotationalInertia(), I3(4, 1, 5, -2, 0, 0));
  EXPECT_EQ(M::PointMass(1, V(1, 2, 0)).CalcRotationalInertia(), I3(4, 1, 5, -2, 0, 0));
  // Zero mass: the unit inertia is the point-mass one, and the body is valid.
  const M massless = M::MakeFromCentralInertia(0, V(1, 2, 0), I3(0, 0, 0));
  EXPECT_TRUE(massless.IsPhysicallyValid());
  EXPECT_TRUE(massless.CalcRotationalInertia().IsZero());
}

TEST(SpatialInertiaTest, FactoriesMakeUnitaryAndZero) {
  const M unit = M::MakeUnitary();
  EXPECT_EQ(unit.get_mass(), 1);
  EXPECT_EQ(unit.get_com(), V::Zero());
  EXPECT_EQ(unit.get_unit_inertia(), G(1, 1, 1));
  const M zero = M::Zero();
  EXPECT_EQ(zero.get_mass(), 0);
  EXPECT_TRUE(zero.get_unit_inertia().IsZero());
  EXPECT_TRUE(zero.IsPhysicallyValid());
}

TEST(SpatialInertiaTest, ValidityIsDecidedAtTheCenterOfMass) {
  // G_SP = (1, 1, 1) is a valid inertia, but with the center of mass at (1, 0, 0) the central
  // G_SScm = G_SP − (y² + z², x² + z², x² + y²) = (1, 0, 0), which is not (0 + 0 < 1).
  const M m(1.0, V(1, 0, 0), G(1, 1, 1), true);
  EXPECT_TRUE(m.get_unit_inertia().CouldBePhysicallyValid());
  EXPECT_FALSE(m.IsPhysicallyValid());
  const std::string why = m.CriticizeNotPhysicallyValid();
  EXPECT_NE(why.find("center of mass"), std::string::npos) << why;
  EXPECT_NE(why.find("triangle inequality"), std::string::npos) << why;
  // With the center of mass at P it is valid.
  EXPECT_TRUE(M(1.0, V::Zero(), G(1, 1, 1)).IsPhysicallyValid());
  EXPECT_EQ(M(1.0, V::Zero(), G(1, 1, 1)).CriticizeNotPhysicallyValid(), "");
}

TEST(SpatialInertiaTest, BadMassOrComIsInvalidAndNamed) {
  const double inf = std::numeric_limits<double>::infinity();
  const M negative(-1.0, V::Zero(), G(1, 1, 1), true);
  EXPECT_FALSE(negative.IsPhysicallyValid());
  EXPECT_NE(negative.CriticizeNotPhysicallyValid().find("The mass -1"), std::string::npos);
  EXPECT_FALSE(M(NAN, V::Zero(), G(1, 1, 1), true).IsPhysicallyValid());
  EXPECT_FALSE(M(inf, V::Zero(), G(1, 1, 1), true).IsPhysicallyValid());
  const M far(1.0, V(inf, 0, 0), G(1, 1, 1), true);
  EXPECT_FALSE(far.IsPhysicallyValid());
  EXPECT_NE(far.CriticizeNotPhysicallyValid().find("center of mass"), std::string::npos);
}

#ifndef NDEBUG
TEST(SpatialInertiaTest, ConstructorThrowsForInvalidInDebugBuildsUnlessSkipped) {
  EXPECT_THROW(M(-1.0, V::Zero(), G(1, 1, 1)), std::logic_error);
  EXPECT_THROW(M(1.0, V(1, 0, 0), G(1, 1, 1)), std::logic_error);
  EXPECT_NO_THROW(M(1.0, V(1, 0, 0), G(1, 1, 1), true));
  EXPECT_THROW(M::MakeFromCentralInertia(-2, V::Zero(), I3(1, 1, 1)), std::logic_error);
}
#endif

TEST(SpatialInertiaTest, RotatedThinRodFarFromThePointStaysValid) {
  // A thin rod (on the boundary) whose center of mass is 1e3 rod lengths from P: the shift to
  // the center of mass loses digits relative to the inertia about P; the test allows for that.
  std::mt19937_64 generator(31);
  for (int k = 0; k < 1000; ++k) {
    const Matrix3<double> R = RandomRotation<double>(&generator);
    const V com = 1e3 * R.col(1);
    const G rod = G::ThinRod(1, R.col(0));
    const M m(3.0, com, rod.ShiftFromCenterOfMass(-com));
    ASSERT_TRUE(m.IsPhysicallyValid()) << m.CriticizeNotPhysicallyValid();
    const M disk(3.0, com, G::ThinDisk(1, R.col(2)).ShiftFromCenterOfMass(-com));
    ASSERT_TRUE(disk.IsPhysicallyValid()) << disk.CriticizeNotPhysicallyValid();
  }
}

TEST(SpatialInertiaTest, ExplicitToleranceIsRelative) {
  // Central unit inertia (1, 1, 2.0001): beyond the disk boundary by 1e-4/4.0001 ≈ 2.5e-5 of the
  // trace: fails 1e-6, passes 1e-4.
  const M m(2.0, V::Zero(),
            G(RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(1, 1, 2.0001, 0, 0, 0,
                                                                             true)),
            true);
  EXPECT_FALSE(m.IsPhysicallyValid(1e-6));
  EXPECT_TRUE(m.IsPhysicallyValid(1e-4));
  EXPECT_EQ(m.CriticizeNotPhysicallyValid(1e-4), "");
  EXPECT_NE(m.CriticizeNotPhysicallyValid(1e-6), "");
}

TEST(SpatialInertiaTest, PseudoInertiaOfPointMassAndBox) {
  // Particle m at c: Σ_P = ∫r·rᵀ dm = m·c·cᵀ, so J = m·[[c·cᵀ, c], [cᵀ, 1]] (hand-derived).
  const V c(1, 2, 3);
  const Matrix4<double> J = M::PointMass(2, c).CalcPseudoInertia();
  Matrix4<double> expected;
  expected.topLeftCorner<3, 3>() = 2 * c * c.transpose();
  expected.topRightCorner<3, 1>() = 2 * c;
  expected.bottomLeftCorner<1, 3>() = 2 * c.transpose();
  expected(3, 3) = 2;
  EXPECT_TRUE(J.isApprox(expected, 4 * kEps));
  // Solid box a × b × c about its center: ∫x² dm = m·a²/12 etc., no cross terms (textbook
  // second moments of a uniform interval).
  const M box = M::MakeFromCentralInertia(6, V::Zero(), G::SolidBox(1, 2, 3) * 6.0);
  const Matrix4<double> Jbox = box.CalcPseudoInertia();
  EXPECT_NEAR(Jbox(0, 0), 6 * 1.0 / 12, 1e-15);
  EXPECT_NEAR(Jbox(1, 1), 6 * 4.0 / 12, 1e-15);
  EXPECT_NEAR(Jbox(2, 2), 6 * 9.0 / 12, 1e-14);
  EXPECT_EQ(Jbox(0, 1), 0);
  EXPECT_EQ(Jbox(3, 3), 6);
  EXPECT_TRUE((Jbox.topRightCorner<3, 1>().isZero(0)));
}

TEST(SpatialInertiaTest, PseudoInertiaIsIndefiniteExactlyForInvalidBodies) {
  const M valid = M::MakeFromCentralInertia(2, V(0.5, -1, 2), I3(1, 2, 2.5));
  const M invalid(1.0, V(1, 0, 0), G(1, 1, 1), true);  // Central (1, 0, 0): see above.
  const auto min_eigenvalue = [](const Matrix4<double>& J) {
    return Eigen::SelfAdjointEigenSolver<Matrix4<double>>(J).eigenvalues()(0);
  };
  EXPECT_GE(min_eigenvalue(valid.CalcPseudoInertia()), -1e-12);
  EXPECT_LT(min_eigenvalue(invalid.CalcPseudoInertia()), -0.1);
}

TEST(SpatialInertiaTest, CopyToFullMatrix6HasDrakesLayout) {
  // Particle m = 2 at c = (1, 0, 0): I_P = (0, 2, 2), m·[c]× = 2·[[0, 0, 0], [0, 0, −1], [0, 1,
  // 0]].
  const Eigen::Matrix<double, 6, 6> K = M::PointMass(2, V(1, 0, 0)).CopyToFullMatrix6();
  EXPECT_EQ(K(1, 1), 2);
  EXPECT_EQ(K(0, 0), 0);
  EXPECT_EQ(K(1, 5), -2);  // top-right (1, 2) = −m·c_x.
  EXPECT_EQ(K(2, 4), 2);   // top-right (2, 1) = +m·c_x.
  EXPECT_EQ(K(4, 2), 2);   // bottom-left (1, 2) = −(m·[c]×)(1, 2) = +m·c_x.
  EXPECT_EQ(K(5, 1), -2);  // bottom-left (2, 1) = −m·c_x.
  EXPECT_EQ(K(3, 3), 2);
  EXPECT_TRUE(K.isApprox(K.transpose(), 0));
}

TEST(SpatialInertiaTest, ShiftMatchesBuildingAtTheNewPoint) {
  std::mt19937_64 generator(41);
  const I3 I_cm = (G::SolidBox(1, 2, 3) * 5.0).ReExpress(RandomRotation<double>(&generator));
  const V p_PScm(0.3, -0.2, 1.0);
  const M M_P = M::MakeFromCentralInertia(5, p_PScm, I_cm);
  const V p_PQ(2, 1, -1);
  const M M_Q = M_P.Shift(p_PQ);
  const M expected = M::MakeFromCentralInertia(5, p_PScm - p_PQ, I_cm);
  EXPECT_EQ(M_Q.get_mass(), 5);
  EXPECT_TRUE(M_Q.get_com().isApprox(p_PScm - p_PQ, 4 * kEps));
  EXPECT_TRUE(M_Q.CalcRotationalInertia().IsNearlyEqualTo(expected.CalcRotationalInertia(), 1e-14));
  // Round trip.
  M back = M_Q;
  back.ShiftInPlace(-p_PQ);
  EXPECT_TRUE(back.CalcRotationalInertia().IsNearlyEqualTo(M_P.CalcRotationalInertia(), 1e-14));
  EXPECT_TRUE(back.get_com().isApprox(p_PScm, 1e-15));
}

TEST(SpatialInertiaTest, ReExpressRotatesComAndInertia) {
  std::mt19937_64 generator(43);
  const I3 I_cm(1, 2, 2.5);
  const V com(1, 2, 3);
  const M spatial_E = M::MakeFromCentralInertia(2, com, I_cm);
  const Matrix3<double> R = RandomRotation<double>(&generator);
  const M spatial_A = spatial_E.ReExpress(R);
  const M expected = M::MakeFromCentralInertia(2, R * com, I_cm.ReExpress(R));
  EXPECT_TRUE(spatial_A.get_com().isApprox(R * com, 4 * kEps));
  EXPECT_TRUE(
      spatial_A.CalcRotationalInertia().IsNearlyEqualTo(expected.CalcRotationalInertia(), 1e-14));
  M in_place = spatial_E;
  in_place.ReExpressInPlace(R);
  EXPECT_TRUE(in_place.get_com() == spatial_A.get_com());
}

TEST(SpatialInertiaTest, AddingPointMassesMatchesTwoHandDerivations) {
  // 1 kg at (1, 0, 0) and 3 kg at (0, 2, 0), about the origin.
  M sum = M::PointMass(1, V(1, 0, 0));
  sum += M::PointMass(3, V(0, 2, 0));
  EXPECT_EQ(sum.get_mass(), 4);
  EXPECT_TRUE(sum.get_com().isApprox(V(0.25, 1.5, 0), 4 * kEps));  // (1·1 + 3·0, 1·0 + 3·2)/4.
  // About the origin: particle sums (0, 1, 1) + 3·(4, 0, 4) = (12, 1, 13), no products.
  EXPECT_TRUE(sum.CalcRotationalInertia().IsNearlyEqualTo(I3(12, 1, 13), 4 * kEps));
  // About the center of mass, two ways: (a) parallel-axis theorem from the origin,
  // I − 4·(|c|²·1 − c·cᵀ) with |c|² = 2.3125: (12 − 9, 1 − 0.25, 13 − 9.25, Ixy = +4·0.375);
  // (b) reduced mass μ = 1·3/4 and separation d = (−1, 2, 0): μ·(|d|²·1 − d·dᵀ) =
  // 0.75·(4, 1, 5) with Ixy = −0.75·(−2) = 1.5. Both give (3, 0.75, 3.75, 1.5, 0, 0).
  const I3 central = sum.CalcRotationalInertia().ShiftToCenterOfMass(4, sum.get_com());
  EXPECT_TRUE(central.IsNearlyEqualTo(I3(3, 0.75, 3.75, 1.5, 0, 0), 8 * kEps));
  EXPECT_TRUE(sum.IsPhysicallyValid());
  // Zero is the identity of +=, and a + b = b + a.
  EXPECT_TRUE((M::Zero() + sum)
                  .CalcRotationalInertia()
                  .IsNearlyEqualTo(sum.CalcRotationalInertia(), 4 * kEps));
  const M other_order = M::PointMass(3, V(0, 2, 0)) + M::PointMass(1, V(1, 0, 0));
  EXPECT_TRUE(
      other_order.CalcRotationalInertia().IsNearlyEqualTo(sum.CalcRotationalInertia(), 4 * kEps));
  // Two massless bodies: mass stays 0 and this body's com is kept.
  const M nothing = M::PointMass(0, V(1, 1, 1)) + M::PointMass(0, V(2, 2, 2));
  EXPECT_EQ(nothing.get_mass(), 0);
  EXPECT_EQ(nothing.get_com(), V(1, 1, 1));
}

TEST(SpatialInertiaTest, CastAndOtherScalarTypes) {
  const M m = M::MakeFromCentralInertia(2, V(1, 2, 3), I3(1, 2, 2.5));
  const SpatialInertia<float> f = m.cast<float>();
  EXPECT_EQ(f.get_mass(), 2.0f);
  EXPECT_EQ(f.get_com(), Vector3<float>(1, 2, 3));
  EXPECT_TRUE(f.IsPhysicallyValid());
  const SpatialInertia<long double> l = m.cast<long double>();
  EXPECT_TRUE(l.IsPhysicallyValid());
  EXPECT_EQ(static_cast<double>(l.get_unit_inertia()(0, 0)), m.get_unit_inertia()(0, 0));
  const SpatialInertia<long double> built = SpatialInertia<long double>::MakeFromCentralInertia(
      2, Vector3<long double>(1, 2, 3), RotationalInertia<long double>(1, 2, 2.5L));
  EXPECT_TRUE(l.CalcRotationalInertia().IsNearlyEqualTo(built.CalcRotationalInertia(), 1e-15L));
}

TEST(SpatialInertiaTest, HugeMassDoesNotOverflowTheValidityTest) {
  const M m = M::MakeFromCentralInertia(1e200, V(1, 0, 0), I3(1e200, 1e200, 2e200));
  EXPECT_TRUE(m.IsPhysicallyValid());
  EXPECT_NEAR(m.CalcRotationalInertia()(1, 1) / 1e200, 2, 1e-15);  // 1 + 1·1² per unit mass.
}

TEST(SpatialInertiaTest, PrintsMassComAndInertia) {
  std::ostringstream out;
  out << M::PointMass(2, V(1, 0, 0));
  EXPECT_EQ(out.str(),
            " mass = 2\n Center of mass = [1  0  0]\n Inertia about point P, I_BP =\n"
            " [0  0  0]\n [0  2  0]\n [0  0  2]\n");
}

}  // namespace
}  // namespace massprops

// Tests of RotationalInertia<T>. Expected values are hand-derived from the definitions
// Ixx = ∫(y²+z²) dm, Ixy (matrix entry) = −∫xy dm, or from the textbook formulas cited beside
// each test; none is produced by the code under test.

#include "massprops/core/rotational_inertia.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "test_shapes.h"

namespace massprops {
namespace {

using test_support::RandomRotation;

template <typename T>
constexpr T kEps = std::numeric_limits<T>::epsilon();

// R_z(θ): re-expresses a vector from E in A when A is E turned by θ about z... (used as a plain
// rotation matrix in the hand derivations below).
Matrix3<double> RotationZ(double theta) {
  Matrix3<double> R;
  R << std::cos(theta), -std::sin(theta), 0, std::sin(theta), std::cos(theta), 0, 0, 0, 1;
  return R;
}

RotationalInertia<double> Unchecked(double xx, double yy, double zz, double xy = 0, double xz = 0,
                                    double yz = 0) {
  return RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(xx, yy, zz, xy, xz, yz,
                                                                        true);
}

TEST(RotationalInertiaTest, DefaultConstructorGivesNaN) {
  const RotationalInertia<double> I;
  EXPECT_TRUE(I.IsNaN());
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) EXPECT_TRUE(std::isnan(I(i, j)));
  }
}

TEST(RotationalInertiaTest, MomentsConstructorHasZeroProducts) {
  const RotationalInertia<double> I(2, 3, 4);
  EXPECT_EQ(I.get_moments(), Vector3<double>(2, 3, 4));
  EXPECT_EQ(I.get_products(), Vector3<double>(0, 0, 0));
}

TEST(RotationalInertiaTest, SixEntryConstructorStoresMatrixEntries) {
  // Entries of the matrix [[5, -0.5, -1], [-0.5, 6, -0.75], [-1, -0.75, 7]] (negated convention).
  const RotationalInertia<double> I(5, 6, 7, -0.5, -1, -0.75);
  EXPECT_EQ(I.get_moments(), Vector3<double>(5, 6, 7));
  EXPECT_EQ(I.get_products(), Vector3<double>(-0.5, -1, -0.75));
  EXPECT_EQ(I(0, 1), -0.5);
  EXPECT_EQ(I(1, 0), -0.5);
  EXPECT_EQ(I(0, 2), -1);
  EXPECT_EQ(I(2, 0), -1);
  EXPECT_EQ(I(1, 2), -0.75);
  EXPECT_EQ(I(2, 1), -0.75);
  EXPECT_EQ(I(2, 2), 7);
}

TEST(RotationalInertiaTest, ParticleConstructorUsesNegatedProducts) {
  // Hand-derived from the definitions for m = 2 at p = (1, 2, 3):
  // Ixx = m(y²+z²) = 26, Iyy = m(x²+z²) = 20, Izz = m(x²+y²) = 10,
  // Ixy = −m·x·y = −4, Ixz = −m·x·z = −6, Iyz = −m·y·z = −12.
  const RotationalInertia<double> I(2.0, Vector3<double>(1, 2, 3));
  EXPECT_EQ(I.get_moments(), Vector3<double>(26, 20, 10));
  EXPECT_EQ(I.get_products(), Vector3<double>(-4, -6, -12));
}

TEST(RotationalInertiaTest, TriaxiallySymmetricHasEqualMomentsAndNoProducts) {
  const auto I = RotationalInertia<double>::TriaxiallySymmetric(3.5);
  EXPECT_EQ(I.get_moments(), Vector3<double>(3.5, 3.5, 3.5));
  EXPECT_TRUE(I.get_products().isZero(0));
}

TEST(RotationalInertiaTest, MakeFromMomentsAndProductsChecksValidityUnlessSkipped) {
  // (1, 1, 3): 1 + 1 < 3 violates the triangle inequality.
  EXPECT_NO_THROW(
      RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(1, 1, 3, 0, 0, 0, true));
  try {
    RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(1, 1, 3, 0, 0, 0);
    FAIL() << "expected std::logic_error";
  } catch (const std::logic_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("The rotational inertia"), std::string::npos) << message;
    EXPECT_NE(message.find("I(0,0)=1, I(1,1)=1, I(2,2)=3"), std::string::npos) << message;
    EXPECT_NE(message.find("I(0,1)=0, I(0,2)=0, I(1,2)=0"), std::string::npos) << message;
    EXPECT_NE(message.find("principal moments: [1  1  3]"), std::string::npos) << message;
    EXPECT_NE(message.find("did not pass the test CouldBePhysicallyValid()"), std::string::npos)
        << message;
  }
  EXPECT_NO_THROW(RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(1, 1, 2, 0, 0, 0));
  EXPECT_THROW(RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(NAN, 1, 1, 0, 0, 0),
               std::logic_error);
}

TEST(RotationalInertiaTest, RowsAndColsAreThree) {
  EXPECT_EQ(RotationalInertia<double>::rows(), 3);
  EXPECT_EQ(RotationalInertia<float>::cols(), 3);
}

TEST(RotationalInertiaTest, TraceAndMaximumPossibleMoment) {
  const RotationalInertia<double> I(3, 4, 5, -0.5, 0.25, 0.125);
  EXPECT_EQ(I.Trace(), 12);
  EXPECT_EQ(I.CalcMaximumPossibleMomentOfInertia(), 6);
  // Halves are summed, so the maximum moment is finite where the trace overflows.
  const double big = std::numeric_limits<double>::max() / 2;
  const auto J = Unchecked(big, big, big);
  EXPECT_TRUE(std::isinf(J.Trace()));
  EXPECT_EQ(J.CalcMaximumPossibleMomentOfInertia(), 1.5 * big);
}

#ifndef NDEBUG
TEST(RotationalInertiaTest, ParenthesisOperatorRejectsOutOfRangeIndexInDebugBuilds) {
  const RotationalInertia<double> I(1, 1, 1);
  EXPECT_THROW(I(3, 0), std::logic_error);
  EXPECT_THROW(I(0, -1), std::logic_error);
}
#endif

TEST(RotationalInertiaTest, CopyToFullMatrix3IsSymmetric) {
  const RotationalInertia<double> I(5, 6, 7, -0.5, -1, -0.75);
  Matrix3<double> expected;
  expected << 5, -0.5, -1, -0.5, 6, -0.75, -1, -0.75, 7;
  EXPECT_EQ(I.CopyToFullMatrix3(), expected);
}

TEST(RotationalInertiaTest, IsNearlyEqualToUsesTheSmallerMaximumMoment) {
  // Imax = trace/2 = 3 for (2, 2, 2); a difference of 0.03 is 1% of Imax.
  const RotationalInertia<double> I(2, 2, 2);
  const RotationalInertia<double> J(2, 2, 2, 0.03, 0, 0);
  EXPECT_TRUE(I.IsNearlyEqualTo(J, 0.011));
  EXPECT_FALSE(I.IsNearlyEqualTo(J, 0.009));
  // (2, 2, 2.06): Imax = 3.03 vs 3; the smaller (3) is used: 0.06/3 = 2%.
  const RotationalInertia<double> K(2, 2, 2.06);
  EXPECT_TRUE(I.IsNearlyEqualTo(K, 0.0201));
  EXPECT_FALSE(I.IsNearlyEqualTo(K, 0.0199));
  EXPECT_FALSE(I.IsNearlyEqualTo(RotationalInertia<double>(), 1e9));
  EXPECT_TRUE(
      RotationalInertia<double>(0, 0, 0).IsNearlyEqualTo(RotationalInertia<double>(0, 0, 0), 0));
}

TEST(RotationalInertiaTest, ExactEqualityComparesAllSixEntries) {
  EXPECT_TRUE(RotationalInertia<double>(1, 2, 2, 0.1, 0, 0) ==
              RotationalInertia<double>(1, 2, 2, 0.1, 0, 0));
  EXPECT_TRUE(RotationalInertia<double>(1, 2, 2, 0.1, 0, 0) !=
              RotationalInertia<double>(1, 2, 2, 0, 0.1, 0));
  EXPECT_FALSE(RotationalInertia<double>() == RotationalInertia<double>());  // NaN.
}

TEST(RotationalInertiaTest, ArithmeticOperatorsActEntryByEntry) {
  // Every operand and result here is valid (Gershgorin discs of ½·tr·1 − I in [0, ∞)).
  const RotationalInertia<double> A(3, 4, 5, -0.5, 0.25, 0.125);
  const RotationalInertia<double> B(1, 1, 1, 0.25, 0, 0);
  EXPECT_EQ(A + B, RotationalInertia<double>(4, 5, 6, -0.25, 0.25, 0.125));
  EXPECT_EQ(A - B, RotationalInertia<double>(2, 3, 4, -0.75, 0.25, 0.125));
  RotationalInertia<double> C = A;
  C += B;
  EXPECT_EQ(C, A + B);
  C -= B;
  EXPECT_EQ(C, A);
  EXPECT_EQ(A * 2.0, RotationalInertia<double>(6, 8, 10, -1, 0.5, 0.25));
  EXPECT_EQ(2.0 * A, A * 2.0);
  EXPECT_EQ(A / 2.0, RotationalInertia<double>(1.5, 2, 2.5, -0.25, 0.125, 0.0625));
  C = A;
  C *= 4.0;
  C /= 2.0;
  EXPECT_EQ(C, A * 2.0);
  // [[3, -0.5, 0.25], [-0.5, 4, 0.125], [0.25, 0.125, 5]] · (1, 2, 3) =
  // (3 − 1 + 0.75, −0.5 + 8 + 0.375, 0.25 + 0.25 + 15), hand-multiplied.
  EXPECT_EQ(A * Vector3<double>(1, 2, 3), Vector3<double>(2.75, 7.875, 15.5));
  // Multiplying by zero gives zero, which is valid.
  EXPECT_TRUE((A * 0.0).IsZero());
}

TEST(RotationalInertiaTest, MultiplyByScalarSkipValidityCheckAcceptsNegativeScalars) {
  const RotationalInertia<double> A(2, 3, 4);
  const RotationalInertia<double> negated = A.MultiplyByScalarSkipValidityCheck(-1);
  EXPECT_EQ(negated.get_moments(), Vector3<double>(-2, -3, -4));
  EXPECT_FALSE(negated.CouldBePhysicallyValid());
}

#ifndef NDEBUG
TEST(RotationalInertiaTest, InvalidOperationsThrowInDebugBuilds) {
  const RotationalInertia<double> A(2, 3, 4);
  EXPECT_THROW(A * -1.0, std::logic_error);
  EXPECT_THROW(-1.0 * A, std::logic_error);
  EXPECT_THROW(A / 0.0, std::logic_error);
  EXPECT_THROW(A / -2.0, std::logic_error);
  EXPECT_THROW(A - RotationalInertia<double>(3, 3, 3), std::logic_error);  // (−1, 0, 1).
  EXPECT_THROW(RotationalInertia<double>(1, 1, 3), std::logic_error);
  EXPECT_THROW(RotationalInertia<double>(-1.0, Vector3<double>(1, 0, 0)), std::logic_error);
  // Shifting a unit point mass at distance 1 "to" its center of mass from a point where the
  // inertia is only (1, 1, 1): 1 − (|p|² − x²) etc. gives (1, 0, 0), invalid.
  EXPECT_THROW(RotationalInertia<double>(1, 1, 1).ShiftToCenterOfMass(1, Vector3<double>(1, 0, 0)),
               std::logic_error);
  try {
    (void)(A * -2.0);
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("negative or NaN scalar -2"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("I(0,0)=2"), std::string::npos) << e.what();
  }
}
#endif

TEST(RotationalInertiaTest, NaNZeroInfAndFinitePredicates) {
  RotationalInertia<double> I(1, 1, 1);
  EXPECT_FALSE(I.IsNaN());
  EXPECT_FALSE(I.IsZero());
  EXPECT_TRUE(I.IsFinite());
  I.SetZero();
  EXPECT_TRUE(I.IsZero());
  EXPECT_TRUE(I.CouldBePhysicallyValid());  // Zero inertia is valid (a particle at the point).
  I.SetToNaN();
  EXPECT_TRUE(I.IsNaN());
  EXPECT_FALSE(I.IsInf());
  EXPECT_FALSE(I.IsFinite());
  const auto J = Unchecked(1, 1, 1, 0, std::numeric_limits<double>::infinity(), 0);
  EXPECT_TRUE(J.IsInf());
  EXPECT_FALSE(J.IsNaN());
  EXPECT_FALSE(J.IsFinite());
}

TEST(RotationalInertiaTest, CastConvertsEveryEntry) {
  const RotationalInertia<double> I(0.1, 0.2, 0.25, -0.01, 0.02, -0.03);
  const RotationalInertia<float> If = I.cast<float>();
  EXPECT_EQ(If(0, 0), 0.1f);
  EXPECT_EQ(If(1, 2), -0.03f);
  const RotationalInertia<long double> Il = I.cast<long double>();
  EXPECT_EQ(Il(0, 2), static_cast<long double>(0.02));
  EXPECT_EQ(Il.cast<double>(), I);
}

TEST(RotationalInertiaTest, FromMatrixRequiresSymmetry) {
  Matrix3<double> M;
  M << 5, -0.5, -1, -0.5, 6, -0.75, -1, -0.75, 7;
  EXPECT_EQ(RotationalInertia<double>::FromMatrix(M),
            RotationalInertia<double>(5, 6, 7, -0.5, -1, -0.75));
  M(0, 1) = -0.75;
  EXPECT_THROW(RotationalInertia<double>::FromMatrix(M), std::logic_error);
  // Asymmetry within round-off (1 ulp of the largest entry) is accepted and averaged.
  M(0, 1) = -0.5 + 8 * kEps<double>;
  EXPECT_NO_THROW(RotationalInertia<double>::FromMatrix(M));
  // Symmetric but not physical: (1, 1, 3).
  const Matrix3<double> bad = Vector3<double>(1, 1, 3).asDiagonal();
  EXPECT_THROW(RotationalInertia<double>::FromMatrix(bad), std::logic_error);
  EXPECT_NO_THROW(RotationalInertia<double>::FromMatrix(bad, true));
}

TEST(RotationalInertiaTest, PrincipalMomentsAndAxesOfAKnownMatrix) {
  // [[5, -1, 0], [-1, 5, 0], [0, 0, 7]]: the xy block has eigenvalues 5 ∓ 1 with eigenvectors
  // (1, 1)/√2 (for 4) and (1, −1)/√2 (for 6); z is an eigenvector with 7 (hand-derived).
  const RotationalInertia<double> I(5, 5, 7, -1, 0, 0);
  for (PrincipalSolver solver : {PrincipalSolver::kAccurate, PrincipalSolver::kFast}) {
    const Vector3<double> moments = I.CalcPrincipalMomentsOfInertia(solver);
    EXPECT_NEAR(moments(0), 4, 1e-14);
    EXPECT_NEAR(moments(1), 6, 1e-14);
    EXPECT_NEAR(moments(2), 7, 1e-14);
    const auto [lambda, R] = I.CalcPrincipalMomentsAndAxesOfInertia(solver);
    EXPECT_NEAR(lambda(0), 4, 1e-14);
    const double s = 1 / std::sqrt(2.0);
    EXPECT_NEAR(std::abs(R.col(0).dot(Vector3<double>(s, s, 0))), 1, 1e-14);
    EXPECT_NEAR(std::abs(R.col(1).dot(Vector3<double>(s, -s, 0))), 1, 1e-14);
    EXPECT_NEAR(std::abs(R(2, 2)), 1, 1e-14);
    EXPECT_NEAR(R.determinant(), 1, 1e-14);  // Right-handed.
    EXPECT_TRUE((R * lambda.asDiagonal() * R.transpose()).isApprox(I.CopyToFullMatrix3(), 1e-14));
  }
}

TEST(RotationalInertiaTest, PrincipalAxesAreIdentityWhenMomentsAreEqual) {
  const auto [lambda, R] =
      RotationalInertia<double>(2, 2, 2).CalcPrincipalMomentsAndAxesOfInertia();
  EXPECT_EQ(lambda, Vector3<double>(2, 2, 2));
  EXPECT_EQ(R, Matrix3<double>::Identity());
}

TEST(RotationalInertiaTest, PrincipalMomentsThrowOnNaNOrInfInEveryBuild) {
  const auto nan = Unchecked(1, 1, 1, NAN, 0, 0);
  const auto inf = Unchecked(1, std::numeric_limits<double>::infinity(), 1);
  EXPECT_THROW(nan.CalcPrincipalMomentsOfInertia(), std::logic_error);
  EXPECT_THROW(inf.CalcPrincipalMomentsOfInertia(PrincipalSolver::kFast), std::logic_error);
  EXPECT_THROW(nan.CalcPrincipalMomentsAndAxesOfInertia(), std::logic_error);
  EXPECT_THROW(inf.CalcPrincipalMomentsAndAxesOfInertia(), std::logic_error);
}

TEST(RotationalInertiaTest, PrincipalMomentsOfRotatedBoxAreItsCentralMoments) {
  // A box's moments about its center along its edges are its principal moments (textbook);
  // rotating the frame changes the matrix, not the eigenvalues.
  std::mt19937_64 generator(20240601);
  const RotationalInertia<double> I(1, 2, 2.5);
  for (int k = 0; k < 200; ++k) {
    const Matrix3<double> R = RandomRotation<double>(&generator);
    const Vector3<double> lambda = I.ReExpress(R).CalcPrincipalMomentsOfInertia();
    EXPECT_NEAR(lambda(0), 1, 8 * kEps<double> * 5.5);
    EXPECT_NEAR(lambda(1), 2, 8 * kEps<double> * 5.5);
    EXPECT_NEAR(lambda(2), 2.5, 8 * kEps<double> * 5.5);
  }
}

TEST(RotationalInertiaTest, ReExpressAboutZMatchesHandDerivation) {
  // R_z(θ)·diag(a, b, c)·R_z(θ)ᵀ = [[a·cos² + b·sin², (a − b)·cos·sin, 0], [·, a·sin² + b·cos², 0],
  // [0, 0, c]] (hand-multiplied).
  const double a = 1, b = 2, c = 2.5, theta = 0.3;
  const double co = std::cos(theta), si = std::sin(theta);
  const RotationalInertia<double> I =
      RotationalInertia<double>(a, b, c).ReExpress(RotationZ(theta));
  EXPECT_NEAR(I(0, 0), a * co * co + b * si * si, 1e-15);
  EXPECT_NEAR(I(1, 1), a * si * si + b * co * co, 1e-15);
  EXPECT_NEAR(I(0, 1), (a - b) * co * si, 1e-15);
  EXPECT_NEAR(I(2, 2), c, 1e-15);
  EXPECT_NEAR(I(0, 2), 0, 1e-15);
  EXPECT_NEAR(I(1, 2), 0, 1e-15);
  // A quarter turn swaps x and y (exactly, as cos and sin are then exact up to 6e-17).
  const RotationalInertia<double> J =
      RotationalInertia<double>(1, 2, 2.5).ReExpress(RotationZ(std::acos(-1.0) / 2));
  EXPECT_NEAR(J(0, 0), 2, 1e-15);
  EXPECT_NEAR(J(1, 1), 1, 1e-15);
}

TEST(RotationalInertiaTest, ReExpressRoundTripAndInPlaceAgree) {
  std::mt19937_64 generator(7);
  const RotationalInertia<double> I(5, 6, 7, -0.5, -1, -0.75);
  for (int k = 0; k < 100; ++k) {
    const Matrix3<double> R = RandomRotation<double>(&generator);
    RotationalInertia<double> J = I;
    J.ReExpressInPlace(R);
    EXPECT_EQ(J, I.ReExpress(R));
    EXPECT_NEAR(J.Trace(), I.Trace(), 1e-13);  // Trace is invariant.
    EXPECT_TRUE(J.ReExpress(R.transpose()).IsNearlyEqualTo(I, 4 * kEps<double> * 10));
  }
}

TEST(RotationalInertiaTest, ShiftingABoxToItsCornerMatchesTextbook) {
  // Solid box of mass m, sides a, b, c: about its center (m/12)(b²+c², a²+c², a²+b²); about a
  // corner (m/3)(b²+c², ...) with products ∫xy dm = m·a·b/4 (e.g. Meriam & Kraige, Engineering
  // Mechanics: Dynamics, Appendix B), so the negated matrix entries are −m·a·b/4.
  const double m = 3, a = 1, b = 2, c = 4;
  const RotationalInertia<double> I_cm(m * (b * b + c * c) / 12, m * (a * a + c * c) / 12,
                                       m * (a * a + b * b) / 12);
  const Vector3<double> p_cm_corner(a / 2, b / 2, c / 2);
  const RotationalInertia<double> I_corner = I_cm.ShiftFromCenterOfMass(m, p_cm_corner);
  EXPECT_NEAR(I_corner(0, 0), m * (b * b + c * c) / 3, 1e-13);
  EXPECT_NEAR(I_corner(1, 1), m * (a * a + c * c) / 3, 1e-13);
  EXPECT_NEAR(I_corner(2, 2), m * (a * a + b * b) / 3, 1e-13);
  EXPECT_NEAR(I_corner(0, 1), -m * a * b / 4, 1e-13);
  EXPECT_NEAR(I_corner(0, 2), -m * a * c / 4, 1e-13);
  EXPECT_NEAR(I_corner(1, 2), -m * b * c / 4, 1e-13);
  // And back (the corner's position from the center of mass is the opposite of p_cm_corner).
  const RotationalInertia<double> back = I_corner.ShiftToCenterOfMass(m, -p_cm_corner);
  EXPECT_TRUE(back.IsNearlyEqualTo(I_cm, 1e-14));
  RotationalInertia<double> in_place = I_cm;
  in_place.ShiftFromCenterOfMassInPlace(m, p_cm_corner).ShiftToCenterOfMassInPlace(m, p_cm_corner);
  EXPECT_TRUE(in_place.IsNearlyEqualTo(I_cm, 1e-14));
}

TEST(RotationalInertiaTest, ShiftToThenAwayEqualsTwoShifts) {
  std::mt19937_64 generator(11);
  std::uniform_real_distribution<double> coordinate(-2, 2);
  const double m = 1.7;
  const RotationalInertia<double> I_cm =
      RotationalInertia<double>(0.4, 0.5, 0.6).ReExpress(RandomRotation<double>(&generator));
  for (int k = 0; k < 500; ++k) {
    const Vector3<double> p_PBcm(coordinate(generator), coordinate(generator),
                                 coordinate(generator));
    const Vector3<double> p_QBcm(coordinate(generator), coordinate(generator),
                                 coordinate(generator));
    const RotationalInertia<double> I_P = I_cm.ShiftFromCenterOfMass(m, -p_PBcm);
    const RotationalInertia<double> one_step =
        I_P.ShiftToThenAwayFromCenterOfMass(m, p_PBcm, p_QBcm);
    const RotationalInertia<double> expected = I_cm.ShiftFromCenterOfMass(m, -p_QBcm);
    EXPECT_TRUE(one_step.IsNearlyEqualTo(expected, 64 * kEps<double>)) << one_step << expected;
    RotationalInertia<double> in_place = I_P;
    in_place.ShiftToThenAwayFromCenterOfMassInPlace(m, p_PBcm, p_QBcm);
    EXPECT_EQ(in_place, one_step);
  }
}

TEST(RotationalInertiaTest, CompositionOfPointMassesMatchesHandComputation) {
  // Particles about the origin: 1 kg at (1, 0, 0), 1 kg at (−1, 0, 0), 2 kg at (0, 1, 1).
  // Hand-derived: Ixx = 0 + 0 + 2·(1+1) = 4; Iyy = 1 + 1 + 2·1 = 4; Izz = 1 + 1 + 2·1 = 4;
  // Ixy = −Σ m·x·y = 0; Ixz = 0; Iyz = −2·1·1 = −2.
  RotationalInertia<double> I(1.0, Vector3<double>(1, 0, 0));
  I += RotationalInertia<double>(1.0, Vector3<double>(-1, 0, 0));
  I += RotationalInertia<double>(2.0, Vector3<double>(0, 1, 1));
  EXPECT_EQ(I, RotationalInertia<double>(4, 4, 4, 0, 0, -2));
  // Principal moments: the yz block [[4, −2], [−2, 4]] has eigenvalues 2 and 6; x gives 4.
  const Vector3<double> lambda = I.CalcPrincipalMomentsOfInertia();
  EXPECT_NEAR(lambda(0), 2, 1e-14);
  EXPECT_NEAR(lambda(1), 4, 1e-14);
  EXPECT_NEAR(lambda(2), 6, 1e-14);
  // Center of mass (0, 0.5, 0.5), total mass 4: the parallel-axis theorem gives the central
  // inertia I − 4·(|c|²·1 − c·cᵀ) = (4 − 4·0.5, 4 − 4·0.25, 4 − 4·0.25, 0, 0, −2 + 4·0.25).
  const RotationalInertia<double> I_cm = I.ShiftToCenterOfMass(4, Vector3<double>(0, 0.5, 0.5));
  EXPECT_EQ(I_cm, RotationalInertia<double>(2, 3, 3, 0, 0, -1));
}

TEST(RotationalInertiaTest, PrintsRowsLikeDrake) {
  std::ostringstream out;
  out << RotationalInertia<double>(5, 6, 7, -0.5, -1, -0.75);
  EXPECT_EQ(out.str(), " [5  -0.5  -1]\n [-0.5  6  -0.75]\n [-1  -0.75  7]\n");
}

TEST(RotationalInertiaTest, IndefiniteMatrixWithTriangleDiagonalIsInvalid) {
  // diag(1, 1, 1) satisfies the triangle inequality, but with Ixy = 0.9 its principal moments
  // are 1 ∓ 0.9 and 1, i.e. (0.1, 1, 1.9), and 0.1 + 1 < 1.9 (hand-derived 2x2 eigenvalues).
  const auto I = Unchecked(1, 1, 1, 0.9, 0, 0);
  EXPECT_FALSE(I.CouldBePhysicallyValid());
  EXPECT_FALSE(I.CouldBePhysicallyValid(1e-6));
  // With Ixy = 0.5: (0.5, 1, 1.5), exactly on the boundary: valid.
  EXPECT_TRUE(Unchecked(1, 1, 1, 0.5, 0, 0).CouldBePhysicallyValid());
  // All three products: the matrix 1 + 0.6·(J − 1) (J all ones) has eigenvalues 1 + 1.2 = 2.2
  // and 1 − 0.6 = 0.4 (twice): 0.4 + 0.4 < 2.2.
  EXPECT_FALSE(Unchecked(1, 1, 1, 0.6, 0.6, 0.6).CouldBePhysicallyValid());
}

TEST(RotationalInertiaTest, NonFiniteInertiaIsInvalidAndDoesNotThrow) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(Unchecked(NAN, 1, 1).CouldBePhysicallyValid());
  EXPECT_FALSE(Unchecked(inf, inf, inf).CouldBePhysicallyValid());
  EXPECT_FALSE(Unchecked(1, 1, 1, 0, 0, -inf).CouldBePhysicallyValid());
  EXPECT_FALSE(RotationalInertia<double>().CouldBePhysicallyValid());
  EXPECT_NE(RotationalInertia<double>().CriticizeNotPhysicallyValid().find("NaN or infinite"),
            std::string::npos);
}

TEST(RotationalInertiaTest, CriticizeNamesTheFailure) {
  EXPECT_EQ(RotationalInertia<double>(1, 1, 2).CriticizeNotPhysicallyValid(), "");
  const std::string triangle = Unchecked(1, 1, 3).CriticizeNotPhysicallyValid();
  EXPECT_NE(triangle.find("triangle inequality"), std::string::npos) << triangle;
  EXPECT_NE(triangle.find("I(2,2)=3"), std::string::npos) << triangle;
  const std::string negative = Unchecked(-1, 1, 1).CriticizeNotPhysicallyValid();
  EXPECT_NE(negative.find("negative principal moment"), std::string::npos) << negative;
  // A 0.1% excess fails the default tolerance but passes a 1% one.
  EXPECT_NE(Unchecked(1, 1, 2.002).CriticizeNotPhysicallyValid(), "");
  EXPECT_EQ(Unchecked(1, 1, 2.002).CriticizeNotPhysicallyValid(1e-2), "");
}

TEST(RotationalInertiaTest, HugeAndTinyInertiasAreHandledWithoutOverflow) {
  // 1e200² overflows double; the validity test and the eigen-solvers scale first. The rotated
  // thin disk (1, 1, 2)·1e200 must stay valid and keep its principal moments.
  std::mt19937_64 generator(3);
  for (const double scale : {1e200, 1e300, 1e-200, 1e-300}) {
    const RotationalInertia<double> disk =
        Unchecked(scale, scale, 2 * scale).ReExpress(RandomRotation<double>(&generator));
    EXPECT_TRUE(disk.CouldBePhysicallyValid()) << scale;
    const Vector3<double> lambda = disk.CalcPrincipalMomentsOfInertia();
    EXPECT_NEAR(lambda(0) / scale, 1, 1e-14);
    EXPECT_NEAR(lambda(2) / scale, 2, 1e-14);
    const auto [moments, axes] = disk.CalcPrincipalMomentsAndAxesOfInertia();
    EXPECT_TRUE(axes.allFinite());
    EXPECT_NEAR(moments(1) / scale, 1, 1e-14);
    EXPECT_FALSE(Unchecked(scale, scale, 2.001 * scale).CouldBePhysicallyValid()) << scale;
    EXPECT_FALSE(Unchecked(scale, scale, scale, 0.9 * scale, 0, 0).CouldBePhysicallyValid());
  }
  const double max = std::numeric_limits<double>::max();
  EXPECT_TRUE(Unchecked(max, max, max).CouldBePhysicallyValid());
  EXPECT_TRUE(Unchecked(max / 2, max / 2, max).CouldBePhysicallyValid());
  EXPECT_FALSE(Unchecked(max / 4, max / 4, max).CouldBePhysicallyValid());
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_TRUE(Unchecked(tiny, tiny, 2 * tiny).CouldBePhysicallyValid());
  EXPECT_FALSE(Unchecked(-tiny, tiny, tiny).CouldBePhysicallyValid());
}

// ------------------------------------------- the class path is the free solver, bit for bit

// True iff a and b hold the same bits (NaN payloads and the sign of zero included).
template <typename T>
bool SameBits(const T& a, const T& b) {
  // long double: only the 10 value bytes of x87's 80-bit format (the rest is padding).
  constexpr std::size_t kBytes = std::numeric_limits<T>::digits == 64 ? 10 : sizeof(T);
  return std::memcmp(&a, &b, kBytes) == 0;
}

template <typename T, int R, int C>
bool SameBits(const Eigen::Matrix<T, R, C>& a, const Eigen::Matrix<T, R, C>& b) {
  for (int i = 0; i < a.size(); ++i) {
    if (!SameBits(a.data()[i], b.data()[i])) return false;
  }
  return true;
}

// Inputs of every kind the solvers branch on: rotated general inertias, thin rods, thin disks,
// near-spheres (eigenvalues equal to 1e-9), diagonal ones, ones with one product, invalid ones
// (negative moments, triangle inequality violated), each at scales 2^-900 .. 2^900 where the
// solver works unscaled, scales by a power of two first, or falls back to Jacobi.
template <typename T>
std::vector<RotationalInertia<T>> BitIdentityInputs() {
  std::mt19937_64 generator(17);
  std::uniform_real_distribution<double> uniform(0.05, 1.0);
  std::vector<Vector3<T>> moments;
  for (int k = 0; k < 40; ++k) {
    const T a = T(uniform(generator)), b = T(uniform(generator)), c = T(uniform(generator));
    moments.push_back(Vector3<T>(b + c, a + c, a + b));  // general
  }
  for (const double eps : {1e-3, 1e-8, 1e-16, 0.0}) {
    moments.push_back(Vector3<T>(T(eps), 1, 1));      // thin rods
    moments.push_back(Vector3<T>(1, 1, T(2 - eps)));  // thin disks
    moments.push_back(Vector3<T>(1, T(1 + eps), 1));  // near-spheres
  }
  moments.push_back(Vector3<T>(-1, 2, 3));  // invalid: a negative moment
  moments.push_back(Vector3<T>(1, 1, 5));   // invalid: triangle inequality
  std::vector<RotationalInertia<T>> inputs;
  for (const int exponent : {0, -900, -600, -480, -300, -100, -40, 40, 100, 300, 480, 600, 900}) {
    if (exponent < std::numeric_limits<T>::min_exponent + 60 ||
        exponent > std::numeric_limits<T>::max_exponent - 60) {
      continue;  // Beyond float's range.
    }
    for (const Vector3<T>& m : moments) {
      const Vector3<T> scaled = m * std::ldexp(T(1), exponent);
      const RotationalInertia<T> diagonal =
          RotationalInertia<T>::MakeFromMomentsAndProductsOfInertia(scaled(0), scaled(1), scaled(2),
                                                                    0, 0, 0, true);
      inputs.push_back(diagonal);
      inputs.push_back(diagonal.ReExpress(RandomRotation<T>(&generator)));
      inputs.push_back(RotationalInertia<T>::MakeFromMomentsAndProductsOfInertia(
          scaled(0), scaled(1), scaled(2), scaled(0) / 4, 0, 0, true));
    }
  }
  return inputs;
}

template <typename T>
class PrincipalClassPathTest : public ::testing::Test {};
using ClassPathScalarTypes = ::testing::Types<float, double, long double>;
TYPED_TEST_SUITE(PrincipalClassPathTest, ClassPathScalarTypes);

// The contract (#17): the class path is the bare solver with no other arithmetic, so
// what a user gets through RotationalInertia is exactly what CalcSymmetricEigenvalues /
// CalcSymmetricEigensystem give on the same matrix; both are compared bit for bit.
TYPED_TEST(PrincipalClassPathTest, MomentsAndAxesAreBitForBitThoseOfTheFreeSolver) {
  using T = TypeParam;
  const std::vector<RotationalInertia<T>> inputs = BitIdentityInputs<T>();
  ASSERT_GT(inputs.size(), 400u);  // 486 for float (three scales), 2106 for double
  for (const RotationalInertia<T>& I : inputs) {
    const Matrix3<T> A = I.CopyToFullMatrix3();
    for (const PrincipalSolver solver : {PrincipalSolver::kAccurate, PrincipalSolver::kFast}) {
      const Vector3<T> by_class = I.CalcPrincipalMomentsOfInertia(solver);
      const Vector3<T> by_solver = CalcSymmetricEigenvalues<T>(A, solver);
      ASSERT_TRUE(SameBits(by_class, by_solver)) << I << by_class.transpose() << "\n"
                                                 << by_solver.transpose();
      ASSERT_TRUE(by_class.allFinite()) << I;
      const auto [moments, axes] = I.CalcPrincipalMomentsAndAxesOfInertia(solver);
      const auto [solver_moments, solver_axes] = CalcSymmetricEigensystem<T>(A, solver);
      ASSERT_TRUE(SameBits(moments, solver_moments)) << I;
      ASSERT_TRUE(SameBits(axes, solver_axes)) << I;
    }
  }
}

// Scaling by a power of two is exact, and so is every operation of the solvers on the scaled
// matrix as long as nothing overflows or underflows: the moments of 2^k·A are 2^k times those of
// A, bit for bit, whether the solver ran on 2^k·A directly or scaled it back first. So moving the
// scaling from the class into the solver changed no result.
TYPED_TEST(PrincipalClassPathTest, MomentsOfPowerOfTwoMultiplesAreExactMultiples) {
  using T = TypeParam;
  std::mt19937_64 generator(5);
  std::uniform_real_distribution<double> uniform(0.05, 1.0);
  for (int k = 0; k < 50; ++k) {
    const T a = T(uniform(generator)), b = T(uniform(generator)), c = T(uniform(generator));
    const Matrix3<T> R = RandomRotation<T>(&generator);
    const Matrix3<T> A = R * Vector3<T>(b + c, a + c, a + b).asDiagonal() * R.transpose();
    const Vector3<T> fast = CalcSymmetricEigenvalues<T>(A, PrincipalSolver::kFast);
    const Vector3<T> accurate = CalcSymmetricEigenvalues<T>(A, PrincipalSolver::kAccurate);
    const auto [values, vectors] = CalcSymmetricEigensystem<T>(A);
    for (const int exponent : {-900, -500, -120, -90, -40, -20, 20, 40, 90, 120, 500, 900}) {
      if (exponent < std::numeric_limits<T>::min_exponent + 60 ||
          exponent > std::numeric_limits<T>::max_exponent - 60) {
        continue;
      }
      const T s = std::ldexp(T(1), exponent);
      const Matrix3<T> B = A * s;
      ASSERT_TRUE(SameBits(Vector3<T>(CalcSymmetricEigenvalues<T>(B, PrincipalSolver::kFast)),
                           Vector3<T>(fast * s)))
          << exponent;
      ASSERT_TRUE(SameBits(Vector3<T>(CalcSymmetricEigenvalues<T>(B, PrincipalSolver::kAccurate)),
                           Vector3<T>(accurate * s)))
          << exponent;
      const auto [scaled_values, scaled_vectors] = CalcSymmetricEigensystem<T>(B);
      ASSERT_TRUE(SameBits(scaled_values, Vector3<T>(values * s))) << exponent;
      ASSERT_TRUE(SameBits(scaled_vectors, vectors)) << exponent;
    }
  }
}

// ----------------------------------------------------------- the validity boundary, by type

template <typename T>
class ValidityBoundaryTest : public ::testing::Test {};
using ScalarTypes = ::testing::Types<float, double, long double>;
TYPED_TEST_SUITE(ValidityBoundaryTest, ScalarTypes);

// How far beyond the boundary (relative to the trace) must fail at every scale: 1e-6 for double
// and long double (the requirement); float resolves 1e-5 (its eps is 1.2e-7 and the
// default tolerance 32·eps = 3.8e-6, plus round-off of the rotation).
template <typename T>
T RequiredResolution() {
  return std::is_same_v<T, float> ? T(1e-5) : T(1e-6);
}

TYPED_TEST(ValidityBoundaryTest, ThinDiskAndRodPassAfterAnyRotationAtAnyScale) {
  using T = TypeParam;
  std::mt19937_64 generator(12345);
  int checked = 0;
  for (int exponent = -9; exponent <= 9; ++exponent) {
    const T scale = static_cast<T>(std::pow(10.0L, exponent));
    // Thin disk: (s, s, 2s); thin rod: (0, s, s); both exactly on the boundary.
    const RotationalInertia<T> disk = RotationalInertia<T>::MakeFromMomentsAndProductsOfInertia(
        scale, scale, 2 * scale, 0, 0, 0, true);
    const RotationalInertia<T> rod =
        RotationalInertia<T>::MakeFromMomentsAndProductsOfInertia(0, scale, scale, 0, 0, 0, true);
    for (int k = 0; k < 300; ++k) {
      const Matrix3<T> R = RandomRotation<T>(&generator);
      const RotationalInertia<T> rotated_disk = disk.ReExpress(R);
      const RotationalInertia<T> rotated_rod = rod.ReExpress(R);
      ASSERT_TRUE(rotated_disk.CouldBePhysicallyValid())
          << "scale " << scale << "\n"
          << rotated_disk << rotated_disk.CriticizeNotPhysicallyValid();
      ASSERT_TRUE(rotated_rod.CouldBePhysicallyValid())
          << "scale " << scale << "\n"
          << rotated_rod << rotated_rod.CriticizeNotPhysicallyValid();
      checked += 2;
    }
  }
  EXPECT_EQ(checked, 19 * 600);
}

TYPED_TEST(ValidityBoundaryTest, AnythingBeyondTheBoundaryFailsAtEveryScale) {
  using T = TypeParam;
  const T delta = RequiredResolution<T>();
  std::mt19937_64 generator(54321);
  for (int exponent = -9; exponent <= 9; ++exponent) {
    const T s = static_cast<T>(std::pow(10.0L, exponent));
    // Disk with Izz larger than Ixx + Iyy by delta·trace (trace = 4s + excess ≈ 4s; using
    // 4.0001·s as the trace bound keeps the excess >= delta·trace).
    const T excess = delta * T(4.0001) * s;
    const auto fat_disk = RotationalInertia<T>::MakeFromMomentsAndProductsOfInertia(
        s, s, 2 * s + excess, 0, 0, 0, true);
    // Rod with a negative moment of −delta·trace (trace = 2s − excess').
    const auto negative_rod = RotationalInertia<T>::MakeFromMomentsAndProductsOfInertia(
        -delta * T(2) * s, s, s, 0, 0, 0, true);
    for (int k = 0; k < 300; ++k) {
      const Matrix3<T> R = RandomRotation<T>(&generator);
      ASSERT_FALSE(fat_disk.ReExpress(R).CouldBePhysicallyValid()) << "scale " << s;
      ASSERT_FALSE(negative_rod.ReExpress(R).CouldBePhysicallyValid()) << "scale " << s;
    }
  }
}

TYPED_TEST(ValidityBoundaryTest, ExplicitToleranceWidensTheBoundary) {
  using T = TypeParam;
  // (1, 1, 2 + 2e-6): beyond the boundary by 2e-6/(4 + 2e-6) ≈ 5e-7 of the trace: passes a
  // 1e-6 tolerance, fails 1e-7 (float cannot resolve 1e-7, so only the passing half for it).
  const auto I = RotationalInertia<T>::MakeFromMomentsAndProductsOfInertia(1, 1, T(2) + T(2e-6), 0,
                                                                           0, 0, true);
  EXPECT_TRUE(I.CouldBePhysicallyValid(T(1e-6)));
  if (!std::is_same_v<T, float>) {
    EXPECT_FALSE(I.CouldBePhysicallyValid(T(1e-7)));
    EXPECT_FALSE(I.CouldBePhysicallyValid());
  }
  EXPECT_FALSE(I.CouldBePhysicallyValid(T(-1)));  // A negative tolerance is refused.
}

TYPED_TEST(ValidityBoundaryTest, PrincipalMomentsOfRotatedThinRodAreAccurate) {
  using T = TypeParam;
  // Thin rod (0, 1, 1) rotated: moments within a few eps of the trace (accurate solver contract).
  std::mt19937_64 generator(99);
  const auto rod =
      RotationalInertia<T>::MakeFromMomentsAndProductsOfInertia(0, 1, 1, 0, 0, 0, true);
  for (int k = 0; k < 500; ++k) {
    const Vector3<T> lambda =
        rod.ReExpress(RandomRotation<T>(&generator)).CalcPrincipalMomentsOfInertia();
    EXPECT_NEAR(lambda(0), T(0), 16 * kEps<T> * 2);
    EXPECT_NEAR(lambda(1), T(1), 16 * kEps<T> * 2);
    EXPECT_NEAR(lambda(2), T(1), 16 * kEps<T> * 2);
  }
}

}  // namespace
}  // namespace massprops

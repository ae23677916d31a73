#include "massprops/core/principal_axes.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "test_shapes.h"

namespace massprops {
namespace {

using test_support::RandomRotation;

using LongDouble = long double;

template <typename T>
constexpr T kEps = std::numeric_limits<T>::epsilon();

// R diag(moments) R^T, computed in long double and rounded to T.
template <typename T>
Matrix3<T> Rotated(const Matrix3<LongDouble>& R, const Vector3<LongDouble>& moments) {
  return (R * moments.asDiagonal() * R.transpose()).template cast<T>();
}

#ifdef __SIZEOF_FLOAT128__
using Reference = __float128;  // 113-bit significand: far below every error measured here.
#else
using Reference = long double;
#endif

Reference ReferenceSqrt(Reference x) {
  if (!(x > 0)) return 0;
  Reference r = std::sqrt(static_cast<long double>(x));
  return (r + x / r) / 2;  // One Newton step doubles the 64 correct bits.
}

// Reference eigenvalues of the T matrix A (its exact value), ascending: the textbook cyclic
// Jacobi method (Golub and Van Loan, Matrix Computations, Algorithm 8.5.3) run in binary128.
template <typename T>
std::array<Reference, 3> ReferenceEigenvalues(const Matrix3<T>& A) {
  Reference a[3][3];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) a[i][j] = static_cast<Reference>(A(std::max(i, j), std::min(i, j)));
  }
  for (int sweep = 0; sweep < 60; ++sweep) {
    bool rotated = false;
    for (int p = 0; p < 2; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        // Negligible: below 1e-40 of the diagonal (binary128 round-off is 1e-34).
        const Reference apq = a[p][q] < 0 ? -a[p][q] : a[p][q];
        const Reference app = a[p][p] < 0 ? -a[p][p] : a[p][p];
        const Reference aqq = a[q][q] < 0 ? -a[q][q] : a[q][q];
        if (apq <= Reference(1e-40L) * (app + aqq)) continue;
        rotated = true;
        const Reference theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
        const Reference t = (theta >= 0 ? 1 : -1) /
                            ((theta >= 0 ? theta : -theta) + ReferenceSqrt(theta * theta + 1));
        const Reference c = 1 / ReferenceSqrt(t * t + 1), s = t * c;
        for (int k = 0; k < 3; ++k) {
          const Reference akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) {
          const Reference apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        a[p][q] = a[q][p] = 0;
      }
    }
    if (!rotated) break;
  }
  std::array<Reference, 3> w = {a[0][0], a[1][1], a[2][2]};
  std::sort(w.begin(), w.end());
  return w;
}

// Without binary128 the reference has long double's error: allow for it when T = long double.
template <typename T>
constexpr LongDouble kReferenceSlack =
    std::is_same_v<T, LongDouble> && !std::is_same_v<Reference, __float128> ? 4 : 0;

template <typename T>
LongDouble MaxValueError(const Vector3<T>& w, const Matrix3<T>& A) {
  const std::array<Reference, 3> reference = ReferenceEigenvalues(A);
  Reference worst = 0;
  for (int i = 0; i < 3; ++i) {
    const Reference error = static_cast<Reference>(w[i]) - reference[i];
    worst = std::max(worst, error < 0 ? -error : error);
  }
  return static_cast<LongDouble>(worst);
}

template <typename T>
LongDouble FrobeniusNorm(const Matrix3<T>& A) {
  return A.template cast<LongDouble>().norm();
}

// Checks everything an eigensystem promises: ascending values, orthonormal right-handed vectors,
// and A v = lambda v, to `tolerance` (a multiple of eps) relative to the Frobenius norm of A.
template <typename T>
void ExpectValidEigensystem(const Matrix3<T>& A, const std::pair<Vector3<T>, Matrix3<T>>& result,
                            LongDouble tolerance) {
  const Vector3<LongDouble> w = result.first.template cast<LongDouble>();
  const Matrix3<LongDouble> V = result.second.template cast<LongDouble>();
  const Matrix3<LongDouble> Al = A.template cast<LongDouble>();
  const LongDouble scale = Al.norm();
  EXPECT_LE(w[0], w[1]);
  EXPECT_LE(w[1], w[2]);
  EXPECT_LE((V.transpose() * V - Matrix3<LongDouble>::Identity()).cwiseAbs().maxCoeff(), tolerance)
      << V;
  EXPECT_NEAR(V.determinant(), 1, tolerance);
  EXPECT_LE((Al * V - V * w.asDiagonal()).cwiseAbs().maxCoeff(), tolerance * scale)
      << "A =\n"
      << A << "\nw = " << w.transpose() << "\nV =\n"
      << V;
}

template <typename T>
class PrincipalAxesTest : public ::testing::Test {};
using ScalarTypes = ::testing::Types<float, double, long double>;
TYPED_TEST_SUITE(PrincipalAxesTest, ScalarTypes);

constexpr PrincipalSolver kBothSolvers[] = {PrincipalSolver::kAccurate, PrincipalSolver::kFast};

// Hand-derived: a diagonal matrix's eigenvalues are its diagonal entries and its eigenvectors the
// coordinate axes; no rotation may be applied, so the values are returned bit for bit.
TYPED_TEST(PrincipalAxesTest, DiagonalInputIsReturnedExactlySorted) {
  using T = TypeParam;
  for (PrincipalSolver solver : kBothSolvers) {
    // diag(2, 3, 1): sorted order takes entries (2, 0, 1), an even (cyclic) permutation.
    const Matrix3<T> A = Vector3<T>(T(2.1), T(3.7), T(0.3)).asDiagonal();
    const Vector3<T> expected(T(0.3), T(2.1), T(3.7));
    EXPECT_EQ(CalcSymmetricEigenvalues(A, solver), expected);
    const auto [w, V] = CalcSymmetricEigensystem(A, solver);
    EXPECT_EQ(w, expected);
    Matrix3<T> R;
    R << 0, 1, 0, 0, 0, 1, 1, 0, 0;  // Columns e2, e0, e1: a rotation (det +1).
    EXPECT_EQ(V, R);

    // diag(2, 1, 3): sorted order takes entries (1, 0, 2), an odd permutation: one axis must be
    // reversed to keep a rotation; every entry is still exactly 0 or +-1.
    const Matrix3<T> B = Vector3<T>(T(2), T(1), T(3)).asDiagonal();
    const auto [wb, Vb] = CalcSymmetricEigensystem(B, solver);
    EXPECT_EQ(wb, Vector3<T>(1, 2, 3));
    EXPECT_EQ(Vb.cwiseAbs(), (Matrix3<T>() << 0, 1, 0, 1, 0, 0, 0, 0, 1).finished());
    EXPECT_EQ(Vb.determinant(), T(1));
  }
}

// Hand-derived: for c*I every vector is an eigenvector; the documented choice is the identity.
TYPED_TEST(PrincipalAxesTest, AllEqualEigenvaluesGiveIdentityAxes) {
  using T = TypeParam;
  for (PrincipalSolver solver : kBothSolvers) {
    const Matrix3<T> A = T(2.5) * Matrix3<T>::Identity();
    const auto [w, V] = CalcSymmetricEigensystem(A, solver);
    EXPECT_EQ(w, Vector3<T>::Constant(T(2.5)));
    EXPECT_EQ(V, Matrix3<T>::Identity());
    const auto [w0, V0] = CalcSymmetricEigensystem(Matrix3<T>::Zero().eval(), solver);
    EXPECT_EQ(w0, Vector3<T>::Zero());
    EXPECT_EQ(V0, Matrix3<T>::Identity());
  }
}

// Hand-derived: [[2, 1, 0], [1, 2, 0], [0, 0, 3]] has the block [[2, 1], [1, 2]] with eigenvalues
// 2 -+ 1 and eigenvectors (1, -+1)/sqrt(2), plus 3 on the z axis: eigenvalues 1, 3, 3.
TYPED_TEST(PrincipalAxesTest, KnownMatrixWithRepeatedEigenvalue) {
  using T = TypeParam;
  Matrix3<T> A;
  A << 2, 1, 0, 1, 2, 0, 0, 0, 3;
  const T tolerance = 4 * kEps<T> * 7;  // 4 eps * trace.
  for (PrincipalSolver solver : kBothSolvers) {
    const Vector3<T> values = CalcSymmetricEigenvalues(A, solver);
    EXPECT_NEAR(values[0], 1, tolerance);
    EXPECT_NEAR(values[1], 3, tolerance);
    EXPECT_NEAR(values[2], 3, tolerance);
    const auto result = CalcSymmetricEigensystem(A, solver);
    const Vector3<T> axis = result.second.col(0);
    const T s = T(1) / std::sqrt(T(2));
    EXPECT_LE((axis.cwiseAbs() - Vector3<T>(s, s, 0)).cwiseAbs().maxCoeff(), 8 * kEps<T>);
    EXPECT_LT(axis[0] * axis[1], 0);  // (1, -1, 0) up to sign.
    ExpectValidEigensystem<T>(A, result, 8 * kEps<T>);
  }
}

// Hand-derived: with R the rotation by 30 degrees about z (c = sqrt(3)/2, s = 1/2),
// R diag(1, 2, 3) R^T = [[c^2 + 2 s^2, -c s, 0], [-c s, s^2 + 2 c^2, 0], [0, 0, 3]]
//                     = [[5/4, -sqrt(3)/4, 0], [-sqrt(3)/4, 7/4, 0], [0, 0, 3]],
// with eigenvalues 1, 2, 3 and eigenvectors the columns of R: (c, s, 0), (-s, c, 0), (0, 0, 1).
TYPED_TEST(PrincipalAxesTest, DiagonalRotatedThirtyDegreesAboutZ) {
  using T = TypeParam;
  const T sqrt3 = std::sqrt(T(3));
  Matrix3<T> A;
  A << T(1.25), -sqrt3 / 4, 0, -sqrt3 / 4, T(1.75), 0, 0, 0, 3;
  Matrix3<T> R;
  R << sqrt3 / 2, T(-0.5), 0, T(0.5), sqrt3 / 2, 0, 0, 0, 1;
  const T tolerance = 4 * kEps<T> * 6;
  for (PrincipalSolver solver : kBothSolvers) {
    const Vector3<T> values = CalcSymmetricEigenvalues(A, solver);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(values[i], i + 1, tolerance) << i;
    const auto result = CalcSymmetricEigensystem(A, solver);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(result.first[i], i + 1, tolerance);
      // Same axis up to sign: |cos| = 1.
      EXPECT_NEAR(std::abs(result.second.col(i).dot(R.col(i))), 1, 8 * kEps<T>) << i;
    }
    ExpectValidEigensystem<T>(A, result, 8 * kEps<T>);
  }
}

// Backward stability on random symmetric (indefinite) matrices: every eigenvalue within a few
// units of round-off of the Frobenius norm of a long double reference, axes orthonormal.
TYPED_TEST(PrincipalAxesTest, AccurateSolverMatchesReferenceOnRandomSymmetricMatrices) {
  using T = TypeParam;
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> uniform(-1, 1);
  LongDouble worst = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Matrix3<T> A;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j <= i; ++j) A(i, j) = A(j, i) = T(uniform(rng));
    }
    const Vector3<T> values = CalcSymmetricEigenvalues(A);
    const auto result = CalcSymmetricEigensystem(A);
    EXPECT_EQ(values, result.first);  // Same computation with or without vectors.
    worst = std::max(worst, MaxValueError(values, A) / FrobeniusNorm(A));
    ExpectValidEigensystem<T>(A, result, 10 * kEps<T>);
    if (this->HasFailure()) break;
  }
  EXPECT_LE(worst, (4 + kReferenceSlack<T>)*kEps<T>);
}

// Rotated physically valid inertias with distinct moments (gaps >= 5% of the trace): both
// solvers; the fast solver's values-only closed form within 4500 eps of the trace (1e-12 in
// double), the accurate one within 4 eps.
TYPED_TEST(PrincipalAxesTest, BothSolversMatchReferenceOnWellConditionedInertias) {
  using T = TypeParam;
  std::mt19937_64 rng(777);
  std::uniform_real_distribution<double> uniform(0.1, 1.0);
  LongDouble worst_accurate = 0, worst_fast = 0;
  int count = 0;
  while (count < 2000) {
    // Principal moments (b + c, a + c, a + b) from positive second moments a, b, c.
    const LongDouble a = uniform(rng), b = uniform(rng), c = uniform(rng);
    Vector3<LongDouble> moments(b + c, a + c, a + b);
    std::sort(moments.data(), moments.data() + 3);
    const LongDouble trace = moments.sum();
    if (moments[1] - moments[0] < 0.05 * trace || moments[2] - moments[1] < 0.05 * trace) continue;
    ++count;
    const Matrix3<T> A = Rotated<T>(RandomRotation(&rng), moments);
    worst_accurate = std::max(
        worst_accurate, MaxValueError(CalcSymmetricEigenvalues(A, PrincipalSolver::kAccurate), A));
    worst_fast =
        std::max(worst_fast, MaxValueError(CalcSymmetricEigenvalues(A, PrincipalSolver::kFast), A));
    for (PrincipalSolver solver : kBothSolvers) {
      ExpectValidEigensystem<T>(A, CalcSymmetricEigensystem(A, solver), 10 * kEps<T>);
    }
    if (this->HasFailure()) break;
  }
  // Moments are at most trace/2 here, and the trace is about 2 to 6; bound relative to 6.
  EXPECT_LE(worst_accurate / 6, (4 + kReferenceSlack<T>)*kEps<T>);
  EXPECT_LE(worst_fast / 6, 4500 * kEps<T>);
}

// A thin rod diag(eps, 1, 1) lies on the validity boundary; after a rotation the accurate solver
// must still find the tiny moment to round-off of the trace, and the rod's axis (the first column
// of the rotation) to round-off. Formula: the rod's moments are (0, mL^2/12, mL^2/12), scaled here.
TYPED_TEST(PrincipalAxesTest, ThinRodsKeepFullAccuracyAfterAnyRotation) {
  using T = TypeParam;
  std::mt19937_64 rng(4242);
  for (const LongDouble eps : {1e-4L, 1e-8L, 1e-12L, 1e-16L}) {
    LongDouble worst_value = 0, worst_axis = 0, worst_fast = 0;
    for (int trial = 0; trial < 500; ++trial) {
      const Matrix3<LongDouble> R = RandomRotation(&rng);
      const Matrix3<T> A = Rotated<T>(R, Vector3<LongDouble>(eps, 1, 1));
      const auto result = CalcSymmetricEigensystem(A);
      worst_value = std::max(worst_value, MaxValueError(result.first, A) / 2);
      worst_axis = std::max(
          worst_axis, result.second.col(0).template cast<LongDouble>().cross(R.col(0)).norm());
      worst_fast = std::max(
          worst_fast, MaxValueError(CalcSymmetricEigenvalues(A, PrincipalSolver::kFast), A) / 2);
      ExpectValidEigensystem<T>(A, result, 10 * kEps<T>);
      ExpectValidEigensystem<T>(A, CalcSymmetricEigensystem(A, PrincipalSolver::kFast),
                                10 * kEps<T>);
      if (this->HasFailure()) return;
    }
    EXPECT_LE(worst_value, (4 + kReferenceSlack<T>)*kEps<T>) << eps;
    EXPECT_LE(worst_axis, 16 * kEps<T>) << eps;
    // The repeated pair is found by deflation, not by the closed form, even in kFast.
    EXPECT_LE(worst_fast, (4 + kReferenceSlack<T>)*kEps<T>) << eps;
  }
}

// A sphere perturbed by 1e-15 (relative): the moments are equal to round-off, the axes arbitrary
// but they must still form an orthonormal right-handed frame with small residuals.
TYPED_TEST(PrincipalAxesTest, NearlyEqualMomentsGiveOrthonormalAxes) {
  using T = TypeParam;
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (int trial = 0; trial < 1000; ++trial) {
    const Vector3<LongDouble> moments(1 + 1e-15L * uniform(rng), 1 + 1e-15L * uniform(rng),
                                      1 + 1e-15L * uniform(rng));
    const Matrix3<T> A = Rotated<T>(RandomRotation(&rng), moments);
    for (PrincipalSolver solver : kBothSolvers) {
      const Vector3<T> values = CalcSymmetricEigenvalues(A, solver);
      EXPECT_LE(MaxValueError(values, A) / 3, (4 + kReferenceSlack<T>)*kEps<T>);
      ExpectValidEigensystem<T>(A, CalcSymmetricEigensystem(A, solver), 10 * kEps<T>);
    }
    if (this->HasFailure()) return;
  }
}

// Eigenvalues scale with the matrix; axes do not. Inertia scales as mass * length^2, here over
// 1e-9..1e9 for every type and 1e-150..1e150 where the type's range allows it (without overflow
// or underflow in the squares that the solvers form).
TYPED_TEST(PrincipalAxesTest, ResultsAreScaleInvariantOverTheWholeRange) {
  using T = TypeParam;
  std::mt19937_64 rng(2024);
  std::vector<LongDouble> scales = {1e-9L, 1e-6L, 1e-3L, 1, 1e3L, 1e6L, 1e9L};
  if (std::numeric_limits<T>::max_exponent10 > 300) {
    scales.insert(scales.end(), {1e-150L, 1e-100L, 1e100L, 1e150L, 1e200L});
  }
  const Vector3<LongDouble> moments(0.3L, 0.5L, 0.7L);
  for (const LongDouble scale : scales) {
    for (int trial = 0; trial < 50; ++trial) {
      const Matrix3<T> A = Rotated<T>(RandomRotation(&rng), moments * scale);
      const LongDouble trace = A.template cast<LongDouble>().trace();
      for (PrincipalSolver solver : kBothSolvers) {
        const Vector3<T> values = CalcSymmetricEigenvalues(A, solver);
        ASSERT_TRUE(values.allFinite()) << scale;
        const LongDouble tolerance = solver == PrincipalSolver::kAccurate
                                         ? (4 + kReferenceSlack<T>)*kEps<T>
                                         : 4500 * kEps<T>;
        EXPECT_LE(MaxValueError(values, A) / trace, tolerance) << scale;
        const auto result = CalcSymmetricEigensystem(A, solver);
        ASSERT_TRUE(result.second.allFinite()) << scale;
        ExpectValidEigensystem<T>(A, result, 10 * kEps<T>);
      }
      if (this->HasFailure()) return;
    }
  }
}

// Hand-derived: s [[1, 1/2, 0], [1/2, 1, 0], [0, 0, 1]] has eigenvalues s/2, s, 3s/2 with
// eigenvectors (1, -1, 0)/sqrt(2), (0, 0, 1), (1, 1, 0)/sqrt(2). With s = 1e-300 the squares that
// the closed form needs underflow: the solvers must scale (exactly, by a power of two) and still
// return the same axes.
TEST(PrincipalAxesTest, TinyMatrixBelowTheSquaringRangeStillGivesTheAxes) {
  const double s = 1e-300;
  Matrix3<double> A;
  A << s, s / 2, 0, s / 2, s, 0, 0, 0, s;
  const double r = std::sqrt(0.5);
  for (PrincipalSolver solver : kBothSolvers) {
    const auto [w, V] = CalcSymmetricEigensystem(A, solver);
    EXPECT_NEAR(w[0] / s, 0.5, 4 * kEps<double>);
    EXPECT_NEAR(w[1] / s, 1.0, 4 * kEps<double>);
    EXPECT_NEAR(w[2] / s, 1.5, 4 * kEps<double>);
    EXPECT_NEAR(std::abs(V.col(0).dot(Vector3<double>(r, -r, 0))), 1, 4 * kEps<double>);
    EXPECT_NEAR(std::abs(V(2, 1)), 1, 4 * kEps<double>);
    EXPECT_NEAR(std::abs(V.col(2).dot(Vector3<double>(r, r, 0))), 1, 4 * kEps<double>);
    EXPECT_NEAR(V.determinant(), 1, 4 * kEps<double>);
  }
}

// Off-diagonal entries far below round-off of the diagonal (1e-200 against 1): the axes are not
// determined by the data (the identity is an exact eigenbasis of a matrix within 1e-200 of A), but
// the result must still be a valid eigensystem and the values exact.
TEST(PrincipalAxesTest, NegligibleOffDiagonalGivesAValidEigensystem) {
  Matrix3<double> A;
  A << 1, 1e-200, 0, 1e-200, 1, 0, 0, 0, 1;
  for (PrincipalSolver solver : kBothSolvers) {
    const auto result = CalcSymmetricEigensystem(A, solver);
    EXPECT_EQ(result.first, Vector3<double>(1, 1, 1));  // 1 -+ 1e-200 rounds to 1.
    ExpectValidEigensystem<double>(A, result, 4 * kEps<double>);
  }
}

// Found by the inertia fuzzer (testdata/fuzz/regressions/inertia/axes-underflowing-pair-*, and
// the earlier open finding of six entries between 8e-320 and 1.3e-231): one moment dominates by
// 160 orders (1.1e74 against 0.377 and products of -1.2e-88), so the other two are equal to
// round-off and any orthonormal pair spans their plane; the deflation's 2x2 rotation was
// normalized with squares that underflowed (|x| ~ 1e-162), returning axes of length 1.0027 and
// 1.0000168. Hand-derived expectation: the values are 0, 0 and the trace (to round-off of the
// trace), and V is a rotation (orthonormal, determinant 1) whatever the pair's axes are.
TEST(PrincipalAxesTest, AxesStayOrthonormalWhenTheEqualPairUnderflows) {
  const std::array<std::array<double, 6>, 2> cases = {{
      {1.1063927024996823e+74, 0.37701416044477737, -1.1655535480901152e-88,
       -1.1655535480901393e-88, -1.1655535480901393e-88, -1.1655535480901393e-88},
      {1.2895927855622272e-231, 0.0, 3.22526e-319, 5.012646388445023e-304, 8.087e-320, 0.0},
  }};
  for (const auto& e : cases) {
    Matrix3<double> A;  // (ixx, iyy, izz, ixy, ixz, iyz) as matrix entries
    A << e[0], e[3], e[4], e[3], e[1], e[5], e[4], e[5], e[2];
    const double trace = e[0] + e[1] + e[2];
    for (PrincipalSolver solver : kBothSolvers) {
      const auto [w, V] = CalcSymmetricEigensystem(A, solver);
      EXPECT_LE((V.transpose() * V - Matrix3<double>::Identity()).norm(), 8 * kEps<double>);
      EXPECT_NEAR(V.determinant(), 1, 8 * kEps<double>);
      EXPECT_NEAR(w[0] / trace, 0, 4 * kEps<double>);
      EXPECT_NEAR(w[1] / trace, 0, 4 * kEps<double>);
      EXPECT_NEAR(w[2] / trace, 1, 4 * kEps<double>);
    }
  }
}

// Only the lower triangle is read (documented): garbage in the upper triangle has no effect.
TEST(PrincipalAxesTest, OnlyTheLowerTriangleIsRead) {
  Matrix3<double> lower;
  lower << 2, 99, -7, 1, 2, 42, 0, 0, 3;
  Matrix3<double> symmetric;
  symmetric << 2, 1, 0, 1, 2, 0, 0, 0, 3;
  for (PrincipalSolver solver : kBothSolvers) {
    EXPECT_EQ(CalcSymmetricEigenvalues(lower, solver), CalcSymmetricEigenvalues(symmetric, solver));
    EXPECT_EQ(CalcSymmetricEigensystem(lower, solver), CalcSymmetricEigensystem(symmetric, solver));
  }
}

#ifndef NDEBUG
// Debug builds check the precondition and quote the matrix in the message.
TEST(PrincipalAxesTest, NonFiniteInputThrowsInDebugBuilds) {
  for (PrincipalSolver solver : kBothSolvers) {
    Matrix3<double> A = Matrix3<double>::Identity();
    A(2, 0) = A(0, 2) = std::numeric_limits<double>::quiet_NaN();
    try {
      CalcSymmetricEigensystem(A, solver);
      ADD_FAILURE() << "no exception";
    } catch (const std::logic_error& e) {
      EXPECT_NE(std::string(e.what()).find("nan"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("CalcSymmetricEigensystem"), std::string::npos);
    }
    A(2, 0) = A(0, 2) = std::numeric_limits<double>::infinity();
    EXPECT_THROW(CalcSymmetricEigenvalues(A, solver), std::logic_error);
    A(2, 0) = A(0, 2) = 0;
    A(1, 1) = -std::numeric_limits<double>::infinity();
    EXPECT_THROW(CalcSymmetricEigensystem(A, solver), std::logic_error);
    EXPECT_THROW(CalcSymmetricEigensystem(A.cast<float>().eval(), solver), std::logic_error);
    EXPECT_THROW(CalcSymmetricEigenvalues(A.cast<long double>().eval(), solver), std::logic_error);
  }
}
#else
// Release builds skip the check (documented) but must return, with non-finite results rather
// than plausible numbers: the iterations are bounded.
TEST(PrincipalAxesTest, NonFiniteInputReturnsNonFiniteResultsInReleaseBuilds) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const double bad : {nan, inf, -inf}) {
    for (int entry = 0; entry < 6; ++entry) {
      const int i = entry < 3 ? entry : (entry == 3 ? 1 : 2);
      const int j = entry < 3 ? entry : (entry == 5 ? 1 : 0);
      Matrix3<double> A;
      A << 2, 1, 0, 1, 2, 0, 0, 0, 3;
      A(i, j) = A(j, i) = bad;
      for (PrincipalSolver solver : kBothSolvers) {
        EXPECT_FALSE(CalcSymmetricEigenvalues(A, solver).allFinite()) << i << j << bad;
        const auto [w, V] = CalcSymmetricEigensystem(A, solver);
        EXPECT_FALSE(w.allFinite() && V.allFinite()) << i << j << bad;
      }
    }
  }
}
#endif

}  // namespace
}  // namespace massprops

#pragma once
/// @file
/// Eigen-decomposition of symmetric 3x3 matrices (inertia matrices), with a choice of speed or
/// accuracy. Both solvers read only the six entries of the lower triangle (A(0,0), A(1,0),
/// A(1,1), A(2,0), A(2,1), A(2,2)); the upper triangle is ignored.
///
/// How they work (src/core/principal_axes.cc): shift by trace/3 and scale by the root-mean-square p
/// of the shifted entries; the eigenvalue farthest from the other two (the "isolated" one) is the
/// root of a well-conditioned cubic, found without trigonometric functions (polynomial guess and a
/// Halley step). kAccurate then deflates: the isolated eigenvector is the largest cross product of
/// two rows of A - lambda*1, and the 2x2 problem left in the orthogonal plane is solved exactly by
/// one plane rotation, so every step is an orthogonal transformation or well conditioned. kFast
/// (values only) takes the other two eigenvalues from the closed form instead, unless they are
/// close (less than 1e-3 * 2 sqrt(3) p apart), where the closed form would lose digits and it
/// deflates too. Diagonal input is sorted without arithmetic. Inputs outside the range where the
/// squares are safe (shifted entries below about 1e-146 or above 1e153 in double) go to a cyclic
/// Jacobi iteration, after an exact scaling by a power of two, with a bounded number of sweeps.
///
/// Measured in double (docs/benchmarks.md, same inputs for every solver): kAccurate
/// eigenvalues within about 1.1 eps of the trace on rotated inertias, thin rods and near-spheres,
/// axes orthonormal to about 5 eps; kFast values within about 60 eps of the trace; with vectors,
/// both solvers run the same code. kAccurate is about 3.6-4.2x faster than Eigen 3.4's
/// SelfAdjointEigenSolver::compute on general inputs (1.6x on thin rods); the ratios for every
/// solver, including where kFast is slower than computeDirect, are in that file.

#include <utility>

#include "massprops/core/eigen_types.h"

namespace massprops {

/// Which solver computes principal moments and axes.
enum class PrincipalSolver {
  /// Backward stable: every eigenvalue within a few units of round-off of the trace (of the
  /// Frobenius norm), eigenvectors orthonormal to round-off, exact on diagonal input,
  /// well-defined vectors when eigenvalues are equal or nearly so. The default.
  kAccurate,
  /// Closed form (the cubic's roots, without trigonometric functions), as fast as it can be made.
  /// Eigenvalues within about 1200 eps of the trace (2.6e-13 in double) on any input, measured
  /// at most about 60 eps; nearly equal eigenvalues (thin rods, near-spheres) cost as much as
  /// kAccurate instead of losing digits.
  kFast,
};

/// The eigenvalues of the symmetric matrix A, ascending. Only the lower triangle of A is read.
/// With kAccurate, the values are exactly those CalcSymmetricEigensystem(A, kAccurate) returns.
/// Entries of any finite magnitude (1e-300 .. 1e300 in double) are handled by an exact scaling by a
/// power of two when the closed form's squares would overflow or underflow, so the result on A and
/// on 2^k·A differ by exactly 2^k. Precondition: A is finite. Debug builds (NDEBUG not defined)
/// check it and throw std::logic_error quoting the matrix; release builds do not check, but always
/// return (no unbounded iteration) and a non-finite input gives non-finite output.
/// Cost (double, 2.1 GHz x86-64): about 40 ns (kFast, distinct eigenvalues) or 80 ns (kAccurate).
template <typename T>
Vector3<T> CalcSymmetricEigenvalues(const Matrix3<T>& A,
                                    PrincipalSolver solver = PrincipalSolver::kAccurate);

/// The eigenvalues of the symmetric matrix A, ascending, and the matching unit eigenvectors as
/// the columns of a rotation matrix (orthonormal, determinant +1). Only the lower triangle is read.
/// When all eigenvalues are equal the vectors are the identity; when two are equal (or nearly)
/// their vectors are still an orthonormal pair spanning their eigenspace. Diagonal input gives the
/// diagonal entries sorted, unchanged, and signed coordinate axes. Both solvers compute vectors the
/// same (backward stable) way, so `solver` only matters for CalcSymmetricEigenvalues.
/// Precondition: A is finite. Debug builds (NDEBUG not defined) check it and throw
/// std::logic_error quoting the matrix; release builds do not check, but always return (no
/// unbounded iteration) and a non-finite input gives non-finite output.
/// Cost (double, 2.1 GHz x86-64): 80-100 ns.
template <typename T>
std::pair<Vector3<T>, Matrix3<T>> CalcSymmetricEigensystem(
    const Matrix3<T>& A, PrincipalSolver solver = PrincipalSolver::kAccurate);

namespace internal {

/// The solvers on the six entries of the lower triangle given as numbers (the path of
/// RotationalInertia, which stores six numbers, not a matrix): *values (and *vectors) are bit for
/// bit those CalcSymmetricEigenvalues(A, solver) (CalcSymmetricEigensystem(A)) return for the
/// matrix A with these entries, at the same cost. Returns false, with non-finite output, iff an
/// entry is NaN or infinite; the finiteness test runs only off the fast path. Never throws.
template <typename T>
bool SymmetricEigenvaluesOfEntries(T a00, T a11, T a22, T a10, T a20, T a21, PrincipalSolver solver,
                                   Vector3<T>* values);
/// See SymmetricEigenvaluesOfEntries; the vectors as CalcSymmetricEigensystem gives them.
template <typename T>
bool SymmetricEigensystemOfEntries(T a00, T a11, T a22, T a10, T a20, T a21, Vector3<T>* values,
                                   Matrix3<T>* vectors);

}  // namespace internal

}  // namespace massprops

#pragma once
/// @file
/// Eigen-decomposition of symmetric 3x3 matrices (inertia matrices), with a choice of speed or
/// accuracy. Both solvers read the six unique entries of the lower triangle... (see below).

#include <utility>

#include "massprops/eigen_types.h"

namespace massprops {

/// Which solver computes principal moments and axes.
enum class PrincipalSolver {
  /// Backward stable: every eigenvalue within a few units of round-off of the trace (of the
  /// Frobenius norm), eigenvectors orthonormal to round-off, exact on diagonal input,
  /// well-defined vectors when eigenvalues are equal or nearly so. The default.
  kAccurate,
  /// Closed form (trigonometric), as fast as it can be made; error grows for nearly equal
  /// eigenvalues (see bench/ for the measured error).
  kFast,
};

/// The eigenvalues of the symmetric matrix A, ascending. Only the lower triangle of A is read.
/// Precondition: A is finite (checked in debug builds: throws std::logic_error).
template <typename T>
Vector3<T> CalcSymmetricEigenvalues(const Matrix3<T>& A,
                                    PrincipalSolver solver = PrincipalSolver::kAccurate);

/// The eigenvalues of the symmetric matrix A, ascending, and the matching unit eigenvectors as
/// the columns of a rotation matrix (orthonormal, determinant +1). Only the lower triangle is read.
/// When all eigenvalues are equal the vectors are the identity.
/// Precondition: A is finite (checked in debug builds: throws std::logic_error).
template <typename T>
std::pair<Vector3<T>, Matrix3<T>> CalcSymmetricEigensystem(
    const Matrix3<T>& A, PrincipalSolver solver = PrincipalSolver::kAccurate);

}  // namespace massprops

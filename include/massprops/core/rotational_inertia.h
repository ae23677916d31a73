#pragma once
/// @file
/// RotationalInertia<T>: the rotational inertia I_BP_E of a body (or a set of particles) B about a
/// point P, expressed in a frame E. Names and semantics follow Drake's RotationalInertia, with
/// Simbody's Inertia_ extras (IsInf, IsFinite, FromMatrix, exact ==).
///
/// Conventions
/// - Products of inertia use the negated convention: the 3x3 matrix is
///   [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]] with Ixx = ∫(y²+z²) dm and
///   Ixy = -∫xy dm (the matrix entry). Constructors take matrix entries, as Drake's do; the ixy,
///   ixz, iyz values of URDF and SDF files are exactly these matrix entries.
/// - Storage: the six unique entries as six scalars (48 bytes for double), no padding, no 3x3.
/// - Validity: see CouldBePhysicallyValid(). In debug builds (NDEBUG not defined) constructors and
///   operations whose result could be invalid throw std::logic_error whose message quotes the
///   moments, products and principal moments; release builds skip these checks for speed, as
///   Drake does. To hold numbers that may be invalid (e.g. read from a file), use
///   MakeFromMomentsAndProductsOfInertia(..., true) or FromMatrix(..., true). Explicit predicates
///   (CouldBePhysicallyValid, IsNaN, ...) never throw.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "massprops/core/eigen_types.h"
#include "massprops/core/principal_axes.h"

namespace massprops {

namespace internal {

/// Relative tolerance used by CouldBePhysicallyValid() with no argument: 32·eps(T)
/// (7.1e-15 for double, 3.5e-18 for x86 long double, 3.8e-6 for float).
template <typename T>
constexpr T DefaultInertiaValidityTolerance() {
  return T(32) * std::numeric_limits<T>::epsilon();
}

/// The shared physical-validity test on the six entries (matrix entries, negated products).
/// True iff all six are finite and the principal moments λ1 <= λ2 <= λ3 satisfy
/// λ1 >= -τ and λ1 + λ2 >= λ3 - τ with τ = relative_tolerance · max(trace, reference_trace).
/// reference_trace (>= 0, may be 0) lets a caller widen the tolerance when the entries carry
/// round-off relative to a larger quantity (e.g. an inertia shifted from a distant point).
/// Entries outside about 1e-77 .. 1e77 (double) are scaled by a power of two first (exact), so
/// 1e300 or subnormal inputs neither overflow nor underflow. Never throws.
template <typename T>
bool IsPhysicallyValidInertia(const T& xx, const T& yy, const T& zz, const T& xy, const T& xz,
                              const T& yz, const T& relative_tolerance,
                              const T& reference_trace = T(0));

/// Principal moments (ascending) of the six entries (the solver scales huge or tiny entries by a
/// power of two, exactly, so they neither overflow nor underflow); +0 for all-zero entries.
/// Precondition: entries finite.
template <typename T>
Vector3<T> ScaledPrincipalMoments(const T& xx, const T& yy, const T& zz, const T& xy, const T& xz,
                                  const T& yz, PrincipalSolver solver);

}  // namespace internal

/// The rotational inertia of a body or set of particles about a point, expressed in a frame.
/// See the file comment for the conventions (negated products, debug-build checks).
/// T is float, double or long double (explicitly instantiated in src/core/rotational_inertia.cc).
template <typename T>
class RotationalInertia {
 public:
  /// Constructs an inertia whose six entries are NaN (so that use before assignment shows).
  RotationalInertia() { SetToNaN(); }

  /// Principal moments Ixx, Iyy, Izz with zero products.
  /// Debug builds: throws std::logic_error if the result fails CouldBePhysicallyValid().
  RotationalInertia(const T& Ixx, const T& Iyy, const T& Izz)
      : RotationalInertia(Ixx, Iyy, Izz, T(0), T(0), T(0)) {}

  /// From the six matrix entries (Ixy = -∫xy dm etc., see the file comment).
  /// Debug builds: throws std::logic_error if the result fails CouldBePhysicallyValid().
  RotationalInertia(const T& Ixx, const T& Iyy, const T& Izz, const T& Ixy, const T& Ixz,
                    const T& Iyz)
      : xx_(Ixx), yy_(Iyy), zz_(Izz), xy_(Ixy), xz_(Ixz), yz_(Iyz) {
#ifndef NDEBUG
    ThrowIfNotPhysicallyValid("RotationalInertia(Ixx, Iyy, Izz, Ixy, Ixz, Iyz)");
#endif
  }

  /// The inertia about P of a particle Q of the given mass at p_PQ_E:
  /// m·(|p|²·1 − p·pᵀ). About 15 flops. Debug builds: throws if mass < 0 or not finite.
  RotationalInertia(const T& mass, const Vector3<T>& p_PQ_E) {
#ifndef NDEBUG
    ThrowIfMassIsNegativeOrNotFinite(mass, "RotationalInertia(mass, p_PQ_E)");
#endif
    SetZero();
    AddPointMass(mass, p_PQ_E);
  }

  /// The six entries, checked always: throws std::logic_error (message quotes the entries and
  /// the principal moments) if the result fails CouldBePhysicallyValid(), unless
  /// skip_validity_check is true (then any numbers, even NaN, are accepted).
  static RotationalInertia MakeFromMomentsAndProductsOfInertia(const T& Ixx, const T& Iyy,
                                                               const T& Izz, const T& Ixy,
                                                               const T& Ixz, const T& Iyz,
                                                               bool skip_validity_check = false) {
    RotationalInertia I = Raw(Ixx, Iyy, Izz, Ixy, Ixz, Iyz);
    if (!skip_validity_check) I.ThrowIfNotPhysicallyValid("MakeFromMomentsAndProductsOfInertia()");
    return I;
  }

  /// From a full 3x3 matrix (negated-product convention). Throws std::logic_error always if the
  /// matrix is not symmetric to round-off (|A(i,j) − A(j,i)| > 8·eps·max|A|, or a NaN in
  /// an off-diagonal pair); the two triangles are averaged. Also throws (always) if the result
  /// fails CouldBePhysicallyValid(), unless skip_validity_check is true (Simbody's
  /// Inertia(Mat33) checks symmetry only in debug builds; this one always does).
  static RotationalInertia FromMatrix(const Matrix3<T>& I, bool skip_validity_check = false);

  /// Ixx = Iyy = Izz = I_triaxial, zero products (e.g. a sphere or a cube about its center).
  /// Debug builds: throws std::logic_error if I_triaxial < 0 or not finite.
  static RotationalInertia TriaxiallySymmetric(const T& I_triaxial) {
    return RotationalInertia(I_triaxial, I_triaxial, I_triaxial, T(0), T(0), T(0));
  }

  /// 3 (Eigen-style size queries).
  static constexpr int rows() { return 3; }
  /// 3 (Eigen-style size queries).
  static constexpr int cols() { return 3; }

  /// [Ixx, Iyy, Izz].
  Vector3<T> get_moments() const { return Vector3<T>(xx_, yy_, zz_); }
  /// [Ixy, Ixz, Iyz] (matrix entries, negated convention).
  Vector3<T> get_products() const { return Vector3<T>(xy_, xz_, yz_); }

  /// Ixx + Iyy + Izz, invariant under re-expression; equals 2·∫|r|² dm. 2 flops. Overflows to
  /// +Inf when the sum exceeds the range of T (the validity test does not).
  T Trace() const { return xx_ + yy_ + zz_; }

  /// Trace()/2: no moment of inertia about any axis through P can exceed it (for a valid
  /// inertia). Computed as halves summed, so it does not overflow when Trace() would.
  T CalcMaximumPossibleMomentOfInertia() const { return xx_ / T(2) + yy_ / T(2) + zz_ / T(2); }

  /// The (i, j) matrix entry, 0 <= i, j <= 2 (read-only: an inertia is changed only as a whole).
  /// Debug builds: throws std::logic_error if i or j is out of range.
  const T& operator()(int i, int j) const {
#ifndef NDEBUG
    if (i < 0 || i > 2 || j < 0 || j > 2) {
      throw std::logic_error("RotationalInertia::operator()(i, j): index out of range [0, 2]");
    }
#endif
    const T* const entries[3][3] = {{&xx_, &xy_, &xz_}, {&xy_, &yy_, &yz_}, {&xz_, &yz_, &zz_}};
    return *entries[i][j];
  }

  /// The full symmetric 3x3 matrix.
  Matrix3<T> CopyToFullMatrix3() const {
    Matrix3<T> I;
    I << xx_, xy_, xz_, xy_, yy_, yz_, xz_, yz_, zz_;
    return I;
  }

  /// True iff max|this − other| (over the six entries) <= precision · min(Imax_this,
  /// Imax_other), with Imax = CalcMaximumPossibleMomentOfInertia(). (Drake uses the larger
  /// Imax; the smaller is stricter and symmetric as well.) False if either has a NaN.
  bool IsNearlyEqualTo(const RotationalInertia& other, const T& precision) const {
    using std::abs;
    const T scale =
        std::min(CalcMaximumPossibleMomentOfInertia(), other.CalcMaximumPossibleMomentOfInertia());
    T d = abs(xx_ - other.xx_);
    d = std::max(d, abs(yy_ - other.yy_));
    d = std::max(d, abs(zz_ - other.zz_));
    d = std::max(d, abs(xy_ - other.xy_));
    d = std::max(d, abs(xz_ - other.xz_));
    d = std::max(d, abs(yz_ - other.yz_));
    return !IsNaN() && !other.IsNaN() && d <= precision * scale;
  }

  /// Exact equality of all six entries (Simbody). NaN compares unequal.
  bool operator==(const RotationalInertia& other) const {
    return xx_ == other.xx_ && yy_ == other.yy_ && zz_ == other.zz_ && xy_ == other.xy_ &&
           xz_ == other.xz_ && yz_ == other.yz_;
  }
  bool operator!=(const RotationalInertia& other) const { return !(*this == other); }

  /// Adds an inertia about the same point, expressed in the same frame (sum of valid is valid:
  /// not checked). 6 flops.
  RotationalInertia& operator+=(const RotationalInertia& I) {
    xx_ += I.xx_, yy_ += I.yy_, zz_ += I.zz_, xy_ += I.xy_, xz_ += I.xz_, yz_ += I.yz_;
    return *this;
  }
  /// The sum (see operator+=).
  RotationalInertia operator+(const RotationalInertia& I) const {
    return RotationalInertia(*this) += I;
  }

  /// Subtracts an inertia about the same point, same frame. Debug builds: throws
  /// std::logic_error if the result fails CouldBePhysicallyValid(). 6 flops.
  RotationalInertia& operator-=(const RotationalInertia& I) {
    xx_ -= I.xx_, yy_ -= I.yy_, zz_ -= I.zz_, xy_ -= I.xy_, xz_ -= I.xz_, yz_ -= I.yz_;
#ifndef NDEBUG
    ThrowIfNotPhysicallyValid("operator-=");
#endif
    return *this;
  }
  /// The difference (see operator-=).
  RotationalInertia operator-(const RotationalInertia& I) const {
    return RotationalInertia(*this) -= I;
  }

  /// Multiplies by a scalar s >= 0. Debug builds: throws std::logic_error if s < 0 (or NaN).
  RotationalInertia& operator*=(const T& nonnegative_scalar) {
#ifndef NDEBUG
    if (!(nonnegative_scalar >= T(0))) {
      ThrowWithDescription("operator*= (or operator*) by the negative or NaN scalar " +
                           ToString(nonnegative_scalar));
    }
#endif
    ScaleEntries(nonnegative_scalar);
    return *this;
  }
  /// The product by a scalar s >= 0 (see operator*=).
  RotationalInertia operator*(const T& nonnegative_scalar) const {
    return RotationalInertia(*this) *= nonnegative_scalar;
  }
  /// s · I for a scalar s >= 0 (see operator*=).
  friend RotationalInertia operator*(const T& nonnegative_scalar, const RotationalInertia& I) {
    return I * nonnegative_scalar;
  }

  /// Divides by a scalar s > 0. Debug builds: throws std::logic_error if s <= 0 (or NaN).
  RotationalInertia& operator/=(const T& positive_scalar) {
#ifndef NDEBUG
    if (!(positive_scalar > T(0))) {
      ThrowWithDescription("operator/= (or operator/) by the non-positive or NaN scalar " +
                           ToString(positive_scalar));
    }
#endif
    xx_ /= positive_scalar, yy_ /= positive_scalar, zz_ /= positive_scalar;
    xy_ /= positive_scalar, xz_ /= positive_scalar, yz_ /= positive_scalar;
    return *this;
  }
  /// The quotient by a scalar s > 0 (see operator/=).
  RotationalInertia operator/(const T& positive_scalar) const {
    return RotationalInertia(*this) /= positive_scalar;
  }

  /// I · w_E (e.g. the angular momentum H = I·ω about P). 15 flops.
  Vector3<T> operator*(const Vector3<T>& w_E) const {
    return Vector3<T>(xx_ * w_E(0) + xy_ * w_E(1) + xz_ * w_E(2),
                      xy_ * w_E(0) + yy_ * w_E(1) + yz_ * w_E(2),
                      xz_ * w_E(0) + yz_ * w_E(1) + zz_ * w_E(2));
  }

  /// s · I for any scalar s (even negative), never checked: for intermediate results, e.g. the
  /// negative of an inertia about to be added to a larger one.
  RotationalInertia MultiplyByScalarSkipValidityCheck(const T& s) const {
    RotationalInertia I(*this);
    I.ScaleEntries(s);
    return I;
  }

  /// Sets all six entries to NaN.
  void SetToNaN() { xx_ = yy_ = zz_ = xy_ = xz_ = yz_ = std::numeric_limits<T>::quiet_NaN(); }
  /// Sets all six entries to zero (the inertia of nothing, or of a particle at P).
  void SetZero() { xx_ = yy_ = zz_ = xy_ = xz_ = yz_ = T(0); }

  /// True iff any entry is NaN.
  bool IsNaN() const {
    using std::isnan;
    return isnan(xx_) || isnan(yy_) || isnan(zz_) || isnan(xy_) || isnan(xz_) || isnan(yz_);
  }
  /// True iff any entry is +Inf or -Inf (Simbody).
  bool IsInf() const {
    using std::isinf;
    return isinf(xx_) || isinf(yy_) || isinf(zz_) || isinf(xy_) || isinf(xz_) || isinf(yz_);
  }
  /// True iff every entry is finite (neither NaN nor Inf) (Simbody).
  bool IsFinite() const {
    using std::isfinite;
    return isfinite(xx_) && isfinite(yy_) && isfinite(zz_) && isfinite(xy_) && isfinite(xz_) &&
           isfinite(yz_);
  }
  /// True iff all six entries are exactly zero.
  bool IsZero() const {
    return xx_ == T(0) && yy_ == T(0) && zz_ == T(0) && xy_ == T(0) && xz_ == T(0) && yz_ == T(0);
  }

  /// This inertia with scalar type S (each entry converted with static_cast; no check).
  template <typename S>
  RotationalInertia<S> cast() const {
    return RotationalInertia<S>::MakeFromMomentsAndProductsOfInertia(
        static_cast<S>(xx_), static_cast<S>(yy_), static_cast<S>(zz_), static_cast<S>(xy_),
        static_cast<S>(xz_), static_cast<S>(yz_), true);
  }

  /// The principal moments of inertia, ascending: bit for bit CalcSymmetricEigenvalues(
  /// CopyToFullMatrix3(), solver), at the same cost (no copy, no extra pass: the solver itself
  /// scales by a power of two, exactly, where squares of 1e300 entries would overflow, and tests
  /// finiteness only off its fast path). Throws std::logic_error (always, not only in debug
  /// builds) if an entry is NaN or Inf. The accurate solver (default) gives every moment within a
  /// few units of round-off of the trace and is exact on diagonal input; see principal_axes.h and
  /// bench/ for the fast one.
  Vector3<T> CalcPrincipalMomentsOfInertia(
      PrincipalSolver solver = PrincipalSolver::kAccurate) const {
    Vector3<T> moments;
    if (!internal::SymmetricEigenvaluesOfEntries(xx_, yy_, zz_, xy_, xz_, yz_, solver, &moments)) {
      ThrowWithDescription("CalcPrincipalMomentsOfInertia() on non-finite entries");
    }
    return moments;
  }

  /// The principal moments (ascending) and the principal axes as the columns of a rotation
  /// matrix R_EA (right-handed, orthonormal; column k is the axis of moment k, expressed in E):
  /// bit for bit CalcSymmetricEigensystem(CopyToFullMatrix3()), at the same cost. When all three
  /// moments are equal the axes are the identity. Throws std::logic_error (always) if an entry is
  /// NaN or Inf. Both solvers compute axes the same way (see principal_axes.h).
  std::pair<Vector3<T>, Matrix3<T>> CalcPrincipalMomentsAndAxesOfInertia(
      PrincipalSolver solver = PrincipalSolver::kAccurate) const {
    static_cast<void>(solver);
    std::pair<Vector3<T>, Matrix3<T>> result;
    if (!internal::SymmetricEigensystemOfEntries(xx_, yy_, zz_, xy_, xz_, yz_, &result.first,
                                                 &result.second)) {
      ThrowWithDescription("CalcPrincipalMomentsAndAxesOfInertia() on non-finite entries");
    }
    return result;
  }

  /// True iff this could be the rotational inertia of a real body about some point: all six
  /// entries finite and the principal moments λ1 <= λ2 <= λ3 (accurate solver) satisfy
  /// λ1 >= -τ and λ1 + λ2 >= λ3 - τ, with τ = 32·eps(T)·trace (scale-free). Equivalently the
  /// second-moment matrix Σ = ½·tr(I)·1 − I is positive semi-definite within τ/2, so an
  /// indefinite matrix whose diagonal satisfies the triangle inequality fails. Zero is valid.
  /// Thin disks and thin rods (on the boundary) pass after any rotation at any scale; anything
  /// beyond the boundary by more than about τ plus round-off fails: for double and long double
  /// anything beyond by 1e-6·trace fails at every scale; float resolves about 1e-5·trace.
  /// Cost: about 40 flops when Σ is diagonally dominant (Gershgorin accepts), otherwise one
  /// accurate eigenvalue solve. Never throws.
  bool CouldBePhysicallyValid() const {
    return CouldBePhysicallyValid(internal::DefaultInertiaValidityTolerance<T>());
  }

  /// As CouldBePhysicallyValid() with τ = relative_tolerance·trace (e.g. 1e-6 for numbers
  /// written in files with a few significant digits). relative_tolerance 0 means "round-off
  /// only". Never throws.
  bool CouldBePhysicallyValid(const T& relative_tolerance) const {
    return internal::IsPhysicallyValidInertia(xx_, yy_, zz_, xy_, xz_, yz_, relative_tolerance);
  }

  /// A sentence (several lines) saying why CouldBePhysicallyValid(relative_tolerance) is false,
  /// quoting the entries and the principal moments; empty when valid. Never throws.
  std::string CriticizeNotPhysicallyValid(
      const T& relative_tolerance = internal::DefaultInertiaValidityTolerance<T>()) const;

  /// Re-expresses in frame A: I_BP_A = R_AE · I_BP_E · R_AEᵀ, where R_AE is a rotation matrix
  /// (orthonormal, det +1; not checked). About 75 flops (R·I as 45, then only the six unique
  /// entries of (R·I)·Rᵀ as 30).
  RotationalInertia& ReExpressInPlace(const Matrix3<T>& R_AE);
  /// Re-expressed copy (see ReExpressInPlace).
  RotationalInertia ReExpress(const Matrix3<T>& R_AE) const {
    return RotationalInertia(*this).ReExpressInPlace(R_AE);
  }

  /// Parallel-axis theorem away from the center of mass: this is I_BBcm_E, the result is
  /// I_BQ_E = I_BBcm_E + m·(|p|²·1 − p·pᵀ) with p = p_BcmQ_E. 18 flops (9 multiplies, 9 adds).
  /// Sums of valid terms: not checked.
  RotationalInertia& ShiftFromCenterOfMassInPlace(const T& mass, const Vector3<T>& p_BcmQ_E) {
    AddPointMass(mass, p_BcmQ_E);
    return *this;
  }
  /// Shifted copy (see ShiftFromCenterOfMassInPlace).
  RotationalInertia ShiftFromCenterOfMass(const T& mass, const Vector3<T>& p_BcmQ_E) const {
    return RotationalInertia(*this).ShiftFromCenterOfMassInPlace(mass, p_BcmQ_E);
  }

  /// Parallel-axis theorem toward the center of mass: this is I_BQ_E, the result is
  /// I_BBcm_E = I_BQ_E − m·(|p|²·1 − p·pᵀ) with p = p_QBcm_E. 18 flops. Subtraction loses
  /// accuracy when |p|² ≫ the radius of gyration² (prefer shifting away from a central
  /// inertia). Debug builds: throws std::logic_error if the result fails CouldBePhysicallyValid().
  RotationalInertia& ShiftToCenterOfMassInPlace(const T& mass, const Vector3<T>& p_QBcm_E) {
    AddPointMass(-mass, p_QBcm_E);
#ifndef NDEBUG
    ThrowIfNotPhysicallyValid("ShiftToCenterOfMass()");
#endif
    return *this;
  }
  /// Shifted copy (see ShiftToCenterOfMassInPlace).
  RotationalInertia ShiftToCenterOfMass(const T& mass, const Vector3<T>& p_QBcm_E) const {
    return RotationalInertia(*this).ShiftToCenterOfMassInPlace(mass, p_QBcm_E);
  }

  /// From I_BP_E to I_BQ_E in one step: I_BQ = I_BP + m·([b]ᵀ[b] − [a]ᵀ[a]) with a = p_PBcm_E,
  /// b = p_QBcm_E, written with d = b − a (= p_QP_E) so that no term cancels when P and Q are
  /// close: 30 flops, versus 36 for ShiftToCenterOfMass followed by ShiftFromCenterOfMass.
  /// Debug builds: throws std::logic_error if the result fails CouldBePhysicallyValid().
  RotationalInertia& ShiftToThenAwayFromCenterOfMassInPlace(const T& mass,
                                                            const Vector3<T>& p_PBcm_E,
                                                            const Vector3<T>& p_QBcm_E);
  /// Shifted copy (see ShiftToThenAwayFromCenterOfMassInPlace).
  RotationalInertia ShiftToThenAwayFromCenterOfMass(const T& mass, const Vector3<T>& p_PBcm_E,
                                                    const Vector3<T>& p_QBcm_E) const {
    return RotationalInertia(*this).ShiftToThenAwayFromCenterOfMassInPlace(mass, p_PBcm_E,
                                                                           p_QBcm_E);
  }

 protected:
  /// Unchecked construction from the six entries (for factories and derived classes).
  static RotationalInertia Raw(const T& Ixx, const T& Iyy, const T& Izz, const T& Ixy, const T& Ixz,
                               const T& Iyz) {
    RotationalInertia I;
    I.xx_ = Ixx, I.yy_ = Iyy, I.zz_ = Izz, I.xy_ = Ixy, I.xz_ = Ixz, I.yz_ = Iyz;
    return I;
  }

  /// Multiplies the six entries by s, unchecked.
  void ScaleEntries(const T& s) { xx_ *= s, yy_ *= s, zz_ *= s, xy_ *= s, xz_ *= s, yz_ *= s; }

  /// Adds m·(|p|²·1 − p·pᵀ) (m may be negative). 18 flops.
  void AddPointMass(const T& m, const Vector3<T>& p) {
    const T mx = m * p(0), my = m * p(1), mz = m * p(2);
    const T mxx = mx * p(0), myy = my * p(1), mzz = mz * p(2);
    xx_ += myy + mzz;
    yy_ += mxx + mzz;
    zz_ += mxx + myy;
    xy_ -= mx * p(1);
    xz_ -= mx * p(2);
    yz_ -= my * p(2);
  }

  /// Throws std::logic_error "The rotational inertia\n <entries, principal moments>\nresulting
  /// from <operation> did not pass the test CouldBePhysicallyValid()." if it fails the test.
  void ThrowIfNotPhysicallyValid(const char* operation) const;
  /// Throws std::logic_error quoting this inertia and the given reason.
  [[noreturn]] void ThrowWithDescription(const std::string& reason) const;
  /// Debug-check helper: throws std::logic_error if !(mass >= 0) or mass is infinite.
  static void ThrowIfMassIsNegativeOrNotFinite(const T& mass, const char* operation);
  /// The entries and principal moments, one per line, for error messages.
  std::string Describe() const;
  /// A number as text with digits10 significant digits.
  static std::string ToString(const T& value);

 private:
  T xx_, yy_, zz_, xy_, xz_, yz_;
};

/// Prints the 3x3 matrix as Drake does, one row per line: " [Ixx  Ixy  Ixz]\n [Ixy  Iyy  Iyz]\n
/// [Ixz  Iyz  Izz]\n".
template <typename T>
std::ostream& operator<<(std::ostream& out, const RotationalInertia<T>& I) {
  for (int i = 0; i < 3; ++i) {
    out << " [" << I(i, 0) << "  " << I(i, 1) << "  " << I(i, 2) << "]\n";
  }
  return out;
}

// ------------------------------------------------------------------------------- definitions

namespace internal {

/// The power of two e such that entries of magnitude at most s (> 0, finite), scaled by 2^-e,
/// can be squared and summed without overflow or underflow: 0 (no scaling, the fast common case)
/// when s lies within 2^(min_exponent/4) .. 2^(max_exponent/4) (about 1e-77 .. 1e77 for double),
/// otherwise the exponent of s.
constexpr long double PowerOfTwo(int n) {
  long double x = 1;
  for (; n > 0; --n) x *= 2;
  for (; n < 0; ++n) x /= 2;
  return x;
}

template <typename T>
int SafeScaleExponent(const T& s) {
  constexpr T kLow = static_cast<T>(PowerOfTwo(std::numeric_limits<T>::min_exponent / 4));
  constexpr T kHigh = static_cast<T>(PowerOfTwo(std::numeric_limits<T>::max_exponent / 4));
  return (s > kLow && s < kHigh) ? 0 : std::ilogb(s);
}

/// Fills the full symmetric matrix of the six entries scaled by 2^-e (exact; e may be 0).
template <typename T>
Matrix3<T> ScaledMatrix(const T& xx, const T& yy, const T& zz, const T& xy, const T& xz,
                        const T& yz, int e) {
  Matrix3<T> A;
  if (e == 0) {
    A << xx, xy, xz, xy, yy, yz, xz, yz, zz;
  } else {
    A(0, 0) = std::ldexp(xx, -e), A(1, 1) = std::ldexp(yy, -e), A(2, 2) = std::ldexp(zz, -e);
    A(1, 0) = A(0, 1) = std::ldexp(xy, -e);
    A(2, 0) = A(0, 2) = std::ldexp(xz, -e);
    A(2, 1) = A(1, 2) = std::ldexp(yz, -e);
  }
  return A;
}

template <typename T>
Vector3<T> ScaledPrincipalMoments(const T& xx, const T& yy, const T& zz, const T& xy, const T& xz,
                                  const T& yz, PrincipalSolver solver) {
  if (xx == T(0) && yy == T(0) && zz == T(0) && xy == T(0) && xz == T(0) && yz == T(0)) {
    return Vector3<T>::Zero();  // +0 even for -0 entries.
  }
  Vector3<T> lambda;
  SymmetricEigenvaluesOfEntries(xx, yy, zz, xy, xz, yz, solver, &lambda);
  return lambda;
}

template <typename T>
bool IsPhysicallyValidInertia(const T& xx, const T& yy, const T& zz, const T& xy, const T& xz,
                              const T& yz, const T& relative_tolerance, const T& reference_trace) {
  using std::abs;
  using std::isfinite;
  if (!(isfinite(xx) && isfinite(yy) && isfinite(zz) && isfinite(xy) && isfinite(xz) &&
        isfinite(yz))) {
    return false;
  }
  if (!(relative_tolerance >= T(0)) || !(reference_trace >= T(0))) return false;
  const T s = std::max({abs(xx), abs(yy), abs(zz), abs(xy), abs(xz), abs(yz)});
  if (s == T(0)) return true;  // Zero inertia: a particle at the point, or nothing.
  // Scale by a power of two (exact) when needed, so that nothing below overflows or underflows.
  const int e = SafeScaleExponent(s);
  const Matrix3<T> A = ScaledMatrix(xx, yy, zz, xy, xz, yz, e);
  const T a = A(0, 0), b = A(1, 1), c = A(2, 2), p = A(1, 0), q = A(2, 0), r = A(2, 1);
  const T trace = a + b + c;
  if (trace < T(0)) return false;  // Some principal moment is negative.
  const T reference =
      e == 0 ? reference_trace
             : std::min(std::ldexp(reference_trace, -e), std::numeric_limits<T>::max());
  const T tau = relative_tolerance * std::max(trace, reference);
  // Diagonal of Σ = ½·tr·1 − I, and its off-diagonal entries −p, −q, −r.
  const T sxx = (b + c - a) / T(2), syy = (a + c - b) / T(2), szz = (a + b - c) / T(2);
  // Quick reject: the smallest eigenvalue of Σ is at most its smallest diagonal entry, and
  // λ1 + λ2 − λ3 = 2·σmin.
  if (std::min({sxx, syy, szz}) < -tau / T(2)) return false;
  // Quick accept (Gershgorin): every disc of Σ lies in [0, ∞) so σmin >= 0.
  if (sxx >= abs(p) + abs(q) && syy >= abs(p) + abs(r) && szz >= abs(q) + abs(r)) return true;
  const Vector3<T> lambda = CalcSymmetricEigenvalues<T>(A, PrincipalSolver::kAccurate);
  return lambda(0) >= -tau && lambda(0) + lambda(1) >= lambda(2) - tau;
}

}  // namespace internal

template <typename T>
std::string RotationalInertia<T>::ToString(const T& value) {
  std::ostringstream out;
  out.precision(std::numeric_limits<T>::digits10);
  out << value;
  return out.str();
}

template <typename T>
std::string RotationalInertia<T>::Describe() const {
  std::string text = "\n I(0,0)=" + ToString(xx_) + ", I(1,1)=" + ToString(yy_) +
                     ", I(2,2)=" + ToString(zz_) + "\n I(0,1)=" + ToString(xy_) +
                     ", I(0,2)=" + ToString(xz_) + ", I(1,2)=" + ToString(yz_) + "\n";
  if (IsFinite()) {
    const Vector3<T> lambda =
        internal::ScaledPrincipalMoments(xx_, yy_, zz_, xy_, xz_, yz_, PrincipalSolver::kAccurate);
    text += " principal moments: [" + ToString(lambda(0)) + "  " + ToString(lambda(1)) + "  " +
            ToString(lambda(2)) + "]\n";
  } else {
    text += " principal moments: not computed (an entry is NaN or infinite)\n";
  }
  return text;
}

template <typename T>
void RotationalInertia<T>::ThrowWithDescription(const std::string& reason) const {
  throw std::logic_error("The rotational inertia" + Describe() + "resulting from " + reason +
                         " is not allowed.");
}

template <typename T>
void RotationalInertia<T>::ThrowIfNotPhysicallyValid(const char* operation) const {
  if (CouldBePhysicallyValid()) return;
  throw std::logic_error("The rotational inertia" + Describe() + "resulting from " +
                         std::string(operation) +
                         " did not pass the test CouldBePhysicallyValid().");
}

template <typename T>
void RotationalInertia<T>::ThrowIfMassIsNegativeOrNotFinite(const T& mass, const char* operation) {
  using std::isfinite;
  if (!(mass >= T(0)) || !isfinite(mass)) {
    throw std::logic_error(std::string(operation) + ": the mass " + ToString(mass) +
                           " is negative or not finite.");
  }
}

template <typename T>
std::string RotationalInertia<T>::CriticizeNotPhysicallyValid(const T& relative_tolerance) const {
  if (CouldBePhysicallyValid(relative_tolerance)) return "";
  std::string reason;
  if (!IsFinite()) {
    reason = "has an entry that is NaN or infinite";
  } else {
    const Vector3<T> lambda =
        internal::ScaledPrincipalMoments(xx_, yy_, zz_, xy_, xz_, yz_, PrincipalSolver::kAccurate);
    if (lambda(0) < T(0) && !(lambda(0) + lambda(1) >= lambda(2))) {
      reason =
          "has a negative principal moment and principal moments that violate the "
          "triangle inequality";
    } else if (lambda(0) < T(0)) {
      reason = "has a negative principal moment";
    } else {
      reason =
          "has principal moments that violate the triangle inequality (the smaller two sum "
          "to less than the largest)";
    }
  }
  return "The rotational inertia" + Describe() + reason + " (relative tolerance " +
         ToString(relative_tolerance) + " of the trace).";
}

template <typename T>
RotationalInertia<T> RotationalInertia<T>::FromMatrix(const Matrix3<T>& I,
                                                      bool skip_validity_check) {
  using std::abs;
  const T scale = I.cwiseAbs().maxCoeff();
  const T tolerance = T(8) * std::numeric_limits<T>::epsilon() * scale;
  for (int i = 0; i < 3; ++i) {
    for (int j = i + 1; j < 3; ++j) {
      if (!(abs(I(i, j) - I(j, i)) <= tolerance) && !(I(i, j) == I(j, i))) {
        std::ostringstream message;
        message.precision(std::numeric_limits<T>::digits10);
        message << "RotationalInertia::FromMatrix(): the matrix\n"
                << I << "\nis not symmetric: entry (" << i << "," << j << ") = " << I(i, j)
                << " but entry (" << j << "," << i << ") = " << I(j, i) << ".";
        throw std::logic_error(message.str());
      }
    }
  }
  const T half(0.5);
  RotationalInertia result = Raw(I(0, 0), I(1, 1), I(2, 2), half * I(0, 1) + half * I(1, 0),
                                 half * I(0, 2) + half * I(2, 0), half * I(1, 2) + half * I(2, 1));
  if (!skip_validity_check) result.ThrowIfNotPhysicallyValid("FromMatrix()");
  return result;
}

template <typename T>
RotationalInertia<T>& RotationalInertia<T>::ReExpressInPlace(const Matrix3<T>& R) {
  // M = R·I (45 flops), then the upper triangle of M·Rᵀ (6 dot products, 30 flops).
  T M[3][3];
  for (int i = 0; i < 3; ++i) {
    const T r0 = R(i, 0), r1 = R(i, 1), r2 = R(i, 2);
    M[i][0] = r0 * xx_ + r1 * xy_ + r2 * xz_;
    M[i][1] = r0 * xy_ + r1 * yy_ + r2 * yz_;
    M[i][2] = r0 * xz_ + r1 * yz_ + r2 * zz_;
  }
  const auto dot = [&M, &R](int i, int j) {
    return M[i][0] * R(j, 0) + M[i][1] * R(j, 1) + M[i][2] * R(j, 2);
  };
  xx_ = dot(0, 0), yy_ = dot(1, 1), zz_ = dot(2, 2);
  xy_ = dot(0, 1), xz_ = dot(0, 2), yz_ = dot(1, 2);
  return *this;
}

template <typename T>
RotationalInertia<T>& RotationalInertia<T>::ShiftToThenAwayFromCenterOfMassInPlace(
    const T& mass, const Vector3<T>& p_PBcm_E, const Vector3<T>& p_QBcm_E) {
  // I_BQ − I_BP = m·(|b|²·1 − b·bᵀ) − m·(|a|²·1 − a·aᵀ), a = p_PBcm, b = p_QBcm, d = b − a.
  // Diagonal: m·(b_i² − a_i²) = u_i·(b_i + a_i) with u = m·d.
  // Off-diagonal (negated): −m·(b_i·b_j − a_i·a_j) = −(u_i·b_j + a_i·u_j).
  const Vector3<T>& a = p_PBcm_E;
  const Vector3<T>& b = p_QBcm_E;
  const T ux = mass * (b(0) - a(0)), uy = mass * (b(1) - a(1)), uz = mass * (b(2) - a(2));
  const T tx = ux * (b(0) + a(0)), ty = uy * (b(1) + a(1)), tz = uz * (b(2) + a(2));
  xx_ += ty + tz;
  yy_ += tx + tz;
  zz_ += tx + ty;
  xy_ -= ux * b(1) + a(0) * uy;
  xz_ -= ux * b(2) + a(0) * uz;
  yz_ -= uy * b(2) + a(1) * uz;
#ifndef NDEBUG
  ThrowIfNotPhysicallyValid("ShiftToThenAwayFromCenterOfMass()");
#endif
  return *this;
}

extern template class RotationalInertia<float>;
extern template class RotationalInertia<double>;
extern template class RotationalInertia<long double>;

}  // namespace massprops

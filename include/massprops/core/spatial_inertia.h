#pragma once
/// @file
/// SpatialInertia<T>: the mass distribution of a body S about a point P, expressed in a frame E —
/// its mass m, the position p_PScm_E of its center of mass Scm from P, and its unit inertia
/// G_SP_E about P (Drake's SpatialInertia, same names and storage). The rotational inertia
/// about P is I_SP_E = m·G_SP_E. Physical validity is decided at the center of mass.

#include <Eigen/Core>
#include <ostream>
#include <string>

#include "massprops/core/eigen_types.h"
#include "massprops/core/rotational_inertia.h"
#include "massprops/core/unit_inertia.h"

namespace massprops {

/// Mass, center of mass and unit inertia of a body about a point P, expressed in frame E.
/// Debug builds (NDEBUG not defined) check the constructors' preconditions (throw
/// std::logic_error) unless skip_validity_check is true; release builds skip them. Predicates
/// (IsPhysicallyValid, CriticizeNotPhysicallyValid, IsNaN) never throw.
/// T is float, double or long double (explicitly instantiated in src/core/spatial_inertia.cc).
template <typename T>
class SpatialInertia {
 public:
  /// Mass, center of mass and unit inertia all NaN.
  SpatialInertia() { SetNaN(); }

  /// From the mass m, the center of mass p_PScm_E and the unit inertia G_SP_E about P (not about
  /// the center of mass). Debug builds, unless skip_validity_check: throws std::logic_error if
  /// !IsPhysicallyValid() (mass negative or not finite, or central inertia not valid), the
  /// message naming what fails.
  SpatialInertia(const T& mass, const Vector3<T>& p_PScm_E, const UnitInertia<T>& G_SP_E,
                 bool skip_validity_check = false)
      : mass_(mass), p_PScm_E_(p_PScm_E), G_SP_E_(G_SP_E) {
#ifndef NDEBUG
    if (!skip_validity_check) ThrowIfNotPhysicallyValid("SpatialInertia(mass, p_PScm_E, G_SP_E)");
#else
    (void)skip_validity_check;
#endif
  }

  /// From the mass, the center of mass p_PScm_E and the rotational inertia I_SScm_E about the
  /// center of mass: shifts I_SScm_E/m away from Scm to P (sums of positive semi-definite terms
  /// only). Mass 0 gives G_SP = the point-mass unit inertia of p_PScm_E (I_SScm_E is ignored).
  /// Debug builds: throws std::logic_error if mass < 0 or not finite, or I_SScm_E not valid.
  static SpatialInertia MakeFromCentralInertia(const T& mass, const Vector3<T>& p_PScm_E,
                                               const RotationalInertia<T>& I_SScm_E);

  /// A particle of the given mass at p_PQ_E (about P). Debug builds: throws if mass < 0.
  static SpatialInertia PointMass(const T& mass, const Vector3<T>& p_PQ_E) {
    return SpatialInertia(mass, p_PQ_E, UnitInertia<T>::PointMass(p_PQ_E));
  }

  /// Mass 1, center of mass at P, unit inertia the identity (Drake's MakeUnitary).
  static SpatialInertia MakeUnitary() {
    return SpatialInertia(T(1), Vector3<T>::Zero(), UnitInertia<T>(T(1), T(1), T(1)));
  }

  /// Mass 0, center of mass at P, zero unit inertia: the identity of operator+=.
  static SpatialInertia Zero() {
    return SpatialInertia(T(0), Vector3<T>::Zero(), UnitInertia<T>(T(0), T(0), T(0)));
  }

  /// All NaN (as the default constructor).
  static SpatialInertia NaN() { return SpatialInertia(); }

  /// The mass m.
  const T& get_mass() const { return mass_; }
  /// p_PScm_E, the center of mass from P.
  const Vector3<T>& get_com() const { return p_PScm_E_; }
  /// m·p_PScm_E, the first mass moment about P. 3 flops.
  Vector3<T> CalcComMoment() const { return mass_ * p_PScm_E_; }
  /// G_SP_E, the unit inertia about P.
  const UnitInertia<T>& get_unit_inertia() const { return G_SP_E_; }
  /// I_SP_E = m·G_SP_E, the rotational inertia about P (not checked). 6 flops.
  RotationalInertia<T> CalcRotationalInertia() const {
    return G_SP_E_.MultiplyByScalarSkipValidityCheck(mass_);
  }

  /// True iff any of mass, center of mass or unit inertia has a NaN.
  bool IsNaN() const {
    using std::isnan;
    return isnan(mass_) || p_PScm_E_.array().isNaN().any() || G_SP_E_.IsNaN();
  }
  /// Sets every number to NaN.
  void SetNaN() {
    mass_ = std::numeric_limits<T>::quiet_NaN();
    p_PScm_E_.setConstant(std::numeric_limits<T>::quiet_NaN());
    G_SP_E_.SetToNaN();
  }

  /// True iff the mass is finite and >= 0, the center of mass is finite, and the unit inertia
  /// about the center of mass, G_SScm = G_SP − PointMass(p_PScm), passes
  /// CouldBePhysicallyValid(τ) with τ = relative_tolerance relative to the larger of tr(G_SScm)
  /// and tr(G_SP) (the shift to Scm carries round-off relative to the latter). The default is
  /// RotationalInertia's (32·eps). A mass of 0 with a finite com and valid central G is valid.
  /// Never throws.
  bool IsPhysicallyValid() const {
    return IsPhysicallyValid(internal::DefaultInertiaValidityTolerance<T>());
  }
  /// As IsPhysicallyValid() with the given relative tolerance (e.g. 1e-6).
  bool IsPhysicallyValid(const T& relative_tolerance) const;

  /// A sentence naming what fails IsPhysicallyValid(relative_tolerance) (negative, NaN or
  /// infinite mass; non-finite center of mass; the central inertia, with its entries and
  /// principal moments); empty when valid. Never throws.
  std::string CriticizeNotPhysicallyValid(
      const T& relative_tolerance = internal::DefaultInertiaValidityTolerance<T>()) const;

  /// The 4x4 pseudo-inertia about P, [[Σ_P, m·c], [m·cᵀ, m]] with c = p_PScm_E and
  /// Σ_P = ∫ r·rᵀ dm = ½·tr(I_SP)·1 − I_SP. It is positive semi-definite iff the mass
  /// distribution is physically realizable (Wensing, Kim, Slotine, "Linear matrix inequalities
  /// for physically consistent inertial parameter identification", IEEE RA-L 2018).
  Matrix4<T> CalcPseudoInertia() const;

  /// The 6x6 spatial inertia matrix about P, [[I_SP, m·[c]×], [−m·[c]×, m·1]] (Drake's layout,
  /// angular velocity first).
  Eigen::Matrix<T, 6, 6> CopyToFullMatrix6() const;

  /// Moves the point about which the inertia is taken from P to Q (p_PQ_E from P to Q): mass
  /// unchanged, p_QScm = p_PScm − p_PQ, G_SQ = G_SP shifted to then away from Scm (30 flops,
  /// about 36 in all).
  SpatialInertia& ShiftInPlace(const Vector3<T>& p_PQ_E) {
    const Vector3<T> p_QScm_E = p_PScm_E_ - p_PQ_E;
    RotationalInertiaShift(p_QScm_E);
    p_PScm_E_ = p_QScm_E;
    return *this;
  }
  /// Shifted copy (see ShiftInPlace).
  SpatialInertia Shift(const Vector3<T>& p_PQ_E) const {
    return SpatialInertia(*this).ShiftInPlace(p_PQ_E);
  }

  /// Re-expresses in frame A: p_PScm_A = R_AE·p_PScm_E, G_SP_A = R_AE·G_SP_E·R_AEᵀ. R_AE is a
  /// rotation matrix (not checked). About 90 flops.
  SpatialInertia& ReExpressInPlace(const Matrix3<T>& R_AE) {
    p_PScm_E_ = R_AE * p_PScm_E_;
    G_SP_E_.ReExpressInPlace(R_AE);
    return *this;
  }
  /// Re-expressed copy (see ReExpressInPlace).
  SpatialInertia ReExpress(const Matrix3<T>& R_AE) const {
    return SpatialInertia(*this).ReExpressInPlace(R_AE);
  }

  /// Adds another body's spatial inertia about the same point P, expressed in the same frame E:
  /// m = m1 + m2, c = (m1·c1 + m2·c2)/m, G = (m1·G1 + m2·G2)/m. When the total mass is 0 the
  /// center of mass and unit inertia of *this are kept (the other's contribute nothing).
  SpatialInertia& operator+=(const SpatialInertia& M_BP_E);
  /// The sum (see operator+=).
  SpatialInertia operator+(const SpatialInertia& M_BP_E) const {
    return SpatialInertia(*this) += M_BP_E;
  }

  /// This spatial inertia with scalar type S (no check).
  template <typename S>
  SpatialInertia<S> cast() const {
    return SpatialInertia<S>(static_cast<S>(mass_), p_PScm_E_.template cast<S>(),
                             G_SP_E_.template cast<S>(), true);
  }

 private:
  void RotationalInertiaShift(const Vector3<T>& p_QScm_E) {
    G_SP_E_.ShiftToThenAwayFromCenterOfMassInPlace(p_PScm_E_, p_QScm_E);
  }
  void ThrowIfNotPhysicallyValid(const char* operation) const;

  T mass_;
  Vector3<T> p_PScm_E_;
  UnitInertia<T> G_SP_E_;
};

/// Prints " mass = m\n Center of mass = [x  y  z]\n Inertia about point P, I_BP =\n" followed by
/// the rotational inertia m·G_SP (RotationalInertia's operator<<).
template <typename T>
std::ostream& operator<<(std::ostream& out, const SpatialInertia<T>& M) {
  const Vector3<T>& c = M.get_com();
  out << " mass = " << M.get_mass() << "\n Center of mass = [" << c(0) << "  " << c(1) << "  "
      << c(2) << "]\n Inertia about point P, I_BP =\n"
      << M.CalcRotationalInertia();
  return out;
}

// ------------------------------------------------------------------------------- definitions

template <typename T>
SpatialInertia<T> SpatialInertia<T>::MakeFromCentralInertia(const T& mass,
                                                            const Vector3<T>& p_PScm_E,
                                                            const RotationalInertia<T>& I_SScm_E) {
#ifndef NDEBUG
  if (!(mass >= T(0)) || !std::isfinite(mass)) {
    throw std::logic_error("SpatialInertia::MakeFromCentralInertia(): the mass " +
                           std::to_string(static_cast<double>(mass)) +
                           " is negative or not finite.");
  }
  if (!I_SScm_E.CouldBePhysicallyValid()) {
    throw std::logic_error("SpatialInertia::MakeFromCentralInertia(): " +
                           I_SScm_E.CriticizeNotPhysicallyValid());
  }
#endif
  UnitInertia<T> G_SP_E;
  if (mass == T(0)) {
    G_SP_E = UnitInertia<T>::PointMass(p_PScm_E);
  } else {
    // Divide each entry (one rounding each) rather than multiply by a rounded 1/m.
    G_SP_E = UnitInertia<T>(RotationalInertia<T>::MakeFromMomentsAndProductsOfInertia(
        I_SScm_E(0, 0) / mass, I_SScm_E(1, 1) / mass, I_SScm_E(2, 2) / mass, I_SScm_E(0, 1) / mass,
        I_SScm_E(0, 2) / mass, I_SScm_E(1, 2) / mass, true));
    G_SP_E.ShiftFromCenterOfMassInPlace(-p_PScm_E);
  }
  return SpatialInertia(mass, p_PScm_E, G_SP_E, true);
}

template <typename T>
bool SpatialInertia<T>::IsPhysicallyValid(const T& relative_tolerance) const {
  using std::isfinite;
  if (!(mass_ >= T(0)) || !isfinite(mass_) || !p_PScm_E_.allFinite() || !G_SP_E_.IsFinite()) {
    return false;
  }
  using std::abs;
  // G_SScm = G_SP − (|c|²·1 − c·cᵀ), unchecked (it may be invalid: that is what we test).
  const Vector3<T> c = p_PScm_E_;
  const T xx = G_SP_E_(0, 0) - (c(1) * c(1) + c(2) * c(2));
  const T yy = G_SP_E_(1, 1) - (c(0) * c(0) + c(2) * c(2));
  const T zz = G_SP_E_(2, 2) - (c(0) * c(0) + c(1) * c(1));
  const T xy = G_SP_E_(0, 1) + c(0) * c(1);
  const T xz = G_SP_E_(0, 2) + c(0) * c(2);
  const T yz = G_SP_E_(1, 2) + c(1) * c(2);
  // Round-off of the shift is relative to the entries about P: widen the reference to tr(G_SP).
  const T reference = abs(G_SP_E_(0, 0)) + abs(G_SP_E_(1, 1)) + abs(G_SP_E_(2, 2));
  return internal::IsPhysicallyValidInertia(xx, yy, zz, xy, xz, yz, relative_tolerance, reference);
}

template <typename T>
Matrix4<T> SpatialInertia<T>::CalcPseudoInertia() const {
  const RotationalInertia<T> I = CalcRotationalInertia();
  const T half_trace = I.CalcMaximumPossibleMomentOfInertia();
  Matrix4<T> J;
  J.template topLeftCorner<3, 3>() = -I.CopyToFullMatrix3();
  J.template topLeftCorner<3, 3>().diagonal().array() += half_trace;
  const Vector3<T> h = CalcComMoment();
  J.template topRightCorner<3, 1>() = h;
  J.template bottomLeftCorner<1, 3>() = h.transpose();
  J(3, 3) = mass_;
  return J;
}

template <typename T>
Eigen::Matrix<T, 6, 6> SpatialInertia<T>::CopyToFullMatrix6() const {
  const Vector3<T> h = CalcComMoment();
  Matrix3<T> h_cross;
  h_cross << T(0), -h(2), h(1), h(2), T(0), -h(0), -h(1), h(0), T(0);
  Eigen::Matrix<T, 6, 6> M;
  M.template topLeftCorner<3, 3>() = CalcRotationalInertia().CopyToFullMatrix3();
  M.template topRightCorner<3, 3>() = h_cross;
  M.template bottomLeftCorner<3, 3>() = -h_cross;
  M.template bottomRightCorner<3, 3>() = mass_ * Matrix3<T>::Identity();
  return M;
}

template <typename T>
SpatialInertia<T>& SpatialInertia<T>::operator+=(const SpatialInertia& M_BP_E) {
  const T total_mass = mass_ + M_BP_E.mass_;
  if (total_mass != T(0)) {
    p_PScm_E_ = (mass_ * p_PScm_E_ + M_BP_E.mass_ * M_BP_E.p_PScm_E_) / total_mass;
    RotationalInertia<T> sum = G_SP_E_.MultiplyByScalarSkipValidityCheck(mass_ / total_mass);
    sum += M_BP_E.G_SP_E_.MultiplyByScalarSkipValidityCheck(M_BP_E.mass_ / total_mass);
    G_SP_E_ = UnitInertia<T>(sum);
  }
  mass_ = total_mass;
  return *this;
}

template <typename T>
std::string SpatialInertia<T>::CriticizeNotPhysicallyValid(const T& relative_tolerance) const {
  using std::isfinite;
  if (IsPhysicallyValid(relative_tolerance)) return "";
  std::ostringstream out;
  out.precision(std::numeric_limits<T>::digits10);
  if (!(mass_ >= T(0)) || !isfinite(mass_)) {
    out << "The mass " << mass_ << " is negative, NaN or infinite.";
    return out.str();
  }
  if (!p_PScm_E_.allFinite()) {
    out << "The center of mass [" << p_PScm_E_(0) << " " << p_PScm_E_(1) << " " << p_PScm_E_(2)
        << "] is not finite.";
    return out.str();
  }
  if (!G_SP_E_.IsFinite()) {
    out << "The unit inertia has an entry that is NaN or infinite:\n" << G_SP_E_;
    return out.str();
  }
  const Vector3<T>& c = p_PScm_E_;
  const RotationalInertia<T> G_SScm =
      G_SP_E_.MultiplyByScalarSkipValidityCheck(T(1)) +
      RotationalInertia<T>(T(1), c).MultiplyByScalarSkipValidityCheck(T(-1));
  const RotationalInertia<T> I_SScm = G_SScm.MultiplyByScalarSkipValidityCheck(mass_);
  std::string why =
      (mass_ > T(0) ? I_SScm : G_SScm).CriticizeNotPhysicallyValid(relative_tolerance);
  if (why.empty()) {
    // On the edge: failed only against the tolerance widened to the trace about P, or by the
    // rounding of m·G. Say so rather than say nothing.
    why =
        "its principal moments are negative or violate the triangle inequality by more than "
        "the tolerance relative to the trace about P.";
  }
  out << "The " << (mass_ > T(0) ? "inertia" : "unit inertia") << " about the center of mass (mass "
      << mass_ << ", center of mass [" << c(0) << " " << c(1) << " " << c(2)
      << "]) is not physically valid: " << why;
  return out.str();
}

template <typename T>
void SpatialInertia<T>::ThrowIfNotPhysicallyValid(const char* operation) const {
  if (IsPhysicallyValid()) return;
  throw std::logic_error(std::string(operation) + ": " + CriticizeNotPhysicallyValid());
}

extern template class SpatialInertia<float>;
extern template class SpatialInertia<double>;
extern template class SpatialInertia<long double>;

}  // namespace massprops

#pragma once
/// @file
/// UnitInertia<T>: the rotational inertia of a body per unit of its mass, G_BP_E = I_BP_E / m
/// (Drake's UnitInertia), and the unit-mass shape factories (sphere, box, cylinder, capsule, ...).
/// Lengths are full lengths (box sides, cylinder length) except where a radius or semi-axis is
/// named; axes are unit vectors expressed in the frame E of the result. Factories throw
/// std::logic_error (always: the checks are cheap) for a negative or non-finite dimension or an
/// axis whose norm differs from 1 by more than max(1e-14, 16·eps(T)) (Drake throws likewise).

#include <string>

#include "massprops/core/eigen_types.h"
#include "massprops/core/rotational_inertia.h"

namespace massprops {

/// A rotational inertia for unit mass. Everything of RotationalInertia applies; the shifts take
/// no mass argument, and operators that would give a non-unit inertia (+=, -=, *=, /=) are
/// deleted (the binary +, -, *, / still return a RotationalInertia).
/// T is float, double or long double (explicitly instantiated in src/core/unit_inertia.cc).
template <typename T>
class UnitInertia : public RotationalInertia<T> {
 public:
  /// All entries NaN.
  UnitInertia() = default;

  /// Principal moments, zero products. Debug builds: throws std::logic_error if invalid.
  UnitInertia(const T& Ixx, const T& Iyy, const T& Izz) : RotationalInertia<T>(Ixx, Iyy, Izz) {}

  /// The six matrix entries (negated products). Debug builds: throws std::logic_error if invalid.
  UnitInertia(const T& Ixx, const T& Iyy, const T& Izz, const T& Ixy, const T& Ixz, const T& Iyz)
      : RotationalInertia<T>(Ixx, Iyy, Izz, Ixy, Ixz, Iyz) {}

  /// Takes I as a unit inertia as it is (there is no way to check that it is one).
  explicit UnitInertia(const RotationalInertia<T>& I) : RotationalInertia<T>(I) {}

  /// Sets this to I / mass. Debug builds: throws std::logic_error if mass <= 0 (or NaN).
  UnitInertia& SetFromRotationalInertia(const RotationalInertia<T>& I, const T& mass) {
    *this = UnitInertia(I / mass);
    return *this;
  }

  /// Re-expresses in frame A (see RotationalInertia::ReExpressInPlace). About 75 flops.
  UnitInertia& ReExpressInPlace(const Matrix3<T>& R_AE) {
    RotationalInertia<T>::ReExpressInPlace(R_AE);
    return *this;
  }
  /// Re-expressed copy.
  UnitInertia ReExpress(const Matrix3<T>& R_AE) const {
    return UnitInertia(*this).ReExpressInPlace(R_AE);
  }

  /// G_BQ_E from this G_BBcm_E: adds |p|²·1 − p·pᵀ, p = p_BcmQ_E. 18 flops.
  UnitInertia& ShiftFromCenterOfMassInPlace(const Vector3<T>& p_BcmQ_E) {
    RotationalInertia<T>::ShiftFromCenterOfMassInPlace(T(1), p_BcmQ_E);
    return *this;
  }
  /// Shifted copy.
  UnitInertia ShiftFromCenterOfMass(const Vector3<T>& p_BcmQ_E) const {
    return UnitInertia(*this).ShiftFromCenterOfMassInPlace(p_BcmQ_E);
  }

  /// G_BBcm_E from this G_BQ_E: subtracts |p|²·1 − p·pᵀ, p = p_QBcm_E. 18 flops.
  /// Debug builds: throws std::logic_error if the result is not physically valid.
  UnitInertia& ShiftToCenterOfMassInPlace(const Vector3<T>& p_QBcm_E) {
    RotationalInertia<T>::ShiftToCenterOfMassInPlace(T(1), p_QBcm_E);
    return *this;
  }
  /// Shifted copy.
  UnitInertia ShiftToCenterOfMass(const Vector3<T>& p_QBcm_E) const {
    return UnitInertia(*this).ShiftToCenterOfMassInPlace(p_QBcm_E);
  }

  /// G_BQ_E from this G_BP_E in one step (see
  /// RotationalInertia::ShiftToThenAwayFromCenterOfMassInPlace). 30 flops.
  UnitInertia& ShiftToThenAwayFromCenterOfMassInPlace(const Vector3<T>& p_PBcm_E,
                                                      const Vector3<T>& p_QBcm_E) {
    RotationalInertia<T>::ShiftToThenAwayFromCenterOfMassInPlace(T(1), p_PBcm_E, p_QBcm_E);
    return *this;
  }
  /// Shifted copy.
  UnitInertia ShiftToThenAwayFromCenterOfMass(const Vector3<T>& p_PBcm_E,
                                              const Vector3<T>& p_QBcm_E) const {
    return UnitInertia(*this).ShiftToThenAwayFromCenterOfMassInPlace(p_PBcm_E, p_QBcm_E);
  }

  /// This unit inertia with scalar type S (no check).
  template <typename S>
  UnitInertia<S> cast() const {
    return UnitInertia<S>(RotationalInertia<T>::template cast<S>());
  }

  UnitInertia& operator+=(const RotationalInertia<T>&) = delete;
  UnitInertia& operator-=(const RotationalInertia<T>&) = delete;
  UnitInertia& operator*=(const T&) = delete;
  UnitInertia& operator/=(const T&) = delete;

  // ------------------------------------------------------------------ shape factories

  /// A particle at p_FQ (unit mass), about F's origin: |p|²·1 − p·pᵀ.
  static UnitInertia PointMass(const Vector3<T>& p_FQ) {
    return UnitInertia(RotationalInertia<T>(T(1), p_FQ));
  }

  /// Ixx = Iyy = Izz = I_triaxial (e.g. a sphere or cube about its center).
  static UnitInertia TriaxiallySymmetric(const T& I_triaxial) {
    return UnitInertia(I_triaxial, I_triaxial, I_triaxial);
  }

  /// Solid ellipsoid with semi-axes a, b, c along x, y, z, about its center:
  /// ((b²+c²)/5, (a²+c²)/5, (a²+b²)/5).
  static UnitInertia SolidEllipsoid(const T& a, const T& b, const T& c);

  /// Solid sphere of radius r about its center: 2/5·r².
  static UnitInertia SolidSphere(const T& r);

  /// Hollow (thin-shell) sphere of radius r about its center: 2/3·r².
  static UnitInertia HollowSphere(const T& r);

  /// Solid box with full side lengths Lx, Ly, Lz about its center:
  /// ((Ly²+Lz²)/12, (Lx²+Lz²)/12, (Lx²+Ly²)/12).
  static UnitInertia SolidBox(const T& Lx, const T& Ly, const T& Lz);

  /// Solid cube of side L about its center: L²/6.
  static UnitInertia SolidCube(const T& L);

  /// Solid cylinder of radius r and length L, axis along unit_vector, about its center:
  /// r²/2 about the axis, (3r² + L²)/12 about any perpendicular axis.
  static UnitInertia SolidCylinder(const T& r, const T& L, const Vector3<T>& unit_vector);

  /// Solid cylinder as SolidCylinder, about the center of one of its ends (flat faces):
  /// r²/2 about the axis, r²/4 + L²/3 about any perpendicular axis.
  static UnitInertia SolidCylinderAboutEnd(const T& r, const T& L, const Vector3<T>& unit_vector);

  /// Solid capsule (a cylinder of radius r and length L, the cylindrical part only, capped by two
  /// hemispheres of radius r; uniform density) with axis unit_vector, about its center.
  static UnitInertia SolidCapsule(const T& r, const T& L, const Vector3<T>& unit_vector);

  /// Thin rod of length L along unit_vector, about its center: 0 about the axis, L²/12 about any
  /// perpendicular axis (on the validity boundary).
  static UnitInertia ThinRod(const T& L, const Vector3<T>& unit_vector);

  /// Thin disk of radius r with unit_normal, about its center: r²/2 about the normal, r²/4 about
  /// any axis in its plane (on the validity boundary).
  static UnitInertia ThinDisk(const T& r, const Vector3<T>& unit_normal);

  /// Axially symmetric body: J about the unit_vector axis, K about any perpendicular axis through
  /// the point: G = K·1 + (J − K)·b·bᵀ. Throws std::logic_error (always) if J or K is negative
  /// or not finite, if J > 2K (beyond 1e-14 relative; no body has it), or unit_vector is not unit.
  static UnitInertia AxiallySymmetric(const T& J, const T& K, const Vector3<T>& unit_vector);

  /// Axially symmetric with J = 0: a body along a straight line, K about perpendicular axes.
  static UnitInertia StraightLine(const T& K, const Vector3<T>& unit_vector) {
    return AxiallySymmetric(T(0), K, unit_vector);
  }

  /// Solid tetrahedron with vertices A (at the origin of the frame), p1, p2, p3 (positions from
  /// A), about A. Uses the second-moment (covariance) matrix of a tetrahedron, C = (Σ pᵢpᵢᵀ +
  /// s·sᵀ)/20 with s = Σ pᵢ (unit mass), and G = tr(C)·1 − C. The vertex order does not matter.
  static UnitInertia SolidTetrahedronAboutVertex(const Vector3<T>& p1, const Vector3<T>& p2,
                                                 const Vector3<T>& p3);

  /// Solid tetrahedron with vertices p0, p1, p2, p3 (positions from a point A), about A.
  static UnitInertia SolidTetrahedronAboutPoint(const Vector3<T>& p0, const Vector3<T>& p1,
                                                const Vector3<T>& p2, const Vector3<T>& p3);

 private:
  static void ThrowIfNotUnitVector(const Vector3<T>& v, const char* function);
  static void ThrowIfNegativeOrNotFinite(const T& value, const char* name, const char* function);
};

// ------------------------------------------------------------------------------- definitions

template <typename T>
void UnitInertia<T>::ThrowIfNotUnitVector(const Vector3<T>& v, const char* function) {
  using std::abs;
  const T tolerance = std::max(T(1e-14), T(16) * std::numeric_limits<T>::epsilon());
  const T norm = v.norm();
  if (!(abs(norm - T(1)) <= tolerance)) {
    std::ostringstream message;
    message.precision(std::numeric_limits<T>::digits10);
    message << "UnitInertia::" << function << "(): the axis [" << v(0) << " " << v(1) << " " << v(2)
            << "] has norm " << norm << ", which differs from 1 by more than " << tolerance << ".";
    throw std::logic_error(message.str());
  }
}

template <typename T>
void UnitInertia<T>::ThrowIfNegativeOrNotFinite(const T& value, const char* name,
                                                const char* function) {
  using std::isfinite;
  if (!(value >= T(0)) || !isfinite(value)) {
    std::ostringstream message;
    message.precision(std::numeric_limits<T>::digits10);
    message << "UnitInertia::" << function << "(): " << name << " = " << value
            << " is negative or not finite.";
    throw std::logic_error(message.str());
  }
}

template <typename T>
UnitInertia<T> UnitInertia<T>::SolidEllipsoid(const T& a, const T& b, const T& c) {
  ThrowIfNegativeOrNotFinite(a, "a", "SolidEllipsoid");
  ThrowIfNegativeOrNotFinite(b, "b", "SolidEllipsoid");
  ThrowIfNegativeOrNotFinite(c, "c", "SolidEllipsoid");
  const T a2 = a * a, b2 = b * b, c2 = c * c;
  return UnitInertia((b2 + c2) / T(5), (a2 + c2) / T(5), (a2 + b2) / T(5));
}

template <typename T>
UnitInertia<T> UnitInertia<T>::SolidSphere(const T& r) {
  ThrowIfNegativeOrNotFinite(r, "r", "SolidSphere");
  return TriaxiallySymmetric(T(2) * r * r / T(5));
}

template <typename T>
UnitInertia<T> UnitInertia<T>::HollowSphere(const T& r) {
  ThrowIfNegativeOrNotFinite(r, "r", "HollowSphere");
  return TriaxiallySymmetric(T(2) * r * r / T(3));
}

template <typename T>
UnitInertia<T> UnitInertia<T>::SolidBox(const T& Lx, const T& Ly, const T& Lz) {
  ThrowIfNegativeOrNotFinite(Lx, "Lx", "SolidBox");
  ThrowIfNegativeOrNotFinite(Ly, "Ly", "SolidBox");
  ThrowIfNegativeOrNotFinite(Lz, "Lz", "SolidBox");
  const T x2 = Lx * Lx, y2 = Ly * Ly, z2 = Lz * Lz;
  return UnitInertia((y2 + z2) / T(12), (x2 + z2) / T(12), (x2 + y2) / T(12));
}

template <typename T>
UnitInertia<T> UnitInertia<T>::SolidCube(const T& L) {
  ThrowIfNegativeOrNotFinite(L, "L", "SolidCube");
  return TriaxiallySymmetric(L * L / T(6));
}

template <typename T>
UnitInertia<T> UnitInertia<T>::SolidCylinder(const T& r, const T& L,
                                             const Vector3<T>& unit_vector) {
  ThrowIfNegativeOrNotFinite(r, "r", "SolidCylinder");
  ThrowIfNegativeOrNotFinite(L, "L", "SolidCylinder");
  ThrowIfNotUnitVector(unit_vector, "SolidCylinder");
  const T J = r * r / T(2);
  const T K = (T(3) * r * r + L * L) / T(12);
  return AxiallySymmetric(J, K, unit_vector);
}

template <typename T>
UnitInertia<T> UnitInertia<T>::SolidCylinderAboutEnd(const T& r, const T& L,
                                                     const Vector3<T>& unit_vector) {
  ThrowIfNegativeOrNotFinite(r, "r", "SolidCylinderAboutEnd");
  ThrowIfNegativeOrNotFinite(L, "L", "SolidCylinderAboutEnd");
  ThrowIfNotUnitVector(unit_vector, "SolidCylinderAboutEnd");
  const T J = r * r / T(2);
  const T K = r * r / T(4) + L * L / T(3);
  return AxiallySymmetric(J, K, unit_vector);
}

template <typename T>
UnitInertia<T> UnitInertia<T>::SolidCapsule(const T& r, const T& L, const Vector3<T>& unit_vector) {
  ThrowIfNegativeOrNotFinite(r, "r", "SolidCapsule");
  ThrowIfNegativeOrNotFinite(L, "L", "SolidCapsule");
  ThrowIfNotUnitVector(unit_vector, "SolidCapsule");
  if (r == T(0) && L == T(0)) return AxiallySymmetric(T(0), T(0), unit_vector);
  // Mass fractions by volume: cylinder π·r²·L, two hemispheres (one sphere) 4/3·π·r³.
  const T denominator = L + T(4) * r / T(3);
  const T m_cylinder = L / denominator;
  const T m_caps = (T(4) * r / T(3)) / denominator;
  const T r2 = r * r;
  // Cylinder about its center; the two hemispheres: 2/5·r² about the axis, and about a
  // perpendicular axis through the capsule's center 2/5·r² + L²/4 + 3·L·r/8 (each hemisphere's
  // 2/5·r² about its flat face's center, moved to its center of mass at 3r/8 from the face and
  // then to the capsule's center at L/2 + 3r/8).
  const T J = m_cylinder * r2 / T(2) + m_caps * T(2) * r2 / T(5);
  const T K = m_cylinder * (T(3) * r2 + L * L) / T(12) +
              m_caps * (T(2) * r2 / T(5) + L * L / T(4) + T(3) * L * r / T(8));
  return AxiallySymmetric(J, K, unit_vector);
}

template <typename T>
UnitInertia<T> UnitInertia<T>::ThinRod(const T& L, const Vector3<T>& unit_vector) {
  ThrowIfNegativeOrNotFinite(L, "L", "ThinRod");
  ThrowIfNotUnitVector(unit_vector, "ThinRod");
  return AxiallySymmetric(T(0), L * L / T(12), unit_vector);
}

template <typename T>
UnitInertia<T> UnitInertia<T>::ThinDisk(const T& r, const Vector3<T>& unit_normal) {
  ThrowIfNegativeOrNotFinite(r, "r", "ThinDisk");
  ThrowIfNotUnitVector(unit_normal, "ThinDisk");
  return AxiallySymmetric(r * r / T(2), r * r / T(4), unit_normal);
}

template <typename T>
UnitInertia<T> UnitInertia<T>::AxiallySymmetric(const T& J, const T& K,
                                                const Vector3<T>& unit_vector) {
  ThrowIfNegativeOrNotFinite(J, "J", "AxiallySymmetric");
  ThrowIfNegativeOrNotFinite(K, "K", "AxiallySymmetric");
  ThrowIfNotUnitVector(unit_vector, "AxiallySymmetric");
  if (J > T(2) * K * (T(1) + T(1e-14))) {
    std::ostringstream message;
    message.precision(std::numeric_limits<T>::digits10);
    message << "UnitInertia::AxiallySymmetric(): J = " << J << " exceeds 2·K = " << T(2) * K
            << ": no body has a moment about its axis larger than the sum of the two others.";
    throw std::logic_error(message.str());
  }
  // Normalize the (already unit within tolerance) axis so b·bᵀ has unit trace to round-off.
  const Vector3<T> b = unit_vector / unit_vector.norm();
  const T d = J - K;
  return UnitInertia(RotationalInertia<T>::MakeFromMomentsAndProductsOfInertia(
      K + d * b(0) * b(0), K + d * b(1) * b(1), K + d * b(2) * b(2), d * b(0) * b(1),
      d * b(0) * b(2), d * b(1) * b(2), true));
}

template <typename T>
UnitInertia<T> UnitInertia<T>::SolidTetrahedronAboutPoint(const Vector3<T>& p0,
                                                          const Vector3<T>& p1,
                                                          const Vector3<T>& p2,
                                                          const Vector3<T>& p3) {
  const Vector3<T> s = p0 + p1 + p2 + p3;
  const Matrix3<T> C = (p0 * p0.transpose() + p1 * p1.transpose() + p2 * p2.transpose() +
                        p3 * p3.transpose() + s * s.transpose()) /
                       T(20);
  const T trace = C.trace();
  return UnitInertia(RotationalInertia<T>::MakeFromMomentsAndProductsOfInertia(
      trace - C(0, 0), trace - C(1, 1), trace - C(2, 2), -C(0, 1), -C(0, 2), -C(1, 2), true));
}

template <typename T>
UnitInertia<T> UnitInertia<T>::SolidTetrahedronAboutVertex(const Vector3<T>& p1,
                                                           const Vector3<T>& p2,
                                                           const Vector3<T>& p3) {
  return SolidTetrahedronAboutPoint(Vector3<T>::Zero(), p1, p2, p3);
}

extern template class UnitInertia<float>;
extern template class UnitInertia<double>;
extern template class UnitInertia<long double>;

}  // namespace massprops

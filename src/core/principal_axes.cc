#include "massprops/core/principal_axes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace massprops {
namespace {

// The six unique entries of a symmetric 3x3 matrix. Off-diagonal entry o[k] is the one in row
// and column {p, q} = {0, 1, 2} \ {k}: o[0] = a12, o[1] = a02, o[2] = a01.
template <typename T>
struct Sym3 {
  T d[3];
  T o[3];
};

template <typename T>
Sym3<T> ReadLowerTriangle(const Matrix3<T>& A) {
  return Sym3<T>{{A(0, 0), A(1, 1), A(2, 2)}, {A(2, 1), A(2, 0), A(1, 0)}};
}

#ifndef NDEBUG
template <typename T>
void ThrowIfNotFinite(const Matrix3<T>& A, const char* function) {
  const Sym3<T> s = ReadLowerTriangle(A);
  bool finite = true;
  for (int i = 0; i < 3; ++i) finite = finite && std::isfinite(s.d[i]) && std::isfinite(s.o[i]);
  if (finite) return;
  std::ostringstream message;
  message.precision(std::numeric_limits<T>::max_digits10);
  message << function << "(): the matrix is not finite (lower triangle read): [[" << s.d[0]
          << "], [" << s.o[2] << ", " << s.d[1] << "], [" << s.o[1] << ", " << s.o[0] << ", "
          << s.d[2] << "]]";
  throw std::logic_error(message.str());
}
#endif

template <typename T>
bool IsDiagonal(const Sym3<T>& s) {
  return s.o[0] == T(0) && s.o[1] == T(0) && s.o[2] == T(0);
}

// Sorts the three values ascending with three compare-exchanges, applying the same permutation to
// the columns of V (when given). When the permutation is odd, the last column is negated so that
// a rotation stays a rotation (determinant +1).
template <typename T>
void SortAscending(T w[3], Matrix3<T>* V) {
  bool odd = false;
  auto exchange = [&](int i, int j) {
    if (w[j] < w[i]) {
      std::swap(w[i], w[j]);
      if (V != nullptr) V->col(i).swap(V->col(j));
      odd = !odd;
    }
  };
  exchange(0, 1);
  exchange(1, 2);
  exchange(0, 1);
  if (odd && V != nullptr) V->col(2) = -V->col(2);
}

// Powers of two bracketing the range in which the Jacobi iteration can square entries and
// multiply them by the squared unit round-off without overflow or harmful underflow.
template <typename T>
constexpr int kJacobiMaxExponent = std::numeric_limits<T>::max_exponent / 4;
template <typename T>
constexpr int kJacobiMinExponent = std::numeric_limits<T>::min_exponent / 4;

template <typename T>
bool AllFinite(const Sym3<T>& s) {
  using std::isfinite;
  return isfinite(s.d[0]) && isfinite(s.d[1]) && isfinite(s.d[2]) && isfinite(s.o[0]) &&
         isfinite(s.o[1]) && isfinite(s.o[2]);
}

template <typename T>
T MaxAbsEntry(const Sym3<T>& s) {
  using std::abs;
  return std::max({abs(s.d[0]), abs(s.d[1]), abs(s.d[2]), abs(s.o[0]), abs(s.o[1]), abs(s.o[2])});
}

// Cyclic Jacobi on the symmetric matrix s, in place: on return s.d holds the eigenvalues
// (unsorted) and, when V is given, V's columns (V must start as the identity) the eigenvectors.
// Each rotation is the symmetric Schur rotation of Golub and Van Loan (Algorithm 8.5.1) with the
// smaller of the two tangents, the diagonal updated as a_pp - t*a_pq (Rutishauser). A pair is
// skipped when |a_pq| <= u*sqrt(|a_pp*a_qq|) (u: unit round-off), the test of Demmel and Veselic
// that keeps even the small eigenvalues of a graded matrix accurate; the iteration stops after a
// sweep with no rotation, or after a fixed number of sweeps (NaN input cannot loop forever).
template <typename T>
void Jacobi(Sym3<T>* s, Matrix3<T>* V) {
  using std::abs;
  using std::sqrt;
  constexpr T u = std::numeric_limits<T>::epsilon() / 2;
  constexpr T u2 = u * u;
  constexpr int kMaxSweeps = 12;
  T* d = s->d;
  T* o = s->o;
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    bool rotated = false;
    for (int k = 2; k >= 0; --k) {
      // The pair (p, q) with p < q is {0, 1, 2} without k: k = 2 -> (0, 1), 1 -> (0, 2), 0 -> (1,
      // 2).
      const int p = k == 0 ? 1 : 0;
      const int q = k == 2 ? 1 : 2;
      const T apq = o[k];
      if (!(apq * apq > u2 * abs(d[p] * d[q]))) continue;  // Negligible (or NaN): skip.
      rotated = true;
      const T delta = d[q] - d[p];
      const T two_apq = apq + apq;
      // t = tan(theta), the root of t^2 + 2 t delta/(2 apq) - 1 = 0 of smaller magnitude.
      T t = two_apq / (abs(delta) + sqrt(delta * delta + two_apq * two_apq));
      if (delta < T(0)) t = -t;
      const T c = T(1) / sqrt(T(1) + t * t);
      const T sn = t * c;
      const T tau = sn / (T(1) + c);
      d[p] -= t * apq;
      d[q] += t * apq;
      o[k] = T(0);
      // The other two off-diagonal entries: g = a_kp (stored at o[q]), h = a_kq (stored at o[p]).
      const T g = o[q];
      const T h = o[p];
      o[q] = g - sn * (h + g * tau);
      o[p] = h + sn * (g - h * tau);
      if (V != nullptr) {
        for (int i = 0; i < 3; ++i) {
          const T vg = (*V)(i, p);
          const T vh = (*V)(i, q);
          (*V)(i, p) = vg - sn * (vh + vg * tau);
          (*V)(i, q) = vh + sn * (vg - vh * tau);
        }
      }
    }
    if (!rotated) break;
  }
}

// Jacobi with scaling. Diagonal input is returned sorted, untouched. Otherwise the matrix is
// scaled by a power of two (exactly) when its entries lie outside the range where squares are
// safe, diagonalized by Jacobi, and scaled back.
template <typename T>
void SolveJacobi(Sym3<T> s, Vector3<T>* w, Matrix3<T>* V) {
  if (V != nullptr) V->setIdentity();
  T values[3] = {s.d[0], s.d[1], s.d[2]};
  if (!IsDiagonal(s)) {
    if (!AllFinite(s)) {  // NaN or infinity (release builds): NaN out, no iterations.
      w->setConstant(std::numeric_limits<T>::quiet_NaN());
      if (V != nullptr) V->setConstant(std::numeric_limits<T>::quiet_NaN());
      return;
    }
    int exponent = 0;
    std::frexp(MaxAbsEntry(s), &exponent);
    if (exponent > kJacobiMinExponent<T> && exponent < kJacobiMaxExponent<T>) exponent = 0;
    if (exponent != 0) {
      for (int i = 0; i < 3; ++i) {
        s.d[i] = std::ldexp(s.d[i], -exponent);
        s.o[i] = std::ldexp(s.o[i], -exponent);
      }
    }
    Jacobi(&s, V);
    for (int i = 0; i < 3; ++i) values[i] = exponent != 0 ? std::ldexp(s.d[i], exponent) : s.d[i];
  }
  SortAscending(values, V);
  *w = Vector3<T>(values[0], values[1], values[2]);
}

// --------------------------------------------------------------------------- closed form

template <typename T>
Vector3<T> Cross(const Vector3<T>& a, const Vector3<T>& b) {
  return Vector3<T>(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                    a[0] * b[1] - a[1] * b[0]);
}

// The largest root x in [sqrt(3)/2, 1] of 4 x^3 - 3 x = s for s in [0, 1], i.e. cos(acos(s)/3),
// without trigonometric functions: a degree-7 Chebyshev fit on [0, 1] (max error 1.3e-8, fitted
// with mpmath.chebyfit) polished by Halley steps on the cubic, whose derivative 12 x^2 - 3 >= 6 on
// that interval keeps the root well conditioned. One step gives about 1e-23 (enough for float and
// double), two for long double.
template <typename T>
T IsolatedChebyshevRoot(T s) {
  T x = T(0.00054260771277183782708L);
  x = x * s + T(-0.0029228305021561782155L);
  x = x * s + T(0.0076643017549149815846L);
  x = x * s + T(-0.014289564825934010135L);
  x = x * s + T(0.024392383831564001784L);
  x = x * s + T(-0.048077350344917115416L);
  x = x * s + T(0.16666504306322794154L);
  x = x * s + T(0.86602541639084193184L);
  constexpr int kSteps = std::numeric_limits<T>::digits > 53 ? 2 : 1;
  for (int i = 0; i < kSteps; ++i) {
    const T f = (T(4) * x * x - T(3)) * x - s;
    const T df = T(12) * x * x - T(3);
    x -= T(2) * f * df / (T(2) * df * df - T(24) * f * x);
  }
  return std::min(x, T(1));
}

enum class Mode { kClosedFormValues, kDeflatedValues, kDeflatedVectors };

// The unit eigenvector (a, b) of the smaller eigenvalue of [[m00, m01], [m01, m11]], given
// delta = m11 - m00, h = sqrt(delta^2 + 4 m01^2) and two_m01 = 2 m01, from the formula that does
// not cancel: (|delta| + h, -2 m01) when delta >= 0, (-2 m01, |delta| + h) otherwise, normalized.
// When the pair is equal to round-off of the spread, x and y can be so small that their squares
// are subnormal or zero (entries 1e-88 beside 1e74: |x| ~ 1e-162): (a, b) would then not be a
// unit vector and the axes not orthonormal (found by the inertia fuzzer). They are rescaled by the
// larger of the two first; normal inputs never take that branch, so their results are unchanged.
template <typename T>
void LowerEigenvectorOfPair(T delta, T h, T two_m01, T* a, T* b) {
  using std::abs;
  using std::sqrt;
  T x = abs(delta) + h;
  T y = two_m01;
  *a = T(1);
  *b = T(0);
  T norm2 = x * x + y * y;
  constexpr T kMinNorm2 = std::numeric_limits<T>::min() / std::numeric_limits<T>::epsilon();
  if (norm2 < kMinNorm2) {
    const T big = std::max(abs(x), abs(y));
    if (big > T(0)) {
      x /= big;
      y /= big;
      norm2 = x * x + y * y;
    }
  }
  if (!(norm2 > T(0))) return;
  const T scale = T(1) / sqrt(norm2);
  if (delta >= T(0)) {
    *a = x * scale;
    *b = -y * scale;
  } else {
    *a = -y * scale;
    *b = x * scale;
  }
}

// Deflation of the normalized, shifted matrix C (trace 0, sum of squares 6) by its isolated
// eigenvalue mu (the one farthest from the other two, at least sqrt(3) away from both). Its unit
// eigenvector v is the largest cross product of two rows of C - mu*1 (accurate because mu is well
// separated: the rank-2 matrix has both nonzero singular values >= sqrt(3)); u and w = v x u span
// the orthogonal plane, where the 2x2 restriction of C is diagonalized exactly (one rotation).
// Every step is an orthogonal transformation or well conditioned: backward stable.
// On return mu_out is ascending and, when V is given, its columns are the eigenvectors (a
// right-handed frame). Returns false when the input was not finite.
template <typename T>
bool Deflate(const Sym3<T>& c, T mu, Vector3<T>* mu_out, Matrix3<T>* V) {
  using std::abs;
  using std::sqrt;
  const Vector3<T> r0(c.d[0] - mu, c.o[2], c.o[1]);
  const Vector3<T> r1(c.o[2], c.d[1] - mu, c.o[0]);
  const Vector3<T> r2(c.o[1], c.o[0], c.d[2] - mu);
  const Vector3<T> x01 = Cross(r0, r1);
  const Vector3<T> x02 = Cross(r0, r2);
  const Vector3<T> x12 = Cross(r1, r2);
  const T n01 = x01.squaredNorm(), n02 = x02.squaredNorm(), n12 = x12.squaredNorm();
  Vector3<T> v = x01;
  T n = n01;
  if (n02 > n) {
    v = x02;
    n = n02;
  }
  if (n12 > n) {
    v = x12;
    n = n12;
  }
  if (!(n > T(0) && n <= std::numeric_limits<T>::max())) return false;
  // v is not normalized yet (|v|^2 = n): the normalizations below run while C u and C w are formed.
  // u = v x e_k, with e_k the coordinate axis least aligned with v: |u|^2 = n - v_k^2 >= 2n/3.
  const T ax = abs(v[0]), ay = abs(v[1]), az = abs(v[2]);
  Vector3<T> u;
  T nu;
  if (ax <= ay && ax <= az) {
    u = Vector3<T>(T(0), v[2], -v[1]);
    nu = v[1] * v[1] + v[2] * v[2];
  } else if (ay <= az) {
    u = Vector3<T>(-v[2], T(0), v[0]);
    nu = v[0] * v[0] + v[2] * v[2];
  } else {
    u = Vector3<T>(v[1], -v[0], T(0));
    nu = v[0] * v[0] + v[1] * v[1];
  }
  const Vector3<T> w = Cross(v, u);  // |w|^2 = n * nu.
  const T rv = T(1) / sqrt(n);
  const T ru = T(1) / sqrt(nu);
  auto times_c = [&c](const Vector3<T>& x) {
    return Vector3<T>(c.d[0] * x[0] + c.o[2] * x[1] + c.o[1] * x[2],
                      c.o[2] * x[0] + c.d[1] * x[1] + c.o[0] * x[2],
                      c.o[1] * x[0] + c.o[0] * x[1] + c.d[2] * x[2]);
  };
  const Vector3<T> cu = times_c(u);
  const Vector3<T> cw = times_c(w);
  const T ru2 = ru * ru;
  const T m00 = u.dot(cu) * ru2;
  const T m01 = w.dot(cu) * (ru2 * rv);
  const T m11 = w.dot(cw) * (ru2 * (rv * rv));
  // The 2x2 [[m00, m01], [m01, m11]]: eigenvalues (m00 + m11 -+ h)/2 with h = sqrt(delta^2 +
  // 4 m01^2); all entries are O(1) here, so the absolute error is O(u).
  const T delta = m11 - m00;
  const T two_m01 = m01 + m01;
  const T h = sqrt(delta * delta + two_m01 * two_m01);
  const T mean = (m00 + m11) / T(2);
  const T lo = mean - h / T(2);
  const T hi = mean + h / T(2);
  // Ascending, the isolated value first or last (clamped: the pair never crosses it).
  const bool iso_is_max = mu > mean;
  if (iso_is_max) {
    *mu_out = Vector3<T>(lo, hi, std::max(mu, hi));
  } else {
    *mu_out = Vector3<T>(std::min(mu, lo), lo, hi);
  }
  if (V == nullptr) return true;
  // The eigenvector of lo in the (u, w) plane, (a, b) in that basis.
  T a, b;
  LowerEigenvectorOfPair(delta, h, two_m01, &a, &b);
  // Unit u = u * ru, unit w = w * ru * rv.
  const T au = a * ru, bu = b * ru, aw = a * ru * rv, bw = b * ru * rv;
  const Vector3<T> e_lo = au * u + bw * w;
  const Vector3<T> e_hi = aw * w - bu * u;  // e_lo turned by +90 degrees in the (u, w) plane.
  v *= rv;
  // (v, u, w) is right-handed, hence so are (v, e_lo, e_hi) and its cyclic shift (e_lo, e_hi, v).
  if (iso_is_max) {
    V->col(0) = e_lo;
    V->col(1) = e_hi;
    V->col(2) = v;
  } else {
    V->col(0) = v;
    V->col(1) = e_lo;
    V->col(2) = e_hi;
  }
  return true;
}

// Closed form after shifting by trace/3 and scaling by p, the root-mean-square of the shifted
// entries: the eigenvalues of C = (A - tr/3)/p solve mu^3 - 3 mu = det(C), i.e. mu = 2 cos(phi +
// 2 pi k/3) with cos(3 phi) = det(C)/2 (Smith, 1961). The root farthest from the others, the
// isolated one, is computed without trigonometry (IsolatedChebyshevRoot) and is accurate to O(u);
// the other two are then mu' = -mu/2 -+ sqrt(3 - 3 mu^2/4), which loses half the digits when they
// are nearly equal (kClosedFormValues), or come from Deflate (the other modes).
// Returns false (the caller falls back) when the squares could overflow or lose digits.
template <Mode mode, typename T>
bool ClosedForm(const Sym3<T>& a, Vector3<T>* values, Matrix3<T>* V) {
  using std::sqrt;
  constexpr T kSqrt3 = T(1.7320508075688772935274463415058723669L);
  constexpr T kMinP2 = std::numeric_limits<T>::min() / std::numeric_limits<T>::epsilon();
  constexpr T kMaxP2 = std::numeric_limits<T>::max() / T(64);
  T m = (a.d[0] + a.d[1] + a.d[2]) / T(3);
  T b0 = a.d[0] - m, b1 = a.d[1] - m, b2 = a.d[2] - m;
  // The rounding of m leaves trace(B) = O(u m), which the cubic (written for trace 0) would turn
  // into an error of O(u m / y) when the spread p is tiny next to m (a near-sphere): correct once.
  const T correction = (b0 + b1 + b2) / T(3);
  m += correction;
  b0 -= correction;
  b1 -= correction;
  b2 -= correction;
  const T off2 = a.o[0] * a.o[0] + a.o[1] * a.o[1] + a.o[2] * a.o[2];
  const T p2 = (b0 * b0 + b1 * b1 + b2 * b2 + T(2) * off2) / T(6);
  if (!(p2 >= kMinP2 && p2 <= kMaxP2)) return false;
  const T p = sqrt(p2);
  const T ip = T(1) / p;
  const Sym3<T> c{{b0 * ip, b1 * ip, b2 * ip}, {a.o[0] * ip, a.o[1] * ip, a.o[2] * ip}};
  const T det = c.d[0] * (c.d[1] * c.d[2] - c.o[0] * c.o[0]) -
                c.o[2] * (c.o[2] * c.d[2] - c.o[0] * c.o[1]) +
                c.o[1] * (c.o[2] * c.o[0] - c.d[1] * c.o[1]);
  const T half_det = det / T(2);
  const T s = std::min(T(1), std::abs(half_det));
  const T x = IsolatedChebyshevRoot(s);
  Vector3<T> mu;
  // y = sin(phi) measures the gap between the two other eigenvalues (it is (hi - lo)/(2 sqrt(3))
  // in units of p); the closed form gives them with an error of about u/y, so below
  // kClusterThreshold they come from the deflation instead (error O(u)).
  constexpr T kClusterThreshold = T(1e-3);
  const T y = sqrt(std::max(T(0), T(1) - x * x));
  if (mode == Mode::kClosedFormValues && y >= kClusterThreshold) {
    const T y3 = kSqrt3 * y;
    if (half_det >= T(0)) {
      mu = Vector3<T>(-x - y3, -x + y3, T(2) * x);
    } else {
      mu = Vector3<T>(T(-2) * x, x - y3, x + y3);
    }
  } else {
    const T iso = half_det >= T(0) ? T(2) * x : T(-2) * x;
    if (!Deflate(c, iso, &mu, mode == Mode::kDeflatedVectors ? V : nullptr)) return false;
  }
  *values = Vector3<T>(m + p * mu[0], m + p * mu[1], m + p * mu[2]);
  return true;
}

// The power of two e such that entries of magnitude at most s (> 0, finite), scaled by 2^-e, can
// be squared and summed without overflow or underflow: 0 when s lies within 2^(min_exponent/4) ..
// 2^(max_exponent/4) (about 1e-77 .. 1e77 for double), otherwise the exponent of s. The same
// range as internal::SafeScaleExponent of rotational_inertia.h.
template <typename T>
int ScaleExponent(const T& s) {
  static const T kLow = std::ldexp(T(1), std::numeric_limits<T>::min_exponent / 4);
  static const T kHigh = std::ldexp(T(1), std::numeric_limits<T>::max_exponent / 4);
  return (s > kLow && s < kHigh) ? 0 : std::ilogb(s);
}

// The rare path of Solve, kept out of line so that the common one stays as short as the closed
// form itself: not finite (false), or an exact scaling by a power of two and the closed form
// again, else Jacobi.
template <Mode mode, typename T>
[[gnu::noinline]] bool SolveOutsideClosedFormRange(const Sym3<T>& s, Vector3<T>* w, Matrix3<T>* V) {
  if (!AllFinite(s)) {
    w->setConstant(std::numeric_limits<T>::quiet_NaN());
    if (V != nullptr) V->setConstant(std::numeric_limits<T>::quiet_NaN());
    return false;
  }
  const int e = ScaleExponent(MaxAbsEntry(s));
  if (e != 0) {
    Sym3<T> scaled;
    for (int i = 0; i < 3; ++i) {
      scaled.d[i] = std::ldexp(s.d[i], -e);
      scaled.o[i] = std::ldexp(s.o[i], -e);
    }
    if (ClosedForm<mode>(scaled, w, V)) {
      for (int k = 0; k < 3; ++k) (*w)(k) = std::ldexp((*w)(k), e);
      return true;
    }
  }
  SolveJacobi(s, w, V);  // Scales itself.
  return true;
}

// Diagonal input: sorted, exactly. Otherwise the closed form; outside its safe range, again
// after an exact scaling by a power of two (so the result is the closed form's on any finite
// input whose eigenvalue spread does not underflow, bit for bit what it gives on the scaled
// matrix); and if that fails too (the spread underflows), Jacobi. Returns false when an entry is
// not finite (the values are then not finite either); this is the only finiteness test, and it
// runs only off the fast path.
template <Mode mode, typename T>
bool Solve(const Sym3<T>& s, Vector3<T>* w, Matrix3<T>* V) {
  using std::isfinite;
  if (IsDiagonal(s)) {
    SolveJacobi(s, w, V);  // Exact: the diagonal sorted.
    return isfinite(s.d[0]) && isfinite(s.d[1]) && isfinite(s.d[2]);
  }
  if (ClosedForm<mode>(s, w, V)) return true;
  return SolveOutsideClosedFormRange<mode>(s, w, V);
}

template <typename T>
bool SolveValues(const Sym3<T>& s, PrincipalSolver solver, Vector3<T>* w) {
  return solver == PrincipalSolver::kFast
             ? Solve<Mode::kClosedFormValues>(s, w, static_cast<Matrix3<T>*>(nullptr))
             : Solve<Mode::kDeflatedValues>(s, w, static_cast<Matrix3<T>*>(nullptr));
}

}  // namespace

namespace internal {

template <typename T>
bool SymmetricEigenvaluesOfEntries(T a00, T a11, T a22, T a10, T a20, T a21, PrincipalSolver solver,
                                   Vector3<T>* values) {
  return SolveValues(Sym3<T>{{a00, a11, a22}, {a21, a20, a10}}, solver, values);
}

template <typename T>
bool SymmetricEigensystemOfEntries(T a00, T a11, T a22, T a10, T a20, T a21, Vector3<T>* values,
                                   Matrix3<T>* vectors) {
  return Solve<Mode::kDeflatedVectors>(Sym3<T>{{a00, a11, a22}, {a21, a20, a10}}, values, vectors);
}

}  // namespace internal

template <typename T>
Vector3<T> CalcSymmetricEigenvalues(const Matrix3<T>& A, PrincipalSolver solver) {
#ifndef NDEBUG
  ThrowIfNotFinite(A, "CalcSymmetricEigenvalues");
#endif
  Vector3<T> w;
  SolveValues(ReadLowerTriangle(A), solver, &w);
  return w;
}

template <typename T>
std::pair<Vector3<T>, Matrix3<T>> CalcSymmetricEigensystem(const Matrix3<T>& A,
                                                           PrincipalSolver solver) {
#ifndef NDEBUG
  ThrowIfNotFinite(A, "CalcSymmetricEigensystem");
#endif
  std::pair<Vector3<T>, Matrix3<T>> result;
  // With vectors both solvers deflate: the eigenvectors of the two closest eigenvalues need it.
  static_cast<void>(solver);
  Solve<Mode::kDeflatedVectors>(ReadLowerTriangle(A), &result.first, &result.second);
  return result;
}

template Vector3<float> CalcSymmetricEigenvalues<float>(const Matrix3<float>&, PrincipalSolver);
template Vector3<double> CalcSymmetricEigenvalues<double>(const Matrix3<double>&, PrincipalSolver);
template Vector3<long double> CalcSymmetricEigenvalues<long double>(const Matrix3<long double>&,
                                                                    PrincipalSolver);
template std::pair<Vector3<float>, Matrix3<float>> CalcSymmetricEigensystem<float>(
    const Matrix3<float>&, PrincipalSolver);
template std::pair<Vector3<double>, Matrix3<double>> CalcSymmetricEigensystem<double>(
    const Matrix3<double>&, PrincipalSolver);
template std::pair<Vector3<long double>, Matrix3<long double>>
CalcSymmetricEigensystem<long double>(const Matrix3<long double>&, PrincipalSolver);

namespace internal {
template bool SymmetricEigenvaluesOfEntries<float>(float, float, float, float, float, float,
                                                   PrincipalSolver, Vector3<float>*);
template bool SymmetricEigenvaluesOfEntries<double>(double, double, double, double, double, double,
                                                    PrincipalSolver, Vector3<double>*);
template bool SymmetricEigenvaluesOfEntries<long double>(long double, long double, long double,
                                                         long double, long double, long double,
                                                         PrincipalSolver, Vector3<long double>*);
template bool SymmetricEigensystemOfEntries<float>(float, float, float, float, float, float,
                                                   Vector3<float>*, Matrix3<float>*);
template bool SymmetricEigensystemOfEntries<double>(double, double, double, double, double, double,
                                                    Vector3<double>*, Matrix3<double>*);
template bool SymmetricEigensystemOfEntries<long double>(long double, long double, long double,
                                                         long double, long double, long double,
                                                         Vector3<long double>*,
                                                         Matrix3<long double>*);
}  // namespace internal

}  // namespace massprops

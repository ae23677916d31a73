// Python bindings of the numeric core: RotationalInertia, UnitInertia, SpatialInertia (double),
// PrincipalSolver, and the vectorised principal_moments / is_physically_valid.
//
// Validity in Python does not depend on the build type: where the C++ classes check a result
// only in debug builds (constructors, subtraction, shifts toward the center of mass), the
// bindings check it always and raise ValueError with the C++ message; the skip_validity_check
// factories hold numbers that may be invalid (e.g. read from a file).
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/operators.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "massprops/core/principal_axes.h"
#include "massprops/core/rotational_inertia.h"
#include "massprops/core/spatial_inertia.h"
#include "massprops/core/unit_inertia.h"
#include "massprops/output/xml_patch.h"

namespace py = pybind11;

namespace massprops::python {

using RI = RotationalInertia<double>;
using UI = UnitInertia<double>;
using SI = SpatialInertia<double>;
using Vector3d = Eigen::Vector3d;
using Matrix3d = Eigen::Matrix3d;

constexpr double kDefaultTolerance = internal::DefaultInertiaValidityTolerance<double>();

PrincipalSolver ToSolver(const py::handle& solver) {
  if (py::isinstance<PrincipalSolver>(solver)) return solver.cast<PrincipalSolver>();
  if (py::isinstance<py::str>(solver)) {
    const std::string name = solver.cast<std::string>();
    if (name == "accurate") return PrincipalSolver::kAccurate;
    if (name == "fast") return PrincipalSolver::kFast;
    throw py::value_error("solver must be 'accurate' or 'fast' (or a PrincipalSolver), got '" +
                          name + "'");
  }
  throw py::type_error("solver must be 'accurate', 'fast' or a PrincipalSolver, got " +
                       py::repr(solver).cast<std::string>());
}

std::string Repr(double x) { return FormatShortest(x); }

namespace {

// Throws ValueError quoting the inertia when it fails CouldBePhysicallyValid().
template <typename Inertia>
const Inertia& Checked(const Inertia& I, const char* operation) {
  if (!I.CouldBePhysicallyValid()) {
    throw py::value_error(std::string(operation) + ": " + I.CriticizeNotPhysicallyValid());
  }
  return I;
}

const SI& Checked(const SI& M, const char* operation) {
  if (!M.IsPhysicallyValid()) {
    throw py::value_error(std::string(operation) + ": " + M.CriticizeNotPhysicallyValid());
  }
  return M;
}

RI RawInertia(double xx, double yy, double zz, double xy, double xz, double yz) {
  return RI::MakeFromMomentsAndProductsOfInertia(xx, yy, zz, xy, xz, yz, true);
}

std::string Entries(const RI& I) {
  return "Ixx=" + Repr(I(0, 0)) + ", Iyy=" + Repr(I(1, 1)) + ", Izz=" + Repr(I(2, 2)) +
         ", Ixy=" + Repr(I(0, 1)) + ", Ixz=" + Repr(I(0, 2)) + ", Iyz=" + Repr(I(1, 2));
}

std::string VectorRepr(const Vector3d& v) {
  return "[" + Repr(v(0)) + ", " + Repr(v(1)) + ", " + Repr(v(2)) + "]";
}

template <typename T>
std::string Str(const T& value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

double Entry(const RI& I, const py::tuple& index) {
  if (index.size() != 2) throw py::index_error("an inertia is indexed by (i, j)");
  const long i = index[0].cast<long>(), j = index[1].cast<long>();
  if (i < 0 || i > 2 || j < 0 || j > 2) {
    throw py::index_error("inertia index (" + std::to_string(i) + ", " + std::to_string(j) +
                          ") out of range [0, 2]");
  }
  return I(static_cast<int>(i), static_cast<int>(j));
}

// Reads the (..., 3, 3) float64 array `a` into rows of six entries (xx, yy, zz, xy, xz, yz) with
// the two triangles averaged as RotationalInertia::FromMatrix does; throws ValueError naming the
// first matrix that is not symmetric (FromMatrix's test). `*leading` gets the leading shape.
struct Batch {
  std::vector<py::ssize_t> leading;
  std::size_t count = 0;
  const double* data = nullptr;
};

Batch ReadBatch(const py::array_t<double, py::array::c_style | py::array::forcecast>& a,
                const char* function) {
  if (a.ndim() < 2 || a.shape(a.ndim() - 1) != 3 || a.shape(a.ndim() - 2) != 3) {
    std::string shape = "(";
    for (py::ssize_t k = 0; k < a.ndim(); ++k) {
      shape += (k ? ", " : "") + std::to_string(a.shape(k));
    }
    shape += a.ndim() == 1 ? ",)" : ")";
    throw py::value_error(std::string(function) + ": expected an array of shape (N, 3, 3) or " +
                          "(..., 3, 3), got shape " + shape);
  }
  Batch batch;
  batch.count = 1;
  for (py::ssize_t k = 0; k + 2 < a.ndim(); ++k) {
    batch.leading.push_back(a.shape(k));
    batch.count *= static_cast<std::size_t>(a.shape(k));
  }
  batch.data = a.data();
  return batch;
}

// The six entries of matrix k, triangles averaged as FromMatrix does; false (and *bad set) when
// the matrix is not symmetric by FromMatrix's test.
bool SixEntries(const double* m, double e[6]) {
  const double scale =
      std::max({std::abs(m[0]), std::abs(m[1]), std::abs(m[2]), std::abs(m[3]), std::abs(m[4]),
                std::abs(m[5]), std::abs(m[6]), std::abs(m[7]), std::abs(m[8])});
  const double tolerance = 8 * std::numeric_limits<double>::epsilon() * scale;
  const int pairs[3][2] = {{1, 3}, {2, 6}, {5, 7}};
  for (const auto& p : pairs) {
    const double a = m[p[0]], b = m[p[1]];
    if (!(std::abs(a - b) <= tolerance) && !(a == b)) return false;
  }
  e[0] = m[0], e[1] = m[4], e[2] = m[8];
  e[3] = 0.5 * m[1] + 0.5 * m[3];
  e[4] = 0.5 * m[2] + 0.5 * m[6];
  e[5] = 0.5 * m[5] + 0.5 * m[7];
  return true;
}

[[noreturn]] void ThrowNotSymmetric(const char* function, std::size_t k, const double* m) {
  std::ostringstream out;
  out.precision(17);
  out << function << ": matrix " << k << " is not symmetric: [[" << m[0] << ", " << m[1] << ", "
      << m[2] << "], [" << m[3] << ", " << m[4] << ", " << m[5] << "], [" << m[6] << ", " << m[7]
      << ", " << m[8] << "]]";
  throw py::value_error(out.str());
}

py::array_t<double> PrincipalMoments(
    const py::array_t<double, py::array::c_style | py::array::forcecast>& I,
    const py::object& solver_arg) {
  const PrincipalSolver solver = ToSolver(solver_arg);
  const Batch batch = ReadBatch(I, "principal_moments");
  std::vector<py::ssize_t> shape = batch.leading;
  shape.push_back(3);
  py::array_t<double> result(shape);
  double* out = result.mutable_data();
  std::size_t bad = batch.count;
  {
    py::gil_scoped_release release;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t k = 0; k < batch.count; ++k) {
      const double* m = batch.data + 9 * k;
      double e[6];
      if (!SixEntries(m, e)) {
        bad = k;
        break;
      }
      double* o = out + 3 * k;
      if (!(std::isfinite(e[0]) && std::isfinite(e[1]) && std::isfinite(e[2]) &&
            std::isfinite(e[3]) && std::isfinite(e[4]) && std::isfinite(e[5]))) {
        o[0] = o[1] = o[2] = nan;
        continue;
      }
      // The same call as RotationalInertia::CalcPrincipalMomentsOfInertia(solver).
      const Vector3d lambda =
          internal::ScaledPrincipalMoments(e[0], e[1], e[2], e[3], e[4], e[5], solver);
      o[0] = lambda(0), o[1] = lambda(1), o[2] = lambda(2);
    }
  }
  if (bad < batch.count) ThrowNotSymmetric("principal_moments", bad, batch.data + 9 * bad);
  return result;
}

py::array_t<bool> IsPhysicallyValid(
    const py::array_t<double, py::array::c_style | py::array::forcecast>& I, double tolerance) {
  if (!(tolerance >= 0) || !std::isfinite(tolerance)) {
    throw py::value_error("is_physically_valid: tolerance must be a finite number >= 0, got " +
                          Repr(tolerance));
  }
  const Batch batch = ReadBatch(I, "is_physically_valid");
  py::array_t<bool> result(batch.leading);
  bool* out = result.mutable_data();
  std::size_t bad = batch.count;
  {
    py::gil_scoped_release release;
    for (std::size_t k = 0; k < batch.count; ++k) {
      const double* m = batch.data + 9 * k;
      double e[6];
      if (!SixEntries(m, e)) {
        bad = k;
        break;
      }
      // The same call as RotationalInertia::CouldBePhysicallyValid(tolerance).
      out[k] = internal::IsPhysicallyValidInertia(e[0], e[1], e[2], e[3], e[4], e[5], tolerance);
    }
  }
  if (bad < batch.count) ThrowNotSymmetric("is_physically_valid", bad, batch.data + 9 * bad);
  return result;
}

// The constructors and factories of RotationalInertia (checked unless asked not to).
void DefRotationalInertiaConstructors(py::class_<RI>& c) {
  c.def(py::init<>(), "An inertia whose six entries are NaN.")
      .def(py::init([](double Ixx, double Iyy, double Izz, double Ixy, double Ixz, double Iyz,
                       bool skip_validity_check) {
             const RI I = RawInertia(Ixx, Iyy, Izz, Ixy, Ixz, Iyz);
             return skip_validity_check ? I : Checked(I, "RotationalInertia()");
           }),
           py::arg("Ixx"), py::arg("Iyy"), py::arg("Izz"), py::arg("Ixy") = 0.0,
           py::arg("Ixz") = 0.0, py::arg("Iyz") = 0.0, py::kw_only(),
           py::arg("skip_validity_check") = false,
           "From the moments and (negated) products. Raises ValueError if the result is not "
           "physically valid (unless skip_validity_check).\n\n"
           ">>> massprops.RotationalInertia(1.0, 1.0, 1.0, Ixy=0.1)")
      .def(py::init([](double mass, const Vector3d& p_PQ_E) {
             if (!(mass >= 0) || !std::isfinite(mass)) {
               throw py::value_error("RotationalInertia(mass, p_PQ_E): the mass " + Repr(mass) +
                                     " is negative or not finite");
             }
             return RI(mass, p_PQ_E);
           }),
           py::arg("mass"), py::arg("p_PQ_E"),
           "The inertia about P of a particle of the given mass at p_PQ_E: "
           "m·(|p|²·1 − p·pᵀ).\n\n>>> massprops.RotationalInertia(2.0, [1.0, 0.0, 0.0])")
      .def_static(
          "make_from_moments_and_products_of_inertia",
          [](double Ixx, double Iyy, double Izz, double Ixy, double Ixz, double Iyz,
             bool skip_validity_check) {
            return RI::MakeFromMomentsAndProductsOfInertia(Ixx, Iyy, Izz, Ixy, Ixz, Iyz,
                                                           skip_validity_check);
          },
          py::arg("Ixx"), py::arg("Iyy"), py::arg("Izz"), py::arg("Ixy"), py::arg("Ixz"),
          py::arg("Iyz"), py::arg("skip_validity_check") = false,
          "From the six matrix entries; raises ValueError if not physically valid unless "
          "skip_validity_check (then any numbers, even NaN, are kept).\n\n"
          ">>> massprops.RotationalInertia.make_from_moments_and_products_of_inertia("
          "0.1, 0.2, 0.5, 0, 0, 0, skip_validity_check=True)")
      .def_static("from_matrix", &RI::FromMatrix, py::arg("I"),
                  py::arg("skip_validity_check") = false,
                  "From a symmetric 3x3 array (negated products). Raises ValueError if it is not "
                  "symmetric to round-off (8·eps·max|I|), or not physically valid unless "
                  "skip_validity_check.\n\n"
                  ">>> massprops.RotationalInertia.from_matrix(numpy.diag([1.0, 2.0, 2.5]))")
      .def_static(
          "triaxially_symmetric",
          [](double I) { return Checked(RI::TriaxiallySymmetric(I), "triaxially_symmetric()"); },
          py::arg("I_triaxial"),
          "Ixx = Iyy = Izz = I_triaxial, zero products (a sphere or cube about its center).");
}

// The entries, trace and matrix of a RotationalInertia, and comparison within a precision.
void DefRotationalInertiaAccessors(py::class_<RI>& c) {
  c.def("get_moments", &RI::get_moments, "[Ixx, Iyy, Izz] as a numpy array.")
      .def("get_products", &RI::get_products,
           "[Ixy, Ixz, Iyz] (matrix entries, negated convention) as a numpy array.")
      .def("trace", &RI::Trace, "Ixx + Iyy + Izz (invariant under re-expression).")
      .def("calc_maximum_possible_moment_of_inertia", &RI::CalcMaximumPossibleMomentOfInertia,
           "trace()/2: no moment about any axis through P can exceed it (for a valid inertia).")
      .def("__getitem__", &Entry, py::arg("index"), "I[i, j]: the (i, j) matrix entry.")
      .def("copy_to_full_matrix3", &RI::CopyToFullMatrix3,
           "The symmetric 3x3 matrix as a numpy array.")
      .def(
          "__array__",
          [](const RI& I, const py::object& dtype, const py::object& /*copy*/) {
            py::array result = py::cast(I.CopyToFullMatrix3());
            return dtype.is_none() ? result : result.attr("astype")(dtype).cast<py::array>();
          },
          py::arg("dtype") = py::none(), py::arg("copy") = py::none(),
          "numpy.asarray(I): the 3x3 matrix.")
      .def("is_nearly_equal_to", &RI::IsNearlyEqualTo, py::arg("other"), py::arg("precision"),
           "True iff max|self − other| over the six entries <= precision · the smaller of the "
           "two maximum possible moments; False if either has a NaN.");
}

// Equality, sum, difference, scaling and the product with a vector of a RotationalInertia.
void DefRotationalInertiaArithmetic(py::class_<RI>& c) {
  // pybind11's operator idiom (py::self == py::self) is no redundant expression.
  c.def(py::self == py::self,  // NOLINT(misc-redundant-expression)
        "Exact equality of all six entries (NaN compares unequal).")
      .def(py::self != py::self)  // NOLINT(misc-redundant-expression)
      .def(py::self + py::self, "The sum (about the same point, in the same frame).")
      .def(
          "__sub__", [](const RI& a, const RI& b) { return Checked(a - b, "operator-"); },
          py::is_operator(), "The difference; raises ValueError if it is not physically valid.")
      .def(
          "__mul__",
          [](const RI& I, double s) {
            if (!(s >= 0)) {
              throw py::value_error("RotationalInertia * s: s = " + Repr(s) +
                                    " must be >= 0 (multiply_by_scalar_skip_validity_check "
                                    "takes any scalar)");
            }
            return I.MultiplyByScalarSkipValidityCheck(s);
          },
          py::is_operator(), "I * s for a scalar s >= 0 (ValueError otherwise).")
      .def(
          "__rmul__",
          [](const RI& I, double s) {
            if (!(s >= 0)) {
              throw py::value_error("s * RotationalInertia: s = " + Repr(s) + " must be >= 0");
            }
            return I.MultiplyByScalarSkipValidityCheck(s);
          },
          py::is_operator())
      .def(
          "__mul__", [](const RI& I, const Vector3d& w_E) { return I * w_E; }, py::is_operator(),
          "I * w: the matrix times a 3-vector (e.g. angular momentum I·ω), a numpy array.")
      .def(
          "__truediv__",
          [](const RI& I, double s) {
            if (!(s > 0)) {
              throw py::value_error("RotationalInertia / s: s = " + Repr(s) + " must be > 0");
            }
            return I / s;
          },
          py::is_operator(), "I / s for a scalar s > 0 (ValueError otherwise).")
      .def("multiply_by_scalar_skip_validity_check", &RI::MultiplyByScalarSkipValidityCheck,
           py::arg("s"), "s · I for any scalar s (even negative), never checked.");
}

// The NaN / finite / zero predicates, principal moments and physical validity.
void DefRotationalInertiaValidity(py::class_<RI>& c) {
  c.def("set_to_nan", &RI::SetToNaN, "Sets all six entries to NaN.")
      .def("set_zero", &RI::SetZero, "Sets all six entries to zero.")
      .def("is_nan", &RI::IsNaN, "True iff any entry is NaN.")
      .def("is_inf", &RI::IsInf, "True iff any entry is +inf or -inf.")
      .def("is_finite", &RI::IsFinite, "True iff every entry is finite.")
      .def("is_zero", &RI::IsZero, "True iff all six entries are exactly zero.")
      .def(
          "calc_principal_moments_of_inertia",
          [](const RI& I, const py::object& solver) {
            return I.CalcPrincipalMomentsOfInertia(ToSolver(solver));
          },
          py::arg("solver") = "accurate",
          "The principal moments, ascending, as a numpy array. solver: 'accurate' (default; "
          "every moment within a few units of round-off of the trace) or 'fast' (closed form). "
          "Raises ValueError if an entry is NaN or infinite.")
      .def(
          "calc_principal_moments_and_axes_of_inertia",
          [](const RI& I, const py::object& solver) {
            return I.CalcPrincipalMomentsAndAxesOfInertia(ToSolver(solver));
          },
          py::arg("solver") = "accurate",
          "(moments, R_EA): the principal moments ascending and the principal axes as the "
          "columns of a rotation matrix (column k is the axis of moment k, expressed in E). "
          "Raises ValueError if an entry is NaN or infinite.")
      .def("could_be_physically_valid",
           py::overload_cast<const double&>(&RI::CouldBePhysicallyValid, py::const_),
           py::arg("relative_tolerance") = kDefaultTolerance,
           "True iff the six entries are finite and the principal moments λ1 <= λ2 <= λ3 "
           "satisfy λ1 >= -τ and λ1 + λ2 >= λ3 - τ, τ = relative_tolerance·trace (default "
           "32·eps). Never raises.")
      .def("criticize_not_physically_valid", &RI::CriticizeNotPhysicallyValid,
           py::arg("relative_tolerance") = kDefaultTolerance,
           "Why could_be_physically_valid(relative_tolerance) is False (entries and principal "
           "moments quoted); '' when valid.");
}

// Re-expression in another frame and the parallel-axis shifts of a RotationalInertia.
void DefRotationalInertiaFrameChanges(py::class_<RI>& c) {
  c.def("re_express", &RI::ReExpress, py::arg("R_AE"),
        "I_BP_A = R_AE · I_BP_E · R_AEᵀ for a rotation matrix R_AE (not checked).")
      .def("shift_from_center_of_mass", &RI::ShiftFromCenterOfMass, py::arg("mass"),
           py::arg("p_BcmQ_E"),
           "Parallel-axis theorem away from the center of mass: self is I_BBcm_E; returns "
           "I_BQ_E = I_BBcm_E + m·(|p|²·1 − p·pᵀ).")
      .def(
          "shift_to_center_of_mass",
          [](const RI& I, double mass, const Vector3d& p) {
            return Checked(I.ShiftToCenterOfMass(mass, p), "shift_to_center_of_mass()");
          },
          py::arg("mass"), py::arg("p_QBcm_E"),
          "Parallel-axis theorem toward the center of mass: self is I_BQ_E; returns "
          "I_BBcm_E = I_BQ_E − m·(|p|²·1 − p·pᵀ). Raises ValueError if the result is not "
          "physically valid.")
      .def(
          "shift_to_then_away_from_center_of_mass",
          [](const RI& I, double mass, const Vector3d& p_PBcm_E, const Vector3d& p_QBcm_E) {
            return Checked(I.ShiftToThenAwayFromCenterOfMass(mass, p_PBcm_E, p_QBcm_E),
                           "shift_to_then_away_from_center_of_mass()");
          },
          py::arg("mass"), py::arg("p_PBcm_E"), py::arg("p_QBcm_E"),
          "From I_BP_E to I_BQ_E in one step: I_BP + m·([b]ᵀ[b] − [a]ᵀ[a]) with a = p_PBcm_E, "
          "b = p_QBcm_E (30 flops, no cancellation when P and Q are close). Raises ValueError "
          "if the result is not physically valid.");
}

// __repr__, __str__ and pickling of RotationalInertia.
void DefRotationalInertiaPythonProtocol(py::class_<RI>& c) {
  c.def("__repr__", [](const RI& I) { return "RotationalInertia(" + Entries(I) + ")"; })
      .def("__str__", &Str<RI>)
      .def(py::pickle(
          [](const RI& I) {
            return py::make_tuple(I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2));
          },
          [](const py::tuple& t) {
            if (t.size() != 6) throw py::value_error("RotationalInertia: bad pickle state");
            return RawInertia(t[0].cast<double>(), t[1].cast<double>(), t[2].cast<double>(),
                              t[3].cast<double>(), t[4].cast<double>(), t[5].cast<double>());
          }));
}

// massprops.RotationalInertia: the class, its members by group, unhashable.
void BindRotationalInertia(py::module_& m) {
  py::class_<RI> c(m, "RotationalInertia", R"doc(
The rotational inertia I_BP_E of a body B about a point P, expressed in a frame E (kg·m²).

Products of inertia use the negated convention of URDF and SDF: the 3x3 matrix is
[[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]] with Ixy = -∫xy dm, so the ixy, ixz, iyz of a
URDF <inertia> are these entries. Every constructor and operation whose result could be invalid
checks it (ValueError with the entries and principal moments); to hold numbers that may be invalid
use make_from_moments_and_products_of_inertia(..., skip_validity_check=True) or
from_matrix(..., skip_validity_check=True).

>>> I = massprops.RotationalInertia(2.0, 3.0, 4.0)
>>> I.calc_principal_moments_of_inertia()
array([2., 3., 4.])
)doc");
  DefRotationalInertiaConstructors(c);
  DefRotationalInertiaAccessors(c);
  DefRotationalInertiaArithmetic(c);
  DefRotationalInertiaValidity(c);
  DefRotationalInertiaFrameChanges(c);
  DefRotationalInertiaPythonProtocol(c);
  c.attr("__hash__") = py::none();
}

// The constructors of UnitInertia and set_from_rotational_inertia.
void DefUnitInertiaConstructors(py::class_<UI, RI>& c) {
  c.def(py::init<>(), "A unit inertia whose six entries are NaN.")
      .def(py::init([](double Ixx, double Iyy, double Izz, double Ixy, double Ixz, double Iyz,
                       bool skip_validity_check) {
             const UI G(RawInertia(Ixx, Iyy, Izz, Ixy, Ixz, Iyz));
             return skip_validity_check ? G : Checked(G, "UnitInertia()");
           }),
           py::arg("Ixx"), py::arg("Iyy"), py::arg("Izz"), py::arg("Ixy") = 0.0,
           py::arg("Ixz") = 0.0, py::arg("Iyz") = 0.0, py::kw_only(),
           py::arg("skip_validity_check") = false,
           "From the moments and (negated) products per unit mass; ValueError if not physically "
           "valid (unless skip_validity_check).")
      .def(py::init([](const RI& I) { return UI(I); }), py::arg("I"),
           "Takes I as a unit inertia as it is.")
      .def(
          "set_from_rotational_inertia",
          [](UI& G, const RI& I, double mass) -> UI& {
            if (!(mass > 0) || !std::isfinite(mass)) {
              throw py::value_error("set_from_rotational_inertia: mass " + Repr(mass) +
                                    " must be positive and finite");
            }
            return G.SetFromRotationalInertia(I, mass);
          },
          py::arg("I"), py::arg("mass"), py::return_value_policy::reference_internal,
          "Sets self to I / mass (mass > 0) and returns self.");
}

// Re-expression in another frame and the parallel-axis shifts of a UnitInertia.
void DefUnitInertiaFrameChanges(py::class_<UI, RI>& c) {
  c.def("re_express", &UI::ReExpress, py::arg("R_AE"),
        "G_BP_A = R_AE · G_BP_E · R_AEᵀ for a rotation matrix R_AE.")
      .def("shift_from_center_of_mass", &UI::ShiftFromCenterOfMass, py::arg("p_BcmQ_E"),
           "G_BQ_E from self = G_BBcm_E: adds |p|²·1 − p·pᵀ.")
      .def(
          "shift_to_center_of_mass",
          [](const UI& G, const Vector3d& p) {
            return Checked(G.ShiftToCenterOfMass(p), "shift_to_center_of_mass()");
          },
          py::arg("p_QBcm_E"),
          "G_BBcm_E from self = G_BQ_E: subtracts |p|²·1 − p·pᵀ; ValueError if the result is "
          "not physically valid.")
      .def(
          "shift_to_then_away_from_center_of_mass",
          [](const UI& G, const Vector3d& a, const Vector3d& b) {
            return Checked(G.ShiftToThenAwayFromCenterOfMass(a, b),
                           "shift_to_then_away_from_center_of_mass()");
          },
          py::arg("p_PBcm_E"), py::arg("p_QBcm_E"),
          "G_BQ_E from self = G_BP_E in one step; ValueError if the result is not valid.");
}

// The factories of UnitInertia: point mass and uniform solids.
void DefUnitInertiaShapeFactories(py::class_<UI, RI>& c) {
  c.def_static("point_mass", &UI::PointMass, py::arg("p_FQ"),
               "A particle at p_FQ (unit mass) about F's origin: |p|²·1 − p·pᵀ.")
      .def_static(
          "triaxially_symmetric",
          [](double I) { return Checked(UI::TriaxiallySymmetric(I), "triaxially_symmetric()"); },
          py::arg("I_triaxial"), "Ixx = Iyy = Izz = I_triaxial.")
      .def_static("solid_ellipsoid", &UI::SolidEllipsoid, py::arg("a"), py::arg("b"), py::arg("c"),
                  "Solid ellipsoid with semi-axes a, b, c: ((b²+c²)/5, (a²+c²)/5, (a²+b²)/5).")
      .def_static("solid_sphere", &UI::SolidSphere, py::arg("r"),
                  "Solid sphere of radius r about its center: 2/5·r².")
      .def_static("hollow_sphere", &UI::HollowSphere, py::arg("r"),
                  "Thin spherical shell of radius r about its center: 2/3·r².")
      .def_static("solid_box", &UI::SolidBox, py::arg("Lx"), py::arg("Ly"), py::arg("Lz"),
                  "Solid box with full sides Lx, Ly, Lz: ((Ly²+Lz²)/12, (Lx²+Lz²)/12, "
                  "(Lx²+Ly²)/12).\n\n>>> massprops.UnitInertia.solid_box(1.0, 2.0, 3.0)")
      .def_static("solid_cube", &UI::SolidCube, py::arg("L"), "Solid cube of side L: L²/6.")
      .def_static("solid_cylinder", &UI::SolidCylinder, py::arg("r"), py::arg("L"),
                  py::arg("unit_vector"),
                  "Solid cylinder (radius r, length L, axis unit_vector) about its center: r²/2 "
                  "about the axis, (3r² + L²)/12 about perpendicular axes.")
      .def_static("solid_cylinder_about_end", &UI::SolidCylinderAboutEnd, py::arg("r"),
                  py::arg("L"), py::arg("unit_vector"),
                  "Solid cylinder about the center of one end: r²/2 about the axis, "
                  "r²/4 + L²/3 about perpendicular axes.")
      .def_static("solid_capsule", &UI::SolidCapsule, py::arg("r"), py::arg("L"),
                  py::arg("unit_vector"),
                  "Solid capsule (cylinder of radius r and length L capped by two hemispheres) "
                  "about its center.")
      .def_static("thin_rod", &UI::ThinRod, py::arg("L"), py::arg("unit_vector"),
                  "Thin rod of length L: 0 about its axis, L²/12 about perpendicular axes.")
      .def_static("thin_disk", &UI::ThinDisk, py::arg("r"), py::arg("unit_normal"),
                  "Thin disk of radius r: r²/2 about the normal, r²/4 in its plane.")
      .def_static("axially_symmetric", &UI::AxiallySymmetric, py::arg("J"), py::arg("K"),
                  py::arg("unit_vector"),
                  "J about the unit_vector axis, K about perpendicular axes: "
                  "K·1 + (J − K)·b·bᵀ. ValueError if J > 2K, J or K negative, or not unit.")
      .def_static("straight_line", &UI::StraightLine, py::arg("K"), py::arg("unit_vector"),
                  "axially_symmetric with J = 0.")
      .def_static("solid_tetrahedron_about_vertex", &UI::SolidTetrahedronAboutVertex, py::arg("p1"),
                  py::arg("p2"), py::arg("p3"),
                  "Solid tetrahedron with vertices A (the origin), p1, p2, p3, about A.")
      .def_static("solid_tetrahedron_about_point", &UI::SolidTetrahedronAboutPoint, py::arg("p0"),
                  py::arg("p1"), py::arg("p2"), py::arg("p3"),
                  "Solid tetrahedron with vertices p0..p3 (from a point A), about A.");
}

// __repr__ and pickling of UnitInertia.
void DefUnitInertiaPythonProtocol(py::class_<UI, RI>& c) {
  c.def("__repr__", [](const UI& G) { return "UnitInertia(" + Entries(G) + ")"; })
      .def(py::pickle(
          [](const UI& G) {
            return py::make_tuple(G(0, 0), G(1, 1), G(2, 2), G(0, 1), G(0, 2), G(1, 2));
          },
          [](const py::tuple& t) {
            if (t.size() != 6) throw py::value_error("UnitInertia: bad pickle state");
            return UI(RawInertia(t[0].cast<double>(), t[1].cast<double>(), t[2].cast<double>(),
                                 t[3].cast<double>(), t[4].cast<double>(), t[5].cast<double>()));
          }));
}

// massprops.UnitInertia (a RotationalInertia): the class and its members by group.
void BindUnitInertia(py::module_& m) {
  py::class_<UI, RI> c(m, "UnitInertia", R"doc(
The unit inertia G_BP_E (inertia per unit mass, m²) of a body B about a point P, expressed in E:
I_BP_E = m · G_BP_E. Shape factories give the unit inertia of uniform solids.

>>> G = massprops.UnitInertia.solid_box(0.1, 0.2, 0.3)
>>> 2.0 * G   # the RotationalInertia of a 2 kg box
)doc");
  DefUnitInertiaConstructors(c);
  DefUnitInertiaFrameChanges(c);
  DefUnitInertiaShapeFactories(c);
  DefUnitInertiaPythonProtocol(c);
}

bool SpatialEqual(const SI& a, const SI& b) {
  return a.get_mass() == b.get_mass() && a.get_com() == b.get_com() &&
         a.get_unit_inertia() == b.get_unit_inertia();
}

// The constructors and factories of SpatialInertia (checked unless asked not to).
void DefSpatialInertiaConstructors(py::class_<SI>& c) {
  c.def(py::init<>(), "Mass, center of mass and unit inertia all NaN.")
      .def(py::init([](double mass, const Vector3d& p, const UI& G, bool skip) {
             const SI M(mass, p, G, true);
             return skip ? M : Checked(M, "SpatialInertia()");
           }),
           py::arg("mass"), py::arg("p_PScm_E"), py::arg("G_SP_E"),
           py::arg("skip_validity_check") = false,
           "From the mass, the center of mass p_PScm_E and the unit inertia about P (not about "
           "the center of mass). ValueError if not physically valid unless "
           "skip_validity_check.")
      .def_static(
          "make_from_central_inertia",
          [](double mass, const Vector3d& p, const RI& I_SScm_E) {
            if (!(mass >= 0) || !std::isfinite(mass)) {
              throw py::value_error("make_from_central_inertia: the mass " + Repr(mass) +
                                    " is negative or not finite");
            }
            Checked(I_SScm_E, "make_from_central_inertia()");
            return Checked(SI::MakeFromCentralInertia(mass, p, I_SScm_E),
                           "make_from_central_inertia()");
          },
          py::arg("mass"), py::arg("p_PScm_E"), py::arg("I_SScm_E"),
          "From the mass, the center of mass from P, and the rotational inertia about the "
          "center of mass (shifted away from it: sums of positive terms only). ValueError if "
          "the mass is negative or the inertia not valid.")
      .def_static(
          "point_mass",
          [](double mass, const Vector3d& p) {
            if (!(mass >= 0) || !std::isfinite(mass)) {
              throw py::value_error("point_mass: the mass " + Repr(mass) +
                                    " is negative or not finite");
            }
            return SI(mass, p, UI::PointMass(p), true);
          },
          py::arg("mass"), py::arg("p_PQ_E"), "A particle of the given mass at p_PQ_E.")
      .def_static("make_unitary", &SI::MakeUnitary,
                  "Mass 1, center of mass at P, unit inertia the identity.")
      .def_static("zero", &SI::Zero, "Mass 0, center of mass at P, zero inertia.")
      .def_static("nan", &SI::NaN, "All NaN.");
}

// The mass, center of mass and inertias of a SpatialInertia, and its validity.
void DefSpatialInertiaAccessors(py::class_<SI>& c) {
  c.def("get_mass", &SI::get_mass, "The mass m.")
      .def("get_com", &SI::get_com, "p_PScm_E, the center of mass from P (numpy array).")
      .def("calc_com_moment", &SI::CalcComMoment, "m·p_PScm_E.")
      .def("get_unit_inertia", &SI::get_unit_inertia, "G_SP_E, the unit inertia about P.")
      .def("calc_rotational_inertia", &SI::CalcRotationalInertia,
           "I_SP_E = m·G_SP_E, the rotational inertia about P.")
      .def("is_nan", &SI::IsNaN, "True iff any number is NaN.")
      .def("set_nan", &SI::SetNaN, "Sets every number to NaN.")
      .def("is_physically_valid",
           py::overload_cast<const double&>(&SI::IsPhysicallyValid, py::const_),
           py::arg("relative_tolerance") = kDefaultTolerance,
           "True iff the mass is finite and >= 0, the center of mass finite, and the central "
           "unit inertia passes could_be_physically_valid(relative_tolerance). Never raises.")
      .def("criticize_not_physically_valid", &SI::CriticizeNotPhysicallyValid,
           py::arg("relative_tolerance") = kDefaultTolerance,
           "What fails is_physically_valid(relative_tolerance); '' when valid.");
}

// Pseudo-inertia, 6x6 matrix, shift, re-expression, sum and equality of SpatialInertia.
void DefSpatialInertiaOperations(py::class_<SI>& c) {
  c.def("calc_pseudo_inertia", &SI::CalcPseudoInertia,
        "The 4x4 pseudo-inertia [[Σ_P, m·c], [m·cᵀ, m]] (positive semi-definite iff "
        "physically realizable; Wensing, Kim, Slotine, RA-L 2018).")
      .def("copy_to_full_matrix6", &SI::CopyToFullMatrix6,
           "The 6x6 spatial inertia matrix about P (angular first, Drake's layout).")
      .def("shift", &SI::Shift, py::arg("p_PQ_E"),
           "The same body about the point Q (p_PQ_E from P to Q).")
      .def("re_express", &SI::ReExpress, py::arg("R_AE"),
           "Re-expressed in frame A for a rotation matrix R_AE.")
      .def(
          "__add__", [](const SI& a, const SI& b) { return a + b; }, py::is_operator(),
          "The composite of two bodies about the same point P, in the same frame.")
      .def("__eq__", &SpatialEqual, py::is_operator(),
           "Exact equality of mass, center of mass and unit inertia.")
      .def(
          "__ne__", [](const SI& a, const SI& b) { return !SpatialEqual(a, b); },
          py::is_operator());
}

// __repr__, __str__ and pickling of SpatialInertia.
void DefSpatialInertiaPythonProtocol(py::class_<SI>& c) {
  c.def("__repr__",
        [](const SI& M) {
          return "SpatialInertia(mass=" + Repr(M.get_mass()) +
                 ", p_PScm_E=" + VectorRepr(M.get_com()) + ", G_SP_E=UnitInertia(" +
                 Entries(M.get_unit_inertia()) + "))";
        })
      .def("__str__", &Str<SI>)
      .def(py::pickle(
          [](const SI& M) {
            const UI& G = M.get_unit_inertia();
            return py::make_tuple(
                M.get_mass(), M.get_com(),
                py::make_tuple(G(0, 0), G(1, 1), G(2, 2), G(0, 1), G(0, 2), G(1, 2)));
          },
          [](const py::tuple& t) {
            if (t.size() != 3) throw py::value_error("SpatialInertia: bad pickle state");
            const py::tuple g = t[2].cast<py::tuple>();
            return SI(t[0].cast<double>(), t[1].cast<Vector3d>(),
                      UI(RawInertia(g[0].cast<double>(), g[1].cast<double>(), g[2].cast<double>(),
                                    g[3].cast<double>(), g[4].cast<double>(), g[5].cast<double>())),
                      true);
          }));
}

// massprops.SpatialInertia: the class, its members by group, unhashable.
void BindSpatialInertia(py::module_& m) {
  py::class_<SI> c(m, "SpatialInertia", R"doc(
The mass distribution of a body S about a point P, expressed in a frame E: mass m, center of
mass p_PScm_E, and unit inertia G_SP_E about P (Drake's SpatialInertia). Validity is decided at
the center of mass. Constructors check validity (ValueError) unless skip_validity_check.

>>> box = massprops.SpatialInertia.make_from_central_inertia(
...     2.0, [0.1, 0, 0], 2.0 * massprops.UnitInertia.solid_box(0.1, 0.2, 0.3))
>>> (box + box.shift([0.5, 0, 0])).get_mass()
4.0
)doc");
  DefSpatialInertiaConstructors(c);
  DefSpatialInertiaAccessors(c);
  DefSpatialInertiaOperations(c);
  DefSpatialInertiaPythonProtocol(c);
  c.attr("__hash__") = py::none();
}

}  // namespace

void BindCore(py::module_& m) {
  py::enum_<PrincipalSolver>(m, "PrincipalSolver",
                             "Which solver computes principal moments: ACCURATE (backward "
                             "stable, the default) or FAST (closed form). Functions that take a "
                             "solver also accept the strings 'accurate' and 'fast'.")
      .value("ACCURATE", PrincipalSolver::kAccurate)
      .value("FAST", PrincipalSolver::kFast);
  m.attr("DEFAULT_VALIDITY_TOLERANCE") = kDefaultTolerance;
  BindRotationalInertia(m);
  BindUnitInertia(m);
  BindSpatialInertia(m);

  m.def("principal_moments", &PrincipalMoments, py::arg("I"), py::arg("solver") = "accurate",
        R"doc(Principal moments (ascending) of many inertia matrices at once.

I: array of shape (N, 3, 3) (or (..., 3, 3); converted to float64), each matrix symmetric to
round-off (ValueError naming the first that is not). Returns an array of shape (N, 3) (or
(..., 3)), each row exactly RotationalInertia.from_matrix(I[k], skip_validity_check=True)
.calc_principal_moments_of_inertia(solver); rows with a NaN or infinite entry are NaN.
solver: 'accurate' (default) or 'fast'. Runs without the GIL.

>>> massprops.principal_moments(numpy.array([numpy.diag([3.0, 1.0, 2.0])]))
array([[1., 2., 3.]])
)doc");
  m.def("is_physically_valid", &IsPhysicallyValid, py::arg("I"), py::arg("tolerance") = 1e-6,
        R"doc(Physical validity of many inertia matrices at once.

I: array of shape (N, 3, 3) (or (..., 3, 3)), symmetric to round-off (ValueError otherwise).
Returns a bool array of shape (N,) (or (...)), each exactly
RotationalInertia.from_matrix(I[k], skip_validity_check=True).could_be_physically_valid(tolerance):
finite entries and principal moments λ1 <= λ2 <= λ3 with λ1 >= -τ and λ1 + λ2 >= λ3 - τ,
τ = tolerance·trace. The default tolerance 1e-6 is `massprops check`'s; use
DEFAULT_VALIDITY_TOLERANCE (32·eps) for round-off only. Runs without the GIL.

>>> massprops.is_physically_valid(numpy.array([numpy.diag([0.1, 0.2, 0.5])]))
array([False])
)doc");
}

}  // namespace massprops::python

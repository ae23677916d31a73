#pragma once
// Shared declarations of the pybind11 module `massprops._massprops` (see python/CMakeLists.txt).
// Each Bind* function adds its part to the module; module.cc calls them in order.
#include <pybind11/pybind11.h>

#include <string>

#include "massprops/core/principal_axes.h"

namespace massprops::python {

/// RotationalInertia, UnitInertia, SpatialInertia, PrincipalSolver, and the vectorised
/// principal_moments / is_physically_valid (core_bindings.cc).
void BindCore(pybind11::module_& m);

/// massprops.ReadError, Model, Link, Joint, ..., read, read_all (reading_bindings.cc).
void BindReading(pybind11::module_& m);

/// Finding, the engine of check, rules (checking_bindings.cc).
void BindChecking(pybind11::module_& m);

/// FieldChange, Repair, PatchError, FixResult, the engine of fix, repair_inertia
/// (fixing_bindings.cc).
void BindFixing(pybind11::module_& m);

/// The engine of report (reporting_bindings.cc).
void BindReporting(pybind11::module_& m);

/// The engine of identify (identify_bindings.cc).
void BindIdentify(pybind11::module_& m);

/// The solver named by `solver`: a PrincipalSolver value or the string "accurate" / "fast".
/// Throws pybind11::value_error (unknown name) or pybind11::type_error (another type).
PrincipalSolver ToSolver(const pybind11::handle& solver);

/// The shortest text that reads back as exactly x ("0.1", "1e-06", "nan").
std::string Repr(double x);

}  // namespace massprops::python

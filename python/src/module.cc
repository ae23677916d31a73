// The pybind11 module `massprops._massprops`; python/massprops/__init__.py re-exports it.
#include <pybind11/pybind11.h>

#include <stdexcept>

#include "bindings.h"

PYBIND11_MODULE(_massprops, m) {
  m.doc() =
      "massprops: validate and repair the mass properties (mass, center of mass, inertia) of "
      "rigid bodies and of the links of URDF and SDF robot models. The compiled part of the "
      "`massprops` package; import `massprops` instead.";
  m.attr("__version__") = MASSPROPS_VERSION;
  // The core's precondition failures (std::logic_error, with the offending numbers in the
  // message) are bad arguments in Python: ValueError. Other C++ exceptions keep pybind11's
  // translation (std::bad_alloc: MemoryError, anything else: RuntimeError).
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const std::logic_error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  massprops::python::BindCore(m);
  massprops::python::BindReading(m);
  massprops::python::BindChecking(m);
  massprops::python::BindFixing(m);
  massprops::python::BindReporting(m);
  massprops::python::BindIdentify(m);
}

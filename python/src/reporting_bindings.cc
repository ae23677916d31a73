// Python bindings of reporting (massprops.report's engine _report: the JSON report of `massprops
// report` as Python data, src/tool/report_command.cc). Stubs: the "reporting" section of
// python/massprops/__init__.pyi.
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "file_bindings.h"
#include "massprops/analysis/checks.h"
#include "massprops/analysis/config.h"
#include "massprops/analysis/finding_sources.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/analysis/mass_repair.h"
#include "massprops/analysis/mass_report.h"
#include "massprops/analysis/materials.h"
#include "massprops/analysis/repair.h"
#include "massprops/analysis/welded_groups.h"
#include "massprops/core/rotational_inertia.h"
#include "massprops/core/spatial_inertia.h"
#include "massprops/io/model_reader.h"
#include "massprops/io/xacro_trace.h"
#include "massprops/mesh/mesh_loader.h"
#include "massprops/model/model.h"
#include "massprops/output/report_format.h"
#include "massprops/output/reporters.h"
#include "massprops/output/xml_patch.h"

namespace py = pybind11;

namespace massprops::python {

namespace {

py::object Report(const py::handle& source_arg, const std::map<std::string, double>& joints,
                  const std::string& frame, const std::vector<std::string>& only,
                  const std::string& subtree, bool geometry,
                  const std::vector<std::string>& package_paths,
                  const std::vector<std::string>& model_paths) {
  const Source source = ToSource(source_arg, "report");
  if (!only.empty() && !subtree.empty()) {
    throw py::value_error("report: only and subtree cannot be combined");
  }
  MassReportOptions options;
  for (const auto& [name, value] : joints) {
    if (!std::isfinite(value)) {
      throw py::value_error("report: joints['" + name + "'] = " + Repr(value) + " is not finite");
    }
    options.joint_values[name] = value;
  }
  options.frame = frame;
  options.only = only;
  options.subtree = subtree;
  const std::vector<Model> models = ReadModels(source, model_paths);
  MeshCache cache;
  MeshResolveOptions resolve = MeshResolveFor(source, package_paths, model_paths, &cache);
  options.geometry = geometry ? &resolve : nullptr;
  std::vector<ModelMassReport> reports;
  for (const Model& model : models) {
    ModelMassReport report;
    std::string error;
    if (!ComputeMassReport(model, options, &report, &error)) {
      throw py::value_error("report: " + source.path + ": " + error);
    }
    reports.push_back(std::move(report));
  }
  std::ostringstream out;
  WriteMassReport(out, MassReportFormat::kJson, reports, {}, options.digits_lost_threshold);
  return py::module_::import("json").attr("loads")(out.str());
}

}  // namespace

void BindReporting(py::module_& m) {
  m.def("_report", &Report, py::arg("path_or_text"), py::arg("joints"), py::arg("frame"),
        py::arg("only"), py::arg("subtree"), py::arg("geometry"), py::arg("package_paths"),
        py::arg("model_paths"), "The engine of massprops.report (use that).");
}

}  // namespace massprops::python

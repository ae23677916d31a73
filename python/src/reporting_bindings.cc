// Python bindings of reporting (massprops.report's engine _report: the JSON report of `massprops
// report` as Python data, src/tool/report_command.cc; massprops.diff's engine _diff: that of
// `massprops diff --format json`, src/tool/diff_command.cc). Stubs: the "reporting" section of
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
#include "massprops/analysis/model_diff.h"
#include "massprops/analysis/repair.h"
#include "massprops/analysis/target_profile.h"
#include "massprops/analysis/welded_groups.h"
#include "massprops/core/rotational_inertia.h"
#include "massprops/core/spatial_inertia.h"
#include "massprops/io/model_reader.h"
#include "massprops/io/xacro_trace.h"
#include "massprops/mesh/mesh_loader.h"
#include "massprops/model/model.h"
#include "massprops/output/diff_report.h"
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

// The target a file is read for, as `massprops diff` resolves it: `target` when given, else the
// target of the .massprops.toml found for the file, else generic.
Target DiffTarget(const std::optional<std::string>& target, const std::string& file) {
  if (target) {
    const std::optional<Target> parsed = ParseTarget(*target);
    if (!parsed) throw py::value_error("diff: unknown target '" + *target + "'");
    return *parsed;
  }
  const std::optional<std::string> config = FindConfigFor(file);
  if (!config) return Target::kGeneric;
  return LoadConfig(*config).target.value_or(Target::kGeneric);
}

// `massprops diff A B --format json` as Python data: each file read as the command reads it (its
// first model compared), then DiffModels and RenderDiffJson.
py::object Diff(const std::string& a, const std::string& b, double tolerance,
                const std::optional<std::string>& target,
                const std::vector<std::string>& model_paths) {
  if (!(tolerance >= 0)) throw py::value_error("diff: tolerance must be at least 0");
  std::vector<Model> models;
  for (const std::string& file : {a, b}) {
    ReadOptions options;
    options.sdf.model_paths = model_paths;
    options.mjcf.mujoco_mesh_inertia = DiffTarget(target, file) == Target::kMujoco;
    const ReadResult read = ReadModelFile(file, options);
    if (!read.errors.empty()) RaiseReadError(read.errors);
    if (read.models.empty()) {
      ReadError error;
      error.location.file = file;
      error.message = "no model in the file";
      RaiseReadError({error});
    }
    models.push_back(read.models.front());
  }
  const ModelDiff diff = DiffModels(models[0], models[1], tolerance);
  return py::module_::import("json").attr("loads")(RenderDiffJson(diff, models[0], models[1]));
}

}  // namespace

void BindReporting(py::module_& m) {
  m.def("_report", &Report, py::arg("path_or_text"), py::arg("joints"), py::arg("frame"),
        py::arg("only"), py::arg("subtree"), py::arg("geometry"), py::arg("package_paths"),
        py::arg("model_paths"), "The engine of massprops.report (use that).");
  m.def("_diff", &Diff, py::arg("a"), py::arg("b"), py::arg("tolerance"), py::arg("target"),
        py::arg("model_paths"), "The engine of massprops.diff (use that).");
}

}  // namespace massprops::python

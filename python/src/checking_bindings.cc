// Python bindings of checking (massprops.check's engine _check, massprops.rules; Finding). The
// findings are the tool's (src/tool/main.cc): the same readers, configuration lookup and checks.
// Stubs: the "checking" section of python/massprops/__init__.pyi.
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
#include "massprops/analysis/finding_text.h"
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

std::vector<Finding> Check(const py::handle& source_arg, std::optional<double> tolerance,
                           const std::vector<std::string>& disable,
                           const std::map<std::string, std::string>& severity,
                           const py::object& config, const std::vector<std::string>& model_paths,
                           bool geometry, double geometry_factor,
                           const std::vector<std::string>& package_paths,
                           const std::vector<std::string>& source_roots,
                           const std::map<std::string, std::string>& xacro_args) {
  const Source source = ToSource(source_arg, "check");
  if (tolerance && !(*tolerance >= 0 && *tolerance < 1)) {
    throw py::value_error("check: tolerance must be at least 0 and less than 1, got " +
                          Repr(*tolerance));
  }
  if (!(geometry_factor > 1) || !std::isfinite(geometry_factor)) {
    throw py::value_error("check: geometry_factor must be a finite number > 1, got " +
                          Repr(geometry_factor));
  }
  std::map<std::string, std::optional<Severity>> overrides;
  for (const std::string& rule : disable) {
    RequireKnownRule(rule, "check: disable");
    overrides[rule] = std::nullopt;
  }
  for (const auto& [rule, level] : severity) {
    RequireKnownRule(rule, "check: severity");
    if (level == "off") {
      overrides[rule] = std::nullopt;
    } else if (const std::optional<Severity> s = ParseSeverity(level)) {
      overrides[rule] = s;
    } else {
      throw py::value_error("check: severity['" + rule + "'] = '" + level +
                            "': the level must be off, note, warning or error");
    }
  }

  // The configuration file, as the tool finds it: "auto" = the nearest .massprops.toml upward
  // from the file's folder, else upward from the working directory; None = none; else a path.
  std::optional<Config> loaded;
  try {
    if (py::isinstance<py::str>(config) && config.cast<std::string>() == "auto") {
      const std::optional<std::string> found = FindConfigFor(source.is_text ? "-" : source.path);
      if (found) loaded = LoadConfig(*found);
    } else if (!config.is_none()) {
      loaded = LoadConfig(py::str(py::module_::import("os").attr("fspath")(config)));
    }
  } catch (const ConfigError& e) {
    throw py::value_error(e.what());
  }

  CheckOptions options;
  std::vector<std::string> paths = model_paths;
  std::vector<std::string> packages = package_paths;
  if (loaded) {
    ApplyConfig(*loaded, options);
    paths.insert(paths.end(), loaded->model_paths.begin(), loaded->model_paths.end());
    packages.insert(packages.end(), loaded->package_paths.begin(), loaded->package_paths.end());
  }
  if (tolerance) options.tolerance = *tolerance;
  for (const auto& [rule, level] : overrides) options.overrides[rule] = level;

  ReadOptions read_options;
  read_options.sdf.model_paths = paths;
  const ReadResult read = source.is_text ? ReadModelString(source.text, source.path, read_options)
                                         : ReadModelFile(source.path, read_options);
  if (!read.errors.empty()) RaiseReadError(read.errors);

  std::vector<Finding> findings;
  // As `massprops check` gives them (reporters.h).
  for (const ReadError& warning : read.warnings) findings.push_back(ReadWarningFinding(warning));
  for (Finding& finding : ReaderFindings(read, options)) findings.push_back(std::move(finding));
  MeshCache cache;
  for (const Model& model : read.models) {
    CheckOptions model_options = options;
    MeshResolveOptions resolve;
    resolve.package_paths = packages;
    resolve.model_paths = paths;
    resolve.model_file = model.file;
    resolve.cache = &cache;
    if (geometry) model_options.shape = MakeLinkShapeFunction(resolve);
    // As `massprops check` by default: the meshes' bounding boxes give mesh-only links a size.
    model_options.box = MakeLinkBoxFunction(resolve);
    std::vector<Finding> found = CheckModel(model, model_options);
    if (geometry) {
      GeometryCheckOptions geometry_options;
      geometry_options.enabled = true;
      geometry_options.factor = geometry_factor;
      geometry_options.resolve = resolve;
      geometry_options.check = options;
      const std::vector<Finding> more = CheckModelGeometry(model, geometry_options);
      found.insert(found.end(), more.begin(), more.end());
    }
    findings.insert(findings.end(), found.begin(), found.end());
  }
  // The file named by a finding: its own location, else the input (as the tool's reports).
  for (Finding& f : findings) {
    if (f.location.file.empty()) f.location.file = source.path;
  }
  // An expanded xacro package: each finding gets the place its numbers were written
  // (docs/xacro.md).
  if (!source_roots.empty()) {
    XacroTraceOptions trace_options;
    trace_options.source_roots = source_roots;
    trace_options.args = xacro_args;
    std::string text = source.text;
    if (!source.is_text) {
      trace_options.exclude_files.push_back(source.path);
      if (std::optional<ReadError> error = ReadInputFile(source.path, kMaxModelFileBytes, &text)) {
        RaiseReadError({*error});
      }
    }
    const XacroTrace trace = TraceXacro(text, source.path, trace_options);
    AttachXacroSources(trace, source.path, &findings);
  }
  return findings;
}

// A FindingSource as a dict: the first place's file, line, how, text, inputs; "places" when
// there are several; "number" and "generated" ({file, line}).
py::object SourceDict(const std::optional<FindingSource>& source) {
  if (!source || source->places.empty()) return py::none();
  auto place_dict = [](const SourcePlace& p) {
    py::dict d;
    d["file"] = p.file;
    d["line"] = p.line;
    d["how"] = p.how;
    d["text"] = p.text;
    d["inputs"] = p.inputs;
    return d;
  };
  py::dict d = place_dict(source->places.front());
  d["number"] = source->number;
  if (source->places.size() > 1) {
    py::list places;
    for (const SourcePlace& p : source->places) places.append(place_dict(p));
    d["places"] = places;
  }
  py::dict generated;
  generated["file"] = source->generated.file;
  generated["line"] = source->generated.line;
  d["generated"] = generated;
  return std::move(d);
}

// massprops.Finding: one problem found in a model.
void BindFinding(py::module_& m) {
  py::class_<Finding>(m, "Finding",
                      "One problem found in a model: rule, severity, link, file, line, "
                      "message and the measured values behind it.")
      .def_readonly("rule", &Finding::rule, "Stable rule id, e.g. 'inertia-not-physical'.")
      .def_property_readonly(
          "severity", [](const Finding& f) { return std::string(ToString(f.severity)); },
          "'error', 'warning' or 'note'.")
      .def_readonly("model", &Finding::model, "The model's name.")
      .def_readonly("link", &Finding::link, "The link ('' for the whole file).")
      .def_property_readonly("file", &FindingFile, "The file the finding points into.")
      .def_property_readonly(
          "line", [](const Finding& f) { return f.location.line; }, "1-based; 0 when unknown.")
      .def_property_readonly(
          "column", [](const Finding& f) { return f.location.column; }, "1-based; 0 when unknown.")
      .def_readonly("message", &Finding::message,
                    "The full reasoning: a sentence quoting the offending numbers.")
      .def_readonly("headline", &Finding::headline,
                    "One line: what is wrong with the link, the deciding number, the likely cause.")
      .def_property_readonly(
          "evidence", [](const Finding& f) { return ValuesDict(f.evidence); },
          "The named numbers that decided, a dict; each name ends in its SI unit ('mass_kg', "
          "'half_diagonal_m', 'trace_kg_m2') or names a pure number ('ratio').")
      .def_readonly("help", &Finding::help,
                    "The next step: the value to write, or the massprops fix command.")
      .def_property_readonly(
          "values", [](const Finding& f) { return ValuesDict(f.values); },
          "The named measured values, a dict.")
      .def_readonly("group", &Finding::group,
                    "A finding about a welded group of links (judged as one rigid body): its "
                    "members' names, the root (the finding's link) first; [] for a finding about "
                    "one link or the model.")
      .def_readonly("repair", &Finding::repair, "Always None from check(); see fix().")
      .def_property_readonly(
          "source", [](const Finding& f) { return SourceDict(f.source); },
          "check(..., source_root=DIR) on an expanded xacro package: where the numbers were "
          "written, a dict {file, line, how, text, inputs, number, generated: {file, line}} "
          "(and places: [...] when several); None otherwise.")
      .def(
          "to_dict",
          [](const Finding& f) {
            py::dict d;
            d["rule"] = f.rule;
            d["severity"] = ToString(f.severity);
            d["model"] = f.model;
            d["link"] = f.link;
            d["file"] = f.location.file;
            d["line"] = f.location.line;
            d["column"] = f.location.column;
            d["message"] = f.message;
            d["headline"] = HeadlineOf(f);
            d["evidence"] = ValuesDict(f.evidence);
            d["help"] = f.help;
            d["values"] = ValuesDict(f.values);
            if (!f.group.empty()) d["group"] = f.group;
            if (f.source) d["source"] = SourceDict(f.source);
            return d;
          },
          "The finding as the dict `massprops check --format json` writes for it (NaN where "
          "the JSON has null).")
      .def("__str__",
           [](const Finding& f) {
             std::string where = f.location.file;
             if (f.location.line > 0) where += ":" + std::to_string(f.location.line);
             if (f.location.column > 0) where += ":" + std::to_string(f.location.column);
             return where + ": " + ToString(f.severity) + ": " + HeadlineOf(f) + " [" + f.rule +
                    "]";
           })
      .def("__repr__", [](const Finding& f) {
        return "Finding(rule=" + Quote(f.rule) + ", severity=" + Quote(ToString(f.severity)) +
               ", link=" + Quote(f.link) + ", file=" + Quote(f.location.file) +
               ", line=" + std::to_string(f.location.line) + ")";
      });
}

}  // namespace

void BindChecking(py::module_& m) {
  BindFinding(m);
  m.def("_check", &Check, py::arg("path_or_text"), py::arg("tolerance"), py::arg("disable"),
        py::arg("severity"), py::arg("config"), py::arg("model_paths"), py::arg("geometry"),
        py::arg("geometry_factor"), py::arg("package_paths"), py::arg("source_roots"),
        py::arg("xacro_args"), "The engine of massprops.check (use that).");
  m.def(
      "rules",
      [] {
        py::list list;
        auto add = [&](const RuleInfo& r) {
          py::dict d;
          d["id"] = r.id;
          d["severity"] = ToString(r.default_severity);
          d["enabled"] = r.enabled_by_default;
          d["summary"] = r.summary;
          list.append(d);
        };
        for (const RuleInfo& r : AllRules()) add(r);
        for (const RuleInfo& r : GeometryRules()) {
          bool listed = false;
          for (const RuleInfo& a : AllRules()) listed |= a.id == r.id;
          if (!listed) add(r);
        }
        return list;
      },
      "Every rule as a dict {id, severity, enabled, summary} (as `massprops check "
      "--list-rules --format json`).");
}

}  // namespace massprops::python

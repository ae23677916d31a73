// Python bindings of the file side: read (Model, Link, Joint, ...), check (Finding), report
// (the JSON report as Python data) and fix (FixResult). Files are read as the `massprops` tool
// reads them (src/tool/main.cc, src/tool/fix_command.cc, src/tool/report_command.cc): the same
// readers, configuration lookup, checks and repairs, so the findings are the tool's.
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

// massprops.ReadError (created in BindFiles; the module holds the reference).
PyObject* g_read_error = nullptr;

// Raises massprops.ReadError for `errors` (at least one): the message lists them all, one per
// line ("file:line:col: element: message"); the attributes file, line, column, element and
// message are the first one's, `errors` all of them as strings.
[[noreturn]] void RaiseReadError(const std::vector<ReadError>& errors) {
  std::string text;
  py::list all;
  for (const ReadError& e : errors) {
    text += (text.empty() ? "" : "\n") + e.ToString();
    all.append(e.ToString());
  }
  py::object exception = py::reinterpret_borrow<py::object>(g_read_error)(text);
  const ReadError& first = errors.front();
  exception.attr("file") = first.location.file;
  exception.attr("line") = first.location.line;
  exception.attr("column") = first.location.column;
  exception.attr("element") = first.element;
  exception.attr("message") = first.message;
  exception.attr("errors") = all;
  PyErr_SetObject(g_read_error, exception.ptr());
  throw py::error_already_set();
}

// What a `path_or_text` argument is: model text (a str whose first non-blank character is '<',
// or bytes) or a path (any other str, or an os.PathLike).
struct Source {
  bool is_text = false;
  std::string path;  // the path, or "<string>" for text
  std::string text;
};

Source ToSource(const py::handle& source, const char* function) {
  Source s;
  if (py::isinstance<py::bytes>(source)) {
    s.is_text = true;
    s.text = source.cast<std::string>();
  } else if (py::isinstance<py::str>(source)) {
    const std::string value = source.cast<std::string>();
    std::size_t i = 0;
    if (value.compare(0, 3, "\xEF\xBB\xBF") == 0) i = 3;  // byte order mark
    while (i < value.size() && std::isspace(static_cast<unsigned char>(value[i]))) ++i;
    if (i < value.size() && value[i] == '<') {
      s.is_text = true;
      s.text = value;
    } else {
      s.path = value;
    }
  } else if (py::hasattr(source, "__fspath__")) {
    py::object path = py::module_::import("os").attr("fspath")(source);
    if (!py::isinstance<py::str>(path)) {
      throw py::type_error(std::string(function) + ": a path must be text, not bytes");
    }
    s.path = path.cast<std::string>();
  } else {
    throw py::type_error(std::string(function) +
                         ": expected a path (str or os.PathLike) or model text (str starting "
                         "with '<', or bytes), got " +
                         py::str(py::type::of(source).attr("__name__")).cast<std::string>());
  }
  if (s.is_text) {
    s.path = "<string>";
  } else if (s.path.empty() || s.path == "-") {
    throw py::value_error(std::string(function) + ": the path is empty or '-' (pass the text " +
                          "of a model instead of standard input)");
  }
  return s;
}

ReadResult ReadSource(const Source& s, const std::vector<std::string>& model_paths) {
  ReadOptions options;
  options.sdf.model_paths = model_paths;
  return s.is_text ? ReadModelString(s.text, s.path, options) : ReadModelFile(s.path, options);
}

// Reads the models; raises ReadError when the file could not be read or holds no model.
std::vector<Model> ReadModels(const Source& s, const std::vector<std::string>& model_paths,
                              ReadResult* read_out = nullptr) {
  ReadResult read = ReadSource(s, model_paths);
  if (!read.errors.empty()) RaiseReadError(read.errors);
  if (read.models.empty()) {
    ReadError error;
    error.location.file = s.path;
    error.message = "no model found";
    RaiseReadError({error});
  }
  std::vector<Model> models = read.models;
  if (read_out) *read_out = std::move(read);
  return models;
}

std::string FormatName(Model::Format format) {
  return ToString(format);
}

std::string GeometryTypeName(Geometry::Type type) {
  switch (type) {
    case Geometry::Type::kBox:
      return "box";
    case Geometry::Type::kCylinder:
      return "cylinder";
    case Geometry::Type::kSphere:
      return "sphere";
    case Geometry::Type::kCapsule:
      return "capsule";
    case Geometry::Type::kEllipsoid:
      return "ellipsoid";
    case Geometry::Type::kMesh:
      return "mesh";
    case Geometry::Type::kOther:
      break;
  }
  return "other";
}

Eigen::Matrix3d InertiaAsWritten(const Inertial& in) {
  Eigen::Matrix3d I;
  I << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  return I;
}

// The central inertia of the inertial, expressed in the link frame B: R_BBi·I_Bi·R_BBiᵀ.
Eigen::Matrix3d CentralInertiaInLinkFrame(const Inertial& in) {
  const Eigen::Matrix3d& R = in.X_BBi.R_AB;
  return R * InertiaAsWritten(in) * R.transpose();
}

RotationalInertia<double> Unchecked(const Eigen::Matrix3d& I) {
  return RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(
      I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2), true);
}

// The SpatialInertia of the inertial about the link origin Bo, expressed in B (not checked).
SpatialInertia<double> SpatialInertiaAboutLinkOrigin(const Inertial& in) {
  const double mass = in.mass;
  const Eigen::Vector3d& c = in.X_BBi.p_AB;
  const Eigen::Matrix3d I = CentralInertiaInLinkFrame(in);
  UnitInertia<double> G = UnitInertia<double>::PointMass(c);
  if (mass != 0) {
    G = UnitInertia<double>(Unchecked(I / mass));
    G.ShiftFromCenterOfMassInPlace(c);
  }
  return SpatialInertia<double>(mass, c, G, true);
}

// The composite of a body (welded group or model), with the frame that expresses it.
struct Composite {
  std::string frame;
  CompositeInertia inertia;
  std::vector<std::string> unreachable_links;
};

struct PyWeldedGroup {
  std::string root_link;
  std::vector<std::string> links;
  std::vector<int> link_indices;
  std::vector<Pose> X_RL;
  std::optional<std::string> parent_joint;
  bool is_moving = false;
  Composite composite;
};

// The welded groups of the model with their names and composites, as Model.welded_groups gives.
std::vector<PyWeldedGroup> WeldedGroupsOf(const Model& model) {
  std::vector<PyWeldedGroup> groups;
  for (const WeldedGroup& g : FindWeldedGroups(model)) {
    PyWeldedGroup p;
    p.root_link = g.root_link;
    p.link_indices = g.links;
    for (int i : g.links) p.links.push_back(model.links[static_cast<std::size_t>(i)].name);
    p.X_RL = g.X_RL;
    if (g.parent_joint >= 0) {
      p.parent_joint = model.joints[static_cast<std::size_t>(g.parent_joint)].name;
    }
    p.is_moving = g.is_moving;
    p.composite = {g.root_link, CalcCompositeInertia(model, g), {}};
    groups.push_back(std::move(p));
  }
  return groups;
}

struct FixResult {
  std::string path;
  std::string original;
  std::string text;
  bool changed = false;
  bool reads_back = true;
  std::vector<Repair> changes;
  std::vector<PatchError> patch_errors;
  std::vector<Finding> remaining_errors;
  std::vector<std::string> warnings;
  std::optional<std::string> written;
};

// Text as str, bytes that are not UTF-8 kept as surrogate escapes (they encode back unchanged
// with errors="surrogateescape").
py::str Text(const std::string& text) {
  PyObject* s =
      PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "surrogateescape");
  if (s == nullptr) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(s);
}

std::string Quote(const std::string& s) { return py::repr(py::str(s)).cast<std::string>(); }

template <typename Items>
py::list ReferenceList(const py::handle& parent, const Items& items) {
  py::list list;
  for (const auto& item : items) {
    list.append(py::cast(&item, py::return_value_policy::reference_internal, parent));
  }
  return list;
}

py::dict ValuesDict(const std::vector<std::pair<std::string, double>>& values) {
  py::dict d;
  for (const auto& [name, value] : values) d[py::str(name)] = value;
  return d;
}

std::string FindingFile(const Finding& f) { return f.location.file; }

bool IsKnownRule(const std::string& rule) {
  for (const RuleInfo& info : AllRules()) {
    if (info.id == rule) return true;
  }
  for (const RuleInfo& info : GeometryRules()) {
    if (info.id == rule) return true;
  }
  return false;
}

void RequireKnownRule(const std::string& rule, const char* what) {
  if (!IsKnownRule(rule)) {
    throw py::value_error(std::string(what) + ": unknown rule '" + rule +
                          "' (massprops.rules() lists them)");
  }
}

// ------------------------------------------------------------------------------------ check

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
  for (const ReadError& warning : read.warnings) {
    Finding finding;
    finding.rule = kReadWarningRule;
    finding.severity = Severity::kWarning;
    finding.location = warning.location;
    finding.message =
        warning.element.empty() ? warning.message : warning.element + ": " + warning.message;
    findings.push_back(finding);
  }
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

// -------------------------------------------------------------------------------------- fix

// What fix()'s from_geometry names: every link (True), none (False), or the links listed.
struct FromGeometry {
  bool all = false;
  std::vector<std::string> links;
};

// Checks fix()'s apply, repair, density and tolerance (ValueError) and reads from_geometry
// (TypeError when it is not True, False, a link name or a list of link names).
FromGeometry CheckFixArguments(const std::vector<std::string>& apply, const std::string& repair,
                               double density, double tolerance, const py::object& from_geometry) {
  for (const std::string& rule : apply) RequireKnownRule(rule, "fix: apply");
  if (repair != "project" && repair != "balance") {
    throw py::value_error("fix: repair must be 'project' or 'balance', got '" + repair + "'");
  }
  if (!(density > 0) || !std::isfinite(density)) {
    throw py::value_error("fix: density must be a positive number of kg/m³, got " + Repr(density));
  }
  if (!(tolerance >= 0 && tolerance < 1)) {
    throw py::value_error("fix: tolerance must be at least 0 and less than 1, got " +
                          Repr(tolerance));
  }
  FromGeometry result;
  if (py::isinstance<py::bool_>(from_geometry)) {
    result.all = from_geometry.cast<bool>();
  } else if (py::isinstance<py::str>(from_geometry)) {
    result.links.push_back(from_geometry.cast<std::string>());
  } else {
    try {
      result.links = from_geometry.cast<std::vector<std::string>>();
    } catch (const py::cast_error&) {
      throw py::type_error("fix: from_geometry must be True, False or a list of link names");
    }
  }
  return result;
}

// Sets result->path and result->original (the text given, or the file's bytes; ReadError when
// the file cannot be read) and returns the models read from that text (ReadError if none).
std::vector<Model> ReadFixInput(const Source& source, const std::vector<std::string>& model_paths,
                                FixResult* result) {
  result->path = source.path;
  if (source.is_text) {
    result->original = source.text;
  } else if (std::optional<ReadError> error =
                 ReadInputFile(source.path, kMaxModelFileBytes, &result->original)) {
    RaiseReadError({*error});
  }
  const Source text_source{true, source.path, result->original};
  ReadResult read;
  return ReadModels(text_source, model_paths, &read);
}

// The repair options of fix()'s arguments, without a shape function.
RepairOptions MakeRepairOptions(const std::string& repair, bool fix_units,
                                const std::vector<std::string>& apply, double density,
                                const FromGeometry& from_geometry, double tolerance) {
  RepairOptions options;
  options.method =
      repair == "balance" ? InertiaRepairMethod::kBalance : InertiaRepairMethod::kProject;
  options.fix_units = fix_units;
  options.apply = apply;  // PlanRepairs plans heuristic repairs only when named
  options.density = density;
  options.from_geometry_all = from_geometry.all;
  options.from_geometry_links = from_geometry.links;
  options.tolerance = tolerance;
  return options;
}

// Plans the repairs of every model into result->changes and returns the names of all links.
// `apply`: error findings are always repaired (physics decides); a warning or note is repaired
// only when its rule is named in `apply` (a heuristic repair runs only when asked for).
std::vector<std::string> PlanFixRepairs(const std::vector<Model>& models,
                                        const std::vector<std::string>& apply,
                                        const CheckOptions& check_options,
                                        const RepairOptions& options, FixResult* result) {
  const std::set<std::string> applied(apply.begin(), apply.end());
  std::vector<std::string> known_links;
  for (const Model& model : models) {
    for (const Link& link : model.links) known_links.push_back(link.name);
    std::vector<Finding> findings = CheckModel(model, check_options);
    findings.erase(std::remove_if(findings.begin(), findings.end(),
                                  [&](const Finding& f) {
                                    return f.severity != Severity::kError && !applied.count(f.rule);
                                  }),
                   findings.end());
    std::vector<Repair> planned = PlanRepairs(model, findings, options);
    result->changes.insert(result->changes.end(), planned.begin(), planned.end());
  }
  return known_links;
}

// Raises ValueError for a from_geometry link the file does not have, and adds a warning for
// each one no repair changes, saying why.
void WarnUnrepairedGeometryLinks(const std::vector<Model>& models,
                                 const std::vector<std::string>& known_links,
                                 const std::vector<std::string>& from_geometry_links,
                                 const MeshResolveOptions& resolve, const std::string& path,
                                 FixResult* result) {
  for (const std::string& link : from_geometry_links) {
    if (std::find(known_links.begin(), known_links.end(), link) == known_links.end()) {
      throw py::value_error("fix: from_geometry: " + path + " has no link '" + link + "'");
    }
    const bool repaired = std::any_of(result->changes.begin(), result->changes.end(),
                                      [&](const Repair& r) { return r.link == link; });
    if (repaired) continue;
    for (const Model& model : models) {
      const int index = model.FindLink(link);
      if (index < 0) continue;
      std::string why;
      if (CalcLinkGeometryInertia(model.links[static_cast<std::size_t>(index)], 1.0, resolve,
                                  &why)) {
        why = "its geometry gives the inertial it already has";
      }
      result->warnings.push_back("from_geometry: link '" + link + "' is left as it is: " + why);
    }
  }
}

// Writes result->changes into result->text (sets patch_errors and changed); repairs that could
// not be written are not changes.
void PatchFixedText(Model::Format format, FixResult* result) {
  const PatchResult patched = PatchModelText(result->original, format, result->changes);
  result->text = patched.text;
  result->patch_errors = patched.errors;
  result->changes.erase(std::remove_if(result->changes.begin(), result->changes.end(),
                                       [&](const Repair& r) {
                                         return std::any_of(
                                             patched.errors.begin(), patched.errors.end(),
                                             [&](const PatchError& e) {
                                               return e.link == r.link && e.line == r.link_line;
                                             });
                                       }),
                        result->changes.end());
  result->changed = result->text != result->original;
}

// Never write something worse: whether result->text reads back, and its remaining errors.
void RecheckFixedText(const std::string& path, const std::vector<std::string>& model_paths,
                      const CheckOptions& check_options, FixResult* result) {
  ReadOptions read_options;
  read_options.sdf.model_paths = model_paths;
  const ReadResult reread = ReadModelString(result->text, path, read_options);
  result->reads_back = reread.ok();
  for (const Model& model : reread.models) {
    for (Finding& f : CheckModel(model, check_options)) {
      if (f.severity == Severity::kError) result->remaining_errors.push_back(std::move(f));
    }
  }
}

// The mass repairs asked for (fix --total-mass, --mass, --density LINK=, --material); raises
// ValueError for a number that is not positive or a material not in the table.
MassRepairOptions MakeMassOptions(const std::optional<double>& total_mass,
                                  const std::map<std::string, double>& link_masses,
                                  const std::map<std::string, double>& link_densities,
                                  const std::map<std::string, std::string>& materials) {
  MassRepairOptions mass;
  if (total_mass) {
    if (!(*total_mass > 0) || !std::isfinite(*total_mass)) {
      throw py::value_error("fix: total_mass must be a positive number of kg, got " +
                            Repr(*total_mass));
    }
    mass.total_mass = *total_mass;
  }
  for (const auto& [link, kg] : link_masses) mass.link_masses.emplace_back(link, kg);
  for (const auto& [link, rho] : link_densities) mass.link_densities.push_back({link, rho, ""});
  for (const auto& [link, name] : materials) {
    const Material* material = FindMaterial(name);
    if (material == nullptr) {
      throw py::value_error("fix: material['" + link + "'] = '" + name + "' is not one of " +
                            MaterialNames());
    }
    mass.link_densities.push_back({link, material->density, material->label});
  }
  return mass;
}

// The engine of massprops.fix: checks the arguments, plans and writes the repairs, re-checks.
FixResult Fix(const py::handle& source_arg, const std::vector<std::string>& apply,
              const std::string& repair, bool fix_units, double density,
              const py::object& from_geometry_arg, double tolerance, bool geometry,
              const std::vector<std::string>& package_paths,
              const std::vector<std::string>& model_paths, const std::optional<double>& total_mass,
              const std::map<std::string, double>& link_masses,
              const std::map<std::string, double>& link_densities,
              const std::map<std::string, std::string>& materials) {
  MassRepairOptions mass = MakeMassOptions(total_mass, link_masses, link_densities, materials);
  const Source source = ToSource(source_arg, "fix");
  const FromGeometry from_geometry =
      CheckFixArguments(apply, repair, density, tolerance, from_geometry_arg);

  FixResult result;
  const std::vector<Model> models = ReadFixInput(source, model_paths, &result);

  RepairOptions options =
      MakeRepairOptions(repair, fix_units, apply, density, from_geometry, tolerance);
  CheckOptions check_options;
  check_options.tolerance = tolerance;
  MeshCache cache;
  MeshResolveOptions resolve;
  resolve.package_paths = package_paths;
  resolve.model_paths = model_paths;
  resolve.model_file = source.is_text ? std::string() : source.path;
  resolve.cache = &cache;
  if (geometry || from_geometry.all || !from_geometry.links.empty()) {
    options.shape = MakeLinkShapeFunction(resolve);
    if (geometry) check_options.shape = options.shape;
  }
  options.box = MakeLinkBoxFunction(resolve);  // as `massprops fix` by default
  check_options.box = options.box;

  // The mass repairs asked for by name first; the others are planned on their result.
  std::vector<Model> planned_models = models;
  std::vector<Repair> mass_repairs;
  if (mass.any()) {
    if (models.size() != 1) {
      throw py::value_error(
          "fix: total_mass, mass, density={link: ...} and material work on a "
          "file with one model; " +
          source.path + " has " + std::to_string(models.size()));
    }
    mass.closed_mesh = MakeClosedMeshShapeFunction(resolve);
    check_options.closed_mesh = mass.closed_mesh;
    std::string error;
    if (!PlanMassRepairs(models.front(), mass, &mass_repairs, &error)) {
      throw py::value_error("fix: " + error);
    }
    planned_models.front() = ApplyRepairs(models.front(), mass_repairs);
  }
  const std::vector<std::string> known_links =
      PlanFixRepairs(planned_models, apply, check_options, options, &result);
  if (!mass_repairs.empty()) {
    result.changes = ChainRepairs(models.front(), mass_repairs, result.changes);
  }
  WarnUnrepairedGeometryLinks(models, known_links, from_geometry.links, resolve, source.path,
                              &result);
  PatchFixedText(models.front().format, &result);
  RecheckFixedText(source.path, model_paths, check_options, &result);
  return result;
}

// ----------------------------------------------------------------------------------- report

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
  MeshResolveOptions resolve;
  resolve.package_paths = package_paths;
  resolve.model_paths = model_paths;
  resolve.model_file = source.is_text ? std::string() : source.path;
  resolve.cache = &cache;
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

// ------------------------------------------------------------------------------ the classes

// massprops.SourceLocation: where an element was read from.
void BindSourceLocation(py::module_& m) {
  py::class_<SourceLocation>(m, "SourceLocation",
                             "Where an element was read from: file, line and column (1-based; "
                             "0 when unknown).")
      .def_readonly("file", &SourceLocation::file, "The path as given (or '<string>').")
      .def_readonly("line", &SourceLocation::line, "1-based line; 0 when unknown.")
      .def_readonly("column", &SourceLocation::column, "1-based column; 0 when unknown.")
      .def("__repr__",
           [](const SourceLocation& l) {
             return "SourceLocation(" + Quote(l.file) + ", line=" + std::to_string(l.line) +
                    ", column=" + std::to_string(l.column) + ")";
           })
      .def("__str__", [](const SourceLocation& l) {
        return l.file + (l.line > 0 ? ":" + std::to_string(l.line) : "");
      });
}

// massprops.Pose: a rigid pose X_AB.
void BindPose(py::module_& m) {
  py::class_<Pose>(m, "Pose",
                   "A rigid pose X_AB: p_AB (position of B's origin from A's, in A) and R_AB "
                   "(rotation re-expressing vectors from B in A).")
      .def_readonly("p_AB", &Pose::p_AB, "The position, a numpy 3-vector.")
      .def_readonly("R_AB", &Pose::R_AB, "The rotation matrix, a numpy 3x3 array.")
      .def("inverse", &Pose::Inverse, "X_BA.")
      .def("is_identity", &Pose::IsIdentity, "True iff exactly the identity.")
      .def("__mul__", &Pose::operator*, py::is_operator(), "X_AC = X_AB * X_BC.")
      .def("__repr__", [](const Pose& X) {
        std::ostringstream out;
        out.precision(17);
        out << "Pose(p_AB=[" << X.p_AB(0) << ", " << X.p_AB(1) << ", " << X.p_AB(2) << "], R_AB=[["
            << X.R_AB(0, 0) << ", " << X.R_AB(0, 1) << ", " << X.R_AB(0, 2) << "], ["
            << X.R_AB(1, 0) << ", " << X.R_AB(1, 1) << ", " << X.R_AB(1, 2) << "], ["
            << X.R_AB(2, 0) << ", " << X.R_AB(2, 1) << ", " << X.R_AB(2, 2) << "]])";
        return out.str();
      });
}

// massprops.Inertial: an <inertial> exactly as written.
void BindInertial(py::module_& m) {
  py::class_<Inertial>(m, "Inertial",
                       "An <inertial> exactly as written: mass, the pose X_BBi of the inertial "
                       "frame in the link frame, and the six numbers about the center of mass "
                       "in Bi (ixy = -∫xy dm, as URDF and SDF write them).")
      .def_readonly("mass", &Inertial::mass, "The <mass> (kg) as written.")
      .def_readonly("X_BBi", &Inertial::X_BBi, "URDF <origin> / SDF <pose> of the inertial.")
      .def_readonly("ixx", &Inertial::ixx,
                    "<inertia ixx> as written (kg·m², about the center of mass, in Bi).")
      .def_readonly("iyy", &Inertial::iyy,
                    "<inertia iyy> as written (kg·m², about the center of mass, in Bi).")
      .def_readonly("izz", &Inertial::izz,
                    "<inertia izz> as written (kg·m², about the center of mass, in Bi).")
      .def_readonly("ixy", &Inertial::ixy,
                    "<inertia ixy> as written (kg·m², about the center of mass, in Bi).")
      .def_readonly("ixz", &Inertial::ixz,
                    "<inertia ixz> as written (kg·m², about the center of mass, in Bi).")
      .def_readonly("iyz", &Inertial::iyz,
                    "<inertia iyz> as written (kg·m², about the center of mass, in Bi).")
      .def_property_readonly("inertia", &InertiaAsWritten,
                             "The 3x3 inertia matrix as written (about the center of mass, in "
                             "Bi).")
      .def_readonly("location", &Inertial::location, "The <inertial> element.")
      .def_readonly("mass_location", &Inertial::mass_location, "The <mass> element.")
      .def_readonly("inertia_location", &Inertial::inertia_location, "The <inertia> element.")
      .def_readonly("pose_location", &Inertial::pose_location, "The <origin>/<pose> element.")
      .def("__repr__", [](const Inertial& in) {
        return "Inertial(mass=" + Repr(in.mass) + ", ixx=" + Repr(in.ixx) +
               ", iyy=" + Repr(in.iyy) + ", izz=" + Repr(in.izz) + ", ixy=" + Repr(in.ixy) +
               ", ixz=" + Repr(in.ixz) + ", iyz=" + Repr(in.iyz) +
               ", line=" + std::to_string(in.location.line) + ")";
      });
}

// massprops.Geometry: a collision or visual geometry of a link.
void BindGeometry(py::module_& m) {
  py::class_<Geometry>(m, "Geometry", "A collision or visual geometry of a link.")
      .def_property_readonly(
          "type", [](const Geometry& g) { return GeometryTypeName(g.type); },
          "'box', 'cylinder', 'sphere', 'capsule', 'ellipsoid', 'mesh' or 'other'.")
      .def_readonly("size", &Geometry::size, "box: full lengths along x, y, z.")
      .def_readonly("radius", &Geometry::radius, "cylinder, sphere, capsule.")
      .def_readonly("length", &Geometry::length, "cylinder, capsule (cylindrical part).")
      .def_readonly("radii", &Geometry::radii, "ellipsoid: semi-axes.")
      .def_readonly("uri", &Geometry::uri, "mesh: the filename/uri as written.")
      .def_readonly("scale", &Geometry::scale, "mesh: the scale.")
      .def_readonly("X_BG", &Geometry::X_BG, "Pose of the geometry in the link frame.")
      .def_readonly("is_collision", &Geometry::is_collision, "False for <visual>.")
      .def_readonly("location", &Geometry::location, "The <collision>/<visual> element.")
      .def("__repr__", [](const Geometry& g) {
        return "Geometry(type=" + Quote(GeometryTypeName(g.type)) +
               (g.is_collision ? ", collision" : ", visual") +
               ", line=" + std::to_string(g.location.line) + ")";
      });
}

// massprops.Link: a link, its inertial as written and as core inertias, its geometries.
void BindLink(py::module_& m) {
  py::class_<Link>(m, "Link",
                   "A link: its name, its <inertial> (or None), geometries and source line.\n\n"
                   ">>> link = massprops.read('robot.urdf').link('arm')\n"
                   ">>> link.mass, link.com, link.inertia")
      .def_readonly("name", &Link::name, "The link's name (SDF: scoped, 'inner::link').")
      .def_readonly("inertial", &Link::inertial, "The Inertial as written, or None.")
      .def_property_readonly(
          "mass",
          [](const Link& l) -> std::optional<double> {
            if (!l.inertial) return std::nullopt;
            return l.inertial->mass;
          },
          "The mass (kg) as written, or None without <inertial>.")
      .def_property_readonly(
          "com",
          [](const Link& l) -> std::optional<Eigen::Vector3d> {
            if (!l.inertial) return std::nullopt;
            return l.inertial->X_BBi.p_AB;
          },
          "The center of mass p_BoBcm_B in the link frame (numpy 3-vector), or None.")
      .def_property_readonly(
          "inertia",
          [](const Link& l) -> std::optional<Eigen::Matrix3d> {
            if (!l.inertial) return std::nullopt;
            return CentralInertiaInLinkFrame(*l.inertial);
          },
          "The inertia about the center of mass expressed in the link frame B "
          "(R_BBi·I·R_BBiᵀ, numpy 3x3), or None.")
      .def(
          "rotational_inertia",
          [](const Link& l) -> std::optional<RotationalInertia<double>> {
            if (!l.inertial) return std::nullopt;
            return Unchecked(CentralInertiaInLinkFrame(*l.inertial));
          },
          "The central inertia in B as a RotationalInertia (not checked: call "
          "could_be_physically_valid()), or None.")
      .def(
          "spatial_inertia",
          [](const Link& l) -> std::optional<SpatialInertia<double>> {
            if (!l.inertial) return std::nullopt;
            return SpatialInertiaAboutLinkOrigin(*l.inertial);
          },
          "The SpatialInertia about the link origin Bo, expressed in B (not checked: call "
          "is_physically_valid()), or None.")
      .def_property_readonly(
          "geometries",
          [](py::object self) { return ReferenceList(self, self.cast<const Link&>().geometries); },
          "Collisions and visuals, in file order.")
      .def_readonly("ignored_rules", &Link::ignored_rules,
                    "Rules disabled by a `<!-- massprops: ignore ... -->` comment.")
      .def_readonly("inertial_unreadable", &Link::inertial_unreadable,
                    "True when the <inertial> could not be read.")
      .def_readonly("location", &Link::location, "The <link> element.")
      .def_property_readonly(
          "line", [](const Link& l) { return l.location.line; }, "Line of the <link> element.")
      .def("__repr__", [](const Link& l) {
        std::string text = "Link(" + Quote(l.name);
        if (l.inertial) text += ", mass=" + Repr(l.inertial->mass);
        return text + ", line=" + std::to_string(l.location.line) + ")";
      });
}

// massprops.Joint: a joint of the model.
void BindJoint(py::module_& m) {
  py::class_<Joint>(m, "Joint", "A joint: name, type, parent and child links, origin, axis.")
      .def_readonly("name", &Joint::name, "The joint's name.")
      .def_readonly("type", &Joint::type_name, "As written: 'revolute', 'fixed', ...")
      .def_readonly("parent", &Joint::parent, "Parent link name ('world' for SDF world joints).")
      .def_readonly("child", &Joint::child, "Child link name.")
      .def_readonly("X_PC", &Joint::X_PC, "Child frame in the parent frame at joint value 0.")
      .def_readonly("axis", &Joint::axis, "Unit axis in the child frame.")
      .def_readonly("location", &Joint::location, "The <joint> element.")
      .def("__repr__", [](const Joint& j) {
        return "Joint(" + Quote(j.name) + ", " + Quote(j.type_name) +
               ", parent=" + Quote(j.parent) + ", child=" + Quote(j.child) + ")";
      });
}

// massprops.CompositeInertia: the composite of several links in the frame of a link.
void BindCompositeInertia(py::module_& m) {
  py::class_<Composite>(m, "CompositeInertia",
                        "The composite mass properties of several links (a welded group or "
                        "the whole model) in the frame of a link.")
      .def_readonly("frame", &Composite::frame, "The link whose frame F expresses the numbers.")
      .def_property_readonly(
          "mass", [](const Composite& c) { return c.inertia.mass; }, "Total mass (kg).")
      .def_property_readonly(
          "com", [](const Composite& c) { return c.inertia.p_RoScm_R; },
          "The composite center of mass from F's origin, in F.")
      .def_property_readonly(
          "inertia_about_com", [](const Composite& c) { return c.inertia.I_SScm_R; },
          "The composite inertia about its center of mass, in F (3x3).")
      .def(
          "calc_inertia_about_origin",
          [](const Composite& c) { return c.inertia.CalcInertiaAboutOrigin(); },
          "The inertia about F's origin, in F.")
      .def(
          "rotational_inertia", [](const Composite& c) { return Unchecked(c.inertia.I_SScm_R); },
          "The central inertia as a RotationalInertia (not checked).")
      .def_readonly("unreachable_links", &Composite::unreachable_links,
                    "Links left out (not reachable from the root through joints).")
      .def("__repr__", [](const Composite& c) {
        return "CompositeInertia(frame=" + Quote(c.frame) + ", mass=" + Repr(c.inertia.mass) +
               ", com=[" + Repr(c.inertia.p_RoScm_R(0)) + ", " + Repr(c.inertia.p_RoScm_R(1)) +
               ", " + Repr(c.inertia.p_RoScm_R(2)) + "])";
      });
}

// massprops.WeldedGroup: links joined by fixed joints, with their composite.
void BindWeldedGroup(py::module_& m) {
  py::class_<PyWeldedGroup>(m, "WeldedGroup",
                            "Links joined by fixed joints (one rigid body), with their "
                            "composite in the root link's frame.")
      .def_readonly("root_link", &PyWeldedGroup::root_link, "The member nearest the model root.")
      .def_readonly("links", &PyWeldedGroup::links, "Names, root first.")
      .def_readonly("link_indices", &PyWeldedGroup::link_indices, "Indices into Model.links.")
      .def_readonly("X_RL", &PyWeldedGroup::X_RL, "Pose of each member in the root frame.")
      .def_readonly("parent_joint", &PyWeldedGroup::parent_joint,
                    "The non-fixed joint attaching the group, or None.")
      .def_readonly("is_moving", &PyWeldedGroup::is_moving,
                    "True when the group can move relative to its parent.")
      .def_readonly("composite", &PyWeldedGroup::composite,
                    "The group's CompositeInertia in the root link's frame.")
      .def("__repr__", [](const PyWeldedGroup& g) {
        return "WeldedGroup(root_link=" + Quote(g.root_link) + ", " +
               std::to_string(g.links.size()) + " links, mass=" + Repr(g.composite.inertia.mass) +
               ")";
      });
}

// massprops.Model: links, joints, welded groups and composite of a model.
void BindModel(py::module_& m) {
  py::class_<Model>(m, "Model",
                    "A robot model read from a URDF or SDF file: links, joints, root link.\n\n"
                    ">>> model = massprops.read('robot.urdf')\n"
                    ">>> [link.name for link in model.links]")
      .def_readonly("name", &Model::name, "The <robot>/<model> name.")
      .def_property_readonly(
          "format", [](const Model& model) { return FormatName(model.format); }, "'urdf' or 'sdf'.")
      .def_readonly("file", &Model::file, "The path as given ('<string>' for text).")
      .def_property_readonly(
          "links",
          [](py::object self) { return ReferenceList(self, self.cast<const Model&>().links); },
          "The links, in file order.")
      .def_property_readonly(
          "joints",
          [](py::object self) { return ReferenceList(self, self.cast<const Model&>().joints); },
          "The joints, in file order.")
      .def_readonly("root_link", &Model::root_link, "The link that is no joint's child.")
      .def_readonly("location", &Model::location, "The <robot>/<model> element.")
      .def_readonly("is_static", &Model::is_static, "SDF <static>true</static>.")
      .def("find_link", &Model::FindLink, py::arg("name"), "Index of the link, or -1.")
      .def(
          "link",
          [](py::object self, const std::string& name) {
            const Model& model = self.cast<const Model&>();
            const int index = model.FindLink(name);
            if (index < 0) throw py::key_error("the model has no link '" + name + "'");
            return py::cast(&model.links[static_cast<std::size_t>(index)],
                            py::return_value_policy::reference_internal, self);
          },
          py::arg("name"), "The link of that name (KeyError if none).")
      .def(
          "welded_groups", [](const Model& model) { return WeldedGroupsOf(model); },
          "The welded groups (links joined by fixed joints), each with its composite.")
      .def(
          "composite",
          [](const Model& model) {
            const ModelCompositeInertia c = CalcModelCompositeInertia(model);
            Composite result{model.root_link, c.inertia, {}};
            for (int i : c.unreachable_links) {
              result.unreachable_links.push_back(model.links[static_cast<std::size_t>(i)].name);
            }
            return result;
          },
          "The whole model's composite at the zero configuration, in the root link's frame.")
      .def("__repr__", [](const Model& model) {
        return "Model(" + Quote(model.name) + ", format=" + Quote(FormatName(model.format)) + ", " +
               std::to_string(model.links.size()) + " links, " +
               std::to_string(model.joints.size()) + " joints)";
      });
}

// The classes of a read model, in the order their names appear in later signatures.
void BindModelClasses(py::module_& m) {
  BindSourceLocation(m);
  BindPose(m);
  BindInertial(m);
  BindGeometry(m);
  BindLink(m);
  BindJoint(m);
  BindCompositeInertia(m);
  BindWeldedGroup(m);
  BindModel(m);
}

// massprops.FieldChange: one number (or run of numbers) a repair changes.
void BindFieldChange(py::module_& m) {
  py::class_<FieldChange>(m, "FieldChange",
                          "One number (or run of numbers) of the file that a repair changes.")
      .def_readonly("element", &FieldChange::element, "'mass', 'inertia', 'origin' or 'pose'.")
      .def_readonly("attribute", &FieldChange::attribute,
                    "URDF attribute ('ixx', 'value', 'xyz') or SDF child element; '' for the "
                    "element's own text.")
      .def_readonly("line", &FieldChange::line, "Line in the original text (0: inserted).")
      .def_readonly("first_token", &FieldChange::first_token,
                    "Index of the first number of the value that changes.")
      .def_readonly("old_values", &FieldChange::old_values, "The numbers as written.")
      .def_readonly("new_values", &FieldChange::new_values, "The numbers written instead.")
      .def("__repr__", [](const FieldChange& c) {
        std::string text = "FieldChange(" + Quote(c.element) + ", " + Quote(c.attribute) +
                           ", line=" + std::to_string(c.line) + ", old=[";
        for (std::size_t i = 0; i < c.old_values.size(); ++i) {
          text += (i ? ", " : "") + Repr(c.old_values[i]);
        }
        text += "], new=[";
        for (std::size_t i = 0; i < c.new_values.size(); ++i) {
          text += (i ? ", " : "") + Repr(c.new_values[i]);
        }
        return text + "])";
      });
}

// massprops.Repair: the new mass properties of one link.
void BindRepair(py::module_& m) {
  py::class_<Repair>(m, "Repair",
                     "The new mass properties of one link and how they differ from the file.")
      .def_readonly("rule", &Repair::rule, "The finding it answers first.")
      .def_readonly("link", &Repair::link, "The link's name.")
      .def_readonly("method", &Repair::method,
                    "'project', 'balance', 'negate-products', 'rescale-units', 'shift-to-com', "
                    "'from-geometry', ...")
      .def_readonly("before", &Repair::before, "The Inertial as written (None if missing).")
      .def_readonly("after", &Repair::after, "The repaired Inertial.")
      .def_readonly("inserts_inertial", &Repair::inserts_inertial,
                    "A new <inertial> is inserted (inertial-missing).")
      .def_readonly("inserts_origin", &Repair::inserts_origin,
                    "An <origin>/<pose> is inserted into the <inertial>.")
      .def_readonly("changes", &Repair::changes, "The FieldChanges.")
      .def_readonly("link_line", &Repair::link_line, "Line of the <link> start tag.")
      .def_readonly("why", &Repair::why, "What was wrong and what the new numbers are.")
      .def_readonly("relative_change", &Repair::relative_change,
                    "‖I_after − I_before‖_F / ‖I_before‖_F (1 when nothing was there).")
      .def_readonly("resolves", &Repair::resolves, "Rules this repair resolves on its link.")
      .def("__str__", &DescribeRepair)
      .def("__repr__", [](const Repair& r) {
        return "Repair(link=" + Quote(r.link) + ", rule=" + Quote(r.rule) +
               ", method=" + Quote(r.method) + ")";
      });
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
      .def_readonly("message", &Finding::message, "A sentence quoting the offending numbers.")
      .def_property_readonly(
          "values", [](const Finding& f) { return ValuesDict(f.values); },
          "The named measured values, a dict.")
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
            d["values"] = ValuesDict(f.values);
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
             return where + ": " + ToString(f.severity) + ": " + f.message + " [" + f.rule + "]";
           })
      .def("__repr__", [](const Finding& f) {
        return "Finding(rule=" + Quote(f.rule) + ", severity=" + Quote(ToString(f.severity)) +
               ", link=" + Quote(f.link) + ", file=" + Quote(f.location.file) +
               ", line=" + std::to_string(f.location.line) + ")";
      });
}

// massprops.PatchError: a repair that could not be written.
void BindPatchError(py::module_& m) {
  py::class_<PatchError>(m, "PatchError", "A repair that could not be written, and why.")
      .def_readonly("link", &PatchError::link, "The link's name.")
      .def_readonly("line", &PatchError::line, "Line of the link.")
      .def_readonly("message", &PatchError::message, "Why the repair was not written.")
      .def("__repr__", [](const PatchError& e) {
        return "PatchError(link=" + Quote(e.link) + ", line=" + std::to_string(e.line) +
               ", message=" + Quote(e.message) + ")";
      });
}

// massprops.FixResult: what fix() did.
void BindFixResult(py::module_& m) {
  py::class_<FixResult>(m, "FixResult",
                        "What fix() did: the repairs (changes), the new text, what is left.")
      .def_readonly("path", &FixResult::path, "The input path ('<string>' for text).")
      .def_property_readonly(
          "original", [](const FixResult& r) { return Text(r.original); },
          "The text before (bytes that are not UTF-8 as surrogate escapes).")
      .def_property_readonly(
          "text", [](const FixResult& r) { return Text(r.text); },
          "The repaired text (== original if unchanged).")
      .def_readonly("changed", &FixResult::changed, "True iff text != original.")
      .def_readonly("reads_back", &FixResult::reads_back,
                    "The repaired text reads back (else nothing is ever written).")
      .def_readonly("changes", &FixResult::changes, "The Repairs written, one per link.")
      .def_readonly("patch_errors", &FixResult::patch_errors, "Repairs that could not be written.")
      .def_readonly("remaining_errors", &FixResult::remaining_errors,
                    "Error findings of the repaired text (no repair exists for them).")
      .def_readonly("warnings", &FixResult::warnings, "Notes about from_geometry links.")
      .def_readwrite("written", &FixResult::written,
                     "The path written, or None (dry run, or nothing to change).")
      .def(
          "diff",
          [](const FixResult& r, int context) {
            return Text(UnifiedDiff(r.original, r.text, r.path, context));
          },
          py::arg("context") = 3, "A unified diff of original → text ('' when unchanged).")
      .def("__repr__", [](const FixResult& r) {
        return "FixResult(path=" + Quote(r.path) + ", " + std::to_string(r.changes.size()) +
               " change(s), changed=" + (r.changed ? "True" : "False") +
               ", remaining_errors=" + std::to_string(r.remaining_errors.size()) + ")";
      });
}

// The classes of check and fix results.
void BindFindingClasses(py::module_& m) {
  BindFieldChange(m);
  BindRepair(m);
  BindFinding(m);
  BindPatchError(m);
  BindFixResult(m);
}

}  // namespace

void BindFiles(py::module_& m) {
  g_read_error = PyErr_NewExceptionWithDoc(
      "massprops.ReadError",
      "A model file could not be read or parsed. Attributes: file, line, column, element, "
      "message (of the first error) and errors (every error as 'file:line:col: element: "
      "message').",
      PyExc_Exception, nullptr);
  if (g_read_error == nullptr) throw py::error_already_set();
  m.add_object("ReadError", py::handle(g_read_error));

  BindModelClasses(m);
  BindFindingClasses(m);

  m.def(
      "read",
      [](const py::handle& path_or_text, const std::vector<std::string>& model_paths) {
        return ReadModels(ToSource(path_or_text, "read"), model_paths).front();
      },
      py::arg("path_or_text"), py::kw_only(), py::arg("model_paths") = std::vector<std::string>(),
      R"doc(Reads a URDF or SDF model (format detected by content) and returns its Model.

path_or_text: a path (str or os.PathLike), or the model's text (a str starting with '<', or
bytes). model_paths: folders searched for SDF model:// includes. A world with several models:
the first (read_all returns every one). Raises massprops.ReadError (with file and line) when the
file cannot be read or parsed.

>>> model = massprops.read('robot.urdf')
>>> model.link('arm').mass
)doc");
  m.def(
      "read_all",
      [](const py::handle& path_or_text, const std::vector<std::string>& model_paths) {
        return ReadModels(ToSource(path_or_text, "read_all"), model_paths);
      },
      py::arg("path_or_text"), py::kw_only(), py::arg("model_paths") = std::vector<std::string>(),
      "As read(), every model of the file (an SDF world may hold several).");
  m.def("_check", &Check, py::arg("path_or_text"), py::arg("tolerance"), py::arg("disable"),
        py::arg("severity"), py::arg("config"), py::arg("model_paths"), py::arg("geometry"),
        py::arg("geometry_factor"), py::arg("package_paths"), py::arg("source_roots"),
        py::arg("xacro_args"), "The engine of massprops.check (use that).");
  m.def("_fix", &Fix, py::arg("path_or_text"), py::arg("apply"), py::arg("repair"),
        py::arg("fix_units"), py::arg("density"), py::arg("from_geometry"), py::arg("tolerance"),
        py::arg("geometry"), py::arg("package_paths"), py::arg("model_paths"),
        py::arg("total_mass"), py::arg("link_masses"), py::arg("link_densities"),
        py::arg("materials"), "The engine of massprops.fix (use that).");
  m.def("_report", &Report, py::arg("path_or_text"), py::arg("joints"), py::arg("frame"),
        py::arg("only"), py::arg("subtree"), py::arg("geometry"), py::arg("package_paths"),
        py::arg("model_paths"), "The engine of massprops.report (use that).");
  m.def(
      "repair_inertia",
      [](const Eigen::Matrix3d& I, const std::string& method, double tolerance) {
        if (method != "project" && method != "balance") {
          throw py::value_error("repair_inertia: method must be 'project' or 'balance', got '" +
                                method + "'");
        }
        if (!(tolerance >= 0 && tolerance < 1)) {
          throw py::value_error("repair_inertia: tolerance must be at least 0 and less than 1");
        }
        if ((I - I.transpose()).cwiseAbs().maxCoeff() >
            8 * std::numeric_limits<double>::epsilon() * I.cwiseAbs().maxCoeff()) {
          throw py::value_error("repair_inertia: the matrix is not symmetric");
        }
        return RepairInertia(
            I, method == "balance" ? InertiaRepairMethod::kBalance : InertiaRepairMethod::kProject,
            tolerance);
      },
      py::arg("I"), py::arg("method") = "project", py::arg("tolerance") = 1e-6,
      R"doc(The nearest physically valid inertia to the symmetric 3x3 matrix I (what `massprops fix`
writes for inertia-not-physical), as a numpy array. method: 'project' (default; the nearest valid
inertia in the Frobenius norm with the same principal axes) or 'balance' (principal moments set
to their mean, MuJoCo's balanceinertia). A valid I (at `tolerance` relative to the trace) is
returned unchanged.

>>> massprops.repair_inertia(numpy.diag([0.1, 0.2, 0.5]))   # moments move by 0.2/3
)doc");
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

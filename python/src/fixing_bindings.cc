// Python bindings of fixing (massprops.fix's engine _fix, massprops.repair_inertia; FieldChange,
// Repair, PatchError, FixResult), as `massprops fix` repairs (src/tool/fix_command.cc). Stubs: the
// "fixing" section of python/massprops/__init__.pyi.
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
  MeshResolveOptions resolve = MeshResolveFor(source, package_paths, model_paths, &cache);
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

}  // namespace

void BindFixing(py::module_& m) {
  BindFieldChange(m);
  BindRepair(m);
  BindPatchError(m);
  BindFixResult(m);
  m.def("_fix", &Fix, py::arg("path_or_text"), py::arg("apply"), py::arg("repair"),
        py::arg("fix_units"), py::arg("density"), py::arg("from_geometry"), py::arg("tolerance"),
        py::arg("geometry"), py::arg("package_paths"), py::arg("model_paths"),
        py::arg("total_mass"), py::arg("link_masses"), py::arg("link_densities"),
        py::arg("materials"), "The engine of massprops.fix (use that).");
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
}

}  // namespace massprops::python

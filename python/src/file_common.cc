// What the Python bindings of files share (file_bindings.h): the path-or-text argument, reading
// with massprops.ReadError, inertia helpers, text conversion and rule names.
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

// massprops.ReadError (created in BindReading; the module holds the reference).
PyObject* g_read_error = nullptr;

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

std::vector<Model> ReadModels(const Source& s, const std::vector<std::string>& model_paths,
                              ReadResult* read_out) {
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

MeshResolveOptions MeshResolveFor(const Source& s, const std::vector<std::string>& package_paths,
                                  const std::vector<std::string>& model_paths, MeshCache* cache) {
  MeshResolveOptions resolve;
  resolve.package_paths = package_paths;
  resolve.model_paths = model_paths;
  resolve.model_file = s.is_text ? std::string() : s.path;
  resolve.cache = cache;
  return resolve;
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

Eigen::Matrix3d CentralInertiaInLinkFrame(const Inertial& in) {
  const Eigen::Matrix3d& R = in.X_BBi.R_AB;
  return R * InertiaAsWritten(in) * R.transpose();
}

RotationalInertia<double> Unchecked(const Eigen::Matrix3d& I) {
  return RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(
      I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2), true);
}

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

py::str Text(const std::string& text) {
  PyObject* s =
      PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "surrogateescape");
  if (s == nullptr) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(s);
}

std::string Quote(const std::string& s) { return py::repr(py::str(s)).cast<std::string>(); }

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

}  // namespace massprops::python

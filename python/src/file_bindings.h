#pragma once
// Private to the Python module: what the bindings of files share (file_common.cc). The bindings
// are one file per area, each with its section of python/massprops/__init__.pyi:
// reading_bindings.cc, checking_bindings.cc, reporting_bindings.cc, fixing_bindings.cc.
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

// massprops.ReadError (created in BindReading; the module holds the reference).
extern PyObject* g_read_error;

// Raises massprops.ReadError for `errors` (at least one): the message lists them all, one per
// line ("file:line:col: element: message"); the attributes file, line, column, element and
// message are the first one's, `errors` all of them as strings.
[[noreturn]] void RaiseReadError(const std::vector<ReadError>& errors);

// What a `path_or_text` argument is: model text (a str whose first non-blank character is '<',
// or bytes) or a path (any other str, or an os.PathLike).
struct Source {
  bool is_text = false;
  std::string path;  // the path, or "<string>" for text
  std::string text;
};

Source ToSource(const py::handle& source, const char* function);

ReadResult ReadSource(const Source& s, const std::vector<std::string>& model_paths);

// Reads the models; raises ReadError when the file could not be read or holds no model.
std::vector<Model> ReadModels(const Source& s, const std::vector<std::string>& model_paths,
                              ReadResult* read_out = nullptr);

// Where the meshes of the model read from `s` are found: the package and model folders, and the
// model file's own folder (none for text), with `cache` shared by the reads.
MeshResolveOptions MeshResolveFor(const Source& s, const std::vector<std::string>& package_paths,
                                  const std::vector<std::string>& model_paths, MeshCache* cache);

std::string FormatName(Model::Format format);

std::string GeometryTypeName(Geometry::Type type);

Eigen::Matrix3d InertiaAsWritten(const Inertial& in);

// The central inertia of the inertial, expressed in the link frame B: R_BBi·I_Bi·R_BBiᵀ.
Eigen::Matrix3d CentralInertiaInLinkFrame(const Inertial& in);

RotationalInertia<double> Unchecked(const Eigen::Matrix3d& I);

// The SpatialInertia of the inertial about the link origin Bo, expressed in B (not checked).
SpatialInertia<double> SpatialInertiaAboutLinkOrigin(const Inertial& in);

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
std::vector<PyWeldedGroup> WeldedGroupsOf(const Model& model);

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
py::str Text(const std::string& text);

std::string Quote(const std::string& s);

py::dict ValuesDict(const std::vector<std::pair<std::string, double>>& values);

std::string FindingFile(const Finding& f);

bool IsKnownRule(const std::string& rule);

void RequireKnownRule(const std::string& rule, const char* what);

template <typename Items>
py::list ReferenceList(const py::handle& parent, const Items& items) {
  py::list list;
  for (const auto& item : items) {
    list.append(py::cast(&item, py::return_value_policy::reference_internal, parent));
  }
  return list;
}

}  // namespace massprops::python

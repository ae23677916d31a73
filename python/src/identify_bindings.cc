// Python binding of identification (massprops.identify's engine _identify: the report of
// `massprops identify ROBOT DATA --format json` as Python data, src/tool/identify_command.cc,
// docs/identify.md). Stubs: the "identification" section of python/massprops/__init__.pyi.
#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "bindings.h"
#include "file_bindings.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/analysis/identify.h"
#include "massprops/io/model_reader.h"
#include "massprops/io/trajectory_csv.h"
#include "massprops/io/trajectory_rosbag.h"
#include "massprops/mesh/mesh_loader.h"
#include "massprops/output/identify_report.h"

namespace py = pybind11;

namespace massprops::python {

namespace {

// The robot's first model as a fixed-base tree; ReadError or ValueError (not a fixed-base tree).
KinematicTree IdentifyTree(const std::string& robot, Model* model) {
  const ReadResult read = ReadModelFile(robot);
  if (!read.errors.empty()) RaiseReadError(read.errors);
  if (read.models.empty()) {
    ReadError error;
    error.location.file = robot;
    error.message = "no model in the file";
    RaiseReadError({error});
  }
  *model = read.models.front();
  KinematicTreeResult made = MakeKinematicTree(*model);
  if (!made.tree) throw py::value_error("identify: " + robot + ": " + made.error);
  return *made.tree;
}

// `massprops identify ROBOT DATA --validate V --format json` as Python data.
py::object Identify(const std::string& robot, const std::string& data, double validate) {
  if (!(validate >= 0 && validate <= 0.9))
    throw py::value_error("identify: validate must be between 0 and 0.9");
  Model model;
  const KinematicTree tree = IdentifyTree(robot, &model);
  const TrajectoryReadResult log =
      IsRosbagPath(data) ? ReadTrajectoryRosbag(data) : ReadTrajectoryCsvFile(data);
  if (!log.ok()) RaiseReadError(log.errors);
  const OrderedTrajectory ordered = OrderTrajectory(tree, *log.trajectory);
  if (!ordered.ok()) throw py::value_error("identify: " + data + ": " + ordered.error);
  IdentifyOptions options;
  options.validation_fraction = validate;
  // The bound of each body's geometry, its meshes found as the command finds them without
  // --package-path (relative to the file, its package's folders, ROS_PACKAGE_PATH).
  MeshCache cache;
  MeshResolveOptions resolve;
  resolve.model_file = robot;
  resolve.cache = &cache;
  options.ellipsoids = BodyBoundingEllipsoids(model, tree, MakeLinkPointsFunction(resolve));
  IdentifyResult result;
  try {
    result = massprops::Identify(tree, ordered, options);
  } catch (const std::invalid_argument& e) {
    throw py::value_error("identify: " + data + ": " + e.what());
  }
  return py::module_::import("json").attr("loads")(RenderIdentifyJson(tree, result));
}

}  // namespace

void BindIdentify(py::module_& m) {
  m.def("_identify", &Identify, py::arg("robot"), py::arg("data"), py::arg("validate"),
        "Engine of massprops.identify.");
}

}  // namespace massprops::python

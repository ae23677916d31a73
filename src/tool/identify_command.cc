// `massprops identify ROBOT DATA` (docs/identify.md, issue 51): the inertial parameters that a
// recorded trajectory proves, physically consistent (analysis/identify.h), reported per joint and
// per link, and written back into the URDF, SDF or MJCF file with fix's minimal-diff writer. Exit
// codes:
//   0  identified (and written, when asked);
//   2  a file could not be read, the model is not a fixed-base tree, the data's joints do not
//      match the model's, the output cannot be written, or the command line is wrong.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "commands.h"
#include "geometry_cli.h"
#include "identify_html.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/analysis/identify.h"
#include "massprops/analysis/repair.h"
#include "massprops/core/rotational_inertia.h"
#include "massprops/io/model_reader.h"
#include "massprops/io/trajectory_csv.h"
#include "massprops/io/trajectory_rosbag.h"
#include "massprops/output/identify_report.h"
#include "massprops/output/xml_patch.h"
#include "safe_write.h"

namespace massprops::cli {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitError = 2;

struct IdentifyArgs {
  std::string robot, data;
  double validate = 0.3;
  std::string write;
  bool in_place = false;
  std::string format = "text";
  std::string html;
  bool no_geometry = false;  // --no-geometry
  std::vector<std::string> package_paths;
};

std::string Number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

// Three numbers; those below 1e-9 of the largest are round-off of a zero and shown as 0.
std::string Triple(Eigen::Vector3d v) {
  const double largest = v.cwiseAbs().maxCoeff();
  for (int k = 0; k < 3; ++k) {
    if (std::abs(v[k]) < 1e-9 * largest) v[k] = 0;
  }
  return "(" + Number(v[0]) + ", " + Number(v[1]) + ", " + Number(v[2]) + ")";
}

// How many links the bounding-ellipsoid condition was imposed on, and those of them whose least
// squares estimate lies outside their ellipsoid, named.
void WriteGeometryBoundSummary(const IdentifyArgs& args, const IdentifyResult& r) {
  std::cout << "geometry bound (a density inside the ellipsoid bounding the link's geometry): ";
  if (args.no_geometry) {
    std::cout << "not imposed (--no-geometry)\n";
    return;
  }
  std::cout << "imposed on " << r.geometry_bound_links << " of " << r.bodies.size() << " links";
  if (r.geometry_bound_links < static_cast<int>(r.bodies.size()))
    std::cout << " (the others' geometry is not known)";
  if (r.geometry_bound_links == 0) {
    std::cout << "\n";
    return;
  }
  std::cout << "; least squares lies outside it for " << r.least_squares_outside_geometry_links
            << " of them";
  std::string names;
  for (const BodyEstimate& b : r.bodies) {
    if (!b.least_squares_within_geometry)
      names += (names.empty() ? "" : ", ") + ("'" + b.link + "'");
  }
  if (!names.empty()) std::cout << " (" << names << ")";
  std::cout << "\n";
}

void WriteText(const IdentifyArgs& args, const KinematicTree& tree, const IdentifyResult& r) {
  const Identifiability& id = r.identifiability;
  std::cout << "massprops identify: " << args.robot << " (" << tree.size() << " joints) with "
            << args.data << " (" << r.training_samples + r.validation_samples
            << " samples: " << r.training_samples << " fitted, " << r.validation_samples
            << " held out)\n\n";
  std::cout << "identifiability: the data determine " << id.rank << " combinations of the "
            << r.column_names.size() << " parameters (condition number "
            << Number(id.condition_number) << ")\n";
  if (r.unexcited_links.empty()) {
    std::cout << "  every link is excited\n";
  } else {
    std::cout << "  not excited (kept as the file has them):";
    for (const std::string& l : r.unexcited_links) std::cout << " '" << l << "'";
    std::cout << "\n";
  }
  std::cout << "  base parameters (file -> identified, ± OLS standard error):\n";
  for (std::size_t i = 0; i < id.base.size(); ++i) {
    const Eigen::Index k = static_cast<Eigen::Index>(i);
    const double scale =
        std::max(r.base_file.cwiseAbs().maxCoeff(), r.base_identified.cwiseAbs().maxCoeff());
    const auto clean = [&](double x) { return std::abs(x) < 1e-12 * scale ? 0.0 : x; };
    std::cout << "    " << id.base[i].ToString() << ": " << Number(clean(r.base_file[k])) << " -> "
              << Number(clean(r.base_identified[k])) << " ± " << Number(r.base_standard_error[k])
              << "\n";
  }
  std::cout << "\ntorque RMS on the " << (r.validation_samples > 0 ? "held-out" : "fitted")
            << " samples (N·m or N): file -> identified (least squares)\n";
  for (int j = 0; j < tree.size(); ++j) {
    std::cout << "  joint '" << tree.bodies[j].joint << "': " << Number(r.rms_file[j]) << " -> "
              << Number(r.rms_identified[j]) << " (" << Number(r.rms_least_squares[j]) << ")\n";
  }
  std::cout << "\nleast squares (the base parameters above, the rest at the file's values): "
            << r.inconsistent_least_squares_links << " of " << r.bodies.size()
            << " links not physically consistent";
  std::string names;
  for (const BodyEstimate& b : r.bodies) {
    if (!b.least_squares_consistent) names += (names.empty() ? "" : ", ") + ("'" + b.link + "'");
  }
  if (!names.empty()) std::cout << " (" << names << ")";
  std::cout << "\n";
  WriteGeometryBoundSummary(args, r);
  std::cout << "the consistent fit " << r.solver_status << " in " << r.solver_iterations
            << " iterations\n\nlinks (with the links welded to them), file -> identified ± its "
               "standard error over the noise:\n";
  const bool errors = r.mass_standard_error.size() == static_cast<Eigen::Index>(r.bodies.size());
  for (std::size_t k = 0; k < r.bodies.size(); ++k) {
    const BodyEstimate& b = r.bodies[k];
    const Eigen::Index i = static_cast<Eigen::Index>(k);
    const BodyCentralProperties before = CentralPropertiesOf(b.file),
                                after = CentralPropertiesOf(b.identified);
    std::cout << "  link '" << b.link << "':\n    mass " << Number(before.mass) << " -> "
              << Number(after.mass)
              << (errors ? " ± " + Number(r.mass_standard_error[i]) : std::string()) << " kg\n"
              << "    center of mass " << Triple(before.com) << " -> " << Triple(after.com)
              << (errors ? " ± " + Triple(r.com_standard_error.col(i)) : std::string())
              << " m\n    principal moments " << Triple(before.principal) << " -> "
              << Triple(after.principal)
              << (errors ? " ± " + Triple(r.principal_moments_standard_error.col(i))
                         : std::string())
              << " kg·m²\n";
    if (b.geometry_bound) {
      std::cout << "    inside the ellipsoid bounding its geometry (ratio, at most 1 inside): "
                << Number(b.file_ellipsoid_ratio) << " -> " << Number(b.identified_ellipsoid_ratio)
                << " (least squares " << Number(b.least_squares_ellipsoid_ratio) << ")\n";
    }
  }
}

void WriteJson(const KinematicTree& tree, const IdentifyResult& r) {
  std::cout << RenderIdentifyJson(tree, r);
}

// x to `digits` significant digits, or 0 when below 1e-9 of `scale` (round-off of a value the
// data and the file leave at zero).
double Rounded(double x, double scale, int digits) {
  if (!(std::abs(x) >= 1e-9 * scale)) return 0;
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", digits, x);
  return std::strtod(text, nullptr);
}

// The <inertial> of central properties p, its inertia expressed in the inertial frame Bi whose
// rotation R_BBi is kept from the file, with the fewest significant digits (6 at least) whose
// inertia is still valid: a fit whose constraint is active sits on the triangle inequality.
Inertial RoundedInertial(const BodyCentralProperties& p, const Eigen::Matrix3d& R_BBi) {
  Inertial a;
  a.X_BBi.R_AB = R_BBi;
  const Eigen::Matrix3d I = R_BBi.transpose() * p.I_BBcm_B * R_BBi;
  const double trace = I.trace();
  const double length = std::max(p.com.norm(), std::sqrt(std::max(trace, 0.0) / p.mass));
  for (int digits : {6, 8, 10, 12, 14, 17}) {
    for (int k = 0; k < 3; ++k) a.X_BBi.p_AB[k] = Rounded(p.com[k], length, digits);
    a.mass = Rounded(p.mass, p.mass, digits);
    a.ixx = Rounded(I(0, 0), trace, digits), a.iyy = Rounded(I(1, 1), trace, digits);
    a.izz = Rounded(I(2, 2), trace, digits), a.ixy = Rounded(I(0, 1), trace, digits);
    a.ixz = Rounded(I(0, 2), trace, digits), a.iyz = Rounded(I(1, 2), trace, digits);
    if (internal::IsPhysicallyValidInertia(a.ixx, a.iyy, a.izz, a.ixy, a.ixz, a.iyz, 1e-12)) break;
  }
  return a;
}

// The identified values of each excited body as repairs of its link's <inertial>. A body with
// massive welded links is not written (its parameters are of the welded group); said in *notes.
std::vector<Repair> PlanWrites(const Model& model, const KinematicTree& tree,
                               const IdentifyResult& r, std::vector<std::string>* notes) {
  std::vector<Repair> repairs;
  for (int b = 0; b < tree.size(); ++b) {
    const MovingBody& body = tree.bodies[static_cast<std::size_t>(b)];
    bool unexcited = false;
    for (const std::string& l : r.unexcited_links) unexcited |= l == body.link;
    if (unexcited) continue;
    bool welded_mass = false;
    for (const std::string& w : body.welded_links) {
      const int i = model.FindLink(w);
      welded_mass |= i >= 0 && model.links[i].inertial && model.links[i].inertial->mass != 0;
    }
    if (welded_mass) {
      notes->push_back("link '" + body.link +
                       "' not written: its identified values include the links welded to it");
      continue;
    }
    const int i = model.FindLink(body.link);
    if (i < 0) continue;
    const Link& link = model.links[i];
    const BodyCentralProperties p =
        CentralPropertiesOf(r.bodies[static_cast<std::size_t>(b)].identified);
    Repair repair;
    repair.rule = "identify";
    repair.method = "identify";
    repair.link = link.name;
    repair.link_line = link.location.line;
    repair.before = link.inertial;
    repair.inserts_inertial = !link.inertial.has_value();
    repair.after =
        RoundedInertial(p, link.inertial ? link.inertial->X_BBi.R_AB : Eigen::Matrix3d::Identity());
    repair.why = "identified from the recorded torques (massprops identify)";
    FillRepairChanges(model, link, &repair);
    repairs.push_back(repair);
  }
  return repairs;
}

int WriteIdentified(const IdentifyArgs& args, const Model& model, const KinematicTree& tree,
                    const IdentifyResult& r) {
  std::ifstream in(args.robot, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  std::vector<std::string> notes;
  const std::vector<Repair> repairs = PlanWrites(model, tree, r, &notes);
  const PatchResult patched = PatchModelText(text.str(), model.format, repairs);
  for (const PatchError& e : patched.errors) {
    std::cerr << args.robot << ":" << e.line << ": error: link '" << e.link << "': " << e.message
              << "\n";
  }
  if (!patched.errors.empty()) return kExitError;
  const std::string out = args.in_place ? args.robot : args.write;
  if (auto error = WriteFileSafely(out, patched.text, &notes)) {
    std::cerr << "massprops: error: " << *error << "\n";
    return kExitError;
  }
  for (const std::string& n : notes) std::cerr << "massprops: note: " << n << "\n";
  std::cerr << "massprops: " << out << ": identified values of " << patched.applied
            << " link(s) written\n";
  return kExitOk;
}

// The bounding ellipsoid of each body's geometry (BodyBoundingEllipsoids), its meshes read as
// `check` reads them (--package-path, then the configuration's package-paths; the mesh cache
// kept between runs).
std::vector<std::optional<BoundingEllipsoid>> ReadBodyEllipsoids(const IdentifyArgs& args,
                                                                 const Model& model,
                                                                 const KinematicTree& tree) {
  static MeshCache cache;  // lives to the end of the run, when its entries are written
  static const bool persistent = [] {
    const std::string folder = DefaultMeshCacheFolder();
    if (!folder.empty()) cache.UsePersistentCache(folder);
    return true;
  }();
  (void)persistent;
  std::vector<std::string> package_paths = args.package_paths;
  try {
    package_paths = WithConfigPackagePaths(package_paths, model.file);
  } catch (const std::exception& e) {
    std::cerr << "massprops: warning: " << e.what() << " (its package-paths are not searched)\n";
  }
  const MeshResolveOptions resolve = MakeResolveOptions(package_paths, {}, model.file, &cache);
  return BodyBoundingEllipsoids(model, tree, MakeLinkPointsFunction(resolve));
}

// The model and its tree, or an error printed (false).
bool ReadRobot(const std::string& file, Model* model, std::optional<KinematicTree>* tree) {
  const ReadResult read = ReadModelFile(file);
  for (const ReadError& e : read.errors) std::cerr << e.ToString() << "\n";
  if (!read.ok() || read.models.empty()) {
    if (read.ok()) std::cerr << file << ": error: no model in the file\n";
    return false;
  }
  *model = read.models[0];
  KinematicTreeResult made = MakeKinematicTree(*model);
  if (!made.tree) {
    std::cerr << file << ": error: " << made.error << "\n";
    return false;
  }
  *tree = std::move(made.tree);
  return true;
}

int RunIdentify(const IdentifyArgs& args) {
  const bool writes = args.in_place || !args.write.empty();
  if (args.in_place && !args.write.empty()) {
    std::cerr << "massprops: error: --write and --in-place exclude each other\n";
    return kExitError;
  }
  if (!args.html.empty() && !IdentifyHtmlAvailable()) {
    std::cerr << "massprops: error: this massprops was built without Chart.js (Debian package "
                 "libjs-chart.js), which --html needs\n";
    return kExitError;
  }
  Model model;
  std::optional<KinematicTree> tree;
  if (!ReadRobot(args.robot, &model, &tree)) return kExitError;
  const TrajectoryReadResult log =
      IsRosbagPath(args.data) ? ReadTrajectoryRosbag(args.data) : ReadTrajectoryCsvFile(args.data);
  for (const ReadError& e : log.errors) std::cerr << e.ToString() << "\n";
  if (!log.ok()) return kExitError;
  for (const std::string& n : log.trajectory->notes)
    std::cerr << args.data << ": note: " << n << "\n";
  const OrderedTrajectory data = OrderTrajectory(*tree, *log.trajectory);
  if (!data.ok()) {
    std::cerr << args.data << ": error: " << data.error << "\n";
    return kExitError;
  }
  IdentifyOptions options;
  options.validation_fraction = args.validate;
  options.geometry_bound = !args.no_geometry;
  if (!args.no_geometry) options.ellipsoids = ReadBodyEllipsoids(args, model, *tree);
  IdentifyResult result;
  try {
    result = Identify(*tree, data, options);
  } catch (const std::invalid_argument& e) {
    std::cerr << args.data << ": error: " << e.what() << "\n";
    return kExitError;
  }
  if (args.format == "json") {
    WriteJson(*tree, result);
  } else {
    WriteText(args, *tree, result);
  }
  int code = writes ? WriteIdentified(args, model, *tree, result) : kExitOk;
  if (!args.html.empty()) {
    std::vector<std::string> notes;
    const std::string page =
        RenderIdentifyHtml(args.robot, args.data, *tree, data, options, result);
    if (auto error = WriteFileSafely(args.html, page, &notes)) {
      std::cerr << "massprops: error: " << *error << "\n";
      code = kExitError;
    }
    for (const std::string& n : notes) std::cerr << args.html << ": note: " << n << "\n";
  }
  return FinishStandardOutput(code);
}

}  // namespace

void AddIdentifyCommands(CLI::App& app, std::function<int()>* run) {
  auto args = std::make_shared<IdentifyArgs>();
  CLI::App* identify = app.add_subcommand(
      "identify",
      "Identify the mass properties that recorded joint torques prove (physically consistent, "
      "regularised toward the file's values): identifiability, torque error on held-out samples "
      "and each link before and after; --write or --in-place writes them into the URDF, SDF or "
      "MJCF file.");
  identify->add_option("ROBOT", args->robot, "The model (URDF, SDF or MJCF; fixed base)")
      ->required();
  identify
      ->add_option("DATA", args->data,
                   "The recording: CSV with time and, per joint J, J.q, J.tau (J.dq, J.ddq), or "
                   "PlotJuggler's CSV of /joint_states, or a rosbag2 folder or .db3 file "
                   "(sensor_msgs/msg/JointState)")
      ->required();
  identify
      ->add_option("--validate", args->validate,
                   "The last FRACTION of the samples is held out to judge the fit (default 0.3)")
      ->check(CLI::Range(0.0, 0.9));
  identify->add_option("--write", args->write,
                       "Write the identified values into OUT (same format as ROBOT)");
  identify->add_flag("--in-place", args->in_place, "Write the identified values into ROBOT");
  identify->add_option("--html", args->html,
                       "Also write an HTML page of the measured against the predicted torques "
                       "per joint (held-out samples; Chart.js embedded)");
  identify->add_flag("--no-geometry", args->no_geometry,
                     "Do not read the links' geometry: impose J ≻ 0 only, not the bounding "
                     "ellipsoid of each link's geometry");
  AddPackagePathOption(identify, &args->package_paths);
  identify->add_option("--format", args->format, "Output format")
      ->check(CLI::IsMember({"text", "json"}));
  identify->callback([args, run]() { *run = [args]() { return RunIdentify(*args); }; });
}

}  // namespace massprops::cli

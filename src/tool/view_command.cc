// `massprops view FILE -o model.html` and `massprops report --format html` (see docs/view.md):
// one self-contained HTML page that draws each link's collision geometry, its equivalent inertia
// box (or ellipsoid) at its center of mass along its principal axes, and its findings. The page
// is the template src/tool/view/view.html with its style, its script (src/tool/view/view.js,
// three.js r111 and OrbitControls from Debian's libjs-three, embedded at build time) and the
// model's numbers as one JSON block. Exit codes: 0 the page was written; 2 a file could not be read
// (the page is still written, with the error in it), a bad configuration file, or the page could
// not be written.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "commands.h"
#include "geometry_cli.h"
#include "html_text.h"
#include "massprops/analysis/checks.h"
#include "massprops/analysis/config.h"
#include "massprops/analysis/finding_text.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/analysis/mass_report.h"
#include "massprops/analysis/repair.h"
#include "massprops/analysis/welded_groups.h"
#include "massprops/io/model_reader.h"
#include "massprops/mesh/mesh_loader.h"
#include "massprops/output/reporters.h"
#include "view_assets.h"

namespace massprops::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kExitOk = 0;
constexpr int kExitError = 2;

// Meshes are decimated (vertex clustering) to at most this many triangles in all, shared evenly
// between the distinct (file, scale) meshes of the page, but never below kMinMeshTriangles or
// above kMaxMeshTriangles each: enough to recognise a part, small enough that a 200-link model
// opens in well under 2 s.
constexpr std::size_t kTriangleBudget = 200000;
constexpr std::size_t kMinMeshTriangles = 300;
constexpr std::size_t kMaxMeshTriangles = 4000;
// Mesh vertices are written as integers 0..kQuantization along each axis of the mesh's box.
constexpr int kQuantization = 4095;

struct ViewArgs {
  std::vector<std::string> files;
  std::string output = "-";
  std::vector<std::string> model_paths;
  std::vector<std::string> package_paths;
  std::string config;
};

json Vec(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

// Row-major 3x3.
json Mat(const Eigen::Matrix3d& m) {
  json out = json::array();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out.push_back(m(r, c));
  }
  return out;
}

json PoseJson(const Pose& X) { return {{"p", Vec(X.p_AB)}, {"R", Mat(X.R_AB)}}; }

// The sides of the uniform box with these principal moments (ascending) and mass: s_k =
// sqrt(6·(I_i + I_j − I_k)/m), a negative argument (no such box) giving 0.
Eigen::Vector3d BoxSides(double mass, const Eigen::Vector3d& moments) {
  Eigen::Vector3d sides;
  const double sum = moments.sum();
  for (int k = 0; k < 3; ++k) {
    sides[k] = std::sqrt(std::max(0.0, 6.0 * (sum - 2 * moments[k]) / mass));
  }
  return sides;
}

// The semi-axes of the uniform solid ellipsoid with these principal moments and mass:
// a_k² = 5·(I_i + I_j − I_k)/(2m) (from I_k = m·(a_i² + a_j²)/5).
Eigen::Vector3d EllipsoidSemiAxes(double mass, const Eigen::Vector3d& moments) {
  Eigen::Vector3d axes;
  const double sum = moments.sum();
  for (int k = 0; k < 3; ++k) {
    axes[k] = std::sqrt(std::max(0.0, 2.5 * (sum - 2 * moments[k]) / mass));
  }
  return axes;
}

// Vertex clustering: vertices are merged per cell of a grid over the mesh's box (each cluster at
// the mean of its vertices), triangles that collapse are dropped; the grid is coarsened until
// at most `target` triangles remain. A mesh at or under the target is returned as it is.
TriangleMesh Decimate(const TriangleMesh& mesh, std::size_t target) {
  if (mesh.triangles.size() <= target || mesh.vertices.empty()) return mesh;
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& v : mesh.vertices) box.extend(v);
  const double extent = std::max(box.sizes().maxCoeff(), 1e-12);
  int cells = std::max(2, static_cast<int>(std::sqrt(static_cast<double>(target) / 2)));
  TriangleMesh out;
  for (int attempt = 0; attempt < 12; ++attempt) {
    const double cell = extent / cells;
    const std::int64_t n = cells + 1;
    std::unordered_map<std::int64_t, std::int32_t> cluster_of_cell;
    std::vector<std::int32_t> cluster_of_vertex(mesh.vertices.size());
    std::vector<Eigen::Vector3d> sums;
    std::vector<int> counts;
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      const Eigen::Vector3d q = (mesh.vertices[i] - box.min()) / cell;
      auto index = [&](int k) {
        return std::clamp<std::int64_t>(static_cast<std::int64_t>(q[k]), 0, n - 1);
      };
      const std::int64_t key = (index(0) * n + index(1)) * n + index(2);
      auto [it, inserted] = cluster_of_cell.emplace(key, static_cast<std::int32_t>(sums.size()));
      if (inserted) {
        sums.push_back(Eigen::Vector3d::Zero());
        counts.push_back(0);
      }
      sums[it->second] += mesh.vertices[i];
      ++counts[it->second];
      cluster_of_vertex[i] = it->second;
    }
    out.vertices.resize(sums.size());
    for (std::size_t c = 0; c < sums.size(); ++c) out.vertices[c] = sums[c] / counts[c];
    out.triangles.clear();
    std::unordered_map<std::int64_t, bool> seen;
    const std::int64_t m = static_cast<std::int64_t>(sums.size());
    for (const auto& t : mesh.triangles) {
      std::array<std::int32_t, 3> c{};
      bool valid = true;
      for (int k = 0; k < 3; ++k) {
        if (t[k] < 0 || static_cast<std::size_t>(t[k]) >= mesh.vertices.size()) {
          valid = false;
          break;
        }
        c[k] = cluster_of_vertex[static_cast<std::size_t>(t[k])];
      }
      if (!valid || c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) continue;
      std::array<std::int64_t, 3> sorted{c[0], c[1], c[2]};
      std::sort(sorted.begin(), sorted.end());
      if (!seen.emplace((sorted[0] * m + sorted[1]) * m + sorted[2], true).second) continue;
      out.triangles.push_back(c);
    }
    if (out.triangles.size() <= target || cells <= 2) break;
    cells = std::max(2, static_cast<int>(cells * 0.75));
  }
  return out;
}

// A mesh as the page stores it: vertices quantized over the mesh's box, triangles as indices.
json MeshJson(const std::string& uri, const TriangleMesh& mesh, std::size_t original_triangles) {
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& v : mesh.vertices) box.extend(v);
  if (mesh.vertices.empty()) box.extend(Eigen::Vector3d::Zero());
  Eigen::Vector3d step = box.sizes() / kQuantization;
  for (int k = 0; k < 3; ++k) {
    if (!(step[k] > 0) || !std::isfinite(step[k])) step[k] = 1;
  }
  std::vector<int> q;
  q.reserve(mesh.vertices.size() * 3);
  for (const Eigen::Vector3d& v : mesh.vertices) {
    for (int k = 0; k < 3; ++k) {
      const double x = (v[k] - box.min()[k]) / step[k];
      q.push_back(std::isfinite(x)
                      ? static_cast<int>(std::clamp(std::lround(x), 0L, long{kQuantization}))
                      : 0);
    }
  }
  std::vector<std::int32_t> t;
  t.reserve(mesh.triangles.size() * 3);
  for (const auto& tri : mesh.triangles) t.insert(t.end(), tri.begin(), tri.end());
  return {{"uri", uri},
          {"min", Vec(box.min())},
          {"step", Vec(step)},
          {"q", q},
          {"t", t},
          {"triangles_in_file", original_triangles}};
}

// Meshes of the page, each (file, scale) loaded once and decimated once.
class MeshTable {
 public:
  // The index of the mesh in the page's table, or nullopt with *error set.
  std::optional<int> Add(const Geometry& geometry, const MeshResolveOptions& resolve,
                         std::string* error) {
    MeshResolveOptions where = resolve;
    const std::string& holder = geometry.location.file;
    if (!holder.empty() && holder != "-" && holder != "<stdin>") where.model_file = holder;
    const std::optional<std::string> path = ResolveMeshUri(geometry.uri, where, error);
    if (!path) return std::nullopt;
    if (!geometry.scale.allFinite()) {
      *error = "the scale is not finite";
      return std::nullopt;
    }
    const auto key = std::make_tuple(*path, geometry.submesh, geometry.center_submesh,
                                     geometry.scale.x(), geometry.scale.y(), geometry.scale.z());
    if (auto it = index_.find(key); it != index_.end()) return it->second;
    std::shared_ptr<const TriangleMesh> mesh = cache_.Load(*path, error, SubmeshOf(geometry));
    if (!mesh) return std::nullopt;
    const int index = static_cast<int>(meshes_.size());
    meshes_.push_back({geometry.uri, ScaleMesh(*mesh, geometry.scale)});
    index_.emplace(key, index);
    return index;
  }

  MeshCache* cache() { return &cache_; }

  // The table as JSON, decimated to the page's triangle budget.
  json ToJson() const {
    json out = json::array();
    const std::size_t per_mesh = meshes_.empty() ? kMaxMeshTriangles
                                                 : std::clamp(kTriangleBudget / meshes_.size(),
                                                              kMinMeshTriangles, kMaxMeshTriangles);
    for (const auto& [uri, mesh] : meshes_) {
      out.push_back(MeshJson(uri, Decimate(mesh, per_mesh), mesh.triangles.size()));
    }
    return out;
  }

 private:
  MeshCache cache_;
  std::map<std::tuple<std::string, std::string, bool, double, double, double>, int> index_;
  std::vector<std::pair<std::string, TriangleMesh>> meshes_;
};

// A finding in the words `check` prints: its headline, evidence and help (finding_text.h), and
// the full reasoning as "message".
json FindingJson(const Finding& finding) {
  return {{"rule", finding.rule},
          {"severity", ToString(finding.severity)},
          {"headline", HeadlineOf(finding)},
          {"evidence", FormatEvidence(finding.evidence)},
          {"help", finding.help},
          {"message", finding.message},
          {"file", finding.location.file},
          {"line", finding.location.line},
          {"fixed_by_repair", finding.repair.has_value()}};
}

json GeometryJson(const Geometry& geometry, const Pose& X_WB, const MeshResolveOptions& resolve,
                  MeshTable* meshes) {
  json out = {{"collision", geometry.is_collision},
              {"pose", PoseJson(X_WB * geometry.X_BG)},
              {"line", geometry.location.line}};
  switch (geometry.type) {
    case Geometry::Type::kBox:
      out["type"] = "box";
      out["size"] = Vec(geometry.size);
      break;
    case Geometry::Type::kCylinder:
      out["type"] = "cylinder";
      out["radius"] = geometry.radius;
      out["length"] = geometry.length;
      break;
    case Geometry::Type::kSphere:
      out["type"] = "sphere";
      out["radius"] = geometry.radius;
      break;
    case Geometry::Type::kCapsule:
      out["type"] = "capsule";
      out["radius"] = geometry.radius;
      out["length"] = geometry.length;
      break;
    case Geometry::Type::kEllipsoid:
      out["type"] = "ellipsoid";
      out["radii"] = Vec(geometry.radii);
      break;
    case Geometry::Type::kMesh: {
      out["type"] = "mesh";
      out["uri"] = geometry.uri;
      std::string error;
      if (const std::optional<int> index = meshes->Add(geometry, resolve, &error)) {
        out["mesh"] = *index;
      } else {
        out["error"] = error;
      }
      break;
    }
    case Geometry::Type::kOther:
      out["type"] = "other";
      break;
  }
  return out;
}

// The numbers of one body for the page (a link or a welded group): mass, center of mass and
// principal axes in the model frame W (the root link's frame), principal moments, the
// equivalent box and ellipsoid.
void AddBodyJson(const BodyMassProperties& body, const Pose& X_WF, json* out) {
  (*out)["mass"] = body.mass;
  (*out)["com"] = Vec(X_WF.p_AB + X_WF.R_AB * body.com);
  (*out)["principal_moments"] = Vec(body.principal_moments);
  (*out)["axes"] = Mat(X_WF.R_AB * body.principal_axes);
  (*out)["inertia_about_com"] = Mat(body.inertia_about_com);
  const bool drawn =
      body.mass > 0 && std::isfinite(body.mass) && body.principal_moments.allFinite();
  (*out)["box_exists"] = body.equivalent_box.has_value();
  if (drawn) {
    (*out)["box"] = Vec(body.equivalent_box ? *body.equivalent_box
                                            : BoxSides(body.mass, body.principal_moments));
    (*out)["ellipsoid"] = Vec(EllipsoidSemiAxes(body.mass, body.principal_moments));
  } else {
    (*out)["box"] = nullptr;
    (*out)["ellipsoid"] = nullptr;
  }
}

struct Settings {
  CheckOptions options;
  std::vector<std::string> model_paths;
  std::vector<std::string> package_paths;  // the configuration's (after --package-path)
};

// The check options of a file, as `massprops check` takes them: --config, else the nearest
// .massprops.toml upward. Throws ConfigError.
Settings SettingsFor(const ViewArgs& args, const std::string& file) {
  Settings settings;
  std::optional<Config> config;
  if (!args.config.empty()) {
    config = LoadConfig(args.config);
  } else {
    if (const std::optional<std::string> path = FindConfigFor(file)) config = LoadConfig(*path);
  }
  if (config) {
    ApplyConfig(*config, settings.options);
    settings.model_paths = config->model_paths;
    settings.package_paths = config->package_paths;
  }
  settings.model_paths.insert(settings.model_paths.begin(), args.model_paths.begin(),
                              args.model_paths.end());
  return settings;
}

// Appends to *findings those `massprops check` gives (`options`), and returns the repairs
// `massprops fix` plans with its default options. Both read the meshes' bounding boxes, as the
// tool does by default.
std::vector<Repair> CheckAndPlan(const Model& model, const CheckOptions& options,
                                 const MeshResolveOptions& resolve,
                                 std::vector<Finding>* findings) {
  CheckOptions check_options = options;
  check_options.box = MakeLinkBoxFunction(resolve);
  check_options.points = MakeLinkPointsFunction(resolve);
  const std::vector<Finding> checked = CheckModel(model, check_options);
  findings->insert(findings->end(), checked.begin(), checked.end());
  RepairOptions repair_options;
  repair_options.box = check_options.box;
  repair_options.points = check_options.points;
  CheckOptions fix_check;  // fix's checks: the default options, and the boxes
  fix_check.box = check_options.box;
  fix_check.points = check_options.points;
  return PlanRepairs(model, CheckModel(model, fix_check), repair_options);
}

json ModelJson(const Model& model, const std::vector<Finding>& reader_findings,
               const Settings& settings, const ViewArgs& args, MeshTable* meshes) {
  std::vector<std::string> package_paths = args.package_paths;
  package_paths.insert(package_paths.end(), settings.package_paths.begin(),
                       settings.package_paths.end());
  const MeshResolveOptions resolve =
      MakeResolveOptions(package_paths, settings.model_paths, model.file, meshes->cache());
  std::vector<Finding> findings = reader_findings;
  const std::vector<Repair> repairs = CheckAndPlan(model, settings.options, resolve, &findings);
  AttachRepairs(repairs, findings);
  std::map<std::string, const Repair*> repair_of_link;
  for (const Repair& repair : repairs) repair_of_link.emplace(repair.link, &repair);

  std::vector<bool> reachable;
  const std::vector<Pose> X_WB = CalcLinkPosesInRootFrame(model, &reachable);

  json links = json::array();
  std::map<std::string, std::size_t> link_index;
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const Link& link = model.links[i];
    link_index.emplace(link.name, i);
    const MassProperties mp = LinkMassProperties(link, model.format);
    const BodyMassProperties body =
        MakeBodyMassProperties(link.name, mp.mass, mp.p_FoScm_F, mp.I_SScm_F);
    json entry = {{"name", link.name},
                  {"line", link.location.line},
                  {"file", link.location.file},
                  {"reachable", static_cast<bool>(reachable[i])},
                  {"has_inertial", link.inertial.has_value()},
                  {"pose", PoseJson(X_WB[i])},
                  {"com_link", Vec(body.com)},
                  {"findings", json::array()},
                  {"repair", nullptr},
                  {"geometry", json::array()}};
    AddBodyJson(body, X_WB[i], &entry);
    if (auto it = repair_of_link.find(link.name); it != repair_of_link.end()) {
      entry["repair"] = DescribeRepair(*it->second);
    }
    // Collision geometry, or the visual geometry of a link that has no collision.
    const bool has_collision = std::any_of(link.geometries.begin(), link.geometries.end(),
                                           [](const Geometry& g) { return g.is_collision; });
    for (const Geometry& geometry : link.geometries) {
      if (geometry.is_collision != has_collision) continue;
      entry["geometry"].push_back(GeometryJson(geometry, X_WB[i], resolve, meshes));
    }
    links.push_back(std::move(entry));
  }

  json model_findings = json::array();
  for (const Finding& finding : findings) {
    auto it = link_index.find(finding.link);
    if (finding.link.empty() || it == link_index.end()) {
      model_findings.push_back(FindingJson(finding));
    } else {
      links[it->second]["findings"].push_back(FindingJson(finding));
    }
  }

  json groups = json::array();
  for (const WeldedGroup& group : FindWeldedGroups(model)) {
    if (group.links.size() < 2) continue;
    const CompositeInertia composite = CalcCompositeInertia(model, group);
    const int root = group.links.front();
    const BodyMassProperties body = MakeBodyMassProperties(model.links[root].name, composite.mass,
                                                           composite.p_RoScm_R, composite.I_SScm_R);
    json entry = {{"root", model.links[root].name}, {"links", json::array()}};
    for (int member : group.links) entry["links"].push_back(model.links[member].name);
    AddBodyJson(body, X_WB[root], &entry);
    groups.push_back(std::move(entry));
  }

  const ModelCompositeInertia total = CalcModelCompositeInertia(model);
  json unreachable = json::array();
  for (int i : total.unreachable_links) unreachable.push_back(model.links[i].name);
  const BodyMassProperties total_body = MakeBodyMassProperties(
      model.root_link, total.inertia.mass, total.inertia.p_RoScm_R, total.inertia.I_SScm_R);
  json total_json = json::object();
  AddBodyJson(total_body, Pose{}, &total_json);

  return {{"name", model.name},
          {"file", model.file},
          {"format", ToString(model.format)},
          {"root_link", model.root_link},
          {"static", model.is_static},
          {"links", std::move(links)},
          {"groups", std::move(groups)},
          {"total", std::move(total_json)},
          {"unreachable_links", std::move(unreachable)},
          {"findings", std::move(model_findings)}};
}

// The template with each {{NAME}} replaced once by its text (inserted text is not scanned again).
std::string FillTemplate(std::string_view page, const std::map<std::string, std::string>& parts) {
  std::string out;
  std::size_t pos = 0;
  while (true) {
    const std::size_t open = page.find("{{", pos);
    if (open == std::string_view::npos) break;
    const std::size_t close = page.find("}}", open);
    if (close == std::string_view::npos) break;
    const auto it = parts.find(std::string(page.substr(open + 2, close - open - 2)));
    if (it == parts.end()) {
      out.append(page.substr(pos, close + 2 - pos));
    } else {
      out.append(page.substr(pos, open - pos));
      out += it->second;
    }
    pos = close + 2;
  }
  out.append(page.substr(pos));
  return out;
}

// Writes `text` to `path` ("-": standard output) through a temporary file renamed over it.
bool WriteOutput(const std::string& path, const std::string& text) {
  if (path == "-") {
    std::cout << text;
    std::cout.flush();
    return static_cast<bool>(std::cout);
  }
  const fs::path tmp = path + ".massprops-tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) {
      std::cerr << "massprops: error: cannot write " << tmp.string() << "\n";
      std::error_code ec;
      fs::remove(tmp, ec);
      return false;
    }
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    std::cerr << "massprops: error: cannot write " << path << ": " << ec.message() << "\n";
    fs::remove(tmp, ec);
    return false;
  }
  return true;
}

int RunView(const ViewArgs& args) {
  if (embedded::kThreeJsSize == 0) {
    std::cerr << "massprops: error: this massprops was built without three.js (Debian package "
                 "libjs-three), which the HTML view needs\n";
    return kExitError;
  }
  MeshTable meshes;
  json models = json::array();
  json errors = json::array();
  bool failed = false;
  for (const std::string& file : args.files) {
    const Settings settings = SettingsFor(args, file);
    ReadOptions read_options;
    read_options.sdf.model_paths = settings.model_paths;
    const ReadResult read = ReadModelFile(file, read_options);
    for (const ReadError& e : read.errors) {
      failed = true;
      errors.push_back({{"file", e.location.file},
                        {"line", e.location.line},
                        {"headline", ReadErrorHeadline(e)},
                        {"message", ReadErrorText(e)}});
      std::cerr << e.ToString() << "\n";
    }
    std::vector<Finding> reader_findings;
    for (const ReadError& warning : read.warnings) {
      reader_findings.push_back(ReadWarningFinding(warning));
    }
    for (Finding& finding : ReaderFindings(read, settings.options)) {
      reader_findings.push_back(std::move(finding));
    }
    for (const Model& model : read.models) {
      std::vector<Finding> own;
      for (const Finding& finding : reader_findings) {
        if (finding.model.empty() || finding.model == model.name) own.push_back(finding);
      }
      models.push_back(ModelJson(model, own, settings, args, &meshes));
    }
  }
  const json data = {{"generator", std::string("massprops ") + MASSPROPS_VERSION},
                     {"models", std::move(models)},
                     {"meshes", meshes.ToJson()},
                     {"errors", std::move(errors)}};
  // '<' only occurs inside JSON strings; escaped, no "</script" can end the data block early.
  std::string data_text = data.dump(-1, ' ', false, json::error_handler_t::replace);
  std::string escaped;
  escaped.reserve(data_text.size());
  for (const char c : data_text) {
    if (c == '<') {
      escaped += "\\u003c";
    } else {
      escaped += c;
    }
  }
  std::string title = "massprops";
  if (args.files.size() == 1) title += ": " + fs::path(args.files.front()).filename().string();
  std::string script;
  script += embedded::AsText(embedded::kThreeJs, embedded::kThreeJsSize);
  script += "\n";
  script += embedded::AsText(embedded::kOrbitControlsJs, embedded::kOrbitControlsJsSize);
  script += "\n";
  script += embedded::AsText(embedded::kViewJs, embedded::kViewJsSize);
  script = ScriptElementText(std::move(script));
  const std::string page = FillTemplate(
      embedded::AsText(embedded::kViewHtml, embedded::kViewHtmlSize),
      {{"TITLE", EscapeHtml(title)},
       {"CSS", std::string(embedded::AsText(embedded::kViewCss, embedded::kViewCssSize))},
       {"DATA", escaped},
       {"SCRIPT", script}});
  if (!WriteOutput(args.output, page)) return kExitError;
  return failed ? kExitError : kExitOk;
}

}  // namespace

int RunHtmlView(const std::vector<std::string>& files, const std::vector<std::string>& model_paths,
                const std::vector<std::string>& package_paths) {
  ViewArgs args;
  args.files = files;
  args.model_paths = model_paths;
  args.package_paths = package_paths;
  try {
    return RunView(args);
  } catch (const ConfigError& error) {
    std::cerr << error.what() << "\n";
    return kExitError;
  }
}

void AddViewCommands(CLI::App& app, std::function<int()>* run) {
  auto args = std::make_shared<ViewArgs>();
  CLI::App* view = app.add_subcommand(
      "view",
      "Write one self-contained HTML page (no network needed) that draws each link's geometry, "
      "its equivalent inertia box or ellipsoid at its center of mass, and its findings.");
  view->add_option("FILE", args->files, "URDF, SDF or MJCF files (detected by content), or '-'")
      ->required();
  view->add_option("-o,--output", args->output, "The HTML file to write ('-': standard output)")
      ->type_name("OUT")
      ->capture_default_str();
  view->add_option("--config", args->config,
                   "Configuration file for the findings (default: the nearest .massprops.toml)")
      ->type_name("TOML");
  view->add_option("--model-path", args->model_paths, "Folder searched for SDF model:// URIs")
      ->type_name("DIR")
      ->allow_extra_args(false);
  AddPackagePathOption(view, &args->package_paths);
  view->callback([run, args] {
    *run = [args] {
      try {
        return RunView(*args);
      } catch (const ConfigError& error) {
        std::cerr << error.what() << "\n";
        return kExitError;
      }
    };
  });
}

}  // namespace massprops::cli

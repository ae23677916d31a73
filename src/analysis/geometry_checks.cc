#include "massprops/analysis/geometry_checks.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include "massprops/analysis/finding_text.h"
#include "massprops/analysis/mass_report.h"

namespace massprops {
namespace {

// The severity of `rule` after overrides, or nullopt when it is disabled.
std::optional<Severity> EffectiveSeverity(const std::string& rule, const CheckOptions& options) {
  const auto it = options.overrides.find(rule);
  if (it != options.overrides.end()) return it->second;
  return Severity::kWarning;
}

bool IgnoredOnLink(const Link& link, const std::string& rule) {
  return std::any_of(link.ignored_rules.begin(), link.ignored_rules.end(),
                     [&](const std::string& id) { return id == rule || id == "all"; });
}

std::string Format(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.4g", value);
  return buffer;
}

// A mesh geometry's unit-density mass properties in the link frame, from the cache's
// MassProperties alone (no bounding box: the mesh's vertices are not loaded a second time).
std::optional<GeometryMassProperties> ClosedMeshOf(const Geometry& geometry,
                                                   const MeshResolveOptions& options) {
  if (options.cache == nullptr) return CalcGeometryMassProperties(geometry, options, nullptr);
  MeshResolveOptions where = options;
  const std::string& holder = geometry.location.file;
  if (!holder.empty() && holder != "-" && holder != "<stdin>") where.model_file = holder;
  std::string error;
  const std::optional<std::string> path = options.cache->Resolve(geometry.uri, where, &error);
  if (!path || !geometry.scale.allFinite()) return std::nullopt;
  const std::optional<MeshMassProperties> mesh = options.cache->MassProperties(
      *path, geometry.scale, options.inertia, &error, SubmeshOf(geometry));
  if (!mesh) return std::nullopt;
  GeometryMassProperties result;
  result.volume = mesh->volume;
  result.p_BoGcm_B = geometry.X_BG.p_AB + geometry.X_BG.R_AB * mesh->p_GoGcm_G;
  result.I_GGcm_B = mesh->I_GGcm_G.ReExpress(geometry.X_BG.R_AB);
  result.mesh_path = *path;
  result.mesh_diagnostics = mesh->diagnostics;
  return result;
}

}  // namespace

LinkShapeFunction MakeLinkShapeFunction(const MeshResolveOptions& resolve) {
  return [resolve](const Link& link) -> std::optional<LinkShape> {
    std::optional<LinkGeometryInertia> g = CalcLinkGeometryInertia(link, 1.0, resolve, nullptr);
    if (!g || !(g->volume > 0) || !std::isfinite(g->volume) || g->box_B.isEmpty()) {
      return std::nullopt;
    }
    LinkShape shape;
    shape.from_collision = g->from_collision;
    shape.box_B = g->box_B;
    shape.volume = g->volume;
    shape.p_BoBcm_B = g->p_BoBcm_B;
    shape.G_BBcm_B = g->I_BBcm_B.CopyToFullMatrix3();
    shape.kind = "primitive";
    for (const GeometryMassProperties& part : g->geometries) {
      if (!part.mesh_path.empty()) shape.kind = "mesh";
    }
    if (!shape.G_BBcm_B.allFinite() || !shape.p_BoBcm_B.allFinite()) return std::nullopt;
    return shape;
  };
}

LinkBoxFunction MakeLinkBoxFunction(const MeshResolveOptions& resolve) {
  return [resolve](const Link& link) -> std::optional<LinkGeometryBox> {
    if (link.geometries.empty()) return std::nullopt;
    LinkGeometryBox result;
    for (const Geometry& geometry : link.geometries) {
      std::string error;
      const std::optional<Eigen::AlignedBox3d> box = CalcGeometryBounds(geometry, resolve, &error);
      if (!box || box->isEmpty()) {
        ++result.unknown;
        if (geometry.type == Geometry::Type::kMesh && result.unresolved_uri.empty()) {
          // An MJCF mesh written inline (vertex and face) or a URDF filename="" has none.
          result.unresolved_uri = geometry.uri.empty() ? "(no filename)" : geometry.uri;
          result.unresolved_reason = error;
        }
        continue;
      }
      result.box_B.extend(*box);
      ++result.known;
      if (geometry.type == Geometry::Type::kMesh) ++result.meshes;
      if (geometry.is_collision) result.from_collision = true;
    }
    return result;
  };
}

LinkPointsFunction MakeLinkPointsFunction(const MeshResolveOptions& resolve) {
  return [resolve](const Link& link) -> std::optional<LinkGeometryPoints> {
    if (link.geometries.empty()) return std::nullopt;
    LinkGeometryPoints result;
    std::vector<std::pair<const Geometry*, std::shared_ptr<const MeshPoints>>> meshes;
    for (const Geometry& geometry : link.geometries) {
      if (geometry.type != Geometry::Type::kMesh) {
        const std::optional<Eigen::AlignedBox3d> box =
            CalcGeometryBounds(geometry, resolve, nullptr);
        if (!box || box->isEmpty()) {
          ++result.unknown;
          continue;
        }
        for (int corner = 0; corner < 8; ++corner) {
          result.corners_B.push_back(
              box->corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)));
        }
        result.count += 8;
        continue;
      }
      // The resolved file (CalcGeometryMassProperties resolves it as every other reader does,
      // included SDF files relative to their own file), then its vertices, scaled and posed.
      // Where it succeeds modelling an open mesh as a thin shell, it succeeds with its convex hull
      // too (the hull's last fallback is that shell): the hull (qhull) is computed only when the
      // shell fails, so that the same geometries are used as before at a fraction of the cost.
      std::string error;
      std::optional<GeometryMassProperties> props;
      if (resolve.inertia.open_mesh_model == MeshSolidModel::kConvexHull) {
        MeshResolveOptions shell = resolve;
        shell.inertia.open_mesh_model = MeshSolidModel::kThinShell;
        props = CalcGeometryMassProperties(geometry, shell, &error);
      }
      if (!props) props = CalcGeometryMassProperties(geometry, resolve, &error);
      std::shared_ptr<const MeshPoints> points;
      if (props && !props->mesh_path.empty()) {
        if (resolve.cache != nullptr) {
          points = resolve.cache->Points(props->mesh_path, &error, SubmeshOf(geometry));
        } else {
          TriangleMesh loaded;
          if (LoadMeshSubmesh(props->mesh_path, SubmeshOf(geometry), &loaded, &error)) {
            auto all = std::make_shared<MeshPoints>();
            all->positions = std::move(loaded.vertices);
            all->loader_vertices = static_cast<std::int64_t>(all->positions.size());
            points = std::move(all);
          }
        }
      }
      if (!points || points->positions.empty()) {
        ++result.unknown;
        continue;
      }
      meshes.emplace_back(&geometry, std::move(points));
    }
    // The meshes' positions, shared with the cache: scaled and posed as they are visited.
    for (const auto& [geometry, points] : meshes) {
      result.posed.push_back(
          {std::shared_ptr<const std::vector<Eigen::Vector3d>>(points, &points->positions),
           geometry->scale, geometry->X_BG});
      result.count += static_cast<std::size_t>(points->loader_vertices);
      ++result.meshes;
    }
    return result;
  };
}

// The options of MakeClosedMeshShapeFunction: an open mesh is refused, so no convex hull
// (qhull) is computed for it; STL without assimp.
MeshResolveOptions ClosedMeshOptions(const MeshResolveOptions& resolve) {
  MeshResolveOptions closed = resolve;
  closed.inertia.open_mesh_model = MeshSolidModel::kClosedSolid;
  closed.inertia.read_stl_directly = true;
  return closed;
}

LinkShapeFunction MakeClosedMeshShapeFunction(const MeshResolveOptions& resolve) {
  const MeshResolveOptions closed = ClosedMeshOptions(resolve);
  return [closed](const Link& link) -> std::optional<LinkShape> {
    for (const bool collision : {false, true}) {
      std::vector<GeometryMassProperties> parts;
      bool usable = true;
      for (const Geometry& geometry : link.geometries) {
        if (geometry.is_collision != collision) continue;
        if (geometry.type != Geometry::Type::kMesh) {
          usable = false;
          break;
        }
        std::optional<GeometryMassProperties> part = ClosedMeshOf(geometry, closed);
        // Watertight: a closed manifold, or a surface that encloses its volume despite
        // T-junctions or cracks of no area (its integral does not depend on the reference point),
        // as CAD exports' STL files are (every mesh of TheRobotStudio/SO-ARM100's raw export).
        const bool watertight = part && part->mesh_diagnostics &&
                                (part->mesh_diagnostics->IsClosedManifold() ||
                                 part->mesh_diagnostics->reference_point_sensitivity <=
                                     closed.inertia.closure_tolerance);
        if (!watertight || !(part->volume > 0) || !std::isfinite(part->volume)) {
          usable = false;
          break;
        }
        parts.push_back(std::move(*part));
      }
      if (!usable || parts.empty()) continue;
      LinkShape shape;
      shape.from_collision = collision;
      shape.kind = "mesh";
      Eigen::Vector3d moment = Eigen::Vector3d::Zero();
      for (const GeometryMassProperties& part : parts) {
        shape.volume += part.volume;
        moment += part.volume * part.p_BoGcm_B;
      }
      shape.p_BoBcm_B = moment / shape.volume;
      Eigen::Matrix3d I = Eigen::Matrix3d::Zero();  // at density 1: mass = volume
      for (const GeometryMassProperties& part : parts) {
        const Eigen::Vector3d d = part.p_BoGcm_B - shape.p_BoBcm_B;
        I += part.I_GGcm_B.CopyToFullMatrix3() +
             part.volume * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
      }
      shape.G_BBcm_B = I / shape.volume;
      if (!shape.G_BBcm_B.allFinite() || !shape.p_BoBcm_B.allFinite()) return std::nullopt;
      return shape;
    }
    return std::nullopt;
  };
}

void PrefetchModelMeshes(const Model& model, const MeshResolveOptions& resolve, int threads) {
  if (resolve.cache == nullptr || threads < 2) return;
  const MeshResolveOptions closed = ClosedMeshOptions(resolve);
  // Each distinct (file, part, scale), in model order.
  struct Work {
    std::string path;
    MeshSubmesh submesh;
    Eigen::Vector3d scale;
  };
  std::vector<Work> work;
  std::set<std::tuple<std::string, std::string, bool, double, double, double>> seen;
  std::set<std::string> files;
  for (const Link& link : model.links) {
    for (const Geometry& geometry : link.geometries) {
      if (geometry.type != Geometry::Type::kMesh || !geometry.scale.allFinite()) continue;
      const std::optional<std::string> path = ResolveGeometryMeshUri(geometry, resolve, nullptr);
      const Eigen::Vector3d& s = geometry.scale;
      if (!path ||
          !seen.insert({*path, geometry.submesh, geometry.center_submesh, s.x(), s.y(), s.z()})
               .second) {
        continue;
      }
      work.push_back({*path, SubmeshOf(geometry), s});
      files.insert(*path);
    }
  }
  if (files.size() < 2) return;
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < work.size(); i = next++) {
      std::string error;
      resolve.cache->Bounds(work[i].path, &error, work[i].submesh);
      resolve.cache->MassProperties(work[i].path, work[i].scale, closed.inertia, &error,
                                    work[i].submesh);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads && static_cast<std::size_t>(t) < work.size(); ++t) {
    pool.emplace_back(worker);
  }
  worker();
  for (std::thread& thread : pool) thread.join();
}

const std::vector<RuleInfo>& GeometryRules() {
  static const std::vector<RuleInfo> rules = {
      {kInertiaDisagreesWithGeometryRule, Severity::kWarning, false,
       "the declared principal moments differ from those the link's geometry implies for its "
       "mass by more than --geometry-factor (default 2x); needs --geometry"},
      {kMeshUnreadableRule, Severity::kWarning, false,
       "a mesh the link references cannot be found or read; needs --geometry"},
  };
  return rules;
}

std::vector<Finding> CheckModelGeometry(const Model& model, const GeometryCheckOptions& options) {
  std::vector<Finding> findings;
  if (!options.enabled) return findings;
  const std::optional<Severity> disagree_severity =
      EffectiveSeverity(kInertiaDisagreesWithGeometryRule, options.check);
  const std::optional<Severity> unreadable_severity =
      EffectiveSeverity(kMeshUnreadableRule, options.check);
  MeshResolveOptions resolve = options.resolve;
  resolve.model_file = model.file;
  for (const Link& link : model.links) {
    if (link.geometries.empty()) continue;
    // mesh-unreadable: every mesh of the link, collision or visual.
    if (unreadable_severity && !IgnoredOnLink(link, kMeshUnreadableRule)) {
      for (const Geometry& geometry : link.geometries) {
        if (geometry.type != Geometry::Type::kMesh) continue;
        std::string error;
        if (CalcGeometryMassProperties(geometry, resolve, &error)) continue;
        Finding finding;
        finding.rule = kMeshUnreadableRule;
        finding.severity = *unreadable_severity;
        finding.model = model.name;
        finding.link = link.name;
        finding.location = geometry.location;
        finding.message = "link '" + link.name + "': mesh '" + geometry.uri +
                          "' cannot be used: " + (error.empty() ? "unknown error" : error);
        // The reason is the error's last clause ("collision at line 7 (mesh 'u'): mesh 'u': it
        // leaves the package folder"): the headline names it, the rest is under --explain.
        const std::size_t clause = error.rfind("': ");
        const std::string why = error.empty()                 ? "unknown error"
                                : clause == std::string::npos ? error
                                                              : error.substr(clause + 3);
        // Whole, or its lead without the most specific details, or a short sentence.
        const std::string whole = LinkHeadline(link.name, ": mesh cannot be used: " + why);
        const std::string lead =
            LongestLeadThatFits("link '" + link.name + "': mesh cannot be used: " + why + ": ");
        finding.headline =
            CountChars(whole) <= kMaxHeadlineChars ? whole
            : lead.size() > link.name.size() + 30
                ? lead
                : LinkHeadline(link.name, ": a mesh cannot be used (--explain says why)");
        finding.help =
            "fix the mesh file or its URI (--package-path DIR); the whole error is under "
            "--explain";
        findings.push_back(std::move(finding));
      }
    }
    // inertia-disagrees-with-geometry.
    if (!disagree_severity || IgnoredOnLink(link, kInertiaDisagreesWithGeometryRule)) continue;
    if (!link.inertial || !(link.inertial->mass > 0)) continue;
    const LinkGeometryComparison comparison = CompareLinkWithGeometry(link, resolve);
    if (!comparison.error.empty()) continue;
    double worst = 1;
    int worst_k = -1;
    const Eigen::Vector3d& declared = comparison.declared_moments;
    for (int k = 0; k < 3; ++k) {
      const double g = comparison.geometry.principal_moments(k);
      const double d = declared(k);
      double ratio;
      if (g > 0 && d > 0) {
        ratio = std::max(d / g, g / d);
      } else if (g == 0 && d == 0) {
        ratio = 1;
      } else {
        ratio = HUGE_VAL;
      }
      if (ratio > worst) {
        worst = ratio;
        worst_k = k;
      }
    }
    if (!(worst > options.factor) || worst_k < 0) continue;
    const double g = comparison.geometry.principal_moments(worst_k);
    Finding finding;
    finding.rule = kInertiaDisagreesWithGeometryRule;
    finding.severity = *disagree_severity;
    finding.model = model.name;
    finding.link = link.name;
    finding.location = link.inertial->inertia_location.line > 0 ? link.inertial->inertia_location
                                                                : link.inertial->location;
    finding.message = "link '" + link.name + "': principal moment " + std::to_string(worst_k + 1) +
                      " of the declared inertia is " + Format(declared(worst_k)) +
                      " kg m^2, but its " + (comparison.from_collision ? "collision" : "visual") +
                      " geometry implies " + Format(g) + " kg m^2 for mass " +
                      Format(link.inertial->mass) + " kg (a factor " + Format(worst) +
                      ", more than " + Format(options.factor) + ")";
    for (const LinkGeometryComparison::Mesh& mesh : comparison.meshes) {
      const std::string note = DescribeMeshDiagnostics(mesh.diagnostics);
      if (!note.empty()) finding.message += "; mesh '" + mesh.uri + "': " + note;
    }
    finding.values = {{"mass", link.inertial->mass},
                      {"declared_moment", declared(worst_k)},
                      {"geometry_moment", g},
                      {"factor", worst}};
    finding.headline = LinkHeadline(
        link.name, ": inertia " + FormatRatio(worst) + " off that of its " +
                       (comparison.from_collision ? "collision" : "visual") +
                       " geometry (principal moment " + std::to_string(worst_k + 1) + ")");
    finding.evidence = {{"mass_kg", link.inertial->mass},
                        {"declared_moment_kg_m2", declared(worst_k)},
                        {"geometry_moment_kg_m2", g},
                        {"ratio", worst}};
    finding.help = "recompute the inertia from the geometry: massprops fix --from-geometry";
    findings.push_back(std::move(finding));
  }
  return findings;
}

}  // namespace massprops

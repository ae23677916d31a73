// inertia-exceeds-model (warning): a link's inertia that no body inside the whole model can have.
//
// Evidence: every link's geometry (primitives, and meshes by their boxes through options.box) posed
// in the frame of its tree's root at the zero configuration; the link's mass, center of mass and
// inertia.
// Why: every point of the link's body lies within the model, so within the distance R from its
// center of mass c to the farthest point of the model's geometry; then
// tr(I)/2 = ∫|x − c|² dm <= m·R², and its radius of gyration k = sqrt(tr(I)/(2m)) is at most R.
// Every link is judged, where no other rule already finds its inertia too large: a link without
// geometry (judged elsewhere by units-suspect's five times the kinematic span) and a link whose
// own geometry spans most of the vehicle (judged by inertia-exceeds-geometry with twice its
// half-diagonal for simplified geometry) are both bounded by the whole model: k beyond
// kModelRatio times R is reported (a drone base with k = 0.49 m on a vehicle whose arms and
// motors all lie within 0.3 m of it; the model may be drawn smaller than the machine, not by
// half again in every direction). Only where the model's extent is known: no geometry of
// unknown size, and every welded group with mass drawn by some geometry.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

#include "analysis/rules/farthest_point.h"
#include "analysis/rules/model_rules.h"
#include "analysis/rules/rules.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kInertiaExceedsModel = "inertia-exceeds-model";

// k beyond this many times the model's reach from the center of mass is reported (a body inside
// it has k <= 1 times; the margin allows for a model drawn a little smaller than the machine, as
// the copied placeholders of units-suspect allow their assembly).
constexpr double kModelRatio = 1.5;

// The links whose inertia a finding already says is too large: one finding per defect. Taken
// once, before this rule emits (an index, not a scan of the findings per link).
// Names are copied: the findings vector grows while this rule emits, and a view into a moved
// short string would dangle.
std::unordered_set<std::string> AlreadyTooLarge(const RuleContext& ctx) {
  std::unordered_set<std::string> links;
  for (const Finding& f : ctx.findings) {
    if (f.rule == "units-suspect" || f.rule == "inertia-exceeds-geometry" ||
        f.rule == "inertia-about-origin-suspect" || f.rule == "inertia-not-physical") {
      links.insert(f.link);
    }
  }
  return links;
}

// Whether link l draws a body: geometry of known size, larger than a placeholder, and not a
// visual-only marker (a 1 cm box that shows where a frame is, not how far its body reaches).
bool Drawn(const RuleContext& ctx, int l) {
  if (ctx.model.links[l].geometries.empty()) return false;
  const std::optional<GeometryBounds>& b = ctx.BoundsOfLink(l);
  if (!b || b->partial || b->box_B.isEmpty()) return false;
  const double half_diagonal = 0.5 * b->box_B.diagonal().norm();
  return half_diagonal >= kPlaceholderHalfDiagonal &&
         (b->from_collision || half_diagonal >= kMarkerHalfDiagonal);
}

// The corners of every link's known geometry in the frame of the tree's root, per root; a root
// whose tree has geometry of unknown size, or a welded group with mass and no geometry of known
// size, gets none (its extent is not known). Each root's corners as a FarthestPointIndex (built
// once per tree: every link of the tree asks it for its reach).
std::vector<std::vector<Eigen::Vector3d>> ModelCorners(const RuleContext& ctx,
                                                       const ModelPoses& poses) {
  const std::size_t n = ctx.model.links.size();
  std::vector<std::vector<Eigen::Vector3d>> corners(n);
  std::vector<bool> unknown(n, false);
  for (std::size_t l = 0; l < n; ++l) {
    const int root = poses.root[l];
    if (root < 0) continue;
    if (ctx.model.links[l].geometries.empty()) continue;
    const std::optional<GeometryBounds>& b = ctx.BoundsOfLink(static_cast<int>(l));
    if (!b || b->partial || b->box_B.isEmpty()) {
      unknown[root] = true;
      continue;
    }
    const Pose& X_WL = poses.X_WL[l];
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d p =
          b->box_B.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner));
      corners[root].push_back(X_WL.p_AB + X_WL.R_AB * p);
    }
  }
  for (const WeldedGroup& group : ctx.groups) {
    double mass = 0;
    bool drawn = false;
    for (int l : group.links) {
      const Link& link = ctx.model.links[l];
      if (link.inertial && link.inertial->mass > 0) mass += link.inertial->mass;
      drawn = drawn || Drawn(ctx, l);
    }
    const int root = group.links.empty() ? -1 : poses.root[group.links.front()];
    if (root >= 0 && mass > kDummyMass && !drawn) unknown[root] = true;
  }
  for (std::size_t r = 0; r < n; ++r) {
    if (unknown[r]) corners[r].clear();
  }
  return corners;
}

}  // namespace

const RuleInfo& InertiaExceedsModelRule() {
  static const RuleInfo kInfo{
      kInertiaExceedsModel, Severity::kWarning, true,
      "A link's radius of gyration exceeds 1.5 times the distance from its center of mass to the "
      "farthest point of the whole model: no body inside the model has it."};
  return kInfo;
}

void CheckInertiaWithinModel(RuleContext& ctx) {
  if (ctx.model.is_static || !ctx.RuleOn(kInertiaExceedsModel)) return;
  const ModelPoses poses = PosesOf(ctx);
  std::vector<std::vector<Eigen::Vector3d>> corners = ModelCorners(ctx, poses);
  std::vector<FarthestPointIndex> model_geometry;  // per tree with known extent
  std::vector<int> geometry_of_root(corners.size(), -1);
  for (std::size_t r = 0; r < corners.size(); ++r) {
    if (corners[r].empty()) continue;
    geometry_of_root[r] = static_cast<int>(model_geometry.size());
    model_geometry.emplace_back(std::move(corners[r]));
    ++ctx.stats.model_extents;
  }
  const std::unordered_set<std::string> already_too_large = AlreadyTooLarge(ctx);
  for (std::size_t l = 0; l < ctx.model.links.size(); ++l) {
    const Link& link = ctx.model.links[l];
    const int root = poses.root[l];
    if (root < 0 || geometry_of_root[root] < 0 || !link.inertial || link.inertial_unreadable) {
      continue;
    }
    const MassProperties props = LinkMassProperties(link, ctx.model.format);
    const double m = props.mass, trace = props.I_SScm_F.trace();
    if (!(m > kDummyMass) || !std::isfinite(m) || !(trace > 0) || !std::isfinite(trace)) continue;
    if (!props.p_FoScm_F.allFinite() || already_too_large.count(link.name) > 0) continue;
    const Eigen::Vector3d c = poses.X_WL[l].p_AB + poses.X_WL[l].R_AB * props.p_FoScm_F;
    const FarthestPointIndex& geometry = model_geometry[geometry_of_root[root]];
    const std::size_t evaluated = geometry.evaluated();
    const double reach = geometry.MaxDistance(c);
    ++ctx.stats.model_reach_measurements;
    ctx.stats.model_reach_distances += geometry.evaluated() - evaluated;
    const double k = std::sqrt(trace / (2 * m));
    if (!(reach > 0) || !(k > kModelRatio * reach)) continue;
    const double ratio = k / reach;
    ctx.Emit(
        kInertiaExceedsModel, link, InertiaLocation(link),
        "link '" + link.name + "': its radius of gyration sqrt(tr(I)/(2m)) = " + Num(k) + " m is " +
            Num(ratio) + " times the " + Num(reach) +
            " m from its center of mass to the farthest point of the whole model's geometry "
            "(every link's, at the zero configuration): a body inside the model has "
            "tr(I)/2 = ∫|x - c|² dm <= m·" +
            Num(reach) + "², so k <= " + Num(reach) + " m (reported beyond " + Num(kModelRatio) +
            " times, for a model drawn smaller than the machine)",
        {{"radius_of_gyration", k}, {"model_reach", reach}, {"ratio", ratio}, {"mass", m}},
        LinkHeadline(link.name, ": radius of gyration " + FormatLength(k) + ", " +
                                    FormatRatio(ratio) + " the whole model's reach of " +
                                    FormatLength(reach)),
        {{"radius_of_gyration_m", k}, {"model_reach_m", reach}, {"ratio", ratio}, {"mass_kg", m}},
        "recompute the part's inertia (from CAD, or massprops fix --from-geometry)");
  }
}

}  // namespace rules
}  // namespace massprops

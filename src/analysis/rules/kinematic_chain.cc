#include "analysis/rules/kinematic_chain.h"

#include <Eigen/Core>
#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

namespace massprops {
namespace rules {
namespace {

// The joint from link `parent` to its tree child `child`, or -1.
int JointBetween(const RuleContext& ctx, int parent, int child) {
  for (const auto& [c, j] : ctx.children[parent]) {
    if (c == child) return j;
  }
  return -1;
}

}  // namespace

double GeometryReach(const RuleContext& ctx, int n, const Pose& X_LN, bool* partial) {
  const Link& link = ctx.model.links[n];
  if (link.geometries.empty()) return 0;
  const std::optional<GeometryBounds>& b = ctx.BoundsOfLink(n);
  if ((!b || b->partial) && partial != nullptr) *partial = true;
  if (!b) return 0;
  double reach = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p = b->box_B.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner));
    reach = std::max(reach, (X_LN.p_AB + X_LN.R_AB * p).norm());
  }
  return reach;
}

ChainSpan ChainSpanOf(const RuleContext& ctx, int link_index) {
  ChainSpan chain;
  // Inboard: the joint into a link lies at its origin, so the next joint inboard of link A is at
  // its parent's origin; the parent spans from there to the point, so its geometry counts.
  Pose X_LA;
  // (A loop of parents, which no model the readers accept has, ends the walks after every link.)
  const int n = static_cast<int>(ctx.model.links.size());
  for (int a = link_index, p = ctx.parent[a], steps = 0; p >= 0 && steps < n;
       a = p, p = ctx.parent[a], ++steps) {
    const int j = JointBetween(ctx, p, a);
    if (j < 0) break;
    const Pose X_LP = X_LA * ctx.model.joints[j].X_PC.Inverse();
    chain.geometry = std::max(chain.geometry, GeometryReach(ctx, p, X_LP));
    const double d = X_LP.p_AB.norm();
    if (d > kCoincidentLength) {
      chain.inboard = d;
      break;
    }
    ++chain.links;
    X_LA = X_LP;
  }
  // Outboard, every branch: through the joints at the origin, up to the first that is not (the
  // joint tree gives each link one parent, so no link is reached twice: the walk costs the links
  // it passes).
  std::vector<std::pair<int, Pose>> stack = {{link_index, Pose()}};
  for (int steps = 0; !stack.empty() && steps < n; ++steps) {
    const auto [a, X_LAo] = stack.back();
    stack.pop_back();
    for (const auto& [c, j] : ctx.children[a]) {
      // A link hung at the point spans from it to its own joints: its geometry counts; one hung
      // at the first joint away from the point lies beyond it and does not.
      const Pose X_LC = X_LAo * ctx.model.joints[j].X_PC;
      const double d = X_LC.p_AB.norm();
      if (d > kCoincidentLength) {
        chain.outboard = std::max(chain.outboard, d);
      } else {
        chain.geometry = std::max(chain.geometry, GeometryReach(ctx, c, X_LC));
        ++chain.links;
        stack.emplace_back(c, X_LC);
      }
    }
  }
  chain.span = std::max({chain.inboard, chain.outboard, chain.geometry});
  chain.evidence = "the chain around it (" + std::to_string(chain.links) + " other link" +
                   (chain.links == 1 ? "" : "s") + " at its origin): the nearest joint inboard " +
                   Num(chain.inboard) + " m, outboard " + Num(chain.outboard) +
                   " m, their links' geometry " + Num(chain.geometry) + " m";
  return chain;
}

}  // namespace rules
}  // namespace massprops

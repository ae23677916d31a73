// units-suspect, copied placeholders: the same typed-in inertial on three or more links that have
// no geometry to judge it by, judged together against the assembly that holds them.
//
// Evidence: every link's mass and six inertia numbers as written (identical on the copies); for
// each geometry-less copy above a dummy's mass, the assembly that holds it, measured from its
// origin: its own geometry, its child joints and their links' geometry, its parent's joints (the
// parent's origin and every joint to its children), its center of mass, and where all of those
// are at one point the chain around it (kinematic_chain.h).
// Why: a body inside a ball of radius A about a point o has tr(I)/2 = ∫|x − c|² dm <=
// ∫|x − o|² dm <= m·A², so its radius of gyration k = sqrt(tr(I)/(2m)) is at most A. A copy
// whose k exceeds kCopyRatio times its assembly is no part of it (0.2 kg with 0.015 kg·m² per
// axis, k = 0.34 m, on the frames of a 10 cm caster). One such frame alone is judged by the
// kinematic tree with a wider allowance (units_suspect.cc); the copies are the evidence that the
// numbers were typed in rather than computed: the same numbers on three or more links whose sizes
// differ severalfold, or numbers of a typed-in pattern (no products, equal or round moments).

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <unordered_set>
#include <vector>

#include "analysis/rules/kinematic_chain.h"
#include "analysis/rules/model_rules.h"
#include "analysis/rules/rules.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kUnitsSuspect = "units-suspect";

// At least this many links carry the same numbers.
constexpr int kMinCopies = 3;
// Sizes that differ by at least this factor are parts of different sizes.
constexpr double kSeveralfold = 3;
// k beyond this many times the assembly's reach is reported (a body inside it has k <= 1 times;
// the margin allows for an assembly whose geometry is drawn smaller than its parts).
constexpr double kCopyRatio = 1.5;

using Numbers = std::tuple<double, double, double, double, double, double, double>;

Numbers NumbersOf(const Inertial& in) {
  return {in.mass, in.ixx, in.iyy, in.izz, in.ixy, in.ixz, in.iyz};
}

// A link with nothing of its own to judge its inertia by: no geometry, or placeholder geometry.
bool WithoutSize(const RuleContext& ctx, int l) {
  const Link& link = ctx.model.links[l];
  if (link.geometries.empty()) return true;
  const std::optional<GeometryBounds>& b = ctx.BoundsOfLink(l);
  return b && !b->partial && 0.5 * b->box_B.diagonal().norm() < kPlaceholderHalfDiagonal;
}

// The assembly that holds link l, as a reach from its origin.
struct Assembly {
  double reach = 0;
  bool partial = false;
  std::string evidence;
};

Assembly AssemblyOf(const RuleContext& ctx, int l, const Eigen::Vector3d& c) {
  Assembly a;
  // What it holds: its own geometry, its child joints and the geometry of the links there.
  double own = GeometryReach(ctx, l, Pose(), &a.partial);
  for (const auto& [child, j] : ctx.children[l]) {
    const Pose& X_LC = ctx.model.joints[j].X_PC;
    own = std::max({own, X_LC.p_AB.norm(), GeometryReach(ctx, child, X_LC, &a.partial)});
  }
  // What holds it: its parent's joints (the parent's origin and every joint to its children).
  double parent_joints = 0;
  const int p = ctx.parent[l];
  if (p >= 0) {
    Pose X_PL;
    for (const auto& [child, j] : ctx.children[p]) {
      if (child == l) X_PL = ctx.model.joints[j].X_PC;
    }
    const Pose X_LP = X_PL.Inverse();
    parent_joints = X_LP.p_AB.norm();
    for (const auto& [child, j] : ctx.children[p]) {
      (void)child;
      parent_joints = std::max(parent_joints, (X_LP * ctx.model.joints[j].X_PC).p_AB.norm());
    }
  }
  a.reach = std::max({own, parent_joints, c.norm()});
  // Only where all of that is at one point (kinematic_chain.h) does the chain around it count.
  const ChainSpan chain = a.reach <= kCoincidentLength ? ChainSpanOf(ctx, l) : ChainSpan();
  const double chain_span = chain.span;
  a.reach = std::max(a.reach, chain_span);
  a.evidence = "its own geometry, joints and children's geometry reach " + Num(own) +
               " m from its origin, its parent's joints " + Num(parent_joints) +
               " m, its center of mass " + Num(c.norm()) + " m" +
               (chain_span > 0 ? "; " + chain.evidence : std::string());
  return a;
}

bool TypedInPattern(const Inertial& in) {
  if (in.ixy != 0 || in.ixz != 0 || in.iyz != 0) return false;
  auto round = [](double x) {
    if (!(x > 0) || !std::isfinite(x)) return false;
    const double mantissa = x / std::pow(10.0, std::floor(std::log10(x)));
    return std::abs(mantissa - std::round(mantissa)) <= 1e-9 * mantissa;
  };
  return (in.ixx == in.iyy && in.iyy == in.izz) ||
         (round(in.ixx) && round(in.iyy) && round(in.izz));
}

// The links a units-suspect finding already names (an index of the findings, kept up to date as
// this rule adds its own, instead of a scan of every finding per link).
std::unordered_set<std::string> UnitsFlagged(const RuleContext& ctx) {
  std::unordered_set<std::string> links;
  for (const Finding& f : ctx.findings) {
    if (f.rule == kUnitsSuspect) links.insert(f.link);
  }
  return links;
}

void ReportCopies(RuleContext& ctx, const std::vector<int>& copies, bool typed_in,
                  double size_ratio, std::unordered_set<std::string>* flagged) {
  std::vector<Assembly> assemblies;
  for (int l : copies) {
    assemblies.push_back(
        AssemblyOf(ctx, l, LinkMassProperties(ctx.model.links[l], ctx.model.format).p_FoScm_F));
  }
  const Inertial& in = *ctx.model.links[copies.front()].inertial;
  const double trace = in.ixx + in.iyy + in.izz;
  const double k = std::sqrt(trace / (2 * in.mass));
  std::string names;
  for (std::size_t i = 0; i < copies.size() && i < 4; ++i) {
    names += (i ? ", '" : "'") + ctx.model.links[copies[i]].name + "'";
  }
  if (copies.size() > 4) names += " and " + std::to_string(copies.size() - 4) + " more";
  for (std::size_t i = 0; i < copies.size(); ++i) {
    const Link& link = ctx.model.links[copies[i]];
    const Assembly& a = assemblies[i];
    if (!WithoutSize(ctx, copies[i])) continue;  // judged by its own geometry
    // A dummy mass's typed-in floor inertia is judged by its share of its group's
    // (CheckMadeUpInertia), not by its size.
    if (!(in.mass > kDummyMass)) continue;
    if (!(a.reach > kCoincidentLength) || a.partial) continue;
    const double ratio = k / a.reach;
    if (!(ratio > kCopyRatio) || flagged->count(link.name) > 0) continue;
    const std::size_t before = ctx.findings.size();
    ctx.Emit(kUnitsSuspect, link, InertiaLocation(link),
             "link '" + link.name + "': the same mass " + Num(in.mass) + " kg and inertia (" +
                 Num(in.ixx) + ", " + Num(in.iyy) + ", " + Num(in.izz) + ") are written on " +
                 std::to_string(copies.size()) + " links (" + names + "), " +
                 (typed_in ? "typed-in numbers (no products, equal or round moments)"
                           : "links whose sizes differ " + Num(size_ratio) + "-fold") +
                 ": a placeholder copied from link to link; its radius of gyration " + Num(k) +
                 " m is " + Num(ratio) + " times the " + Num(a.reach) +
                 " m of the assembly that holds it (" + a.evidence +
                 "), more than any part inside it can have (k <= that reach); give each link "
                 "the inertia of its part (or zero mass and inertia, if it is only a frame)",
             {{"radius_of_gyration", k},
              {"assembly_reach", a.reach},
              {"ratio", ratio},
              {"mass", in.mass},
              {"copies", static_cast<double>(copies.size())}},
             LinkHeadlineFirstFit(
                 link.name, {": placeholder inertia copied onto " + std::to_string(copies.size()) +
                                 " links, radius of gyration " + FormatRatio(ratio) +
                                 " the reach of its assembly",
                             ": placeholder inertia on " + std::to_string(copies.size()) +
                                 " links, " + FormatRatio(ratio) + " too wide for its assembly"}),
             {{"radius_of_gyration_m", k},
              {"assembly_reach_m", a.reach},
              {"ratio", ratio},
              {"mass_kg", in.mass},
              {"copies_count", static_cast<double>(copies.size())}},
             "give each of the " + std::to_string(copies.size()) +
                 " links its own part's inertia (zero mass and inertia if only a frame)");
    if (ctx.findings.size() > before) flagged->insert(link.name);
  }
}

}  // namespace

void CheckCopiedPlaceholders(RuleContext& ctx) {
  if (ctx.model.is_static || !ctx.RuleOn(kUnitsSuspect)) return;
  std::map<Numbers, std::vector<int>> groups;
  for (std::size_t i = 0; i < ctx.model.links.size(); ++i) {
    const Link& link = ctx.model.links[i];
    if (!link.inertial || !(link.inertial->mass > 0) || !std::isfinite(link.inertial->mass)) {
      continue;
    }
    const Inertial& in = *link.inertial;
    if (!(in.ixx + in.iyy + in.izz > 0)) continue;
    groups[NumbersOf(in)].push_back(static_cast<int>(i));
  }
  std::unordered_set<std::string> flagged = UnitsFlagged(ctx);
  for (const auto& [numbers, links] : groups) {
    (void)numbers;
    if (static_cast<int>(links.size()) < kMinCopies) continue;
    const std::vector<int>& copies = links;
    if (std::none_of(copies.begin(), copies.end(), [&](int l) { return WithoutSize(ctx, l); })) {
      continue;
    }
    ++ctx.stats.copied_groups;  // its assemblies measured
    double smallest = HUGE_VAL, largest = 0;
    for (int l : copies) {
      const Eigen::Vector3d c = LinkMassProperties(ctx.model.links[l], ctx.model.format).p_FoScm_F;
      const Assembly a = AssemblyOf(ctx, l, c);
      smallest = std::min(smallest, a.reach);
      largest = std::max(largest, a.reach);
    }
    const double size_ratio = smallest > 0 ? largest / smallest : HUGE_VAL;
    const bool typed_in = TypedInPattern(*ctx.model.links[copies.front()].inertial);
    if (!typed_in && !(size_ratio >= kSeveralfold)) continue;
    ReportCopies(ctx, copies, typed_in, size_ratio, &flagged);
  }
}

}  // namespace rules
}  // namespace massprops

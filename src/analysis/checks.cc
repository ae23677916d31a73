#include "massprops/analysis/checks.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "analysis/rule_severity.h"
#include "analysis/rules/model_rules.h"
#include "analysis/rules/rule_context.h"
#include "analysis/rules/rules.h"
#include "massprops/analysis/check_stats.h"
#include "massprops/analysis/density_rules.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/analysis/target_profile.h"
#include "massprops/analysis/welded_groups.h"

// The rules of `massprops check` are one file each in src/analysis/rules/ (rules.h lists them;
// rule_context.h holds what they share). This file runs them: the order in which they judge each
// link and each welded group, and the order of the findings.

namespace massprops {
namespace {

using rules::RuleContext;

// The per-link rules that judge a link against its geometry, in the order they are judged.
void CheckLinkGeometry(RuleContext& ctx, const rules::JudgedLink& judged, bool units_flagged) {
  if (!judged.group_bounds) return;
  const std::size_t before = ctx.findings.size();
  if (judged.valid && !units_flagged && !rules::CheckInertiaFitsGeometry(ctx, judged)) {
    rules::CheckInertiaFitsHull(ctx, judged);
  }
  // The bounds of the link's whole geometry where the box and the hull found nothing too large
  // (one finding per defect).
  if (!units_flagged && ctx.findings.size() == before) rules::CheckDensityRealizable(ctx, judged);
  rules::CheckComInsideGeometry(ctx, judged);
}

// Every per-link rule on link `link_index`, in the order they are judged.
void CheckLink(RuleContext& ctx, int link_index) {
  const Link& link = ctx.model.links[link_index];
  if (!link.inertial) return;  // inertial-missing is judged with the link's group.
  const std::string who = "link '" + link.name + "'";
  rules::CheckMassNotPositive(ctx, link, who);
  if (!rules::CheckInertiaNotFinite(ctx, link, who)) return;
  const bool valid = rules::CheckInertiaValidity(ctx, link_index, who);
  const double m = link.inertial->mass;
  if (m == 0 && !ctx.model.is_static) rules::CheckInertiaWithoutMass(ctx, link_index, who);
  if (!(m > 0) || !std::isfinite(m)) return;

  // A static SDF model never moves: the simulator never uses its mass properties, so the
  // heuristics (what a simulation would get wrong) have nothing to say (gz-sim's conveyor.sdf).
  if (ctx.model.is_static) return;
  const rules::JudgedLink judged = ctx.JudgeAgainstGeometry(link_index, who, valid);
  rules::CheckProductsSignAgainstGeometry(ctx, judged);
  const bool units_flagged =
      rules::CheckUnits(ctx, judged) || rules::CheckMadeUpInertia(ctx, judged);
  const std::size_t before = ctx.findings.size();
  CheckLinkGeometry(ctx, judged, units_flagged);
  // Too compact for any material, where no rule above found the mass or the size wrong (one
  // finding per defect: a part denser than osmium is also more compact than osmium's ball).
  if (valid && !units_flagged && ctx.findings.size() == before) {
    rules::CheckInertiaTooCompact(ctx, judged);
  }
}

// The findings from index `first` on were made by rules that judge the welded group as one body
// (their `who`): when it has more than one link, each carries its members' names.
void NameGroupMembers(RuleContext& ctx, const WeldedGroup& group, std::size_t first) {
  if (group.links.size() < 2) return;
  std::vector<std::string> members;
  members.reserve(group.links.size());
  for (int i : group.links) members.push_back(ctx.model.links[i].name);
  for (std::size_t i = first; i < ctx.findings.size(); ++i) ctx.findings[i].group = members;
}

// Every per-group rule on welded group `group`, in the order they are judged.
void CheckGroup(RuleContext& ctx, const WeldedGroup& group) {
  const Model& model = ctx.model;
  // A static SDF model never moves: missing or zero mass properties are what it should have.
  if (model.is_static) return;
  // A member whose <inertial> could not be read makes the group's mass properties unknown (the
  // reader's inertial-unreadable finding says why): judge nothing about the group.
  for (int i : group.links) {
    if (model.links[i].inertial_unreadable) return;
  }
  const Link& root = model.links[group.links.front()];
  const CompositeInertia& composite = ctx.GroupComposite(ctx.group_of[group.links.front()]);
  bool all_massless = true;
  const int contributing = ctx.CountContributingMembers(group, &all_massless);
  const std::string who = group.links.size() > 1
                              ? "the welded group rooted at '" + root.name + "' (" +
                                    std::to_string(group.links.size()) + " links)"
                              : "link '" + root.name + "'";
  std::size_t first = ctx.findings.size();
  const rules::MasslessVerdict massless =
      rules::CheckMasslessMovingGroup(ctx, group, who, all_massless);
  NameGroupMembers(ctx, group, first);
  if (massless != rules::MasslessVerdict::kSingular) {
    // Its findings are about single members, not the group.
    rules::CheckInertialMissing(ctx, group, massless == rules::MasslessVerdict::kMassOutboard);
  }
  if (!composite.I_SScm_R.allFinite() || !std::isfinite(composite.mass)) return;
  first = ctx.findings.size();
  rules::CheckCompositeValidity(ctx, group, who, composite, contributing);
  rules::CheckInertiaAboutJointAxis(ctx, group, who, composite);
  NameGroupMembers(ctx, group, first);
}

}  // namespace

const char* ToString(Severity severity) {
  switch (severity) {
    case Severity::kNote:
      return "note";
    case Severity::kWarning:
      return "warning";
    case Severity::kError:
      return "error";
  }
  return "error";
}

std::optional<Severity> ParseSeverity(std::string_view text) {
  if (text == "note") return Severity::kNote;
  if (text == "warning") return Severity::kWarning;
  if (text == "error") return Severity::kError;
  return std::nullopt;
}

std::optional<Severity> RuleSeverity(const std::string& rule, const CheckOptions& options) {
  const auto it = options.overrides.find(rule);
  if (it != options.overrides.end()) return it->second;
  for (const RuleInfo& info : AllRules()) {
    if (info.id == rule) {
      return info.enabled_by_default ? std::optional<Severity>(info.default_severity)
                                     : std::nullopt;
    }
  }
  return std::nullopt;
}

const std::vector<RuleInfo>& AllRules() {
  // Each rule's RuleInfo is in its own file (src/analysis/rules/); this is their stable order.
  static const std::vector<RuleInfo> kRules = {
      rules::MassNotPositiveRule(),
      rules::InertiaNotFiniteRule(),
      rules::InertiaNotPhysicalRule(),
      rules::MasslessMovingBodyRule(),
      rules::MasslessWithMassOutboardRule(),
      rules::ZeroInertiaAboutJointAxisRule(),
      rules::InertiaWithoutMassRule(),
      rules::InertialMissingRule(),
      rules::ModelWithoutInertialsRule(),
      rules::ProductsSignSuspectRule(),
      rules::UnitsSuspectRule(),
      rules::InertiaAboutOriginSuspectRule(),
      rules::InertiaExceedsGeometryRule(),
      rules::InertiaBeyondHullRule(),
      rules::InertiaTooCompactRule(),
      rules::ComOutsideGeometryRule(),
      rules::ComNotMirroredRule(),
      rules::InertiaExceedsModelRule(),
      rules::InertiaNearBoundaryRule(),
      rules::UrdfNotLoadableRule(),
      rules::InertialUnreadableRule(),
      rules::IncludeUnresolvedRule(),
      rules::InertialAutoRule(),
  };
  // The geometry rules (geometry_checks.h) run only with --geometry; listed here so that every
  // rule id is known to the tool, the configuration file and SARIF.
  static const std::vector<RuleInfo> kAll = [] {
    std::vector<RuleInfo> all = kRules;
    all.insert(all.end(), DensityRules().begin(), DensityRules().end());  // density_rules.h
    all.insert(all.end(), TargetRules().begin(), TargetRules().end());    // --target (issue 16)
    all.insert(all.end(), GeometryRules().begin(), GeometryRules().end());
    all.push_back(rules::InertiaContradictsDataRule());  // check --data LOG (data_contradiction.h)
    return all;
  }();
  return kAll;
}

std::vector<Finding> CheckModel(const Model& model, const CheckOptions& options) {
  return CheckModel(model, options, nullptr);
}

std::vector<Finding> CheckModel(const Model& model, const CheckOptions& options,
                                CheckStats* stats) {
  RuleContext ctx(model, options);
  for (std::size_t i = 0; i < model.links.size(); ++i) CheckLink(ctx, static_cast<int>(i));
  bool kinematic_only = model.format == Model::Format::kUrdf;
  for (const Link& link : model.links) kinematic_only = kinematic_only && !link.inertial;
  if (kinematic_only) {
    rules::CheckKinematicOnlyModel(ctx);
  } else {
    for (const WeldedGroup& group : ctx.groups) CheckGroup(ctx, group);
    rules::CheckCopiedPlaceholders(ctx);
    rules::CheckMirroredPairs(ctx);
    rules::CheckInertiaWithinModel(ctx);
  }
  std::vector<Finding>& findings = ctx.findings;
  std::stable_sort(findings.begin(), findings.end(), [](const Finding& a, const Finding& b) {
    if (a.location.line != b.location.line) return a.location.line < b.location.line;
    return a.rule < b.rule;
  });
  AddDensityFindings(model, options, &findings);  // density_rules.h
  if (stats != nullptr) *stats = ctx.stats;
  return std::move(findings);
}

std::vector<Finding> ReaderFindings(const ReadResult& read, const CheckOptions& options) {
  std::vector<Finding> findings;
  // Whether any link ignores a rule: where none does (nearly always), a finding's link is not
  // looked up (a search of every model's links per finding: a world of n links with a reader
  // finding on each, such as SDF 1.11's auto inertia, would cost n^2).
  bool some_ignored = false;
  for (const Model& model : read.models) {
    for (const Link& link : model.links) some_ignored = some_ignored || !link.ignored_rules.empty();
  }
  for (const ReadFinding& rf : read.findings) {
    std::optional<Severity> severity;
    const auto it = options.overrides.find(rf.rule);
    if (it != options.overrides.end()) {
      severity = it->second;
    } else {
      for (const RuleInfo& info : AllRules()) {
        if (info.id == rf.rule && info.enabled_by_default) severity = info.default_severity;
      }
    }
    if (!severity) continue;
    bool ignored = false;
    for (const Model& model : read.models) {
      if (!some_ignored) break;
      if (!rf.model.empty() && model.name != rf.model) continue;
      const int index = rf.link.empty() ? -1 : model.FindLink(rf.link);
      if (index < 0) continue;
      for (const std::string& rule : model.links[index].ignored_rules) {
        ignored = ignored || rule == "all" || rule == rf.rule;
      }
    }
    if (ignored) continue;
    Finding f;
    f.rule = rf.rule;
    f.severity = *severity;
    f.model = rf.model;
    f.link = rf.link;
    f.location = rf.location;
    f.message = rf.message;
    f.values = rf.values;
    f.headline = rf.headline;
    f.evidence = rf.evidence;
    f.help = rf.help;
    if (f.headline.empty()) rules::DescribeReaderFinding(f);
    findings.push_back(std::move(f));
  }
  return findings;
}

std::optional<LinkShape> CalcLinkShape(const Link& link, const LinkShapeFunction& fallback) {
  for (const bool collision : {true, false}) {
    const std::optional<GeometryBounds> bounds = rules::BoundsOf(link, collision);
    if (!bounds) continue;
    Link primitives;  // only the chosen set, so that CalcPrimitiveMassProperties uses it
    for (const Geometry& g : link.geometries) {
      if (g.is_collision == collision) primitives.geometries.push_back(g);
    }
    const std::optional<PrimitiveMassProperties> unit =
        CalcPrimitiveMassProperties(primitives, /*density=*/1, /*mass=*/1);
    if (!unit) continue;
    LinkShape shape;
    shape.from_collision = collision;
    shape.box_B = bounds->box_B;
    shape.volume = unit->volume;
    shape.p_BoBcm_B = unit->p_BoBcm_B;
    shape.G_BBcm_B = unit->I_BBcm_B;
    shape.kind = "primitive";
    return shape;
  }
  if (!fallback) return std::nullopt;
  try {
    return fallback(link);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::optional<ProductsSignEvidence> FindProductsSignEvidence(const Inertial& in,
                                                             const LinkShape& shape) {
  const double m = in.mass;
  if (!(m > 0) || !std::isfinite(m)) return std::nullopt;
  const Eigen::Matrix3d I = rules::WrittenMatrix(in);
  const Eigen::Matrix3d& R = in.X_BBi.R_AB;
  const Eigen::Matrix3d G = m * (R.transpose() * shape.G_BBcm_B * R);  // in Bi
  if (!I.allFinite() || !G.allFinite()) return std::nullopt;
  const Eigen::Vector3d p_written(I(0, 1), I(0, 2), I(1, 2));
  const Eigen::Vector3d p_geometry(G(0, 1), G(0, 2), G(1, 2));
  const double mean_geometry = G.trace() / 3;
  const double mean_written = I.trace() / 3;
  // Products of at least 10% of the mean moment on both sides: smaller ones are within what a
  // simplified geometry or a non-uniform density can change, and say nothing about the sign.
  if (!(mean_geometry > 0) || !(mean_written > 0)) return std::nullopt;
  if (p_geometry.norm() < 0.1 * mean_geometry || p_written.norm() < 0.1 * mean_written) {
    return std::nullopt;
  }
  // The geometry must describe the body: every moment within a factor 2.
  for (int i = 0; i < 3; ++i) {
    const double d = I(i, i), g = G(i, i);
    if (!(d > 0) || !(g > 0) || std::max(d / g, g / d) > 2) return std::nullopt;
  }
  // The direction of the products is what a uniform-density model gets right; their size less
  // so (a motor inside a shell): the written products must point within about 25° of the
  // opposite of the geometry's (cosine <= -0.9) and be within a factor 2 of their size.
  const double size_ratio = p_written.norm() / p_geometry.norm();
  const double cosine = p_written.dot(p_geometry) / (p_written.norm() * p_geometry.norm());
  if (!(cosine <= -0.9) || size_ratio > 2 || size_ratio < 0.5) return std::nullopt;
  ProductsSignEvidence evidence;
  evidence.geometry_products = p_geometry;
  evidence.cosine = cosine;
  evidence.mismatch_as_written = (p_written - p_geometry).norm() / p_geometry.norm();
  evidence.mismatch_negated = (p_written + p_geometry).norm() / p_geometry.norm();
  return evidence;
}

std::optional<GeometryBounds> CalcLinkGeometryBounds(const Link& link) {
  bool has_collision = false, has_visual = false;
  for (const Geometry& g : link.geometries) (g.is_collision ? has_collision : has_visual) = true;
  std::optional<GeometryBounds> collision = rules::BoundsOf(link, /*collision=*/true);
  std::optional<GeometryBounds> visual = rules::BoundsOf(link, /*collision=*/false);
  // Collision geometry often covers only part of the body while the visual covers all of it:
  // the union of both, marked partial when one of them is not all primitives.
  if (collision && visual) {
    collision->box_B.extend(visual->box_B);
    collision->count += visual->count;
    return collision;
  }
  if (collision) {
    collision->partial = has_visual;
    return collision;
  }
  if (visual) visual->partial = has_collision;
  return visual;
}

std::optional<GeometryBounds> CalcLinkGeometryBounds(const Link& link,
                                                     const std::optional<LinkShape>& shape) {
  std::optional<GeometryBounds> bounds = CalcLinkGeometryBounds(link);
  if (bounds && !bounds->partial) return bounds;
  // A shape from the same primitives adds nothing; a mesh shape fills in what is not known.
  if (!shape || (bounds && shape->kind != "mesh")) return bounds;
  GeometryBounds from_shape{shape->box_B, shape->from_collision, 1, shape->kind == "mesh", false};
  if (bounds) from_shape.box_B.extend(bounds->box_B);
  return from_shape;
}

std::optional<GeometryBounds> CalcLinkGeometryBounds(const Link& link,
                                                     const std::optional<LinkShape>& shape,
                                                     const LinkBoxFunction& box) {
  std::optional<GeometryBounds> bounds = CalcLinkGeometryBounds(link, shape);
  if ((bounds && !bounds->partial) || !box) return bounds;
  std::optional<LinkGeometryBox> read;
  try {
    read = box(link);
  } catch (const std::exception&) {
    return bounds;
  }
  if (!read || read->known == 0 || read->box_B.isEmpty()) return bounds;
  GeometryBounds result;
  result.box_B = read->box_B;
  result.from_collision = read->from_collision;
  result.count = read->known;
  result.from_mesh = read->meshes > 0;
  result.partial = read->unknown > 0;
  return result;
}

}  // namespace massprops

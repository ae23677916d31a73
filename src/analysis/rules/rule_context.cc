#include "analysis/rules/rule_context.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "analysis/rule_severity.h"
#include "massprops/core/format_number.h"
#include "massprops/core/principal_axes.h"
#include "massprops/core/rotational_inertia.h"

namespace massprops {
namespace rules {
namespace {

// The half-diagonal that "too small" is judged against: the smaller of the link's collision and
// visual geometry when both are known primitives larger than a placeholder (either may be the
// body: gz-sim's entity_semantics.sdf has a 23.4 m collision sphere around a 1.2 m visual one);
// else that of `bounds`.
double SmallestGeometryExtent(const Link& link, const GeometryBounds& bounds) {
  double extent = 0.5 * bounds.box_B.diagonal().norm();
  const std::optional<GeometryBounds> collision = BoundsOf(link, /*collision=*/true);
  const std::optional<GeometryBounds> visual = BoundsOf(link, /*collision=*/false);
  if (!collision || !visual) return extent;
  for (const GeometryBounds* b : {&*collision, &*visual}) {
    const double e = 0.5 * b->box_B.diagonal().norm();
    if (e >= kPlaceholderHalfDiagonal) extent = std::min(extent, e);
  }
  return extent;
}

}  // namespace

std::string Format(const char* format, ...) {
  char buffer[1024];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof(buffer), format, args);
  va_end(args);
  return buffer;
}

std::string Num(double x) { return FormatPrecision(x, 6); }  // printf's "%.6g"

std::string Vec(const Eigen::Vector3d& v) {
  return "(" + Num(v.x()) + ", " + Num(v.y()) + ", " + Num(v.z()) + ")";
}

Validity Analyze(const Eigen::Matrix3d& I) {
  Validity v;
  v.finite = I.allFinite();
  if (!v.finite) return v;
  v.moments = internal::ScaledPrincipalMoments(I(0, 0), I(1, 1), I(2, 2), I(1, 0), I(2, 0), I(2, 1),
                                               PrincipalSolver::kAccurate);
  v.trace = I.trace();
  v.excess = v.moments(2) - (v.moments(0) + v.moments(1));
  return v;
}

bool IsValid(const Eigen::Matrix3d& I, double relative_tolerance) {
  return internal::IsPhysicallyValidInertia(I(0, 0), I(1, 1), I(2, 2), I(1, 0), I(2, 0), I(2, 1),
                                            relative_tolerance);
}

std::string DescribeViolation(const Validity& v) {
  const Eigen::Vector3d& m = v.moments;
  std::string text = "principal moments " + Num(m(0)) + ", " + Num(m(1)) + ", " + Num(m(2)) + ": ";
  if (m(0) < 0) text += "a negative moment, and ";
  text += Num(m(0)) + " + " + Num(m(1)) + " < " + Num(m(2)) + " (by " + Num(v.excess);
  if (v.trace > 0) {
    text += " = " + Format("%.3g%%", 100 * v.excess / v.trace) + " of the trace";
  }
  return text + ")";
}

std::vector<std::pair<std::string, double>> ValidityValues(const Validity& v, double tolerance) {
  return {
      {"principal_min", v.moments(0)}, {"principal_mid", v.moments(1)},
      {"principal_max", v.moments(2)}, {"trace", v.trace},
      {"violation", v.excess},         {"relative_violation", v.trace > 0 ? v.excess / v.trace : 0},
      {"tolerance", tolerance}};
}

Eigen::Matrix3d WrittenMatrix(const Inertial& in) {
  Eigen::Matrix3d I;
  I << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  return I;
}

std::optional<GeometryBounds> BoundsOf(const Link& link, bool collision) {
  GeometryBounds bounds;
  bounds.from_collision = collision;
  for (const Geometry& g : link.geometries) {
    if (g.is_collision != collision) continue;
    const std::optional<Eigen::AlignedBox3d> box = CalcPrimitiveBounds(g);
    if (!box) return std::nullopt;
    bounds.box_B.extend(*box);
    ++bounds.count;
  }
  if (bounds.count == 0) return std::nullopt;
  return bounds;
}

std::string UnjudgedBecause(const Link& link, const std::optional<GeometryBounds>& bounds) {
  if (bounds) {
    const double e = 0.5 * bounds->box_B.diagonal().norm();
    if (e < kPlaceholderHalfDiagonal) {
      return "its geometry is a placeholder (half-diagonal " + Num(e) + " m)";
    }
  }
  if (link.inertial && link.inertial->mass <= kDummyMass) {
    return "its mass " + Num(link.inertial->mass) + " kg is a dummy's";
  }
  return "";
}

const SourceLocation& InertiaLocation(const Link& link) {
  if (link.inertial) {
    if (link.inertial->inertia_location.line > 0) return link.inertial->inertia_location;
    if (link.inertial->location.line > 0) return link.inertial->location;
  }
  return link.location;
}

const SourceLocation& MassLocation(const Link& link) {
  if (link.inertial && link.inertial->mass_location.line > 0) {
    return link.inertial->mass_location;
  }
  return InertiaLocation(link);
}

const SourceLocation& PoseLocation(const Link& link) {
  if (link.inertial && link.inertial->pose_location.line > 0) {
    return link.inertial->pose_location;
  }
  return InertiaLocation(link);
}

double Allowance(const GeometryBounds& group_bounds, bool for_inertia) {
  if (!group_bounds.partial) return 1.0;
  return for_inertia && !group_bounds.marker ? kPartialGeometryMargin : kMarkerGeometryMargin;
}

double MarginOf(const GeometryBounds& bounds) {
  return bounds.from_mesh && !bounds.partial ? kMeshGeometryMargin : kGeometryMargin;
}

RuleContext::RuleContext(const Model& model_in, const CheckOptions& options_in)
    : model(model_in), options(options_in) {
  groups = FindWeldedGroups(model);
  group_of.assign(model.links.size(), -1);
  index_in_group_.assign(model.links.size(), 0);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    for (std::size_t k = 0; k < groups[g].links.size(); ++k) {
      group_of[groups[g].links[k]] = static_cast<int>(g);
      index_in_group_[groups[g].links[k]] = static_cast<int>(k);
    }
  }
  BuildJointTree();
  group_welded_to_world_.assign(groups.size(), false);
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    if (welded_to_world[i] && group_of[i] >= 0) group_welded_to_world_[group_of[i]] = true;
  }
  sdf_without_inertials = model.format == Model::Format::kSdf && !model.links.empty();
  for (const Link& link : model.links) {
    sdf_without_inertials = sdf_without_inertials && !link.inertial && !link.inertial_unreadable;
  }
}

void RuleContext::BuildJointTree() {
  children.assign(model.links.size(), {});
  welded_to_world.assign(model.links.size(), false);
  parent.assign(model.links.size(), -1);
  // Names hashed once (Model::FindLink and FindParentJoint search linearly: per joint, that
  // would make a chain of n links cost n^2).
  std::unordered_map<std::string_view, int> link_of;
  link_of.reserve(model.links.size());
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    link_of.emplace(model.links[i].name, static_cast<int>(i));  // the first of a name
  }
  std::unordered_set<std::string_view> has_parent_joint;
  has_parent_joint.reserve(model.joints.size());
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const Joint& joint = model.joints[j];
    // The tree parent joint of a link is the first joint naming it as child.
    if (!has_parent_joint.insert(joint.child).second) continue;
    const auto p = link_of.find(joint.parent), c = link_of.find(joint.child);
    if (p == link_of.end() && c != link_of.end() && joint.type == Joint::Type::kFixed) {
      welded_to_world[c->second] = true;  // fixed to a parent outside the model (the world)
    }
    if (p == link_of.end() || c == link_of.end()) continue;
    children[p->second].emplace_back(c->second, static_cast<int>(j));
    parent[c->second] = p->second;
  }
  total_mass = 0;
  for (const Link& link : model.links) {
    const double m = LinkMassProperties(link, model.format).mass;
    if (m > 0 && std::isfinite(m)) total_mass += m;
  }
}

std::optional<CompositeInertia> RuleContext::OutboardComposite(int child_link) const {
  ++stats.outboard_questions;
  if (!subtrees_composed_) ComposeSubtrees();
  return subtree_[child_link];
}

void RuleContext::ComposeSubtrees() const {
  const std::size_t n = model.links.size();
  subtree_.assign(n, std::nullopt);
  subtrees_composed_ = true;
  // 0: not reached, 1: its children pending, 2: composed (a link reached again while pending,
  // which only a loop of parents can do, counts as a leaf of nothing, as a visited link did).
  std::vector<char> state(n, 0);
  for (std::size_t start = 0; start < n; ++start) {
    if (state[start] != 0) continue;
    std::vector<int> stack = {static_cast<int>(start)};
    while (!stack.empty()) {
      const int l = stack.back();
      if (state[l] == 0) {
        state[l] = 1;
        for (const auto& [c, j] : children[l]) {
          (void)j;
          if (state[c] == 0) stack.push_back(c);
        }
        continue;
      }
      stack.pop_back();
      if (state[l] == 2) continue;
      state[l] = 2;
      const Link& link = model.links[l];
      if (link.inertial_unreadable) continue;  // nullopt: unknown
      std::vector<MassProperties> parts;
      const MassProperties props_L = LinkMassProperties(link, model.format);
      if (props_L.mass != 0 || !props_L.I_SScm_F.isZero(0)) parts.push_back(props_L);
      bool known = true;
      for (const auto& [c, j] : children[l]) {
        if (state[c] != 2 || c == l) continue;
        const std::optional<CompositeInertia>& sub = subtree_[c];
        if (!sub) {  // an unreadable <inertial> below: unknown
          known = false;
          break;
        }
        if (sub->mass == 0 && sub->I_SScm_R.isZero(0)) continue;
        const Pose& X_LC = model.joints[j].X_PC;
        MassProperties part;
        part.mass = sub->mass;
        part.p_FoScm_F = X_LC.p_AB + X_LC.R_AB * sub->p_RoScm_R;
        part.I_SScm_F = X_LC.R_AB * sub->I_SScm_R * X_LC.R_AB.transpose();
        parts.push_back(part);
      }
      if (!known) continue;
      subtree_[l] = ComposeMassProperties(parts);
      ++stats.subtree_composites;
    }
  }
}

std::optional<Severity> RuleContext::SeverityOf(const std::string& rule) const {
  return RuleSeverity(rule, options);
}

bool RuleContext::Enabled(const std::string& rule, const Link& link) const {
  for (const std::string& ignored : link.ignored_rules) {
    if (ignored == "all" || ignored == rule) return false;
  }
  return SeverityOf(rule).has_value();
}

Finding* RuleContext::Emit(const std::string& rule, const Link& link,
                           const SourceLocation& location, std::string message,
                           std::vector<std::pair<std::string, double>> values) {
  if (!Enabled(rule, link)) return nullptr;
  Finding f;
  f.rule = rule;
  f.severity = *SeverityOf(rule);
  f.model = model.name;
  f.link = link.name;
  f.location = location;
  f.message = std::move(message);
  f.values = std::move(values);
  findings.push_back(std::move(f));
  return &findings.back();
}

void RuleContext::Emit(const std::string& rule, const Link& link, const SourceLocation& location,
                       std::string message, std::vector<std::pair<std::string, double>> values,
                       std::string headline, std::vector<std::pair<std::string, double>> evidence,
                       std::string help) {
  Finding* f = Emit(rule, link, location, std::move(message), std::move(values));
  if (f == nullptr) return;
  // A headline "link 'NAME'..." written without LinkHeadline that came out too long: the same
  // sentence as LinkHeadline writes it (without the guessed cause, or about "this link").
  const std::string named = "link '" + link.name + "'";
  if (CountChars(headline) > kMaxHeadlineChars && headline.rfind(named, 0) == 0) {
    headline = LinkHeadline(link.name, std::string_view(headline).substr(named.size()));
  }
  f->headline = std::move(headline);
  f->evidence = std::move(evidence);
  f->help = std::move(help);
}

JudgedLink RuleContext::JudgeAgainstGeometry(int link_index, const std::string& who,
                                             bool valid) const {
  const Link& link = model.links[link_index];
  JudgedLink judged;
  judged.link = &link;
  judged.index = link_index;
  judged.who = who;
  judged.valid = valid;
  judged.I_written = WrittenMatrix(*link.inertial);
  judged.props = LinkMassProperties(link, model.format);
  const Eigen::Vector3d& c = judged.props.p_FoScm_F;
  judged.shape = CalcLinkShape(link, options.shape);
  std::optional<GeometryBounds>& bounds = judged.bounds;
  bounds = CalcLinkGeometryBounds(link, judged.shape, options.box);
  // Placeholder geometry and dummy masses: nothing to judge by (see kPlaceholderHalfDiagonal).
  judged.unjudged_because = UnjudgedBecause(link, bounds);
  if (!judged.unjudged_because.empty()) bounds.reset();
  // A visual-only marker (no collision; a box of at most kMarkerHalfDiagonal drawn to show a
  // frame, as PR2, Cassie and Atlas do) shows where the link is, not how far its body reaches:
  // like a mesh of unknown size, it is partial (Cassie's motor rotors, 0.27 kg with k = 3.5 cm,
  // behind 1 cm marker boxes).
  if (bounds && !bounds->from_collision &&
      0.5 * bounds->box_B.diagonal().norm() < kMarkerHalfDiagonal) {
    bounds->partial = true;
    bounds->marker = true;
  }
  if (bounds) judged.smallest_extent = SmallestGeometryExtent(link, *bounds);
  // A mass lumped onto one link of a welded group shows as a center of mass outside the link's
  // own geometry: such a link is judged against the geometry of the whole group (in this link's
  // frame); any other link against its own (collision and visual).
  judged.group_bounds = bounds;
  if (bounds) {
    const Eigen::Vector3d h_own = 0.5 * bounds->box_B.sizes();
    const Eigen::Vector3d out_own =
        ((c - bounds->box_B.center()).cwiseAbs() - h_own).cwiseMax(Eigen::Vector3d::Zero());
    const double com_margin =
        MarginOf(*bounds) == kMeshGeometryMargin ? kMeshComMargin : kGeometryMargin - 1;
    if (out_own.norm() > com_margin * h_own.norm()) {
      judged.group_bounds = GroupBounds(link_index, *bounds);
    }
  }
  judged.collision_envelope =
      bounds && judged.group_bounds && judged.group_bounds->box_B.isApprox(bounds->box_B) &&
      BoundsOf(link, /*collision=*/true).has_value() && JointsWithin(link_index, *bounds);
  judged.geometry_name = std::string(bounds && !bounds->from_collision ? "visual" : "collision") +
                         (bounds && bounds->from_mesh ? " mesh" : "");
  return judged;
}

bool RuleContext::JointsWithin(int link_index, const GeometryBounds& bounds) const {
  const Eigen::Vector3d h = 0.5 * bounds.box_B.sizes();
  const double allowed = (kGeometryMargin - 1) * h.norm();
  for (const auto& [child, j] : children[link_index]) {
    (void)child;
    const Eigen::Vector3d p = model.joints[j].X_PC.p_AB;
    const Eigen::Vector3d out =
        ((p - bounds.box_B.center()).cwiseAbs() - h).cwiseMax(Eigen::Vector3d::Zero());
    if (out.norm() > allowed) return false;
  }
  return true;
}

std::optional<GeometryBounds> RuleContext::GroupBounds(int link_index,
                                                       const GeometryBounds& bounds) const {
  GeometryBounds result = bounds;
  const WeldedGroup& group = groups[group_of[link_index]];
  const Pose X_LR = GroupPoseOf(link_index).Inverse();
  for (std::size_t k = 0; k < group.links.size(); ++k) {
    const int j = group.links[k];
    if (j == link_index) continue;
    const Link& member = model.links[j];
    if (member.geometries.empty()) continue;
    const std::optional<GeometryBounds>& b = BoundsOfLink(j);
    if (!b) {
      result.partial = true;
      continue;
    }
    result.partial |= b->partial;
    const Pose X_LM = X_LR * group.X_RL[k];
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d p =
          b->box_B.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner));
      result.box_B.extend(X_LM.p_AB + X_LM.R_AB * p);
    }
  }
  return result;
}

const std::optional<GeometryBounds>& RuleContext::BoundsOfLink(int link_index) const {
  if (bounds_of_link_.empty()) bounds_of_link_.resize(model.links.size());
  std::optional<std::optional<GeometryBounds>>& memo = bounds_of_link_[link_index];
  if (!memo) memo = CalcLinkGeometryBounds(model.links[link_index], std::nullopt, options.box);
  return *memo;
}

std::string RuleContext::GroupNote(int link_index) const {
  const WeldedGroup& group = groups[group_of[link_index]];
  if (group.links.size() < 2) return "";
  const CompositeInertia& composite = GroupComposite(group_of[link_index]);
  if (composite.I_SScm_R.allFinite() && IsValid(composite.I_SScm_R, options.tolerance)) {
    return "; its welded group rooted at '" + group.root_link +
           "' is valid as a whole (as a simulator that merges fixed joints sees it)";
  }
  return "";
}

int RuleContext::CountContributingMembers(const WeldedGroup& group, bool* all_massless) const {
  int contributing = 0;
  for (int i : group.links) {
    const Link& link = model.links[i];
    if (!link.inertial) {
      if (model.format == Model::Format::kSdf) {  // SDF default: mass 1, inertia diag(1,1,1).
        *all_massless = false;
        ++contributing;
      }
      continue;
    }
    if (link.inertial->mass != 0) *all_massless = false;
    if (link.inertial->mass != 0 || !WrittenMatrix(*link.inertial).isZero(0)) ++contributing;
  }
  return contributing;
}

const RuleContext::GroupCorners& RuleContext::GroupCornersOf(int group_index) const {
  if (corners_of_group_.empty()) corners_of_group_.resize(groups.size());
  std::optional<GroupCorners>& memo = corners_of_group_[group_index];
  ++stats.group_reach_questions;
  if (memo) return *memo;
  ++stats.group_corner_indexes;
  const WeldedGroup& group = groups[group_index];
  std::vector<Eigen::Vector3d> corners;
  bool partial = false;
  for (std::size_t k = 0; k < group.links.size(); ++k) {
    const int j = group.links[k];
    if (model.links[j].geometries.empty()) continue;
    const std::optional<GeometryBounds>& b = BoundsOfLink(j);
    if (!b || b->partial) partial = true;
    if (!b) continue;
    const Pose& X_RM = group.X_RL[k];
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d p =
          b->box_B.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner));
      corners.push_back(X_RM.p_AB + X_RM.R_AB * p);
    }
  }
  memo.emplace(GroupCorners{FarthestPointIndex(std::move(corners)), partial});
  return *memo;
}

const CompositeInertia& RuleContext::GroupComposite(int group_index) const {
  if (composite_of_group_.empty()) composite_of_group_.resize(groups.size());
  std::optional<CompositeInertia>& memo = composite_of_group_[group_index];
  ++stats.group_composite_questions;
  if (!memo) {
    memo = CalcCompositeInertia(model, groups[group_index]);
    ++stats.group_composites;
  }
  return *memo;
}

}  // namespace rules
}  // namespace massprops

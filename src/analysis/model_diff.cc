#include "massprops/analysis/model_diff.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>

#include "massprops/analysis/welded_groups.h"

namespace massprops {
namespace {

double LargestMoment(const Eigen::Matrix3d& I) {
  if (!I.allFinite()) return 0;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(I, Eigen::EigenvaluesOnly);
  return std::max(0.0, eigen.eigenvalues().maxCoeff());
}

double Relative(double a, double b) {
  const double scale = std::max(std::abs(a), std::abs(b));
  return scale > 0 ? std::abs(a - b) / scale : (a == b ? 0 : HUGE_VAL);
}

void Compare(double tolerance, DiffEntry* e) {
  if (!e->a.present || !e->b.present) {
    // A massless link in one file only (a world, a dummy frame) is no difference.
    e->differs = (e->a.present ? e->a.mass : e->b.mass) > 0;
    return;
  }
  e->mass_difference = Relative(e->a.mass, e->b.mass);
  const double lambda = std::max(LargestMoment(e->a.inertia), LargestMoment(e->b.inertia));
  const double mass = std::max(e->a.mass, e->b.mass);
  double length = std::max(e->a.com.norm(), e->b.com.norm());
  if (mass > 0) length = std::max(length, std::sqrt(lambda / mass));
  const double shift = (e->a.com - e->b.com).norm();
  e->com_difference = length > 0 ? shift / length : (shift == 0 ? 0 : HUGE_VAL);
  if (e->a.mass == 0 && e->b.mass == 0) e->com_difference = 0;  // No center to compare.
  const double entries = (e->a.inertia - e->b.inertia).cwiseAbs().maxCoeff();
  e->inertia_difference = lambda > 0 ? entries / lambda : (entries == 0 ? 0 : HUGE_VAL);
  e->differs = !(e->mass_difference <= tolerance) || !(e->com_difference <= tolerance) ||
               !(e->inertia_difference <= tolerance);
}

DiffSide LinkSide(const Model& model, const Link& link) {
  const MassProperties p = LinkMassProperties(link, model.format);
  DiffSide side;
  side.present = true;
  side.mass = p.mass;
  side.com = p.p_FoScm_F;
  side.inertia = p.I_SScm_F;
  side.location = link.location;
  return side;
}

struct Groups {
  std::vector<WeldedGroup> groups;
  std::map<std::string, int> group_of_link;  // Link name -> index into groups.
};

Groups GroupsOf(const Model& model) {
  Groups g;
  g.groups = FindWeldedGroups(model);
  for (std::size_t i = 0; i < g.groups.size(); ++i) {
    for (const int link : g.groups[i].links) {
      g.group_of_link[model.links[static_cast<std::size_t>(link)].name] = static_cast<int>(i);
    }
  }
  return g;
}

DiffSide GroupSide(const Model& model, const WeldedGroup& group) {
  const CompositeInertia c = CalcCompositeInertia(model, group);
  DiffSide side;
  side.present = true;
  side.mass = c.mass;
  side.com = c.p_RoScm_R;
  side.inertia = c.I_SScm_R;
  side.location = model.links[static_cast<std::size_t>(group.links[0])].location;
  return side;
}

// The whole model's composite re-expressed in the frame of link `anchor`.
DiffSide TotalSide(const Model& model, int anchor) {
  const ModelCompositeInertia total = CalcModelCompositeInertia(model);
  std::vector<bool> reachable;
  const std::vector<Pose> X_WL = CalcLinkPosesInRootFrame(model, &reachable);
  const Pose X_LW = anchor >= 0 ? X_WL[static_cast<std::size_t>(anchor)].Inverse() : Pose();
  DiffSide side;
  side.present = true;
  side.mass = total.inertia.mass;
  side.com = X_LW.p_AB + X_LW.R_AB * total.inertia.p_RoScm_R;
  side.inertia = X_LW.R_AB * total.inertia.I_SScm_R * X_LW.R_AB.transpose();
  side.location = model.location;
  return side;
}

}  // namespace

ModelDiff DiffModels(const Model& a, const Model& b, double tolerance) {
  ModelDiff diff;
  diff.tolerance = tolerance;
  const Groups groups_a = GroupsOf(a), groups_b = GroupsOf(b);
  // Links by name, A's order first.
  for (const Link& link : a.links) {
    DiffEntry e;
    e.kind = "link";
    e.name = link.name;
    e.a = LinkSide(a, link);
    const int in_b = b.FindLink(link.name);
    if (in_b >= 0) e.b = LinkSide(b, b.links[static_cast<std::size_t>(in_b)]);
    diff.entries.push_back(std::move(e));
  }
  for (const Link& link : b.links) {
    if (a.FindLink(link.name) >= 0) continue;
    DiffEntry e;
    e.kind = "link";
    e.name = link.name;
    e.b = LinkSide(b, link);
    diff.entries.push_back(std::move(e));
  }
  for (DiffEntry& e : diff.entries) {
    if (e.a.present && e.b.present) continue;
    const Model& other = e.a.present ? b : a;
    const Model& own = e.a.present ? a : b;
    const Groups& own_groups = e.a.present ? groups_a : groups_b;
    const WeldedGroup& group =
        own_groups.groups[static_cast<std::size_t>(own_groups.group_of_link.at(e.name))];
    bool fused = false;
    for (const int member : group.links) {
      fused = fused || other.FindLink(own.links[static_cast<std::size_t>(member)].name) >= 0;
    }
    e.missing_how = fused ? "fused" : "dropped";
  }
  // Welded groups matched by their root link's name.
  for (const WeldedGroup& group : groups_a.groups) {
    const std::string& root = group.root_link;
    const auto in_b = groups_b.group_of_link.find(root);
    if (in_b == groups_b.group_of_link.end()) continue;
    const WeldedGroup& other = groups_b.groups[static_cast<std::size_t>(in_b->second)];
    if (other.root_link != root || (group.links.size() == 1 && other.links.size() == 1)) {
      continue;  // Not the same group, or a lone link compared above.
    }
    DiffEntry e;
    e.kind = "group";
    e.name = root;
    e.a = GroupSide(a, group);
    e.b = GroupSide(b, other);
    diff.entries.push_back(std::move(e));
  }
  // The whole robot, in the frame of the first link both have that is not the root of either
  // (MJCF's world, a URDF world link), else the first link both have.
  int anchor_a = -1, anchor_b = -1;
  for (int pass = 0; pass < 2 && anchor_a < 0; ++pass) {
    for (std::size_t i = 0; i < a.links.size() && anchor_a < 0; ++i) {
      const std::string& name = a.links[i].name;
      const int j = b.FindLink(name);
      if (j < 0 || (pass == 0 && (name == a.root_link || name == b.root_link))) continue;
      anchor_a = static_cast<int>(i);
      anchor_b = j;
    }
  }
  DiffEntry total;
  total.kind = "total";
  total.name = anchor_a >= 0 ? a.links[static_cast<std::size_t>(anchor_a)].name : "";
  total.a = TotalSide(a, anchor_a);
  total.b = TotalSide(b, anchor_b);
  diff.entries.push_back(std::move(total));
  for (DiffEntry& e : diff.entries) {
    Compare(tolerance, &e);
    diff.differs = diff.differs || e.differs;
  }
  return diff;
}

}  // namespace massprops

// The repairs a target asks for on top of the generic ones (PlanTargetRepairs): for MuJoCo, the
// nearest inertia its exact triangle test accepts, and a negligible mass and moment floor.
#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "analysis/targets/target_layer.h"
#include "massprops/analysis/repair.h"

namespace massprops {

using namespace targets;

namespace {

void FillChanges(const Model& model, const Link& link, Repair* repair) {
  repair->changes.clear();
  repair->inserts_origin = false;
  repair->inserts_inertial = !link.inertial.has_value();
  repair->before = link.inertial;
  repair->link_line = link.location.line;
  repair->relative_change = 1;
  if (!link.inertial) return;
  const bool sdf = model.format == Model::Format::kSdf;
  const Inertial& b = *link.inertial;
  const Inertial& a = repair->after;
  auto add = [&](const char* element, const char* attribute, int line,
                 std::vector<double> old_values, std::vector<double> new_values) {
    if (old_values == new_values) return;
    repair->changes.push_back(
        {element, attribute, line, 0, std::move(old_values), std::move(new_values)});
  };
  add("mass", sdf ? "" : "value", b.mass_location.line, {b.mass}, {a.mass});
  if (b.X_BBi.p_AB != a.X_BBi.p_AB) {
    if (b.pose_location.line == 0) repair->inserts_origin = true;
    add(sdf ? "pose" : "origin", sdf ? "" : "xyz", b.pose_location.line,
        {b.X_BBi.p_AB.x(), b.X_BBi.p_AB.y(), b.X_BBi.p_AB.z()},
        {a.X_BBi.p_AB.x(), a.X_BBi.p_AB.y(), a.X_BBi.p_AB.z()});
  }
  const int line = b.inertia_location.line;
  add("inertia", "ixx", line, {b.ixx}, {a.ixx});
  add("inertia", "ixy", line, {b.ixy}, {a.ixy});
  add("inertia", "ixz", line, {b.ixz}, {a.ixz});
  add("inertia", "iyy", line, {b.iyy}, {a.iyy});
  add("inertia", "iyz", line, {b.iyz}, {a.iyz});
  add("inertia", "izz", line, {b.izz}, {a.izz});
  const Eigen::Matrix3d I_before = WrittenMatrixOf(b), I_after = WrittenMatrixOf(a);
  if (I_before.norm() > 0 && I_before != I_after) {
    repair->relative_change = (I_after - I_before).norm() / I_before.norm();
  } else if (I_before == I_after && b.mass != 0) {
    repair->relative_change = std::abs(a.mass - b.mass) / std::abs(b.mass);
  }
}

void SetMatrix(const Eigen::Matrix3d& I, Inertial* in) {
  in->ixx = I(0, 0);
  in->iyy = I(1, 1);
  in->izz = I(2, 2);
  in->ixy = I(0, 1);
  in->ixz = I(0, 2);
  in->iyz = I(1, 2);
}

}  // namespace

std::vector<Repair> PlanTargetRepairs(const Model& model, Target target,
                                      const MujocoCompilerOptions& mujoco,
                                      const std::vector<Repair>& repairs) {
  if (target != Target::kMujoco || model.format != Model::Format::kUrdf) return repairs;
  std::vector<Repair> out = repairs;
  // A negligible mass for bodies MuJoCo finds massless: 1e-6 of the model's mass (at least 1e-9).
  double total = 0;
  for (const Link& link : model.links) {
    if (link.inertial && std::isfinite(link.inertial->mass) && link.inertial->mass > 0) {
      total += link.inertial->mass;
    }
  }
  const double mass_floor = std::max(1e-6 * total, 1e-9);
  Model work = ApplyRepairs(model, out);
  for (int round = 0; round < 4; ++round) {
    const MujocoPrediction prediction = PredictMujoco(work, mujoco);
    if (prediction.accepted() || !prediction.unsupported.empty()) break;
    bool changed = false;
    std::set<int> done;
    for (const MujocoError& e : prediction.errors) {
      if (e.link < 0 || done.count(e.link)) continue;
      done.insert(e.link);
      Link& link = work.links[e.link];
      Inertial after = link.inertial ? *link.inertial : Inertial{};
      std::string method, why;
      if (e.rule == kMujocoTriangle && link.inertial) {
        const Eigen::Matrix3d I = WrittenMatrixOf(after);
        if (!I.allFinite()) continue;
        // Strictly inside the valid set (tolerance < 0 always projects), so that MuJoCo's exact
        // test passes after its own eigen-decomposition.
        SetMatrix(RepairInertia(I, InertiaRepairMethod::kProject, -1), &after);
        method = "mujoco-project";
        why = "MuJoCo refuses the inertia (A + B >= C fails on its principal moments " +
              Moments(e.inertia) + "): replaced by the nearest inertia MuJoCo accepts";
      } else if (e.rule == kMujocoMinValRule || e.rule == kMujocoFusedInertia ||
                 e.rule == kMujocoGeomMass) {
        if (!(after.mass >= kMujocoMinVal) || !std::isfinite(after.mass)) after.mass = mass_floor;
        const double largest =
            std::max({std::fabs(e.inertia[0]), std::fabs(e.inertia[1]), std::fabs(e.inertia[2])});
        const double floor = std::max({1e-9 * largest, mass_floor * 1e-4, 1e-12});
        Eigen::Matrix3d I = WrittenMatrixOf(after);
        if (!I.allFinite()) continue;
        I += floor * Eigen::Matrix3d::Identity();
        SetMatrix(I, &after);
        method = "mujoco-floor";
        why = "MuJoCo refuses body '" + link.name + "' (" + e.message +
              "): mass raised to at least " + Num(after.mass) + " kg and " + Num(floor) +
              " kg·m² added to each moment, negligible next to the model";
      } else {
        continue;
      }
      // Merge with the link's earlier repair, if any.
      auto it = std::find_if(out.begin(), out.end(),
                             [&](const Repair& r) { return r.link == link.name; });
      if (it == out.end()) {
        Repair repair;
        repair.rule = e.rule;
        repair.link = link.name;
        out.push_back(repair);
        it = out.end() - 1;
      }
      it->after = after;
      it->method += (it->method.empty() ? "" : "+") + method;
      it->why += (it->why.empty() ? "" : " Then: ") + why + ".";
      if (std::find(it->resolves.begin(), it->resolves.end(), e.rule) == it->resolves.end()) {
        it->resolves.push_back(e.rule);
      }
      FillChanges(model, model.links[e.link], &*it);
      link.inertial = after;
      changed = true;
    }
    if (!changed) break;
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const Repair& a, const Repair& b) { return a.link_line < b.link_line; });
  return out;
}

}  // namespace massprops

#include "massprops/analysis/welded_groups.h"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "analysis/name_index.h"

namespace massprops {
namespace {

// The tree structure of a model: for each link, the joint that makes it a child (first in file
// order), and that joint's parent link (-1 when the parent is not a link of the model).
struct Tree {
  std::vector<int> parent_joint;  // per link
  std::vector<int> parent_link;   // per link
};

Tree BuildTree(const Model& model) {
  const int n = static_cast<int>(model.links.size());
  const internal::NameIndex index(
      n, [&model](int i) -> const std::string& { return model.links[i].name; });
  auto find = [&index](const std::string& name) { return index.Find(name); };
  Tree tree{std::vector<int>(n, -1), std::vector<int>(n, -1)};
  for (int j = 0; j < static_cast<int>(model.joints.size()); ++j) {
    const Joint& joint = model.joints[j];
    const int child = find(joint.child);
    if (child < 0 || tree.parent_joint[child] >= 0) continue;
    const int parent = find(joint.parent);
    if (parent == child) continue;  // A self-loop attaches nothing.
    tree.parent_joint[child] = j;
    tree.parent_link[child] = parent;
  }
  return tree;
}

// The inertia matrix of the six numbers as written (off-diagonals are the file's ixy, ixz, iyz).
Eigen::Matrix3d InertiaMatrix(const Inertial& inertial) {
  Eigen::Matrix3d I;
  I << inertial.ixx, inertial.ixy, inertial.ixz,  //
      inertial.ixy, inertial.iyy, inertial.iyz,   //
      inertial.ixz, inertial.iyz, inertial.izz;
  return I;
}

// m·(|d|²·1 − d·dᵀ): the inertia of a point mass m at d about the origin (PSD for m >= 0).
Eigen::Matrix3d PointMassInertia(double mass, const Eigen::Vector3d& d) {
  return mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
}

}  // namespace

Eigen::Matrix3d CompositeInertia::CalcInertiaAboutOrigin() const {
  return I_SScm_R + PointMassInertia(mass, p_RoScm_R);
}

RotationalInertia<double> CompositeInertia::CalcRotationalInertia() const {
  const Eigen::Matrix3d& I = I_SScm_R;
  return RotationalInertia<double>(I(0, 0), I(1, 1), I(2, 2), I(1, 0), I(2, 0), I(2, 1));
}

SpatialInertia<double> CompositeInertia::CalcSpatialInertia() const {
  return SpatialInertia<double>::MakeFromCentralInertia(mass, p_RoScm_R, CalcRotationalInertia());
}

std::vector<WeldedGroup> FindWeldedGroups(const Model& model) {
  const int n = static_cast<int>(model.links.size());
  const Tree tree = BuildTree(model);
  // fixed_up[i]: the link that i is welded to (its parent through a fixed joint), or -1.
  std::vector<int> fixed_up(n, -1);
  for (int i = 0; i < n; ++i) {
    const int j = tree.parent_joint[i];
    if (j >= 0 && model.joints[j].type == Joint::Type::kFixed) fixed_up[i] = tree.parent_link[i];
  }
  // Iterative walk toward the root with memoization: each link is finished once.
  enum State : char { kUnvisited, kOnPath, kDone };
  std::vector<State> state(n, kUnvisited);
  std::vector<int> root(n, -1);
  std::vector<Pose> X_RL(n);
  std::vector<int> path;
  for (int i = 0; i < n; ++i) {
    if (state[i] == kDone) continue;
    bool restart = true;
    while (restart) {
      restart = false;
      path.clear();
      int cur = i;
      while (cur >= 0 && state[cur] != kDone) {
        if (state[cur] == kOnPath) {
          // A fixed-joint cycle: cut it here and walk again.
          fixed_up[cur] = -1;
          for (int k : path) state[k] = kUnvisited;
          restart = true;
          break;
        }
        state[cur] = kOnPath;
        path.push_back(cur);
        cur = fixed_up[cur];
      }
    }
    for (auto it = path.rbegin(); it != path.rend(); ++it) {
      const int k = *it;
      const int up = fixed_up[k];
      if (up < 0) {
        root[k] = k;
        X_RL[k] = Pose();
      } else {
        root[k] = root[up];
        X_RL[k] = X_RL[up] * model.joints[tree.parent_joint[k]].X_PC;
      }
      state[k] = kDone;
    }
  }

  std::vector<WeldedGroup> groups;
  std::vector<int> group_of(n, -1);
  bool root_group_seen = false;
  for (int i = 0; i < n; ++i) {
    if (root[i] != i) continue;
    group_of[i] = static_cast<int>(groups.size());
    WeldedGroup group;
    group.root_link = model.links[i].name;
    group.links.push_back(i);
    group.X_RL.push_back(Pose());
    const int j = tree.parent_joint[i];
    if (j < 0) {
      // No parent joint: the model's root, or a free-floating link.
      const bool is_model_root =
          model.root_link.empty() ? !root_group_seen : group.root_link == model.root_link;
      root_group_seen = root_group_seen || is_model_root;
      group.is_moving = !is_model_root;
    } else if (model.joints[j].type == Joint::Type::kFixed) {
      group.is_moving = false;  // Welded to something outside the model (the world).
    } else {
      group.parent_joint = j;
      group.is_moving = true;
    }
    groups.push_back(std::move(group));
  }
  for (int i = 0; i < n; ++i) {
    if (root[i] == i) continue;
    WeldedGroup& group = groups[group_of[root[i]]];
    group.links.push_back(i);
    group.X_RL.push_back(X_RL[i]);
  }
  return groups;
}

MassProperties LinkMassProperties(const Link& link, Model::Format format) {
  MassProperties props;
  if (!link.inertial) {
    if (format == Model::Format::kSdf) {
      // SDF specification (link.sdf, inertial.sdf): mass 1, ixx = iyy = izz = 1, products 0.
      props.mass = 1;
      props.I_SScm_F = Eigen::Matrix3d::Identity();
    }
    return props;
  }
  const Inertial& inertial = *link.inertial;
  const Eigen::Matrix3d& R_BBi = inertial.X_BBi.R_AB;
  props.mass = inertial.mass;
  props.p_FoScm_F = inertial.X_BBi.p_AB;
  props.I_SScm_F = R_BBi * InertiaMatrix(inertial) * R_BBi.transpose();
  // Restore exact symmetry lost to round-off in the product.
  props.I_SScm_F = 0.5 * (props.I_SScm_F + props.I_SScm_F.transpose()).eval();
  return props;
}

SpatialInertia<double> LinkSpatialInertia(const Link& link, Model::Format format) {
  const MassProperties props = LinkMassProperties(link, format);
  CompositeInertia composite;
  composite.mass = props.mass;
  composite.p_RoScm_R = props.p_FoScm_F;
  composite.I_SScm_R = props.I_SScm_F;
  return composite.CalcSpatialInertia();
}

CompositeInertia ComposeMassProperties(const std::vector<MassProperties>& parts_in_R) {
  CompositeInertia result;
  // Pass 1: total mass and the mass-weighted sum of the centers of mass.
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
  for (const MassProperties& part : parts_in_R) {
    result.mass += part.mass;
    if (part.mass != 0) weighted += part.mass * part.p_FoScm_F;
  }
  if (result.mass != 0) result.p_RoScm_R = weighted / result.mass;
  // Pass 2: each central inertia shifted away from its own center of mass to the composite one.
  for (const MassProperties& part : parts_in_R) {
    result.I_SScm_R += part.I_SScm_F;
    if (part.mass != 0) {
      result.I_SScm_R += PointMassInertia(part.mass, part.p_FoScm_F - result.p_RoScm_R);
    }
  }
  return result;
}

CompositeInertia CalcCompositeInertia(const Model& model, const WeldedGroup& group) {
  std::vector<MassProperties> parts;
  parts.reserve(group.links.size());
  for (std::size_t k = 0; k < group.links.size(); ++k) {
    const MassProperties props_L = LinkMassProperties(model.links[group.links[k]], model.format);
    if (props_L.mass == 0 && props_L.I_SScm_F.isZero(0)) continue;
    const Pose& X = group.X_RL[k];
    MassProperties props_R;
    props_R.mass = props_L.mass;
    props_R.p_FoScm_F = X.p_AB + X.R_AB * props_L.p_FoScm_F;
    props_R.I_SScm_F = X.R_AB * props_L.I_SScm_F * X.R_AB.transpose();
    parts.push_back(props_R);
  }
  return ComposeMassProperties(parts);
}

std::vector<Pose> CalcLinkPosesInRootFrame(const Model& model, std::vector<bool>* reachable) {
  const int n = static_cast<int>(model.links.size());
  const Tree tree = BuildTree(model);
  std::vector<Pose> X_WL(n);
  std::vector<bool> seen(n, false);
  // Children lists in compressed form (CSR): children of p are child_list[start[p]..start[p+1]).
  std::vector<int> start(n + 1, 0);
  for (int i = 0; i < n; ++i) {
    if (tree.parent_link[i] >= 0) ++start[tree.parent_link[i] + 1];
  }
  for (int i = 0; i < n; ++i) start[i + 1] += start[i];
  std::vector<int> child_list(start[n]);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int i = 0; i < n; ++i) {
    if (tree.parent_link[i] >= 0) child_list[fill[tree.parent_link[i]]++] = i;
  }
  int root = -1;
  for (int i = 0; i < n && root < 0; ++i) {
    if (model.links[i].name == model.root_link) root = i;
  }
  std::vector<int> queue;
  if (root >= 0) {
    queue.push_back(root);
    seen[root] = true;
  }
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const int p = queue[q];
    for (int k = start[p]; k < start[p + 1]; ++k) {
      const int c = child_list[k];
      if (seen[c]) continue;  // Cannot happen in a tree; guards malformed input.
      seen[c] = true;
      X_WL[c] = X_WL[p] * model.joints[tree.parent_joint[c]].X_PC;
      queue.push_back(c);
    }
  }
  if (reachable != nullptr) *reachable = seen;
  return X_WL;
}

ModelCompositeInertia CalcModelCompositeInertia(const Model& model) {
  std::vector<bool> reachable;
  const std::vector<Pose> X_WL = CalcLinkPosesInRootFrame(model, &reachable);
  ModelCompositeInertia result;
  std::vector<MassProperties> parts;
  parts.reserve(model.links.size());
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    if (!reachable[i]) {
      result.unreachable_links.push_back(static_cast<int>(i));
      continue;
    }
    const MassProperties props_L = LinkMassProperties(model.links[i], model.format);
    if (props_L.mass == 0 && props_L.I_SScm_F.isZero(0)) continue;
    const Pose& X = X_WL[i];
    MassProperties props_W;
    props_W.mass = props_L.mass;
    props_W.p_FoScm_F = X.p_AB + X.R_AB * props_L.p_FoScm_F;
    props_W.I_SScm_F = X.R_AB * props_L.I_SScm_F * X.R_AB.transpose();
    parts.push_back(props_W);
  }
  result.inertia = ComposeMassProperties(parts);
  return result;
}

}  // namespace massprops

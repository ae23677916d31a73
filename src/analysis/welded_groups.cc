#include "massprops/analysis/welded_groups.h"

#include <algorithm>
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

// The same, borrowed (from a Tree, or from the report's index of the model).
struct TreeView {
  const std::vector<int>& parent_joint;
  const std::vector<int>& parent_link;
};

Tree BuildTree(const Model& model) {
  const int n = static_cast<int>(model.links.size());
  const internal::NameIndex index(
      n, [&model](int i) -> const std::string& { return model.links[i].name; });
  Tree tree{std::vector<int>(n, -1), std::vector<int>(n, -1)};
  int previous_child = -1;  // hints for a file written in order (NameIndex::Find)
  for (int j = 0; j < static_cast<int>(model.joints.size()); ++j) {
    const Joint& joint = model.joints[j];
    const int child = index.Find(joint.child, previous_child + 1);
    const int parent_hint = previous_child;
    previous_child = child;
    if (child < 0 || tree.parent_joint[child] >= 0) continue;
    const int parent = index.Find(joint.parent, parent_hint);
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

using internal::PointMassInertia;

// fixed_up[i]: the link that i is welded to (its parent through a fixed joint), or -1.
std::vector<int> FixedParents(const Model& model, const TreeView& tree) {
  const int n = static_cast<int>(model.links.size());
  std::vector<int> fixed_up(n, -1);
  for (int i = 0; i < n; ++i) {
    const int j = tree.parent_joint[i];
    if (j >= 0 && model.joints[j].type == Joint::Type::kFixed) fixed_up[i] = tree.parent_link[i];
  }
  return fixed_up;
}

// root[i]: the top of link i's welded group, found by an iterative walk toward the root with
// memoization (each link is finished once). A fixed-joint cycle is cut in *fixed_up where found.
std::vector<int> FindGroupRoots(std::vector<int>* fixed_up) {
  const int n = static_cast<int>(fixed_up->size());
  enum State : char { kUnvisited, kOnPath, kDone };
  std::vector<State> state(n, kUnvisited);
  std::vector<int> root(n, -1);
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
          (*fixed_up)[cur] = -1;
          for (int k : path) state[k] = kUnvisited;
          restart = true;
          break;
        }
        state[cur] = kOnPath;
        path.push_back(cur);
        cur = (*fixed_up)[cur];
      }
    }
    for (auto it = path.rbegin(); it != path.rend(); ++it) {
      const int up = (*fixed_up)[*it];
      root[*it] = up < 0 ? *it : root[up];
      state[*it] = kDone;
    }
  }
  return root;
}

// One group per root link, in file order, with its members (root first, then file order) and,
// with_poses, room for their poses (identity until FillGroupPoses): each vector allocated once,
// at its size. *position: each link's place in its group; *group_of: each root link's group.
std::vector<WeldedGroup> MakeGroups(const Model& model, const TreeView& tree,
                                    const std::vector<int>& root, bool with_poses,
                                    std::vector<int>* position, std::vector<int>* group_of) {
  const int n = static_cast<int>(model.links.size());
  group_of->assign(n, -1);
  std::vector<int> size;  // per group
  for (int i = 0; i < n; ++i) {
    if (root[i] != i) continue;
    (*group_of)[i] = static_cast<int>(size.size());
    size.push_back(0);
  }
  for (int i = 0; i < n; ++i) ++size[(*group_of)[root[i]]];
  std::vector<WeldedGroup> groups(size.size());
  bool root_group_seen = false;
  for (int i = 0; i < n; ++i) {
    if (root[i] != i) continue;
    WeldedGroup& group = groups[(*group_of)[i]];
    group.root_link = model.links[i].name;
    group.links.reserve(size[(*group_of)[i]]);
    group.links.push_back(i);
    if (with_poses) group.X_RL.resize(size[(*group_of)[i]]);
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
  }
  position->assign(n, 0);
  for (int i = 0; i < n; ++i) {
    if (root[i] == i) continue;
    std::vector<int>& links = groups[(*group_of)[root[i]]].links;
    (*position)[i] = static_cast<int>(links.size());
    links.push_back(i);
  }
  return groups;
}

// X_RL of every member L of every group (R: the group's root link), written in place: each link's
// pose is its welded parent's times the fixed joint's X_PC, walking up to a link already posed.
void FillGroupPoses(const Model& model, const TreeView& tree, const std::vector<int>& fixed_up,
                    const std::vector<int>& root, const std::vector<int>& position,
                    const std::vector<int>& group_of, std::vector<WeldedGroup>* groups) {
  const int n = static_cast<int>(model.links.size());
  auto X_RL = [&](int link) -> Pose& {
    return (*groups)[group_of[root[link]]].X_RL[position[link]];
  };
  std::vector<char> posed(n, 0);
  std::vector<int> path;
  for (int i = 0; i < n; ++i) {
    path.clear();
    // fixed_up[k] >= 0 for every link k that is not its group's root (posed: identity).
    for (int cur = i; !posed[cur] && root[cur] != cur; cur = fixed_up[cur]) path.push_back(cur);
    for (auto it = path.rbegin(); it != path.rend(); ++it) {
      X_RL(*it) = X_RL(fixed_up[*it]) * model.joints[tree.parent_joint[*it]].X_PC;
      posed[*it] = 1;
    }
  }
}

// A link's mass properties in its frame L (props_L) re-expressed in frame R (X_RL given); false
// for a link with neither mass nor inertia, which composition leaves out.
bool PartInR(const MassProperties& props_L, const Pose& X_RL, MassProperties* part_R) {
  if (props_L.mass == 0 && props_L.I_SScm_F.isZero(0)) return false;
  part_R->mass = props_L.mass;
  part_R->p_FoScm_F = X_RL.p_AB + X_RL.R_AB * props_L.p_FoScm_F;
  part_R->I_SScm_F = X_RL.R_AB * props_L.I_SScm_F * X_RL.R_AB.transpose();
  return true;
}

// The same, from the link's <inertial>.
bool LinkPartInR(const Link& link, Model::Format format, const Pose& X_RL, MassProperties* part_R) {
  return PartInR(LinkMassProperties(link, format), X_RL, part_R);
}

// The link's center of mass in frame R (X_RL given) and its mass, as LinkPartInR computes them.
double LinkMassAndComInR(const Link& link, Model::Format format, const Pose& X_RL,
                         Eigen::Vector3d* p_RoLcm_R) {
  Eigen::Vector3d p_LoLcm_L;
  const double mass = internal::LinkMassAndCom(link, format, &p_LoLcm_L);
  *p_RoLcm_R = X_RL.p_AB + X_RL.R_AB * p_LoLcm_L;
  return mass;
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
  const Tree tree = BuildTree(model);
  return internal::FindWeldedGroups(model, tree.parent_joint, tree.parent_link);
}

std::vector<WeldedGroup> internal::FindWeldedGroups(const Model& model,
                                                    const std::vector<int>& parent_joint,
                                                    const std::vector<int>& parent_link,
                                                    bool with_poses) {
  const TreeView tree{parent_joint, parent_link};
  std::vector<int> fixed_up = FixedParents(model, tree);
  const std::vector<int> root = FindGroupRoots(&fixed_up);
  std::vector<int> position;  // of each link in its group's `links` and `X_RL`
  std::vector<int> group_of;  // of each group root link
  std::vector<WeldedGroup> groups = MakeGroups(model, tree, root, with_poses, &position, &group_of);
  if (with_poses) FillGroupPoses(model, tree, fixed_up, root, position, group_of, &groups);
  return groups;
}

void internal::CalcGroupPoses(const Model& model, const WeldedGroup& group,
                              const std::vector<int>& parent_joint,
                              const std::vector<int>& parent_link, std::vector<Pose>* X_RL) {
  // FillGroupPoses' walk, within one group: every member but the root is welded to its tree
  // parent (its fixed_up there), a member of the same group; the members after the root are in
  // file order, so a member's place is found by bisection.
  const std::vector<int>& links = group.links;
  auto position_of = [&links](int link) -> std::size_t {
    if (link == links.front()) return 0;
    return static_cast<std::size_t>(std::lower_bound(links.begin() + 1, links.end(), link) -
                                    links.begin());
  };
  X_RL->assign(links.size(), Pose());
  std::vector<char> posed(links.size(), 0);
  posed[0] = 1;
  std::vector<std::size_t> path;
  for (std::size_t k = 1; k < links.size(); ++k) {
    path.clear();
    for (std::size_t cur = k; !posed[cur]; cur = position_of(parent_link[links[cur]])) {
      path.push_back(cur);
    }
    for (auto it = path.rbegin(); it != path.rend(); ++it) {
      (*X_RL)[*it] = (*X_RL)[position_of(parent_link[links[*it]])] *
                     model.joints[parent_joint[links[*it]]].X_PC;
      posed[*it] = 1;
    }
  }
}

namespace {

// The inertial the loader loads: the one written, or what was loaded of one that could not be read
// wholly (Link::loaded_inertial); null when the link has neither.
const Inertial* LoadedInertial(const Link& link) {
  if (link.inertial) return &*link.inertial;
  return link.loaded_inertial ? &*link.loaded_inertial : nullptr;
}

}  // namespace

double internal::LinkMassAndCom(const Link& link, Model::Format format,
                                Eigen::Vector3d* p_BoBcm_B) {
  const Inertial* inertial = LoadedInertial(link);
  if (inertial == nullptr) {
    p_BoBcm_B->setZero();
    return format == Model::Format::kSdf ? 1.0 : 0.0;
  }
  *p_BoBcm_B = inertial->X_BBi.p_AB;
  return inertial->mass;
}

MassProperties LinkMassProperties(const Link& link, Model::Format format) {
  MassProperties props;
  const Inertial* loaded = LoadedInertial(link);
  if (loaded == nullptr) {
    if (format == Model::Format::kSdf) {
      // SDF specification (link.sdf, inertial.sdf): mass 1, ixx = iyy = izz = 1, products 0.
      props.mass = 1;
      props.I_SScm_F = Eigen::Matrix3d::Identity();
    }
    return props;
  }
  const Inertial& inertial = *loaded;
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
  return internal::ComposeMassPropertiesOnDemand(
      parts_in_R.size(),
      [&parts_in_R](std::size_t k, double* mass, Eigen::Vector3d* p_RoPcm_R) {
        *mass = parts_in_R[k].mass;
        *p_RoPcm_R = parts_in_R[k].p_FoScm_F;
        return true;
      },
      [&parts_in_R](std::size_t k, MassProperties* props) {
        *props = parts_in_R[k];
        return true;
      });
}

CompositeInertia CalcCompositeInertia(const Model& model, const WeldedGroup& group) {
  return internal::ComposeMassPropertiesOnDemand(
      group.links.size(),
      [&](std::size_t k, double* mass, Eigen::Vector3d* p_RoLcm_R) {
        *mass =
            LinkMassAndComInR(model.links[group.links[k]], model.format, group.X_RL[k], p_RoLcm_R);
        return true;
      },
      [&](std::size_t k, MassProperties* part_R) {
        return LinkPartInR(model.links[group.links[k]], model.format, group.X_RL[k], part_R);
      });
}

CompositeInertia internal::CalcCompositeInertia(const WeldedGroup& group,
                                                const std::vector<Pose>& X_RL,
                                                const std::vector<MassProperties>& props_by_link) {
  return internal::ComposeMassPropertiesOnDemand(
      group.links.size(),
      [&](std::size_t k, double* mass, Eigen::Vector3d* p_RoLcm_R) {
        // LinkMassAndComInR's arithmetic: LinkMassAndCom gives these same mass and center of mass.
        const MassProperties& props_L = props_by_link[group.links[k]];
        *mass = props_L.mass;
        *p_RoLcm_R = X_RL[k].p_AB + X_RL[k].R_AB * props_L.p_FoScm_F;
        return true;
      },
      [&](std::size_t k, MassProperties* part_R) {
        return PartInR(props_by_link[group.links[k]], X_RL[k], part_R);
      });
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
  queue.reserve(n);
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
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    if (!reachable[i]) result.unreachable_links.push_back(static_cast<int>(i));
  }
  result.inertia = internal::ComposeMassPropertiesOnDemand(
      model.links.size(),
      [&](std::size_t i, double* mass, Eigen::Vector3d* p_WoLcm_W) {
        if (!reachable[i]) return false;
        *mass = LinkMassAndComInR(model.links[i], model.format, X_WL[i], p_WoLcm_W);
        return true;
      },
      [&](std::size_t i, MassProperties* part_W) {
        return reachable[i] && LinkPartInR(model.links[i], model.format, X_WL[i], part_W);
      });
  return result;
}

}  // namespace massprops

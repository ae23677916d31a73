#include "massprops/analysis/mass_report.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "analysis/name_index.h"
#include "analysis/poses_in_file_order.h"
#include "massprops/core/principal_axes.h"

namespace massprops {
namespace {

// The tree of the model as welded_groups.cc sees it: each link's parent joint is the first joint
// in file order that names it as child (self-loops ignored); its parent link is -1 when that
// joint's parent is not a link of the model (SDF "world").
struct ModelIndex {
  explicit ModelIndex(const Model& model)
      : link(static_cast<int>(model.links.size()),
             [&model](int i) -> const std::string& { return model.links[i].name; }) {}
  internal::NameIndex link;
  std::vector<int> parent_joint;
  std::vector<int> parent_link;
  // Children of link p: child_list[child_start[p] .. child_start[p + 1]).
  std::vector<int> child_start;
  std::vector<int> child_list;

  int FindLink(const std::string& name) const { return link.Find(name); }
  bool IsFixedChild(const Model& model, int c) const {
    return parent_joint[c] >= 0 && model.joints[parent_joint[c]].type == Joint::Type::kFixed;
  }
};

ModelIndex BuildIndex(const Model& model) {
  ModelIndex index(model);
  const int n = static_cast<int>(model.links.size());
  index.parent_joint.assign(n, -1);
  index.parent_link.assign(n, -1);
  int previous_child = -1;  // hints for a file written in order (NameIndex::Find)
  for (int j = 0; j < static_cast<int>(model.joints.size()); ++j) {
    const Joint& joint = model.joints[j];
    const int child = index.link.Find(joint.child, previous_child + 1);
    const int parent_hint = previous_child;
    previous_child = child;
    if (child < 0 || index.parent_joint[child] >= 0) continue;
    const int parent = index.link.Find(joint.parent, parent_hint);
    if (parent == child) continue;
    index.parent_joint[child] = j;
    index.parent_link[child] = parent;
  }
  index.child_start.assign(n + 1, 0);
  for (int i = 0; i < n; ++i) {
    if (index.parent_link[i] >= 0) ++index.child_start[index.parent_link[i] + 1];
  }
  for (int i = 0; i < n; ++i) index.child_start[i + 1] += index.child_start[i];
  index.child_list.resize(index.child_start[n]);
  std::vector<int> fill(index.child_start.begin(), index.child_start.end() - 1);
  for (int i = 0; i < n; ++i) {
    if (index.parent_link[i] >= 0) index.child_list[fill[index.parent_link[i]]++] = i;
  }
  return index;
}

// Poses X_AL of links L in the frame of an anchor link A at the configuration, computed on demand
// by walking toward A and memoized, so the cost is that of the paths actually asked for.
class PoseSolver {
 public:
  PoseSolver(const Model& model, const ModelIndex& index,
             const std::unordered_map<int, double>& joint_values, int anchor)
      : model_(model), index_(index), joint_values_(joint_values), anchor_(anchor) {}

  // X_AL; nullopt when L cannot be reached from A going down the tree.
  std::optional<Pose> Get(int link) {
    if (anchor_ < 0 || link < 0) return std::nullopt;
    if (link == anchor_) return Pose();
    if (known_.empty()) {  // First use: one slot per link (no hashing, no node per pose).
      known_.assign(model_.links.size(), 0);
      memo_.resize(model_.links.size());
    }
    path_.clear();
    int cur = link;
    std::optional<Pose> base;
    const std::size_t n = model_.links.size();
    for (;;) {
      if (cur == anchor_) {
        base = Pose();
        break;
      }
      if (cur >= 0 && known_[cur]) {
        base = memo_[cur];
        break;
      }
      if (cur < 0 || path_.size() > n) break;  // Above the root, or a cycle: unreachable.
      path_.push_back(cur);
      cur = index_.parent_link[cur];
    }
    for (auto it = path_.rbegin(); it != path_.rend(); ++it) {
      if (base) {
        const int j = index_.parent_joint[*it];
        const auto q = joint_values_.find(j);
        base = *base * CalcJointPose(model_.joints[j], q == joint_values_.end() ? 0.0 : q->second);
      }
      known_[*it] = 1;
      memo_[*it] = base;
    }
    return base;
  }

 private:
  const Model& model_;
  const ModelIndex& index_;
  const std::unordered_map<int, double>& joint_values_;
  int anchor_;
  std::vector<char> known_;                // per link: memo_ holds its pose (or nullopt)
  std::vector<std::optional<Pose>> memo_;  // per link
  std::vector<int> path_;                  // of the current walk (kept: no allocation per call)
};

// The group of links welded to `root` below it (root first, the others in file order), with
// their poses in root's frame. Follows only fixed joints down the tree.
WeldedGroup CollectGroupBelow(const Model& model, const ModelIndex& index, int root) {
  std::vector<std::pair<int, Pose>> members{{root, Pose()}};
  std::unordered_set<int> seen{root};
  for (std::size_t k = 0; k < members.size(); ++k) {
    const int p = members[k].first;
    for (int c_pos = index.child_start[p]; c_pos < index.child_start[p + 1]; ++c_pos) {
      const int c = index.child_list[c_pos];
      if (!index.IsFixedChild(model, c) || !seen.insert(c).second) continue;
      members.emplace_back(c, members[k].second * model.joints[index.parent_joint[c]].X_PC);
    }
  }
  std::sort(members.begin() + 1, members.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  WeldedGroup group;
  group.root_link = model.links[root].name;
  for (const auto& [link, X_RL] : members) {
    group.links.push_back(link);
    group.X_RL.push_back(X_RL);
  }
  group.parent_joint = index.parent_joint[root];
  return group;
}

// The body's mass properties given in frame A, re-expressed in frame F (X_FA given).
BodyMassProperties ReExpress(const BodyMassProperties& body_A, const std::string& frame_F,
                             const Pose& X_FA) {
  const Eigen::Matrix3d& R = X_FA.R_AB;
  Eigen::Matrix3d I_F = R * body_A.inertia_about_com * R.transpose();
  I_F = (0.5 * (I_F + I_F.transpose())).eval();
  BodyMassProperties body_F =
      MakeBodyMassProperties(frame_F, body_A.mass, X_FA.p_AB + R * body_A.com, I_F);
  body_F.unknown = body_A.unknown;
  return body_F;
}

// A link's mass properties in its frame L re-expressed in frame A (X_AL given), the inertia made
// exactly symmetric again.
MassProperties InFrameA(const MassProperties& props_L, const Pose& X_AL) {
  MassProperties props_A;
  props_A.mass = props_L.mass;
  props_A.p_FoScm_F = X_AL.p_AB + X_AL.R_AB * props_L.p_FoScm_F;
  props_A.I_SScm_F = X_AL.R_AB * props_L.I_SScm_F * X_AL.R_AB.transpose();
  props_A.I_SScm_F = (0.5 * (props_A.I_SScm_F + props_A.I_SScm_F.transpose())).eval();
  return props_A;
}

BodyMassProperties FromComposite(const std::string& frame, const CompositeInertia& c) {
  return MakeBodyMassProperties(frame, c.mass, c.p_RoScm_R, c.I_SScm_R);
}

}  // namespace

std::optional<Eigen::Vector3d> CalcEquivalentBox(double mass, const Eigen::Vector3d& moments) {
  if (!(mass > 0) || !std::isfinite(mass) || !moments.allFinite()) return std::nullopt;
  const double tolerance = 32 * std::numeric_limits<double>::epsilon() * moments.cwiseAbs().sum();
  if ((moments.array() < -tolerance).any()) return std::nullopt;
  Eigen::Vector3d sides;
  for (int k = 0; k < 3; ++k) {
    const double excess = moments.sum() - 2 * moments(k);  // I_i + I_j − I_k
    if (excess < -tolerance) return std::nullopt;
    sides(k) = std::sqrt(6 * std::max(excess, 0.0) / mass);
  }
  return sides;
}

unsigned BodyUnknownOf(unsigned inertial_unknown) {
  unsigned unknown = 0;
  if (inertial_unknown & kInertialMass) unknown |= kUnknownMass | kUnknownCom | kUnknownInertia;
  if (inertial_unknown & kInertialPosition) unknown |= kUnknownCom | kUnknownInertia;
  if (inertial_unknown != 0) unknown |= kUnknownInertia;
  return unknown;
}

BodyMassProperties MakeBodyMassProperties(const std::string& frame, double mass,
                                          const Eigen::Vector3d& p_FoScm_F,
                                          const Eigen::Matrix3d& I_SScm_F) {
  BodyMassProperties body;
  body.frame = frame;
  body.mass = mass;
  body.com = p_FoScm_F;
  body.inertia_about_com = I_SScm_F;
  if (I_SScm_F.allFinite()) {
    const auto [moments, axes] = CalcSymmetricEigensystem<double>(I_SScm_F);
    body.principal_moments = moments;
    body.principal_axes = axes;
  } else {
    body.principal_moments.setConstant(std::numeric_limits<double>::quiet_NaN());
    body.principal_axes.setConstant(std::numeric_limits<double>::quiet_NaN());
  }
  body.equivalent_box = CalcEquivalentBox(mass, body.principal_moments);
  const double shift = mass * p_FoScm_F.squaredNorm();
  if (mass > 0 && std::isfinite(shift) && shift > 0 && std::isfinite(I_SScm_F.trace())) {
    // The floor eps·m·|c|² caps the estimate at all ~15.7 digits of a double (a point mass).
    const double floor = std::max(std::numeric_limits<double>::min(),
                                  std::numeric_limits<double>::epsilon() * shift);
    body.digits_lost = std::max(0.0, std::log10(shift / std::max(I_SScm_F.trace(), floor)));
  }
  return body;
}

Pose CalcJointPose(const Joint& joint, double q) {
  if (q == 0) return joint.X_PC;
  Pose X_CCq;  // the child frame at q, in the child frame at 0
  switch (joint.type) {
    case Joint::Type::kRevolute:
    case Joint::Type::kContinuous:
      X_CCq.R_AB = Eigen::AngleAxisd(q, joint.axis).toRotationMatrix();
      break;
    case Joint::Type::kPrismatic:
      X_CCq.p_AB = joint.axis * q;
      break;
    default:
      throw std::invalid_argument("joint '" + joint.name + "' of type '" + joint.type_name +
                                  "' cannot be given a value");
  }
  return joint.X_PC * X_CCq;
}

namespace {

// The links named by --frame, --subtree and --only (-1 or empty when not given).
struct NamedLinks {
  int frame = -1;
  int subtree = -1;
  std::vector<int> only;  // without repeats, in the order given
};

// The values of options.joint_values by joint number; false (with *error) when one of them names
// no joint of the model, a joint that takes no value, or is not finite.
bool ParseJointValues(const Model& model, const MassReportOptions& options,
                      std::unordered_map<int, double>* joint_values, std::string* error) {
  // A few names (the usual case) are looked for by one pass over the joints each; more through
  // an index of all the joint names. Either way, of joints with the same name the first.
  constexpr std::size_t kMaxScans = 4;
  std::optional<internal::NameIndex> joint_index;
  if (options.joint_values.size() > kMaxScans) {
    joint_index.emplace(static_cast<int>(model.joints.size()),
                        [&model](int j) -> const std::string& { return model.joints[j].name; });
  }
  auto find_joint = [&](const std::string& name) {
    if (joint_index) return joint_index->Find(name);
    for (std::size_t j = 0; j < model.joints.size(); ++j) {
      if (model.joints[j].name == name) return static_cast<int>(j);
    }
    return -1;
  };
  for (const auto& [name, value] : options.joint_values) {
    const int joint_number = find_joint(name);
    if (joint_number < 0) {
      *error = "model '" + model.name + "' has no joint named '" + name + "'";
      return false;
    }
    const Joint& joint = model.joints[joint_number];
    if (joint.type == Joint::Type::kFixed) {
      *error = "joint '" + name + "' is fixed: it has no value to set";
      return false;
    }
    if (joint.type != Joint::Type::kRevolute && joint.type != Joint::Type::kContinuous &&
        joint.type != Joint::Type::kPrismatic) {
      *error = "joint '" + name + "' is of type '" + joint.type_name +
               "': only revolute, continuous and prismatic joints take a value";
      return false;
    }
    if (!std::isfinite(value)) {
      *error = "the value of joint '" + name + "' is not finite";
      return false;
    }
    joint_values->emplace(joint_number, value);
  }
  return true;
}

// The links of --frame, --subtree and --only; false (with *error) when one is not in the model.
bool FindNamedLinks(const Model& model, const ModelIndex& index, const MassReportOptions& options,
                    NamedLinks* named, std::string* error) {
  auto find_link = [&](const std::string& name, const char* what, int* out) {
    *out = index.FindLink(name);
    if (*out < 0)
      *error = std::string(what) + ": model '" + model.name + "' has no link '" + name + "'";
    return *out >= 0;
  };
  if (!options.frame.empty() && !find_link(options.frame, "--frame", &named->frame)) return false;
  if (!options.subtree.empty() && !find_link(options.subtree, "--subtree", &named->subtree)) {
    return false;
  }
  for (const std::string& name : options.only) {
    int link = -1;
    if (!find_link(name, "--only", &link)) return false;
    if (std::find(named->only.begin(), named->only.end(), link) == named->only.end()) {
      named->only.push_back(link);
    }
  }
  return true;
}

// Re-expresses mass properties given in a link's frame in the frame of the --frame link F (when
// one is given), at the configuration, through the poses of the links in the root link's frame W.
class FrameExpresser {
 public:
  FrameExpresser(const Model& model, const ModelIndex& index,
                 const std::unordered_map<int, double>& joint_values,
                 const MassReportOptions& options, int frame, std::string* error)
      : model_(model),
        options_(options),
        frame_(frame),
        error_(error),
        root_poses_(model, index, joint_values, index.FindLink(model.root_link)) {}

  // Finds X_WF; false (with *error) when F is not connected to the root link.
  bool Init() {
    if (frame_ < 0) return true;
    X_WF_ = root_poses_.Get(frame_);
    if (!X_WF_) {
      *error_ = "--frame: link '" + options_.frame + "' is not connected to the root link '" +
                model_.root_link + "'";
      return false;
    }
    return true;
  }

  // Whether link A's pose is known (else sets *error), so that InFrame can re-express from A.
  bool CanExpress(int link_A) {
    if (frame_ < 0 || link_A == frame_) return true;
    if (!root_poses_.Get(link_A)) {
      *error_ = "--frame: link '" + model_.links[link_A].name +
                "' is not connected to the root link '" + model_.root_link + "'";
      return false;
    }
    return true;
  }

  // `body_A`, given in the frame of link A, in F (unchanged without --frame).
  BodyMassProperties InFrame(const BodyMassProperties& body_A, int link_A) {
    if (frame_ < 0 || link_A == frame_) return body_A;
    const Pose X_FA = X_WF_->Inverse() * *root_poses_.Get(link_A);
    return ReExpress(body_A, options_.frame, X_FA);
  }

 private:
  const Model& model_;
  const MassReportOptions& options_;
  int frame_;
  std::string* error_;
  PoseSolver root_poses_;
  std::optional<Pose> X_WF_;
};

// Each link's mass properties in its own frame, as LinkMassProperties gives them. In a full report
// (every link, in file order) each link's are computed once, while its entry is made, and kept
// (104 bytes a link, read back in order) for its group's composite and for the total: the report
// reads each Link's <inertial> once instead of four times, which at 10^5-10^6 links is a read of
// the 448-byte Link from memory each time (docs/benchmarks.md, section 2). With --only or
// --subtree they are computed on demand (the work stays proportional to what is asked).
class LinkPropsTable {
 public:
  LinkPropsTable(const Model& model, bool keep) : model_(model), keep_(keep) {
    if (keep_) props_.reserve(model.links.size());
  }

  // The link's, computed; when kept, links must come in order 0, 1, 2, ...
  const MassProperties& Add(int link) {
    if (!keep_) return Get(link);
    const Link& l = model_.links[link];
    if (l.inertial_unreadable) unknown_.emplace_back(link, UnknownInertialNumbers(l));
    return props_.emplace_back(LinkMassProperties(l, model_.format));
  }
  // Whether a link may have unknown numbers (when kept: whether one added has).
  bool AnyUnknown() const { return !keep_ || !unknown_.empty(); }
  // The link's unknown numbers (Inertial::unknown bits); when kept, once the link is added.
  unsigned InertialUnknown(int link) const {
    if (!keep_) return UnknownInertialNumbers(model_.links[link]);
    const auto found = std::lower_bound(unknown_.begin(), unknown_.end(), std::make_pair(link, 0u));
    return found != unknown_.end() && found->first == link ? found->second : 0;
  }
  // What of the composite of `links` is unknown (kUnknown* bits); their names with unknown
  // numbers appended to *names.
  unsigned CompositeUnknown(const std::vector<int>& links, std::vector<std::string>* names) const {
    if (!AnyUnknown()) return 0;
    unsigned unknown = 0;
    for (int link : links) {
      const unsigned numbers = InertialUnknown(link);
      if (numbers == 0) continue;
      unknown |= BodyUnknownOf(numbers);
      names->push_back(model_.links[link].name);
    }
    return unknown;
  }
  // The link's (when not kept: valid until the next call).
  const MassProperties& Get(int link) {
    if (keep_) return props_[link];
    scratch_ = LinkMassProperties(model_.links[link], model_.format);
    return scratch_;
  }
  // The group's composite, as CalcCompositeInertia(model, group) (bit for bit). A group whose
  // X_RL was not kept (internal::FindWeldedGroups without poses) has them made here, one group at
  // a time in one reused vector, from the tree in `index`.
  CompositeInertia Composite(const WeldedGroup& group, const ModelIndex& index) {
    if (!keep_) return CalcCompositeInertia(model_, group);
    if (group.X_RL.size() == group.links.size()) {
      return internal::CalcCompositeInertia(group, group.X_RL, props_);
    }
    internal::CalcGroupPoses(model_, group, index.parent_joint, index.parent_link, &X_RL_);
    return internal::CalcCompositeInertia(group, X_RL_, props_);
  }

 private:
  const Model& model_;
  bool keep_;
  std::vector<MassProperties> props_;              // per link, when kept
  std::vector<std::pair<int, unsigned>> unknown_;  // (link, its unknown numbers), when kept
  MassProperties scratch_;
  std::vector<Pose> X_RL_;  // of the group at hand (Composite)
};

// The top of the welded group holding `link`: up the tree through fixed joints.
int GroupTop(const Model& model, const ModelIndex& index, int link) {
  int top = link;
  for (std::size_t steps = 0; index.IsFixedChild(model, top) && steps <= model.links.size();
       ++steps) {
    const int up = index.parent_link[top];
    if (up < 0) break;
    top = up;
  }
  return top;
}

// Which links and welded groups are reported: those of --only, of --subtree, or all of them.
void SelectLinksAndGroups(const Model& model, const ModelIndex& index, const NamedLinks& named,
                          std::vector<int>* links, std::vector<WeldedGroup>* groups) {
  if (!named.only.empty()) {
    *links = named.only;
    std::unordered_set<int> group_roots;
    for (int link : named.only) {
      const int top = GroupTop(model, index, link);
      if (group_roots.insert(top).second) groups->push_back(CollectGroupBelow(model, index, top));
    }
  } else if (named.subtree >= 0) {
    links->push_back(named.subtree);
    std::unordered_set<int> seen{named.subtree};
    for (std::size_t k = 0; k < links->size(); ++k) {
      const int p = (*links)[k];
      for (int pos = index.child_start[p]; pos < index.child_start[p + 1]; ++pos) {
        if (seen.insert(index.child_list[pos]).second) links->push_back(index.child_list[pos]);
      }
    }
    std::sort(links->begin(), links->end());
    for (int link : *links) {
      if (link == named.subtree || !index.IsFixedChild(model, link)) {
        groups->push_back(CollectGroupBelow(model, index, link));
      }
    }
  } else {
    links->resize(model.links.size());
    for (std::size_t i = 0; i < links->size(); ++i) (*links)[i] = static_cast<int>(i);
    // Without poses: each group's are made when its composite is (LinkPropsTable::Composite).
    *groups = internal::FindWeldedGroups(model, index.parent_joint, index.parent_link,
                                         /*with_poses=*/false);
  }
}

// Fills report->links and report->welded_groups; false (with the expresser's error) when one
// cannot be expressed in the --frame link's frame.
bool ReportLinksAndGroups(const Model& model, const ModelIndex& index,
                          const MassReportOptions& options, const std::vector<int>& links,
                          const std::vector<WeldedGroup>& groups, LinkPropsTable* table,
                          FrameExpresser* frame, ModelMassReport* report) {
  // Reserved: growing the vector re-copied every entry so far at each reallocation, with the page
  // faults of the new blocks (docs/benchmarks.md, section 2).
  report->links.reserve(links.size());
  report->welded_groups.reserve(groups.size());
  for (int link : links) {
    const MassProperties& props = table->Add(link);
    BodyMassProperties body =
        MakeBodyMassProperties(model.links[link].name, props.mass, props.p_FoScm_F, props.I_SScm_F);
    body.unknown = BodyUnknownOf(table->InertialUnknown(link));
    if (!frame->CanExpress(link)) return false;
    LinkMassReport& entry = report->links.emplace_back();  // in place: the entry is large
    entry.name = model.links[link].name;
    entry.properties = frame->InFrame(body, link);
    if (options.geometry != nullptr) {
      entry.geometry = std::make_shared<const LinkGeometryComparison>(
          CompareLinkWithGeometry(model.links[link], *options.geometry));
    }
  }
  for (const WeldedGroup& group : groups) {
    BodyMassProperties body = FromComposite(group.root_link, table->Composite(group, index));
    if (!frame->CanExpress(group.links.front())) return false;
    GroupMassReport& entry = report->welded_groups.emplace_back();
    body.unknown = table->CompositeUnknown(group.links, &entry.incomplete_links);
    entry.root_link = group.root_link;
    entry.links.reserve(group.links.size());
    for (int link : group.links) entry.links.push_back(model.links[link].name);
    entry.properties = frame->InFrame(body, group.links.front());
  }
  return true;
}

// Fills report->total: every link of `links` at its pose in the frame of link `anchor` (-1: the
// model's root link is not a link), and report->unreachable_links; false (with the expresser's
// error) when the total cannot be expressed in the --frame link's frame.
bool ReportTotal(const Model& model, const ModelIndex& index,
                 const std::unordered_map<int, double>& joint_values, int anchor,
                 const std::vector<int>& links, LinkPropsTable* table, FrameExpresser* frame,
                 ModelMassReport* report) {
  // Each part made twice on demand (its pose too) rather than stored: see
  // internal::ComposeMassPropertiesOnDemand. A full report of a model written parents first
  // makes the poses in file order without keeping one per link (internal::PosesInFileOrder);
  // the others ask PoseSolver, which remembers every pose.
  const bool in_file_order = links.size() == model.links.size() && anchor >= 0 &&
                             internal::PosesInFileOrder::Applies(index.parent_link);
  std::optional<internal::PosesInFileOrder> stream;
  std::optional<PoseSolver> solver;
  if (in_file_order) {
    stream.emplace(index.parent_link, anchor);
  } else {
    solver.emplace(model, index, joint_values, anchor);
    for (int link : links) {
      if (!solver->Get(link)) report->unreachable_links.push_back(model.links[link].name);
    }
  }
  // X_AL of links[k], k = 0, 1, 2, ... in each pass; nullopt when not reachable from A.
  auto pose = [&](std::size_t k) -> std::optional<Pose> {
    if (!in_file_order) return solver->Get(links[k]);
    if (k == 0) stream->Restart();
    const Pose* X_AL = stream->Next(links[k], [&] {
      const int j = index.parent_joint[links[k]];
      const auto q = joint_values.find(j);
      return CalcJointPose(model.joints[j], q == joint_values.end() ? 0.0 : q->second);
    });
    return X_AL != nullptr ? std::optional<Pose>(*X_AL) : std::nullopt;
  };
  const CompositeInertia composite = internal::ComposeMassPropertiesOnDemand(
      links.size(),
      [&](std::size_t k, double* mass, Eigen::Vector3d* p_AoLcm_A) {
        const std::optional<Pose> X_AL = pose(k);
        if (!X_AL) {
          if (in_file_order) report->unreachable_links.push_back(model.links[links[k]].name);
          return false;
        }
        // LinkMassAndCom's mass and center of mass, which are LinkMassProperties'.
        const MassProperties& props_L = table->Get(links[k]);
        *mass = props_L.mass;
        *p_AoLcm_A = X_AL->p_AB + X_AL->R_AB * props_L.p_FoScm_F;
        return true;
      },
      [&](std::size_t k, MassProperties* props_A) {
        const std::optional<Pose> X_AL = pose(k);
        if (!X_AL) return false;
        *props_A = InFrameA(table->Get(links[k]), *X_AL);
        return true;
      });
  const std::string anchor_name = anchor >= 0 ? model.links[anchor].name : model.root_link;
  BodyMassProperties total = FromComposite(anchor_name, composite);
  // The links left out of the total (unreachable) do not make it incomplete.
  std::vector<int> included;
  if (table->AnyUnknown()) {
    included.reserve(links.size());
    for (int link : links) {
      if (std::find(report->unreachable_links.begin(), report->unreachable_links.end(),
                    model.links[link].name) == report->unreachable_links.end()) {
        included.push_back(link);
      }
    }
  }
  total.unknown = table->CompositeUnknown(included, &report->total_incomplete_links);
  if (anchor >= 0 && !frame->CanExpress(anchor)) return false;
  report->total = anchor >= 0 ? frame->InFrame(total, anchor) : total;
  return true;
}

}  // namespace

bool ComputeMassReport(const Model& model, const MassReportOptions& options,
                       ModelMassReport* report, std::string* error) {
  *report = ModelMassReport();
  report->name = model.name;
  report->file = model.file;
  if (!options.only.empty() && !options.subtree.empty()) {
    *error = "--only and --subtree cannot be combined";
    return false;
  }
  const ModelIndex index = BuildIndex(model);
  std::unordered_map<int, double> joint_values;
  if (!ParseJointValues(model, options, &joint_values, error)) return false;
  NamedLinks named;
  if (!FindNamedLinks(model, index, options, &named, error)) return false;
  FrameExpresser frame(model, index, joint_values, options, named.frame, error);
  if (!frame.Init()) return false;

  std::vector<int> links;
  std::vector<WeldedGroup> groups;
  SelectLinksAndGroups(model, index, named, &links, &groups);
  // A full report (every link in file order) keeps each link's mass properties for the groups
  // and the total.
  LinkPropsTable table(model, named.only.empty() && named.subtree < 0);
  if (!ReportLinksAndGroups(model, index, options, links, groups, &table, &frame, report)) {
    return false;
  }
  if (!named.only.empty()) return true;

  // The total: every link of the model (or subtree) at its pose in the anchor's frame.
  const int root = index.FindLink(model.root_link);
  const int anchor = named.subtree >= 0 ? named.subtree : root;
  return ReportTotal(model, index, joint_values, anchor, links, &table, &frame, report);
}

// ------------------------------------------------------------------------------ geometry
std::optional<double> CalcPrincipalAxisAngle(const Eigen::Vector3d& moments_A,
                                             const Eigen::Matrix3d& axes_A,
                                             const Eigen::Vector3d& moments_B,
                                             const Eigen::Matrix3d& axes_B, double rel_gap) {
  // Which adjacent pairs (0-1, 1-2) of ascending moments count as equal.
  auto equal_pairs = [rel_gap](const Eigen::Vector3d& m, bool eq[2]) {
    const double scale = std::max({std::abs(m(0)), std::abs(m(1)), std::abs(m(2))});
    eq[0] = !(std::abs(m(1) - m(0)) > rel_gap * scale);
    eq[1] = !(std::abs(m(2) - m(1)) > rel_gap * scale);
  };
  bool eq_A[2], eq_B[2];
  equal_pairs(moments_A, eq_A);
  equal_pairs(moments_B, eq_B);
  constexpr double kDegrees = 180.0 / 3.14159265358979323846;
  if (!eq_A[0] && !eq_A[1] && !eq_B[0] && !eq_B[1]) {
    // R = A^T B maps B's axes into A's; flipping two axes of B keeps it a rotation. The rotation
    // angle θ satisfies trace(R) = 1 + 2 cos θ.
    const Eigen::Matrix3d R = axes_A.transpose() * axes_B;
    double best = 180;
    const double signs[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    for (const auto& d : signs) {
      const double trace = d[0] * R(0, 0) + d[1] * R(1, 1) + d[2] * R(2, 2);
      const double c = std::clamp((trace - 1) / 2, -1.0, 1.0);
      best = std::min(best, std::acos(c) * kDegrees);
    }
    return best;
  }
  // Exactly one equal pair in each, the same pair: the remaining distinct axis is defined.
  if (eq_A[0] != eq_A[1] && eq_B[0] == eq_A[0] && eq_B[1] == eq_A[1]) {
    const int k = eq_A[0] ? 2 : 0;
    const double c = std::min(1.0, std::abs(axes_A.col(k).dot(axes_B.col(k))));
    return std::acos(c) * kDegrees;
  }
  return std::nullopt;
}

LinkGeometryComparison CompareLinkWithGeometry(const Link& link,
                                               const MeshResolveOptions& options) {
  LinkGeometryComparison result;
  const double mass = link.inertial ? link.inertial->mass : 0;
  if (!(mass > 0) || !std::isfinite(mass)) {
    result.error = "the link declares no positive mass to give its geometry";
    return result;
  }
  std::string error;
  const std::optional<LinkGeometryInertia> implied =
      CalcLinkGeometryInertia(link, mass, options, &error);
  if (!implied) {
    result.error = error.empty() ? "the link's geometry gives no inertia" : error;
    return result;
  }
  result.from_collision = implied->from_collision;
  // implied->geometries are the link's geometries of the chosen kind, in file order.
  std::size_t part = 0;
  for (const Geometry& g : link.geometries) {
    if (g.is_collision != implied->from_collision) continue;
    if (part >= implied->geometries.size()) break;
    const GeometryMassProperties& used = implied->geometries[part++];
    if (g.type == Geometry::Type::kMesh && used.mesh_diagnostics) {
      result.meshes.push_back({g.uri, used.mesh_path, *used.mesh_diagnostics, used.mesh_found_by});
    }
  }
  result.geometry = MakeBodyMassProperties(link.name, mass, implied->p_BoBcm_B,
                                           implied->I_BBcm_B.CopyToFullMatrix3());
  // The declared inertia, about its center of mass, expressed in B: R_BBi I_Bi R_BBi^T.
  const Inertial& in = *link.inertial;
  Eigen::Matrix3d I_Bi;
  I_Bi << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  const Eigen::Matrix3d& R = in.X_BBi.R_AB;
  const BodyMassProperties declared =
      MakeBodyMassProperties(link.name, mass, in.X_BBi.p_AB, R * I_Bi * R.transpose());
  result.declared_moments = declared.principal_moments;
  for (int k = 0; k < 3; ++k) {
    const double g = result.geometry.principal_moments(k);
    result.moment_rel_diff(k) =
        g != 0 ? (declared.principal_moments(k) - g) / g : std::numeric_limits<double>::quiet_NaN();
  }
  result.axis_angle_deg =
      CalcPrincipalAxisAngle(declared.principal_moments, declared.principal_axes,
                             result.geometry.principal_moments, result.geometry.principal_axes);
  return result;
}

}  // namespace massprops

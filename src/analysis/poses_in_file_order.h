#pragma once
// Private to the library: the poses X_AL of a model's links L in the frame of an anchor link A,
// made for link 0, 1, 2, ... in turn, for a model whose every link comes after its parent link in
// file order (the usual file). Each pose is its parent's times its joint's, X_AP * X_PL, the
// arithmetic of the report's PoseSolver, which keeps a pose per link, so bit for bit its poses;
// but only the poses of links with children still to come are kept (a chain: one). The memo's 104
// bytes per link were fresh memory on every call of a full report above ~10^5 links, which the
// kernel maps and clears page by page (docs/benchmarks.md, section 2).

#include <cstddef>
#include <vector>

#include "massprops/model/model.h"

namespace massprops::internal {

class PosesInFileOrder {
 public:
  /// Whether the links can be walked so: every link's parent link (parent_link[i], −1: none)
  /// comes before it.
  static bool Applies(const std::vector<int>& parent_link) {
    for (std::size_t i = 0; i < parent_link.size(); ++i) {
      if (parent_link[i] >= static_cast<int>(i)) return false;
    }
    return true;
  }

  /// Precondition: Applies(parent_link); `parent_link` outlives this object. `anchor`: the link
  /// A (−1: none, every link unreachable).
  PosesInFileOrder(const std::vector<int>& parent_link, int anchor)
      : parent_link_(parent_link),
        anchor_(anchor),
        last_child_(parent_link.size(), -1),
        slot_of_(parent_link.size(), -1) {
    for (std::size_t i = 0; i < parent_link.size(); ++i) {
      if (parent_link[i] >= 0) last_child_[parent_link[i]] = static_cast<int>(i);
    }
  }

  /// Begins again at link 0.
  void Restart() {
    for (int link = 0; link < next_; ++link) slot_of_[link] = -1;
    pool_.clear();
    free_slots_.clear();
    next_ = 0;
  }

  /// X_AL of link `link`, which must be 0 after construction or Restart() and then the link
  /// after the previous call's; nullptr when L cannot be reached from A going down the tree
  /// (valid until the next call). `joint_pose()` gives X_PL of the joint to L's parent P; it is
  /// called only when P's pose is known.
  template <typename JointPose>
  const Pose* Next(int link, JointPose joint_pose) {
    next_ = link + 1;
    const int parent = parent_link_[link];
    const int parent_slot = parent >= 0 ? slot_of_[parent] : -1;
    const Pose* X_AL = nullptr;
    if (link == anchor_) {
      current_ = Pose();
      X_AL = &current_;
    } else if (parent_slot >= 0) {
      current_ = pool_[parent_slot] * joint_pose();
      X_AL = &current_;
    }
    // The parent's pose is not needed after its last child; this link's is kept while it has
    // children to come.
    if (parent_slot >= 0 && last_child_[parent] == link) {
      free_slots_.push_back(parent_slot);
      slot_of_[parent] = -1;
    }
    if (X_AL != nullptr && last_child_[link] >= 0) {
      if (free_slots_.empty()) {
        slot_of_[link] = static_cast<int>(pool_.size());
        pool_.push_back(current_);
      } else {
        slot_of_[link] = free_slots_.back();
        free_slots_.pop_back();
        pool_[slot_of_[link]] = current_;
      }
    }
    return X_AL;
  }

 private:
  const std::vector<int>& parent_link_;
  int anchor_;
  std::vector<int> last_child_;  // per link: its child with the largest index, or −1
  std::vector<int> slot_of_;     // per link: where pool_ keeps its pose, or −1
  std::vector<Pose> pool_;
  std::vector<int> free_slots_;  // of pool_
  int next_ = 0;
  Pose current_;
};

}  // namespace massprops::internal

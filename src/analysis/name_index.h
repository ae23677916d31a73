#pragma once
// Private to the library: names (of links, of joints) to their positions, for the analyses that
// look up every joint's parent and child. An open-addressing table of 4-byte slots with the
// names' hashes kept beside them, built once per call: each lookup touches one slot (the table
// is 8 bytes per name, so 10^5 names fit in cache) and compares strings only when the hashes
// agree. std::unordered_map<std::string, int> allocated a node (and, for names over 15
// characters, a copy of the name) per name and chased pointers on every lookup, which made
// welded groups and the report grow 55x for 10x links (docs/benchmarks.md).

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace massprops::internal {

class NameIndex {
 public:
  /// Indexes name_of(0) .. name_of(count − 1), which must outlive the index; of equal names the
  /// first is kept (as std::unordered_map::emplace does).
  template <typename NameOf>
  NameIndex(int count, NameOf name_of) {
    std::size_t capacity = 16;
    while (capacity < 2 * static_cast<std::size_t>(count)) capacity *= 2;
    slots_.assign(capacity, -1);
    mask_ = capacity - 1;
    names_.reserve(count);
    hashes_.reserve(count);
    for (int i = 0; i < count; ++i) {
      const std::string_view name = name_of(i);
      const std::size_t hash = std::hash<std::string_view>{}(name);
      names_.push_back(name);
      hashes_.push_back(hash);
      std::size_t pos = hash & mask_;
      bool duplicate = false;
      for (int k; (k = slots_[pos]) >= 0; pos = (pos + 1) & mask_) {
        if (hashes_[k] == hash && names_[k] == name) {
          duplicate = true;
          break;
        }
      }
      if (duplicate) {
        has_duplicates_ = true;
      } else {
        slots_[pos] = i;
      }
    }
  }

  /// The position of `name`, or −1; tries position `hint` first (any int), which costs one string
  /// comparison and, when it is right, spares the hashing and the table's cache miss. Analyses
  /// pass where the name usually is in a file written in order (a joint's child is the link after
  /// the previous joint's child, its parent that child). Without repeated names the name at
  /// `hint` is the answer; with repeated names the hint is not used (the first must be found).
  int Find(std::string_view name, int hint) const {
    if (!has_duplicates_ && hint >= 0 && static_cast<std::size_t>(hint) < names_.size() &&
        names_[hint] == name) {
      return hint;
    }
    return Find(name);
  }

  /// The position of `name`, or −1.
  int Find(std::string_view name) const {
    const std::size_t hash = std::hash<std::string_view>{}(name);
    for (std::size_t pos = hash & mask_;; pos = (pos + 1) & mask_) {
      const int k = slots_[pos];
      if (k < 0) return -1;
      if (hashes_[k] == hash && names_[k] == name) return k;
    }
  }

 private:
  std::vector<int> slots_;  // a position, or −1 for an empty slot (at most half are full)
  std::size_t mask_ = 0;
  std::vector<std::string_view> names_;
  std::vector<std::size_t> hashes_;
  bool has_duplicates_ = false;  // some name is given more than once
};

}  // namespace massprops::internal

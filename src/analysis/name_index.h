#pragma once
// Private to the library: names (of links, of joints) to their positions, for the analyses that
// look up every joint's parent and child. An open-addressing table of 8-byte slots (a position
// and 32 bits of its name's hash), built once per call: each lookup touches one slot (the table
// is 16 bytes per name, so 10^5 names fit in cache) and compares strings only when the hash bits
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
    slots_.assign(capacity, Slot{-1, 0});
    mask_ = capacity - 1;
    names_.reserve(count);
    // Pipelined, kAhead names apart: name a is read and hashed (its string prefetched kAhead
    // names before) and its slot prefetched, while name a − kAhead, whose slot has had time to
    // arrive, is inserted. Above ~10^5 names the table is out of cache and each insertion waited
    // for a random slot; the order of insertions, and so the table, is that of a plain loop.
    constexpr int kAhead = 16;
    std::size_t hashes[kAhead];  // of names a − kAhead + 1 .. a, by position modulo kAhead
    for (int a = 0; a < count + kAhead; ++a) {
      const int b = a - kAhead;
      if (b >= 0) Insert(b, hashes[b % kAhead]);
      if (a >= count) continue;
      const std::string_view name = name_of(a);
      names_.push_back(name);
      hashes[a % kAhead] = std::hash<std::string_view>{}(name);
#if defined(__GNUC__)
      // Hints only: no effect on the table.
      if (a + kAhead < count) __builtin_prefetch(&name_of(a + kAhead));
      __builtin_prefetch(&slots_[hashes[a % kAhead] & mask_]);
#endif
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
      const Slot& slot = slots_[pos];
      if (slot.position < 0) return -1;
      if (slot.tag == Tag(hash) && names_[slot.position] == name) return slot.position;
    }
  }

 private:
  // A position and bits of its name's hash that do not choose the slot: probing compares them
  // before the name, without reading a separate array of hashes (a second random access per
  // probe, out of cache above ~10^5 names).
  struct Slot {
    int position;  // −1 for an empty slot (at most half are full)
    std::uint32_t tag;
  };
  static std::uint32_t Tag(std::size_t hash) {
    return static_cast<std::uint32_t>(static_cast<std::uint64_t>(hash) >> 32);
  }

  void Insert(int position, std::size_t hash) {
    std::size_t pos = hash & mask_;
    for (; slots_[pos].position >= 0; pos = (pos + 1) & mask_) {
      const Slot& slot = slots_[pos];
      if (slot.tag == Tag(hash) && names_[slot.position] == names_[position]) {
        has_duplicates_ = true;
        return;
      }
    }
    slots_[pos] = Slot{position, Tag(hash)};
  }

  std::vector<Slot> slots_;
  std::size_t mask_ = 0;
  std::vector<std::string_view> names_;
  bool has_duplicates_ = false;  // some name is given more than once
};

}  // namespace massprops::internal

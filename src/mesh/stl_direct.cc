// ReadStlDirect (stl_direct.h): an STL file's triangles in one pass over its bytes, without assimp.
#include "mesh/stl_direct.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <exception>
#include <memory>
#include <unordered_map>
#include <utility>

#include "mesh/assimp_join_hash.h"
#include "mesh/mesh_store.h"

namespace massprops::internal {
namespace {

// A binary STL (its size already checked: 84 + 50·count bytes) as DirectStl says. Assimp 5.2's
// STL importer gives every corner the facet's normal; its aiProcess_JoinIdenticalVertices then
// walks the corners in order and keeps one unless an element of its hash bucket (see
// JoinIdenticalVertices in mesh_libraries.cc) has a position and a normal each within 1e-5
// (squared distance in float arithmetic, not above 1e-10; a NaN distance matches). Within a
// bucket that is the same position (-0 and +0 alike), unless two positions within 1e-5 of each
// other share a bucket: such a file is left to assimp. Where several kept corners could take one,
// they share its position, so every number derived from the mesh is the same whichever is named.
// Colors (a SolidWorks "COLOR=" header, bit 15 of a facet's attribute) do not matter: assimp
// 5.2.4's join does not compare them. False when a coordinate is not finite, two positions could
// be joined as above (assimp's triangles then differ from the file's), or there are more than
// 2^31 - 1 corners.
// The distinct positions of a binary STL: one slot per position (open addressing, linear probing,
// at most half full) holding the position, its index and its last kept corner, all a probe needs
// in 20 bytes. Positions are compared in float (-0 == +0).
class PositionTable {
 public:
  struct Slot {
    std::array<float, 3> p;
    std::int32_t position = -1;  // -1: empty
    std::int32_t last = -1;      // the last corner kept at this position, or -1
  };

  explicit PositionTable(std::size_t corners) {
    // 2 to 4 times the positions of a closed mesh (a sixth of its corners), which never fill
    // half of it; an open mesh's may (then it grows).
    while (capacity_ < corners / 3) capacity_ *= 2;
    table_.resize(capacity_);
  }

  // The slot of p (empty when p is new).
  Slot& Find(const std::array<float, 3>& p) { return table_[SlotOf(p)]; }
  // Where p's first probe looks: asked of the memory early (__builtin_prefetch), as these are
  // where the time goes, a cache miss each.
  const Slot* FirstProbe(const std::array<float, 3>& p) const {
    return table_.data() + (Hash(p) & (capacity_ - 1));
  }
  // Fills the empty slot of p as position `position`; the slot of p again (the table may grow).
  Slot& Insert(Slot& slot, const std::array<float, 3>& p, std::int32_t position) {
    slot.p = p;
    slot.position = position;
    if (2 * static_cast<std::size_t>(++positions_) <= capacity_) return slot;
    std::vector<Slot> old(2 * capacity_);  // grow: every slot moved to a table twice as big
    old.swap(table_);
    capacity_ *= 2;
    for (const Slot& moved : old) {
      if (moved.position >= 0) table_[SlotOf(moved.p)] = moved;
    }
    return Find(p);
  }

 private:
  static std::uint32_t Bits(float v) {
    std::uint32_t u;
    const float w = v + 0.0f;  // -0 + 0 == +0
    std::memcpy(&u, &w, sizeof u);
    return u;
  }
  static std::uint64_t Hash(const std::array<float, 3>& p) {
    std::uint64_t h = Bits(p[0]) * 0x9E3779B97F4A7C15ull;
    h = (h ^ (h >> 29) ^ Bits(p[1])) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 32) ^ Bits(p[2])) * 0x94D049BB133111EBull;
    return h ^ (h >> 31);
  }
  std::size_t SlotOf(const std::array<float, 3>& p) const {
    std::size_t slot = Hash(p) & (capacity_ - 1);
    while (table_[slot].position >= 0 && table_[slot].p != p) slot = (slot + 1) & (capacity_ - 1);
    return slot;
  }
  std::size_t capacity_ = 1024;
  std::int64_t positions_ = 0;
  std::vector<Slot> table_;
};

// Assimp's join looks a vertex up in a std::unordered_map reserved for every corner, hashed by its
// position (mesh_libraries.cc), and compares it with every element of its bucket: a position
// within 1e-5 of another in the same bucket (float arithmetic) could be joined to it. NearPair()
// tells whether two of the distinct positions are such a pair. Few buckets hold two positions (a
// closed mesh has about a sixth as many positions as corners): one bit per bucket (a table small
// enough to stay in cache) finds them, then only the positions of those buckets are compared.
class AssimpBuckets {
 public:
  explicit AssimpBuckets(std::size_t corners) {
    buckets_ = AssimpJoinBuckets(corners);
    seen_.assign((buckets_ + 63) / 64, 0);
  }
  // Notes the next position (positions are added in order).
  void Add(const std::array<float, 3>& p) {
    const std::size_t bucket = AssimpJoinHash(p[0], p[1], p[2]) % buckets_;
    bucket_of_.push_back(bucket);
    std::uint64_t& word = seen_[bucket / 64];
    const std::uint64_t bit = std::uint64_t{1} << (bucket % 64);
    if (word & bit) {
      if (shared_bits_.empty()) shared_bits_.assign(seen_.size(), 0);
      shared_bits_[bucket / 64] |= bit;
      shared_.push_back(bucket);
    }
    word |= bit;
  }
  bool NearPair(const std::vector<Eigen::Vector3d>& positions) const {
    if (shared_.empty()) return false;
    std::unordered_map<std::size_t, std::vector<std::size_t>> members;
    for (const std::size_t bucket : shared_) members[bucket];
    for (std::size_t i = 0; i < bucket_of_.size(); ++i) {
      const std::size_t bucket = bucket_of_[i];  // a bit test first: few buckets are shared
      if (!((shared_bits_[bucket / 64] >> (bucket % 64)) & 1)) continue;
      members[bucket].push_back(i);
    }
    for (const auto& [bucket, list] : members) {
      for (std::size_t a = 0; a < list.size(); ++a) {
        for (std::size_t b = a + 1; b < list.size(); ++b) {
          const Eigen::Vector3f d =
              positions[list[a]].cast<float>() - positions[list[b]].cast<float>();
          if (!(d.x() * d.x() + d.y() * d.y() + d.z() * d.z() > 1e-5f * 1e-5f)) return true;
        }
      }
    }
    return false;
  }

 private:
  std::size_t buckets_ = 1;
  std::vector<std::uint64_t> seen_;         // one bit per bucket: holds a position
  std::vector<std::uint64_t> shared_bits_;  // one bit per bucket: holds two (once there is one)
  std::vector<std::size_t> bucket_of_;      // per position
  std::vector<std::size_t> shared_;         // buckets found holding a second position
};

// The join of a binary STL's records, fed in order a piece at a time (the records of a whole
// file, or of one buffer of a file read in pieces).
class BinaryStlJoiner {
 public:
  // `count` records will be added (at most 0x7fffffff / 3: checked by the caller).
  BinaryStlJoiner(std::uint32_t count, DirectStl* stl)
      : corners_(3 * static_cast<std::size_t>(count)),
        table_(corners_),
        buckets_(corners_),
        stl_(stl) {
    normal_of_.reserve(corners_);
    previous_.reserve(corners_);
    stl->vertex_position.reserve(corners_);
    stl->joined_triangles.reserve(count);  // filled a triangle at a time: no zeros written first
    stl->mesh.vertices.reserve(corners_ / 4);
    stl->mesh.triangles.reserve(count);
  }

  // Adds the `count` 50-byte records at `records`; false when a coordinate is not finite.
  bool Add(const char* records, std::uint32_t count) {
    TriangleMesh& mesh = stl_->mesh;
    auto corner = [&](std::uint32_t t, int v) {
      std::array<float, 3> p;
      std::memcpy(p.data(), records + 50 * static_cast<std::size_t>(t) + 12 * (v + 1), 12);
      return p;
    };
    constexpr std::uint32_t kAhead = 8;  // the slots of a triangle this far ahead are prefetched
    for (std::uint32_t t = 0; t < count; ++t) {
      if (t + kAhead < count) {
        for (int v = 0; v < 3; ++v) __builtin_prefetch(table_.FirstProbe(corner(t + kAhead, v)));
      }
      std::array<float, 3> normal;
      std::memcpy(normal.data(), records + 50 * static_cast<std::size_t>(t), 12);
      std::array<std::int32_t, 3> joined_triangle, triangle;
      for (int v = 0; v < 3; ++v) {
        const std::array<float, 3> p = corner(t, v);
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) return false;
        PositionTable::Slot* slot = &table_.Find(p);
        if (slot->position < 0) {
          buckets_.Add(p);
          slot = &table_.Insert(*slot, p, static_cast<std::int32_t>(mesh.vertices.size()));
          // + 0.0: LoadMeshFile applies the scene's (identity) transform, whose translation turns
          // a -0 coordinate into +0.
          mesh.vertices.emplace_back(p[0] + 0.0, p[1] + 0.0, p[2] + 0.0);
        }
        joined_triangle[static_cast<std::size_t>(v)] = Join(slot, normal);
        triangle[static_cast<std::size_t>(v)] = slot->position;
      }
      stl_->joined_triangles.push_back(joined_triangle);
      mesh.triangles.push_back(triangle);
    }
    return true;
  }

  // After every record: false when two positions could be joined by assimp (left to it).
  bool Finish() {
    if (buckets_.NearPair(stl_->mesh.vertices)) return false;
    stl_->joined = true;
    return true;
  }

 private:
  // The kept corner at `slot`'s position with a normal within 1e-5 of `normal`, else a new one.
  std::int32_t Join(PositionTable::Slot* slot, const std::array<float, 3>& normal) {
    for (std::int32_t k = slot->last; k >= 0; k = previous_[static_cast<std::size_t>(k)]) {
      const std::array<float, 3>& n = normal_of_[static_cast<std::size_t>(k)];
      const float dx = normal[0] - n[0], dy = normal[1] - n[1], dz = normal[2] - n[2];
      if (!(dx * dx + dy * dy + dz * dz > 1e-5f * 1e-5f)) return k;
    }
    const auto joined = static_cast<std::int32_t>(normal_of_.size());
    normal_of_.push_back(normal);
    previous_.push_back(slot->last);
    stl_->vertex_position.push_back(slot->position);
    slot->last = joined;
    return joined;
  }

  std::size_t corners_;
  PositionTable table_;
  AssimpBuckets buckets_;
  std::vector<std::array<float, 3>> normal_of_;  // per kept corner
  std::vector<std::int32_t> previous_;           // per kept corner: the one kept before it there
  DirectStl* stl_;
};

// The record count a binary STL's 84-byte header gives, and whether a file of `size` bytes is a
// binary STL of that many records (assimp 5.2's test: exactly 84 + 50·count bytes).
std::uint32_t RecordCount(const char* header) {
  std::uint32_t count = 0;
  std::memcpy(&count, header + 80, sizeof(count));
  return count;
}
bool IsBinaryStl(const char* header, std::uint64_t size) {
  return 84 + 50 * static_cast<std::uint64_t>(RecordCount(header)) == size;
}
// Whether the records can be joined here: at least one, and every corner indexable by int32.
bool Joinable(std::uint32_t count) {
  return count > 0 && 3 * static_cast<std::uint64_t>(count) <= 0x7fffffff;
}

bool BinaryStlJoined(const std::string& bytes, std::uint32_t count, DirectStl* stl) {
  BinaryStlJoiner joiner(count, stl);
  return joiner.Add(bytes.data() + 84, count) && joiner.Finish();
}

// Reads up to n bytes from fd into buffer; fewer only at the end of the file or on a read error
// (then *failed, if not null, is set).
std::size_t ReadFull(int fd, char* buffer, std::size_t n, bool* failed = nullptr) {
  std::size_t done = 0;
  while (done < n) {
    const ssize_t got = ::read(fd, buffer + done, n - done);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0 && failed != nullptr) *failed = true;
    if (got <= 0) break;
    done += static_cast<std::size_t>(got);
  }
  return done;
}

class FileDescriptor {
 public:
  explicit FileDescriptor(const std::string& path)
      : fd_(::open(path.c_str(), O_RDONLY | O_CLOEXEC)) {}
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

// The triangles of an ascii STL: its "vertex" triples in order; as many as its "endfacet"s (a
// facet of another vertex count is left to assimp).
bool AsciiStlTriangles(const std::string& bytes, TriangleMesh* mesh) {
  std::size_t facets = 0;
  for (std::size_t at = bytes.find("endfacet"); at != std::string::npos;
       at = bytes.find("endfacet", at + 8)) {
    ++facets;
  }
  if (!ForEachAsciiStlVertex(bytes,
                             [&](const Eigen::Vector3d& p) { mesh->vertices.push_back(p); })) {
    return false;
  }
  const std::size_t n = mesh->vertices.size();
  if (n == 0 || n != 3 * facets || n > 0x7fffffff) return false;
  for (std::size_t t = 0; t < facets; ++t) {
    const std::int32_t first = static_cast<std::int32_t>(3 * t);
    mesh->triangles.push_back({first, first + 1, first + 2});
  }
  return true;
}

}  // namespace

bool ReadStlDirect(const std::string& bytes, DirectStl* stl) {
  DirectStl found;
  bool ok = false;
  try {
    if (bytes.size() >= 84 && IsBinaryStl(bytes.data(), bytes.size())) {
      const std::uint32_t count = RecordCount(bytes.data());
      ok = Joinable(count) && BinaryStlJoined(bytes, count, &found);
    } else {
      const std::size_t first = bytes.find_first_not_of(" \t\r\n\f\v");
      ok = first != std::string::npos && bytes.compare(first, 5, "solid") == 0 &&
           AsciiStlTriangles(bytes, &found.mesh);
    }
  } catch (const std::exception&) {  // std::bad_alloc on a huge file: assimp's message
    ok = false;
  }
  if (ok) *stl = std::move(found);
  return ok;
}

bool ReadStlDirectFile(const std::string& path, DirectStl* stl, ContentHasher* hasher) {
  const FileDescriptor fd(path);
  if (fd.get() < 0) return false;
  struct stat info {};
  if (::fstat(fd.get(), &info) != 0 || !S_ISREG(info.st_mode)) return false;
  const auto size = static_cast<std::uint64_t>(info.st_size);
  char header[84];
  const bool has_header = size >= 84 && ReadFull(fd.get(), header, 84) == 84;
  if (has_header && IsBinaryStl(header, size)) {
    const std::uint32_t count = RecordCount(header);
    if (!Joinable(count)) return false;
    if (hasher != nullptr) hasher->Add(header, sizeof header);
    DirectStl found;
    try {
      BinaryStlJoiner joiner(count, &found);
      constexpr std::uint32_t kRecordsPerPiece = 1310;  // 65 500 bytes: stays in the L2 cache
      const std::unique_ptr<char[]> piece(new char[50 * kRecordsPerPiece]);
      for (std::uint32_t done = 0; done < count;) {
        const std::uint32_t n = std::min(kRecordsPerPiece, count - done);
        // A file that shrank while it was read is left to assimp.
        if (ReadFull(fd.get(), piece.get(), 50 * std::size_t{n}) != 50 * std::size_t{n}) {
          return false;
        }
        if (hasher != nullptr) hasher->Add(piece.get(), 50 * std::size_t{n});
        if (!joiner.Add(piece.get(), n)) return false;
        done += n;
      }
      if (!joiner.Finish()) return false;
    } catch (const std::exception&) {  // std::bad_alloc on a huge file: assimp's message
      return false;
    }
    *stl = std::move(found);
    return true;
  }
  std::string bytes;  // an ascii STL (or no STL): its whole text
  if (!ReadWholeFile(path, &bytes)) return false;
  if (hasher != nullptr) hasher->Add(bytes.data(), bytes.size());
  return ReadStlDirect(bytes, stl);
}

TriangleMesh JoinedMesh(const DirectStl& stl) {
  TriangleMesh joined;
  joined.vertices.reserve(stl.vertex_position.size());
  for (const std::int32_t p : stl.vertex_position) {
    joined.vertices.push_back(stl.mesh.vertices[static_cast<std::size_t>(p)]);
  }
  joined.triangles = stl.joined_triangles;
  return joined;
}

std::int64_t ReadFileInPieces(const std::string& path, std::size_t piece,
                              const std::function<void(const char*, std::size_t)>& take) {
  const FileDescriptor fd(path);
  if (fd.get() < 0) return -1;
  std::int64_t total = 0;
  try {
    const std::unique_ptr<char[]> buffer(new char[piece]);
    for (;;) {
      bool failed = false;
      const std::size_t got = ReadFull(fd.get(), buffer.get(), piece, &failed);
      if (failed) return -1;  // a read error, not the end of the file
      if (got > 0) take(buffer.get(), got);
      total += static_cast<std::int64_t>(got);
      if (got < piece) return total;
    }
  } catch (const std::bad_alloc&) {
    return -1;
  }
}

bool ReadWholeFile(const std::string& path, std::string* bytes) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  struct stat info {};
  bool ok = ::fstat(fd, &info) == 0 && S_ISREG(info.st_mode);
  try {
    if (ok) bytes->resize(static_cast<std::size_t>(info.st_size));
  } catch (const std::exception&) {  // std::bad_alloc
    ok = false;
  }
  std::size_t done = 0;
  while (ok && done < bytes->size()) {
    const ssize_t got = ::read(fd, bytes->data() + done, bytes->size() - done);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;  // the file shrank: keep what was read
    done += static_cast<std::size_t>(got);
  }
  ::close(fd);
  if (!ok) return false;
  bytes->resize(done);  // a file that shrank while it was read: what it held
  return true;
}

}  // namespace massprops::internal

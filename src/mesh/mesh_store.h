#pragma once
// Private to the library: the numbers derived from mesh files, kept between runs under
// $XDG_CACHE_HOME/massprops/meshes (MeshCache::UsePersistentCache, docs/meshes.md#cache).
//
// Two kinds of files, each written whole to a temporary name and renamed (atomic on POSIX, so
// a concurrent run sees the old entry, the new one or none, never half of one):
//   d-<content hash>-<size>: a mesh file's derived numbers (StoredMesh), for any file with
//     those bytes (a checkout on CI gives the files new modification times: they still hit);
//     d-<content hash>.<part hash>-<size> those of one part of it (an SDF <submesh>, FileKey);
//   r-<run>: stat entries, one file per run that learned any: the content hash of the file at
//     a path with a size, modification time and inode, so that an unchanged file is not even
//     read. A run reads them all at its first lookup; past 16 such files, the next run that
//     writes one merges them all into it (one file created per run, not one per mesh: creating
//     a file costs up to 1 ms on some file systems, docs/benchmarks.md section 8).
// Every file ends with a hash of its bytes: a damaged or truncated one is ignored (and
// rewritten by the run that computes the numbers again).

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "massprops/mesh/mesh_inertia.h"
#include "massprops/mesh/mesh_loader.h"

namespace massprops::internal {

/// A 64-bit hash of `size` bytes, 8 at a time (not cryptographic: with the size beside it, it
/// tells changed files and damaged entries apart).
std::uint64_t HashBytes(const char* bytes, std::size_t size, std::uint64_t seed = 0);

/// The content key's hash of a file's bytes, fed in order in pieces of any size (the value does
/// not depend on where the pieces split): four independent lanes over 32-byte blocks, one
/// multiply per 8 bytes (each step a bijection of its lane, so a changed word is never
/// forgotten), then the lanes and the last bytes folded by HashBytes. Not cryptographic: with the
/// size beside it, it tells changed files apart.
class ContentHasher {
 public:
  void Add(const char* bytes, std::size_t size);
  /// Bytes added so far.
  std::uint64_t size() const { return size_; }
  /// The hash of the bytes added.
  std::uint64_t Finish() const;

 private:
  void AddBlocks(const char* bytes, std::size_t size);  // size a multiple of 32
  std::uint64_t lane_[4] = {0x9E3779B97F4A7C15ull, 0xBF58476D1CE4E5B9ull, 0x94D049BB133111EBull,
                            0xA0761D6478BD642Full};
  char carry_[32] = {};  // the bytes after the last whole block
  std::size_t carried_ = 0;
  std::uint64_t size_ = 0;
};

/// The MassProperties options a result depends on: scale x, y, z, open-mesh model, shell
/// thickness, closure tolerance, read_stl_directly.
using MassKey = std::tuple<double, double, double, int, double, double, bool>;

/// What the cache keeps of one mesh file.
struct StoredMesh {
  std::optional<Eigen::AlignedBox3d> box;
  std::shared_ptr<const MeshPoints> points;
  std::vector<std::pair<MassKey, MeshMassProperties>> properties;
};

/// Which file an entry is of: its absolute path, size, modification time and (once read)
/// content hash.
struct FileKey {
  std::string path;
  std::uint64_t size = 0;
  std::int64_t mtime_ns = 0;
  std::uint64_t inode = 0;  // with the device: part of the stat entry's name only
  std::uint64_t content_hash = 0;
  bool hashed = false;
  /// Which part of the file the entry is of (SubmeshKey of src/mesh/submesh.h: an SDF <submesh>
  /// and its centering), "" for the whole file: a part's entry is named
  /// d-<content hash>.<hash of part>-<size>, so it is never taken for the whole file's or another
  /// part's. The stat entries (path to content hash) are the file's, whatever the part.
  std::string part;
};

/// Serialises a StoredMesh (exact: doubles as their bits) and back; Parse returns nullopt for
/// bytes that are not a whole, undamaged entry of this version.
std::string SerializeStoredMesh(const StoredMesh& mesh);
std::optional<StoredMesh> ParseStoredMesh(const std::string& bytes);

/// The folder of the cache: $XDG_CACHE_HOME/massprops/meshes, or ~/.cache/massprops/meshes when
/// XDG_CACHE_HOME is unset or not absolute (the XDG base directory specification); "" when
/// neither HOME nor XDG_CACHE_HOME is set.
std::string DefaultMeshStoreFolder();

/// The cache folder: lookups and atomic writes. Thread-safe (its state: the folder, listed once
/// at the first lookup, the stat entries read then, and this run's new ones until WriteStats).
class MeshStore {
 public:
  /// `max_bytes`: Trim removes the least recently written entries above it.
  MeshStore(std::string folder, std::uint64_t max_bytes);

  /// *key for the file at `path` (stat); false when it is not a regular file.
  static bool Stat(const std::string& path, FileKey* key);
  /// The entry of key's file: through its stat entry, else by hashing the file's bytes (read in
  /// pieces: none is kept); then key->content_hash is set, and the stat entry is written. nullopt
  /// when there is none, it is damaged, or the file cannot be read. A file of a size no content
  /// entry has (the folder is listed once, at the first such question) is not hashed: it cannot
  /// have one, and its reader hashes the bytes it reads (MeshCache) for Save.
  std::optional<StoredMesh> Find(FileKey* key) const;
  /// Writes the entry of key's file (hashing it first when key->hashed is false); its stat entry
  /// waits for WriteStats. Failures (a read-only folder, a full disk) are ignored: the cache is
  /// an optimisation.
  void Save(FileKey* key, const StoredMesh& mesh) const;
  /// Writes this run's stat entries (from Save, and from Find by content) as one file.
  void WriteStats() const;
  /// Removes the oldest entries while the folder holds more than max_bytes (down to 3/4 of it).
  void Trim() const;

  const std::string& folder() const { return folder_; }

 private:
  struct StatRecord {
    std::string path;
    std::uint64_t size = 0;
    std::int64_t mtime_ns = 0;
    std::uint64_t inode = 0;
    std::uint64_t content_hash = 0;
  };
  bool WriteAtomically(const std::string& name, const std::string& bytes) const;
  // Whether a content entry of that size may exist: the sizes in the folder's entry names when
  // first asked, and those this store wrote since.
  bool MayHoldSize(std::uint64_t size) const;
  // Lists the folder once: the content entries' sizes, and the stat entries' files, read.
  void ListLocked() const;
  // Notes key's stat entry for WriteStats (not for a file modified within the last 2 s).
  void RememberStat(const FileKey& key) const;
  std::string folder_;
  std::uint64_t max_bytes_;
  mutable std::mutex mutex_;  // guards what follows
  mutable bool listed_ = false;
  mutable std::set<std::uint64_t> sizes_;
  mutable std::unordered_map<std::string, std::vector<StatRecord>> stats_;  // by path
  mutable std::vector<std::string> batches_;                                // the stat files read
  mutable std::vector<StatRecord> pending_;                                 // this run's
};

/// Removes the cache folder's entries (and the folder). Returns the number of files removed, or
/// -1 with *error set when the folder cannot be listed or a file not removed.
long RemoveMeshStore(const std::string& folder, std::string* error);

}  // namespace massprops::internal

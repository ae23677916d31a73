// The cache of mesh files' derived numbers between runs (see mesh_store.h).
#include "mesh/mesh_store.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string_view>
#include <system_error>
#include <unordered_set>
#include <vector>

#include "mesh/stl_direct.h"

namespace massprops::internal {
namespace fs = std::filesystem;

namespace {

constexpr char kEntryMagic[] = "massprops-mesh-entry-1\n";
constexpr char kStatsMagic[] = "massprops-mesh-stats-1\n";
constexpr std::size_t kMaxStatBatches = 16;  // more are merged into one by the next run

std::uint64_t Mix(std::uint64_t h) {  // the finaliser of SplitMix64
  h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
  h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
  return h ^ (h >> 31);
}

std::string Hex(std::uint64_t value) {
  static const char kDigits[] = "0123456789abcdef";
  std::string text(16, '0');
  for (int i = 15; i >= 0; --i, value >>= 4)
    text[static_cast<std::size_t>(i)] = kDigits[value & 15];
  return text;
}

// Appends plain values (their bytes as in memory: the cache is per machine).
class Writer {
 public:
  template <typename T>
  void Put(const T& value) {
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  void PutText(const std::string& text) {
    Put<std::uint64_t>(text.size());
    bytes_ += text;
  }
  void PutRaw(const char* text) { bytes_ += text; }
  // `count` values at once, as Put writes each.
  template <typename T>
  void PutArray(const T* values, std::size_t count) {
    bytes_.append(reinterpret_cast<const char*>(values), count * sizeof(T));
  }
  void Reserve(std::size_t size) { bytes_.reserve(size); }
  std::string Finish() {
    Put<std::uint64_t>(HashBytes(bytes_.data(), bytes_.size()));
    return std::move(bytes_);
  }

 private:
  std::string bytes_;
};

// Reads what Writer wrote; every read checks the bounds (ok() false after a short read).
class Reader {
 public:
  // Fails at once unless `bytes` ends with the hash of what precedes it and starts with magic.
  Reader(const std::string& bytes, const char* magic) : bytes_(bytes) {
    const std::size_t n = std::strlen(magic);
    if (bytes.size() < n + sizeof(std::uint64_t) || bytes.compare(0, n, magic) != 0) {
      ok_ = false;
      return;
    }
    end_ = bytes.size() - sizeof(std::uint64_t);
    std::uint64_t stored = 0;
    std::memcpy(&stored, bytes.data() + end_, sizeof(stored));
    ok_ = stored == HashBytes(bytes.data(), end_);
    at_ = n;
  }
  template <typename T>
  T Get() {
    T value{};
    if (!ok_ || end_ - at_ < sizeof(T)) {
      ok_ = false;
      return value;
    }
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  std::string GetText() {
    const auto n = Get<std::uint64_t>();
    if (!ok_ || end_ - at_ < n) {
      ok_ = false;
      return {};
    }
    std::string text = bytes_.substr(at_, n);
    at_ += n;
    return text;
  }
  void Fail() { ok_ = false; }
  bool ok() const { return ok_; }
  bool AtEnd() const { return ok_ && at_ == end_; }

 private:
  const std::string& bytes_;
  std::size_t at_ = 0, end_ = 0;
  bool ok_ = true;
};

void PutProperties(const MeshMassProperties& p, Writer* out) {
  out->Put(p.volume);
  out->Put(p.area);
  out->Put(p.mass);
  for (int i = 0; i < 3; ++i) out->Put(p.p_GoGcm_G(i));
  for (const auto& [i, j] : {std::pair{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}}) {
    out->Put(p.I_GGcm_G(i, j));
  }
  const MeshDiagnostics& d = p.diagnostics;
  for (const std::int64_t n :
       {d.num_vertices, d.num_triangles, d.duplicate_vertices_merged, d.degenerate_triangles,
        d.edges, d.boundary_edges, d.non_manifold_edges, d.inconsistent_edges}) {
    out->Put(n);
  }
  out->Put<std::uint8_t>(d.winding_inverted ? 1 : 0);
  out->Put(d.reference_point_sensitivity);
  out->Put<std::int32_t>(static_cast<std::int32_t>(d.model));
  out->PutText(d.fallback_reason);
}

MeshMassProperties GetProperties(Reader* in) {
  MeshMassProperties p;
  p.volume = in->Get<double>();
  p.area = in->Get<double>();
  p.mass = in->Get<double>();
  for (int i = 0; i < 3; ++i) p.p_GoGcm_G(i) = in->Get<double>();
  double I[6];
  for (double& entry : I) entry = in->Get<double>();
  p.I_GGcm_G = RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(
      I[0], I[1], I[2], I[3], I[4], I[5], true);
  MeshDiagnostics& d = p.diagnostics;
  for (std::int64_t* n :
       {&d.num_vertices, &d.num_triangles, &d.duplicate_vertices_merged, &d.degenerate_triangles,
        &d.edges, &d.boundary_edges, &d.non_manifold_edges, &d.inconsistent_edges}) {
    *n = in->Get<std::int64_t>();
  }
  d.winding_inverted = in->Get<std::uint8_t>() != 0;
  d.reference_point_sensitivity = in->Get<double>();
  const auto model = in->Get<std::int32_t>();
  if (model < 0 || model > static_cast<std::int32_t>(MeshSolidModel::kThinShell)) {
    in->Fail();  // not a model this version writes
  }
  d.model = static_cast<MeshSolidModel>(model);
  d.fallback_reason = in->GetText();
  return p;
}

// A file modified within the last 2 s may change again within its file system's timestamp
// granularity without its size or time changing: its stat entry is not written (git's "racily
// clean" files), so the next run hashes its content.
bool RecentlyModified(const FileKey& key) {
  timespec now{};
  clock_gettime(CLOCK_REALTIME, &now);
  const std::int64_t now_ns = static_cast<std::int64_t>(now.tv_sec) * 1000000000 + now.tv_nsec;
  return now_ns - key.mtime_ns < std::int64_t{2000000000};
}

std::string EntryName(const FileKey& key) {
  const std::string part =
      key.part.empty() ? "" : "." + Hex(HashBytes(key.part.data(), key.part.size()));
  return "d-" + Hex(key.content_hash) + part + "-" + std::to_string(key.size);
}

}  // namespace

void ContentHasher::AddBlocks(const char* bytes, std::size_t size) {
  for (std::size_t i = 0; i + 32 <= size; i += 32) {
    for (int k = 0; k < 4; ++k) {
      std::uint64_t word;
      std::memcpy(&word, bytes + i + 8 * k, 8);
      const std::uint64_t x = (lane_[k] ^ word) * 0x9FB21C651E98DF25ull;
      lane_[k] = (x << 31) | (x >> 33);
    }
  }
}

void ContentHasher::Add(const char* bytes, std::size_t size) {
  size_ += size;
  if (carried_ > 0) {  // complete the block begun by the last piece
    const std::size_t take = std::min(size, 32 - carried_);
    std::memcpy(carry_ + carried_, bytes, take);
    carried_ += take;
    bytes += take;
    size -= take;
    if (carried_ < 32) return;
    AddBlocks(carry_, 32);
    carried_ = 0;
  }
  const std::size_t whole = size / 32 * 32;
  AddBlocks(bytes, whole);
  carried_ = size - whole;
  std::memcpy(carry_, bytes + whole, carried_);
}

std::uint64_t ContentHasher::Finish() const {
  std::uint64_t seed = size_;
  for (const std::uint64_t l : lane_) seed = Mix(seed ^ l) + 0x9E3779B97F4A7C15ull;
  return HashBytes(carry_, carried_, seed);
}

namespace {

// The file's content hash, its bytes read in pieces into a buffer that stays in the processor's
// cache (not into fresh memory of its whole size: three times the cost, docs/benchmarks.md
// section 8). False when it cannot be read, or its size is not the one its stat gave.
bool HashFile(FileKey* key) {
  ContentHasher hasher;
  const std::int64_t size = ReadFileInPieces(
      key->path, 65536, [&](const char* bytes, std::size_t n) { hasher.Add(bytes, n); });
  if (size < 0 || static_cast<std::uint64_t>(size) != key->size) return false;
  key->content_hash = hasher.Finish();
  key->hashed = true;
  return true;
}

}  // namespace

std::uint64_t HashBytes(const char* bytes, std::size_t size, std::uint64_t seed) {
  std::uint64_t h = Mix(seed ^ (size * 0x9E3779B97F4A7C15ull));
  std::size_t i = 0;
  for (; i + 8 <= size; i += 8) {
    std::uint64_t word;
    std::memcpy(&word, bytes + i, 8);
    h = (h ^ Mix(word)) * 0x9E3779B97F4A7C15ull;
  }
  std::uint64_t tail = 0;
  std::memcpy(&tail, bytes + i, size - i);
  return Mix(h ^ Mix(tail ^ 0xA0761D6478BD642Full));
}

std::string SerializeStoredMesh(const StoredMesh& mesh) {
  Writer out;
  // Room for all of it at once (the points, at most 24 bytes each, are most of an entry).
  out.Reserve(256 + (mesh.points ? 24 * mesh.points->positions.size() : 0) +
              256 * mesh.properties.size());
  out.PutRaw(kEntryMagic);
  out.Put<std::uint8_t>(mesh.box ? 1 : 0);
  if (mesh.box) {
    for (int i = 0; i < 3; ++i) out.Put(mesh.box->min()(i));
    for (int i = 0; i < 3; ++i) out.Put(mesh.box->max()(i));
  }
  out.Put<std::uint8_t>(mesh.points ? 1 : 0);
  if (mesh.points) {
    const std::vector<Eigen::Vector3d>& p = mesh.points->positions;
    out.Put<std::int64_t>(mesh.points->loader_vertices);
    out.Put<std::uint64_t>(p.size());
    // As floats when that is exact (every loader gives floats), else as doubles.
    const bool floats = std::all_of(p.begin(), p.end(), [](const Eigen::Vector3d& v) {
      return v.cast<float>().cast<double>() == v;
    });
    out.Put<std::uint8_t>(floats ? 1 : 0);
    if (floats) {
      std::vector<float> coordinates;
      coordinates.reserve(3 * p.size());
      for (const Eigen::Vector3d& v : p) {
        for (int i = 0; i < 3; ++i) coordinates.push_back(static_cast<float>(v(i)));
      }
      out.PutArray(coordinates.data(), coordinates.size());
    } else {
      for (const Eigen::Vector3d& v : p) out.PutArray(v.data(), 3);
    }
  }
  out.Put<std::uint32_t>(static_cast<std::uint32_t>(mesh.properties.size()));
  for (const auto& [key, properties] : mesh.properties) {
    out.Put(std::get<0>(key));
    out.Put(std::get<1>(key));
    out.Put(std::get<2>(key));
    out.Put<std::int32_t>(std::get<3>(key));
    out.Put(std::get<4>(key));
    out.Put(std::get<5>(key));
    out.Put<std::uint8_t>(std::get<6>(key) ? 1 : 0);
    PutProperties(properties, &out);
  }
  return out.Finish();
}

std::optional<StoredMesh> ParseStoredMesh(const std::string& bytes) {
  Reader in(bytes, kEntryMagic);
  StoredMesh mesh;
  if (in.Get<std::uint8_t>() != 0) {
    Eigen::Vector3d lo, hi;
    for (int i = 0; i < 3; ++i) lo(i) = in.Get<double>();
    for (int i = 0; i < 3; ++i) hi(i) = in.Get<double>();
    mesh.box = Eigen::AlignedBox3d(lo, hi);
  }
  if (in.Get<std::uint8_t>() != 0) {
    auto points = std::make_shared<MeshPoints>();
    points->loader_vertices = in.Get<std::int64_t>();
    const auto n = in.Get<std::uint64_t>();
    const bool floats = in.Get<std::uint8_t>() != 0;
    if (!in.ok() || n > bytes.size() / (floats ? 12 : 24)) return std::nullopt;
    points->positions.resize(n);
    for (Eigen::Vector3d& v : points->positions) {
      for (int i = 0; i < 3; ++i) v(i) = floats ? in.Get<float>() : in.Get<double>();
    }
    mesh.points = std::move(points);
  }
  const auto count = in.Get<std::uint32_t>();
  for (std::uint32_t k = 0; k < count && in.ok(); ++k) {
    const double x = in.Get<double>(), y = in.Get<double>(), z = in.Get<double>();
    const auto model = in.Get<std::int32_t>();
    const double thickness = in.Get<double>(), tolerance = in.Get<double>();
    const bool direct = in.Get<std::uint8_t>() != 0;
    MeshMassProperties properties = GetProperties(&in);
    mesh.properties.emplace_back(MassKey{x, y, z, model, thickness, tolerance, direct},
                                 std::move(properties));
  }
  if (!in.AtEnd()) return std::nullopt;
  return mesh;
}

std::string DefaultMeshStoreFolder() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg != nullptr && xdg[0] == '/') return std::string(xdg) + "/massprops/meshes";
  const char* home = std::getenv("HOME");
  if (home != nullptr && home[0] != '\0') return std::string(home) + "/.cache/massprops/meshes";
  return "";
}

MeshStore::MeshStore(std::string folder, std::uint64_t max_bytes)
    : folder_(std::move(folder)), max_bytes_(max_bytes) {}

bool MeshStore::Stat(const std::string& path, FileKey* key) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode)) return false;
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  key->path = ec ? path : absolute.lexically_normal().string();
  key->inode =
      static_cast<std::uint64_t>(info.st_ino) ^ (static_cast<std::uint64_t>(info.st_dev) << 32);
  key->size = static_cast<std::uint64_t>(info.st_size);
  key->mtime_ns = static_cast<std::int64_t>(info.st_mtim.tv_sec) * 1000000000 +
                  static_cast<std::int64_t>(info.st_mtim.tv_nsec);
  key->hashed = false;
  return true;
}

std::optional<StoredMesh> MeshStore::Find(FileKey* key) const {
  std::string bytes;
  bool from_stat = false;
  if (!key->hashed) {
    std::lock_guard<std::mutex> lock(mutex_);
    ListLocked();
    const auto it = stats_.find(key->path);
    if (it != stats_.end()) {
      for (const StatRecord& r : it->second) {
        if (r.size == key->size && r.mtime_ns == key->mtime_ns && r.inode == key->inode) {
          key->content_hash = r.content_hash;
          key->hashed = from_stat = true;
        }
      }
    }
  }
  if (!key->hashed && (!MayHoldSize(key->size) || !HashFile(key))) return std::nullopt;
  if (!ReadWholeFile(folder_ + "/" + EntryName(*key), &bytes)) return std::nullopt;
  std::optional<StoredMesh> mesh = ParseStoredMesh(bytes);
  if (mesh && !from_stat) RememberStat(*key);  // found by content: its stat, for the next run
  return mesh;
}

void MeshStore::Save(FileKey* key, const StoredMesh& mesh) const {
  if (!key->hashed && !HashFile(key)) return;
  std::error_code ec;
  fs::create_directories(folder_, ec);
  if (!WriteAtomically(EntryName(*key), SerializeStoredMesh(mesh))) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    sizes_.insert(key->size);
  }
  RememberStat(*key);
}

void MeshStore::RememberStat(const FileKey& key) const {
  if (RecentlyModified(key)) return;
  std::lock_guard<std::mutex> lock(mutex_);
  pending_.push_back({key.path, key.size, key.mtime_ns, key.inode, key.content_hash});
}

bool MeshStore::MayHoldSize(std::uint64_t size) const {
  std::lock_guard<std::mutex> lock(mutex_);
  ListLocked();
  return sizes_.count(size) > 0;
}

void MeshStore::ListLocked() const {
  if (listed_) return;
  listed_ = true;
  std::error_code ec;
  for (fs::directory_iterator it(folder_, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind("r-", 0) == 0) {  // a run's stat entries
      std::string bytes;
      if (!ReadWholeFile(it->path().string(), &bytes)) continue;
      batches_.push_back(name);
      Reader in(bytes, kStatsMagic);
      const auto count = in.Get<std::uint64_t>();
      std::vector<StatRecord> records;
      for (std::uint64_t i = 0; in.ok() && i < count; ++i) {
        StatRecord r;
        r.path = in.GetText();
        r.size = in.Get<std::uint64_t>();
        r.mtime_ns = in.Get<std::int64_t>();
        r.inode = in.Get<std::uint64_t>();
        r.content_hash = in.Get<std::uint64_t>();
        records.push_back(std::move(r));
      }
      if (!in.AtEnd()) continue;  // damaged: ignored (and merged away later)
      for (StatRecord& r : records) stats_[r.path].push_back(std::move(r));
      continue;
    }
    const std::size_t dash = name.rfind('-');  // d-<hash>-<size>
    if (name.rfind("d-", 0) != 0 || dash < 2 || dash + 1 >= name.size()) continue;
    std::uint64_t entry_size = 0;
    const char* first = name.data() + dash + 1;
    const char* last = name.data() + name.size();
    const std::from_chars_result r = std::from_chars(first, last, entry_size);
    if (r.ec == std::errc() && r.ptr == last) sizes_.insert(entry_size);
  }
}

void MeshStore::WriteStats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (pending_.empty()) return;
  // Past kMaxStatBatches files, this run's batch takes in the records read and replaces them:
  // of each path, only the newest (a file given an older time again is hashed again).
  const bool merge = batches_.size() + 1 > kMaxStatBatches;
  std::vector<const StatRecord*> records;
  if (merge) {
    std::unordered_set<std::string_view> pending_paths;
    for (const StatRecord& r : pending_) pending_paths.insert(r.path);
    for (const auto& [path, list] : stats_) {
      const StatRecord* newest = &list.front();
      for (const StatRecord& r : list) newest = r.mtime_ns > newest->mtime_ns ? &r : newest;
      if (pending_paths.count(path) == 0) records.push_back(newest);
    }
  }
  for (const StatRecord& r : pending_) records.push_back(&r);
  Writer out;
  out.PutRaw(kStatsMagic);
  out.Put<std::uint64_t>(records.size());
  for (const StatRecord* r : records) {
    out.PutText(r->path);
    out.Put(r->size);
    out.Put(r->mtime_ns);
    out.Put(r->inode);
    out.Put(r->content_hash);
  }
  timespec now{};
  clock_gettime(CLOCK_REALTIME, &now);
  const std::uint64_t id = Mix(static_cast<std::uint64_t>(::getpid()) ^
                               Mix(static_cast<std::uint64_t>(now.tv_sec) * 1000000000u +
                                   static_cast<std::uint64_t>(now.tv_nsec)));
  std::error_code ec;
  fs::create_directories(folder_, ec);
  if (!WriteAtomically("r-" + Hex(id), out.Finish())) return;
  pending_.clear();
  if (!merge) return;
  for (const std::string& name : batches_) fs::remove(folder_ + "/" + name, ec);
  batches_.clear();
}

bool MeshStore::WriteAtomically(const std::string& name, const std::string& bytes) const {
  static std::atomic<unsigned> counter{0};
  const std::string temporary = folder_ + "/." + name + "." + std::to_string(::getpid()) + "." +
                                std::to_string(counter++) + ".tmp";
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) return false;
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n <= 0) break;
    written += static_cast<std::size_t>(n);
  }
  const bool ok = ::close(fd) == 0 && written == bytes.size();
  if (!ok || ::rename(temporary.c_str(), (folder_ + "/" + name).c_str()) != 0) {
    ::unlink(temporary.c_str());
    return false;
  }
  return true;
}

void MeshStore::Trim() const {
  std::error_code ec;
  struct File {
    fs::file_time_type time;
    std::uintmax_t size;
    fs::path path;
  };
  std::vector<File> files;
  std::uintmax_t total = 0;
  for (fs::directory_iterator it(folder_, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code entry_ec;
    const std::uintmax_t size = it->file_size(entry_ec);
    if (entry_ec) continue;
    files.push_back({it->last_write_time(entry_ec), size, it->path()});
    total += size;
  }
  if (total <= max_bytes_) return;
  std::sort(files.begin(), files.end(),
            [](const File& a, const File& b) { return a.time < b.time; });
  for (const File& file : files) {
    if (total <= max_bytes_ / 4 * 3) break;
    if (fs::remove(file.path, ec)) total -= file.size;
  }
}

long RemoveMeshStore(const std::string& folder, std::string* error) {
  std::error_code ec;
  if (!fs::exists(folder, ec)) return 0;
  const std::uintmax_t removed = fs::remove_all(folder, ec);
  if (ec) {
    if (error) *error = "cannot remove the mesh cache " + folder + ": " + ec.message();
    return -1;
  }
  return removed == 0 ? 0 : static_cast<long>(removed - 1);  // the folder itself not counted
}

}  // namespace massprops::internal

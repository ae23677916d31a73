// MeshCache (mesh_loader.h): each mesh file read once per run, its numbers kept between runs.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <utility>
#include <vector>

#include "massprops/mesh/mesh_loader.h"
#include "mesh/mesh_coincidence.h"
#include "mesh/mesh_store.h"
#include "mesh/stl_direct.h"
#include "mesh/submesh.h"

namespace massprops {

namespace {

// MeshSolidAnalysis of a mesh file, by (scale, read directly).
using AnalysisMemo =
    std::vector<std::pair<std::pair<Eigen::Vector3d, bool>, internal::MeshSolidAnalysis>>;

// Whether `path` ends with the 4-character `suffix` (lower case), in any case.
bool HasSuffix(const std::string& path, const char* suffix) {
  if (path.size() < 4) return false;
  for (std::size_t i = 0; i < 4; ++i) {
    const char c = path[path.size() - 4 + i];
    if (std::tolower(static_cast<unsigned char>(c)) != suffix[i]) return false;
  }
  return true;
}

bool IsStlPath(const std::string& path) { return HasSuffix(path, ".stl"); }

// Whether LoadMeshBounds reads the box of `path` itself (an STL or OBJ file), not through
// LoadMeshFile.
bool HasDirectBox(const std::string& path) { return IsStlPath(path) || HasSuffix(path, ".obj"); }

// The start of CalcMeshMassProperties' reason when it integrates an open mesh as a closed solid
// because MeshInertiaOptions::open_mesh_model says so (the only closed solid that depends on it).
constexpr char kIntegratedDespite[] = "integrated as a closed solid despite";

bool IsIdentity(const Eigen::Vector3d& scale) { return scale == Eigen::Vector3d::Ones(); }

// Whether vertices at distinct positions stay distinct once scaled (mesh_coincidence.h).
bool StayDistinct(const Eigen::Vector3d& scale) {
  for (int i = 0; i < 3; ++i) {
    const double s = std::abs(scale[i]);
    if (!(s >= 1e-30 && s <= 1e30)) return false;
  }
  return true;
}

internal::MassKey KeyOf(const Eigen::Vector3d& scale, const MeshInertiaOptions& options) {
  return {scale.x(),
          scale.y(),
          scale.z(),
          static_cast<int>(options.open_mesh_model),
          options.shell_thickness,
          options.closure_tolerance,
          options.read_stl_directly};
}

// Each distinct position of `mesh` once (-0 and +0 the same), in order of first appearance.
std::vector<Eigen::Vector3d> DistinctPositions(const TriangleMesh& mesh) {
  auto bits = [](double v) {
    std::uint64_t u;
    const double w = v + 0.0;
    std::memcpy(&u, &w, sizeof u);
    return u;
  };
  std::size_t capacity = 16;
  while (capacity < 2 * mesh.vertices.size()) capacity *= 2;
  std::vector<std::int64_t> table(capacity, -1);
  std::vector<Eigen::Vector3d> positions;
  for (const Eigen::Vector3d& v : mesh.vertices) {
    std::uint64_t h = bits(v.x()) * 0x9E3779B97F4A7C15ull;
    h = (h ^ (h >> 29) ^ bits(v.y())) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 32) ^ bits(v.z())) * 0x94D049BB133111EBull;
    std::size_t slot = (h ^ (h >> 31)) & (capacity - 1);
    while (table[slot] >= 0 && !(positions[static_cast<std::size_t>(table[slot])] == v)) {
      slot = (slot + 1) & (capacity - 1);
    }
    if (table[slot] >= 0) continue;
    table[slot] = static_cast<std::int64_t>(positions.size());
    positions.push_back(v);
  }
  return positions;
}

// The mass properties of `mesh` (the file's, scaled by `scale`; `direct`: the STL read directly)
// with `options`, from the analysis in *memo when the mesh was analyzed already, else from one
// added to it: the same numbers as internal::CalcMeshMassProperties(mesh, options, distinct).
MeshMassProperties CalcRemembering(AnalysisMemo* memo, const TriangleMesh& mesh,
                                   const Eigen::Vector3d& scale, bool direct, bool distinct,
                                   const MeshInertiaOptions& options) {
  const internal::MeshSolidAnalysis* analysis = nullptr;
  for (const auto& [key, known] : *memo) {
    if (key.first == scale && key.second == direct) analysis = &known;
  }
  if (analysis == nullptr) {
    internal::CheckMeshInertiaOptions(options);  // before the mesh's own errors, as always
    memo->emplace_back(std::make_pair(scale, direct), internal::AnalyzeMeshSolid(mesh, distinct));
    analysis = &memo->back().second;
  }
  return internal::CalcMeshMassProperties(mesh, options, *analysis);
}

}  // namespace

// What is known of one mesh file, or of one part of it (an SDF <submesh>: then its mesh is taken
// from the whole file's state); guarded by its own mutex (different files in parallel).
struct MeshCache::FileState {
  std::mutex mutex;
  MeshSubmesh submesh;  // the part; an empty name: the whole file
  bool IsPart() const { return !submesh.name.empty(); }
  // The persistent cache: looked up once; `stored` holds what is known (from it or this run).
  bool looked_up = false;
  bool stat_ok = false;
  internal::FileKey key;
  internal::StoredMesh stored;
  bool dirty = false;
  // This run.
  bool loaded = false;  // LoadMeshFile's mesh known (or tried)
  std::shared_ptr<const TriangleMesh> mesh;
  std::vector<internal::MeshPartRange> parts;  // the whole file's, when assimp read it
  std::string load_error;
  bool direct_tried = false;  // the direct STL reader tried
  // An STL read directly (DirectStl): its triangles; LoadMeshFile's mesh is made from it on
  // demand when it is joined (a binary STL).
  std::shared_ptr<const internal::DirectStl> direct;
  bool bounded = false;
  std::string bounds_error;
  bool pointed = false;
  std::string points_error;
  std::map<internal::MassKey, std::string> mass_errors;
  // This run's analyses of the mesh (MeshSolidAnalysis), by scale and by source (the STL read
  // directly, or LoadMeshFile's mesh): an open mesh is asked for with two sets of options.
  AnalysisMemo analyses;
};

MeshCache::MeshCache() = default;

MeshCache::~MeshCache() { Flush(); }

void MeshCache::UsePersistentCache(const std::string& folder, std::uint64_t max_bytes) {
  std::lock_guard<std::mutex> lock(mutex_);
  store_ = folder.empty() ? nullptr : std::make_shared<internal::MeshStore>(folder, max_bytes);
}

void MeshCache::Flush() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!store_) return;
  bool wrote = false;
  for (auto& [path, state] : files_) {
    std::lock_guard<std::mutex> file_lock(state->mutex);
    if (!state->dirty || !state->stat_ok) continue;
    store_->Save(&state->key, state->stored);
    state->dirty = false;
    wrote = true;
  }
  store_->WriteStats();  // also those of files found by their content
  if (wrote) store_->Trim();
}

MeshCache::FileState& MeshCache::StateOf(const std::string& path, const MeshSubmesh& submesh) {
  // A part's state under the path and its key, which no path holds (a NUL).
  const std::string part = internal::SubmeshKey(submesh);
  std::lock_guard<std::mutex> lock(mutex_);
  std::unique_ptr<FileState>& state = files_[part.empty() ? path : path + '\0' + part];
  if (!state) {
    state = std::make_unique<FileState>();
    state->submesh = submesh;
  }
  return *state;
}

void MeshCache::LookUp(FileState& state, const std::string& path) {
  if (state.looked_up) return;
  state.looked_up = true;
  std::shared_ptr<internal::MeshStore> store;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    store = store_;
  }
  if (!store) return;
  state.key.part = internal::SubmeshKey(state.submesh);
  state.stat_ok = internal::MeshStore::Stat(path, &state.key);
  if (!state.stat_ok) return;
  // The content hash, when the path, size and time are not known, is read in pieces: a file
  // missing from the cache is then read again by its reader (the pieces stay in the processor's
  // cache; keeping the whole file for its reader cost more, docs/benchmarks.md section 8).
  std::optional<internal::StoredMesh> found = store->Find(&state.key);
  if (found) {
    state.stored = std::move(*found);
    std::lock_guard<std::mutex> lock(mutex_);
    ++files_from_store_;
  }
}

std::shared_ptr<const TriangleMesh> MeshCache::LoadLocked(FileState& state, const std::string& path,
                                                          std::string* error) {
  if (!state.loaded && state.IsPart()) {  // from the whole file's mesh, read once for all parts
    state.loaded = true;
    FileState& whole = StateOf(path, {});
    std::shared_ptr<const TriangleMesh> all;
    std::vector<internal::MeshPartRange> parts;
    {
      std::lock_guard<std::mutex> lock(whole.mutex);
      all = LoadLocked(whole, path, &state.load_error);
      parts = whole.parts;
    }
    auto mesh = std::make_shared<TriangleMesh>();
    if (all &&
        internal::SelectSubmesh(*all, parts, state.submesh, path, mesh.get(), &state.load_error)) {
      state.mesh = std::move(mesh);
    }
  }
  if (!state.loaded) {
    ReadDirectLocked(state, path);
    if (state.direct && state.direct->joined) {  // a binary STL: LoadMeshFile's mesh, from it
      state.loaded = true;
      state.mesh = std::make_shared<TriangleMesh>(internal::JoinedMesh(*state.direct));
    }
  }
  if (!state.loaded) {
    state.loaded = true;
    auto mesh = std::make_shared<TriangleMesh>();
    if (internal::LoadMeshFileParts(path, mesh.get(), &state.parts, &state.load_error)) {
      state.mesh = std::move(mesh);
    }
    std::lock_guard<std::mutex> lock(mutex_);
    ++files_loaded_;
  }
  if (!state.mesh && error) *error = state.load_error;
  return state.mesh;
}

// One read of an STL file (DirectStl): a binary STL's distinct positions (its hull-bound points),
// its triangles on them and what LoadMeshFile's mesh is made of (so assimp is not needed for
// it); an ascii STL's triangles. Nothing for other files (then LoadMeshFile).
void MeshCache::ReadDirectLocked(FileState& state, const std::string& path) {
  if (state.direct_tried) return;
  state.direct_tried = true;
  if (!IsStlPath(path) || state.IsPart()) return;
  auto stl = std::make_shared<internal::DirectStl>();
  // With the cache, the content hash of the bytes read: the file need not be read again to save
  // its entry, and the entry is saved under the hash of exactly the bytes its numbers come from
  // (should the file change after a lookup hashed it).
  internal::ContentHasher hasher;
  const bool hash = state.stat_ok;
  if (!internal::ReadStlDirectFile(path, stl.get(), hash ? &hasher : nullptr)) return;
  if (hash && hasher.size() == state.key.size) {
    state.key.content_hash = hasher.Finish();
    state.key.hashed = true;
  }
  if (stl->joined && !state.stored.points) {
    auto points = std::make_shared<MeshPoints>();
    points->positions = stl->mesh.vertices;
    points->loader_vertices = static_cast<std::int64_t>(stl->vertex_position.size());
    state.stored.points = std::move(points);
    state.dirty = true;
  }
  state.direct = std::move(stl);
  std::lock_guard<std::mutex> lock(mutex_);
  ++files_loaded_;
}

std::shared_ptr<const TriangleMesh> MeshCache::Load(const std::string& path, std::string* error,
                                                    const MeshSubmesh& submesh) {
  FileState& state = StateOf(path, submesh);
  std::lock_guard<std::mutex> lock(state.mutex);
  return LoadLocked(state, path, error);
}

std::optional<MeshMassProperties> MeshCache::MassProperties(const std::string& path,
                                                            const Eigen::Vector3d& scale,
                                                            const MeshInertiaOptions& options,
                                                            std::string* error,
                                                            const MeshSubmesh& submesh) {
  FileState& state = StateOf(path, submesh);
  std::lock_guard<std::mutex> lock(state.mutex);
  const internal::MassKey key = KeyOf(scale, options);
  auto known = [&]() -> const MeshMassProperties* {
    for (const auto& [k, properties] : state.stored.properties) {
      if (k == key) return &properties;
    }
    return nullptr;
  };
  LookUp(state, path);
  if (const MeshMassProperties* found = known()) return *found;
  // A closed solid found with other open-mesh options (the density rules' and the hull bound's
  // differ only there) is this one too: the branches that give it do not look at those options.
  for (const auto& [k, properties] : state.stored.properties) {
    const MeshDiagnostics& d = properties.diagnostics;
    if (std::get<0>(k) == scale.x() && std::get<1>(k) == scale.y() && std::get<2>(k) == scale.z() &&
        std::get<4>(k) == options.shell_thickness && std::get<5>(k) == options.closure_tolerance &&
        d.model == MeshSolidModel::kClosedSolid &&
        d.fallback_reason.rfind(kIntegratedDespite, 0) != 0) {
      MeshMassProperties same = properties;  // copied before the vector may grow
      state.stored.properties.emplace_back(key, same);
      state.dirty = true;
      return same;
    }
  }
  if (auto failed = state.mass_errors.find(key); failed != state.mass_errors.end()) {
    if (error) *error = failed->second;
    return std::nullopt;
  }
  MeshInertiaOptions unit_density = options;
  unit_density.density = 1;
  std::string why;
  try {
    // An STL read directly: a binary STL's triangles are LoadMeshFile's, so the same numbers for
    // every model but the convex hull, which qhull computes from the vertex list. With the hull
    // model, the probe models an open mesh as a thin shell (cheap) and its result is dropped when
    // the mesh turns out open: then LoadMeshFile's mesh (a binary STL's from the same read).
    ReadDirectLocked(state, path);
    std::optional<MeshMassProperties> properties;
    if (state.direct) {
      const bool hull = unit_density.open_mesh_model == MeshSolidModel::kConvexHull;
      MeshInertiaOptions probe = unit_density;
      if (hull) probe.open_mesh_model = MeshSolidModel::kThinShell;
      const TriangleMesh* triangles = &state.direct->mesh;
      TriangleMesh scaled;
      if (!IsIdentity(scale)) {
        scaled = ScaleMesh(*triangles, scale);
        triangles = &scaled;
      }
      properties = CalcRemembering(&state.analyses, *triangles, scale, true,
                                   state.direct->joined && StayDistinct(scale), probe);
      // An ascii STL's triangles are assimp's only when no nearby positions share one of its
      // buckets (stl_direct.cc), which is not checked there: its numbers are kept only for a
      // closed solid, whose integral any such join would hardly change, as before.
      const bool keep = properties->diagnostics.model == MeshSolidModel::kClosedSolid ||
                        (!hull && state.direct->joined);
      if (!keep) properties.reset();
    }
    if (!properties) {
      if (std::shared_ptr<const TriangleMesh> mesh = LoadLocked(state, path, &why)) {
        const TriangleMesh* triangles = mesh.get();
        TriangleMesh scaled;
        if (!IsIdentity(scale)) {
          scaled = ScaleMesh(*mesh, scale);
          triangles = &scaled;
        }
        properties =
            CalcRemembering(&state.analyses, *triangles, scale, false, false, unit_density);
      }
    }
    if (properties) {
      state.stored.properties.emplace_back(key, *properties);
      state.dirty = true;
      return properties;
    }
  } catch (const std::exception& e) {
    why = "mesh file '" + path + "': " + e.what();
  }
  state.mass_errors.emplace(key, why);
  if (error) *error = why;
  return std::nullopt;
}

std::optional<Eigen::AlignedBox3d> MeshCache::Bounds(const std::string& path, std::string* error,
                                                     const MeshSubmesh& submesh) {
  FileState& state = StateOf(path, submesh);
  std::lock_guard<std::mutex> lock(state.mutex);
  LookUp(state, path);
  if (!state.bounded && !state.stored.box) {
    state.bounded = true;
    // An STL: its box from the one read that gives the rest (a file Bounds read).
    const bool unread = !state.direct_tried && !state.loaded;
    ReadDirectLocked(state, path);
    if (unread && state.direct) {
      std::lock_guard<std::mutex> lock_counters(mutex_);
      ++files_bounded_;
    }
    const TriangleMesh* mesh = state.mesh ? state.mesh.get() : nullptr;
    if (mesh == nullptr && state.direct) mesh = &state.direct->mesh;
    if (mesh == nullptr && !state.loaded && (!HasDirectBox(path) || state.IsPart())) {
      // A DAE, glTF or other file only assimp reads: its box from LoadMeshFile's mesh, which is
      // kept for the numbers asked next (the rules ask them of nearly every mesh), so the file is
      // imported once. LoadMeshBounds would import it and drop the mesh. A part: its mesh.
      mesh = LoadLocked(state, path, nullptr).get();  // state.mesh keeps it
    }
    if (mesh != nullptr) {  // read already: its box, no second read
      Eigen::AlignedBox3d box;
      for (const Eigen::Vector3d& v : mesh->vertices) box.extend(v);
      state.stored.box = box;
    } else if (state.loaded) {
      state.bounds_error = state.load_error;
    } else {
      {
        std::lock_guard<std::mutex> lock_counters(mutex_);
        ++files_bounded_;
      }
      Eigen::AlignedBox3d box;
      if (LoadMeshBounds(path, &box, nullptr, &state.bounds_error)) state.stored.box = box;
    }
    if (state.stored.box) state.dirty = true;
  }
  if (!state.stored.box && error) *error = state.bounds_error;
  return state.stored.box;
}

std::shared_ptr<const MeshPoints> MeshCache::Points(const std::string& path, std::string* error,
                                                    const MeshSubmesh& submesh) {
  FileState& state = StateOf(path, submesh);
  std::lock_guard<std::mutex> lock(state.mutex);
  LookUp(state, path);
  if (!state.pointed && !state.stored.points) {
    state.pointed = true;
    ReadDirectLocked(state, path);
    if (!state.stored.points) {
      if (std::shared_ptr<const TriangleMesh> mesh = LoadLocked(state, path, &state.points_error)) {
        auto points = std::make_shared<MeshPoints>();
        points->positions = DistinctPositions(*mesh);
        points->loader_vertices = static_cast<std::int64_t>(mesh->vertices.size());
        state.stored.points = std::move(points);
        state.dirty = true;
      }
    }
  }
  if (!state.stored.points && error) *error = state.points_error;
  return state.stored.points;
}

std::optional<std::vector<std::string>> MeshCache::SubmeshNames(const std::string& path,
                                                                std::string* error) {
  FileState& state = StateOf(path, {});
  std::lock_guard<std::mutex> lock(state.mutex);
  if (!LoadLocked(state, path, error)) return std::nullopt;
  return internal::PartNames(state.parts);  // none for an STL read directly
}

int MeshCache::files_loaded() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return files_loaded_;
}

int MeshCache::files_bounded() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return files_bounded_;
}

int MeshCache::files_from_persistent_cache() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return files_from_store_;
}

std::string DefaultMeshCacheFolder() { return internal::DefaultMeshStoreFolder(); }

long CleanMeshCache(const std::string& folder, std::string* error) {
  return internal::RemoveMeshStore(folder, error);
}

}  // namespace massprops

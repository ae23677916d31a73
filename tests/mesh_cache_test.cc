// MeshCache's numbers kept between runs (UsePersistentCache, src/mesh/mesh_store.h) and its
// one read per STL file (Points, MassProperties). Every cache folder here is a fresh temporary
// one: never the user's.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "massprops/mesh/mesh_loader.h"
#include "shared_data.h"

namespace massprops {
namespace {
namespace fs = std::filesystem;

const std::string kMeshDir = std::string(MASSPROPS_TESTDATA_DIR) + "/mesh";

// A fresh folder under the system's temporary folder, removed at the end of the test.
class TempFolder {
 public:
  TempFolder() {
    std::string pattern = (fs::temp_directory_path() / "massprops-cache-test-XXXXXX").string();
    path_ = mkdtemp(pattern.data());
  }
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string operator/(const std::string& name) const { return path_ + "/" + name; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// Writes a binary STL of the cube [0, a]³: 12 triangles wound outward, each corner written in
// each of its triangles, with the facets' normals.
void WriteCubeStl(const std::string& path, float a) {
  using V = std::array<float, 3>;
  const auto corner = [a](int i) { return V{(i & 1) * a, ((i >> 1) & 1) * a, ((i >> 2) & 1) * a}; };
  // Two triangles per face, counter-clockwise seen from outside: corner indices (bit 0 = x,
  // bit 1 = y, bit 2 = z) and the outward normal.
  const std::vector<std::tuple<std::array<int, 3>, V>> facets = {
      {{0, 2, 1}, {0, 0, -1}}, {{1, 2, 3}, {0, 0, -1}}, {{4, 5, 6}, {0, 0, 1}},
      {{5, 7, 6}, {0, 0, 1}},  {{0, 1, 4}, {0, -1, 0}}, {{1, 5, 4}, {0, -1, 0}},
      {{2, 6, 3}, {0, 1, 0}},  {{3, 6, 7}, {0, 1, 0}},  {{0, 4, 2}, {-1, 0, 0}},
      {{2, 4, 6}, {-1, 0, 0}}, {{1, 3, 5}, {1, 0, 0}},  {{3, 7, 5}, {1, 0, 0}}};
  std::string bytes(80, ' ');
  const std::uint32_t count = static_cast<std::uint32_t>(facets.size());
  bytes.append(reinterpret_cast<const char*>(&count), 4);
  for (const auto& [corners, normal] : facets) {
    bytes.append(reinterpret_cast<const char*>(normal.data()), 12);
    for (const int c : corners) bytes.append(reinterpret_cast<const char*>(corner(c).data()), 12);
    bytes.append(2, '\0');
  }
  std::ofstream(path, std::ios::binary) << bytes;
}

struct Numbers {
  Eigen::AlignedBox3d box;
  std::shared_ptr<const MeshPoints> points;
  MeshMassProperties properties;
};

Numbers Read(MeshCache* cache, const std::string& path) {
  std::string error;
  Numbers numbers;
  const auto box = cache->Bounds(path, &error);
  numbers.points = cache->Points(path, &error);
  const auto properties =
      cache->MassProperties(path, Eigen::Vector3d(1, 2, 3), MeshInertiaOptions{}, &error);
  EXPECT_TRUE(box && numbers.points && properties) << error;
  if (box) numbers.box = *box;
  if (properties) numbers.properties = *properties;
  return numbers;
}

std::vector<fs::path> EntriesIn(const std::string& folder) {
  std::vector<fs::path> entries;
  for (const auto& entry : fs::directory_iterator(folder)) entries.push_back(entry.path());
  return entries;
}

TEST(MeshCacheTest, SecondRunReadsNoMeshAndGetsTheSameNumbers) {
  TempFolder temp;
  const std::string mesh = temp / "cube.stl";
  WriteCubeStl(mesh, 0.5f);
  Numbers first;
  {
    MeshCache cache;
    cache.UsePersistentCache(temp / "cache");
    first = Read(&cache, mesh);
    EXPECT_EQ(cache.files_loaded(), 1);  // one direct read for the box, points and integral
    EXPECT_EQ(cache.files_from_persistent_cache(), 0);
  }  // written here
  // The cube of side 0.5 scaled by (1, 2, 3): volume 0.125 · 6 (hand-derived), center
  // (0.25, 0.5, 0.75); 8 distinct corners, 24 vertices once joined (each corner in 3 faces of
  // different normals, as assimp joins them).
  EXPECT_DOUBLE_EQ(first.properties.volume, 0.75);
  EXPECT_TRUE(first.properties.p_GoGcm_G.isApprox(Eigen::Vector3d(0.25, 0.5, 0.75), 1e-15));
  EXPECT_EQ(first.points->positions.size(), 8u);
  EXPECT_EQ(first.points->loader_vertices, 24);
  MeshCache again;
  again.UsePersistentCache(temp / "cache");
  const Numbers second = Read(&again, mesh);
  EXPECT_EQ(again.files_loaded(), 0);
  EXPECT_EQ(again.files_bounded(), 0);
  EXPECT_EQ(again.files_from_persistent_cache(), 1);
  EXPECT_EQ(second.box.min(), first.box.min());
  EXPECT_EQ(second.box.max(), first.box.max());
  EXPECT_EQ(second.points->positions, first.points->positions);
  EXPECT_EQ(second.points->loader_vertices, first.points->loader_vertices);
  EXPECT_EQ(second.properties.volume, first.properties.volume);  // bit for bit
  EXPECT_EQ(second.properties.p_GoGcm_G, first.properties.p_GoGcm_G);
  EXPECT_EQ(second.properties.I_GGcm_G.CopyToFullMatrix3(),
            first.properties.I_GGcm_G.CopyToFullMatrix3());
  EXPECT_EQ(second.properties.diagnostics.edges, 18);  // 12 cube edges + 6 face diagonals
}

TEST(MeshCacheTest, ChangedFileIsReadAgain) {
  TempFolder temp;
  const std::string mesh = temp / "cube.stl";
  WriteCubeStl(mesh, 0.5f);
  {
    MeshCache cache;
    cache.UsePersistentCache(temp / "cache");
    Read(&cache, mesh);
  }
  WriteCubeStl(mesh, 2.0f);  // same size, new content (and modification time)
  MeshCache cache;
  cache.UsePersistentCache(temp / "cache");
  const Numbers numbers = Read(&cache, mesh);
  EXPECT_EQ(cache.files_from_persistent_cache(), 0);
  EXPECT_EQ(cache.files_loaded(), 1);
  EXPECT_DOUBLE_EQ(numbers.properties.volume, 8.0 * 6);  // 2³ scaled by 1 · 2 · 3
  EXPECT_EQ(numbers.box.max(), Eigen::Vector3d(2, 2, 2));
}

// The cache key's content hash reads 32-byte blocks in four lanes of 8 bytes, then the last bytes
// (mesh_store.cc): a file that differs from a cached one in one byte, in any lane or in the tail,
// is another entry. The cube's STL is 684 bytes (84 + 12 · 50): 21 blocks and 12 more. The bytes
// changed are in the header (offsets 0 to 79) or the last facet's attribute (683), which the
// geometry ignores: only the key tells the files apart.
TEST(MeshCacheTest, FilesThatDifferInOneByteAreDifferentEntries) {
  TempFolder temp;
  const std::string mesh = temp / "cube.stl";
  WriteCubeStl(mesh, 1.0f);
  std::string original;
  {
    std::ifstream in(mesh, std::ios::binary);
    original.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  ASSERT_EQ(original.size(), 684u);
  auto read_as = [&](const std::string& bytes) {
    std::ofstream(mesh, std::ios::binary | std::ios::trunc) << bytes;
    MeshCache cache;
    cache.UsePersistentCache(temp / "cache");
    const Numbers numbers = Read(&cache, mesh);
    EXPECT_EQ(numbers.box.max(), Eigen::Vector3d(1, 1, 1));
    return cache.files_from_persistent_cache();
  };
  EXPECT_EQ(read_as(original), 0);
  for (const std::size_t offset : {0, 8, 16, 24, 31, 40, 63, 79, 683}) {
    std::string changed = original;
    changed[offset] = static_cast<char>(changed[offset] ^ 1);
    EXPECT_EQ(read_as(changed), 0) << offset;  // not the entry of any file before
    EXPECT_EQ(read_as(changed), 1) << offset;  // its own entry, found by its content
  }
  EXPECT_EQ(read_as(original), 1);
}

TEST(MeshCacheTest, UnchangedOlderFileIsFoundByItsPathSizeAndTime) {
  // A file last modified a minute ago gets a stat entry: the next run does not even hash it
  // (checked by making the file unreadable: its numbers still come from the cache).
  TempFolder temp;
  const std::string mesh = temp / "cube.stl";
  WriteCubeStl(mesh, 0.5f);
  fs::last_write_time(mesh, fs::last_write_time(mesh) - std::chrono::minutes(1));
  {
    MeshCache cache;
    cache.UsePersistentCache(temp / "cache");
    Read(&cache, mesh);
  }
  EXPECT_EQ(EntriesIn(temp / "cache").size(), 2u);  // the numbers and the stat entry
  if (geteuid() != 0) {                             // root reads any file
    fs::permissions(mesh, fs::perms::none);
    MeshCache cache;
    cache.UsePersistentCache(temp / "cache");
    std::string error;
    EXPECT_TRUE(cache.Bounds(mesh, &error)) << error;
    EXPECT_EQ(cache.files_from_persistent_cache(), 1);
    fs::permissions(mesh, fs::perms::owner_all);
  }
}

int StatFilesIn(const std::string& folder) {
  int n = 0;
  for (const fs::path& entry : EntriesIn(folder))
    n += entry.filename().string().rfind("r-", 0) == 0;
  return n;
}

// One run's stat entries are one file, whatever the number of meshes; when a run reads 16 such
// files, it merges them all into its own. A stat entry is trusted without reading the file: a
// file rewritten with other bytes of the same size, given back its recorded modification time
// (and keeping its inode), still gets the numbers of its old bytes. That shows that the merged
// entries are the ones used.
TEST(MeshCacheTest, StatEntriesAreOneFilePerRunAndMergedPastSixteen) {
  TempFolder temp;
  const std::string cache_folder = temp / "cache";
  std::vector<std::string> meshes;
  for (int i = 1; i <= 19; ++i) {
    meshes.push_back(temp / ("cube" + std::to_string(i) + ".stl"));
    WriteCubeStl(meshes.back(), static_cast<float>(i));
    fs::last_write_time(meshes.back(),
                        fs::last_write_time(meshes.back()) - std::chrono::minutes(1));
  }
  {  // the first three meshes in one run: three entries, one stat file
    MeshCache cache;
    cache.UsePersistentCache(cache_folder);
    for (int i = 0; i < 3; ++i) Read(&cache, meshes[static_cast<std::size_t>(i)]);
  }
  EXPECT_EQ(EntriesIn(cache_folder).size(), 4u);
  EXPECT_EQ(StatFilesIn(cache_folder), 1);
  for (std::size_t i = 3; i < meshes.size(); ++i) {  // then one mesh per run (written at its end)
    {
      MeshCache cache;
      cache.UsePersistentCache(cache_folder);
      Read(&cache, meshes[i]);
    }
    // Runs 2 to 17 add a file each; run 18 reads 16 and merges them all into its own.
    EXPECT_EQ(StatFilesIn(cache_folder), i < 18 ? static_cast<int>(i) - 1 : 1) << i;
  }
  EXPECT_EQ(StatFilesIn(cache_folder), 1);
  // The first cube (side 1) rewritten as the cube of side 0.5: 684 bytes either way.
  const auto time = fs::last_write_time(meshes[0]);
  WriteCubeStl(meshes[0] + ".new", 0.5f);
  {
    std::ifstream in(meshes[0] + ".new", std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(meshes[0], std::ios::binary | std::ios::in | std::ios::out)
        << bytes;  // same inode
  }
  fs::last_write_time(meshes[0], time);
  MeshCache cache;
  cache.UsePersistentCache(cache_folder);
  for (const std::string& mesh : meshes) Read(&cache, mesh);
  EXPECT_EQ(cache.files_from_persistent_cache(), 19);
  EXPECT_EQ(cache.files_loaded(), 0);
  // The side-1 cube's numbers (scaled by (1, 2, 3): volume 6), not the side-0.5 one's (0.75).
  EXPECT_DOUBLE_EQ(Read(&cache, meshes[0]).properties.volume, 6.0);
}

// A merge keeps each path's newest stat entry only: the file's time at its last run.
TEST(MeshCacheTest, AMergeKeepsEachPathsNewestStatEntry) {
  TempFolder temp;
  const std::string cache_folder = temp / "cache";
  const std::string mesh = temp / "a.stl";
  WriteCubeStl(mesh, 1.0f);
  const auto now = fs::last_write_time(mesh);
  const auto run = [&](const std::string& path) {
    MeshCache cache;
    cache.UsePersistentCache(cache_folder);
    return Read(&cache, path).properties.volume;
  };
  fs::last_write_time(mesh, now - std::chrono::minutes(2));
  run(mesh);  // its stat entry at now − 2 min
  fs::last_write_time(mesh, now - std::chrono::minutes(1));
  run(mesh);  // found by content; its stat entry at now − 1 min
  bool merged = false;
  for (int i = 0; i < 20 && !merged; ++i) {  // one new mesh per run until a run merges
    const std::string other = temp / ("b" + std::to_string(i) + ".stl");
    WriteCubeStl(other, 2.0f + static_cast<float>(i));
    fs::last_write_time(other, now - std::chrono::minutes(1));
    run(other);
    merged = StatFilesIn(cache_folder) == 1;
  }
  ASSERT_TRUE(merged);
  // The file rewritten as the cube of side 0.5 (the same 684 bytes' size, the same inode).
  const std::string smaller = temp / "smaller.stl";
  WriteCubeStl(smaller, 0.5f);
  {
    std::ifstream in(smaller, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(mesh, std::ios::binary | std::ios::in | std::ios::out) << bytes;
  }
  // At the newest time, the entry is trusted: the side-1 cube's volume, scaled by (1, 2, 3): 6.
  fs::last_write_time(mesh, now - std::chrono::minutes(1));
  EXPECT_DOUBLE_EQ(run(mesh), 6.0);
  // At the older time there is no entry any more: the file is hashed, and its bytes give 0.75.
  fs::last_write_time(mesh, now - std::chrono::minutes(2));
  EXPECT_DOUBLE_EQ(run(mesh), 0.75);
}

TEST(MeshCacheTest, SameBytesWithANewTimeAreFoundByTheirContent) {
  // A checkout on CI gives every file a new modification time: the entry is found by hashing.
  TempFolder temp;
  const std::string mesh = temp / "cube.stl";
  WriteCubeStl(mesh, 0.5f);
  {
    MeshCache cache;
    cache.UsePersistentCache(temp / "cache");
    Read(&cache, mesh);
  }
  fs::last_write_time(mesh, fs::last_write_time(mesh) + std::chrono::hours(1));
  MeshCache cache;
  cache.UsePersistentCache(temp / "cache");
  Read(&cache, mesh);
  EXPECT_EQ(cache.files_from_persistent_cache(), 1);
  EXPECT_EQ(cache.files_loaded(), 0);
}

// A binary STL of `copies` unit cubes in a row along x, one unit apart (12 facets each: 84 +
// 600·copies bytes), so that a file spans several of the pieces its readers read.
void WriteCubesStl(const std::string& path, int copies) {
  const std::string cube_path = path + ".one";
  WriteCubeStl(cube_path, 1.0f);
  std::string cube;
  {
    std::ifstream in(cube_path, std::ios::binary);
    cube.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  fs::remove(cube_path);
  std::string bytes = cube.substr(0, 80);
  const auto count = static_cast<std::uint32_t>(12 * copies);
  bytes.append(reinterpret_cast<const char*>(&count), 4);
  for (int c = 0; c < copies; ++c) {
    for (int f = 0; f < 12; ++f) {
      std::string facet = cube.substr(84 + 50 * static_cast<std::size_t>(f), 50);
      for (int corner = 0; corner < 3; ++corner) {  // x of each corner moved by 2c
        float x;
        std::memcpy(&x, facet.data() + 12 + 12 * corner, 4);
        x += static_cast<float>(2 * c);
        std::memcpy(facet.data() + 12 + 12 * corner, &x, 4);
      }
      bytes += facet;
    }
  }
  std::ofstream(path, std::ios::binary) << bytes;
}

// A first run hashes a binary STL in the pass that reads it (no entry of its size yet, so no
// lookup by content); a checkout's run hashes it on its own, in pieces of another size. Both
// must give the same key: the second run finds the first run's entry by content.
TEST(MeshCacheTest, AnEntrySavedFromTheReadingPassIsFoundByContent) {
  TempFolder temp;
  const std::string mesh = temp / "cubes.stl";
  WriteCubesStl(mesh, 250);  // 150 084 bytes: three pieces of 65 500 and of 65 536 bytes
  ASSERT_EQ(fs::file_size(mesh), 150084u);
  Numbers first;
  {
    MeshCache cache;
    cache.UsePersistentCache(temp / "cache");
    first = Read(&cache, mesh);
    EXPECT_EQ(cache.files_loaded(), 1);
  }
  // 250 unit cubes, the last at [498, 499]: the box [0, 499] × [0, 1] × [0, 1]; scaled by
  // (1, 2, 3), each has volume 6 (by hand), 1500 in all.
  EXPECT_EQ(first.box.max(), Eigen::Vector3d(499, 1, 1));
  EXPECT_NEAR(first.properties.volume, 1500, 1e-9);
  fs::last_write_time(mesh, fs::last_write_time(mesh) + std::chrono::hours(1));
  MeshCache cache;
  cache.UsePersistentCache(temp / "cache");
  const Numbers again = Read(&cache, mesh);
  EXPECT_EQ(cache.files_from_persistent_cache(), 1);
  EXPECT_EQ(cache.files_loaded(), 0);
  EXPECT_EQ(again.properties.volume, first.properties.volume);
}

TEST(MeshCacheTest, DamagedEntryIsIgnoredAndRewritten) {
  TempFolder temp;
  const std::string mesh = temp / "cube.stl";
  WriteCubeStl(mesh, 0.5f);
  {
    MeshCache cache;
    cache.UsePersistentCache(temp / "cache");
    Read(&cache, mesh);
  }
  // Flip one byte of the data entry (its volume, say), then truncate it in a second round.
  for (const bool truncate : {false, true}) {
    for (const fs::path& entry : EntriesIn(temp / "cache")) {
      if (entry.filename().string().rfind("d-", 0) != 0) continue;
      std::string bytes;
      {
        std::ifstream in(entry, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
      }
      if (truncate) {
        bytes.resize(bytes.size() / 2);
      } else {
        bytes[bytes.size() / 3] ^= 0x10;
      }
      std::ofstream(entry, std::ios::binary | std::ios::trunc) << bytes;
    }
    {
      MeshCache cache;
      cache.UsePersistentCache(temp / "cache");
      const Numbers numbers = Read(&cache, mesh);
      EXPECT_EQ(cache.files_from_persistent_cache(), 0) << truncate;
      EXPECT_EQ(cache.files_loaded(), 1) << truncate;
      EXPECT_DOUBLE_EQ(numbers.properties.volume, 0.75) << truncate;
    }
    MeshCache rewritten;
    rewritten.UsePersistentCache(temp / "cache");
    Read(&rewritten, mesh);
    EXPECT_EQ(rewritten.files_from_persistent_cache(), 1) << truncate;
  }
}

TEST(MeshCacheTest, ConcurrentWritersLeaveOneWholeEntry) {
  // Sixteen runs at once read and write (when destroyed) the entries of the same two files, 20
  // times each: every run gets the right numbers, whether from a whole entry or by computing
  // them; at the end no temporary file is left and both entries are found.
  TempFolder temp;
  const std::string a = temp / "a.stl", b = temp / "b.stl";
  WriteCubeStl(a, 0.5f);
  WriteCubeStl(b, 2.0f);
  std::atomic<int> found{0}, wrong{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 16; ++t) {
    threads.emplace_back([&] {
      for (int round = 0; round < 20; ++round) {
        MeshCache cache;
        cache.UsePersistentCache(temp / "cache");
        const Numbers na = Read(&cache, a), nb = Read(&cache, b);
        if (na.properties.volume != 0.75 || nb.properties.volume != 48.0) ++wrong;
        found += cache.files_from_persistent_cache();
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(found, 0);
  for (const fs::path& entry : EntriesIn(temp / "cache")) {
    EXPECT_EQ(entry.extension(), "") << entry;  // no leftover .tmp file
  }
  MeshCache after;
  after.UsePersistentCache(temp / "cache");
  Read(&after, a);
  Read(&after, b);
  EXPECT_EQ(after.files_from_persistent_cache(), 2);
}

TEST(MeshCacheTest, FolderIsTrimmedToItsBound) {
  TempFolder temp;
  for (int i = 0; i < 6; ++i) {
    const std::string mesh = temp / ("cube" + std::to_string(i) + ".stl");
    WriteCubeStl(mesh, 0.5f + static_cast<float>(i));
    MeshCache cache;
    cache.UsePersistentCache(temp / "cache", 2000);  // bytes: room for a few entries only
    Read(&cache, mesh);
  }
  std::uintmax_t total = 0;
  for (const fs::path& entry : EntriesIn(temp / "cache")) total += fs::file_size(entry);
  EXPECT_LE(total, 2000u);
  EXPECT_GT(total, 0u);
}

TEST(MeshCacheTest, CleanRemovesTheFolder) {
  TempFolder temp;
  const std::string mesh = temp / "cube.stl";
  WriteCubeStl(mesh, 0.5f);
  {
    MeshCache cache;
    cache.UsePersistentCache(temp / "cache");
    Read(&cache, mesh);
  }
  std::string error;
  // One entry (the file was just written: no stat entry, its next run hashes it).
  EXPECT_EQ(CleanMeshCache(temp / "cache", &error), 1) << error;
  EXPECT_FALSE(fs::exists(temp / "cache"));
  EXPECT_EQ(CleanMeshCache(temp / "cache", &error), 0) << error;
}

TEST(MeshCacheTest, FolderFollowsXdgCacheHome) {
  // The XDG base directory specification: an absolute XDG_CACHE_HOME, else ~/.cache.
  const char* saved = std::getenv("XDG_CACHE_HOME");
  const std::string restore = saved ? saved : "";
  setenv("XDG_CACHE_HOME", "/somewhere/cache", 1);
  EXPECT_EQ(DefaultMeshCacheFolder(), "/somewhere/cache/massprops/meshes");
  setenv("XDG_CACHE_HOME", "relative/cache", 1);
  const char* home = std::getenv("HOME");
  if (home != nullptr) {
    EXPECT_EQ(DefaultMeshCacheFolder(), std::string(home) + "/.cache/massprops/meshes");
  }
  if (saved) {
    setenv("XDG_CACHE_HOME", restore.c_str(), 1);
  } else {
    unsetenv("XDG_CACHE_HOME");
  }
}

// Points: the distinct positions of LoadMeshFile's (assimp's) mesh and its vertex count, from
// one direct read of a binary STL; the same as computed from assimp's mesh for the ascii STL,
// an OBJ and a DAE, and for the corpus' SolidWorks exports (binary STL).
TEST(MeshCacheTest, PointsAreThoseOfTheFullLoader) {
  std::vector<std::string> files = {kMeshDir + "/box_binary.stl", kMeshDir + "/box_ascii.stl",
                                    kMeshDir + "/cube_quads.obj", kMeshDir + "/tet_cm.dae"};
  const std::string corpus = std::string(MASSPROPS_CORPUS_DIR) +
                             "/example-robot-data/robots/double_pendulum_description/meshes/";
  if (test_support::SharedPartPresent(
          "corpus/example-robot-data/robots/double_pendulum_description/meshes")) {
    for (const char* name : {"base_link.stl", "link1.stl", "link2.stl"}) {
      files.push_back(corpus + name);
    }
  }
  for (const std::string& file : files) {
    MeshCache cache;
    std::string error;
    const std::shared_ptr<const MeshPoints> points = cache.Points(file, &error);
    ASSERT_TRUE(points) << file << ": " << error;
    TriangleMesh assimp;
    ASSERT_TRUE(LoadMeshFile(file, &assimp, &error)) << error;
    EXPECT_EQ(points->loader_vertices, static_cast<std::int64_t>(assimp.vertices.size())) << file;
    // The same set of positions (independently: an ordered set of the loader's vertices).
    auto key = [](const Eigen::Vector3d& v) { return std::array<double, 3>{v.x(), v.y(), v.z()}; };
    std::set<std::array<double, 3>> expected, got;
    for (const Eigen::Vector3d& v : assimp.vertices) expected.insert(key(v));
    for (const Eigen::Vector3d& v : points->positions) got.insert(key(v));
    EXPECT_EQ(got, expected) << file;
    EXPECT_EQ(got.size(), points->positions.size()) << file;  // each once
  }
}

// An open mesh is asked for with several sets of options in one run, and its analysis (topology,
// box, signed integrals) is kept between them by file and scale: each answer must be the number
// a fresh CalcMeshMassProperties gives for those options, bit for bit, and the hand-worked value.
// testdata/mesh/open_box.obj is the box 0.1 x 0.2 x 0.3 without its top face, wound outward. By
// hand: as a closed solid despite the hole, the signed integral about the box's center is the box
// (0.006 m³) less the pyramid from the center to the missing face (0.02 m² x 0.15 m / 3 = 0.001):
// 0.005; as a thin shell, its area 0.02 + 2 x 0.03 + 2 x 0.06 = 0.2 m² times the default 1 mm:
// 2e-4 m³; as its convex hull, the whole box: 0.006. Scaled by 2 along x, each volume doubles.
TEST(MeshCacheTest, AnOpenMeshAskedWithEveryModelGetsEachModelsNumbers) {
  const std::string path = kMeshDir + "/open_box.obj";
  TriangleMesh mesh;
  std::string error;
  ASSERT_TRUE(LoadMeshFile(path, &mesh, &error)) << error;
  MeshCache cache;
  struct Case {
    MeshSolidModel model;
    Eigen::Vector3d scale;
    double volume;
  };
  const Eigen::Vector3d one = Eigen::Vector3d::Ones(), twice_x(2, 1, 1);
  for (const Case& c :
       {Case{MeshSolidModel::kClosedSolid, one, 0.005}, Case{MeshSolidModel::kThinShell, one, 2e-4},
        Case{MeshSolidModel::kConvexHull, one, 0.006},
        Case{MeshSolidModel::kThinShell, twice_x, -1},  // area by its own
        Case{MeshSolidModel::kClosedSolid, twice_x, 0.010},
        Case{MeshSolidModel::kConvexHull, twice_x, 0.012}}) {
    MeshInertiaOptions options;
    options.open_mesh_model = c.model;
    const std::optional<MeshMassProperties> cached =
        cache.MassProperties(path, c.scale, options, &error);
    ASSERT_TRUE(cached) << error;
    const MeshMassProperties fresh = CalcMeshMassProperties(ScaleMesh(mesh, c.scale), options);
    EXPECT_EQ(cached->volume, fresh.volume);
    EXPECT_EQ(cached->p_GoGcm_G, fresh.p_GoGcm_G);
    EXPECT_EQ(cached->I_GGcm_G.CopyToFullMatrix3(), fresh.I_GGcm_G.CopyToFullMatrix3());
    EXPECT_EQ(cached->diagnostics.model, c.model);
    EXPECT_EQ(cached->diagnostics.boundary_edges, 4);
    EXPECT_EQ(cached->diagnostics.reference_point_sensitivity,
              fresh.diagnostics.reference_point_sensitivity);
    EXPECT_EQ(cached->diagnostics.fallback_reason, fresh.diagnostics.fallback_reason);
    if (c.volume > 0) {
      EXPECT_NEAR(cached->volume, c.volume, 1e-6 * c.volume);  // the file's floats: 1e-7
    }
  }
  // Scaled by 2 along x: area 2 x 0.02 + 2 x 0.06 + 2 x 0.06 = 0.28 m², so 2.8e-4 m³ of shell.
  MeshInertiaOptions shell;
  shell.open_mesh_model = MeshSolidModel::kThinShell;
  EXPECT_NEAR(cache.MassProperties(path, twice_x, shell, &error)->volume, 2.8e-4, 2.8e-10);
  EXPECT_EQ(cache.files_loaded(), 1);
}

}  // namespace
}  // namespace massprops

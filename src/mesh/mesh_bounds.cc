// LoadMeshBounds (mesh_loader.h): the bounding box of a mesh file without its mass properties.
// STL and OBJ are read here directly (no assimp: the mesh libraries stay unloaded); anything
// else, and anything these readers do not understand, goes through LoadMeshFile so that the box
// is always that of the mesh the full loader gives.
#include <Eigen/Geometry>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "massprops/mesh/mesh_loader.h"
#include "mesh/stl_direct.h"

namespace massprops {
namespace {

// What a direct reader found: a box, or "not understood" (then LoadMeshFile decides, and says
// what is wrong when the file cannot be used).
enum class Direct { kBox, kNotUnderstood };

// Assimp keeps coordinates as 32-bit floats (ai_real): a vertex of the full loader is the float
// nearest to the number written, so the direct readers parse coordinates with strtof.

bool EndsWithNoCase(const std::string& text, const char* suffix) {
  const std::size_t n = std::strlen(suffix);
  if (text.size() < n) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[text.size() - n + i]);
    if (std::tolower(c) != suffix[i]) return false;
  }
  return true;
}

bool ReadWholeFile(const std::string& path, std::string* bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  bytes->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

// Binary STL, as assimp 5.2 tells it from ascii: 84 + 50·(triangle count) bytes exactly.
Direct BinaryStlBox(const std::string& bytes, Eigen::AlignedBox3d* box) {
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, sizeof(count));
  if (count == 0) return Direct::kNotUnderstood;  // No triangle: LoadMeshFile's message.
  for (std::uint32_t t = 0; t < count; ++t) {
    const char* facet = bytes.data() + 84 + 50 * static_cast<std::size_t>(t);
    for (int v = 0; v < 3; ++v) {
      float xyz[3];
      std::memcpy(xyz, facet + 12 * (v + 1), sizeof(xyz));  // after the 12-byte normal
      const Eigen::Vector3d p(xyz[0], xyz[1], xyz[2]);
      if (!p.allFinite()) return Direct::kNotUnderstood;
      box->extend(p);
    }
  }
  return Direct::kBox;
}

// Calls visit(p) for every "vertex x y z" of an ascii STL, in order (facets and loops need not be
// checked: their vertices are all the full loader keeps). Returns false when a vertex is not
// three finite numbers. strtof stops at the end of the buffer's text: the bytes are followed by
// '\0'.
template <typename Visit>
bool ForEachAsciiStlVertex(const std::string& bytes, Visit visit) {
  const char* const end = bytes.data() + bytes.size();
  for (const char* at = bytes.data(); at < end;) {
    const char* found = static_cast<const char*>(std::memchr(at, 'v', end - at));
    if (found == nullptr) break;
    const bool word_start =
        found == bytes.data() || std::isspace(static_cast<unsigned char>(found[-1]));
    if (!word_start || end - found < 7 || std::strncmp(found, "vertex", 6) != 0 ||
        !std::isspace(static_cast<unsigned char>(found[6]))) {
      at = found + 1;
      continue;
    }
    float xyz[3];
    const char* cursor = found + 6;
    for (float& c : xyz) {
      char* next = nullptr;
      c = std::strtof(cursor, &next);
      if (next == cursor) return false;
      cursor = next;
    }
    const Eigen::Vector3d p(xyz[0], xyz[1], xyz[2]);
    if (!p.allFinite()) return false;
    visit(p);
    at = cursor;
  }
  return true;
}

// Ascii STL: the box of every vertex.
Direct AsciiStlBox(const std::string& bytes, Eigen::AlignedBox3d* box) {
  std::size_t vertices = 0;
  const bool read = ForEachAsciiStlVertex(bytes, [&](const Eigen::Vector3d& p) {
    box->extend(p);
    ++vertices;
  });
  if (!read || vertices == 0 || vertices % 3 != 0) return Direct::kNotUnderstood;
  return Direct::kBox;
}

Direct StlBox(const std::string& bytes, Eigen::AlignedBox3d* box) {
  if (bytes.size() >= 84) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, sizeof(count));
    if (84 + 50 * static_cast<std::uint64_t>(count) == bytes.size()) {
      return BinaryStlBox(bytes, box);
    }
  }
  const std::size_t first = bytes.find_first_not_of(" \t\r\n\f\v");
  if (first == std::string::npos || bytes.compare(first, 5, "solid") != 0) {
    return Direct::kNotUnderstood;
  }
  return AsciiStlBox(bytes, box);
}

// The numbers of one OBJ line after its keyword; false if a word is not a number.
bool ParseNumbers(const std::string& line, std::size_t from, std::vector<float>* numbers) {
  numbers->clear();
  const char* cursor = line.c_str() + from;
  while (true) {
    while (*cursor == ' ' || *cursor == '\t' || *cursor == '\r') ++cursor;
    if (*cursor == '\0' || *cursor == '#') return true;
    char* next = nullptr;
    const float value = std::strtof(cursor, &next);
    if (next == cursor) return false;
    numbers->push_back(value);
    cursor = next;
  }
}

// The vertex indices of an OBJ element line ("f 1/1/1 2//2 -1", "l 1 2", "p 3"), 0-based, given
// `count` vertices read so far (negative indices count back from the last); false if an index
// is not a valid integer or out of range.
bool ParseElement(const std::string& line, std::size_t count, std::vector<std::size_t>* indices) {
  indices->clear();
  const char* cursor = line.c_str() + 1;
  while (true) {
    while (*cursor == ' ' || *cursor == '\t' || *cursor == '\r') ++cursor;
    if (*cursor == '\0' || *cursor == '#') return true;
    char* next = nullptr;
    const long long index = std::strtoll(cursor, &next, 10);
    if (next == cursor) return false;
    long long zero_based = index > 0 ? index - 1 : static_cast<long long>(count) + index;
    if (index == 0 || zero_based < 0 || zero_based >= static_cast<long long>(count)) return false;
    indices->push_back(static_cast<std::size_t>(zero_based));
    cursor = next;
    while (*cursor != '\0' && *cursor != ' ' && *cursor != '\t' && *cursor != '\r') ++cursor;
  }
}

// OBJ: the box of the vertices that an element (face, line, point) uses, which are the only ones
// assimp's OBJ importer puts into its meshes. Vertex lines of 3 numbers (x y z), 4 (x y z w:
// divided by w, as assimp does) or 6 (x y z r g b).
Direct ObjBox(const std::string& bytes, Eigen::AlignedBox3d* box) {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<bool> used;
  std::vector<float> numbers;
  std::vector<std::size_t> indices;
  bool any_triangle = false;
  std::size_t begin = 0;
  while (begin < bytes.size()) {
    std::size_t end = bytes.find('\n', begin);
    if (end == std::string::npos) end = bytes.size();
    std::string line = bytes.substr(begin, end - begin);
    begin = end + 1;
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    line.erase(0, first);
    const auto last = line.find_last_not_of(" \t\r");
    if (last != std::string::npos && line[last] == '\\') return Direct::kNotUnderstood;
    const char c = line[0];
    const bool keyword_alone = line.size() > 1 && (line[1] == ' ' || line[1] == '\t');
    if (c == 'v' && keyword_alone) {
      if (!ParseNumbers(line, 1, &numbers)) return Direct::kNotUnderstood;
      Eigen::Vector3d p;
      if (numbers.size() == 3 || numbers.size() == 6) {
        p = Eigen::Vector3d(numbers[0], numbers[1], numbers[2]);
      } else if (numbers.size() == 4 && numbers[3] != 0) {
        const float w = numbers[3];
        p = Eigen::Vector3d(numbers[0] / w, numbers[1] / w, numbers[2] / w);
      } else {
        return Direct::kNotUnderstood;
      }
      vertices.push_back(p);
      used.push_back(false);
    } else if ((c == 'f' || c == 'l' || c == 'p') && keyword_alone) {
      if (!ParseElement(line, vertices.size(), &indices)) return Direct::kNotUnderstood;
      if (c == 'f' && indices.size() >= 3) any_triangle = true;
      for (std::size_t i : indices) used[i] = true;
    }
  }
  if (!any_triangle) return Direct::kNotUnderstood;  // LoadMeshFile's message.
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (!used[i]) continue;
    if (!vertices[i].allFinite()) return Direct::kNotUnderstood;
    box->extend(vertices[i]);
  }
  return Direct::kBox;
}

// The triangles of a binary STL (its size already checked: 84 + 50·count bytes).
bool BinaryStlTriangles(const std::string& bytes, TriangleMesh* mesh) {
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, sizeof(count));
  if (count == 0) return false;
  mesh->vertices.reserve(3 * static_cast<std::size_t>(count));
  mesh->triangles.reserve(count);
  for (std::uint32_t t = 0; t < count; ++t) {
    const char* facet = bytes.data() + 84 + 50 * static_cast<std::size_t>(t);
    const std::int32_t first = static_cast<std::int32_t>(mesh->vertices.size());
    for (int v = 0; v < 3; ++v) {
      float xyz[3];
      std::memcpy(xyz, facet + 12 * (v + 1), sizeof(xyz));  // after the 12-byte normal
      const Eigen::Vector3d p(xyz[0], xyz[1], xyz[2]);
      if (!p.allFinite()) return false;
      mesh->vertices.push_back(p);
    }
    mesh->triangles.push_back({first, first + 1, first + 2});
  }
  return true;
}

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
  if (n == 0 || n != 3 * facets) return false;
  for (std::size_t t = 0; t < facets; ++t) {
    const std::int32_t first = static_cast<std::int32_t>(3 * t);
    mesh->triangles.push_back({first, first + 1, first + 2});
  }
  return true;
}

// The hull-bound points of a binary STL (its size already checked): each distinct position
// once (-0 and +0 the same: the first one written is kept), in order of first appearance, and the
// number of vertices assimp 5.2 gives for it. Its STL importer gives every corner the facet's
// normal; aiProcess_JoinIdenticalVertices then keeps a corner unless an earlier kept one is at the
// same position (its spatial sort's tolerance of a few ULPs of the squared distance is exact
// equality at any length above 1e-20) with a normal within 1e-5 (squared distance in float
// arithmetic, not above 1e-10; a NaN normal matches): the same test is made here, in float, against
// the kept corners at that position. False when a coordinate is not finite, or the header asks for
// colors (which assimp's join compares too).
bool BinaryStlPoints(const std::string& bytes, MeshPoints* points) {
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, sizeof(count));
  if (count == 0 || std::string(bytes.data(), 80).find("COLOR=") != std::string::npos) {
    return false;
  }
  const std::size_t corners = 3 * static_cast<std::size_t>(count);
  std::size_t capacity = 16;
  while (capacity < 2 * corners) capacity *= 2;
  // Per distinct position: its index in points->positions; its kept normals in a chain.
  std::vector<std::int32_t> table(capacity, -1);
  std::vector<std::array<float, 3>> position_of;
  std::vector<std::int32_t> first_kept;  // per position: the first kept corner, or -1
  std::vector<std::array<float, 3>> kept_normal;
  std::vector<std::int32_t> next_kept;  // per kept corner: the next at its position, or -1
  position_of.reserve(corners / 4);
  first_kept.reserve(corners / 4);
  auto bits = [](float v) {
    std::uint32_t u;
    const float w = v + 0.0f;  // -0 + 0 == +0
    std::memcpy(&u, &w, sizeof u);
    return u;
  };
  for (std::uint32_t t = 0; t < count; ++t) {
    const char* facet = bytes.data() + 84 + 50 * static_cast<std::size_t>(t);
    std::array<float, 3> normal;
    std::memcpy(normal.data(), facet, sizeof(normal));
    for (int v = 0; v < 3; ++v) {
      std::array<float, 3> p;
      std::memcpy(p.data(), facet + 12 * (v + 1), sizeof(p));
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) return false;
      std::uint64_t h = bits(p[0]) * 0x9E3779B97F4A7C15ull;
      h = (h ^ (h >> 29) ^ bits(p[1])) * 0xBF58476D1CE4E5B9ull;
      h = (h ^ (h >> 32) ^ bits(p[2])) * 0x94D049BB133111EBull;
      std::size_t slot = (h ^ (h >> 31)) & (capacity - 1);
      while (table[slot] >= 0 && position_of[static_cast<std::size_t>(table[slot])] != p) {
        slot = (slot + 1) & (capacity - 1);
      }
      if (table[slot] < 0) {
        table[slot] = static_cast<std::int32_t>(position_of.size());
        position_of.push_back(p);
        first_kept.push_back(-1);
      }
      const auto at = static_cast<std::size_t>(table[slot]);
      bool joined = false;
      for (std::int32_t k = first_kept[at]; k >= 0 && !joined; k = next_kept[k]) {
        const std::array<float, 3>& n = kept_normal[static_cast<std::size_t>(k)];
        const float dx = normal[0] - n[0], dy = normal[1] - n[1], dz = normal[2] - n[2];
        const float square_epsilon = 1e-5f * 1e-5f;
        joined = !(dx * dx + dy * dy + dz * dz > square_epsilon);
      }
      if (joined) continue;
      next_kept.push_back(first_kept[at]);
      first_kept[at] = static_cast<std::int32_t>(kept_normal.size());
      kept_normal.push_back(normal);
    }
  }
  points->loader_vertices = static_cast<std::int64_t>(kept_normal.size());
  points->positions.clear();
  points->positions.reserve(position_of.size());
  for (const auto& p : position_of) points->positions.emplace_back(p[0], p[1], p[2]);
  return true;
}

}  // namespace

namespace internal {

bool ReadStlDirect(const std::string& path, TriangleMesh* mesh, MeshPoints* points,
                   bool* has_points) {
  TriangleMesh found;
  bool ok = false;
  if (has_points) *has_points = false;
  try {
    std::string bytes;
    {
      std::ifstream in(path, std::ios::binary | std::ios::ate);
      if (!in) return false;
      const std::streamoff size = in.tellg();
      if (size <= 0) return false;
      bytes.resize(static_cast<std::size_t>(size));
      in.seekg(0);
      if (!in.read(bytes.data(), size)) return false;
    }
    std::uint32_t count = 0;
    if (bytes.size() >= 84) std::memcpy(&count, bytes.data() + 80, sizeof(count));
    const bool binary =
        bytes.size() >= 84 && 84 + 50 * static_cast<std::uint64_t>(count) == bytes.size();
    if (binary) {
      ok = BinaryStlTriangles(bytes, &found);
    } else {
      const std::size_t first = bytes.find_first_not_of(" \t\r\n\f\v");
      ok = first != std::string::npos && bytes.compare(first, 5, "solid") == 0 &&
           AsciiStlTriangles(bytes, &found);
    }
    // Indices are 32-bit: a file of more than 2^31 / 3 triangles is left to assimp.
    if (ok && found.vertices.size() > 0x7fffffff) ok = false;
    if (ok && binary && points != nullptr && BinaryStlPoints(bytes, points) && has_points) {
      *has_points = true;
    }
  } catch (const std::exception&) {  // std::bad_alloc on a huge file: assimp's message
    ok = false;
  }
  if (ok) *mesh = std::move(found);
  return ok;
}

}  // namespace internal

bool LoadMeshBounds(const std::string& path, Eigen::AlignedBox3d* box, bool* direct,
                    std::string* error) {
  Eigen::AlignedBox3d found;  // empty
  Direct result = Direct::kNotUnderstood;
  const bool stl = EndsWithNoCase(path, ".stl");
  const bool obj = EndsWithNoCase(path, ".obj");
  if (stl || obj) {
    try {
      std::string bytes;
      if (ReadWholeFile(path, &bytes) && !bytes.empty()) {
        result = stl ? StlBox(bytes, &found) : ObjBox(bytes, &found);
      }
    } catch (const std::exception&) {  // std::bad_alloc on a huge file: LoadMeshFile's message
      result = Direct::kNotUnderstood;
    }
  }
  if (direct) *direct = result == Direct::kBox;
  if (result == Direct::kBox) {
    *box = found;
    return true;
  }
  TriangleMesh mesh;
  if (!LoadMeshFile(path, &mesh, error)) return false;
  found.setEmpty();
  for (const Eigen::Vector3d& v : mesh.vertices) found.extend(v);
  *box = found;
  return true;
}

}  // namespace massprops

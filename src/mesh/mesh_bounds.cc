// LoadMeshBounds (mesh_loader.h): the bounding box of a mesh file without its mass properties.
// STL and OBJ are read here directly (no assimp: the mesh libraries stay unloaded); anything
// else, and anything these readers do not understand, goes through LoadMeshFile so that the box
// is always that of the mesh the full loader gives.
#include <Eigen/Geometry>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
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

// Ascii STL: the box of every vertex.
Direct AsciiStlBox(const std::string& bytes, Eigen::AlignedBox3d* box) {
  std::size_t vertices = 0;
  const bool read = internal::ForEachAsciiStlVertex(bytes, [&](const Eigen::Vector3d& p) {
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

}  // namespace

bool LoadMeshBounds(const std::string& path, Eigen::AlignedBox3d* box, bool* direct,
                    std::string* error) {
  Eigen::AlignedBox3d found;  // empty
  Direct result = Direct::kNotUnderstood;
  const bool stl = EndsWithNoCase(path, ".stl");
  const bool obj = EndsWithNoCase(path, ".obj");
  if (stl || obj) {
    try {
      std::string bytes;
      if (internal::ReadWholeFile(path, &bytes) && !bytes.empty()) {
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

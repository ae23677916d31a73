#include "massprops/mesh/mesh_inertia.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "mesh/mesh_backend.h"
#include "mesh/mesh_coincidence.h"

namespace massprops {
namespace {

// The six distinct entries of a symmetric 3x3 matrix: xx, yy, zz, xy, xz, yz.
using Sym6 = std::array<double, 6>;

void ValidateMesh(const TriangleMesh& mesh) {
  const auto n = static_cast<std::int64_t>(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (!mesh.vertices[i].allFinite()) {
      std::ostringstream message;
      message << "mesh vertex " << i << " is not finite: [" << mesh.vertices[i].transpose() << "]";
      throw std::invalid_argument(message.str());
    }
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (const std::int32_t index : mesh.triangles[t]) {
      if (index < 0 || index >= n) {
        std::ostringstream message;
        message << "mesh triangle " << t << " has vertex index " << index << " outside [0, " << n
                << ")";
        throw std::invalid_argument(message.str());
      }
    }
  }
}

// The bounding box of the vertices that triangles use (empty if none).
Eigen::AlignedBox3d UsedBoundingBox(const TriangleMesh& mesh) {
  Eigen::AlignedBox3d box;
  for (const auto& triangle : mesh.triangles) {
    for (const std::int32_t index : triangle) box.extend(mesh.vertices[index]);
  }
  return box;
}

// Its center (the origin if there is no triangle).
Eigen::Vector3d BoundingBoxCenter(const TriangleMesh& mesh) {
  const Eigen::AlignedBox3d box = UsedBoundingBox(mesh);
  return box.isEmpty() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(box.center());
}

// Adds w·(a·aᵀ + b·bᵀ + c·cᵀ + s·sᵀ), s = a + b + c, to C.
inline void AddTriangleSecondMoment(double w, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c, Sym6* C) {
  const Eigen::Vector3d s = a + b + c;
  (*C)[0] += w * (a.x() * a.x() + b.x() * b.x() + c.x() * c.x() + s.x() * s.x());
  (*C)[1] += w * (a.y() * a.y() + b.y() * b.y() + c.y() * c.y() + s.y() * s.y());
  (*C)[2] += w * (a.z() * a.z() + b.z() * b.z() + c.z() * c.z() + s.z() * s.z());
  (*C)[3] += w * (a.x() * a.y() + b.x() * b.y() + c.x() * c.y() + s.x() * s.y());
  (*C)[4] += w * (a.x() * a.z() + b.x() * b.z() + c.x() * c.z() + s.x() * s.z());
  (*C)[5] += w * (a.y() * a.z() + b.y() * b.z() + c.y() * c.z() + s.y() * s.z());
}

// From the zeroth moment m0 (volume or area), the first moment m1 and the second moment
// (covariance) C about R, all about R: the center p_GoGcm_G = R + m1/m0 and the inertia about the
// center, density·(tr(Cc)·1 − Cc) with Cc = C − m0·c·cᵀ, c = m1/m0.
void FinishFromMoments(double m0, const Eigen::Vector3d& m1, const Sym6& C,
                       const Eigen::Vector3d& R, double density, MeshMassProperties* result) {
  if (m0 == 0) {
    result->p_GoGcm_G = R;
    result->I_GGcm_G =
        RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(0, 0, 0, 0, 0, 0, true);
    return;
  }
  const Eigen::Vector3d c = m1 / m0;
  const double xx = C[0] - m0 * c.x() * c.x();
  const double yy = C[1] - m0 * c.y() * c.y();
  const double zz = C[2] - m0 * c.z() * c.z();
  const double xy = C[3] - m0 * c.x() * c.y();
  const double xz = C[4] - m0 * c.x() * c.z();
  const double yz = C[5] - m0 * c.y() * c.z();
  result->p_GoGcm_G = R + c;
  // Inertia = tr(Cc)·1 − Cc: Ixx = yy + zz, and the (negated-product) entry Ixy = −xy.
  result->I_GGcm_G = RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(
      density * (yy + zz), density * (xx + zz), density * (xx + yy), -density * xy, -density * xz,
      -density * yz, true);
}

// Surface area, area-weighted first and second moments of the triangles about R.
double TriangleArea(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return (b - a).cross(c - a).norm() / 2;
}

// R: the center of the box of the used vertices (CalcMeshMassProperties has it).
MeshMassProperties CalcThinShell(const TriangleMesh& mesh, const Eigen::Vector3d& R,
                                 double thickness, double density) {
  double area = 0;
  Eigen::Vector3d m1 = Eigen::Vector3d::Zero();
  Sym6 C{};
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[t[0]] - R;
    const Eigen::Vector3d b = mesh.vertices[t[1]] - R;
    const Eigen::Vector3d c = mesh.vertices[t[2]] - R;
    const double A = TriangleArea(a, b, c);
    area += A;
    // A triangle's first moment is A·(a + b + c)/3 and its second moment
    // A/12·(a·aᵀ + b·bᵀ + c·cᵀ + s·sᵀ) (hand-derived from the barycentric integrals
    // ∫λᵢ² dA = A/6, ∫λᵢλⱼ dA = A/12).
    m1 += A * (a + b + c) / 3;
    AddTriangleSecondMoment(A / 12, a, b, c, &C);
  }
  MeshMassProperties result;
  result.area = area;
  result.volume = area * thickness;
  result.mass = density * result.volume;
  FinishFromMoments(area, m1, C, R, density * thickness, &result);
  return result;
}

std::string DescribeDefects(const MeshDiagnostics& d) {
  std::ostringstream out;
  const char* separator = "";
  if (d.boundary_edges > 0)
    out << separator << d.boundary_edges << " boundary edges", separator = ", ";
  if (d.non_manifold_edges > 0)
    out << separator << d.non_manifold_edges << " non-manifold edges", separator = ", ";
  if (d.inconsistent_edges > 0)
    out << separator << d.inconsistent_edges << " inconsistently oriented edges", separator = ", ";
  return out.str();
}

}  // namespace

const char* ToString(MeshSolidModel model) {
  switch (model) {
    case MeshSolidModel::kClosedSolid:
      return "closed solid";
    case MeshSolidModel::kConvexHull:
      return "convex hull";
    case MeshSolidModel::kThinShell:
      return "thin shell";
  }
  return "unknown";
}

std::string DescribeMeshDiagnostics(const MeshDiagnostics& d) {
  std::vector<std::string> parts;
  if (d.winding_inverted) {
    parts.push_back("its triangles are wound inward (negative volume): the sign was flipped");
  }
  std::vector<std::string> edges;
  if (d.boundary_edges > 0) edges.push_back(std::to_string(d.boundary_edges) + " boundary");
  if (d.non_manifold_edges > 0) {
    edges.push_back(std::to_string(d.non_manifold_edges) + " non-manifold");
  }
  if (d.inconsistent_edges > 0) {
    edges.push_back(std::to_string(d.inconsistent_edges) + " inconsistently oriented");
  }
  if (!edges.empty()) {
    std::string list;
    for (std::size_t i = 0; i < edges.size(); ++i) {
      list += (i == 0 ? "" : i + 1 == edges.size() ? " and " : ", ") + edges[i];
    }
    std::string text = "it is not a closed manifold (" + list + " edges): ";
    if (d.model == MeshSolidModel::kClosedSolid) {
      text +=
          "integrated as a closed solid, since its volume does not depend on the reference "
          "point (cracks or T-junctions of no area)";
    } else {
      text += std::string("modelled as its ") + ToString(d.model);
      // The reason, unless it only repeats the edge counts.
      if (!d.fallback_reason.empty() && d.fallback_reason.find("edge") == std::string::npos) {
        text += " (" + d.fallback_reason + ")";
      }
    }
    parts.push_back(text);
  } else if (d.model != MeshSolidModel::kClosedSolid) {
    std::string text = std::string("modelled as its ") + ToString(d.model);
    if (!d.fallback_reason.empty()) text += " (" + d.fallback_reason + ")";
    parts.push_back(text);
  }
  if (d.degenerate_triangles > 0) {
    parts.push_back(std::to_string(d.degenerate_triangles) + " degenerate triangle(s) add nothing");
  }
  std::string sentence;
  for (std::size_t i = 0; i < parts.size(); ++i) sentence += (i ? "; " : "") + parts[i];
  return sentence;
}

namespace {

// 1. Merges vertices at exactly the same position (-0.0 and 0.0 are the same position), with an
// open-addressing hash table (linear probing, load factor <= 1/2): each vertex's representative.
std::vector<std::int32_t> MergeCoincidentVertices(const TriangleMesh& mesh, MeshDiagnostics* d) {
  auto bits = [](double v) {
    std::uint64_t u;
    const double w = v + 0.0;  // -0.0 + 0.0 == +0.0
    std::memcpy(&u, &w, sizeof u);
    return u;
  };
  auto hash = [&](const Eigen::Vector3d& v) {
    std::uint64_t h = bits(v.x()) * 0x9E3779B97F4A7C15ull;
    h = (h ^ (h >> 29) ^ bits(v.y())) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 32) ^ bits(v.z())) * 0x94D049BB133111EBull;
    return h ^ (h >> 31);
  };
  std::vector<std::int32_t> representative(mesh.vertices.size());
  {
    std::size_t capacity = 16;
    while (capacity < 2 * mesh.vertices.size()) capacity *= 2;
    std::vector<std::int32_t> table(capacity, -1);
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      const Eigen::Vector3d& v = mesh.vertices[i];
      std::size_t slot = hash(v) & (capacity - 1);
      while (table[slot] >= 0 && !(mesh.vertices[table[slot]] == v)) {
        slot = (slot + 1) & (capacity - 1);
      }
      if (table[slot] < 0) {
        table[slot] = static_cast<std::int32_t>(i);
        representative[i] = static_cast<std::int32_t>(i);
      } else {
        representative[i] = table[slot];
        ++d->duplicate_vertices_merged;
      }
    }
  }
  return representative;
}

// 2. Counts degenerate triangles; marks those without a repeated vertex, which alone take part
// in the topology. `rep(i)` is vertex i's representative.
template <typename Representative>
std::vector<char> MarkTrianglesWithEdges(const TriangleMesh& mesh, Representative rep,
                                         MeshDiagnostics* d) {
  std::vector<char> has_edges(mesh.triangles.size(), 0);
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    const std::int32_t r[3] = {rep(t[0]), rep(t[1]), rep(t[2])};
    if (r[0] == r[1] || r[1] == r[2] || r[2] == r[0]) {
      ++d->degenerate_triangles;
      continue;
    }
    has_edges[i] = 1;
    const Eigen::Vector3d& a = mesh.vertices[r[0]];
    const Eigen::Vector3d& b = mesh.vertices[r[1]];
    const Eigen::Vector3d& c = mesh.vertices[r[2]];
    const double longest2 =
        std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    const double twice_area = (b - a).cross(c - a).norm();
    if (twice_area <= 2e-12 * longest2) ++d->degenerate_triangles;
  }
  return has_edges;
}

// 3. Buckets the directed edges by their smaller vertex (counting sort: linear; the edges are
// generated twice from the triangles rather than stored), then sorts each small bucket (its
// size is the vertex's degree) by the larger vertex and counts the uses. An edge is its larger
// vertex and its direction in 32 bits (vertex indices are below 2^31), in an array that is
// written before it is read (not zeroed first).
template <typename Representative>
void CountEdgeUses(const TriangleMesh& mesh, Representative rep, const std::vector<char>& has_edges,
                   MeshDiagnostics* d) {
  auto for_each_edge = [&](auto&& visit) {
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
      if (!has_edges[i]) continue;
      const auto& t = mesh.triangles[i];
      const std::int32_t r[3] = {rep(t[0]), rep(t[1]), rep(t[2])};
      for (int k = 0; k < 3; ++k) visit(r[k], r[(k + 1) % 3]);
    }
  };
  std::vector<std::int64_t> start(mesh.vertices.size() + 1, 0);
  for_each_edge([&](std::int32_t from, std::int32_t to) { ++start[std::min(from, to) + 1]; });
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) start[v + 1] += start[v];
  // hi << 1 | forward
  const std::unique_ptr<std::uint32_t[]> bucket(
      new std::uint32_t[static_cast<std::size_t>(start.back())]);
  {
    std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
    for_each_edge([&](std::int32_t from, std::int32_t to) {
      bucket[fill[std::min(from, to)]++] =
          (static_cast<std::uint32_t>(std::max(from, to)) << 1) | (from < to ? 1u : 0u);
    });
  }
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    std::uint32_t* const begin = bucket.get() + start[v];
    std::uint32_t* const end = bucket.get() + start[v + 1];
    std::sort(begin, end);
    for (const std::uint32_t* it = begin; it != end;) {
      const std::uint32_t hi = *it >> 1;
      std::int64_t uses = 0, forward = 0;
      for (; it != end && (*it >> 1) == hi; ++it) {
        ++uses;
        forward += *it & 1;
      }
      ++d->edges;
      if (uses == 1) {
        ++d->boundary_edges;
      } else if (uses == 2) {
        if (forward != 1) ++d->inconsistent_edges;
      } else {
        ++d->non_manifold_edges;
      }
    }
  }
}

}  // namespace

namespace {

// AnalyzeMeshTopology; with `distinct` (mesh_coincidence.h), each vertex is its own
// representative, else they are found by hashing the positions.
MeshDiagnostics AnalyzeTopology(const TriangleMesh& mesh, bool distinct) {
  if (!distinct) ValidateMesh(mesh);  // else valid by what the caller vouches
  MeshDiagnostics d;
  d.num_vertices = static_cast<std::int64_t>(mesh.vertices.size());
  d.num_triangles = static_cast<std::int64_t>(mesh.triangles.size());
  if (distinct) {
    const auto itself = [](std::int32_t i) { return i; };
    CountEdgeUses(mesh, itself, MarkTrianglesWithEdges(mesh, itself, &d), &d);
  } else {
    const std::vector<std::int32_t> representative = MergeCoincidentVertices(mesh, &d);
    const auto rep = [&representative](std::int32_t i) { return representative[i]; };
    CountEdgeUses(mesh, rep, MarkTrianglesWithEdges(mesh, rep, &d), &d);
  }
  return d;
}

}  // namespace

MeshDiagnostics AnalyzeMeshTopology(const TriangleMesh& mesh) {
  return AnalyzeTopology(mesh, false);
}

namespace {

// The sums of the signed divergence-theorem integral with the reference point R (see
// CalcClosedMeshMassPropertiesSigned). Kallay (2006): over the signed tetrahedra (R, a, b, c),
// 6·volume = det[a b c], 24·first moment = det·(a + b + c), and 120·covariance =
// det·(a·aᵀ + b·bᵀ + c·cᵀ + s·sᵀ).
struct SignedSums {
  Eigen::Vector3d R;
  double six_volume = 0;
  Eigen::Vector3d m1_24 = Eigen::Vector3d::Zero();
  Sym6 C120{};
  double area = 0;

  explicit SignedSums(const Eigen::Vector3d& reference) : R(reference) {}

  void Add(const Eigen::Vector3d& va, const Eigen::Vector3d& vb, const Eigen::Vector3d& vc,
           bool with_area) {
    const Eigen::Vector3d a = va - R;
    const Eigen::Vector3d b = vb - R;
    const Eigen::Vector3d c = vc - R;
    const double det = a.dot(b.cross(c));
    six_volume += det;
    m1_24 += det * (a + b + c);
    AddTriangleSecondMoment(det, a, b, c, &C120);
    if (with_area) area += TriangleArea(a, b, c);
  }

  MeshMassProperties Finish(const TriangleMesh& mesh) const {
    const double volume = six_volume / 6;
    Sym6 C;
    for (int i = 0; i < 6; ++i) C[i] = C120[i] / 120;
    MeshMassProperties result;
    result.volume = volume;
    result.area = area;
    result.mass = volume;
    FinishFromMoments(volume, m1_24 / 24, C, R, 1.0, &result);
    result.diagnostics.num_vertices = static_cast<std::int64_t>(mesh.vertices.size());
    result.diagnostics.num_triangles = static_cast<std::int64_t>(mesh.triangles.size());
    return result;
  }
};

// The signed integral with the reference point R.
MeshMassProperties IntegrateSigned(const TriangleMesh& mesh, const Eigen::Vector3d& R) {
  SignedSums sums(R);
  for (const auto& t : mesh.triangles) {
    sums.Add(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], true);
  }
  return sums.Finish(mesh);
}

// The reference point ReferencePointSensitivity moves the integral's to, from the box `used` of
// the used vertices: its center plus d = the half extents times (1, 0.618, 0.382) (a direction
// no symmetric mesh favours).
Eigen::Vector3d MovedReferencePoint(const Eigen::AlignedBox3d& used) {
  const Eigen::Vector3d& lo = used.min();
  const Eigen::Vector3d& hi = used.max();
  const Eigen::Vector3d d = ((hi - lo) / 2).cwiseProduct(Eigen::Vector3d(1, 0.618, 0.382));
  return (lo + hi) / 2 + d;
}

// How much the signed integral changes when the reference point moves from the bounding-box
// center to MovedReferencePoint: the largest of the relative changes of the volume, of the center
// (relative to the bounding-box diagonal) and of the central inertia (relative to its largest
// entry). Zero up to round-off for a surface that encloses a volume (divergence theorem), whatever
// its edges; about (hole area)/(surface size)² for a surface with holes. `moved` is the integral
// about the moved point (its area is not used).
double ReferencePointSensitivity(const Eigen::AlignedBox3d& used,
                                 const MeshMassProperties& at_center,
                                 const MeshMassProperties& moved) {
  const double diagonal = (used.max() - used.min()).norm();
  const Eigen::Matrix3d I0 = at_center.I_GGcm_G.CopyToFullMatrix3();
  const Eigen::Matrix3d I1 = moved.I_GGcm_G.CopyToFullMatrix3();
  const double scale = I0.cwiseAbs().maxCoeff();
  if (at_center.volume == 0 || diagonal == 0 || scale == 0) return 1.0;
  return std::max({std::abs(moved.volume - at_center.volume) / std::abs(at_center.volume),
                   (moved.p_GoGcm_G - at_center.p_GoGcm_G).norm() / diagonal,
                   (I1 - I0).cwiseAbs().maxCoeff() / scale});
}

}  // namespace

MeshMassProperties CalcClosedMeshMassPropertiesSigned(const TriangleMesh& mesh) {
  ValidateMesh(mesh);
  return IntegrateSigned(mesh, BoundingBoxCenter(mesh));
}

bool CalcConvexHull(const TriangleMesh& mesh, TriangleMesh* hull, std::string* error) {
  ValidateMesh(mesh);
  // The points the triangles use, from the bounding-box center (qhull then works near 0).
  const Eigen::Vector3d R = BoundingBoxCenter(mesh);
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const auto& t : mesh.triangles) used[t[0]] = used[t[1]] = used[t[2]] = 1;
  std::vector<double> points;
  std::vector<std::int32_t> original;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (!used[i]) continue;
    const Eigen::Vector3d p = mesh.vertices[i] - R;
    points.insert(points.end(), {p.x(), p.y(), p.z()});
    original.push_back(static_cast<std::int32_t>(i));
  }
  if (original.size() < 4) {
    if (error) *error = "fewer than 4 points: no convex hull";
    return false;
  }

  const internal::MeshBackend* backend = internal::GetMeshBackend(error);
  if (backend == nullptr) return false;
  std::vector<std::array<int, 3>> facets;
  std::vector<std::array<double, 3>> normals;
  std::string text;
  const int exit_code = backend->convex_hull(points.data(), static_cast<int>(original.size()),
                                             &facets, &normals, &text);
  TriangleMesh result;
  std::unordered_map<int, std::int32_t> hull_index;  // qhull point id → result vertex
  for (std::size_t f = 0; f < facets.size() && exit_code == 0; ++f) {
    std::array<std::int32_t, 3> triangle{};
    for (int k = 0; k < 3; ++k) {
      const int id = facets[f][k];
      auto found = hull_index.find(id);
      if (found == hull_index.end()) {
        found = hull_index.emplace(id, static_cast<std::int32_t>(result.vertices.size())).first;
        result.vertices.push_back(mesh.vertices[original[id]]);
      }
      triangle[k] = found->second;
    }
    const Eigen::Vector3d& a = result.vertices[triangle[0]];
    const Eigen::Vector3d& b = result.vertices[triangle[1]];
    const Eigen::Vector3d& c = result.vertices[triangle[2]];
    const Eigen::Vector3d outward(normals[f][0], normals[f][1], normals[f][2]);
    if ((b - a).cross(c - a).dot(outward) < 0) std::swap(triangle[1], triangle[2]);
    result.triangles.push_back(triangle);
  }
  if (exit_code != 0 || result.triangles.empty()) {
    if (error) {
      // qhull's first line says what went wrong (e.g. "QH6154 ... initial simplex is flat").
      const std::size_t begin = text.find("QH");
      const std::string first =
          text.substr(begin == std::string::npos ? 0 : begin,
                      text.find('\n', begin == std::string::npos ? 0 : begin) -
                          (begin == std::string::npos ? 0 : begin));
      *error = "qhull failed (exit code " + std::to_string(exit_code) + ")" +
               (first.empty() ? std::string() : ": " + first);
    }
    return false;
  }
  *hull = std::move(result);
  return true;
}

MeshMassProperties CalcMeshMassProperties(const TriangleMesh& mesh,
                                          const MeshInertiaOptions& options) {
  return internal::CalcMeshMassProperties(mesh, options, false);
}

namespace internal {

void CheckMeshInertiaOptions(const MeshInertiaOptions& options) {
  if (!(options.density >= 0) || !std::isfinite(options.density) ||
      !(options.shell_thickness >= 0) || !std::isfinite(options.shell_thickness)) {
    std::ostringstream message;
    message << "CalcMeshMassProperties(): density " << options.density << " and shell thickness "
            << options.shell_thickness << " must be finite and non-negative";
    throw std::invalid_argument(message.str());
  }
}

MeshSolidAnalysis AnalyzeMeshSolid(const TriangleMesh& mesh, bool distinct_vertices) {
  MeshSolidAnalysis a;
  a.diagnostics = AnalyzeTopology(mesh, distinct_vertices);  // validates the mesh
  // The box of the used vertices, once: its diagonal, and its center as the reference point of
  // the signed integral (CalcClosedMeshMassPropertiesSigned's, without a second validation).
  // Every vertex of a mesh read directly is used: the box of its vertices, in order.
  Eigen::AlignedBox3d box;
  if (distinct_vertices) {
    for (const Eigen::Vector3d& v : mesh.vertices) box.extend(v);
  } else {
    box = UsedBoundingBox(mesh);
  }
  a.diagonal = box.isEmpty() ? 0 : box.diagonal().norm();
  a.center =
      box.isEmpty() ? Eigen::Vector3d(Eigen::Vector3d::Zero()) : Eigen::Vector3d(box.center());
  if (a.diagnostics.IsClosedManifold()) {
    a.signed_result = IntegrateSigned(mesh, a.center);
    return a;
  }
  // Not a closed manifold: the integral about the center and about a moved point (which tells
  // whether the surface encloses its volume all the same), in one pass over the triangles.
  SignedSums at_center(a.center), moved(MovedReferencePoint(box));
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& va = mesh.vertices[t[0]];
    const Eigen::Vector3d& vb = mesh.vertices[t[1]];
    const Eigen::Vector3d& vc = mesh.vertices[t[2]];
    at_center.Add(va, vb, vc, true);
    moved.Add(va, vb, vc, false);
  }
  a.signed_result = at_center.Finish(mesh);
  a.diagnostics.reference_point_sensitivity =
      ReferencePointSensitivity(box, a.signed_result, moved.Finish(mesh));
  return a;
}

MeshMassProperties CalcMeshMassProperties(const TriangleMesh& mesh,
                                          const MeshInertiaOptions& options,
                                          bool distinct_vertices) {
  CheckMeshInertiaOptions(options);
  return CalcMeshMassProperties(mesh, options, AnalyzeMeshSolid(mesh, distinct_vertices));
}

MeshMassProperties CalcMeshMassProperties(const TriangleMesh& mesh,
                                          const MeshInertiaOptions& options,
                                          const MeshSolidAnalysis& analysis) {
  CheckMeshInertiaOptions(options);
  MeshDiagnostics diagnostics = analysis.diagnostics;
  const double diagonal = analysis.diagonal;
  const Eigen::Vector3d& center = analysis.center;
  // A closed mesh whose volume is below this is flat (e.g. a double-sided plane).
  const double negligible_volume = 1e-12 * diagonal * diagonal * diagonal;

  auto finish_solid = [&](MeshMassProperties solid, MeshSolidModel model,
                          const std::string& reason) {
    if (solid.volume < 0) {
      // Inward winding: every moment has the wrong sign; the solid is the same.
      solid.volume = -solid.volume;
      const RotationalInertia<double>& I = solid.I_GGcm_G;
      solid.I_GGcm_G = RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(
          -I(0, 0), -I(1, 1), -I(2, 2), -I(0, 1), -I(0, 2), -I(1, 2), true);
      diagnostics.winding_inverted = (model == MeshSolidModel::kClosedSolid);
    }
    solid.mass = solid.volume;  // Density 1 so far.
    if (solid.volume > 0) solid = ScaleToMass(solid, options.density * solid.volume);
    if (model != MeshSolidModel::kClosedSolid) {
      // The area is that of the mesh's own triangles, not of the hull.
      double mesh_area = 0;
      for (const auto& t : mesh.triangles) {
        mesh_area += TriangleArea(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
      }
      solid.area = mesh_area;
    }
    diagnostics.model = model;
    diagnostics.fallback_reason = reason;
    solid.diagnostics = diagnostics;
    return solid;
  };

  std::string reason;
  const MeshMassProperties& signed_result = analysis.signed_result;
  if (diagnostics.IsClosedManifold()) {
    if (std::abs(signed_result.volume) > negligible_volume) {
      return finish_solid(signed_result, MeshSolidModel::kClosedSolid, "");
    }
    reason = mesh.triangles.empty() ? "no triangles" : "closed but encloses no volume";
  } else {
    reason = DescribeDefects(diagnostics);
    if (std::abs(signed_result.volume) > negligible_volume &&
        diagnostics.reference_point_sensitivity <= options.closure_tolerance) {
      std::ostringstream note;
      note << reason << ", but the surface encloses its volume (T-junctions or cracks: the "
           << "integral changes by " << diagnostics.reference_point_sensitivity
           << " relative when the reference point moves)";
      return finish_solid(signed_result, MeshSolidModel::kClosedSolid, note.str());
    }
    if (options.open_mesh_model == MeshSolidModel::kClosedSolid) {  // the same integral again
      return finish_solid(signed_result, MeshSolidModel::kClosedSolid,
                          "integrated as a closed solid despite " + reason);
    }
  }

  if (options.open_mesh_model != MeshSolidModel::kThinShell && !mesh.triangles.empty()) {
    TriangleMesh hull;
    std::string hull_error;
    if (CalcConvexHull(mesh, &hull, &hull_error)) {
      MeshMassProperties solid = CalcClosedMeshMassPropertiesSigned(hull);
      if (std::abs(solid.volume) > negligible_volume) {
        return finish_solid(solid, MeshSolidModel::kConvexHull, reason);
      }
      hull_error = "the convex hull has no volume";
    }
    reason += "; " + hull_error;
  }

  MeshMassProperties shell = CalcThinShell(mesh, center, options.shell_thickness, options.density);
  diagnostics.model = MeshSolidModel::kThinShell;
  diagnostics.fallback_reason = reason;
  shell.diagnostics = diagnostics;
  return shell;
}

}  // namespace internal

MeshMassProperties ScaleToMass(const MeshMassProperties& properties, double mass) {
  if (!(properties.mass > 0) || !(mass >= 0) || !std::isfinite(mass)) {
    std::ostringstream message;
    message << "ScaleToMass(): needs a positive mass to scale from (have " << properties.mass
            << ") and a finite non-negative mass to scale to (have " << mass << ")";
    throw std::invalid_argument(message.str());
  }
  MeshMassProperties result = properties;
  const double s = mass / properties.mass;
  const RotationalInertia<double>& I = properties.I_GGcm_G;
  result.I_GGcm_G = RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(
      s * I(0, 0), s * I(1, 1), s * I(2, 2), s * I(0, 1), s * I(0, 2), s * I(1, 2), true);
  result.mass = mass;
  return result;
}

}  // namespace massprops

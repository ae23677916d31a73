#include "massprops/analysis/link_measure.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "massprops/mesh/mesh_inertia.h"

namespace massprops {
namespace {

// Khachiyan's algorithm stops when a step moves the weights by less than this (the ellipsoid's
// volume is then within a few per mille of the least; it is grown afterwards to hold every
// point, so the stopping point decides only how tight, never whether it encloses).
constexpr double kKhachiyanTolerance = 1e-4;
constexpr int kKhachiyanIterations = 2000;
// More hull points than this: no ellipsoid (each iteration visits every point).
constexpr std::size_t kMaxEllipsoidPoints = 20000;

// The half-sizes of a primitive's own box, in its frame; false for a mesh, an unknown type or a
// size that is not finite and non-negative.
bool HalfSizes(const Geometry& g, Eigen::Vector3d* h) {
  switch (g.type) {
    case Geometry::Type::kBox:
      *h = 0.5 * g.size;
      break;
    case Geometry::Type::kCylinder:
      *h = Eigen::Vector3d(g.radius, g.radius, 0.5 * g.length);
      break;
    case Geometry::Type::kCapsule:
      *h = Eigen::Vector3d(g.radius, g.radius, 0.5 * g.length + g.radius);
      break;
    case Geometry::Type::kSphere:
      *h = Eigen::Vector3d::Constant(g.radius);
      break;
    case Geometry::Type::kEllipsoid:
      *h = g.radii;
      break;
    default:
      return false;
  }
  return h->allFinite() && (h->array() >= 0).all() && g.X_BG.p_AB.allFinite() &&
         g.X_BG.R_AB.allFinite();
}

// The convex hull of `points` (qhull): its vertices, volume and largest faces' normals. False
// when it cannot be built (fewer than 4 points, all in a plane, qhull not loadable).
bool Hull(const std::vector<Eigen::Vector3d>& points, std::vector<Eigen::Vector3d>* vertices,
          double* volume, std::vector<Eigen::Vector3d>* normals) {
  if (points.size() < 4) return false;
  TriangleMesh cloud;
  cloud.vertices = points;
  const auto n = static_cast<std::int32_t>(points.size());
  for (std::int32_t i = 0; i < n; i += 3) {
    cloud.triangles.push_back({i, std::min(i + 1, n - 1), std::min(i + 2, n - 1)});
  }
  TriangleMesh hull;
  std::string error;
  if (!CalcConvexHull(cloud, &hull, &error) || hull.triangles.size() < 4) return false;
  *vertices = hull.vertices;
  std::vector<std::pair<double, Eigen::Vector3d>> faces;
  double six_volume = 0;
  for (const auto& t : hull.triangles) {
    const Eigen::Vector3d& a = hull.vertices[t[0]];
    const Eigen::Vector3d& b = hull.vertices[t[1]];
    const Eigen::Vector3d& c = hull.vertices[t[2]];
    six_volume += a.dot(b.cross(c));
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    if (normal.norm() > 0) faces.emplace_back(normal.norm(), normal.normalized());
  }
  *volume = std::abs(six_volume) / 6;
  std::sort(faces.begin(), faces.end(),
            [](const auto& x, const auto& y) { return x.first > y.first; });
  for (const auto& face : faces) {
    // Named, not a structured binding: a C++17 lambda cannot capture one (clang rejects it).
    const Eigen::Vector3d& normal = face.second;
    if (normals->size() >= static_cast<std::size_t>(kMaxFaceNormals)) break;
    const bool seen = std::any_of(normals->begin(), normals->end(), [&](const Eigen::Vector3d& v) {
      return v.dot(normal) > 1 - 1e-9;
    });
    if (!seen) normals->push_back(normal);
  }
  return true;
}

// Khachiyan's algorithm (as Todd and Yildirim state it) for the minimum-volume ellipsoid holding
// `points`, then grown about its center until it holds each of them exactly. False when the
// points lie in a plane (no ellipsoid of positive volume).
bool EnclosingEllipsoid(const std::vector<Eigen::Vector3d>& points, Eigen::Vector3d* x0,
                        Eigen::Matrix3d* Q_inverse) {
  const std::size_t n = points.size();
  if (n < 4 || n > kMaxEllipsoidPoints) return false;
  Eigen::VectorXd weight = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(n), 1.0 / n);
  for (int iteration = 0; iteration < kKhachiyanIterations; ++iteration) {
    Eigen::Matrix4d X = Eigen::Matrix4d::Zero();
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector4d q(points[i].x(), points[i].y(), points[i].z(), 1);
      X += weight(static_cast<Eigen::Index>(i)) * q * q.transpose();
    }
    const Eigen::LDLT<Eigen::Matrix4d> ldlt(X);
    if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 0)) return false;
    double largest = -1;
    std::size_t j = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector4d q(points[i].x(), points[i].y(), points[i].z(), 1);
      const double value = q.dot(ldlt.solve(q));
      if (value > largest) largest = value, j = i;
    }
    const double step = (largest - 4) / (4 * (largest - 1));
    if (!(step > kKhachiyanTolerance)) break;
    weight *= 1 - step;
    weight(static_cast<Eigen::Index>(j)) += step;
  }
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < n; ++i) center += weight(static_cast<Eigen::Index>(i)) * points[i];
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d d = points[i] - center;
    scatter += weight(static_cast<Eigen::Index>(i)) * d * d.transpose();
  }
  // Q = 3·scatter; grown so that the farthest point lies on E.
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(3 * scatter);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 0)) return false;
  Eigen::Matrix3d inverse = ldlt.solve(Eigen::Matrix3d::Identity());
  inverse = 0.5 * (inverse + inverse.transpose());
  double grow = 1;
  for (const Eigen::Vector3d& p : points)
    grow = std::max(grow, (p - center).dot(inverse * (p - center)));
  *x0 = center;
  *Q_inverse = inverse / (grow * (1 + 1e-12));
  return Q_inverse->allFinite();
}

// The kSphereDirections points of the Fibonacci lattice on the unit sphere.
const std::vector<Eigen::Vector3d>& SphereDirections() {
  static const std::vector<Eigen::Vector3d> kDirections = [] {
    std::vector<Eigen::Vector3d> directions;
    const double golden_angle = M_PI * (3 - std::sqrt(5.0));
    for (int i = 0; i < kSphereDirections; ++i) {
      const double z = 1 - (2 * i + 1.0) / kSphereDirections;
      const double rho = std::sqrt(1 - z * z);
      directions.emplace_back(rho * std::cos(golden_angle * i), rho * std::sin(golden_angle * i),
                              z);
    }
    return directions;
  }();
  return kDirections;
}

}  // namespace

double HalfWidthAlong(const Geometry& g, const Eigen::Vector3d& v) {
  switch (g.type) {
    case Geometry::Type::kBox:
      return 0.5 * v.cwiseAbs().dot(g.size);
    case Geometry::Type::kCylinder:
      return g.radius * std::hypot(v.x(), v.y()) + 0.5 * g.length * std::abs(v.z());
    case Geometry::Type::kCapsule:
      return g.radius * v.norm() + 0.5 * g.length * std::abs(v.z());
    case Geometry::Type::kSphere:
      return g.radius * v.norm();
    case Geometry::Type::kEllipsoid:
      return v.cwiseProduct(g.radii).norm();
    default:
      return 0;
  }
}

double LinkMeasure::Support(const Eigen::Vector3d& u) const {
  double h = -HUGE_VAL;
  for (const Geometry* g : primitives) {
    h = std::max(h, u.dot(g->X_BG.p_AB) + HalfWidthAlong(*g, g->X_BG.R_AB.transpose() * u));
  }
  for (const Eigen::Vector3d& p : mesh_vertices_B) h = std::max(h, u.dot(p));
  return h;
}

namespace {

// The volume of a primitive (exact; 0 for a mesh or an unknown type).
double PrimitiveVolume(const Geometry& g) {
  Eigen::Vector3d h;
  if (!HalfSizes(g, &h)) return 0;
  switch (g.type) {
    case Geometry::Type::kBox:
      return 8 * h.prod();
    case Geometry::Type::kCylinder:
      return M_PI * g.radius * g.radius * g.length;
    case Geometry::Type::kCapsule:
      return M_PI * g.radius * g.radius * (g.length + 4 * g.radius / 3);
    case Geometry::Type::kSphere:
      return 4 * M_PI * g.radius * g.radius * g.radius / 3;
    case Geometry::Type::kEllipsoid:
      return 4 * M_PI * h.prod() / 3;
    default:
      return 0;
  }
}

}  // namespace

double InnerVolume(const Link& link, const std::optional<LinkGeometryPoints>& points) {
  double volume = 0;
  for (const Geometry& g : link.geometries) volume = std::max(volume, PrimitiveVolume(g));
  if (!points || points->posed.empty()) return volume;
  // 13 axes: the frame's 3, the 6 face diagonals and the 4 body diagonals.
  std::array<Eigen::Vector3d, 13> axes;
  int k = 0;
  for (int x = -1; x <= 1; ++x) {
    for (int y = -1; y <= 1; ++y) {
      for (int z = -1; z <= 1; ++z) {
        const Eigen::Vector3d a(x, y, z);
        // One of each pair ±a: the first nonzero component positive.
        const bool first = x > 0 || (x == 0 && (y > 0 || (y == 0 && z > 0)));
        if (first) axes[k++] = a;
      }
    }
  }
  std::array<double, 13> low, high;
  low.fill(HUGE_VAL);
  high.fill(-HUGE_VAL);
  std::array<Eigen::Vector3d, 26> extreme;
  bool finite = true;
  for (const LinkGeometryPoints::PosedPositions& mesh : points->posed) {
    for (const Eigen::Vector3d& v : *mesh.positions) {
      const Eigen::Vector3d p = mesh.X_BG.p_AB + mesh.X_BG.R_AB * v.cwiseProduct(mesh.scale);
      finite = finite && p.allFinite();
      for (int i = 0; i < 13; ++i) {
        const double t = axes[i].dot(p);
        if (t < low[i]) low[i] = t, extreme[2 * i] = p;
        if (t > high[i]) high[i] = t, extreme[2 * i + 1] = p;
      }
    }
  }
  if (!finite || !(high[0] >= low[0])) return volume;
  std::vector<Eigen::Vector3d> vertices, normals;
  double hull_volume = 0;
  if (Hull(std::vector<Eigen::Vector3d>(extreme.begin(), extreme.end()), &vertices, &hull_volume,
           &normals)) {
    volume = std::max(volume, hull_volume);
  }
  return volume;
}

LinkMeasure MeasureLink(const Link& link, const std::optional<LinkGeometryPoints>& points,
                        bool ellipsoid) {
  LinkMeasure measure;
  std::vector<Eigen::Vector3d> cloud;  // the meshes' positions and the primitives' box corners
  for (const Geometry& g : link.geometries) {
    if (g.type == Geometry::Type::kMesh) {
      measure.has_mesh = true;
      continue;
    }
    Eigen::Vector3d h;
    if (!HalfSizes(g, &h)) return measure;
    measure.primitives.push_back(&g);
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d s((corner & 1) ? 1 : -1, (corner & 2) ? 1 : -1, (corner & 4) ? 1 : -1);
      cloud.push_back(g.X_BG.p_AB + g.X_BG.R_AB * s.cwiseProduct(h));
    }
  }
  const std::size_t corners = cloud.size();
  if (measure.has_mesh) {
    if (!points || points->unknown > 0 || points->posed.empty()) return measure;
    for (const LinkGeometryPoints::PosedPositions& mesh : points->posed) {
      for (const Eigen::Vector3d& v : *mesh.positions) {
        cloud.emplace_back(mesh.X_BG.p_AB + mesh.X_BG.R_AB * v.cwiseProduct(mesh.scale));
      }
    }
  }
  if (cloud.empty()) return measure;
  for (const Eigen::Vector3d& p : cloud) {
    if (!p.allFinite()) return measure;
  }
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& p : cloud) box.extend(p);
  measure.center_B = box.center();
  measure.half_diagonal = 0.5 * box.diagonal().norm();
  std::vector<Eigen::Vector3d> vertices;
  if (!Hull(cloud, &vertices, &measure.volume, &measure.face_normals_B)) {
    vertices = cloud;  // in a plane, or no qhull: every point (the same hull)
    measure.volume = box.volume();
  }
  if (measure.has_mesh) {
    // The meshes' hull vertices: those of the hull that are no primitive's corner (a corner of
    // a primitive's box lies outside a round primitive; its exact support is used instead).
    for (const Eigen::Vector3d& v : vertices) {
      const bool corner =
          std::find(cloud.begin(), cloud.begin() + static_cast<std::ptrdiff_t>(corners), v) !=
          cloud.begin() + static_cast<std::ptrdiff_t>(corners);
      if (!corner) measure.mesh_vertices_B.push_back(v);
    }
  }
  measure.has_ellipsoid =
      ellipsoid && EnclosingEllipsoid(vertices, &measure.x0, &measure.Q_inverse);
  measure.whole = true;
  return measure;
}

DirectionBound WorstDirection(const LinkMeasure& measure, double m, const Eigen::Vector3d& c,
                              const Eigen::Matrix3d& Sigma, double scale) {
  std::vector<Eigen::Vector3d> directions;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(Sigma);
  if (eig.info() == Eigen::Success) {
    for (int i = 0; i < 3; ++i) directions.emplace_back(eig.eigenvectors().col(i).normalized());
  }
  for (int i = 0; i < 3; ++i) directions.push_back(Eigen::Vector3d::Unit(i));
  for (const Geometry* g : measure.primitives) {
    for (int i = 0; i < 3; ++i) directions.emplace_back(g->X_BG.R_AB.col(i).normalized());
  }
  directions.insert(directions.end(), measure.face_normals_B.begin(), measure.face_normals_B.end());
  directions.insert(directions.end(), SphereDirections().begin(), SphereDirections().end());
  DirectionBound worst;
  for (Eigen::Vector3d u : directions) {
    Eigen::Index largest = 0;
    u.cwiseAbs().maxCoeff(&largest);
    if (u(largest) < 0) u = -u;
    const double middle = u.dot(measure.center_B);
    const double support_ahead = measure.Support(u), support_behind = measure.Support(-u);
    // K grown `scale` times about its box's center: h(u) − u·o scales.
    const double high = middle + scale * (support_ahead - middle);
    const double low = middle - scale * (support_behind + middle);
    const double ahead = high - u.dot(c), behind = u.dot(c) - low;
    if (!(ahead > 0) || !(behind > 0)) continue;  // outside: com-outside-geometry's
    const double second_moment = u.dot(Sigma * u);
    const double bound = m * ahead * behind;
    const double ratio = second_moment / bound;
    if (ratio > worst.ratio) {
      worst = {ratio,
               second_moment,
               bound,
               ahead,
               behind,
               support_ahead - u.dot(c),
               u.dot(c) + support_behind,
               u};
    }
  }
  return worst;
}

double EllipsoidRatio(const LinkMeasure& measure, double m, const Eigen::Vector3d& c,
                      const Eigen::Matrix3d& Sigma, double scale) {
  if (!measure.has_ellipsoid) return NAN;
  const Eigen::Vector3d d = c - measure.x0;
  const Eigen::Matrix3d about_center = Sigma + m * d * d.transpose();
  return (measure.Q_inverse * about_center).trace() / (scale * scale * m);
}

double LeastTrace(double m, double density) {
  const double r = std::cbrt(3 * m / (4 * M_PI * density));
  return 1.2 * m * r * r;
}

}  // namespace massprops

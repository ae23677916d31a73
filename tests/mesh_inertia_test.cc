// Tests of mesh_inertia.h: exact mass properties of polyhedra by the divergence theorem (the
// signed-tetrahedron covariance form of Kallay 2006), against closed forms derived independently.

#include "massprops/mesh/mesh_inertia.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "massprops/core/unit_inertia.h"
#include "test_shapes.h"

namespace massprops {
namespace {

using test_support::MakeUvSphere;

constexpr double kPi = 3.14159265358979323846;

// Largest |entry| difference of two inertias relative to the largest entry of `expected`.
double RelativeDifference(const RotationalInertia<double>& actual,
                          const RotationalInertia<double>& expected) {
  return (actual.CopyToFullMatrix3() - expected.CopyToFullMatrix3()).cwiseAbs().maxCoeff() /
         expected.CopyToFullMatrix3().cwiseAbs().maxCoeff();
}

RotationalInertia<double> Inertia(double xx, double yy, double zz, double xy, double xz,
                                  double yz) {
  return RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(xx, yy, zz, xy, xz, yz,
                                                                        true);
}

// An axis-aligned box [lo, hi], its 6 faces split into 2 triangles each, wound outward
// (counter-clockwise seen from outside). 8 shared vertices.
TriangleMesh MakeBox(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  TriangleMesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.emplace_back((i & 1) ? hi.x() : lo.x(), (i & 2) ? hi.y() : lo.y(),
                               (i & 4) ? hi.z() : lo.z());
  }
  // Each face as a quad (a, b, c, d) counter-clockwise from outside.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
  }
  return mesh;
}

// The same mesh as a triangle soup: every triangle with its own three vertices (as STL).
TriangleMesh MakeSoup(const TriangleMesh& mesh) {
  TriangleMesh soup;
  for (const auto& t : mesh.triangles) {
    const auto n = static_cast<std::int32_t>(soup.vertices.size());
    for (int k = 0; k < 3; ++k) soup.vertices.push_back(mesh.vertices[t[k]]);
    soup.triangles.push_back({n, n + 1, n + 2});
  }
  return soup;
}

// The tetrahedron with the given vertices, wound outward whatever their order.
TriangleMesh MakeTetrahedron(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                             const Eigen::Vector3d& p2, const Eigen::Vector3d& p3) {
  TriangleMesh mesh;
  mesh.vertices = {p0, p1, p2, p3};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  if ((p1 - p0).dot((p2 - p0).cross(p3 - p0)) < 0) {
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  }
  return mesh;
}

// The octahedron |x| + |y| + |z| <= a: 6 vertices, 8 faces.
TriangleMesh MakeOctahedron(double a) {
  TriangleMesh mesh;
  mesh.vertices = {{a, 0, 0}, {-a, 0, 0}, {0, a, 0}, {0, -a, 0}, {0, 0, a}, {0, 0, -a}};
  for (int sx : {0, 1}) {
    for (int sy : {2, 3}) {
      for (int sz : {4, 5}) {
        // Outward winding: (x, y, z) counter-clockwise when the octant has an even number of
        // negative signs.
        const int negatives = (sx == 1) + (sy == 3) + (sz == 5);
        if (negatives % 2 == 0) {
          mesh.triangles.push_back({sx, sy, sz});
        } else {
          mesh.triangles.push_back({sx, sz, sy});
        }
      }
    }
  }
  return mesh;
}

// A cylinder of radius r and length L along z centered at the origin, as an n-gon prism with
// fan-triangulated caps.
TriangleMesh MakeCylinder(double r, double L, int n) {
  TriangleMesh mesh;
  for (int k = 0; k < n; ++k) {
    const double phi = 2 * kPi * k / n;
    mesh.vertices.emplace_back(r * std::cos(phi), r * std::sin(phi), -L / 2);
    mesh.vertices.emplace_back(r * std::cos(phi), r * std::sin(phi), L / 2);
  }
  const auto bottom = static_cast<std::int32_t>(mesh.vertices.size());
  mesh.vertices.emplace_back(0, 0, -L / 2);
  mesh.vertices.emplace_back(0, 0, L / 2);
  const std::int32_t top = bottom + 1;
  for (int k = 0; k < n; ++k) {
    const int b0 = 2 * k, t0 = 2 * k + 1, b1 = 2 * ((k + 1) % n), t1 = b1 + 1;
    mesh.triangles.push_back({b0, b1, t1});
    mesh.triangles.push_back({b0, t1, t0});
    mesh.triangles.push_back({bottom, b1, b0});
    mesh.triangles.push_back({top, t0, t1});
  }
  return mesh;
}

TriangleMesh Transformed(const TriangleMesh& mesh, const Eigen::Matrix3d& R,
                         const Eigen::Vector3d& p) {
  TriangleMesh result = mesh;
  for (auto& v : result.vertices) v = R * v + p;
  return result;
}

TEST(MeshInertiaTest, UnitCubeMatchesClosedForm) {
  // Unit cube of density 1: V = 1, center (1/2, 1/2, 1/2), I = m·L²/6 = 1/6 about every axis
  // through the center, zero products (textbook: solid cube).
  const MeshMassProperties p = CalcMeshMassProperties(MakeBox({0, 0, 0}, {1, 1, 1}));
  EXPECT_NEAR(p.volume, 1.0, 1e-15);
  EXPECT_NEAR(p.mass, 1.0, 1e-15);
  EXPECT_NEAR(p.area, 6.0, 1e-14);
  EXPECT_LT((p.p_GoGcm_G - Eigen::Vector3d(0.5, 0.5, 0.5)).norm(), 1e-15);
  EXPECT_LT(RelativeDifference(p.I_GGcm_G, Inertia(1.0 / 6, 1.0 / 6, 1.0 / 6, 0, 0, 0)), 1e-12);
  EXPECT_EQ(p.diagnostics.model, MeshSolidModel::kClosedSolid);
  EXPECT_TRUE(p.diagnostics.IsClosedManifold());
  EXPECT_EQ(p.diagnostics.edges, 18);  // 12 cube edges + 6 face diagonals.
  EXPECT_FALSE(p.diagnostics.winding_inverted);
  EXPECT_EQ(p.diagnostics.duplicate_vertices_merged, 0);
}

TEST(MeshInertiaTest, BoxMatchesClosedFormWithDensity) {
  // Box 0.3 × 0.5 × 1.1 with density 2700: m = ρ·V; I = m/12·(b² + c²), ... (textbook: solid
  // cuboid).
  const double a = 0.3, b = 0.5, c = 1.1, rho = 2700;
  MeshInertiaOptions options;
  options.density = rho;
  const MeshMassProperties p =
      CalcMeshMassProperties(MakeBox({-0.1, 0.2, 0.4}, {-0.1 + a, 0.2 + b, 0.4 + c}), options);
  const double V = a * b * c, m = rho * V;
  EXPECT_NEAR(p.volume, V, 1e-12 * V);
  EXPECT_NEAR(p.mass, m, 1e-12 * m);
  EXPECT_LT((p.p_GoGcm_G - Eigen::Vector3d(-0.1 + a / 2, 0.2 + b / 2, 0.4 + c / 2)).norm(), 1e-15);
  const RotationalInertia<double> expected = Inertia(
      m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12, 0, 0, 0);
  EXPECT_LT(RelativeDifference(p.I_GGcm_G, expected), 1e-12);
}

TEST(MeshInertiaTest, CornerTetrahedronMatchesHandDerivedClosedForm) {
  // Tetrahedron (0,0,0), (a,0,0), (0,b,0), (0,0,c). Hand-derived with Dirichlet's integral
  // ∫x^p y^q z^r dV = a^(p+1) b^(q+1) c^(r+1) p! q! r! / (p+q+r+3)!: V = abc/6, center
  // (a, b, c)/4, ∫x² = a³bc/60 = V·a²/10, ∫xy = a²b²c/120 = V·ab/20, so about the center
  // Cxx = V·(a²/10 − a²/16) = 3V·a²/80 and Cxy = V·(ab/20 − ab/16) = −V·ab/80; then
  // Ixx = Cyy + Czz and the matrix entry Ixy = −Cxy = V·ab/80.
  const double a = 0.7, b = 1.3, c = 2.9;
  const MeshMassProperties p =
      CalcMeshMassProperties(MakeTetrahedron({0, 0, 0}, {a, 0, 0}, {0, b, 0}, {0, 0, c}));
  const double V = a * b * c / 6;
  EXPECT_NEAR(p.volume, V, 1e-12 * V);
  EXPECT_LT((p.p_GoGcm_G - Eigen::Vector3d(a, b, c) / 4).norm(), 1e-15);
  const RotationalInertia<double> expected =
      Inertia(3 * V * (b * b + c * c) / 80, 3 * V * (a * a + c * c) / 80,
              3 * V * (a * a + b * b) / 80, V * a * b / 80, V * a * c / 80, V * b * c / 80);
  EXPECT_LT(RelativeDifference(p.I_GGcm_G, expected), 1e-12);
}

TEST(MeshInertiaTest, GeneralTetrahedronMatchesTononsPublishedExample) {
  // Tonon, "Explicit exact formulas for the 3-D tetrahedron inertia tensor in terms of its
  // vertex coordinates", J. Math. Stat. 1(1), 2004, numerical example (density 1, about the
  // centroid): a = 43520.33257, b = 194711.28938, c = 191168.76173, a' = 4417.66150,
  // b' = −46343.16662, c' = 11996.20119, with the tensor [[a, −b', −c'], [−b', b, −a'],
  // [−c', −a', c]]. The published values are rounded (they agree with exact arithmetic on the
  // printed vertices to about 2e-8), hence the tolerance.
  const MeshMassProperties p = CalcMeshMassProperties(MakeTetrahedron(
      {8.33220, -11.86875, 0.93355}, {0.75523, 5, 16.37072}, {52.61236, 5, -5.38580}, {2, 5, 3}));
  const RotationalInertia<double> tonon =
      Inertia(43520.33257, 194711.28938, 191168.76173, -11996.20119, 46343.16662, -4417.66150);
  EXPECT_LT(RelativeDifference(p.I_GGcm_G, tonon), 1e-7);
  // Independently: the tetrahedron covariance (Σ pᵢpᵢᵀ + s·sᵀ)/20 of unit_inertia.h about the
  // centroid, times the volume, agrees to round-off.
  const Eigen::Vector3d c = p.p_GoGcm_G;
  const std::vector<Eigen::Vector3d> v = {
      {8.33220, -11.86875, 0.93355}, {0.75523, 5, 16.37072}, {52.61236, 5, -5.38580}, {2, 5, 3}};
  EXPECT_LT((c - (v[0] + v[1] + v[2] + v[3]) / 4).norm(), 1e-12);
  const RotationalInertia<double> from_factory =
      UnitInertia<double>::SolidTetrahedronAboutPoint(v[0] - c, v[1] - c, v[2] - c, v[3] - c) *
      p.volume;
  EXPECT_LT(RelativeDifference(p.I_GGcm_G, from_factory), 1e-12);
}

TEST(MeshInertiaTest, OctahedronMatchesHandDerivedClosedForm) {
  // |x| + |y| + |z| <= a. Hand-derived: 8 corner simplices of volume a³/6, V = 4a³/3;
  // ∫x² = 8·a⁵/60 (Dirichlet's integral on each simplex), so Ixx = ∫(y² + z²) = 4a⁵/15
  // = V·a²/5 on every axis, and the products vanish by symmetry.
  const double a = 0.37;
  const MeshMassProperties p = CalcMeshMassProperties(MakeOctahedron(a));
  const double V = 4 * a * a * a / 3, I = 4 * std::pow(a, 5) / 15;
  EXPECT_NEAR(p.volume, V, 1e-12 * V);
  EXPECT_LT(p.p_GoGcm_G.norm(), 1e-16);
  EXPECT_LT(RelativeDifference(p.I_GGcm_G, Inertia(I, I, I, 0, 0, 0)), 1e-12);
  EXPECT_TRUE(p.diagnostics.IsClosedManifold());
  EXPECT_EQ(p.diagnostics.edges, 12);
}

// Relative errors of the volume and of Izz of a UV sphere against the solid sphere
// (V = 4/3·π·r³, I = 2/5·m·r²).
std::pair<double, double> SphereErrors(int slices) {
  const double r = 0.2;
  const MeshMassProperties p = CalcMeshMassProperties(MakeUvSphere(r, slices));
  const double V = 4 * kPi * r * r * r / 3, I = 0.4 * V * r * r;
  EXPECT_TRUE(p.diagnostics.IsClosedManifold()) << slices;
  EXPECT_LT(p.p_GoGcm_G.norm(), 1e-15) << slices;
  return {std::abs(p.volume - V) / V, std::abs(p.I_GGcm_G(2, 2) - I) / I};
}

TEST(MeshInertiaTest, RefinedSphereConvergesQuadratically) {
  // An inscribed polyhedron misses a layer of thickness ~ r·(1 − cos(h/2r)) ∝ h², so halving the
  // edge length h divides the error by about 4.
  double previous_volume_error = 0, previous_inertia_error = 0;
  for (int slices : {16, 32, 64, 128, 256}) {
    const auto [volume_error, inertia_error] = SphereErrors(slices);
    EXPECT_GT(volume_error, 0);
    if (previous_volume_error > 0) {
      EXPECT_NEAR(previous_volume_error / volume_error, 4.0, 0.3) << slices;
      EXPECT_NEAR(previous_inertia_error / inertia_error, 4.0, 0.3) << slices;
    }
    previous_volume_error = volume_error;
    previous_inertia_error = inertia_error;
  }
  // 256 slices, α = 2π/256: a flat patch of angular size α × α lies on average about r·α²/6
  // below the sphere (sagitta r·α²/8, averaged over the chord: r·α²/12 in each direction), so the
  // volume deficit is about 3·α²/6 = α²/2 (hand-derived estimate, an upper bound here).
  const double alpha = 2 * kPi / 256;
  EXPECT_LT(previous_volume_error, alpha * alpha / 2);
}

TEST(MeshInertiaTest, RefinedCylinderMatchesItsPrismAndConvergesToTheCylinder) {
  // The mesh is exactly a prism on a regular n-gon inscribed in the circle. Hand-derived: the
  // n-gon is n triangles (center, two rim points at angle α = 2π/n) of area r²·sin(α)/2 and polar
  // moment about the center A·r²·(2 + cos α)/6 (triangle second moment (a·a + b·b + a·b)·A/6
  // about a vertex); a regular polygon's in-plane second moments are equal, so ∫y² dA = J/2 and
  // Ixx = L·J/2 + A·L³/12, Izz = L·J. As n grows these tend to the solid cylinder's πr²L,
  // m·r²/2 and m(3r² + L²)/12 (textbook), the error ∝ α² ∝ 1/n².
  const double r = 0.05, L = 0.4;
  double previous_error = 0;
  for (int n : {16, 32, 64, 128, 256, 512}) {
    const MeshMassProperties p = CalcMeshMassProperties(MakeCylinder(r, L, n));
    const double alpha = 2 * kPi / n;
    const double A = n * r * r * std::sin(alpha) / 2;
    const double J = A * r * r * (2 + std::cos(alpha)) / 6;
    EXPECT_NEAR(p.volume, A * L, 1e-13 * A * L) << n;
    EXPECT_LT(
        RelativeDifference(p.I_GGcm_G, Inertia(L * J / 2 + A * L * L * L / 12,
                                               L * J / 2 + A * L * L * L / 12, L * J, 0, 0, 0)),
        1e-12)
        << n;
    const double V = kPi * r * r * L;
    const double error = std::abs(p.volume - V) / V;
    const double axial = 0.5 * V * r * r, transverse = V * (3 * r * r + L * L) / 12;
    const double axial_error = std::abs(p.I_GGcm_G(2, 2) - axial) / axial;
    const double transverse_error = std::abs(p.I_GGcm_G(0, 0) - transverse) / transverse;
    EXPECT_LT(axial_error, 3 * error) << n;  // Deficit α²/3 versus α²/6 for the volume.
    EXPECT_LT(transverse_error, 3 * error) << n;
    if (previous_error > 0) {
      EXPECT_NEAR(previous_error / error, 4.0, 0.1) << n;
    }
    previous_error = error;
  }
  EXPECT_LT(previous_error, 3e-5);  // (2π/512)²/6 = 2.5e-5.
}

TEST(MeshInertiaTest, ResultsDoNotDependOnTranslationOrRotation) {
  // A body 1 km from the origin, turned arbitrarily: same volume, the center moved with it and
  // the inertia re-expressed, to 1e-9 relative (accumulation about the bounding-box center).
  const TriangleMesh mesh = MakeUvSphere(0.1, 24);
  TriangleMesh lopsided = mesh;  // Squash it so that no moment is repeated.
  for (auto& v : lopsided.vertices) v = Eigen::Vector3d(v.x() * 1.7, v.y(), v.z() * 0.6);
  const MeshMassProperties here = CalcMeshMassProperties(lopsided);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.83, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const Eigen::Vector3d p(1e3, -0.7e3, 0.4e3);
  const MeshMassProperties there = CalcMeshMassProperties(Transformed(lopsided, R, p));
  EXPECT_NEAR(there.volume, here.volume, 1e-9 * here.volume);
  EXPECT_LT((there.p_GoGcm_G - (R * here.p_GoGcm_G + p)).norm(), 1e-9 * 0.17);
  EXPECT_LT(RelativeDifference(there.I_GGcm_G, here.I_GGcm_G.ReExpress(R)), 1e-9);
  // Translation alone.
  const MeshMassProperties moved =
      CalcMeshMassProperties(Transformed(lopsided, Eigen::Matrix3d::Identity(), p));
  EXPECT_LT(RelativeDifference(moved.I_GGcm_G, here.I_GGcm_G), 1e-9);
}

TEST(MeshInertiaTest, InvertedWindingIsFlippedAndReported) {
  TriangleMesh mesh = MakeBox({0, 0, 0}, {1, 2, 3});
  const MeshMassProperties outward = CalcMeshMassProperties(mesh);
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  // The signed integral sees the negative volume.
  EXPECT_NEAR(CalcClosedMeshMassPropertiesSigned(mesh).volume, -6.0, 1e-13);
  const MeshMassProperties inward = CalcMeshMassProperties(mesh);
  EXPECT_TRUE(inward.diagnostics.winding_inverted);
  EXPECT_FALSE(outward.diagnostics.winding_inverted);
  EXPECT_EQ(inward.diagnostics.model, MeshSolidModel::kClosedSolid);
  EXPECT_NEAR(inward.volume, 6.0, 1e-13);
  EXPECT_NEAR(inward.mass, 6.0, 1e-13);
  // Box 1 × 2 × 3, m = 6: Ixx = m(4 + 9)/12 = 6.5, Iyy = m(1 + 9)/12 = 5, Izz = m(1 + 4)/12 = 2.5.
  EXPECT_LT(RelativeDifference(inward.I_GGcm_G, Inertia(6.5, 5, 2.5, 0, 0, 0)), 1e-12);
}

TEST(MeshInertiaTest, OpenBoxFallsBackToItsConvexHull) {
  // The box without its top face: the 4 rim edges are boundary edges. Its convex hull is the
  // whole box, so the hull model gives the box's closed form.
  TriangleMesh mesh = MakeBox({0, 0, 0}, {1, 2, 3});
  mesh.triangles.erase(mesh.triangles.begin() + 2, mesh.triangles.begin() + 4);  // z = 3 face.
  const MeshMassProperties p = CalcMeshMassProperties(mesh);
  EXPECT_EQ(p.diagnostics.boundary_edges, 4);
  EXPECT_EQ(p.diagnostics.non_manifold_edges, 0);
  EXPECT_EQ(p.diagnostics.model, MeshSolidModel::kConvexHull);
  EXPECT_GT(p.diagnostics.reference_point_sensitivity, 0.01);  // A hole of 1/11 of the area.
  EXPECT_NE(p.diagnostics.fallback_reason.find("4 boundary edges"), std::string::npos)
      << p.diagnostics.fallback_reason;
  EXPECT_NEAR(p.volume, 6.0, 1e-12);
  EXPECT_NEAR(p.area, 22 - 2, 1e-12);  // The mesh's own area: 2(2 + 3 + 6) minus the 1 × 2 top.
  EXPECT_LT((p.p_GoGcm_G - Eigen::Vector3d(0.5, 1, 1.5)).norm(), 1e-12);
  EXPECT_LT(RelativeDifference(p.I_GGcm_G, Inertia(6.5, 5, 2.5, 0, 0, 0)), 1e-12);
}

TEST(MeshInertiaTest, OpenBoxAsThinShellWhenAsked) {
  // Thin shell of thickness t over the 5 faces of the open box 1 × 1 × 1 (top z = 1 missing).
  // Hand-derived: the bottom plate (area 1, at z = 0) and 4 walls (area 1, centers at z = 1/2);
  // center z = (0 + 4·1/2)/5 = 2/5. About the center, with ρ = 1, per unit thickness:
  // Izz = bottom (1/6) + 4 walls (1/12 + 1/4 each: a 1 × 1 plate about an axis in its plane
  // through its center plus the 1/2 offset, the wall's in-plane size along z not counting)
  // = 1/6 + 4/3 = 3/2.
  TriangleMesh mesh = MakeBox({0, 0, 0}, {1, 1, 1});
  mesh.triangles.erase(mesh.triangles.begin() + 2, mesh.triangles.begin() + 4);
  MeshInertiaOptions options;
  options.open_mesh_model = MeshSolidModel::kThinShell;
  options.shell_thickness = 0.002;
  const MeshMassProperties p = CalcMeshMassProperties(mesh, options);
  EXPECT_EQ(p.diagnostics.model, MeshSolidModel::kThinShell);
  EXPECT_NEAR(p.area, 5, 1e-14);
  EXPECT_NEAR(p.volume, 5 * 0.002, 1e-15);
  EXPECT_LT((p.p_GoGcm_G - Eigen::Vector3d(0.5, 0.5, 0.4)).norm(), 1e-15);
  EXPECT_NEAR(p.I_GGcm_G(2, 2), 1.5 * 0.002, 1e-15);
}

TEST(MeshInertiaTest, FlatSquareFallsBackFromHullToThinShell) {
  // A single square has no 3-D hull (qhull: the points are coplanar), so the thin shell is
  // used: a plate a × b of mass ρ·t·a·b; Izz = m(a² + b²)/12 (textbook: thin rectangular plate).
  TriangleMesh mesh;
  const double a = 0.4, b = 0.2, t = 0.001;
  mesh.vertices = {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  MeshInertiaOptions options;
  options.shell_thickness = t;
  const MeshMassProperties p = CalcMeshMassProperties(mesh, options);
  EXPECT_EQ(p.diagnostics.model, MeshSolidModel::kThinShell);
  EXPECT_EQ(p.diagnostics.boundary_edges, 4);
  EXPECT_NE(p.diagnostics.fallback_reason.find("qhull"), std::string::npos)
      << p.diagnostics.fallback_reason;
  const double m = a * b * t;
  EXPECT_NEAR(p.mass, m, 1e-18);
  EXPECT_NEAR(p.I_GGcm_G(2, 2), m * (a * a + b * b) / 12, 1e-15 * m);
  EXPECT_NEAR(p.I_GGcm_G(0, 0), m * b * b / 12, 1e-15 * m);
}

TEST(MeshInertiaTest, ConvexHullOfScatteredPointsIsClosedAndOutward) {
  // The hull of the 8 corners of a box plus interior points is the box: 12 triangles
  // (or more where qhull splits coplanar facets), outward, closed.
  TriangleMesh mesh = MakeBox({-1, -1, -1}, {1, 1, 1});
  mesh.vertices.emplace_back(0.1, 0.2, 0.3);
  mesh.triangles.push_back({0, 1, 8});  // Make the interior point referenced.
  TriangleMesh hull;
  std::string error;
  ASSERT_TRUE(CalcConvexHull(mesh, &hull, &error)) << error;
  EXPECT_EQ(hull.vertices.size(), 8u);
  const MeshDiagnostics d = AnalyzeMeshTopology(hull);
  EXPECT_TRUE(d.IsClosedManifold());
  EXPECT_NEAR(CalcClosedMeshMassPropertiesSigned(hull).volume, 8.0, 1e-13);
}

TEST(MeshInertiaTest, DuplicatedVerticesAndDegenerateTrianglesDoNotChangeTheResult) {
  // The cube as an STL-like soup: 36 vertices of which 28 repeat one of the 8 corners.
  TriangleMesh soup = MakeSoup(MakeBox({0, 0, 0}, {1, 1, 1}));
  // Two degenerate triangles: one with a repeated index, one whose vertices are distinct
  // indices at the same two positions (merged, then repeated).
  soup.triangles.push_back({0, 0, 1});
  soup.vertices.push_back(soup.vertices[0]);
  soup.triangles.push_back({0, 1, static_cast<std::int32_t>(soup.vertices.size() - 1)});
  const MeshMassProperties p = CalcMeshMassProperties(soup);
  EXPECT_EQ(p.diagnostics.duplicate_vertices_merged, 28 + 1);
  EXPECT_EQ(p.diagnostics.degenerate_triangles, 2);
  EXPECT_TRUE(p.diagnostics.IsClosedManifold());
  EXPECT_EQ(p.diagnostics.model, MeshSolidModel::kClosedSolid);
  EXPECT_NEAR(p.volume, 1.0, 1e-15);
  EXPECT_LT(RelativeDifference(p.I_GGcm_G, Inertia(1.0 / 6, 1.0 / 6, 1.0 / 6, 0, 0, 0)), 1e-12);
}

TEST(MeshInertiaTest, SliverTriangleIsCountedAsDegenerate) {
  // A triangle whose third vertex lies on its first edge has zero area.
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, 0, 0}};
  mesh.triangles = {{0, 1, 2}};
  EXPECT_EQ(AnalyzeMeshTopology(mesh).degenerate_triangles, 1);
}

TEST(MeshInertiaTest, EdgeSharedByTwoCubesIsNonManifoldButStillEnclosesTheirVolume) {
  // Cubes [0,1]³ and [1,2]×[1,2]×[0,1] touch along the edge x = y = 1: 4 triangles use it. The
  // surface still encloses the two cubes (the integral does not depend on the reference point),
  // so it is integrated as is: V = 2, center (1, 1, 1/2), and each cube's 1/6 about its own
  // center shifted by the parallel-axis theorem (textbook) to the common center, offsets
  // (∓1/2, ∓1/2, 0): Ixx = Iyy = 2·(1/6 + 1/4), Izz = 2·(1/6 + 1/2), Ixy entry = −Σ m·dx·dy =
  // −2·(1/4).
  TriangleMesh mesh = MakeBox({0, 0, 0}, {1, 1, 1});
  const TriangleMesh other = MakeBox({1, 1, 0}, {2, 2, 1});
  const auto offset = static_cast<std::int32_t>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), other.vertices.begin(), other.vertices.end());
  for (auto t : other.triangles) {
    mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  const MeshMassProperties p = CalcMeshMassProperties(mesh);
  EXPECT_EQ(p.diagnostics.duplicate_vertices_merged, 2);
  EXPECT_EQ(p.diagnostics.non_manifold_edges, 1);
  EXPECT_EQ(p.diagnostics.boundary_edges, 0);
  EXPECT_LT(p.diagnostics.reference_point_sensitivity, 1e-14);
  EXPECT_EQ(p.diagnostics.model, MeshSolidModel::kClosedSolid);
  EXPECT_NE(p.diagnostics.fallback_reason.find("1 non-manifold edges"), std::string::npos);
  EXPECT_NEAR(p.volume, 2.0, 1e-14);
  EXPECT_LT((p.p_GoGcm_G - Eigen::Vector3d(1, 1, 0.5)).norm(), 1e-15);
  EXPECT_LT(RelativeDifference(p.I_GGcm_G, Inertia(2 * (1.0 / 6 + 0.25), 2 * (1.0 / 6 + 0.25),
                                                   2 * (1.0 / 6 + 0.5), -0.5, 0, 0)),
            1e-12);
  // With the closure test off, the convex hull is used. Hand-derived hull: the 2 × 2 × 1 box
  // minus the two corner prisms cut off by the planes through the cubes' far vertical edges:
  // base hexagon area 4 − 2·(1/2) = 3, height 1.
  MeshInertiaOptions strict;
  strict.closure_tolerance = 0;
  const MeshMassProperties q = CalcMeshMassProperties(mesh, strict);
  EXPECT_EQ(q.diagnostics.model, MeshSolidModel::kConvexHull);
  EXPECT_NEAR(q.volume, 3.0, 1e-12);
}

TEST(MeshInertiaTest, TJunctionIsOpenByItsEdgesButClosedByItsIntegral) {
  // The unit cube whose top face is fanned around the midpoint M of its edge y = 0 (a vertex the
  // y = 0 face does not use): the edge and its two halves are boundary edges, yet the surface
  // is closed, so the result is the cube's (V = 1, I = 1/6: textbook).
  TriangleMesh mesh = MakeBox({0, 0, 0}, {1, 1, 1});
  mesh.vertices.emplace_back(0.5, 0, 1);
  const std::int32_t M = 8;
  mesh.triangles.erase(mesh.triangles.begin() + 2, mesh.triangles.begin() + 4);  // z = 1 face.
  mesh.triangles.push_back({M, 5, 7});
  mesh.triangles.push_back({M, 7, 6});
  mesh.triangles.push_back({M, 6, 4});
  const MeshMassProperties p = CalcMeshMassProperties(mesh);
  EXPECT_EQ(p.diagnostics.boundary_edges, 3);
  EXPECT_EQ(p.diagnostics.model, MeshSolidModel::kClosedSolid);
  EXPECT_LT(p.diagnostics.reference_point_sensitivity, 1e-14);
  EXPECT_NEAR(p.volume, 1.0, 1e-15);
  EXPECT_LT(RelativeDifference(p.I_GGcm_G, Inertia(1.0 / 6, 1.0 / 6, 1.0 / 6, 0, 0, 0)), 1e-12);
}

TEST(MeshInertiaTest, OneFlippedTriangleMakesThreeInconsistentEdges) {
  TriangleMesh mesh = MakeBox({0, 0, 0}, {1, 1, 1});
  std::swap(mesh.triangles[5][1], mesh.triangles[5][2]);
  const MeshMassProperties p = CalcMeshMassProperties(mesh);
  EXPECT_EQ(p.diagnostics.inconsistent_edges, 3);
  EXPECT_EQ(p.diagnostics.boundary_edges, 0);
  EXPECT_FALSE(p.diagnostics.IsClosedManifold());
  EXPECT_EQ(p.diagnostics.model, MeshSolidModel::kConvexHull);
  EXPECT_NEAR(p.volume, 1.0, 1e-13);
}

TEST(MeshInertiaTest, ScaleToMassKeepsCenterAndScalesInertia) {
  const MeshMassProperties p = CalcMeshMassProperties(MakeBox({0, 0, 0}, {1, 2, 3}));
  const MeshMassProperties q = ScaleToMass(p, 3.0);
  EXPECT_EQ(q.mass, 3.0);
  EXPECT_EQ(q.volume, p.volume);
  // Box 1 × 2 × 3 of mass 3: Ixx = 3(4 + 9)/12 = 3.25.
  EXPECT_NEAR(q.I_GGcm_G(0, 0), 3.25, 1e-13);
  EXPECT_THROW(ScaleToMass(p, -1.0), std::invalid_argument);
}

TEST(MeshInertiaTest, EmptyMeshHasZeroVolume) {
  const MeshMassProperties p = CalcMeshMassProperties(TriangleMesh{});
  EXPECT_EQ(p.volume, 0.0);
  EXPECT_EQ(p.mass, 0.0);
  EXPECT_EQ(p.diagnostics.model, MeshSolidModel::kThinShell);
}

TEST(MeshInertiaTest, BadIndicesAndNonFiniteVerticesThrow) {
  TriangleMesh mesh = MakeBox({0, 0, 0}, {1, 1, 1});
  mesh.triangles.push_back({0, 1, 8});
  EXPECT_THROW(CalcMeshMassProperties(mesh), std::invalid_argument);
  mesh = MakeBox({0, 0, 0}, {1, 1, 1});
  mesh.vertices[3].x() = std::nan("");
  EXPECT_THROW(CalcMeshMassProperties(mesh), std::invalid_argument);
  MeshInertiaOptions options;
  options.density = -1;
  EXPECT_THROW(CalcMeshMassProperties(MakeBox({0, 0, 0}, {1, 1, 1}), options),
               std::invalid_argument);
}

}  // namespace
}  // namespace massprops

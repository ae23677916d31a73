// Tests of UnitInertia<T> and its shape factories. Expected values come from textbook formulas
// (cited per test; e.g. the table of moments of inertia in Meriam & Kraige, Engineering
// Mechanics: Dynamics, Appendix D, or Wikipedia's "List of moments of inertia"), from
// independent numerical integration, or from F. Tonon, "Explicit exact formulas for the 3-D
// tetrahedron inertia tensor in terms of its vertex coordinates", J. Math. Stat. 1(1), 2004.

#include "massprops/core/unit_inertia.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "test_shapes.h"

namespace massprops {
namespace {

using test_support::RandomRotation;

using G = UnitInertia<double>;
using V = Vector3<double>;
constexpr double kEps = std::numeric_limits<double>::epsilon();

// Expects G to equal the six given matrix entries within tolerance·max|entry|.
void ExpectEntries(const RotationalInertia<double>& I, double xx, double yy, double zz, double xy,
                   double xz, double yz, double tolerance = 8 * kEps) {
  const double scale = std::max({std::abs(xx), std::abs(yy), std::abs(zz), 1e-300});
  EXPECT_NEAR(I(0, 0), xx, tolerance * scale);
  EXPECT_NEAR(I(1, 1), yy, tolerance * scale);
  EXPECT_NEAR(I(2, 2), zz, tolerance * scale);
  EXPECT_NEAR(I(0, 1), xy, tolerance * scale);
  EXPECT_NEAR(I(0, 2), xz, tolerance * scale);
  EXPECT_NEAR(I(1, 2), yz, tolerance * scale);
}

// A rotation whose third column is the unit vector b (so it maps z to b).
Matrix3<double> RotationTakingZTo(const V& b) {
  const V helper = std::abs(b(0)) < 0.9 ? V(1, 0, 0) : V(0, 1, 0);
  const V u = b.cross(helper).normalized();
  const V w = b.cross(u);
  Matrix3<double> R;
  R.col(0) = u;
  R.col(1) = w;
  R.col(2) = b;
  return R;
}

// Detects whether `a op= b` compiles, to check that UnitInertia deletes the compound operators.
template <typename A, typename B, typename = void>
struct HasPlusEquals : std::false_type {};
template <typename A, typename B>
struct HasPlusEquals<A, B, std::void_t<decltype(std::declval<A&>() += std::declval<B>())>>
    : std::true_type {};
template <typename A, typename B, typename = void>
struct HasTimesEquals : std::false_type {};
template <typename A, typename B>
struct HasTimesEquals<A, B, std::void_t<decltype(std::declval<A&>() *= std::declval<B>())>>
    : std::true_type {};

TEST(UnitInertiaTest, CompoundOperatorsThatLeaveUnitMassAreDeleted) {
  EXPECT_TRUE((HasPlusEquals<RotationalInertia<double>, RotationalInertia<double>>::value));
  EXPECT_FALSE((HasPlusEquals<G, RotationalInertia<double>>::value));
  EXPECT_TRUE((HasTimesEquals<RotationalInertia<double>, double>::value));
  EXPECT_FALSE((HasTimesEquals<G, double>::value));
}

TEST(UnitInertiaTest, ConstructorsStoreEntries) {
  EXPECT_TRUE(G().IsNaN());
  ExpectEntries(G(1, 2, 2.5), 1, 2, 2.5, 0, 0, 0, 0);
  ExpectEntries(G(3, 4, 5, -0.5, 0.25, 0.125), 3, 4, 5, -0.5, 0.25, 0.125, 0);
  ExpectEntries(G(RotationalInertia<double>(1, 1, 1)), 1, 1, 1, 0, 0, 0, 0);
}

TEST(UnitInertiaTest, SetFromRotationalInertiaDividesByMass) {
  G g;
  g.SetFromRotationalInertia(RotationalInertia<double>(4, 6, 8, -2, 1, 0.5), 2.0);
  ExpectEntries(g, 2, 3, 4, -1, 0.5, 0.25, 0);
}

TEST(UnitInertiaTest, SolidSphereIsTwoFifthsRSquared) {
  // Solid sphere: I = 2/5·m·r² (textbook).
  ExpectEntries(G::SolidSphere(0.5), 0.1, 0.1, 0.1, 0, 0, 0);
}

TEST(UnitInertiaTest, HollowSphereIsTwoThirdsRSquared) {
  // Thin spherical shell: I = 2/3·m·r² (textbook).
  ExpectEntries(G::HollowSphere(3), 6, 6, 6, 0, 0, 0);
}

TEST(UnitInertiaTest, SolidBoxAndCubeMatchTextbook) {
  // Solid cuboid, sides a, b, c: Ixx = m(b² + c²)/12 etc. (textbook).
  ExpectEntries(G::SolidBox(1, 2, 4), (4 + 16) / 12.0, (1 + 16) / 12.0, (1 + 4) / 12.0, 0, 0, 0);
  // Cube: m·L²/6.
  ExpectEntries(G::SolidCube(3), 1.5, 1.5, 1.5, 0, 0, 0);
  // A zero-size box is a particle: zero, valid.
  EXPECT_TRUE(G::SolidBox(0, 0, 0).IsZero());
}

TEST(UnitInertiaTest, SolidEllipsoidMatchesTextbookAndReducesToSphere) {
  // Solid ellipsoid with semi-axes a, b, c: Ixx = m(b² + c²)/5 etc. (textbook).
  ExpectEntries(G::SolidEllipsoid(1, 2, 3), (4 + 9) / 5.0, (1 + 9) / 5.0, (1 + 4) / 5.0, 0, 0, 0);
  EXPECT_TRUE(G::SolidEllipsoid(0.5, 0.5, 0.5).IsNearlyEqualTo(G::SolidSphere(0.5), 4 * kEps));
}

TEST(UnitInertiaTest, SolidCylinderAlongEachAxisMatchesTextbook) {
  // Solid cylinder, radius r, length L: r²/2 about its axis, (3r² + L²)/12 about a transverse
  // axis through its center (textbook).
  const double r = 0.5, L = 2;
  const double J = r * r / 2, K = (3 * r * r + L * L) / 12;
  ExpectEntries(G::SolidCylinder(r, L, V(0, 0, 1)), K, K, J, 0, 0, 0);
  ExpectEntries(G::SolidCylinder(r, L, V(1, 0, 0)), J, K, K, 0, 0, 0);
  ExpectEntries(G::SolidCylinder(r, L, V(0, -1, 0)), K, J, K, 0, 0, 0);
}

TEST(UnitInertiaTest, SolidCylinderAlongAnyAxisIsTheRotatedZCylinder) {
  std::mt19937_64 generator(5);
  const double r = 0.3, L = 1.7;
  const G along_z = G::SolidCylinder(r, L, V(0, 0, 1));
  for (int k = 0; k < 100; ++k) {
    const V b = RandomRotation<double>(&generator).col(0);
    const G expected = along_z.ReExpress(RotationTakingZTo(b));
    EXPECT_TRUE(G::SolidCylinder(r, L, b).IsNearlyEqualTo(expected, 16 * kEps));
  }
}

TEST(UnitInertiaTest, SolidCylinderAboutEndIsTheParallelAxisTheorem) {
  // About the center of an end face: transverse K + (L/2)² (parallel-axis theorem), axial r²/2.
  const double r = 0.5, L = 2;
  const double K_end = (3 * r * r + L * L) / 12 + (L / 2) * (L / 2);
  ExpectEntries(G::SolidCylinderAboutEnd(r, L, V(0, 0, 1)), K_end, K_end, r * r / 2, 0, 0, 0);
  // The same by shifting the central cylinder half a length along its (oblique) axis.
  const V b = V(1, 2, 2) / 3;
  const G shifted = G::SolidCylinder(r, L, b).ShiftFromCenterOfMass(-L / 2 * b);
  EXPECT_TRUE(G::SolidCylinderAboutEnd(r, L, b).IsNearlyEqualTo(shifted, 16 * kEps));
}

// Capsule moments by numerical integration over slices perpendicular to the axis (z): a slice at
// height z is a disk of radius ρ(z) (ρ = r on the cylinder, ρ² = r² − (|z| − L/2)² on the caps)
// and mass dm ∝ ρ² dz; its moments about the center are ½ρ² dm (axial) and (¼ρ² + z²) dm
// (transverse). Composite Simpson with 20000 intervals on each piece; independent of the closed
// form in the implementation.
std::pair<double, double> CapsuleByIntegration(double r, double L) {
  const auto integrate = [](auto f, double a, double b) {
    const int n = 20000;
    const double h = (b - a) / n;
    double sum = f(a) + f(b);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * f(a + i * h);
    return sum * h / 3;
  };
  const auto rho2 = [r, L](double z) {
    const double over = std::abs(z) - L / 2;
    return over <= 0 ? r * r : std::max(0.0, r * r - over * over);
  };
  const double top = L / 2 + r;
  double mass = 0, axial = 0, transverse = 0;
  for (const auto& [a, b] :
       {std::pair{-top, -L / 2}, std::pair{-L / 2, L / 2}, std::pair{L / 2, top}}) {
    mass += integrate([&](double z) { return rho2(z); }, a, b);
    axial += integrate([&](double z) { return 0.5 * rho2(z) * rho2(z); }, a, b);
    transverse += integrate([&](double z) { return (0.25 * rho2(z) + z * z) * rho2(z); }, a, b);
  }
  return {axial / mass, transverse / mass};
}

TEST(UnitInertiaTest, SolidCapsuleMatchesNumericalIntegration) {
  for (const auto& [r, L] : {std::pair{0.5, 2.0}, std::pair{1.0, 0.5}, std::pair{0.1, 3.0}}) {
    const auto [J, K] = CapsuleByIntegration(r, L);
    ExpectEntries(G::SolidCapsule(r, L, V(0, 0, 1)), K, K, J, 0, 0, 0, 1e-10);
  }
}

TEST(UnitInertiaTest, SolidCapsuleReducesToSphereAndRod) {
  // L = 0: a solid sphere (2/5·r²); r = 0: a thin rod (L²/12, 0 about the axis).
  EXPECT_TRUE(G::SolidCapsule(0.7, 0, V(0, 1, 0)).IsNearlyEqualTo(G::SolidSphere(0.7), 4 * kEps));
  EXPECT_TRUE(
      G::SolidCapsule(0, 2, V(0, 1, 0)).IsNearlyEqualTo(G::ThinRod(2, V(0, 1, 0)), 4 * kEps));
  EXPECT_TRUE(G::SolidCapsule(0, 0, V(0, 1, 0)).IsZero());
}

TEST(UnitInertiaTest, ThinRodAndThinDiskLieOnTheValidityBoundary) {
  // Thin rod: L²/12 transverse, 0 axial. Thin disk: r²/4 in-plane, r²/2 about the normal.
  ExpectEntries(G::ThinRod(6, V(1, 0, 0)), 0, 3, 3, 0, 0, 0);
  ExpectEntries(G::ThinDisk(2, V(0, 0, 1)), 1, 1, 2, 0, 0, 0);
  std::mt19937_64 generator(17);
  for (int k = 0; k < 1000; ++k) {
    const V axis = RandomRotation<double>(&generator).col(2);
    for (const double size : {1e-9, 1e-3, 1.0, 1e3, 1e9}) {
      EXPECT_TRUE(G::ThinRod(size, axis).CouldBePhysicallyValid());
      EXPECT_TRUE(G::ThinDisk(size, axis).CouldBePhysicallyValid());
    }
  }
}

TEST(UnitInertiaTest, PointMassMatchesDefinition) {
  // |p|²·1 − p·pᵀ for p = (1, 2, 3): (13, 10, 5) with products −2, −3, −6 (hand-derived).
  ExpectEntries(G::PointMass(V(1, 2, 3)), 13, 10, 5, -2, -3, -6, 0);
}

TEST(UnitInertiaTest, TriaxiallySymmetricHasEqualMoments) {
  ExpectEntries(G::TriaxiallySymmetric(0.25), 0.25, 0.25, 0.25, 0, 0, 0, 0);
}

TEST(UnitInertiaTest, AxiallySymmetricHasJAlongAxisAndKAcross) {
  // Definition: G·b = J·b and G·u = K·u for any u ⊥ b.
  const double J = 0.3, K = 0.4;
  const V b = V(2, -3, 6) / 7;  // |(2, −3, 6)| = 7.
  const G g = G::AxiallySymmetric(J, K, b);
  EXPECT_TRUE((g * b).isApprox(J * b, 4 * kEps));
  const V u = V(3, 2, 0) / std::sqrt(13.0);  // u·b = 0.
  EXPECT_TRUE((g * u).isApprox(K * u, 4 * kEps));
  const V w = b.cross(u);
  EXPECT_TRUE((g * w).isApprox(K * w, 4 * kEps));
  EXPECT_TRUE(G::StraightLine(K, b).IsNearlyEqualTo(G::AxiallySymmetric(0, K, b), 0));
}

TEST(UnitInertiaTest, FactoriesRejectBadArgumentsInEveryBuild) {
  EXPECT_THROW(G::SolidCylinder(1, 1, V(0, 0, 1.001)), std::logic_error);
  EXPECT_THROW(G::ThinRod(1, V(1, 1, 0)), std::logic_error);
  EXPECT_THROW(G::ThinDisk(1, V(0, 0, 0)), std::logic_error);
  EXPECT_THROW(G::SolidCapsule(1, 1, V(NAN, 0, 0)), std::logic_error);
  EXPECT_THROW(G::SolidSphere(-1), std::logic_error);
  EXPECT_THROW(G::SolidBox(1, NAN, 1), std::logic_error);
  EXPECT_THROW(G::SolidEllipsoid(1, 1, std::numeric_limits<double>::infinity()), std::logic_error);
  EXPECT_THROW(G::AxiallySymmetric(1, 0.4, V(0, 0, 1)), std::logic_error);  // J > 2K.
  EXPECT_THROW(G::AxiallySymmetric(-1, 1, V(0, 0, 1)), std::logic_error);
  // Unit within round-off is accepted.
  EXPECT_NO_THROW(G::ThinRod(1, V(1, 1, 1) / std::sqrt(3.0)));
  try {
    G::ThinRod(1, V(0, 2, 0));
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("norm 2"), std::string::npos) << e.what();
  }
}

// Tonon (2004), equations for a, b, c (moments) and a', b', c' (products ∫yz, ∫xz, ∫xy), written
// out term by term, for unit density; the inertia matrix is [[a, −c', −b'], [−c', b, −a'],
// [−b', −a', c]] times |det J| (J = the matrix of edge vectors from vertex 1).
RotationalInertia<double> TononInertia(const V& p1, const V& p2, const V& p3, const V& p4) {
  const double x1 = p1(0), x2 = p2(0), x3 = p3(0), x4 = p4(0);
  const double y1 = p1(1), y2 = p2(1), y3 = p3(1), y4 = p4(1);
  const double z1 = p1(2), z2 = p2(2), z3 = p3(2), z4 = p4(2);
  Matrix3<double> edges;
  edges.col(0) = p2 - p1;
  edges.col(1) = p3 - p1;
  edges.col(2) = p4 - p1;
  const double detJ = std::abs(edges.determinant());
  const auto square_sum = [](double u1, double u2, double u3, double u4) {
    return u1 * u1 + u1 * u2 + u2 * u2 + u1 * u3 + u2 * u3 + u3 * u3 + u1 * u4 + u2 * u4 + u3 * u4 +
           u4 * u4;
  };
  const auto product_sum = [](double u1, double u2, double u3, double u4, double w1, double w2,
                              double w3, double w4) {
    return 2 * u1 * w1 + u2 * w1 + u3 * w1 + u4 * w1 + u1 * w2 + 2 * u2 * w2 + u3 * w2 + u4 * w2 +
           u1 * w3 + u2 * w3 + 2 * u3 * w3 + u4 * w3 + u1 * w4 + u2 * w4 + u3 * w4 + 2 * u4 * w4;
  };
  const double a = detJ * (square_sum(y1, y2, y3, y4) + square_sum(z1, z2, z3, z4)) / 60;
  const double b = detJ * (square_sum(x1, x2, x3, x4) + square_sum(z1, z2, z3, z4)) / 60;
  const double c = detJ * (square_sum(x1, x2, x3, x4) + square_sum(y1, y2, y3, y4)) / 60;
  const double a_prime = detJ * product_sum(y1, y2, y3, y4, z1, z2, z3, z4) / 120;
  const double b_prime = detJ * product_sum(x1, x2, x3, x4, z1, z2, z3, z4) / 120;
  const double c_prime = detJ * product_sum(x1, x2, x3, x4, y1, y2, y3, y4) / 120;
  return RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(a, b, c, -c_prime, -b_prime,
                                                                        -a_prime, true);
}

TEST(UnitInertiaTest, SolidTetrahedronAboutVertexMatchesTononFormulas) {
  std::mt19937_64 generator(23);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  for (int k = 0; k < 200; ++k) {
    const V p1(coordinate(generator), coordinate(generator), coordinate(generator));
    const V p2(coordinate(generator), coordinate(generator), coordinate(generator));
    const V p3(coordinate(generator), coordinate(generator), coordinate(generator));
    Matrix3<double> edges;
    edges << p1, p2, p3;
    const double volume = std::abs(edges.determinant()) / 6;
    if (volume < 1e-3) continue;
    const RotationalInertia<double> I = TononInertia(V::Zero(), p1, p2, p3);
    const G expected(I / volume);  // Unit mass: divide by the mass of unit density, the volume.
    EXPECT_TRUE(G::SolidTetrahedronAboutVertex(p1, p2, p3).IsNearlyEqualTo(expected, 1e-13));
    // Vertex order does not matter.
    EXPECT_TRUE(G::SolidTetrahedronAboutVertex(p3, p1, p2).IsNearlyEqualTo(expected, 1e-13));
  }
}

TEST(UnitInertiaTest, SolidTetrahedronReproducesTononsNumericalExample) {
  // Tonon (2004), section "Numerical example": vertices below, unit density, inertia about the
  // centroid (15.92492, 0.78281, 3.72962): a = 43520.33257, b = 194711.28938,
  // c = 191168.76173, a' = 4417.66150, b' = −46343.16662, c' = 11996.20119.
  const V p1(8.33220, -11.86875, 0.93355), p2(0.75523, 5.00000, 16.37072);
  const V p3(52.61236, 5.00000, -5.38580), p4(2.00000, 5.00000, 3.00000);
  const V centroid = (p1 + p2 + p3 + p4) / 4;
  // The paper prints its inputs to 5 decimals and its results were computed from unrounded ones
  // (its centroid x, 15.92492, differs from the mean of the printed vertices by 2.7e-5), so
  // agreement is to about 2e-8 of the largest entry; the tolerance is 1e-7 of it (0.02).
  EXPECT_NEAR(centroid(0), 15.92492, 5e-5);
  EXPECT_NEAR(centroid(1), 0.78281, 5e-5);
  Matrix3<double> edges;
  edges << p2 - p1, p3 - p1, p4 - p1;
  const double volume = std::abs(edges.determinant()) / 6;
  const G g =
      G::SolidTetrahedronAboutPoint(p1 - centroid, p2 - centroid, p3 - centroid, p4 - centroid);
  const RotationalInertia<double> I = g.MultiplyByScalarSkipValidityCheck(volume);
  const double kTolerance = 1e-7 * 194711.28938;
  EXPECT_NEAR(I(0, 0), 43520.33257, kTolerance);
  EXPECT_NEAR(I(1, 1), 194711.28938, kTolerance);
  EXPECT_NEAR(I(2, 2), 191168.76173, kTolerance);
  EXPECT_NEAR(I(1, 2), -4417.66150, kTolerance);   // −a' = −∫yz.
  EXPECT_NEAR(I(0, 2), 46343.16662, kTolerance);   // −b' = −∫xz.
  EXPECT_NEAR(I(0, 1), -11996.20119, kTolerance);  // −c' = −∫xy.
}

TEST(UnitInertiaTest, CornerTetrahedronMatchesHandIntegration) {
  // Tetrahedron 0, a·x̂, a·ŷ, a·ẑ: ∫x² dV = a⁵/60 and ∫xy dV = a⁵/120 over x + y + z <= a,
  // volume a³/6 (hand-integrated), so per unit mass ∫x² = a²/10, ∫xy = a²/20:
  // Ixx = a²/5, Ixy = −a²/20.
  const double a = 2;
  const G g = G::SolidTetrahedronAboutVertex(V(a, 0, 0), V(0, a, 0), V(0, 0, a));
  ExpectEntries(g, a * a / 5, a * a / 5, a * a / 5, -a * a / 20, -a * a / 20, -a * a / 20);
}

TEST(UnitInertiaTest, ShiftsAndReExpressKeepTheUnitType) {
  // Unit solid sphere of radius 1 (2/5) shifted by (0, 0, 2): parallel axis adds 4 to Ixx and Iyy.
  const G sphere = G::SolidSphere(1);
  const G shifted = sphere.ShiftFromCenterOfMass(V(0, 0, 2));
  ExpectEntries(shifted, 0.4 + 4, 0.4 + 4, 0.4, 0, 0, 0);
  EXPECT_TRUE(shifted.ShiftToCenterOfMass(V(0, 0, 2)).IsNearlyEqualTo(sphere, 8 * kEps));
  // From the point 2 above the center to the point (1, 0, 0) beside it: the parallel-axis term of
  // p = (1, 0, 0) adds y² + z² = 0 to Ixx and 1 to Iyy and Izz: (0.4, 1.4, 1.4).
  const G moved = shifted.ShiftToThenAwayFromCenterOfMass(V(0, 0, -2), V(-1, 0, 0));
  ExpectEntries(moved, 0.4, 1.4, 1.4, 0, 0, 0);
  G in_place = shifted;
  in_place.ShiftToCenterOfMassInPlace(V(0, 0, 2)).ShiftFromCenterOfMassInPlace(V(1, 0, 0));
  EXPECT_TRUE(in_place.IsNearlyEqualTo(moved, 8 * kEps));
  in_place.ShiftToThenAwayFromCenterOfMassInPlace(V(-1, 0, 0), V(0, 0, -2));
  EXPECT_TRUE(in_place.IsNearlyEqualTo(shifted, 8 * kEps));
  // Quarter turn about z maps the rod along x to a rod along y.
  Matrix3<double> Rz;
  Rz << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  const G rod = G::ThinRod(6, V(1, 0, 0));
  ExpectEntries(rod.ReExpress(Rz), 3, 0, 3, 0, 0, 0);
  G rod2 = rod;
  rod2.ReExpressInPlace(Rz);
  EXPECT_EQ(rod2, rod.ReExpress(Rz));
}

TEST(UnitInertiaTest, CastAndOtherScalarTypes) {
  const UnitInertia<float> f = UnitInertia<float>::SolidBox(1, 2, 4);
  EXPECT_NEAR(f(0, 0), 20.0f / 12, 4e-7f);
  const UnitInertia<long double> l = G::SolidCylinder(0.5, 2, V(0, 0, 1)).cast<long double>();
  EXPECT_NEAR(static_cast<double>(l(2, 2)), 0.125, 1e-16);
  const UnitInertia<long double> exact =
      UnitInertia<long double>::SolidCylinder(0.5L, 2.0L, Vector3<long double>(0, 0, 1));
  EXPECT_TRUE(l.IsNearlyEqualTo(exact, 1e-15L));
  const UnitInertia<float> from_double = G::ThinDisk(1, V(0, 1, 0)).cast<float>();
  EXPECT_EQ(from_double(1, 1), 0.5f);
}

}  // namespace
}  // namespace massprops

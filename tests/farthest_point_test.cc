#include "analysis/rules/farthest_point.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

// The farthest-point index of inertia-exceeds-model (src/analysis/rules/farthest_point.h, a
// private class of the library) against its oracle, the scan it replaces: the same double, bit
// for bit, on chains, clouds, flat sheets and repeated points at scales 1e-3..1e3, with centers
// inside, outside and on the points; and far fewer distances than the scan (issue 50).

namespace massprops {
namespace rules {
namespace {

double Scan(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& c) {
  double farthest = 0;
  for (const Eigen::Vector3d& p : points) farthest = std::max(farthest, (p - c).norm());
  return farthest;
}

// Point i of a set of kind `kind` (0: the corners of a chain of boxes along z, as
// tools/gen_chain.py draws, 1: a flat sheet, 2: a cloud with repeated points, 3: a cloud).
Eigen::Vector3d PointOf(int kind, int i, std::mt19937_64& rng,
                        const std::vector<Eigen::Vector3d>& so_far) {
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::Vector3d p(u(rng), u(rng), u(rng));
  if (kind == 0) {
    p = Eigen::Vector3d(i % 2 ? 0.02 : -0.02, (i / 2) % 2 ? 0.02 : -0.02, 0.1 * (i / 4));
  } else if (kind == 1) {
    p.z() = 0;
  } else if (kind == 2 && i % 3 == 0 && i > 0) {
    p = so_far.back();
  }
  return p;
}

TEST(FarthestPointIndexTest, GivesTheScansDistanceBitForBit) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 24; ++trial) {
    const int n = 1 + trial * trial * 25;
    const double scale = std::pow(10.0, trial % 7 - 3);
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < n; ++i) points.push_back(PointOf(trial % 4, i, rng, points));
    for (Eigen::Vector3d& p : points) p *= scale;
    const FarthestPointIndex index(points);
    for (int q = 0; q < 60; ++q) {
      Eigen::Vector3d c(u(rng), u(rng), u(rng));
      c *= 3 * scale * std::pow(10.0, q % 5 - 2);
      if (q % 10 == 0) c = points[static_cast<std::size_t>(q) % points.size()];
      EXPECT_EQ(index.MaxDistance(c), Scan(points, c)) << "n " << n << " question " << q;
    }
    // A scan evaluates n distances per question; the index a few leaves of 8 points.
    if (n > 1000) {
      EXPECT_LT(index.evaluated(), static_cast<std::size_t>(100 * 60)) << n;
    }
  }
}

TEST(FarthestPointIndexTest, NotFinitePointsOrCentersAreTheScan) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Eigen::Vector3d> points = {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(nan, 0, 0),
                                               Eigen::Vector3d(0, 2, 0)};
  const FarthestPointIndex index(points);
  // std::max skips the NaN distance: the scan's 2, from (0, 2, 0).
  EXPECT_EQ(index.MaxDistance(Eigen::Vector3d::Zero()), 2.0);
  const FarthestPointIndex far(
      std::vector<Eigen::Vector3d>{Eigen::Vector3d(inf, 0, 0), Eigen::Vector3d(1, 0, 0)});
  EXPECT_EQ(far.MaxDistance(Eigen::Vector3d::Zero()), inf);
  const std::vector<Eigen::Vector3d> one = {Eigen::Vector3d(3, 4, 0)};
  const FarthestPointIndex plain(one);
  EXPECT_EQ(plain.MaxDistance(Eigen::Vector3d(nan, 0, 0)), Scan(one, Eigen::Vector3d(nan, 0, 0)));
  const FarthestPointIndex none{std::vector<Eigen::Vector3d>()};
  EXPECT_EQ(none.MaxDistance(Eigen::Vector3d::Zero()), 0.0);
}

}  // namespace
}  // namespace rules
}  // namespace massprops

#pragma once
// The distance from a point to the farthest of a fixed set of points, answered for many points
// (private to src/analysis/rules/): what a rule that measures every link against the whole
// model's geometry asks once per link. A scan over the set costs its size per question, so a
// model of n links asked n times costs n^2; this index (a k-d tree of the points' boxes, pruned
// by the farthest corner of each box) answers a question in about log n steps and gives exactly
// the scan's number: it evaluates the same expression on the same points and skips only boxes
// that cannot hold a farther one.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <vector>

namespace massprops {
namespace rules {

class FarthestPointIndex {
 public:
  /// An index of `points` (any number, any values). Cost: O(n log n) time, O(n) memory.
  explicit FarthestPointIndex(std::vector<Eigen::Vector3d> points);

  /// The largest (p - c).norm() over the points p, bit for bit what the scan
  /// `double d = 0; for (p : points) d = std::max(d, (p - c).norm());` returns (0 for no points;
  /// NaN distances are skipped as std::max skips them). Where a point or c is not finite, it is
  /// that scan.
  double MaxDistance(const Eigen::Vector3d& c) const;

  bool empty() const { return points_.empty(); }

  /// How many distances the questions so far evaluated (a scan evaluates size() per question).
  std::size_t evaluated() const { return evaluated_; }
  std::size_t size() const { return points_.size(); }

 private:
  struct Node {
    Eigen::AlignedBox3d box;  // of the points [begin, end)
    int begin = 0, end = 0;
    int left = -1, right = -1;  // children (nodes), or -1 for a leaf
  };
  int Build(int begin, int end);
  double Scan(const Eigen::Vector3d& c, int begin, int end) const;

  std::vector<Eigen::Vector3d> points_;  // reordered: each node's points are contiguous
  std::vector<Node> nodes_;
  bool finite_ = true;
  mutable std::size_t evaluated_ = 0;
  mutable std::vector<int> stack_;  // the nodes still to open, kept between questions
};

}  // namespace rules
}  // namespace massprops

#include "analysis/rules/farthest_point.h"

#include <algorithm>
#include <utility>

namespace massprops {
namespace rules {
namespace {

// Points per leaf: a leaf is scanned whole.
constexpr int kLeafSize = 8;
// A box is skipped when its bound, this little enlarged, is no farther than the farthest point
// found: the bound is computed with the same operations, in the same order, as a point's
// distance, on per-axis numbers at least as large (rounding is monotone), so it is never below
// the distance of a point inside; the margin only guards against a compiler evaluating the two
// differently (a fused multiply-add in one place and not the other).
constexpr double kBoundMargin = 1 + 1e-12;

// At least the computed (p - c).norm() of every point p in `box`.
double FarthestCornerBound(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& c) {
  const Eigen::Vector3d to_min = box.min() - c, to_max = box.max() - c;
  const Eigen::Vector3d farthest = to_min.cwiseAbs().cwiseMax(to_max.cwiseAbs());
  return farthest.norm();
}

}  // namespace

FarthestPointIndex::FarthestPointIndex(std::vector<Eigen::Vector3d> points)
    : points_(std::move(points)) {
  for (const Eigen::Vector3d& p : points_) finite_ = finite_ && p.allFinite();
  if (!finite_ || points_.empty()) return;
  nodes_.reserve(2 * (points_.size() / kLeafSize + 1));
  Build(0, static_cast<int>(points_.size()));
}

int FarthestPointIndex::Build(int begin, int end) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Eigen::AlignedBox3d box;
  for (int i = begin; i < end; ++i) box.extend(points_[i]);
  nodes_[index].box = box;
  nodes_[index].begin = begin;
  nodes_[index].end = end;
  if (end - begin <= kLeafSize) return index;
  // Split at the median along the box's longest side.
  int axis = 0;
  box.sizes().maxCoeff(&axis);
  const int middle = begin + (end - begin) / 2;
  std::nth_element(
      points_.begin() + begin, points_.begin() + middle, points_.begin() + end,
      [axis](const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return a(axis) < b(axis); });
  const int left = Build(begin, middle);
  const int right = Build(middle, end);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

double FarthestPointIndex::Scan(const Eigen::Vector3d& c, int begin, int end) const {
  double farthest = 0;
  for (int i = begin; i < end; ++i) farthest = std::max(farthest, (points_[i] - c).norm());
  evaluated_ += static_cast<std::size_t>(end - begin);
  return farthest;
}

double FarthestPointIndex::MaxDistance(const Eigen::Vector3d& c) const {
  if (!finite_ || !c.allFinite()) return Scan(c, 0, static_cast<int>(points_.size()));
  if (nodes_.empty()) return 0;
  double farthest = 0;
  std::vector<int>& stack = stack_;
  stack.assign(1, 0);
  while (!stack.empty()) {
    const Node& node = nodes_[stack.back()];
    stack.pop_back();
    if (kBoundMargin * FarthestCornerBound(node.box, c) <= farthest) continue;
    if (node.left < 0) {
      farthest = std::max(farthest, Scan(c, node.begin, node.end));
      continue;
    }
    // The child whose box reaches farther is opened first (pushed last).
    const bool left_first = FarthestCornerBound(nodes_[node.left].box, c) >=
                            FarthestCornerBound(nodes_[node.right].box, c);
    stack.push_back(left_first ? node.right : node.left);
    stack.push_back(left_first ? node.left : node.right);
  }
  return farthest;
}

}  // namespace rules
}  // namespace massprops

#include "io/trajectory_derive.h"

#include <algorithm>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

#include "io/trajectory_filter.h"

namespace massprops::io_internal {

namespace {

// Every row of `m` (samples at `time`) interpolated linearly at `grid` (increasing, within time's
// range).
Eigen::MatrixXd Interpolate(const Eigen::VectorXd& time, const Eigen::MatrixXd& m,
                            const Eigen::VectorXd& grid) {
  Eigen::MatrixXd out(grid.size(), m.cols());
  Eigen::Index k = 0;
  for (Eigen::Index i = 0; i < grid.size(); ++i) {
    while (k + 2 < time.size() && time(k + 1) <= grid(i)) ++k;
    const double w = (grid(i) - time(k)) / (time(k + 1) - time(k));
    out.row(i) = (1 - w) * m.row(k) + w * m.row(k + 1);
  }
  return out;
}

// The whole recording interpolated linearly onto a uniform grid of interval `step` from its first
// time stamp to its last.
void ResampleUniformly(double step, JointTrajectory* t) {
  const double span = t->time(t->time.size() - 1) - t->time(0);
  const Eigen::Index n = static_cast<Eigen::Index>(span / step * (1 + 1e-12)) + 1;
  Eigen::VectorXd grid(n);
  for (Eigen::Index i = 0; i < n; ++i) grid(i) = t->time(0) + static_cast<double>(i) * step;
  t->q = Interpolate(t->time, t->q, grid);
  t->dq = Interpolate(t->time, t->dq, grid);
  t->ddq = Interpolate(t->time, t->ddq, grid);
  t->tau = Interpolate(t->time, t->tau, grid);
  t->time = grid;
}

// The sampling rate from the median interval; 0 (with *error) when the cutoff is not below half
// of it, or when the interval varies by more than 10% and its longest is more than a quarter of
// the filter's period. A recording that varies less widely (a robot's log stamped as messages
// arrive: the Panda's of Gaz et al. 2019 varies from 0.7 to 8.8 ms around 1 ms) is first
// resampled linearly at its median interval, and said in t->notes: linear interpolation over an
// interval below a quarter of the period of the fastest motion the filter keeps moves what it
// keeps little, and the filter needs a constant rate.
double DerivationSampleRate(double cutoff_hz, JointTrajectory* t, std::string* error) {
  const Eigen::VectorXd& time = t->time;
  std::vector<double> dt(static_cast<std::size_t>(time.size() - 1));
  for (std::size_t i = 0; i < dt.size(); ++i)
    dt[i] = time(static_cast<Eigen::Index>(i + 1)) - time(static_cast<Eigen::Index>(i));
  std::vector<double> sorted = dt;
  const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
  std::nth_element(sorted.begin(), middle, sorted.end());
  const double median = sorted[sorted.size() / 2];
  const auto [lo, hi] = std::minmax_element(dt.begin(), dt.end());
  if (*hi > 1.1 * median || *lo < 0.9 * median) {
    const double longest = cutoff_hz > 0 ? 1 / (4 * cutoff_hz) : 0;
    if (!(*hi <= longest)) {
      *error = "the sampling interval varies from " + std::to_string(*lo) + " to " +
               std::to_string(*hi) + " s, and its longest is more than a quarter of the " +
               "filter's period (" + std::to_string(longest) +
               " s): velocities and accelerations cannot be derived across the gap (give the "
               "'J.dq' and 'J.ddq' columns, or split the recording at the gap)";
      return 0;
    }
    const Eigen::Index before = time.size();
    ResampleUniformly(median, t);
    std::ostringstream note;
    note << "the sampling interval varies from " << *lo << " to " << *hi << " s: the " << before
         << " samples were interpolated linearly onto " << t->time.size()
         << " at the median interval, " << median << " s, before deriving";
    t->notes.push_back(note.str());
  }
  const double rate = 1 / median;
  if (!(cutoff_hz > 0 && cutoff_hz < rate / 2)) {
    *error = "the filter cutoff " + std::to_string(cutoff_hz) +
             " Hz is not between 0 and half the sampling rate (" + std::to_string(rate) + " Hz)";
    return 0;
  }
  return rate;
}

}  // namespace

std::string DeriveMissingDerivatives(const std::vector<RecordedDerivatives>& recorded,
                                     const TrajectoryCsvOptions& options, JointTrajectory* t) {
  double rate = 0;
  std::string error;
  for (std::size_t j = 0; j < t->joints.size(); ++j) {
    const RecordedDerivatives& has = recorded[j];
    if (has.dq && has.ddq) continue;
    if (rate == 0 && !(rate = DerivationSampleRate(options.cutoff_hz, t, &error))) return error;
    const Eigen::Index col = static_cast<Eigen::Index>(j);
    if (!has.dq) {
      t->dq.col(col) =
          CentralDifference(t->time, LowPassZeroPhase(t->q.col(col), rate, options.cutoff_hz));
    }
    if (!has.ddq) {
      const Eigen::VectorXd dq = !has.dq
                                     ? Eigen::VectorXd(t->dq.col(col))
                                     : LowPassZeroPhase(t->dq.col(col), rate, options.cutoff_hz);
      t->ddq.col(col) = CentralDifference(t->time, dq);
    }
    const char* what = has.dq    ? "ddq derived from dq"
                       : has.ddq ? "dq derived from q"
                                 : "dq and ddq derived from q";
    std::ostringstream note;
    note << "joint '" << t->joints[j] << "': " << what << " (zero-phase low-pass "
         << options.cutoff_hz << " Hz, central differences)";
    t->notes.push_back(note.str());
  }
  return "";
}

}  // namespace massprops::io_internal

#include "io/trajectory_derive.h"

#include <algorithm>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

#include "io/trajectory_filter.h"

namespace massprops::io_internal {

namespace {

// The sampling rate from the median interval; 0 (with *error) when it varies by more than 10% or
// the cutoff is not below half of it.
double DerivationSampleRate(const Eigen::VectorXd& time, double cutoff_hz, std::string* error) {
  std::vector<double> dt(static_cast<std::size_t>(time.size() - 1));
  for (std::size_t i = 0; i < dt.size(); ++i)
    dt[i] = time(static_cast<Eigen::Index>(i + 1)) - time(static_cast<Eigen::Index>(i));
  std::vector<double> sorted = dt;
  const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
  std::nth_element(sorted.begin(), middle, sorted.end());
  const double median = sorted[sorted.size() / 2];
  const auto [lo, hi] = std::minmax_element(dt.begin(), dt.end());
  if (*hi > 1.1 * median || *lo < 0.9 * median) {
    *error = "the sampling interval varies from " + std::to_string(*lo) + " to " +
             std::to_string(*hi) +
             " s: velocities and accelerations can be derived only "
             "from a constant rate (give the 'J.dq' and 'J.ddq' columns)";
    return 0;
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
    if (rate == 0 && !(rate = DerivationSampleRate(t->time, options.cutoff_hz, &error)))
      return error;
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

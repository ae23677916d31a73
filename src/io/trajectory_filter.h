#pragma once
// The derivatives of a sampled signal for ReadTrajectoryCsv (io/trajectory_csv.h): a zero-phase
// low-pass filter and central differences.

#include <Eigen/Core>

namespace massprops::io_internal {

/// x filtered by a second-order Butterworth low-pass (bilinear transform, cutoff prewarped) run
/// forward, then backward over the result (zero phase, squared magnitude response). The ends are
/// extended by odd reflection (3 cutoff periods, at most x.size() − 1 samples) and the filter
/// starts in the steady state of the first value, so a constant or a ramp passes unchanged.
/// Preconditions: 0 < cutoff_hz < sample_rate_hz / 2, x.size() >= 2.
Eigen::VectorXd LowPassZeroPhase(const Eigen::VectorXd& x, double sample_rate_hz, double cutoff_hz);

/// dx/dt at each sample: (x[i+1] − x[i−1]) / (t[i+1] − t[i−1]) inside, one-sided differences at
/// the two ends. Precondition: t strictly increasing, t.size() == x.size() >= 2.
Eigen::VectorXd CentralDifference(const Eigen::VectorXd& t, const Eigen::VectorXd& x);

}  // namespace massprops::io_internal

#pragma once
// The velocities and accelerations a recording does not give, derived from what it gives: shared
// by the CSV reader (io/trajectory_csv.h) and the rosbag2 reader (io/trajectory_rosbag.h).

#include <string>
#include <vector>

#include "massprops/io/trajectory_csv.h"

namespace massprops::io_internal {

/// Which derivatives a joint's recording has.
struct RecordedDerivatives {
  bool dq = false;
  bool ddq = false;
};

/// Fills t->dq of each joint j without recorded.dq (from its positions) and t->ddq of each joint
/// without recorded.ddq (from its velocities, recorded or derived): a zero-phase low-pass at
/// options.cutoff_hz, then central differences (io/trajectory_filter.h), one sentence per joint
/// derived in t->notes. When a derivative is needed and the sampling interval varies by more than
/// 10% around its median, the whole recording (every column) is first interpolated linearly onto
/// a uniform grid at the median interval, and said in t->notes. Returns an error sentence (and
/// derives nothing more) when such a recording has an interval longer than a quarter of the
/// filter's period, 1 / (4·cutoff) (a gap), or the cutoff is not between 0 and half the sampling
/// rate; "" otherwise. recorded.size() == t->joints.size().
std::string DeriveMissingDerivatives(const std::vector<RecordedDerivatives>& recorded,
                                     const TrajectoryCsvOptions& options, JointTrajectory* t);

}  // namespace massprops::io_internal

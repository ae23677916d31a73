#pragma once
/// @file
/// Recorded joint trajectories from CSV, the input of identification (docs/identify.md): one row
/// per sample, a header row naming the columns `time` (seconds) and, per joint J, `J.q` (rad or
/// m), `J.dq`, `J.ddq` and `J.tau` (N·m or N). `J.q` and `J.tau` are required for every joint;
/// a joint without `J.dq` has its velocities derived from its positions, and without `J.ddq` its
/// accelerations from its velocities, by a zero-phase low-pass filter (a second-order Butterworth
/// run forward and backward, so its phase cancels: a fourth-order magnitude response, -6 dB at
/// the cutoff) followed by central differences. Columns of other names are ignored.
///
/// PlotJuggler's CSV export of a sensor_msgs/JointState topic is read too: its `__time` column as
/// `time` (when there is no `time`), and `<topic>/J/position`, `<topic>/J/velocity`,
/// `<topic>/J/effort` (any topic name, e.g. `/joint_states/shoulder/position`) as `J.q`, `J.dq`,
/// `J.tau`.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "massprops/model/model.h"

namespace massprops {

/// N samples of n joints.
struct JointTrajectory {
  std::vector<std::string> joints;  ///< In the order their `.q` columns appear.
  Eigen::VectorXd time;             ///< N, strictly increasing, seconds.
  Eigen::MatrixXd q, dq, ddq, tau;  ///< N × n each.
  /// What was derived rather than read, one sentence each ("joint 'j1': dq and ddq derived from
  /// q, low-pass 10 Hz, central differences").
  std::vector<std::string> notes;
};

struct TrajectoryCsvOptions {
  /// Cutoff of the zero-phase low-pass filter applied before differentiating, Hz. Must be below
  /// half the sampling rate. 10 Hz keeps the motion of an arm on an exciting trajectory (mostly
  /// below 2 Hz) and removes most encoder quantization noise at 1 kHz.
  double cutoff_hz = 10;
  /// Fewer rows than this is an error (the filter and the fit need data).
  int min_samples = 10;
};

/// What ReadTrajectoryCsv returns: the trajectory, or (absent) the errors, each with the file and
/// line (line 0: the whole file) and a message naming the column or the value.
struct TrajectoryReadResult {
  std::optional<JointTrajectory> trajectory;
  std::vector<ReadError> errors;
  bool ok() const { return errors.empty(); }
};

/// Reads CSV text (comma-separated, no quoting; blank lines and lines starting with '#' are
/// skipped). Errors: no `time` column; a joint with `.dq`, `.ddq` or `.tau` but no `.q`, or with
/// `.q` but no `.tau`; a row with another number of fields than the header; a field that is not
/// a finite number (NaN included); a time not greater than the one before; fewer than
/// options.min_samples rows; a derivative needed from a recording whose sampling interval varies
/// by more than 10% and reaches more than a quarter of the filter's period, 1 / (4·cutoff) (a
/// gap: below it, such a recording is resampled linearly at its median interval, said in
/// `notes`, since the filter assumes a constant rate), or a cutoff at or above half the sampling
/// rate. Never throws for bad input. Cost: linear in the text.
TrajectoryReadResult ReadTrajectoryCsv(const std::string& text, const std::string& file_name,
                                       const TrajectoryCsvOptions& options = {});

/// The same from a file (a ReadError when it cannot be read).
TrajectoryReadResult ReadTrajectoryCsvFile(const std::string& path,
                                           const TrajectoryCsvOptions& options = {});

}  // namespace massprops

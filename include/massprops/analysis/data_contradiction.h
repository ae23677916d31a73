#pragma once
/// @file
/// `massprops check --data LOG` (docs/rules.md, `inertia-contradicts-data`; docs/identify.md):
/// whether a robot file's mass properties explain recorded joint torques much worse than
/// physically consistent values can. The file's inertial parameters are kept as written and only
/// each joint's friction (viscous, Coulomb, offset: the columns identify fits too) is fitted to
/// the training samples, so that a file without friction is not blamed for it; its torque RMS on
/// the held-out samples is compared with the consistent fit's (analysis/identify.h), which
/// estimates what noise and unmodelled effects leave (the noise floor).

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>

#include "massprops/analysis/checks.h"
#include "massprops/analysis/identify.h"
#include "massprops/model/model.h"

namespace massprops {

/// The rule's id.
inline constexpr std::string_view kInertiaContradictsData = "inertia-contradicts-data";

/// The file's held-out RMS must be more than this times the consistent fit's. With Gaussian
/// noise σ the consistent fit's held-out RMS is about σ·√(1 + p/N) ≈ σ, and the file's is
/// √(σ² + e²), e the RMS of the torque error of the file's values: a ratio of 2 means e = √3·σ,
/// an error of the file 1.7 times the whole noise, which N ≫ p samples do not produce by chance
/// (the ratio's own spread is about 1/√N); smaller ratios stay within what joint elasticity,
/// timing offsets or filtering plausibly add, so they are not reported.
inline constexpr double kDataContradictionFactor = 2.0;
/// And the file's held-out RMS must exceed the fit's by more than this fraction of the RMS of the
/// measured held-out torques: with noise-free (simulated) data the fit's RMS is round-off, and a
/// ratio of two round-offs says nothing.
inline constexpr double kDataContradictionFloor = 1e-3;

/// The comparison for one robot and one recording.
struct DataContradiction {
  /// Torque RMS over every held-out joint sample (all samples when none is held out), N·m or N:
  /// of the file's inertial values with friction fitted, of the consistent fit, of the measured
  /// torques themselves.
  double rms_file = 0, rms_identified = 0, rms_measured = 0;
  Eigen::VectorXd rms_file_per_joint;  ///< The file's values' RMS per joint (tree order).
  int validation_samples = 0;          ///< Samples the RMS is over (per joint).
  bool contradicts = false;            ///< Both conditions above hold.
};

/// Compares the file's values with `result`, the consistent fit Identify(tree, data, options)
/// made. Cost: one regressor per sample (torque_regressor.h) and a 3 × 3 solve per joint.
DataContradiction AssessDataContradiction(const KinematicTree& tree, const OrderedTrajectory& data,
                                          const IdentifyResult& result,
                                          const IdentifyOptions& options);

/// The `inertia-contradicts-data` finding of `model` (at its first moving link) for a comparison
/// that contradicts, at `severity`; nullopt when it does not. `data_name` is the LOG as given.
std::optional<Finding> DataContradictionFinding(const Model& model, const KinematicTree& tree,
                                                const DataContradiction& c,
                                                const std::string& data_name, Severity severity);

}  // namespace massprops

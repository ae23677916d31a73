#pragma once
// Private to analysis: what the simulator files of src/analysis/targets/ share (docs/targets.md):
// the rule ids of the target layer, number formatting, the inertia a finding points at, and the
// FindingSink that applies the severities and the rules a link ignores. One file per simulator
// (mujoco_*.cc, drake.cc, gazebo.cc) adds its findings through the entry points below; the
// dispatch by target is target_layer.cc, the repairs target_repairs.cc, the profiles profiles.cc.
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "massprops/analysis/target_profile.h"

namespace massprops::targets {

// Rule ids of the target layer (docs/targets.md explains each, with its source).
constexpr const char* kMujocoTriangle = "mujoco-rejects-inertia-triangle";
constexpr const char* kMujocoMinValRule = "mujoco-rejects-below-minval";
constexpr const char* kMujocoFusedInertia = "mujoco-rejects-fused-inertia";
constexpr const char* kMujocoGeomMass = "mujoco-rejects-geom-inertia";
constexpr const char* kMujocoNegative = "mujoco-rejects-negative";
constexpr const char* kMujocoUnpredicted = "mujoco-not-predicted";
constexpr const char* kDrakeMassless = "drake-rejects-massless-body";
constexpr const char* kDrakeInvalid = "drake-rejects-invalid-inertia";
constexpr const char* kGazeboLumped = "gazebo-lumps-fixed-joint";

/// x with 6 significant digits ("%.6g").
std::string Num(double x);

/// Three principal moments as "a, b, c" (each as Num).
std::string Moments(const std::array<double, 3>& m);

/// Whether `link` ignores `rule` (its massprops:ignore comments, or "all").
bool Ignored(const Link& link, const std::string& rule);

/// Where a finding about the link's inertia points: its <inertia>, else its <inertial>, else the
/// link.
const SourceLocation& InertiaLocationOf(const Link& link);

/// The inertia matrix as written (about the inertial frame's origin, in the inertial frame).
Eigen::Matrix3d WrittenMatrixOf(const Inertial& in);

/// massprops' physics test of a symmetric matrix at the given relative tolerance.
bool PhysicallyValid(const Eigen::Matrix3d& I, double tolerance);

/// Whether the link has a collision geometry.
bool HasCollision(const Link& link);

/// Collects the findings of the target layer, with the severity the options give each rule (none:
/// the finding is dropped) and without those a link ignores.
class FindingSink {
 public:
  FindingSink(const Model& model, const CheckOptions& options) : model_(model), options_(options) {}

  void Emit(const std::string& rule, int link_index, const SourceLocation& location,
            std::string message, std::vector<std::pair<std::string, double>> values);
  std::vector<Finding> Take() { return std::move(findings_); }

 private:
  const Model& model_;
  const CheckOptions& options_;
  std::vector<Finding> findings_;
};

// ------------------------------------------------------------------ MuJoCo (mujoco_layer.cc)
/// The findings of --target mujoco: what PredictMujoco says MuJoCo refuses or cannot predict.
void CheckMujoco(const Model& model, const CheckOptions& options,
                 const MujocoCompilerOptions& mujoco, FindingSink* sink);
/// Adds to each inertia-not-physical finding what MuJoCo decides about that inertia.
void AnnotateMujoco(const Model& model, const MujocoCompilerOptions& mujoco,
                    std::vector<Finding>* findings);

// ------------------------------------------------------------------ Drake (drake.cc)
/// The findings of --target drake: CouldBePhysicallyValid, and singular hinge inertias.
void CheckDrake(const Model& model, FindingSink* sink);

// ------------------------------------------------------------------ Gazebo (gazebo.cc)
/// The findings of --target gazebo: the links lumped across fixed joints.
void CheckGazebo(const Model& model, const CheckOptions& options, std::string_view text,
                 FindingSink* sink);
/// An invalid member of a valid lumped body becomes a warning, saying so.
void AnnotateGazebo(const Model& model, const CheckOptions& options, std::string_view text,
                    std::vector<Finding>* findings);

}  // namespace massprops::targets

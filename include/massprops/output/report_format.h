#pragma once
/// @file
/// The mass report (analysis/mass_report.h) as text, JSON or CSV.

#include <array>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "massprops/analysis/mass_report.h"
#include "massprops/analysis/target_profile.h"
#include "massprops/model/model.h"

namespace massprops {

/// Output formats of the report.
enum class MassReportFormat { kText, kJson, kCsv };

/// An input file that could not be reported, for the renderings.
struct MassReportError {
  std::string file;
  int line = 0;
  std::string message;
};

/// One body of a model as a simulator sees it (`report --target`, docs/targets.md).
struct TargetBody {
  std::string name;                ///< Its (first) link's name.
  std::vector<std::string> links;  ///< Its links: its own first, then those lumped/fused into it.
  /// Gazebo and Drake: mass, center of mass and inertia about it in the frame of its first link,
  /// with principal moments and axes (MakeBodyMassProperties). Absent for MuJoCo.
  std::optional<BodyMassProperties> properties;
  // MuJoCo only: whether it moves, its mass, and the principal moments its eigen-solver gives
  // after its clamping (decreasing).
  bool moving = false;
  double mass = 0;
  std::array<double, 3> mujoco_moments{};
};

/// What `report --target` adds to one model's report.
struct ModelTargetReport {
  Target target = Target::kGeneric;  ///< kGeneric: nothing is added.
  std::vector<TargetBody> bodies;    ///< In the order of their first links.
  // MuJoCo only: its verdict.
  bool accepted = true;
  std::string refusal_message;             ///< MuJoCo's first refusal ("" when accepted).
  std::string refusal_body;                ///< The body it names ("" when none).
  std::vector<std::string> not_predicted;  ///< What the emulation does not predict, and why.
};

/// The bodies of `model` as `target` sees them: Gazebo's lumped bodies (GazeboBodies), Drake's
/// one body per link, MuJoCo's bodies after fusestatic with its verdict (PredictMujoco with the
/// file's <mujoco><compiler>). A URDF root link named "world" is the world for Gazebo and Drake,
/// not a body. `text` is the model's file (for Gazebo's and MuJoCo's tags). kGeneric gives an
/// empty report. Never throws for bad input.
ModelTargetReport MakeTargetReport(const Model& model, Target target, const std::string& text);

/// Writes the reports: JSON as documented in docs/report.md ({"models":[...],"errors":[...]}),
/// numbers round-trip exactly; CSV one row per body (header first), numbers with max_digits10;
/// text aligned tables with 6 significant digits and notes (no equivalent box, unreachable links,
/// digits lost above `digits_lost_threshold`). `errors` appear only in JSON (the tool prints them
/// to standard error for text and CSV). `targets` (empty, or parallel to `reports`) adds each
/// model's target part to JSON ("target", "target_bodies", MuJoCo's verdict) and CSV (rows of
/// kind target_body, target_refusal, target_not_predicted and the columns target,
/// target_moving, target_message when any model has a target); the text format ignores it.
/// Never throws except for stream errors.
void WriteMassReport(std::ostream& out, MassReportFormat format,
                     const std::vector<ModelMassReport>& reports,
                     const std::vector<MassReportError>& errors = {},
                     double digits_lost_threshold = 6,
                     const std::vector<ModelTargetReport>& targets = {});

}  // namespace massprops

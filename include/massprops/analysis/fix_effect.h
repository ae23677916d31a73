#pragma once
/// @file
/// What a fix does to the whole robot: the mass, center of mass and principal moments of the whole
/// model and of each welded group with a changed link, before and after (`massprops fix` prints
/// it for the mass repairs, mass_repair.h). The numbers are those of `massprops report`
/// (ComputeMassReport at the zero configuration, in the root link's frame).

#include <optional>
#include <string>
#include <vector>

#include "massprops/analysis/mass_report.h"
#include "massprops/model/model.h"

namespace massprops {

/// One body (the whole model, or a welded group) before and after.
struct BodyEffect {
  std::string name;                ///< "model" or the group's root link.
  std::vector<std::string> links;  ///< The group's links (root first); empty for the model.
  std::optional<BodyMassProperties> before;
  std::optional<BodyMassProperties> after;
};

/// The effect of a fix on one model.
struct FixEffect {
  std::string model;
  BodyEffect total;                ///< The whole model (its report total).
  std::vector<BodyEffect> groups;  ///< The welded groups holding a changed link, in file order.
};

/// Compares the reports of `before` and `after` (the same model with changed inertials: same
/// links, joints and welded groups). `changed_links` names the links whose inertials changed.
/// Returns false and sets *error when a report cannot be computed. Never throws.
bool CalcFixEffect(const Model& before, const Model& after,
                   const std::vector<std::string>& changed_links, FixEffect* effect,
                   std::string* error);

}  // namespace massprops

#pragma once
/// @file
/// The mass repairs an engineer asks for by name (`massprops fix --total-mass KG`, `--mass
/// LINK=KG`, `--density LINK=RHO`, `--material LINK=NAME`): the weighed robot, the datasheet part,
/// the material. Each gives Repairs (repair.h) that the patcher writes like any other; none runs
/// unless asked for.
///
/// - A scaled link keeps its center of mass and its mass distribution: its mass and every entry
///   of its inertia (moments and products) are multiplied by one factor k.
/// - `--mass LINK=KG`: k = KG / m for that link.
/// - `--density` / `--material`: mass = density × volume of the link's closed meshes, with their
///   center of mass and inertia (LinkShapeFunction of MakeClosedMeshShapeFunction).
/// - `--total-mass M`: every other link with a positive mass is scaled by one common factor
///   k = (M − fixed) / (sum of their masses), where `fixed` is the mass the links named by the
///   options above get (and, in SDF, the default 1 kg of links without <inertial>).
///
/// Changed numbers are rounded to kMassRepairDigits significant digits (a given --mass is written
/// as given); a total within kTotalMassTolerance of M is left alone, so a second run of the same
/// command changes nothing.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "massprops/analysis/link_shape.h"
#include "massprops/analysis/repair.h"
#include "massprops/model/model.h"

namespace massprops {

/// Significant digits of the numbers a mass repair writes (far below a scale's grams).
inline constexpr int kMassRepairDigits = 9;
/// --total-mass: a model whose total is within this relative distance of the asked one is not
/// rescaled (the 9-digit rounding leaves at most 5e-10).
inline constexpr double kTotalMassTolerance = 1e-8;

/// A link given a density: `--density LINK=RHO` (material empty) or `--material LINK=NAME`.
struct LinkDensityRequest {
  std::string link;
  double density = 0;    ///< kg/m³, > 0.
  std::string material;  ///< The material's label ("aluminium 6061"), or empty.
};

struct MassRepairOptions {
  std::optional<double> total_mass;                         ///< kg, > 0 (--total-mass).
  std::vector<std::pair<std::string, double>> link_masses;  ///< (link, kg > 0) (--mass).
  std::vector<LinkDensityRequest> link_densities;           ///< --density LINK=, --material.
  /// The link's closed meshes as a solid (MakeClosedMeshShapeFunction); needed by
  /// link_densities.
  LinkShapeFunction closed_mesh;

  /// Whether any mass repair is asked for.
  bool any() const { return total_mass || !link_masses.empty() || !link_densities.empty(); }
};

/// The mass repairs `options` asks for on `model`, one per changed link, in file order (rule
/// "--total-mass", "--mass", "--density" or "--material"; method "scale" or "from-closed-mesh").
/// Returns false and sets *error (a sentence naming the link or the numbers) when a link is not
/// in the model or is named twice, a link to scale has no <inertial> or no positive mass, a
/// --density link has no closed mesh, or the total cannot be reached (the named links weigh more
/// than it, or nothing is left to scale). Never throws.
bool PlanMassRepairs(const Model& model, const MassRepairOptions& options,
                     std::vector<Repair>* repairs, std::string* error);

/// Merges two sets of repairs of the same model: `first` was planned on `model`, `second` on
/// the model with `first` applied. A link in both gets one repair from its original inertial to
/// the second's result (rules and whys joined). In file order. Never throws.
std::vector<Repair> ChainRepairs(const Model& model, const std::vector<Repair>& first,
                                 const std::vector<Repair>& second);

}  // namespace massprops

#pragma once
/// @file
/// The rules that turn a link's mass into a density by the volume of its closed meshes
/// (CheckOptions::closed_mesh): `density-implausible` (a link) and `cad-default-density` (the
/// whole model). CheckModel runs them; without CheckOptions::closed_mesh they find nothing.

#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/model/model.h"

namespace massprops {

inline constexpr const char* kDensityImplausibleRule = "density-implausible";
inline constexpr const char* kCadDefaultDensityRule = "cad-default-density";

/// The density SolidWorks gives a part that has no material (kg/m³; its Mass Properties use it,
/// and sw_urdf_exporter writes those masses).
inline constexpr double kCadDefaultDensity = 1000;
/// `cad-default-density`: how far from 1000 kg/m³ every link's mass / volume may be (relative).
/// A CAD export's STL is a tessellation of the solid its mass came from, so the two volumes differ
/// by the chord error (0.30% at most on TheRobotStudio/SO-ARM100's raw export, docs/rules.md), and
/// the exporter writes masses with 5-6 digits. The nearest plastics are 4% away (ABS 1040).
inline constexpr double kCadDefaultDensityTolerance = 0.01;
/// `cad-default-density` needs at least this many links with closed meshes (one link at 1000
/// kg/m³ could be a part of a material of that density; several all at it are not).
inline constexpr int kCadDefaultDensityMinLinks = 2;

/// The two rules, as RuleInfo (both warnings, on by default).
const std::vector<RuleInfo>& DensityRules();

/// Appends the density findings of `model` to *findings and sorts them in (by line, then rule,
/// as CheckModel orders). Honours options.overrides and Link::ignored_rules. Cost: one call of
/// options.closed_mesh per link with a positive mass and geometry (each mesh file read once per
/// the function's cache); nothing without it.
void AddDensityFindings(const Model& model, const CheckOptions& options,
                        std::vector<Finding>* findings);

}  // namespace massprops

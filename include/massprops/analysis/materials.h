#pragma once
/// @file
/// A short table of the materials robot parts are made of, with their densities and where each
/// value comes from (`massprops fix --material LINK=NAME`, and the totals the density rules quote),
/// and the bounds of the densities solid parts have (rule `density-implausible`).

#include <string>
#include <string_view>
#include <vector>

namespace massprops {

/// One material: its name on the command line, its density and the source of that value.
struct Material {
  std::string name;    ///< Lower-case, e.g. "aluminium-6061".
  std::string label;   ///< For messages, e.g. "aluminium 6061".
  double density = 0;  ///< kg/m³.
  std::string source;  ///< Where the value comes from (a data sheet or a standard).
};

/// The table, in a stable order: aluminium-6061 2700, steel 7850, pla 1240, abs 1040, petg 1270,
/// nylon 1140, carbon-fibre 1570 (kg/m³; each with its source, see docs/fix.md).
const std::vector<Material>& CommonMaterials();

/// The material named `name` (case-insensitive; "aluminum-6061", "aluminium", "aluminum" and
/// "cfrp" are accepted as other spellings), or nullptr.
const Material* FindMaterial(std::string_view name);

/// The names of the table, comma-separated, for messages ("aluminium-6061, steel, ...").
std::string MaterialNames();

/// Below this density (kg/m³) a part is a foam or an aerogel, not a solid of an engineering
/// material: polymer foams and aerogels lie below it, the lightest solid woods (balsa) about at
/// it (M. F. Ashby, Materials Selection in Mechanical Design, 4th ed., 2011, the density chart).
inline constexpr double kMinSolidDensity = 100;
/// Above this density (kg/m³) no material exists: osmium, the densest element, is 22 590 kg/m³
/// (CRC Handbook of Chemistry and Physics); tungsten is 19 300.
inline constexpr double kMaxSolidDensity = 22590;

}  // namespace massprops

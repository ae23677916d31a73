#pragma once
// The command line of `massprops fix` (fix_command.cc): its arguments and their checks.
#include <optional>
#include <string>
#include <vector>

#include "massprops/analysis/mass_repair.h"
#include "massprops/analysis/repair.h"
#include "xacro_cli.h"

namespace massprops::cli {

struct FixArgs {
  std::string file;
  bool dry_run = false;
  bool diff = false;
  std::string output;
  bool in_place = false;
  std::string backup;
  std::string repair = "project";
  bool fix_units = false;
  std::vector<std::string> apply;
  double density = kDefaultDensity;
  // --density RHO (a bare number: the density above) or LINK=RHO (repeatable), as written.
  std::vector<std::string> density_args;
  std::optional<double> total_mass;        // --total-mass KG
  std::vector<std::string> mass_args;      // --mass LINK=KG
  std::vector<std::string> material_args;  // --material LINK=NAME
  std::string format = "text";             // --format text|json
  MassRepairOptions mass;                  // filled from the four above by ParseMassOptions
  bool from_geometry = false;
  std::vector<std::string> from_geometry_links;
  double tolerance = 1e-6;
  std::vector<std::string> model_paths;
  bool geometry = false;
  bool no_geometry = false;  // --no-geometry: not even the meshes' bounding boxes
  std::vector<std::string> package_paths;
  std::string target;  // --target ("" = generic)
  bool include_files = false;
  XacroOptions xacro;  // a xacro package: the sources are repaired (xacro_fix.h)
};

// Reads --density (RHO or LINK=RHO), --mass LINK=KG, --material LINK=NAME and --total-mass into
// args->density and args->mass; prints the reason and returns false when one is malformed.
bool ParseMassOptions(FixArgs* args);

// Rejects contradictory or out-of-range options before anything is read; prints the reason and
// returns false when the command line is wrong.
bool CheckFixArgs(const FixArgs& args);

}  // namespace massprops::cli

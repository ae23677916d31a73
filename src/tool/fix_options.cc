// The command line of `massprops fix`: parsing and checking its options (fix_options.h).
#include "fix_options.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>

#include "massprops/analysis/materials.h"

namespace massprops::cli {
namespace {

// A positive finite number written whole in `text` (no trailing characters), or nullopt.
std::optional<double> ParsePositive(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !(x > 0) || !std::isfinite(x)) return std::nullopt;
  return x;
}

// Splits "LINK=VALUE" at its last '='; false when there is none or a side is empty.
bool SplitAssignment(const std::string& text, std::string* link, std::string* value) {
  const std::size_t eq = text.rfind('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size()) return false;
  *link = text.substr(0, eq);
  *value = text.substr(eq + 1);
  return true;
}

}  // namespace

bool ParseMassOptions(FixArgs* args) {
  int bare = 0;
  for (const std::string& text : args->density_args) {
    std::string link, value;
    if (text.find('=') == std::string::npos) {
      const std::optional<double> rho = ParsePositive(text);
      if (!rho || ++bare > 1) {
        std::cerr << "massprops: error: --density must be a positive number of kg/m³ (given once) "
                     "or LINK=KG_PER_M3, got '"
                  << text << "'\n";
        return false;
      }
      args->density = *rho;
      continue;
    }
    const std::optional<double> rho =
        SplitAssignment(text, &link, &value) ? ParsePositive(value) : std::nullopt;
    if (!rho) {
      std::cerr << "massprops: error: --density LINK=KG_PER_M3: '" << text
                << "' does not name a link and a positive density\n";
      return false;
    }
    args->mass.link_densities.push_back({link, *rho, ""});
  }
  for (const std::string& text : args->material_args) {
    std::string link, name;
    const Material* material = SplitAssignment(text, &link, &name) ? FindMaterial(name) : nullptr;
    if (material == nullptr) {
      std::cerr << "massprops: error: --material LINK=NAME: '" << text
                << "' does not name a link and one of the materials " << MaterialNames() << "\n";
      return false;
    }
    args->mass.link_densities.push_back({link, material->density, material->label});
  }
  for (const std::string& text : args->mass_args) {
    std::string link, value;
    const std::optional<double> kg =
        SplitAssignment(text, &link, &value) ? ParsePositive(value) : std::nullopt;
    if (!kg) {
      std::cerr << "massprops: error: --mass LINK=KG: '" << text
                << "' does not name a link and a positive mass\n";
      return false;
    }
    args->mass.link_masses.emplace_back(link, *kg);
  }
  if (args->total_mass) {
    if (!(*args->total_mass > 0) || !std::isfinite(*args->total_mass)) {
      std::cerr << "massprops: error: --total-mass must be a positive number of kg\n";
      return false;
    }
    args->mass.total_mass = args->total_mass;
  }
  if (!args->mass.link_densities.empty() && args->no_geometry) {
    std::cerr << "massprops: error: --density LINK=... and --material read the link's meshes: "
                 "they cannot be combined with --no-geometry\n";
    return false;
  }
  if (args->format == "json" && (args->diff || (!args->dry_run && !args->in_place &&
                                                (args->output.empty() || args->output == "-")))) {
    std::cerr << "massprops: error: --format json prints on standard output: use it with "
                 "--dry-run, -o OUT or --in-place, and without --diff\n";
    return false;
  }
  return true;
}

bool CheckFixArgs(const FixArgs& args) {
  if (args.in_place && !args.output.empty()) {
    std::cerr << "massprops: error: --in-place and -o cannot be combined\n";
    return false;
  }
  if (!args.backup.empty() && !args.in_place) {
    std::cerr << "massprops: error: --backup needs --in-place\n";
    return false;
  }
  if (args.dry_run && (args.in_place || !args.output.empty() || args.diff)) {
    std::cerr << "massprops: error: --dry-run cannot be combined with --diff, -o or --in-place\n";
    return false;
  }
  if (args.in_place && args.file == "-") {
    std::cerr << "massprops: error: --in-place needs a file, not standard input\n";
    return false;
  }
  if (!(args.tolerance >= 0) || !std::isfinite(args.tolerance)) {
    std::cerr << "massprops: error: --tolerance must be a finite number at least 0, got "
              << args.tolerance << "\n";
    return false;
  }
  if (!(args.density > 0) || !std::isfinite(args.density)) {
    std::cerr << "massprops: error: --density must be a positive number of kg/m³\n";
    return false;
  }
  return true;
}

}  // namespace massprops::cli

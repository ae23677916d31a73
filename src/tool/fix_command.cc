// `massprops fix` (see docs/fix.md): repairs the mass properties that have a known remedy and
// writes the file back with only those numbers changed. Exit codes:
//   0  the output has no error-severity finding left (changes made, or none needed);
//   1  the output still has errors that no repair exists for (they are listed on stderr);
//   2  the file could not be read or parsed, the command line is wrong, or the output could not
//      be written (then nothing was written: the original is untouched).
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <system_error>
#include <vector>

#include "commands.h"
#include "fix_options.h"
#include "geometry_cli.h"
#include "massprops/analysis/checks.h"
#include "massprops/analysis/finding_text.h"
#include "massprops/analysis/fix_effect.h"
#include "massprops/analysis/fix_text.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/analysis/mass_repair.h"
#include "massprops/analysis/materials.h"
#include "massprops/analysis/repair.h"
#include "massprops/analysis/repair_routes.h"
#include "massprops/io/model_reader.h"
#include "massprops/mesh/mesh_loader.h"
#include "massprops/output/fix_report.h"
#include "massprops/output/reporters.h"
#include "massprops/output/xml_patch.h"
#include "safe_write.h"
#include "target_cli.h"
#include "xacro_cli.h"
#include "xacro_fix.h"

namespace massprops::cli {
namespace {

namespace fs = std::filesystem;

constexpr int kExitOk = 0;
constexpr int kExitErrorsRemain = 1;
constexpr int kExitError = 2;

// The file each repaired link is defined in: the top-level file, or (SDF) the file of an
// included model.
std::string FileOfLink(const std::vector<Model>& models, const std::string& link_name, int line) {
  for (const Model& model : models) {
    for (const Link& link : model.links) {
      if (link.name == link_name && link.location.line == line) return link.location.file;
    }
  }
  return "";
}

// The file being repaired: its text, the name messages give it, and what the reader made of it.
struct FixInput {
  std::string name;  // the file, or "<stdin>" for '-'
  std::string text;
  ReadOptions read_options;
  ReadResult read;
};

// Reads and parses FILE into *input; prints the errors and returns false when it cannot be read
// or holds no model.
bool ReadFixInput(const FixArgs& args, FixInput* input) {
  if (std::optional<ReadError> error = ReadInputFile(args.file, kMaxModelFileBytes, &input->text)) {
    std::cerr << error->ToString() << "\n";
    return false;
  }
  input->name = args.file == "-" ? "<stdin>" : args.file;
  input->read_options.sdf.model_paths = args.model_paths;
  input->read = ReadModelString(input->text, input->name, input->read_options);
  if (!input->read.ok() || input->read.models.empty()) {
    for (const ReadError& e : input->read.errors) std::cerr << e.ToString() << "\n";
    if (input->read.errors.empty()) std::cerr << input->name << ": no model found\n";
    return false;
  }
  return true;
}

// How a run plans and judges repairs, from the command line and the file's text. Filled in place
// (resolve points into mesh_cache), so it is neither copied nor moved.
struct FixSetup {
  RepairOptions repair;
  CheckOptions check;
  Target target = Target::kGeneric;
  MujocoCompilerOptions mujoco;
  MeshCache mesh_cache;  // each mesh file is read once
  MeshResolveOptions resolve;
  // The meshes' shapes for the ways forward of a link fix leaves (repair_routes.h): read only
  // for such a link (unless --no-geometry).
  LinkShapeFunction route_shape;
};

// Whether every --apply RULE names a heuristic repair (or "all"); prints the choices when not.
bool CheckApplyRules(const std::vector<std::string>& apply) {
  for (const std::string& rule : apply) {
    const std::vector<std::string>& known = HeuristicRepairRules();
    if (rule != "all" && std::find(known.begin(), known.end(), rule) == known.end()) {
      std::cerr << "massprops: error: --apply: '" << rule << "' is not a heuristic repair; one of";
      for (const std::string& k : known) std::cerr << " " << k;
      std::cerr << ", or all\n";
      return false;
    }
  }
  return true;
}

// Fills *setup from the command line and the file's text; returns false (with the reason
// printed) when --apply names an unknown rule.
bool ConfigureFix(const FixArgs& args, const std::string& text, FixSetup* setup) {
  if (!CheckApplyRules(args.apply)) return false;
  RepairOptions& options = setup->repair;
  options.method =
      args.repair == "balance" ? InertiaRepairMethod::kBalance : InertiaRepairMethod::kProject;
  options.fix_units = args.fix_units;
  options.apply = args.apply;
  options.density = args.density;
  options.from_geometry_all = args.from_geometry && args.from_geometry_links.empty();
  options.from_geometry_links = args.from_geometry_links;
  options.tolerance = args.tolerance;
  setup->target = ResolveTarget(args.target, args.file);  // --target, else .massprops.toml
  ApplyTargetProfile(setup->target, &setup->check);
  setup->check.tolerance = args.tolerance;
  setup->mujoco = ReadMujocoCompilerOptions(text);
  // Meshes' mass properties are read only when asked: --geometry (the checks and repairs use
  // them) or --from-geometry (the inertials it replaces may come from meshes). Each file is read
  // once.
  setup->resolve = MakeResolveOptions(WithConfigPackagePaths(args.package_paths, args.file),
                                      args.model_paths, args.file, &setup->mesh_cache);
  if (args.geometry || args.from_geometry) {
    options.shape = MakeLinkShapeFunction(setup->resolve);
    if (args.geometry) setup->check.shape = options.shape;
  }
  // By default the meshes' bounding boxes (cheap: no mass properties) give mesh-only links an
  // extent, for the checks that plan the repairs and for the re-check of each, as in `check`.
  if (!args.no_geometry) {
    options.box = MakeLinkBoxFunction(setup->resolve);
    setup->check.box = options.box;
    options.points = MakeLinkPointsFunction(setup->resolve);
    setup->check.points = options.points;
    // The mass repairs asked for by name read the closed meshes (--density LINK=, --material),
    // and so do the density rules that judge the result; a bare fix does not read them.
    if (args.mass.any()) setup->check.closed_mesh = MakeClosedMeshShapeFunction(setup->resolve);
    setup->route_shape = options.shape ? options.shape : MakeLinkShapeFunction(setup->resolve);
  }
  return true;
}

// The repairs planned for every model of the file, and those that were not made.
struct RepairPlan {
  std::vector<Repair> repairs;
  std::vector<RefusedRepair> refused;
  std::vector<std::string> known_links;
  // Heuristic repairs that were not asked for, per rule: listed so that nothing is silent.
  std::map<std::string, std::vector<Repair>> not_asked;
  // The ways forward of each link fix leaves with a finding, or (--dry-run) repairs.
  std::map<std::string, std::vector<RepairRoute>> routes;
  // The severity of each finding (link, rule) the repairs were planned from.
  std::map<std::pair<std::string, std::string>, Severity> severity;
};

// The ways forward (repair_routes.h) of the links of `model` that fix leaves with an error or a
// refused repair, and with `all` (--dry-run) of those it repairs or could repair too.
void AddRoutes(const Model& model, const std::vector<Finding>& findings, const FixSetup& setup,
               const std::vector<Repair>& planned, std::size_t first_refused, bool all,
               RepairPlan* plan) {
  RepairOptions options = setup.repair;
  options.shape = setup.route_shape;
  std::set<std::string> links;
  for (std::size_t i = first_refused; i < plan->refused.size(); ++i) {
    links.insert(plan->refused[i].link);
  }
  for (const Finding& f : findings) {
    plan->severity[{f.link, f.rule}] = f.severity;
    if (f.severity == Severity::kError && !f.link.empty()) links.insert(f.link);
  }
  if (all) {
    for (const Repair& r : planned) links.insert(r.link);
    for (const auto& [rule, list] : plan->not_asked) {
      for (const Repair& r : list) links.insert(r.link);
    }
  }
  for (const std::string& link : links) {
    if (model.FindLink(link) < 0 || plan->routes.count(link)) continue;
    const auto written = std::find_if(planned.begin(), planned.end(),
                                      [&](const Repair& r) { return r.link == link; });
    if (!all && written != planned.end()) continue;
    plan->routes[link] = FindRepairRoutes(model, findings, link, options,
                                          written == planned.end() ? nullptr : &*written);
  }
}

// Plans the repairs of every model: the mass repairs asked for by name (mass_repair.h), then on
// the model they give those asked for (and the target's), and the heuristic ones that were not
// asked for. Returns false (with the reason printed) when a mass option cannot be carried out.
bool PlanFix(const ReadResult& read, const FixSetup& setup, const MassRepairOptions& mass,
             bool dry_run, RepairPlan* result) {
  RepairPlan& plan = *result;
  if (mass.any() && read.models.size() != 1) {
    std::cerr << "massprops: error: --total-mass, --mass, --density LINK=... and --material work "
                 "on a file with one model; this one has "
              << read.models.size() << "\n";
    return false;
  }
  for (const Model& file_model : read.models) {
    for (const Link& link : file_model.links) plan.known_links.push_back(link.name);
    std::vector<Repair> mass_repairs;
    Model with_mass;
    if (mass.any()) {
      MassRepairOptions options = mass;
      options.closed_mesh = setup.check.closed_mesh;
      std::string error;
      if (!PlanMassRepairs(file_model, options, &mass_repairs, &error)) {
        std::cerr << "massprops: error: " << error << "\n";
        return false;
      }
      with_mass = ApplyRepairs(file_model, mass_repairs);
    }
    const Model& model = mass.any() ? with_mass : file_model;
    const std::vector<Finding> findings = CheckModel(model, setup.check);
    const std::size_t first_refused = plan.refused.size();
    std::vector<Repair> planned = PlanRepairs(model, findings, setup.repair, &plan.refused);
    if (setup.target != Target::kGeneric) {  // what the simulator needs on top (target_profile.h)
      planned = PlanTargetRepairs(model, setup.target, setup.mujoco, planned);
    }
    if (!mass_repairs.empty()) planned = ChainRepairs(file_model, mass_repairs, planned);
    plan.repairs.insert(plan.repairs.end(), planned.begin(), planned.end());
    RepairOptions every = setup.repair;
    every.apply = {"all"};
    for (Repair& r : PlanRepairs(model, findings, every)) {
      const bool planned_already = std::any_of(planned.begin(), planned.end(),
                                               [&](const Repair& p) { return p.link == r.link; });
      if (!planned_already) plan.not_asked[r.rule].push_back(std::move(r));
    }
    AddRoutes(model, findings, setup, planned, first_refused, dry_run, &plan);
  }
  return true;
}

// Moves the repairs of links defined in an included SDF model out of *repairs; returns them by
// file. They belong to that model's file: written there with --include-files, otherwise named
// (never applied to an element of the same name here).
std::map<std::string, std::vector<Repair>> TakeIncludedRepairs(const FixInput& input,
                                                               std::vector<Repair>* repairs) {
  std::map<std::string, std::vector<Repair>> included_repairs;  // by file
  std::vector<Repair> top;
  for (Repair& r : *repairs) {
    const std::string file = FileOfLink(input.read.models, r.link, r.link_line);
    if (file.empty() || file == input.name) {
      top.push_back(std::move(r));
    } else {
      included_repairs[file].push_back(std::move(r));
    }
  }
  *repairs = std::move(top);
  return included_repairs;
}

// What repairing the included models' files gave.
struct IncludedFixes {
  int applied = 0;
  int skipped = 0;
  std::vector<std::pair<std::string, std::string>> outputs;  // file, patched text
  std::vector<Finding> remaining;  // errors left in the repaired included files
};

// Patches one included model's file with its repairs, checks that it reads back and collects
// the errors left in it; returns false (with the reason printed) when it cannot be read or the
// result does not read back.
bool FixIncludedFile(const std::string& file, const std::vector<Repair>& file_repairs,
                     const FixInput& input, const FixSetup& setup, IncludedFixes* fixes) {
  std::string included_text;
  if (std::optional<ReadError> error = ReadInputFile(file, kMaxModelFileBytes, &included_text)) {
    std::cerr << error->ToString() << "\n";
    return false;
  }
  PatchOptions patch_options;
  patch_options.included = true;
  const PatchResult included =
      PatchModelText(included_text, Model::Format::kSdf, file_repairs, patch_options);
  for (const PatchError& e : included.errors) {
    std::cerr << file << ":" << e.line << ": link '" << e.link
              << "': the repair cannot be written: " << e.message << "\n";
  }
  const ReadResult reread_included = ReadModelString(included.text, file, input.read_options);
  if (!reread_included.ok()) {
    std::cerr << "massprops: internal error: the repaired " << file
              << " does not read back; nothing written:\n";
    for (const ReadError& e : reread_included.errors) std::cerr << "  " << e.ToString() << "\n";
    return false;
  }
  fixes->applied += included.applied;
  if (included.text != included_text) fixes->outputs.emplace_back(file, included.text);
  for (const Model& model : reread_included.models) {
    for (const Finding& f : CheckModel(model, setup.check)) {
      if (f.severity == Severity::kError) fixes->remaining.push_back(f);
    }
  }
  return true;
}

// Repairs the included models' files with --include-files (kept in memory until written), or
// names each of their repairs as not applied; returns false when one of them fails.
bool FixIncludedFiles(const FixArgs& args, const FixInput& input, const FixSetup& setup,
                      const std::map<std::string, std::vector<Repair>>& included_repairs,
                      IncludedFixes* fixes) {
  for (const auto& [file, file_repairs] : included_repairs) {
    if (!args.include_files) {
      for (const Repair& r : file_repairs) {
        ++fixes->skipped;
        std::cerr << file << ":" << r.link_line << ": "
                  << LinkHeadline(r.link, ": not repaired: it is defined in an included model")
                  << " [" << r.rule << "]\n  = help: fix that file, or massprops fix "
                  << "--include-files FILE repairs it there\n";
      }
      continue;
    }
    if (!FixIncludedFile(file, file_repairs, input, setup, fixes)) return false;
  }
  return true;
}

// Checks the links named by --from-geometry: an unknown one is an error (returns false); one
// that got no repair is named with the reason, rather than changed nothing silently.
bool ExplainFromGeometryLinks(const FixArgs& args, const FixInput& input, const FixSetup& setup,
                              const RepairPlan& plan) {
  for (const std::string& link : args.from_geometry_links) {
    if (std::find(plan.known_links.begin(), plan.known_links.end(), link) ==
        plan.known_links.end()) {
      std::cerr << "massprops: error: --from-geometry: " << input.name << " has no link '" << link
                << "'\n";
      return false;
    }
    const bool repaired = std::any_of(plan.repairs.begin(), plan.repairs.end(),
                                      [&](const Repair& r) { return r.link == link; });
    // A repair planned and refused is said where the refusals are (its reason and the ways
    // forward), not as "left as it is".
    const bool refused = std::any_of(plan.refused.begin(), plan.refused.end(),
                                     [&](const RefusedRepair& r) { return r.link == link; });
    if (repaired || refused) continue;
    for (const Model& model : input.read.models) {
      const int index = model.FindLink(link);
      if (index < 0) continue;
      std::string why;
      if (CalcLinkGeometryInertia(model.links[index], 1.0, setup.resolve, &why)) {
        why = "its geometry gives the inertial it already has";
      }
      std::cerr << "massprops: warning: --from-geometry: link '" << link
                << "' is left as it is: " << why << "\n";
    }
  }
  return true;
}

// Lists the errors left (they have no repair) and returns their number. When included files are
// repaired in place the top-level model is judged again after they are written (its welded groups
// use them): `includes_written` says whether that is `final_read`. Error-level reader findings
// (urdf-not-loadable, inertial-unreadable, ...) count: fix cannot repair them, so the file is not
// clean.
int ListRemainingErrors(const ReadResult& final_read, bool includes_written,
                        const IncludedFixes& included, const FixSetup& setup,
                        const std::string& text, const RepairPlan& plan) {
  auto rewritten = [&](const std::string& file) {
    return std::any_of(included.outputs.begin(), included.outputs.end(),
                       [&](const auto& output) { return output.first == file; });
  };
  std::vector<Finding> remaining = includes_written ? std::vector<Finding>{} : included.remaining;
  for (const Finding& f : ReaderFindings(final_read, setup.check)) {
    if (f.severity == Severity::kError) remaining.push_back(f);
  }
  for (const Model& model : final_read.models) {
    std::vector<Finding> found = CheckModel(model, setup.check);
    AddTargetFindings(model, setup.target, setup.check, setup.mujoco, &found, text);
    for (const Finding& f : found) {
      // Without the written includes, a file being repaired is judged on its repaired text.
      if (f.severity != Severity::kError) continue;
      if (!includes_written && rewritten(f.location.file)) continue;
      remaining.push_back(f);
    }
  }
  for (const Finding& f : remaining) {
    std::cerr << FindingHeadlineLine(f) << " (no repair)\n";
    // The ways forward, unless its refused repair said them already.
    const bool refused = std::any_of(plan.refused.begin(), plan.refused.end(),
                                     [&](const RefusedRepair& r) { return r.link == f.link; });
    const auto routes = plan.routes.find(f.link);
    if (refused || routes == plan.routes.end()) continue;
    for (const std::string& line : RouteHelpLines(routes->second, f.link, f.location.file)) {
      std::cerr << line << "\n";
    }
  }
  return static_cast<int>(remaining.size());
}

// --dry-run: prints each repair that would be written (at its first changed line), then the
// heuristic ones not asked for.
void PrintDryRun(const std::string& name, const RepairPlan& plan, const PatchResult& patched,
                 bool changed) {
  const std::vector<Repair>& repairs = plan.repairs;
  std::vector<bool> failed(repairs.size(), false);
  for (std::size_t i = 0; i < repairs.size(); ++i) {
    for (const PatchError& e : patched.errors) {
      if (e.link == repairs[i].link && e.line == repairs[i].link_line) failed[i] = true;
    }
    if (failed[i]) continue;
    const Repair& r = repairs[i];
    int line = r.link_line;  // the first change that has a line (an inserted one has none)
    for (const FieldChange& change : r.changes) {
      if (change.line > 0) {
        line = change.line;
        break;
      }
    }
    std::cout << name << ":" << line << ": " << DescribeRepair(r) << "\n";
    const auto routes = plan.routes.find(r.link);
    if (routes != plan.routes.end()) std::cout << RenderRouteChoices(routes->second, r.link, name);
  }
  for (const auto& [rule, list] : plan.not_asked) {
    for (const Repair& r : list) {
      std::cout << name << ":" << r.link_line << ": not applied (a guess): " << DescribeRepair(r)
                << "\n  = help: --apply " << rule << " applies it\n";
      const auto routes = plan.routes.find(r.link);
      if (routes != plan.routes.end()) {
        std::cout << RenderRouteChoices(routes->second, r.link, name);
      }
    }
  }
  if (!changed) std::cout << name << ": no change needed\n";
}

// --diff: the unified diff of FILE, then of each included file to be rewritten.
void PrintDiffs(const FixArgs& args, const FixInput& input, const PatchResult& patched,
                const IncludedFixes& included) {
  std::cout << UnifiedDiff(input.text, patched.text, args.file);
  for (const auto& [file, included_text] : included.outputs) {
    std::string before;
    ReadInputFile(file, kMaxModelFileBytes, &before);
    std::cout << UnifiedDiff(before, included_text, file);
  }
}

// Writes the repaired FILE where the command line says (in place, -o OUT, or standard output),
// then the repaired included files in place; returns false (with the reason printed) when a write
// fails.
bool WriteFixOutputs(const FixArgs& args, const FixInput& input, const PatchResult& patched,
                     bool changed, const IncludedFixes& included, std::vector<std::string>* notes) {
  if (args.in_place) {
    if (changed) {
      if (!args.backup.empty()) {
        if (auto error = WriteFileSafely(args.file + args.backup, input.text, notes)) {
          std::cerr << "massprops: error: " << *error << "; nothing written\n";
          return false;
        }
      }
      if (auto error = WriteFileSafely(args.file, patched.text, notes)) {
        std::cerr << "massprops: error: " << *error << "; " << args.file << " is unchanged\n";
        return false;
      }
    }
  } else if (!args.output.empty() && args.output != "-") {
    std::error_code ec;
    if (!changed && args.file != "-" && fs::equivalent(args.output, args.file, ec)) {
      // -o FILE naming the input itself: a file that needs no change is not rewritten.
    } else if (auto error = WriteFileSafely(args.output, patched.text, notes)) {
      std::cerr << "massprops: error: " << *error << "; nothing written\n";
      return false;
    }
  } else if (!args.diff || args.output == "-") {
    std::cout << patched.text;
  }
  // Included models are always repaired in place (they are other files than FILE).
  for (const auto& [file, included_text] : included.outputs) {
    if (auto error = WriteFileSafely(file, included_text, notes)) {
      std::cerr << "massprops: error: " << *error << "; " << file << " is unchanged\n";
      return false;
    }
    std::cerr << "massprops: " << file << ": repaired (an included model)\n";
  }
  return true;
}

// The effect of the repairs on the whole robot (fix_effect.h), for the mass repairs or
// --format json: JSON on standard output; text on standard output with --dry-run, else on
// standard error (standard output may carry the file or its diff).
void PrintFixEffect(const FixArgs& args, const FixInput& input, const FixSetup& setup,
                    const RepairPlan& plan, const ReadResult& reread, bool changed) {
  const bool json = args.format == "json";
  if (!json && !args.mass.any()) return;
  // A mass asked for by name is written even when the result draws a warning the file did not
  // have (e.g. density-implausible for a total no material reaches): the engineer's number wins,
  // and this says so.
  if (args.mass.any()) {
    for (std::size_t i = 0; i < input.read.models.size() && i < reread.models.size(); ++i) {
      std::set<std::pair<std::string, std::string>> before;
      for (const Finding& f : CheckModel(input.read.models[i], setup.check)) {
        before.insert({f.link, f.rule});
      }
      for (const Finding& f : CheckModel(reread.models[i], setup.check)) {
        if (f.severity == Severity::kNote || before.count({f.link, f.rule})) continue;
        std::cerr << FindingHeadlineLine(f) << " (after the repairs asked for)\n";
      }
    }
  }
  std::vector<std::string> changed_links;
  for (const Repair& r : plan.repairs) changed_links.push_back(r.link);
  std::vector<FixEffect> effects;
  for (std::size_t i = 0; i < input.read.models.size() && i < reread.models.size(); ++i) {
    FixEffect effect;
    std::string error;
    if (!CalcFixEffect(input.read.models[i], reread.models[i], changed_links, &effect, &error)) {
      std::cerr << "massprops: warning: the effect of the fix cannot be computed: " << error
                << "\n";
      continue;
    }
    effects.push_back(std::move(effect));
  }
  if (json) {
    std::cout << RenderFixJson(input.name, changed, plan.repairs, effects);
    return;
  }
  std::ostream& out = args.dry_run ? std::cout : std::cerr;
  for (const FixEffect& effect : effects) out << RenderFixEffectText(effect);
}

// The closing line on standard error: how many links were repaired, and what was not.
void PrintFixSummary(const FixArgs& args, const std::string& name, const RepairPlan& plan,
                     const PatchResult& patched, bool changed, const IncludedFixes& included,
                     int remaining_errors) {
  std::cerr << "massprops: " << name << ": " << patched.applied + included.applied
            << " link(s) repaired"
            << (changed || !included.outputs.empty() ? "" : ", no change needed");
  if (!patched.errors.empty()) {
    std::cerr << "; " << patched.errors.size() << " repair(s) could not be written";
  }
  if (included.skipped > 0) {
    std::cerr << "; " << included.skipped << " repair(s) of included models not applied";
  }
  if (remaining_errors > 0) std::cerr << "; " << remaining_errors << " error(s) have no repair";
  if (!plan.refused.empty()) std::cerr << "; " << plan.refused.size() << " repair(s) refused";
  std::cerr << "\n";
  if (!plan.not_asked.empty() && !args.dry_run) {
    std::string list = "heuristic repairs not applied (guesses; --dry-run shows them):";
    for (const auto& [rule, repairs] : plan.not_asked) {
      list += " " + rule + " ×" + std::to_string(repairs.size());
    }
    const std::vector<std::string> lines = WrapWords(list, kMaxDetailChars - 10);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      std::cerr << (i ? "    " : "  = note: ") << lines[i] << "\n";
    }
    std::cerr << "  = help: massprops fix --apply RULE,... FILE applies them\n";
  }
}

// Writes the repaired files (or prints the --dry-run plan) and lists the errors left; returns the
// exit code.
int FinishFix(const FixArgs& args, const FixInput& input, const FixSetup& setup,
              const RepairPlan& plan, const PatchResult& patched, const ReadResult& reread,
              const IncludedFixes& included) {
  const bool changed = patched.text != input.text;
  for (const RefusedRepair& r : plan.refused) {
    const auto severity = plan.severity.find({r.link, r.rule});
    const auto routes = plan.routes.find(r.link);
    std::cerr << RenderFixMessage(RefusedRepairMessage(
        r, severity == plan.severity.end() ? Severity::kError : severity->second, input.name,
        routes == plan.routes.end() ? std::vector<RepairRoute>{} : routes->second));
  }
  int remaining_errors = 0;
  if (args.dry_run || included.outputs.empty()) {
    remaining_errors = ListRemainingErrors(reread, false, included, setup, input.text, plan);
  }
  const bool json = args.format == "json";
  if (args.dry_run && !json) {
    PrintDryRun(input.name, plan, patched, changed);
  } else if (!args.dry_run) {
    if (args.diff) PrintDiffs(args, input, patched, included);
    std::vector<std::string> notes;
    if (!WriteFixOutputs(args, input, patched, changed, included, &notes)) return kExitError;
    if (!included.outputs.empty()) {
      remaining_errors =
          ListRemainingErrors(ReadModelString(patched.text, input.name, input.read_options), true,
                              included, setup, input.text, plan);
    }
    for (const std::string& note : notes) std::cerr << "massprops: note: " << note << "\n";
  }
  PrintFixEffect(args, input, setup, plan, reread, changed);
  std::cout.flush();
  PrintFixSummary(args, input.name, plan, patched, changed, included, remaining_errors);
  return remaining_errors > 0 ? kExitErrorsRemain : kExitOk;
}

int RunFix(const FixArgs& given) {
  if (!CheckFixArgs(given)) return kExitError;
  // A xacro package: the repairs are planned on its expansion and written into its sources.
  FixArgs args = given;
  std::optional<XacroRun> xacro;
  if (IsXacroRun(given.xacro, given.file)) {
    if (!given.output.empty()) {
      std::cerr << "massprops: error: a xacro package is repaired in its sources: use --in-place "
                   "or --dry-run, not -o\n";
      return kExitError;
    }
    std::string error;
    xacro = StartXacroRun(given.xacro, given.file, &error);
    if (!xacro) {
      std::cerr << "massprops: error: " << error << "\n";
      return kExitError;
    }
    args.file = xacro->checked_file;
    args.in_place = args.dry_run = args.diff = false;
  }
  FixInput input;
  const bool read = ReadFixInput(args, &input);
  if (xacro && xacro->temporary) std::remove(xacro->checked_file.c_str());
  if (!read) return kExitError;
  FixSetup setup;
  if (!ConfigureFix(args, input.text, &setup)) return kExitError;
  PrintReaderFindings(input.read, setup.check);

  RepairPlan plan;
  if (!PlanFix(input.read, setup, args.mass, args.dry_run, &plan)) return kExitError;
  const std::map<std::string, std::vector<Repair>> included_repairs =
      TakeIncludedRepairs(input, &plan.repairs);
  IncludedFixes included;
  if (!FixIncludedFiles(args, input, setup, included_repairs, &included)) return kExitError;
  if (!ExplainFromGeometryLinks(args, input, setup, plan)) return kExitError;
  const PatchResult patched =
      PatchModelText(input.text, input.read.models.front().format, plan.repairs);
  for (const PatchError& e : patched.errors) {
    std::cerr << input.name << ":" << e.line << ": link '" << e.link
              << "': the repair cannot be written: " << e.message << "\n";
  }

  // Never write something worse: the output must read back, and its remaining errors are listed.
  const ReadResult reread = ReadModelString(patched.text, input.name, input.read_options);
  if (!reread.ok()) {
    std::cerr << "massprops: internal error: the repaired text does not read back; nothing "
                 "written:\n";
    for (const ReadError& e : reread.errors) std::cerr << "  " << e.ToString() << "\n";
    return kExitError;
  }
  if (xacro) {
    XacroFixRequest request;
    request.in_place = given.in_place;
    request.dry_run = given.dry_run;
    request.diff = given.diff;
    request.backup = given.backup;
    return FixXacroSources(given.xacro, given.file, *xacro, plan.repairs, patched.text, request);
  }
  return FinishFix(args, input, setup, plan, patched, reread, included);
}

}  // namespace

void PrintReaderFindings(const ReadResult& read, const CheckOptions& options) {
  for (const Finding& f : ReaderFindings(read, options)) {
    std::cerr << FindingHeadlineLine(f) << "\n";
  }
  for (const ReadError& w : read.warnings) {  // as `check` prints them
    std::cerr << FindingHeadlineLine(ReadWarningFinding(w)) << "\n";
  }
}

void AddFixCommands(CLI::App& app, std::function<int()>* run) {
  auto args = std::make_shared<FixArgs>();
  CLI::App* fix = app.add_subcommand(
      "fix",
      "Repair the errors that physics decides (an inertia no mass distribution has: the nearest "
      "valid one) and write the file back with only those numbers changed; `fix FILE` never "
      "changes a link that has no error. Guesses (unit mistakes, product signs, inertias about "
      "the origin, masses from geometry) only with --apply RULE,... or --from-geometry. Every "
      "repair is checked again; one that leaves or creates a finding is not written. "
      "Default: the corrected file on standard output.");
  fix->add_option(
      "FILE", args->file,
      "URDF, SDF or MJCF file (detected by content), '-', or a xacro package's top .xacro "
      "file (its sources are repaired: docs/xacro.md)");
  AddXacroOptions(fix, &args->xacro);
  fix->add_flag("--dry-run", args->dry_run,
                "Print what would change (rule, link, old -> new, why); write nothing");
  fix->add_flag("--diff", args->diff, "Print a unified diff of the changes");
  fix->add_option("-o,--output", args->output, "Write the corrected file to OUT ('-': stdout)")
      ->type_name("OUT");
  fix->add_flag("--in-place", args->in_place,
                "Replace FILE (through a temporary file renamed over it when complete; a file "
                "that needs no change is not touched)");
  fix->add_option("--backup", args->backup, "With --in-place: keep the original as FILE+SUFFIX")
      ->type_name("SUFFIX");
  fix->add_option("--repair", args->repair,
                  "inertia-not-physical: project (nearest valid inertia) or balance (principal "
                  "moments set to their mean)")
      ->check(CLI::IsMember({"project", "balance"}))
      ->capture_default_str();
  fix->add_option("--apply", args->apply,
                  "Also apply these heuristic repairs (guesses; by default only errors that "
                  "physics decides are repaired): units-suspect, products-sign-suspect, "
                  "inertia-about-origin-suspect, mass-not-positive, massless-moving-body, "
                  "inertial-missing (the last three from geometry and --density), or all")
      ->type_name("RULE,...")
      ->delimiter(',')
      ->allow_extra_args(false);
  fix->add_flag("--fix-units", args->fix_units,
                "Same as --apply units-suspect, and repair it even when more than one unit "
                "mistake fits");
  fix->add_option("--density", args->density_args,
                  "RHO: kg/m³ for masses computed from geometry (default 1000, water); "
                  "LINK=RHO (repeatable): that link's mass and inertia from its closed mesh at "
                  "that density")
      ->type_name("RHO|LINK=RHO")
      ->allow_extra_args(false);
  fix->add_option("--total-mass", args->total_mass,
                  "The robot weighs KG: every link's mass and inertia scaled by one factor "
                  "(centers of mass unchanged); links named by --mass, --density LINK=, "
                  "--material keep theirs and the others share the rest")
      ->type_name("KG");
  fix->add_option("--mass", args->mass_args,
                  "A part weighs KG (repeatable): that link's mass, its inertia scaled with it")
      ->type_name("LINK=KG")
      ->allow_extra_args(false);
  fix->add_option("--material", args->material_args,
                  "That link's mass and inertia from its closed mesh at the material's density "
                  "(repeatable): " +
                      MaterialNames())
      ->type_name("LINK=NAME")
      ->allow_extra_args(false);
  fix->add_option("--format", args->format,
                  "text (default) or json: what fix says about the repairs and their effect on "
                  "the whole robot (json on standard output: with --dry-run, -o or --in-place)")
      ->check(CLI::IsMember({"text", "json"}));
  fix->add_option("--from-geometry", args->from_geometry_links,
                  "Replace the inertial of these links (all links with usable geometry, meshes "
                  "included, when none is named) with the one of their geometry and current "
                  "mass; put FILE first or write --from-geometry=LINK")
      ->type_name("LINK")
      ->expected(0, -1);
  CLI::Option* geometry =
      fix->add_flag("--geometry", args->geometry,
                    "Judge and repair units, product signs and inertias about the origin against "
                    "mesh geometry too (as check --geometry); meshes are read");
  fix->add_flag("--no-geometry", args->no_geometry,
                "Do not read the meshes' bounding boxes (read by default so that mesh-only links "
                "are judged against their size, as check does)")
      ->excludes(geometry);
  AddPackagePathOption(fix, &args->package_paths);
  AddTargetOption(fix, &args->target);
  fix->add_option("--tolerance", args->tolerance,
                  "Validity tolerance relative to the trace (as check; default 1e-6)");
  fix->add_flag("--include-files", args->include_files,
                "SDF: also repair links of included models (<include>) in their own files, in "
                "place (atomically; without it such a link is named with its file, not repaired)");
  fix->add_option("--model-path", args->model_paths, "Folder searched for SDF model:// URIs")
      ->type_name("DIR")
      ->allow_extra_args(false);
  fix->callback([run, args, fix] {
    args->from_geometry = fix->count("--from-geometry") > 0;
    // CLI11 records `--from-geometry` given without a value as one empty value.
    args->from_geometry_links.erase(
        std::remove(args->from_geometry_links.begin(), args->from_geometry_links.end(), ""),
        args->from_geometry_links.end());
    // `fix --from-geometry robot.urdf`: the option swallowed the FILE.
    if (args->file.empty() && !args->from_geometry_links.empty()) {
      args->file = args->from_geometry_links.back();
      args->from_geometry_links.pop_back();
    }
    *run = [args] {
      if (args->file.empty() && args->xacro.expanded.empty()) {
        std::cerr << "massprops: error: fix needs a FILE\n";
        return kExitError;
      }
      if (!ParseMassOptions(args.get())) return kExitError;
      return RunFix(*args);
    };
  });
}

}  // namespace massprops::cli

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
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "commands.h"
#include "geometry_cli.h"
#include "massprops/analysis/checks.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/analysis/repair.h"
#include "massprops/io/model_reader.h"
#include "massprops/mesh/mesh_loader.h"
#include "massprops/output/reporters.h"
#include "massprops/output/xml_patch.h"
#include "safe_write.h"
#include "target_cli.h"

namespace massprops::cli {
namespace {

namespace fs = std::filesystem;

constexpr int kExitOk = 0;
constexpr int kExitErrorsRemain = 1;
constexpr int kExitError = 2;

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
  bool from_geometry = false;
  std::vector<std::string> from_geometry_links;
  double tolerance = 1e-6;
  std::vector<std::string> model_paths;
  bool geometry = false;
  std::vector<std::string> package_paths;
  std::string target;  // --target ("" = generic)
  bool include_files = false;
};

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

// Prints the reader's findings (unresolved includes, unreadable inertials, ...) as `check` does,
// so that nothing the reader skipped goes unsaid.
void PrintReaderFindings(const ReadResult& read, const CheckOptions& options) {
  for (const Finding& f : ReaderFindings(read, options)) {
    std::cerr << f.location.file << ":" << f.location.line << ": " << ToString(f.severity) << ": "
              << f.message << " [" << f.rule << "]\n";
  }
  for (const ReadError& w : read.warnings) {  // as `check` prints them
    std::cerr << w.location.file << ":" << w.location.line
              << ": warning: " << (w.element.empty() ? w.message : w.element + ": " + w.message)
              << " [" << kReadWarningRule << "]\n";
  }
}

int RunFix(const FixArgs& args) {
  if (args.in_place && !args.output.empty()) {
    std::cerr << "massprops: error: --in-place and -o cannot be combined\n";
    return kExitError;
  }
  if (!args.backup.empty() && !args.in_place) {
    std::cerr << "massprops: error: --backup needs --in-place\n";
    return kExitError;
  }
  if (args.dry_run && (args.in_place || !args.output.empty() || args.diff)) {
    std::cerr << "massprops: error: --dry-run cannot be combined with --diff, -o or --in-place\n";
    return kExitError;
  }
  if (args.in_place && args.file == "-") {
    std::cerr << "massprops: error: --in-place needs a file, not standard input\n";
    return kExitError;
  }
  if (!(args.tolerance >= 0) || !std::isfinite(args.tolerance)) {
    std::cerr << "massprops: error: --tolerance must be a finite number at least 0, got "
              << args.tolerance << "\n";
    return kExitError;
  }
  if (!(args.density > 0) || !std::isfinite(args.density)) {
    std::cerr << "massprops: error: --density must be a positive number of kg/m³\n";
    return kExitError;
  }

  std::string text;
  if (std::optional<ReadError> error = ReadInputFile(args.file, kMaxModelFileBytes, &text)) {
    std::cerr << error->ToString() << "\n";
    return kExitError;
  }
  const std::string name = args.file == "-" ? "<stdin>" : args.file;
  ReadOptions read_options;
  read_options.sdf.model_paths = args.model_paths;
  const ReadResult read = ReadModelString(text, name, read_options);
  if (!read.ok() || read.models.empty()) {
    for (const ReadError& e : read.errors) std::cerr << e.ToString() << "\n";
    if (read.errors.empty()) std::cerr << name << ": no model found\n";
    return kExitError;
  }

  RepairOptions options;
  options.method =
      args.repair == "balance" ? InertiaRepairMethod::kBalance : InertiaRepairMethod::kProject;
  options.fix_units = args.fix_units;
  options.apply = args.apply;
  for (const std::string& rule : args.apply) {
    const std::vector<std::string>& known = HeuristicRepairRules();
    if (rule != "all" && std::find(known.begin(), known.end(), rule) == known.end()) {
      std::cerr << "massprops: error: --apply: '" << rule << "' is not a heuristic repair; one of";
      for (const std::string& k : known) std::cerr << " " << k;
      std::cerr << ", or all\n";
      return kExitError;
    }
  }
  options.density = args.density;
  options.from_geometry_all = args.from_geometry && args.from_geometry_links.empty();
  options.from_geometry_links = args.from_geometry_links;
  options.tolerance = args.tolerance;
  CheckOptions check_options;
  const Target fix_target = args.target.empty() ? Target::kGeneric : *ParseTarget(args.target);
  ApplyTargetProfile(fix_target, &check_options);
  check_options.tolerance = args.tolerance;
  const MujocoCompilerOptions mujoco_options = ReadMujocoCompilerOptions(text);
  // Meshes are read only when asked: --geometry (the checks and repairs use them) or
  // --from-geometry (the inertials it replaces may come from meshes). Each file is read once.
  MeshCache mesh_cache;
  const MeshResolveOptions resolve =
      MakeResolveOptions(args.package_paths, args.model_paths, args.file, &mesh_cache);
  if (args.geometry || args.from_geometry) {
    options.shape = MakeLinkShapeFunction(resolve);
    if (args.geometry) check_options.shape = options.shape;
  }

  PrintReaderFindings(read, check_options);

  std::vector<Repair> repairs;
  std::vector<RefusedRepair> refused;
  std::vector<std::string> known_links;
  // Heuristic repairs that were not asked for, per rule: listed so that nothing is silent.
  std::map<std::string, std::vector<Repair>> not_asked;
  for (const Model& model : read.models) {
    for (const Link& link : model.links) known_links.push_back(link.name);
    const std::vector<Finding> findings = CheckModel(model, check_options);
    std::vector<Repair> planned = PlanRepairs(model, findings, options, &refused);
    if (fix_target != Target::kGeneric) {  // what the simulator needs on top (target_profile.h)
      planned = PlanTargetRepairs(model, fix_target, mujoco_options, planned);
    }
    repairs.insert(repairs.end(), planned.begin(), planned.end());
    RepairOptions every = options;
    every.apply = {"all"};
    for (Repair& r : PlanRepairs(model, findings, every)) {
      const bool planned_already = std::any_of(planned.begin(), planned.end(),
                                               [&](const Repair& p) { return p.link == r.link; });
      if (!planned_already) not_asked[r.rule].push_back(std::move(r));
    }
  }
  // Repairs of links defined in an included SDF model belong to that model's file: written there
  // with --include-files, otherwise named (never applied to an element of the same name here).
  std::map<std::string, std::vector<Repair>> included_repairs;  // by file
  {
    std::vector<Repair> top;
    for (Repair& r : repairs) {
      const std::string file = FileOfLink(read.models, r.link, r.link_line);
      if (file.empty() || file == name) {
        top.push_back(std::move(r));
      } else {
        included_repairs[file].push_back(std::move(r));
      }
    }
    repairs = std::move(top);
  }
  int included_applied = 0;
  int included_skipped = 0;
  std::vector<std::pair<std::string, std::string>> included_outputs;  // file, patched text
  std::vector<Finding> included_remaining;  // errors left in the repaired included files
  for (const auto& [file, file_repairs] : included_repairs) {
    if (!args.include_files) {
      for (const Repair& r : file_repairs) {
        ++included_skipped;
        std::cerr << file << ":" << r.link_line << ": link '" << r.link << "' (" << r.rule
                  << ") is defined in this included model, not in " << name
                  << ": not repaired; fix that file, or run with --include-files\n";
      }
      continue;
    }
    std::string included_text;
    if (std::optional<ReadError> error = ReadInputFile(file, kMaxModelFileBytes, &included_text)) {
      std::cerr << error->ToString() << "\n";
      return kExitError;
    }
    PatchOptions patch_options;
    patch_options.included = true;
    const PatchResult included =
        PatchModelText(included_text, Model::Format::kSdf, file_repairs, patch_options);
    for (const PatchError& e : included.errors) {
      std::cerr << file << ":" << e.line << ": link '" << e.link
                << "': the repair cannot be written: " << e.message << "\n";
    }
    const ReadResult reread_included = ReadModelString(included.text, file, read_options);
    if (!reread_included.ok()) {
      std::cerr << "massprops: internal error: the repaired " << file
                << " does not read back; nothing written:\n";
      for (const ReadError& e : reread_included.errors) std::cerr << "  " << e.ToString() << "\n";
      return kExitError;
    }
    included_applied += included.applied;
    if (included.text != included_text) included_outputs.emplace_back(file, included.text);
    for (const Model& model : reread_included.models) {
      for (const Finding& f : CheckModel(model, check_options)) {
        if (f.severity == Severity::kError) included_remaining.push_back(f);
      }
    }
  }
  for (const std::string& link : args.from_geometry_links) {
    if (std::find(known_links.begin(), known_links.end(), link) == known_links.end()) {
      std::cerr << "massprops: error: --from-geometry: " << name << " has no link '" << link
                << "'\n";
      return kExitError;
    }
    // A named link that got no repair: say why, rather than change nothing silently.
    const bool repaired = std::any_of(repairs.begin(), repairs.end(),
                                      [&](const Repair& r) { return r.link == link; });
    if (repaired) continue;
    for (const Model& model : read.models) {
      const int index = model.FindLink(link);
      if (index < 0) continue;
      std::string why;
      if (CalcLinkGeometryInertia(model.links[index], 1.0, resolve, &why)) {
        why = "its geometry gives the inertial it already has";
      }
      std::cerr << "massprops: warning: --from-geometry: link '" << link
                << "' is left as it is: " << why << "\n";
    }
  }
  const PatchResult patched = PatchModelText(text, read.models.front().format, repairs);
  for (const PatchError& e : patched.errors) {
    std::cerr << name << ":" << e.line << ": link '" << e.link
              << "': the repair cannot be written: " << e.message << "\n";
  }

  // Never write something worse: the output must read back, and its remaining errors are listed.
  const ReadResult reread = ReadModelString(patched.text, name, read_options);
  if (!reread.ok()) {
    std::cerr << "massprops: internal error: the repaired text does not read back; nothing "
                 "written:\n";
    for (const ReadError& e : reread.errors) std::cerr << "  " << e.ToString() << "\n";
    return kExitError;
  }
  // The errors left, listed once the output is final: when included files are repaired in place
  // the top-level model is judged again after they are written (its welded groups use them).
  // Error-level reader findings (urdf-not-loadable, inertial-unreadable, ...) count: fix cannot
  // repair them, so the file is not clean.
  auto list_remaining = [&](const ReadResult& final_read, bool includes_written) {
    auto rewritten = [&](const std::string& file) {
      return std::any_of(included_outputs.begin(), included_outputs.end(),
                         [&](const auto& output) { return output.first == file; });
    };
    std::vector<Finding> remaining = includes_written ? std::vector<Finding>{} : included_remaining;
    for (const Finding& f : ReaderFindings(final_read, check_options)) {
      if (f.severity == Severity::kError) remaining.push_back(f);
    }
    for (const Model& model : final_read.models) {
      std::vector<Finding> found = CheckModel(model, check_options);
      AddTargetFindings(model, fix_target, check_options, mujoco_options, &found, text);
      for (const Finding& f : found) {
        // Without the written includes, a file being repaired is judged on its repaired text.
        if (f.severity != Severity::kError) continue;
        if (!includes_written && rewritten(f.location.file)) continue;
        remaining.push_back(f);
      }
    }
    for (const Finding& f : remaining) {
      std::cerr << f.location.file << ":" << f.location.line
                << ": error: " << ShortenLongWords(f.message) << " [" << f.rule
                << "] (no repair)\n";
    }
    return static_cast<int>(remaining.size());
  };
  const bool changed = patched.text != text;
  for (const RefusedRepair& r : refused) {
    std::cerr << name << ":" << r.link_line << ": link '" << r.link << "' [" << r.rule
              << "]: " << r.why << "\n";
  }

  int remaining_errors = 0;
  if (args.dry_run || included_outputs.empty()) remaining_errors = list_remaining(reread, false);
  if (args.dry_run) {
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
    }
    for (const auto& [rule, list] : not_asked) {
      for (const Repair& r : list) {
        std::cout << name << ":" << r.link_line << ": not applied (a guess; --apply " << rule
                  << " applies it): " << DescribeRepair(r) << "\n";
      }
    }
    if (!changed) std::cout << name << ": no change needed\n";
  } else {
    if (args.diff) {
      std::cout << UnifiedDiff(text, patched.text, args.file);
      for (const auto& [file, included_text] : included_outputs) {
        std::string before;
        ReadInputFile(file, kMaxModelFileBytes, &before);
        std::cout << UnifiedDiff(before, included_text, file);
      }
    }
    std::vector<std::string> notes;
    if (args.in_place) {
      if (changed) {
        if (!args.backup.empty()) {
          if (auto error = WriteFileSafely(args.file + args.backup, text, &notes)) {
            std::cerr << "massprops: error: " << *error << "; nothing written\n";
            return kExitError;
          }
        }
        if (auto error = WriteFileSafely(args.file, patched.text, &notes)) {
          std::cerr << "massprops: error: " << *error << "; " << args.file << " is unchanged\n";
          return kExitError;
        }
      }
    } else if (!args.output.empty() && args.output != "-") {
      std::error_code ec;
      if (!changed && args.file != "-" && fs::equivalent(args.output, args.file, ec)) {
        // -o FILE naming the input itself: a file that needs no change is not rewritten.
      } else if (auto error = WriteFileSafely(args.output, patched.text, &notes)) {
        std::cerr << "massprops: error: " << *error << "; nothing written\n";
        return kExitError;
      }
    } else if (!args.diff || args.output == "-") {
      std::cout << patched.text;
    }
    // Included models are always repaired in place (they are other files than FILE).
    for (const auto& [file, included_text] : included_outputs) {
      if (auto error = WriteFileSafely(file, included_text, &notes)) {
        std::cerr << "massprops: error: " << *error << "; " << file << " is unchanged\n";
        return kExitError;
      }
      std::cerr << "massprops: " << file << ": repaired (an included model)\n";
    }
    if (!included_outputs.empty()) {
      remaining_errors = list_remaining(ReadModelString(patched.text, name, read_options), true);
    }
    for (const std::string& note : notes) std::cerr << "massprops: note: " << note << "\n";
  }
  std::cout.flush();
  std::cerr << "massprops: " << name << ": " << patched.applied + included_applied
            << " link(s) repaired"
            << (changed || !included_outputs.empty() ? "" : ", no change needed");
  if (!patched.errors.empty()) {
    std::cerr << "; " << patched.errors.size() << " repair(s) could not be written";
  }
  if (included_skipped > 0) {
    std::cerr << "; " << included_skipped << " repair(s) of included models not applied";
  }
  if (remaining_errors > 0) std::cerr << "; " << remaining_errors << " error(s) have no repair";
  if (!refused.empty()) std::cerr << "; " << refused.size() << " repair(s) refused";
  if (!not_asked.empty() && !args.dry_run) {
    std::cerr << "; heuristic repairs not applied (see --dry-run):";
    for (const auto& [rule, list] : not_asked) {
      std::cerr << " " << rule << " ×" << list.size();
    }
    std::cerr << " (--apply RULE,... applies them)";
  }
  std::cerr << "\n";
  return remaining_errors > 0 ? kExitErrorsRemain : kExitOk;
}

}  // namespace

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
  fix->add_option("FILE", args->file, "URDF or SDF file (detected by content), or '-'");
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
  fix->add_option("--density", args->density,
                  "kg/m³ for masses computed from geometry (default 1000, water)")
      ->type_name("RHO");
  fix->add_option("--from-geometry", args->from_geometry_links,
                  "Replace the inertial of these links (all links with usable geometry, meshes "
                  "included, when none is named) with the one of their geometry and current "
                  "mass; put FILE first or write --from-geometry=LINK")
      ->type_name("LINK")
      ->expected(0, -1);
  fix->add_flag("--geometry", args->geometry,
                "Judge and repair units, product signs and inertias about the origin against "
                "mesh geometry too (as check --geometry); meshes are read");
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
      if (args->file.empty()) {
        std::cerr << "massprops: error: fix needs a FILE\n";
        return kExitError;
      }
      return RunFix(*args);
    };
  });
}

}  // namespace massprops::cli

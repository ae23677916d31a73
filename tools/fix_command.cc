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
#include "massprops/checks.h"
#include "massprops/geometry_checks.h"
#include "massprops/mesh_loader.h"
#include "massprops/model_reader.h"
#include "massprops/repair.h"
#include "massprops/xml_patch.h"
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
};

// Writes `data` to `path` through a temporary file in the same folder (mkstemp), flushed to disk
// (fsync) and renamed over `path` only when complete. On failure the temporary file is removed,
// `path` is untouched and the error is returned.
std::optional<std::string> WriteAtomically(const fs::path& path, const std::string& data,
                                           std::optional<mode_t> mode) {
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::string name = (dir / ("." + path.filename().string() + ".massprops-XXXXXX")).string();
  std::vector<char> buffer(name.begin(), name.end());
  buffer.push_back('\0');
  const int fd = mkstemp(buffer.data());
  if (fd < 0) return "cannot create a temporary file in " + dir.string() + ": " + strerror(errno);
  const std::string tmp(buffer.data());
  auto fail = [&](const std::string& what) -> std::optional<std::string> {
    const std::string message = what + ": " + strerror(errno);
    ::close(fd);
    ::unlink(tmp.c_str());
    return message;
  };
  std::size_t written = 0;
  while (written < data.size()) {
    const ssize_t n = ::write(fd, data.data() + written, data.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      return fail("cannot write " + tmp);
    }
    written += static_cast<std::size_t>(n);
  }
  if (mode && ::fchmod(fd, *mode) != 0) return fail("cannot set the mode of " + tmp);
  if (::fsync(fd) != 0) return fail("cannot flush " + tmp);
  if (::close(fd) != 0) {
    const std::string message = "cannot close " + tmp + ": " + strerror(errno);
    ::unlink(tmp.c_str());
    return message;
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string message =
        "cannot rename " + tmp + " to " + path.string() + ": " + strerror(errno);
    ::unlink(tmp.c_str());
    return message;
  }
  const int dir_fd = ::open(dir.c_str(), O_RDONLY);  // Make the rename durable (best effort).
  if (dir_fd >= 0) {
    ::fsync(dir_fd);
    ::close(dir_fd);
  }
  return std::nullopt;
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
  int remaining_errors = 0;
  for (const Model& model : reread.models) {
    std::vector<Finding> remaining = CheckModel(model, check_options);
    AddTargetFindings(model, fix_target, check_options, mujoco_options, &remaining, text);
    for (const Finding& f : remaining) {
      if (f.severity != Severity::kError) continue;
      ++remaining_errors;
      std::cerr << f.location.file << ":" << f.location.line << ": error: " << f.message << " ["
                << f.rule << "] (no repair)\n";
    }
  }
  const bool changed = patched.text != text;
  for (const RefusedRepair& r : refused) {
    std::cerr << name << ":" << r.link_line << ": link '" << r.link << "' [" << r.rule
              << "]: " << r.why << "\n";
  }

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
    if (args.diff) std::cout << UnifiedDiff(text, patched.text, args.file);
    if (args.in_place) {
      if (changed) {
        std::error_code ec;
        fs::path target = args.file;
        if (fs::is_symlink(target, ec)) target = fs::canonical(target, ec);
        struct stat st {};
        std::optional<mode_t> mode;
        if (::stat(target.c_str(), &st) == 0) mode = st.st_mode & 07777;
        if (!args.backup.empty()) {
          if (auto error = WriteAtomically(target.string() + args.backup, text, mode)) {
            std::cerr << "massprops: error: " << *error << "; nothing written\n";
            return kExitError;
          }
        }
        if (auto error = WriteAtomically(target, patched.text, mode)) {
          std::cerr << "massprops: error: " << *error << "; " << args.file << " is unchanged\n";
          return kExitError;
        }
      }
    } else if (!args.output.empty() && args.output != "-") {
      std::error_code ec;
      if (!changed && args.file != "-" && fs::equivalent(args.output, args.file, ec)) {
        // -o FILE naming the input itself: a file that needs no change is not rewritten.
      } else if (auto error = WriteAtomically(args.output, patched.text, std::nullopt)) {
        std::cerr << "massprops: error: " << *error << "\n";
        return kExitError;
      }
    } else if (!args.diff || args.output == "-") {
      std::cout << patched.text;
    }
  }
  std::cout.flush();
  std::cerr << "massprops: " << name << ": " << patched.applied << " link(s) repaired"
            << (changed ? "" : ", no change needed");
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

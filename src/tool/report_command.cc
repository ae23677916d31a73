// `massprops report` and `massprops merge-fixed` (see docs/report.md). Exit codes:
//   0  every file was reported (or merged);
//   2  a file could not be read or parsed, an option names a joint or link a model does not have,
//      or the command line is wrong (the other files are still reported).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "commands.h"
#include "geometry_cli.h"
#include "input_size_cli.h"
#include "massprops/analysis/checks.h"
#include "massprops/analysis/mass_report.h"
#include "massprops/io/model_reader.h"
#include "massprops/mesh/mesh_loader.h"
#include "massprops/output/merge_fixed.h"
#include "massprops/output/report_format.h"
#include "massprops/output/reporters.h"
#include "safe_write.h"
#include "target_cli.h"

namespace massprops::cli {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitError = 2;

struct ReportArgs {
  std::vector<std::string> files;
  std::string format = "text";
  std::vector<std::string> joints;
  std::string frame;
  std::vector<std::string> only;
  std::string subtree;
  std::vector<std::string> model_paths;
  bool geometry = false;
  std::vector<std::string> package_paths;
  std::string target;                                // --target ("" = generic)
  std::size_t max_input_bytes = kMaxModelFileBytes;  // --max-input-size
};

// `report --target`: the bodies as the simulator sees them (text format).
void WriteTargetBodies(std::ostream& out, const Model& model, Target target,
                       const std::string& text) {
  char line[512];
  if (target == Target::kMujoco) {
    const MujocoPrediction p = PredictMujoco(model, ReadMujocoCompilerOptions(text));
    out << "\nBodies as MuJoCo 2.2.2 compiles " << model.name
        << " (fusestatic; principal moments as its eigen-solver gives them):\n";
    for (const MujocoBody& b : p.bodies) {
      std::snprintf(line, sizeof(line), "  %-32s %s mass %-12.6g moments %.6g, %.6g, %.6g",
                    b.name.c_str(), b.moving ? "moving" : "static", b.mass, b.inertia[0],
                    b.inertia[1], b.inertia[2]);
      out << line;
      if (!b.fused_links.empty()) {
        out << "  (fused:";
        for (int l : b.fused_links) out << " " << model.links[l].name;
        out << ")";
      }
      out << "\n";
    }
    if (p.accepted()) {
      out << "  MuJoCo accepts the mass properties.\n";
    } else {
      const MujocoError& e = p.errors.front();
      out << "  MuJoCo refuses: " << e.message << (e.body.empty() ? "" : " (body '" + e.body + "')")
          << "\n";
    }
    for (const std::string& why : p.unsupported) out << "  not predicted: " << why << "\n";
  } else if (target == Target::kGazebo) {
    out << "\nBodies as Gazebo simulates " << model.name
        << " (fixed joints lumped unless preserved):\n";
    for (const GazeboBody& b : GazeboBodies(model, text)) {
      std::snprintf(line, sizeof(line), "  %-32s mass %-12.6g com (%.6g, %.6g, %.6g)",
                    b.name.c_str(), b.inertia.mass, b.inertia.p_RoScm_R.x(),
                    b.inertia.p_RoScm_R.y(), b.inertia.p_RoScm_R.z());
      out << line;
      if (b.links.size() > 1) {
        out << "  (lumped:";
        for (std::size_t i = 1; i < b.links.size(); ++i) out << " " << model.links[b.links[i]].name;
        out << ")";
      }
      out << "\n";
    }
  } else if (target == Target::kDrake) {
    out << "\nDrake keeps every link of " << model.name
        << " as a body (fixed joints become welds); see the per-link report above.\n";
  }
}

struct MergeArgs {
  std::string input;
  std::string output;
  std::string target = "generic";  // --target (the command line only)
};

// Parses "NAME=VALUE" with a finite VALUE; false on anything else.
bool ParseJointValue(const std::string& spec, std::string* name, double* value) {
  const std::size_t eq = spec.rfind('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size()) return false;
  *name = spec.substr(0, eq);
  const std::string text = spec.substr(eq + 1);
  char* end = nullptr;
  *value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(*value);
}

// Fills `options` from --joint, --frame, --only and --subtree; prints the reason and returns
// false when they are wrong.
bool ReadReportOptions(const ReportArgs& args, MassReportOptions* options) {
  for (const std::string& spec : args.joints) {
    std::string name;
    double value = 0;
    if (!ParseJointValue(spec, &name, &value)) {
      std::cerr << "massprops: error: --joint expects NAME=VALUE with a finite number, got '"
                << spec << "'\n";
      return false;
    }
    options->joint_values[name] = value;
  }
  options->frame = args.frame;
  options->only = args.only;
  options->subtree = args.subtree;
  if (!options->only.empty() && !options->subtree.empty()) {
    std::cerr << "massprops: error: --only and --subtree cannot be combined\n";
    return false;
  }
  return true;
}

// Reads one file and appends the report of each of its models to *reports, and what went wrong
// to *errors; the reader's findings and warnings go to standard error, as `check` says them (the
// numbers leave out what the reader skipped).
// With `targets` (JSON or CSV with a target): also each report's target part, parallel to
// *reports.
void ReportFile(const std::string& file, const ReportArgs& args, const ReadOptions& read_options,
                MassReportOptions options, MeshCache* mesh_cache,
                std::vector<ModelMassReport>* reports, std::vector<MassReportError>* errors,
                Target target, std::vector<ModelTargetReport>* targets) {
  const ReadResult read = ReadModelFile(file, read_options);
  PrintReaderFindings(read, CheckOptions{});
  for (const ReadError& e : read.errors) {
    errors->push_back({e.location.file, e.location.line,
                       e.element.empty() ? e.message : e.element + ": " + e.message});
  }
  // One mesh cache per run; relative mesh paths are relative to this file.
  const MeshResolveOptions geometry = MakeResolveOptions(
      WithConfigPackagePaths(args.package_paths, file), args.model_paths, file, mesh_cache);
  options.geometry = args.geometry ? &geometry : nullptr;
  for (const Model& model : read.models) {
    ModelMassReport report;
    std::string error;
    if (ComputeMassReport(model, options, &report, &error)) {
      reports->push_back(std::move(report));
      if (targets != nullptr) {
        targets->push_back(target == Target::kGeneric
                               ? ModelTargetReport()
                               : MakeTargetReport(model, target, ReadTextForTarget(file)));
      }
    } else {
      errors->push_back({file == "-" ? "<stdin>" : file, 0, error});
    }
  }
}

int RunReport(const ReportArgs& args) {
  if (args.format == "html") {
    // The page is of the zero configuration, every link, in the model frame (docs/view.md).
    if (!args.joints.empty() || !args.frame.empty() || !args.only.empty() ||
        !args.subtree.empty() || args.geometry) {
      std::cerr << "massprops: error: --format html cannot be combined with --joint, --frame, "
                   "--only, --subtree or --geometry\n";
      return kExitError;
    }
    return RunHtmlView(args.files, args.model_paths, args.package_paths);
  }
  MassReportOptions options;
  if (!ReadReportOptions(args, &options)) return kExitError;
  // The target of each file (--target, else its .massprops.toml), before anything is written.
  std::vector<Target> targets;
  for (const std::string& file : args.files) targets.push_back(ResolveTarget(args.target, file));
  const MassReportFormat format = args.format == "json"  ? MassReportFormat::kJson
                                  : args.format == "csv" ? MassReportFormat::kCsv
                                                         : MassReportFormat::kText;
  ReadOptions read_options;
  read_options.sdf.model_paths = args.model_paths;
  read_options.mjcf.mujoco_mesh_inertia = args.target == "mujoco";
  read_options.max_file_bytes = args.max_input_bytes;
  std::vector<ModelMassReport> reports;
  std::vector<MassReportError> errors;
  MeshCache mesh_cache;
  // JSON and CSV carry the target part (report_format.h); the text format adds it below.
  const bool with_targets =
      format != MassReportFormat::kText &&
      std::any_of(targets.begin(), targets.end(), [](Target t) { return t != Target::kGeneric; });
  std::vector<ModelTargetReport> target_reports;
  for (std::size_t i = 0; i < args.files.size(); ++i) {
    ReportFile(args.files[i], args, read_options, options, &mesh_cache, &reports, &errors,
               targets[i], with_targets ? &target_reports : nullptr);
  }
  if (format != MassReportFormat::kJson) {
    for (const MassReportError& e : errors) {
      std::cerr << e.file << (e.line > 0 ? ":" + std::to_string(e.line) : "")
                << ": error: " << e.message << "\n";
    }
  }
  WriteMassReport(std::cout, format, reports, errors, options.digits_lost_threshold,
                  target_reports);
  for (std::size_t i = 0; i < args.files.size() && format == MassReportFormat::kText; ++i) {
    if (targets[i] == Target::kGeneric) continue;
    const std::string text = ReadTextForTarget(args.files[i]);
    const ReadResult read = ReadModelString(text, args.files[i], read_options);
    for (const Model& model : read.models) WriteTargetBodies(std::cout, model, targets[i], text);
  }
  std::cout.flush();
  return errors.empty() ? kExitOk : kExitError;
}

int RunMerge(const MergeArgs& args) {
  const Target target = *ParseTarget(args.target);
  if (target == Target::kMujoco || target == Target::kDrake) {  // a usage error: nothing is read
    std::cerr << "massprops: error: " << MergeFixedJoints("", "", target).errors.front().message
              << "\n";
    return kExitError;
  }
  std::string text;
  if (const auto error = ReadInputFile(args.input, kMaxModelFileBytes, &text)) {
    std::cerr << error->ToString() << "\n";
    return kExitError;
  }
  const MergeFixedResult merged =
      MergeFixedJoints(text, args.input == "-" ? "<stdin>" : args.input, target);
  if (!merged.errors.empty()) {
    for (const ReadError& e : merged.errors) std::cerr << e.ToString() << "\n";
    return kExitError;
  }
  if (args.output == "-") {
    std::cout << merged.text;
    std::cout.flush();
  } else {
    // Atomically (a temporary file created exclusively beside it, renamed when complete); a
    // device, FIFO or symbolic link is written through, never replaced (safe_write.h).
    std::vector<std::string> notes;
    if (const auto error = WriteFileSafely(args.output, merged.text, &notes)) {
      std::cerr << "massprops: error: " << *error << "; nothing written\n";
      return kExitError;
    }
    for (const std::string& note : notes) std::cerr << "massprops: note: " << note << "\n";
  }
  for (const std::string& note : merged.notes) std::cerr << "massprops: note: " << note << "\n";
  std::cerr << "massprops: merged " << merged.merged_links << " link(s) into "
            << merged.groups_merged << " welded group root(s)\n";
  return kExitOk;
}

}  // namespace

void AddReportCommands(CLI::App& app, std::function<int()>* run) {
  auto report_args = std::make_shared<ReportArgs>();
  CLI::App* report = app.add_subcommand(
      "report",
      "Report mass, center of mass, inertia about the center of mass, principal moments and axes "
      "and the equivalent box of every link, welded group and the whole model.");
  report
      ->add_option("FILE", report_args->files, "URDF, SDF or MJCF files (detected by content), '-'")
      ->required();
  report->add_option("--format", report_args->format, "Output format")
      ->check(CLI::IsMember({"text", "json", "csv", "html"}))
      ->capture_default_str();
  report
      ->add_option("--joint", report_args->joints,
                   "Joint value, radians or meters (repeatable; other joints at 0)")
      ->type_name("NAME=VALUE")
      ->allow_extra_args(false);
  report
      ->add_option("--frame", report_args->frame,
                   "Express everything in this link's frame (at the joint values)")
      ->type_name("LINK");
  report->add_option("--only", report_args->only, "Report only these links and their welded groups")
      ->type_name("LINK");
  report
      ->add_option("--subtree", report_args->subtree,
                   "Report only this link and its descendants (total in its frame)")
      ->type_name("LINK");
  report
      ->add_option("--model-path", report_args->model_paths,
                   "Folder searched for SDF model:// URIs (repeatable)")
      ->type_name("DIR")
      ->allow_extra_args(false);
  report->add_flag("--geometry", report_args->geometry,
                   "Also give, per link, the inertia its geometry (collision, else visual; "
                   "meshes read) implies for its declared mass, and how the declared one differs");
  AddPackagePathOption(report, &report_args->package_paths);
  AddTargetOption(report, &report_args->target);
  AddMaxInputSizeOption(report, &report_args->max_input_bytes);
  report->callback(
      [run, report_args] { *run = [report_args] { return RunReport(*report_args); }; });

  auto merge_args = std::make_shared<MergeArgs>();
  CLI::App* merge = app.add_subcommand(
      "merge-fixed",
      "Write the model with every welded group (links joined by fixed joints) merged into one "
      "link carrying the composite inertial (URDF or SDF); with --target gazebo, as Gazebo lumps "
      "it.");
  merge->add_option("IN", merge_args->input, "URDF or SDF file, or '-' for standard input")
      ->required();
  merge->add_option("-o,--output", merge_args->output, "Output file, or '-' for standard output")
      ->required();
  merge
      ->add_option(
          "--target", merge_args->target,
          "Merge as this simulator does (docs/targets.md): generic (every fixed joint), "
          "gazebo (as libsdformat lumps: <preserveFixedJoint>/<disableFixedJointLumping> "
          "and joints from a root link named world kept; SDF is not lumped: written unchanged); "
          "mujoco and drake are refused")
      ->check(CLI::IsMember({"generic", "mujoco", "drake", "gazebo"}))
      ->capture_default_str();
  merge->callback([run, merge_args] { *run = [merge_args] { return RunMerge(*merge_args); }; });
}

}  // namespace massprops::cli

// `massprops diff A B` (docs/cli.md): the mass properties of two descriptions of one robot, in
// any of the formats massprops reads (model_diff.h says what is compared and how). Exit codes:
//   0  nothing differs beyond --tolerance;
//   1  something differs (a number beyond the tolerance, a link with mass in one file only);
//   2  a file could not be read, or the command line is wrong.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "commands.h"
#include "massprops/analysis/model_diff.h"
#include "massprops/analysis/target_profile.h"
#include "massprops/io/model_reader.h"
#include "massprops/output/diff_report.h"
#include "massprops/output/reporters.h"
#include "target_cli.h"

namespace massprops::cli {
namespace {

struct DiffArgs {
  std::string a, b;
  std::string format = "text";
  double tolerance = 1e-6;
  std::string target;
  std::vector<std::string> model_paths;
};

std::string Number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

std::string Vector(const Eigen::Vector3d& v) {
  return Number(v[0]) + " " + Number(v[1]) + " " + Number(v[2]);
}

// "mass 1.2 vs 1.3 (8.3%)": the numbers of an entry that differ, or all three when asked.
std::string Describe(const DiffEntry& e, double tolerance, bool all) {
  if (!e.a.present || !e.b.present) {
    const DiffSide& s = e.a.present ? e.a : e.b;
    return std::string("only in ") + (e.a.present ? "A" : "B") + " (" + Number(s.mass) + " kg; " +
           (e.missing_how == "fused" ? "its welded group is in the other file"
                                     : "none of its welded group is in the other file") +
           ")";
  }
  std::string out;
  const auto add = [&](const std::string& part) { out += (out.empty() ? "" : "; ") + part; };
  if (all || !(e.mass_difference <= tolerance)) {
    add("mass " + Number(e.a.mass) + " vs " + Number(e.b.mass) + " kg (relative " +
        Number(e.mass_difference) + ")");
  }
  if (all || !(e.com_difference <= tolerance)) {
    add("center of mass " + Vector(e.a.com) + " vs " + Vector(e.b.com) + " m (relative " +
        Number(e.com_difference) + ")");
  }
  if (all || !(e.inertia_difference <= tolerance)) {
    add("inertia differs by " + Number(e.inertia_difference) + " of its largest moment");
  }
  return out;
}

std::string Title(const DiffEntry& e) {
  if (e.kind == "total") return "whole robot (in the frame of link '" + e.name + "')";
  return (e.kind == "group" ? "welded group '" : "link '") + e.name + "'";
}

void WriteText(const ModelDiff& diff, const Model& a, const Model& b) {
  std::cout << "A: " << a.file << " (" << ToString(a.format) << ", " << a.links.size()
            << " links)\nB: " << b.file << " (" << ToString(b.format) << ", " << b.links.size()
            << " links)\ntolerance " << Number(diff.tolerance) << " (relative)\n\n";
  int differing = 0, compared = 0;
  for (const DiffEntry& e : diff.entries) {
    if (e.kind == "total") continue;
    ++compared;
    if (!e.differs) continue;
    ++differing;
    std::cout << "differs: " << Title(e) << ": " << Describe(e, diff.tolerance, false) << "\n";
  }
  for (const DiffEntry& e : diff.entries) {
    if (e.differs || e.kind == "total" || (e.a.present && e.b.present)) continue;
    std::cout << "note: " << Title(e) << " is massless and " << Describe(e, 0, false) << "\n";
  }
  const DiffEntry& total = diff.entries.back();
  std::cout << (total.differs ? "differs: " : "same: ") << Title(total) << ": "
            << Describe(total, diff.tolerance, true) << "\n\n"
            << differing << " of " << compared << " links and welded groups differ beyond "
            << Number(diff.tolerance) << (total.differs ? "; the whole robot differs" : "") << "\n";
}

void WriteGithub(const ModelDiff& diff) {
  for (const DiffEntry& e : diff.entries) {
    if (!e.differs) continue;
    const DiffSide& where = e.b.present ? e.b : e.a;
    std::cout << "::error file=" << EscapeGithubProperty(where.location.file);
    if (where.location.line > 0) std::cout << ",line=" << where.location.line;
    std::cout << ",title=" << EscapeGithubProperty("massprops diff: " + Title(e))
              << "::" << EscapeGithubData(Describe(e, diff.tolerance, false)) << "\n";
  }
}

int RunDiff(const DiffArgs& args) {
  std::vector<Model> models;
  for (const std::string& file : {args.a, args.b}) {
    ReadOptions options;
    options.sdf.model_paths = args.model_paths;
    options.mjcf.mujoco_mesh_inertia = ResolveTarget(args.target, file) == Target::kMujoco;
    const ReadResult read = ReadModelFile(file, options);
    for (const ReadError& e : read.errors) std::cerr << e.ToString() << "\n";
    if (!read.ok() || read.models.empty()) {
      if (read.ok()) std::cerr << file << ": error: no model in the file\n";
      return 2;
    }
    if (read.models.size() > 1) {
      std::cerr << file << ": note: " << read.models.size() << " models; the first is compared\n";
    }
    models.push_back(read.models[0]);
  }
  const ModelDiff diff = DiffModels(models[0], models[1], args.tolerance);
  if (args.format == "json") {
    std::cout << RenderDiffJson(diff, models[0], models[1]);
  } else if (args.format == "github") {
    WriteGithub(diff);
  } else {
    WriteText(diff, models[0], models[1]);
  }
  std::cout.flush();
  return diff.differs ? 1 : 0;
}

}  // namespace

void AddDiffCommands(CLI::App& app, std::function<int()>* run) {
  auto args = std::make_shared<DiffArgs>();
  CLI::App* diff = app.add_subcommand(
      "diff",
      "Compare the mass properties of two descriptions of one robot (URDF, SDF or MJCF, in any "
      "pair): per link matched by name, per welded group and for the whole robot. Exits 1 when "
      "something differs beyond --tolerance.");
  diff->add_option("A", args->a, "The first model file")->required();
  diff->add_option("B", args->b, "The second model file")->required();
  diff->add_option("--format", args->format, "Output format")
      ->check(CLI::IsMember({"text", "json", "github"}));
  diff->add_option("--tolerance", args->tolerance,
                   "Largest relative difference that counts as equal (default 1e-6)")
      ->check(CLI::NonNegativeNumber);
  diff->add_option("--model-path", args->model_paths, "Folders searched for SDF model:// URIs");
  AddTargetOption(diff, &args->target);
  diff->callback([run, args] { *run = [args] { return RunDiff(*args); }; });
}

}  // namespace massprops::cli

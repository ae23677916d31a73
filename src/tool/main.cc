// The `massprops` command-line tool: `massprops check [options] FILE...` lints the mass properties
// of URDF/SDF robot models. Exit codes (a contract, see docs/cli.md):
//   0  nothing at or above the fail level;
//   1  findings at or above the fail level (--fail-on, default error);
//   2  a file could not be read or parsed (the others are still checked and reported), a
//      configuration file is invalid, or the command line is wrong.
#include <unistd.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <thread>
#include <vector>

#include "check_data.h"
#include "check_pipeline.h"
#include "commands.h"
#include "geometry_cli.h"
#include "input_size_cli.h"
#include "massprops/analysis/checks.h"
#include "massprops/analysis/config.h"
#include "massprops/analysis/target_profile.h"
#include "massprops/io/model_reader.h"
#include "massprops/model/model.h"
#include "massprops/output/reporters.h"
#include "option_filter.h"
#include "safe_write.h"
#include "target_cli.h"
#include "xacro_cli.h"

namespace {

namespace fs = std::filesystem;
using massprops::CheckOptions;
using massprops::Config;
using massprops::ConfigError;
using massprops::FileResult;
using massprops::Finding;
using massprops::ReadError;
using massprops::ReadResult;
using massprops::Severity;

constexpr int kExitClean = 0;
constexpr int kExitFindings = 1;
constexpr int kExitError = 2;  // unreadable input, bad configuration, bad command line

constexpr const char* kExampleName = "two_link_arm.urdf";

struct CheckArgs {
  std::vector<std::string> files;
  std::string format = "text";
  std::string color = "auto";
  std::string fail_on = "error";
  std::vector<std::string> disable;
  std::vector<std::string> severity;
  double tolerance = 0;
  bool tolerance_given = false;
  std::string config;
  std::vector<std::string> model_paths;
  std::string data;  // --data LOG (check_data.h)
  bool quiet = false;
  bool brief = false;       // --brief: headlines only
  bool explain = false;     // --explain: the full reasoning under each finding
  bool statistics = false;  // --statistics: counts per rule
  bool list_rules = false;
  int jobs = 0;                                                 // 0: one per core
  std::size_t max_input_bytes = massprops::kMaxModelFileBytes;  // --max-input-size
  std::string target;                                           // --target; "" when not given
  massprops::cli::XacroOptions xacro;                           // a xacro package (docs/xacro.md)
};

// A command-line mistake found after CLI11 has parsed the arguments.
struct UsageError {
  std::string message;
};

// The folder holding the running executable ("" when it cannot be found).
fs::path ExecutableDir(const char* argv0) {
  std::error_code ec;
  fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec || self.empty()) {
    if (argv0 == nullptr || std::string(argv0).find('/') == std::string::npos) return {};
    self = fs::absolute(argv0, ec);
    if (ec) return {};
  }
  return self.parent_path();
}

// The bundled example model: next to the source tree of a build directory, or installed.
std::optional<std::string> FindBundledExample(const char* argv0) {
  std::vector<fs::path> candidates;
#ifdef MASSPROPS_EXAMPLES_DIR
  candidates.push_back(fs::path(MASSPROPS_EXAMPLES_DIR) / kExampleName);
#endif
  const fs::path dir = ExecutableDir(argv0);
  if (!dir.empty()) {
    candidates.push_back(dir / ".." / "examples" / kExampleName);         // <src>/build/massprops
    candidates.push_back(dir / ".." / ".." / "examples" / kExampleName);  // <src>/build/x/massprops
    candidates.push_back(dir / ".." / "share" / "massprops" / "examples" / kExampleName);
  }
  for (const fs::path& candidate : candidates) {
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec)) return candidate.lexically_normal().string();
  }
  return std::nullopt;
}

// Whether the file's content starts with a <robot> or <sdf> root element (first 64 KiB).
bool LooksLikeModel(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::string text(64 * 1024, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return massprops::DetectModelFormat(text).has_value();
}

// Whether a subfolder met while collecting can be listed; when it cannot (no permission, an I/O
// error), it is named on standard error, even with --quiet (its files are not checked), and
// counted in *skipped.
bool CanListSubfolder(const fs::path& dir, int* skipped) {
  std::error_code ec;
  fs::directory_iterator probe(dir, ec);
  if (!ec) return true;
  std::cerr << "massprops: warning: cannot read the folder " << dir.string() << ": " << ec.message()
            << "; its files are skipped\n";
  ++*skipped;
  return false;
}

// Files of a directory tree that look like robot models, sorted. *.urdf and *.sdf are always
// taken; *.world and *.xml only when their root element is <robot>, <sdf> or <mujoco>. Hidden
// folders are skipped; symbolic links to folders are not followed. Extensions are matched
// case-insensitively (.URDF, .Sdf). Every other regular file (outside hidden folders) and every
// subfolder that cannot be listed is counted in *skipped.
std::vector<std::string> CollectModelFiles(const fs::path& dir, int* skipped) {
  std::vector<std::string> files;
  std::error_code ec;
  // skip_permission_denied stays as a safety net: every subfolder is probed before the iterator
  // enters it (CanListSubfolder), so none is skipped without a word.
  fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec);
  for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    const fs::path& path = it->path();
    const std::string name = path.filename().string();
    std::error_code type_ec;
    if (it->is_directory(type_ec)) {
      const bool hidden = !name.empty() && name[0] == '.';
      if (hidden || (!it->is_symlink(type_ec) && !CanListSubfolder(path, skipped))) {
        it.disable_recursion_pending();
      }
      continue;
    }
    if (!it->is_regular_file(type_ec)) continue;
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".urdf" || ext == ".sdf") {
      files.push_back(path.string());
    } else if ((ext == ".world" || ext == ".xml") && LooksLikeModel(path)) {
      files.push_back(path.string());
    } else {
      ++*skipped;
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Parses "RULE=LEVEL" (LEVEL: off|note|warning|error) into `overrides`.
void AddOverride(const std::string& rule, const std::string& level_text,
                 std::map<std::string, std::optional<Severity>>& overrides) {
  bool known = false;
  for (const massprops::RuleInfo& info : massprops::AllRules()) known |= info.id == rule;
  if (!known) {
    throw UsageError{"unknown rule '" + rule + "' (massprops check --list-rules lists them)"};
  }
  if (level_text == "off") {
    overrides[rule] = std::nullopt;
    return;
  }
  const std::optional<Severity> level = massprops::ParseSeverity(level_text);
  if (!level) {
    throw UsageError{"--severity " + rule + "=" + level_text +
                     ": the level must be off, note, warning or error"};
  }
  overrides[rule] = level;
}

int ListRules(const CheckArgs& args) {
  const auto& rules = massprops::AllRules();
  if (args.format == "json") {
    nlohmann::json out = nlohmann::json::array();
    for (const massprops::RuleInfo& rule : rules) {
      out.push_back({{"id", rule.id},
                     {"severity", massprops::ToString(rule.default_severity)},
                     {"enabled", rule.enabled_by_default},
                     {"summary", rule.summary}});
    }
    std::cout << out.dump(2) << "\n";
    return kExitClean;
  }
  std::size_t width = 0;
  for (const massprops::RuleInfo& rule : rules) width = std::max(width, rule.id.size());
  for (const massprops::RuleInfo& rule : rules) {
    std::string line = std::string(rule.id) + std::string(width + 2 - rule.id.size(), ' ');
    std::string severity = massprops::ToString(rule.default_severity);
    if (!rule.enabled_by_default) severity += " (off)";
    line += severity + std::string(severity.size() < 15 ? 15 - severity.size() : 1, ' ');
    std::cout << line << rule.summary << "\n";
  }
  return kExitClean;
}

// Per-folder configuration lookup, each file read once.
class ConfigCache {
 public:
  // The configuration that applies to `file` (massprops::FindConfigFor); nullptr when there is
  // none. Throws ConfigError.
  const Config* ForFile(const std::string& file) {
    const std::optional<std::string> path = massprops::FindConfigFor(file);
    if (!path) return nullptr;
    auto it = configs_.find(*path);
    if (it == configs_.end()) it = configs_.emplace(*path, massprops::LoadConfig(*path)).first;
    return &it->second;
  }

 private:
  std::map<std::string, Config> configs_;
};

// How many threads check files: --jobs, or one per core (at least 1), never more than the files;
// one for standard input, which is read once, in order.
std::size_t JobCount(int jobs, const std::vector<std::string>& files) {
  if (files.size() <= 1) return 1;  // without asking the system for its cores
  std::size_t n = jobs > 0 ? static_cast<std::size_t>(jobs) : std::thread::hardware_concurrency();
  n = std::max<std::size_t>(1, std::min(n, files.size()));
  if (std::find(files.begin(), files.end(), "-") != files.end()) n = 1;
  return n;
}

// Calls work(i) for every i < count on `threads` threads (the calling one included), each taking
// the next index as it finishes one. work(i) must touch only its own slot i of shared state. An
// exception thrown by work is rethrown here after every index has been worked on (the one of the
// lowest index, so that the same one is seen whatever the thread count).
void RunInParallel(std::size_t count, std::size_t threads,
                   const std::function<void(std::size_t)>& work) {
  std::vector<std::exception_ptr> errors(count);
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < count; i = next++) {
      try {
        work(i);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& thread : pool) thread.join();
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
}

using Settings = massprops::cli::CheckSettings;

// The rule overrides and fail level given on the command line; they win over the configuration.
struct CliOverrides {
  std::map<std::string, std::optional<Severity>> rules;
  std::optional<Severity> fail_on;
};

// Reads --disable, --severity and --fail-on, validated before any file is read. Throws
// UsageError.
CliOverrides ParseCliOverrides(const CheckArgs& args) {
  CliOverrides cli;
  for (const std::string& rule : args.disable) AddOverride(rule, "off", cli.rules);
  for (const std::string& spec : args.severity) {
    const std::size_t eq = spec.find('=');
    if (eq == std::string::npos) {
      throw UsageError{"--severity expects RULE=LEVEL, got '" + spec + "'"};
    }
    AddOverride(spec.substr(0, eq), spec.substr(eq + 1), cli.rules);
  }
  cli.fail_on = args.fail_on.empty() ? std::nullopt : massprops::ParseSeverity(args.fail_on);
  return cli;
}

// The settings of one file: the target profile first, then the configuration (`config`, may be
// null), then the command line, each overriding the one before.
Settings SettingsFor(const CheckArgs& args, const CliOverrides& cli, const Config* config) {
  Settings settings = massprops::cli::MakeCheckSettings(
      args.target.empty() ? std::nullopt : massprops::ParseTarget(args.target), config);
  if (args.tolerance_given) settings.options.tolerance = args.tolerance;
  for (const auto& [rule, level] : cli.rules) settings.options.overrides[rule] = level;
  if (cli.fail_on) settings.fail_on = *cli.fail_on;
  settings.model_paths.insert(settings.model_paths.begin(), args.model_paths.begin(),
                              args.model_paths.end());
  settings.max_input_bytes = args.max_input_bytes;
  return settings;
}

// The FILE arguments, or the bundled example when none is given (said on standard error unless
// --quiet). Throws UsageError when the example cannot be found.
std::vector<std::string> InputsOrExample(const CheckArgs& args, const char* argv0) {
  std::vector<std::string> inputs = args.files;
  if (inputs.empty()) {
    const std::optional<std::string> example = FindBundledExample(argv0);
    if (!example) {
      throw UsageError{"no FILE given, and the bundled example " + std::string(kExampleName) +
                       " was not found next to the executable"};
    }
    if (!args.quiet) {
      std::cerr << "massprops: no FILE given; checking the bundled example " << *example << "\n";
    }
    inputs.push_back(*example);
  }
  return inputs;
}

// The files to check, with folders expanded.
struct CheckInputs {
  std::vector<std::string> files;
  int skipped_files = 0;          // files of the folders given that are not models
  bool unreadable_input = false;  // a folder could not be listed
};

// Expands the folders among the inputs into the model files they hold.
CheckInputs ExpandInputs(const CheckArgs& args, const std::vector<std::string>& inputs) {
  CheckInputs expanded;
  for (const std::string& input : inputs) {
    std::error_code ec;
    if (input != "-" && fs::is_directory(input, ec)) {
      // A folder that cannot be listed is an error, not "nothing found" (exit 0).
      std::error_code list_ec;
      fs::directory_iterator probe(input, list_ec);
      if (list_ec) {
        std::cerr << "massprops: error: cannot read the folder " << input << ": "
                  << list_ec.message() << "\n";
        expanded.unreadable_input = true;
        continue;
      }
      const std::vector<std::string> found = CollectModelFiles(input, &expanded.skipped_files);
      if (found.empty() && !args.quiet) {
        std::cerr << "massprops: no URDF or SDF files found in " << input << "\n";
      }
      expanded.files.insert(expanded.files.end(), found.begin(), found.end());
    } else {
      expanded.files.push_back(input);
    }
  }
  return expanded;
}

// The settings of each file. They are all loaded before anything is checked, so a bad
// configuration stops the run before any report is written. Throws ConfigError.
std::vector<Settings> LoadSettings(const CheckArgs& args, const CliOverrides& cli,
                                   const std::optional<Config>& explicit_config,
                                   const std::vector<std::string>& files) {
  ConfigCache config_cache;
  std::vector<Settings> settings;
  for (const std::string& file : files) {
    const Config* config = explicit_config ? &*explicit_config : config_cache.ForFile(file);
    settings.push_back(SettingsFor(args, cli, config));
  }
  return settings;
}

// One file's result; reads only its own settings, so files can be checked in parallel.
FileResult CheckFile(const std::string& file, const Settings& settings) {
  const ReadResult read =
      massprops::ReadModelFile(file, massprops::cli::CheckReadOptions(settings));
  return massprops::cli::CheckReadModels(file, read, settings, nullptr);
}

// The exit code of a check: 2 when an input could not be read, else 1 when a file has a finding
// at or above its fail level, else 0.
int CheckExitCode(const std::vector<FileResult>& results, const std::vector<Settings>& settings,
                  bool unreadable_input) {
  bool read_failed = false;
  bool findings_at_fail_level = false;
  for (std::size_t i = 0; i < results.size(); ++i) {
    if (!results[i].errors.empty()) read_failed = true;
    for (const Finding& finding : results[i].findings) {
      if (finding.severity >= settings[i].fail_on) findings_at_fail_level = true;
    }
  }
  if (read_failed || unreadable_input) return kExitError;
  return findings_at_fail_level ? kExitFindings : kExitClean;
}

// How the report is written: --quiet, the skipped files, and colour (--color; auto: on a
// terminal when NO_COLOR is unset or empty).
massprops::ReportOptions MakeReportOptions(const CheckArgs& args, int skipped_files) {
  massprops::ReportOptions report_options;
  report_options.quiet = args.quiet;
  report_options.brief = args.brief;
  report_options.explain = args.explain;
  report_options.statistics = args.statistics;
  report_options.skipped_files = skipped_files;
  if (args.color == "always") {
    report_options.color = true;
  } else if (args.color == "auto") {
    const char* no_color = std::getenv("NO_COLOR");
    report_options.color =
        isatty(STDOUT_FILENO) != 0 && (no_color == nullptr || no_color[0] == '\0');
  }
  return report_options;
}

// `massprops check`: checks every file and writes the report; returns the exit code. Throws
// UsageError and ConfigError.
int RunCheck(const CheckArgs& args, const char* argv0) {
  if (args.list_rules) return ListRules(args);
  const CliOverrides cli = ParseCliOverrides(args);
  std::optional<Config> explicit_config;
  if (!args.config.empty()) explicit_config = massprops::LoadConfig(args.config);
  // A xacro package (docs/xacro.md): its expansion is checked, and findings traced to the sources.
  const std::string top = args.files.empty() ? "" : args.files.front();
  std::optional<massprops::cli::XacroRun> xacro;
  if (massprops::cli::IsXacroRun(args.xacro, top)) {
    if (args.files.size() > 1) throw UsageError{"check takes one .xacro FILE at a time"};
    std::string error;
    xacro = massprops::cli::StartXacroRun(args.xacro, top, &error);
    if (!xacro) throw UsageError{error};
  }
  const CheckInputs inputs = xacro ? CheckInputs{{xacro->checked_file}, 0, false}
                                   : ExpandInputs(args, InputsOrExample(args, argv0));
  const std::vector<std::string>& files = inputs.files;
  const std::vector<Settings> settings = LoadSettings(args, cli, explicit_config, files);
  std::optional<massprops::JointTrajectory> data;
  if (!args.data.empty() && !(data = massprops::cli::ReadCheckData(args.data))) return kExitError;

  std::vector<FileResult> results(files.size());
  massprops::cli::SetMeshJobs(args.jobs, JobCount(args.jobs, files));
  RunInParallel(files.size(), JobCount(args.jobs, files), [&](std::size_t i) {
    results[i] = CheckFile(files[i], settings[i]);
    results[i].fail_on = settings[i].fail_on;
    if (data && results[i].errors.empty()) {
      massprops::cli::AddDataFindings(files[i], *data, args.data, settings[i].options, &results[i]);
    }
  });
  if (xacro) massprops::cli::FinishXacroRun(&*xacro, &results.front());

  const massprops::ReportFormat format = *massprops::ParseReportFormat(args.format);
  massprops::WriteReport(std::cout, format, results, MakeReportOptions(args, inputs.skipped_files));
  std::cout.flush();
  return CheckExitCode(results, settings, inputs.unreadable_input);
}

// Accepts a --tolerance that is a number at least 0 and less than 1.
CLI::Validator ToleranceValidator() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0' || !(value >= 0 && value < 1)) {
          return "must be a number at least 0 and less than 1, got " + text;
        }
        return {};
      },
      "0<=X<1");
}

// The options of `check` whose presence, not only their value, matters after parsing.
struct CheckOptionsGiven {
  CLI::Option* fail_on = nullptr;
  CLI::Option* tolerance = nullptr;
};

// Adds the `check` subcommand and those of its options that `wanted` asks for (all by default),
// which fill *args.
CheckOptionsGiven AddCheckCommand(CLI::App& app, CheckArgs* args,
                                  const massprops::cli::OptionFilter& wanted = {}) {
  CheckOptionsGiven given;
  CLI::App* check = app.add_subcommand(
      "check",
      "Check models for mass properties that no real body could have, and for CAD-export defects. "
      "With no FILE, checks the bundled example model.");
  check->add_option("FILE", args->files,
                    "URDF, SDF or MJCF files (detected by content), '-' for standard input, or "
                    "folders (searched recursively for *.urdf, *.sdf, and *.world/*.xml with a "
                    "<robot>, <sdf> or <mujoco> root)");
  if (wanted.Wants({"--format"})) {
    check->add_option("--format", args->format, "Output format")
        ->check(CLI::IsMember({"text", "json", "sarif", "github", "junit", "gitlab"}))
        ->capture_default_str();
  }
  if (wanted.Wants({"--color"})) {
    check
        ->add_option("--color", args->color,
                     "Colour text output (auto: on a terminal, no NO_COLOR)")
        ->check(CLI::IsMember({"auto", "always", "never"}))
        ->capture_default_str();
  }
  if (wanted.Wants({"--fail-on"})) {
    given.fail_on = check
                        ->add_option("--fail-on", args->fail_on,
                                     "Exit with 1 when a finding is at least this severe (default: "
                                     "error, or fail-on in the configuration file)")
                        ->check(CLI::IsMember({"error", "warning", "note"}));
  }
  if (wanted.Wants({"--disable"})) {
    check->add_option("--disable", args->disable, "Disable a rule (repeatable)")
        ->type_name("RULE")
        ->allow_extra_args(false);
  }
  if (wanted.Wants({"--severity"})) {
    check
        ->add_option("--severity", args->severity,
                     "Change a rule's severity: RULE=off|note|warning|error (repeatable)")
        ->type_name("RULE=LEVEL")
        ->allow_extra_args(false);
  }
  if (wanted.Wants({"--tolerance"})) {
    given.tolerance = check
                          ->add_option("--tolerance", args->tolerance,
                                       "Tolerance of the physical-validity test, relative to the "
                                       "trace of the inertia, at least 0 and less than 1 (default "
                                       "1e-6)")
                          ->check(ToleranceValidator());
  }
  if (wanted.Wants({"--config"})) {
    check
        ->add_option("--config", args->config,
                     "Configuration file (default: .massprops.toml found upward from each file, "
                     "then from the working directory)")
        ->check(CLI::ExistingFile);
  }
  if (wanted.Wants({"--model-path"})) {
    check
        ->add_option("--model-path", args->model_paths,
                     "Folder searched for SDF model:// URIs (repeatable)")
        ->type_name("DIR")
        ->allow_extra_args(false);
  }
  if (wanted.Wants({"--target"})) massprops::cli::AddTargetOption(check, &args->target);
  if (wanted.Wants({"--max-input-size"})) {
    massprops::cli::AddMaxInputSizeOption(check, &args->max_input_bytes);
  }
  if (wanted.Wants({"--data"})) massprops::cli::AddCheckDataOption(check, &args->data);
  if (wanted.Wants({"-q", "--quiet"})) {
    check->add_flag("-q,--quiet", args->quiet, "Only the findings: no summary line, no notes");
  }
  if (wanted.Wants({"--brief"})) {
    check->add_flag("--brief", args->brief, "Text: each finding's headline alone");
  }
  if (wanted.Wants({"--explain"})) {
    check->add_flag("--explain", args->explain,
                    "Text: under each finding, its full reasoning (the causes considered and what "
                    "the numbers say of each); repeats are not grouped");
  }
  if (wanted.Wants({"--statistics"})) {
    check->add_flag("--statistics", args->statistics,
                    "Text: the number of findings per rule instead of the findings");
  }
  if (wanted.Wants({"-j", "--jobs"})) {
    check
        ->add_option("-j,--jobs", args->jobs,
                     "Check this many files at once, and read one file's meshes on this many "
                     "threads (default 0: one per core); the output is the same, byte for byte, "
                     "whatever the number")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
  }
  if (wanted.Wants({"--list-rules"})) {
    check->add_flag("--list-rules", args->list_rules,
                    "List the rules and their default severities");
  }
  massprops::cli::AddGeometryCheckOptions(check, wanted);
  if (wanted.Wants({"--xacro-arg", "--xacro-command", "--expanded", "--source-root"})) {
    massprops::cli::AddXacroOptions(check, &args->xacro);
  }
  return given;
}

// Runs the chosen subcommand (`run`, or check when it is unset) and returns its exit code; a
// usage, configuration or internal error becomes 2 with its message on standard error.
int RunCommand(const std::function<int()>& run, const CheckArgs& args, const char* argv0) {
  try {
    // A report that did not reach standard output (full disk, closed pipe end) is exit 2.
    if (run) return massprops::cli::FinishStandardOutput(run());
    return massprops::cli::FinishStandardOutput(RunCheck(args, argv0));
  } catch (const UsageError& error) {
    std::cerr << "massprops: error: " << error.message << "\n";
    return kExitError;
  } catch (const ConfigError& error) {
    std::cerr << error.what() << "\n";
    return kExitError;
  } catch (const std::exception& error) {
    std::cerr << "massprops: internal error: " << error.what() << "\n";
    return kExitError;
  }
}

}  // namespace

int main(int argc, char** argv) {
#if defined(__GLIBC__)
  // A mesh's buffers (its bytes, triangles, positions: megabytes each) are freed before the next
  // mesh asks for as much again. glibc would map each afresh (and fault in zeroed pages: a fifth
  // of a binary STL robot's first check) once they are over its sliding mmap threshold; kept in
  // the heap, freed memory is reused (docs/benchmarks.md, section 8). Exits return it all.
  mallopt(M_MMAP_THRESHOLD, 256 << 20);
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
#endif
  CLI::App app{
      "massprops: validate the mass properties (mass, center of mass, inertia) of the links of "
      "URDF and SDF robot models.",
      "massprops"};
  app.set_version_flag("--version", std::string("massprops ") + MASSPROPS_VERSION);
  app.require_subcommand(1);
  app.footer(
      "Exit codes of check: 0 nothing at or above the fail level, 1 findings at or above it,\n"
      "2 a file could not be read or parsed, a bad configuration file, or a usage error.");

  CheckArgs args;
  const CheckOptionsGiven given =
      AddCheckCommand(app, &args, massprops::cli::OptionFilter::ForCheck(argc, argv));

  // Subcommands defined in other files (src/tool/commands.h) set `run` when chosen. After
  // `check`, CLI11 reads every word as check's (require_subcommand(1): a second subcommand name
  // is a FILE), so `massprops check ...`, run once per file by pre-commit hooks, does not build
  // the options of report, merge-fixed, fix and view: 0.5 million instructions of a 5.6 million
  // run (callgrind; docs/benchmarks.md section 3).
  std::function<int()> run;
  if (argc < 2 || std::string_view(argv[1]) != "check") {
    massprops::cli::AddReportCommands(app, &run);
    massprops::cli::AddFixCommands(app, &run);
    massprops::cli::AddViewCommands(app, &run);
    massprops::cli::AddDiffCommands(app, &run);
    massprops::cli::AddIdentifyCommands(app, &run);
    massprops::cli::AddTraceCommand(app, &run);
    massprops::cli::AddCacheCommands(app, &run);
    massprops::cli::AddExplainCommand(app, &run);
    massprops::cli::AddLspCommand(app, &run);
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help and --version have exit code 0; every usage error becomes 2.
    const int code = app.exit(error);
    return code == 0 ? kExitClean : kExitError;
  }
  if (given.fail_on == nullptr || given.fail_on->count() == 0) args.fail_on.clear();
  args.tolerance_given = given.tolerance != nullptr && given.tolerance->count() > 0;
  return RunCommand(run, args, argc > 0 ? argv[0] : nullptr);
}

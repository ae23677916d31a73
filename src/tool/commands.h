#pragma once
// Subcommands of the `massprops` tool defined outside main.cc. Each Add*Commands function adds its
// subcommands to `app`; when one of them is chosen on the command line, CLI11 sets *run to the
// function that does its work and returns the exit code (0 ok; 1 findings; 2 read, parse or usage
// errors). main() calls *run after parsing when it is set.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/io/model_reader.h"

namespace massprops::cli {

/// `report` (mass, center of mass, inertia per link, welded group and model) and `merge-fixed`
/// (one link per welded group). Defined in src/tool/report_command.cc.
void AddReportCommands(CLI::App& app, std::function<int()>* run);

/// `fix` (repair mass properties and write the file back, changing only those numbers). Defined
/// in src/tool/fix_command.cc.
void AddFixCommands(CLI::App& app, std::function<int()>* run);

/// `view` (one self-contained HTML page drawing each link's equivalent inertia box over its
/// geometry, with its findings). Defined in src/tool/view_command.cc.
void AddViewCommands(CLI::App& app, std::function<int()>* run);

/// `cache clean` (empties the cache of mesh numbers kept between runs) and `cache dir` (prints
/// where it is). Defined in src/tool/cache_command.cc.
void AddCacheCommands(CLI::App& app, std::function<int()>* run);

/// `diff` (mass properties of two model files compared: per link, welded group and whole robot).
/// Defined in src/tool/diff_command.cc.
void AddDiffCommands(CLI::App& app, std::function<int()>* run);

/// `identify` (the mass properties recorded joint torques prove, physically consistent; written
/// back with fix's writer). Defined in src/tool/identify_command.cc.
void AddIdentifyCommands(CLI::App& app, std::function<int()>* run);

/// `lsp` (the language server on standard input and output, docs/editors.md). Defined in
/// src/tool/lsp_command.cc.
void AddLspCommand(CLI::App& app, std::function<int()>* run);

/// Writes the HTML view of `files` to standard output (`report --format html`); returns the exit
/// code (0 written; 2 a file could not be read, a bad configuration file, or a write error).
int RunHtmlView(const std::vector<std::string>& files, const std::vector<std::string>& model_paths,
                const std::vector<std::string>& package_paths);

/// `explain RULE` (a rule's long form, from docs/rules.md compiled in). Defined in
/// src/tool/explain_command.cc.
void AddExplainCommand(CLI::App& app, std::function<int()>* run);

/// Prints the reader's findings (unresolved includes, unreadable inertials, ...) and read
/// warnings to standard error as `check` prints them, so that nothing the reader skipped goes
/// unsaid. Defined in src/tool/fix_command.cc.
void PrintReaderFindings(const ReadResult& read, const CheckOptions& options);

}  // namespace massprops::cli

#pragma once
// The xacro side of the tool (docs/xacro.md): running an expander, the options that say where the
// expansion and the sources are, and attaching the trace to findings. Defined in xacro_cli.cc.
#include <CLI/CLI.hpp>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "massprops/io/xacro_trace.h"
#include "massprops/output/reporters.h"

namespace massprops::cli {

/// The options of a xacro package, shared by check, fix and trace.
struct XacroOptions {
  std::vector<std::string> xacro_args;    ///< --xacro-arg NAME:=VALUE (repeatable)
  std::string xacro_command;              ///< --xacro-command CMD (default: `xacro` on PATH)
  std::string expanded;                   ///< --expanded FILE: an expansion made elsewhere
  std::vector<std::string> source_roots;  ///< --source-root DIR (repeatable)
};

/// Adds --xacro-arg, --xacro-command, --expanded and --source-root to `command`.
void AddXacroOptions(CLI::App* command, XacroOptions* options);

/// True when the run is on a xacro package: --expanded given, or `file` ends in ".xacro".
bool IsXacroRun(const XacroOptions& options, const std::string& file);

/// An expansion: its text, the name it is reported under, and the trace options.
struct Expansion {
  std::string text;
  std::string name;  ///< --expanded's path, or "<expansion of TOP>"
  XacroTraceOptions trace;
};

/// Reads --expanded or runs the expander on `top`. Returns nullopt with *error set (a sentence
/// that says how to give the expansion when no expander is found).
std::optional<Expansion> MakeExpansion(const XacroOptions& options, const std::string& top,
                                       std::string* error);

/// Runs the expander again on `top` (after an edit); nullopt when none is available or it fails
/// (*error says why).
std::optional<std::string> ReExpand(const XacroOptions& options, const std::string& top,
                                    std::string* error);

/// A `check` of a xacro package: the file that is checked (--expanded, or a temporary file that
/// holds the expansion, removed by FinishXacroRun) and the expansion.
struct XacroRun {
  Expansion expansion;
  std::string checked_file;
  bool temporary = false;
};

/// Makes the expansion (MakeExpansion) and the file to check. nullopt with *error on failure.
std::optional<XacroRun> StartXacroRun(const XacroOptions& options, const std::string& top,
                                      std::string* error);

/// After the check: names the generated text as Expansion::name in `result`, traces it, attaches
/// the sources to the findings (AttachSources), says on standard error which source files could
/// not be read, and removes the temporary file.
void FinishXacroRun(XacroRun* run, FileResult* result);

/// Gives each finding of `result` the source place of the numbers it is about (see
/// FindingSource): the numbers of its link at the finding's line (the <inertia>, <mass> or
/// <origin> element), or the link's inertia, then mass, when the line is the <inertial>.
void AttachSources(const XacroTrace& trace, const std::string& generated_name, FileResult* result);

/// `trace`: prints every inertial number's source (text, json, or the share summary).
void AddTraceCommand(CLI::App& app, std::function<int()>* run);

}  // namespace massprops::cli

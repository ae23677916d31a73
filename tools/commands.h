#pragma once
// Subcommands of the `massprops` tool defined outside main.cc. Each Add*Commands function adds its
// subcommands to `app`; when one of them is chosen on the command line, CLI11 sets *run to the
// function that does its work and returns the exit code (0 ok; 1 findings; 2 read, parse or usage
// errors). main() calls *run after parsing when it is set.
#include <CLI/CLI.hpp>
#include <functional>

namespace massprops::cli {

/// `report` (mass, center of mass, inertia per link, welded group and model) and `merge-fixed`
/// (one link per welded group). Defined in tools/report_command.cc.
void AddReportCommands(CLI::App& app, std::function<int()>* run);

/// `fix` (repair mass properties and write the file back, changing only those numbers). Defined
/// in tools/fix_command.cc.
void AddFixCommands(CLI::App& app, std::function<int()>* run);

}  // namespace massprops::cli

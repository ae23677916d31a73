#pragma once
// `massprops check --data LOG` (docs/rules.md, inertia-contradicts-data): the recording read once
// for the run, and each checked file's robots compared with it (analysis/data_contradiction.h).
// Defined in src/tool/check_data.cc.
#include <optional>
#include <string>

#include "massprops/analysis/checks.h"
#include "massprops/io/trajectory_csv.h"
#include "massprops/output/reporters.h"

namespace CLI {
class App;
}

namespace massprops::cli {

/// Adds --data LOG to `check`, filling *log.
void AddCheckDataOption(CLI::App* check, std::string* log);

/// The recording at `path` (identify's DATA: CSV, PlotJuggler's CSV, a rosbag2 folder or .db3),
/// or nullopt with its errors printed on standard error (check then exits 2, reporting nothing).
std::optional<JointTrajectory> ReadCheckData(const std::string& path);

/// Adds the inertia-contradicts-data finding of each robot of `file` (read again: the check
/// pipeline does not hand its models out) to *result, at the rule's severity under `options`
/// (warning unless overridden). A robot that is not a fixed-base tree, whose joints the
/// recording does not match, or that cannot be fitted gets a note on standard error, no finding.
void AddDataFindings(const std::string& file, const JointTrajectory& log,
                     const std::string& log_name, const CheckOptions& options, FileResult* result);

}  // namespace massprops::cli

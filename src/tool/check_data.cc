#include "check_data.h"

#include <CLI/CLI.hpp>
#include <iostream>
#include <stdexcept>

#include "massprops/analysis/data_contradiction.h"
#include "massprops/analysis/identify.h"
#include "massprops/io/model_reader.h"
#include "massprops/io/trajectory_rosbag.h"

namespace massprops::cli {

void AddCheckDataOption(CLI::App* check, std::string* log) {
  check
      ->add_option("--data", *log,
                   "A recording of the robot's joints (as identify's DATA: CSV, PlotJuggler's "
                   "CSV, a rosbag2 folder or .db3): warn (inertia-contradicts-data) when the "
                   "file's values predict its torques more than 2x worse than consistent ones")
      ->type_name("LOG");
}

std::optional<JointTrajectory> ReadCheckData(const std::string& path) {
  const TrajectoryReadResult log =
      IsRosbagPath(path) ? ReadTrajectoryRosbag(path) : ReadTrajectoryCsvFile(path);
  for (const ReadError& e : log.errors) std::cerr << e.ToString() << "\n";
  if (!log.ok()) {
    std::cerr << "massprops: error: --data " << path << " could not be read; nothing checked\n";
    return std::nullopt;
  }
  return *log.trajectory;
}

void AddDataFindings(const std::string& file, const JointTrajectory& log,
                     const std::string& log_name, const CheckOptions& options, FileResult* result) {
  const std::string rule(kInertiaContradictsData);
  std::optional<Severity> severity = Severity::kWarning;
  if (const auto it = options.overrides.find(rule); it != options.overrides.end()) {
    severity = it->second;
  }
  if (!severity) return;
  const ReadResult read = ReadModelFile(file);
  for (const Model& model : read.models) {
    const auto note = [&](const std::string& why) {
      std::cerr << file << ": note: model '" << model.name << "' not compared with " << log_name
                << ": " << why << "\n";
    };
    KinematicTreeResult made = MakeKinematicTree(model);
    if (!made.tree) {
      note(made.error);
      continue;
    }
    const OrderedTrajectory data = OrderTrajectory(*made.tree, log);
    if (!data.ok()) {
      note(data.error);
      continue;
    }
    const IdentifyOptions identify;
    try {
      const IdentifyResult fitted = Identify(*made.tree, data, identify);
      const DataContradiction c = AssessDataContradiction(*made.tree, data, fitted, identify);
      if (auto f = DataContradictionFinding(model, *made.tree, c, log_name, *severity)) {
        result->findings.push_back(std::move(*f));
      }
    } catch (const std::invalid_argument& e) {
      note(e.what());
    }
  }
}

}  // namespace massprops::cli

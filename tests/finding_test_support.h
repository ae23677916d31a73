#pragma once
// The helpers of the rule tests that check a fixture file as `massprops check` does by default
// (warnings_round2_test.cc, warnings_round3_test.cc, unseen_rules_test.cc): the run, and the
// look-ups of a finding's rule, values and evidence.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/io/model_reader.h"
#include "massprops/mesh/mesh_loader.h"

namespace massprops::test_support {

/// The first model of `file` checked as `massprops check` checks it by default: the meshes'
/// boxes and vertices read (and their closed volumes, with `closed_meshes`), from the file's
/// place only (no environment), through one cache for the test program. `options` adds rule
/// overrides.
inline std::vector<Finding> CheckAsTheTool(const std::string& file, bool closed_meshes = true,
                                           CheckOptions options = {}) {
  const ReadResult read = ReadModelFile(file);
  EXPECT_TRUE(read.ok()) << file;
  if (read.models.empty()) return {};
  static MeshCache cache;
  MeshResolveOptions resolve;
  resolve.model_file = file;
  resolve.use_environment = false;
  resolve.cache = &cache;
  options.box = MakeLinkBoxFunction(resolve);
  options.points = MakeLinkPointsFunction(resolve);
  if (closed_meshes) options.closed_mesh = MakeClosedMeshShapeFunction(resolve);
  return CheckModel(read.models[0], options);
}

/// The findings of `rule`, in their order.
inline std::vector<Finding> Select(const std::vector<Finding>& findings, const std::string& rule) {
  std::vector<Finding> out;
  for (const Finding& f : findings) {
    if (f.rule == rule) out.push_back(f);
  }
  return out;
}

/// The finding's measured value `name` (Finding::values); NaN and a test failure when absent.
inline double ValueOf(const Finding& f, const std::string& name) {
  for (const auto& [key, value] : f.values) {
    if (key == name) return value;
  }
  ADD_FAILURE() << "no value " << name << " in " << f.message;
  return NAN;
}

/// The finding's evidence `name` (Finding::evidence); NaN and a test failure when absent.
inline double EvidenceOf(const Finding& f, const std::string& name) {
  for (const auto& [key, value] : f.evidence) {
    if (key == name) return value;
  }
  ADD_FAILURE() << "no evidence " << name << " in " << f.headline;
  return NAN;
}

/// One line per finding, "  [rule] message", for a failure's message.
inline std::string Dump(const std::vector<Finding>& findings) {
  std::string text;
  for (const Finding& f : findings) text += "  [" + f.rule + "] " + f.message + "\n";
  return text;
}

}  // namespace massprops::test_support

#include "fuzz_targets.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/analysis/repair.h"
#include "massprops/analysis/welded_groups.h"
#include "massprops/core/rotational_inertia.h"
#include "massprops/io/mjcf_reader.h"
#include "massprops/io/model_reader.h"
#include "massprops/io/sdf_reader.h"
#include "massprops/io/urdf_reader.h"
#include "massprops/output/merge_fixed.h"
#include "massprops/output/xml_patch.h"

namespace massprops::fuzz {
namespace {

// Every rule on, each at its default severity (rules off by default included).
CheckOptions AllRulesOn() {
  CheckOptions options;
  for (const RuleInfo& rule : AllRules())
    options.overrides[std::string(rule.id)] = rule.default_severity;
  return options;
}

// Every check the tool runs on a read model, plus the composites and the fix planner.
void CheckEverything(const ReadResult& read) {
  static const CheckOptions options = AllRulesOn();
  (void)ReaderFindings(read, options);
  for (const Model& model : read.models) {
    const std::vector<Finding> findings = CheckModel(model, options);
    (void)PlanRepairs(model, findings, RepairOptions{});
    (void)CalcModelCompositeInertia(model);
  }
}

ReadOptions NoEnvironment() {
  ReadOptions options;
  options.sdf.use_environment = false;  // Includes resolve against nothing on this machine.
  return options;
}

// The repairs `massprops fix` would write for `read` (every model of the file).
std::vector<Repair> PlanAll(const ReadResult& read) {
  std::vector<Repair> repairs;
  for (const Model& model : read.models) {
    const std::vector<Finding> findings = CheckModel(model, CheckOptions{});
    std::vector<Repair> planned = PlanRepairs(model, findings, RepairOptions{});
    repairs.insert(repairs.end(), planned.begin(), planned.end());
  }
  return repairs;
}

bool Finite(double x) { return std::isfinite(x); }

// The Frobenius norm without underflow (1e-300 entries) or overflow: scaled by the largest entry.
// (Eigen 3.4's stableNorm() asserts on fixed-size 3x3 matrices in debug builds.)
double FrobeniusNorm(const Eigen::Matrix3d& m) {
  const double scale = m.cwiseAbs().maxCoeff();
  return scale > 0 ? scale * (m / scale).norm() : 0.0;
}

}  // namespace

std::string FuzzUrdf(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  CheckEverything(ReadUrdfString(text, "fuzz.urdf"));
  return "";
}

// merge-fixed of an SDF text: when it merges, the result must read again with the merged links
// gone.
std::string CheckMergeFixed(const std::string& text, const ReadResult& read) {
  const MergeFixedResult merged = MergeFixedJoints(text, "fuzz.sdf");
  if (!merged.errors.empty() || merged.merged_links == 0) return "";
  const ReadResult reread = ReadModelString(merged.text, "fuzz.sdf");
  std::size_t before = 0, after = 0;
  for (const Model& model : read.models) before += model.links.size();
  for (const Model& model : reread.models) after += model.links.size();
  if (!reread.ok() || after + merged.merged_links != before) {
    std::string why = "the merged text does not read back with " +
                      std::to_string(before - merged.merged_links) + " links (" +
                      std::to_string(after) + ")";
    for (const ReadError& e : reread.errors) why += "; " + e.ToString();
    return why;
  }
  return "";
}

std::string FuzzSdf(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  SdfReadOptions options;
  options.use_environment = false;
  const ReadResult read = ReadSdfString(text, "fuzz.sdf", options);
  CheckEverything(read);
  if (!read.ok() || read.models.empty()) return "";
  return CheckMergeFixed(text, read);
}

std::string FuzzMjcf(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (const bool mujoco : {false, true}) {
    MjcfReadOptions options;
    options.max_include_depth = 0;
    options.mujoco_mesh_inertia = mujoco;
    const ReadResult read = ReadMjcfString(text, "fuzz.xml", options);
    CheckEverything(read);
    for (const Model& model : read.models) {
      if (model.links.empty() || model.links[0].name != "world") return "no world link first";
      if (model.joints.size() + 1 != model.links.size()) return "not one joint per body";
      for (const Joint& joint : model.joints) {
        if (model.FindLink(joint.parent) < 0 || model.FindLink(joint.child) < 0) {
          return "joint '" + joint.name + "' names a link the model does not have";
        }
      }
    }
  }
  return "";
}

std::string FuzzFix(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const ReadOptions options = NoEnvironment();
  const ReadResult read = ReadModelString(text, "fuzz.model", options);
  if (!read.ok() || read.models.empty()) return "";
  const Model::Format format = read.models.front().format;
  const PatchResult first = PatchModelText(text, format, PlanAll(read));
  if (first.text == text) return "";
  const ReadResult reread = ReadModelString(first.text, "fuzz.model", options);
  if (!reread.ok() || reread.models.size() != read.models.size()) {
    std::string why = "the patched text does not read back";
    for (const ReadError& e : reread.errors) why += "; " + e.ToString();
    return why;
  }
  const PatchResult second = PatchModelText(first.text, format, PlanAll(reread));
  if (second.text != first.text) {
    return "a second fix changed the text again:\n" +
           UnifiedDiff(first.text, second.text, "fuzz.model");
  }
  return "";
}

std::string FuzzInertia(const std::uint8_t* data, std::size_t size) {
  constexpr std::size_t kDouble = sizeof(double);
  if (size < 6 * kDouble) return "";
  double v[10] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  const std::size_t count = std::min<std::size_t>(10, size / kDouble);
  for (std::size_t i = 0; i < count; ++i) std::memcpy(&v[i], data + i * kDouble, kDouble);
  // Entries up to 1e100: products of two stay finite (no overflow, so no inf − inf). Nonzero
  // entries below 1e-150 are out of scope: there results carry only the few digits of subnormal
  // numbers, which the absolute bounds below do not allow for. (The principal axes of such input
  // are orthonormal since the fix of testdata/fuzz/open/README.md; FuzzRegressionTest checks the
  // inputs found there directly.)
  for (std::size_t i = 0; i < count; ++i) {
    if (!Finite(v[i]) || std::abs(v[i]) > 1e100) return "";
    if (v[i] != 0 && std::abs(v[i]) < 1e-150) return "";
  }
  using I3 = RotationalInertia<double>;
  const I3 I = I3::MakeFromMomentsAndProductsOfInertia(v[0], v[1], v[2], v[3], v[4], v[5], true);
  const bool valid = I.CouldBePhysicallyValid();
  (void)I.CouldBePhysicallyValid(1e-6);
  (void)I.CriticizeNotPhysicallyValid();
  const Eigen::Vector3d moments = I.CalcPrincipalMomentsOfInertia();
  const auto [moments2, R_EA] = I.CalcPrincipalMomentsAndAxesOfInertia();
  if (!moments.allFinite() || !moments2.allFinite() || !R_EA.allFinite()) {
    return "non-finite principal moments or axes from finite entries";
  }
  if (!(moments(0) <= moments(1) && moments(1) <= moments(2))) return "moments not ascending";
  // Bounds (principal_axes.h: every moment within a few units of round-off): the eigenvalues of a
  // symmetric matrix sum to its trace and none exceeds its Frobenius norm.
  const double norm = FrobeniusNorm(I.CopyToFullMatrix3());
  const double slack = 1e-12 * norm + std::numeric_limits<double>::denorm_min();
  if (std::abs(moments.sum() - I.Trace()) > slack) return "moments do not sum to the trace";
  if (moments.cwiseAbs().maxCoeff() > norm + slack) return "a moment exceeds the Frobenius norm";
  if ((R_EA.transpose() * R_EA - Eigen::Matrix3d::Identity()).norm() > 1e-9) {
    return "principal axes not orthonormal";
  }
  if (valid && moments(0) < -1e-9 * norm) return "a valid inertia has a negative principal moment";
  if (count >= 10) {
    const double mass = std::abs(v[6]);
    const Eigen::Vector3d p(v[7], v[8], v[9]);
    if (mass > 1e30 || p.cwiseAbs().maxCoeff() > 1e30) return "";
    const I3 shifted = I.ShiftFromCenterOfMass(mass, p);
    if (shifted.IsNaN() || !shifted.IsFinite()) return "a shift of finite numbers is not finite";
    // The same scope as above: a shift whose result has entries below 1e-150 works in the
    // subnormal range, where a sum keeps only a few digits (found by CI's fuzz run: entries of
    // 1e-322 whose shifted principal moments lost the triangle inequality to rounding).
    const Eigen::Matrix3d shifted_entries = shifted.CopyToFullMatrix3();
    for (int k = 0; k < 9; ++k) {
      const double x = shifted_entries(k / 3, k % 3);
      if (x != 0 && std::abs(x) < 1e-150) return "";
    }
    if (valid && !shifted.CouldBePhysicallyValid(1e-9)) {
      return "a valid inertia shifted away from its center of mass is not valid:\n" +
             shifted.CriticizeNotPhysicallyValid(1e-9);
    }
    const Eigen::Vector3d shifted_moments = shifted.CalcPrincipalMomentsOfInertia();
    if (!shifted_moments.allFinite()) return "non-finite principal moments after a shift";
    // Removing the parallel-axis term again recovers the entries up to round-off of the larger
    // of the two (unchecked arithmetic: the checked shift throws in debug builds when round-off
    // leaves a result just outside the valid set).
    const Eigen::Matrix3d term =
        mass * (p.squaredNorm() * Eigen::Matrix3d::Identity() - p * p.transpose());
    const Eigen::Matrix3d d = shifted.CopyToFullMatrix3() - term - I.CopyToFullMatrix3();
    const double scale = std::max(norm, FrobeniusNorm(term));
    // Absolute floor 1e-300: below it the products m·p·p underflow (subnormal results carry
    // few digits; testdata/fuzz/regressions/inertia/shift-underflow-*).
    if (FrobeniusNorm(d) > 1e-12 * scale + 1e-300) {
      return "shifting away and back does not recover the inertia";
    }
  }
  return "";
}

FuzzFunction FindFuzzTarget(const std::string& name) {
  if (name == "urdf") return &FuzzUrdf;
  if (name == "sdf") return &FuzzSdf;
  if (name == "mjcf") return &FuzzMjcf;
  if (name == "fix") return &FuzzFix;
  if (name == "inertia") return &FuzzInertia;
  return nullptr;
}

}  // namespace massprops::fuzz

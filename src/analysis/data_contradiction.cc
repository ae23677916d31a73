// inertia-contradicts-data (warning, only with `check --data LOG`): the file's mass properties
// explain the recorded torques much worse than consistent values can
// (massprops/analysis/data_contradiction.h says the test and why its factor is 2).
#include "massprops/analysis/data_contradiction.h"

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "analysis/rules/rules.h"
#include "massprops/analysis/finding_text.h"
#include "massprops/dynamics/torque_regressor.h"

namespace massprops {

namespace rules {

const RuleInfo& InertiaContradictsDataRule() {
  static const RuleInfo kInfo{
      kInertiaContradictsData, Severity::kWarning, false,
      "the file's mass properties predict a recording's joint torques more than 2x worse (held-out "
      "RMS) than consistent values fitted to it; needs --data LOG"};
  return kInfo;
}

}  // namespace rules

namespace {

// The friction terms of each joint (its 3 columns of the regressor) that best fit, on the
// training rows [0, fit), the torques the file's inertial parameters leave unexplained.
Eigen::VectorXd FitFrictionToFile(const KinematicTree& tree, const OrderedTrajectory& data,
                                  Eigen::Index fit, const Eigen::VectorXd& pi,
                                  const RegressorOptions& options) {
  const int n = tree.size();
  const Eigen::Index inertial = 10 * n;
  std::vector<Eigen::Matrix3d> A(static_cast<std::size_t>(n), Eigen::Matrix3d::Zero());
  std::vector<Eigen::Vector3d> b(static_cast<std::size_t>(n), Eigen::Vector3d::Zero());
  Eigen::MatrixXd Y(n, CountRegressorColumns(tree, options));
  for (Eigen::Index k = 0; k < fit; ++k) {
    CalcTorqueRegressor(tree, data.q.row(k).transpose(), data.dq.row(k).transpose(),
                        data.ddq.row(k).transpose(), options, Y);
    const Eigen::VectorXd rest =
        data.tau.row(k).transpose() - Y.leftCols(inertial) * pi.head(inertial);
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector3d x = Y.block(j, inertial + 3 * j, 1, 3).transpose();
      A[static_cast<std::size_t>(j)] += x * x.transpose();
      b[static_cast<std::size_t>(j)] += x * rest[j];
    }
  }
  Eigen::VectorXd full = pi;
  for (int j = 0; j < n; ++j) {  // minimum norm where a joint never moves (zero columns)
    full.segment<3>(inertial + 3 * j) =
        A[static_cast<std::size_t>(j)].completeOrthogonalDecomposition().solve(
            b[static_cast<std::size_t>(j)]);
  }
  return full;
}

}  // namespace

DataContradiction AssessDataContradiction(const KinematicTree& tree, const OrderedTrajectory& data,
                                          const IdentifyResult& result,
                                          const IdentifyOptions& options) {
  const int n = tree.size();
  const Eigen::Index N = data.q.rows();
  const Eigen::Index held = result.validation_samples;
  const Eigen::Index fit = N - held;
  DataContradiction c;
  Eigen::VectorXd pi = RegressorParameters(tree, options.regressor);
  if (options.regressor.friction) pi = FitFrictionToFile(tree, data, fit, pi, options.regressor);
  const Eigen::Index first = held > 0 ? fit : 0, count = held > 0 ? held : fit;
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(n);
  double measured = 0;
  Eigen::MatrixXd Y(n, CountRegressorColumns(tree, options.regressor));
  for (Eigen::Index k = first; k < first + count; ++k) {
    CalcTorqueRegressor(tree, data.q.row(k).transpose(), data.dq.row(k).transpose(),
                        data.ddq.row(k).transpose(), options.regressor, Y);
    sum += (data.tau.row(k).transpose() - Y * pi).cwiseAbs2();
    measured += data.tau.row(k).squaredNorm();
  }
  const double joint_samples = static_cast<double>(count) * n;
  c.validation_samples = static_cast<int>(count);
  c.rms_file_per_joint = (sum / static_cast<double>(count)).cwiseSqrt();
  c.rms_file = std::sqrt(sum.sum() / joint_samples);
  c.rms_identified = std::sqrt(result.rms_identified.squaredNorm() / n);
  c.rms_measured = std::sqrt(measured / joint_samples);
  c.contradicts = c.rms_file > kDataContradictionFactor * c.rms_identified &&
                  c.rms_file - c.rms_identified > kDataContradictionFloor * c.rms_measured;
  return c;
}

std::optional<Finding> DataContradictionFinding(const Model& model, const KinematicTree& tree,
                                                const DataContradiction& c,
                                                const std::string& data_name, Severity severity) {
  if (!c.contradicts || tree.size() == 0) return std::nullopt;
  const double ratio = c.rms_file / c.rms_identified;
  Finding f;
  f.rule = std::string(kInertiaContradictsData);
  f.severity = severity;
  f.model = model.name;
  f.link = tree.bodies[0].link;
  const int i = model.FindLink(f.link);
  if (i >= 0) f.location = model.links[static_cast<std::size_t>(i)].location;
  int worst = 0;
  c.rms_file_per_joint.maxCoeff(&worst);
  const std::string rms =
      FormatSignificant(c.rms_file) + " vs " + FormatSignificant(c.rms_identified) + " N·m";
  f.message = "the mass properties of model '" + model.name + "' predict the torques of " +
              data_name + " with an RMS of " + FormatSignificant(c.rms_file) + " N·m on the " +
              std::to_string(c.validation_samples) + " held-out samples (friction fitted), " +
              FormatRatio(ratio) + " the " + FormatSignificant(c.rms_identified) +
              " N·m of physically consistent values fitted to the rest (more than " +
              FormatSignificant(kDataContradictionFactor) + "x is reported); worst joint '" +
              tree.bodies[static_cast<std::size_t>(worst)].joint + "' (" +
              FormatSignificant(c.rms_file_per_joint[worst]) + " N·m)";
  const std::string times = FormatRatio(ratio);
  f.headline = FirstThatFits(
      {ModelHeadline(model.name, ": predicts the recorded torques " + times +
                                     " worse than consistent inertias (" + rms + ")"),
       ModelHeadline(model.name,
                     ": predicts the recorded torques " + times + " worse (" + rms + ")"),
       "this model predicts the recorded torques " + times + " worse than consistent inertias"});
  f.evidence = {{"file_torque_rms_n_m", c.rms_file},
                {"consistent_fit_torque_rms_n_m", c.rms_identified},
                {"ratio", ratio},
                {"held_out_samples_count", static_cast<double>(c.validation_samples)}};
  f.values = {{"rms_file", c.rms_file},
              {"rms_identified", c.rms_identified},
              {"rms_measured", c.rms_measured},
              {"ratio", ratio}};
  f.help =
      "fit consistent values to the data and write them: massprops identify ROBOT LOG --write OUT";
  return f;
}

}  // namespace massprops

// End-to-end tests of `massprops check --data LOG` (docs/rules.md, inertia-contradicts-data) on
// the planar two-link arm of testdata/identify/planar_arm.urdf. Expected numbers come from the
// closed-form equations of motion of Spong, Hutchinson and Vidyasagar ("Robot Modeling and
// Control", 2006, §7.4; the same as tools/make_identify_csv.py), not from massprops' dynamics.
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "tool_runner.h"

namespace {

namespace fs = std::filesystem;

const std::string kDir = std::string(MASSPROPS_TESTDATA_DIR) + "/identify/";

// The arm's parameters: masses (kg), upper arm length, COM distances (m), central inertias
// about the joint axis (kg·m²).
struct Arm {
  double m1, m2, l1, lc1, lc2, I1, I2;
};
// planar_arm.urdf's values (its comment and <inertial>s: iyy is the inertia about the axis).
constexpr Arm kFileArm{2, 1.2, 0.5, 0.25, 0.2, 0.04, 0.015};

struct Sample {
  double q1, dq1, ddq1, q2, dq2, ddq2, tau1, tau2;
};

// Spong et al. (2006) §7.4, gravity 9.81 along -z, without friction.
std::pair<double, double> SpongTorques(const Arm& p, const Sample& s) {
  const double g = 9.81;
  const double d11 = p.m1 * p.lc1 * p.lc1 +
                     p.m2 * (p.l1 * p.l1 + p.lc2 * p.lc2 + 2 * p.l1 * p.lc2 * std::cos(s.q2)) +
                     p.I1 + p.I2;
  const double d12 = p.m2 * (p.lc2 * p.lc2 + p.l1 * p.lc2 * std::cos(s.q2)) + p.I2;
  const double d22 = p.m2 * p.lc2 * p.lc2 + p.I2;
  const double h = -p.m2 * p.l1 * p.lc2 * std::sin(s.q2);
  const double phi1 =
      (p.m1 * p.lc1 + p.m2 * p.l1) * g * std::cos(s.q1) + p.m2 * p.lc2 * g * std::cos(s.q1 + s.q2);
  const double phi2 = p.m2 * p.lc2 * g * std::cos(s.q1 + s.q2);
  return {d11 * s.ddq1 + d12 * s.ddq2 + 2 * h * s.dq1 * s.dq2 + h * s.dq2 * s.dq2 + phi1,
          d12 * s.ddq1 + d22 * s.ddq2 - h * s.dq1 * s.dq1 + phi2};
}

// planar_arm.csv's samples (its header: time, then q, dq, ddq, tau of shoulder and elbow).
std::vector<Sample> ReadPlanarArmCsv(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::vector<Sample> samples;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 't') continue;
    std::vector<double> v;
    std::stringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ',')) v.push_back(std::strtod(field.c_str(), nullptr));
    samples.push_back({v[1], v[2], v[3], v[5], v[6], v[7], v[4], v[8]});
  }
  return samples;
}

// The held-out torque RMS (over both joints) of `arm` with each joint's viscous, Coulomb and
// offset terms fitted by least squares to the first `fit` samples, on the samples after them.
double HeldOutRmsWithFittedFriction(const Arm& arm, const std::vector<Sample>& s, int fit) {
  double sum = 0;
  for (int j = 0; j < 2; ++j) {
    Eigen::MatrixXd X(fit, 3);
    Eigen::VectorXd y(fit);
    const auto row = [&](const Sample& k) {
      const double dq = j == 0 ? k.dq1 : k.dq2;
      return Eigen::RowVector3d(dq, dq > 0 ? 1.0 : dq < 0 ? -1.0 : 0.0, 1.0);
    };
    const auto rest = [&](const Sample& k) {
      const auto [t1, t2] = SpongTorques(arm, k);
      return j == 0 ? k.tau1 - t1 : k.tau2 - t2;
    };
    for (int k = 0; k < fit; ++k) {
      X.row(k) = row(s[k]);
      y[k] = rest(s[k]);
    }
    const Eigen::Vector3d f = X.colPivHouseholderQr().solve(y);
    for (std::size_t k = static_cast<std::size_t>(fit); k < s.size(); ++k) {
      const double e = rest(s[k]) - row(s[k]).dot(f);
      sum += e * e;
    }
  }
  return std::sqrt(sum / (2.0 * static_cast<double>(s.size() - static_cast<std::size_t>(fit))));
}

class CheckDataCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "massprops-check-data-XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  massprops::test_support::SplitToolRun Run(const std::string& args) {
    return massprops::test_support::RunToolSplit(args, dir_);
  }
  fs::path dir_;
};

TEST_F(CheckDataCliTest, DataOfTheFilesOwnValuesGiveNoFinding) {
  // The recording planar_arm.csv's trajectory, its torques recomputed from the FILE's values
  // plus viscous friction (0.3, 0.1 N·m·s) and Gaussian noise σ = 0.01 N·m (seed 51).
  std::vector<Sample> samples = ReadPlanarArmCsv(kDir + "planar_arm.csv");
  ASSERT_EQ(samples.size(), 800u);
  std::mt19937 rng(51);
  std::normal_distribution<double> noise(0.0, 0.01);
  const fs::path csv = dir_ / "true.csv";
  std::ofstream out(csv);
  out.precision(17);
  out << "time,shoulder.q,shoulder.dq,shoulder.ddq,shoulder.tau,elbow.q,elbow.dq,elbow.ddq,"
         "elbow.tau\n";
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const Sample& s = samples[k];
    const auto [t1, t2] = SpongTorques(kFileArm, s);
    out << 0.01 * static_cast<double>(k) << "," << s.q1 << "," << s.dq1 << "," << s.ddq1 << ","
        << t1 + 0.3 * s.dq1 + noise(rng) << "," << s.q2 << "," << s.dq2 << "," << s.ddq2 << ","
        << t2 + 0.1 * s.dq2 + noise(rng) << "\n";
  }
  out.close();
  const auto run =
      Run("check --format json '" + kDir + "planar_arm.urdf' --data '" + csv.string() + "'");
  ASSERT_EQ(run.code, 0) << run.err;
  const nlohmann::json doc = nlohmann::json::parse(run.out);
  for (const auto& f : doc["files"][0]["findings"]) {
    EXPECT_NE(f["rule"], "inertia-contradicts-data") << f.dump();
  }
}

TEST_F(CheckDataCliTest, DataOfADifferentArmGiveOneWarningWithWorkedOutNumbers) {
  const auto run =
      Run("check --format json '" + kDir + "planar_arm.urdf' --data '" + kDir + "planar_arm.csv'");
  ASSERT_EQ(run.code, 0) << run.err;  // a warning: below the default fail level (error)
  const nlohmann::json doc = nlohmann::json::parse(run.out);
  std::vector<nlohmann::json> found;
  for (const auto& f : doc["files"][0]["findings"]) {
    if (f["rule"] == "inertia-contradicts-data") found.push_back(f);
  }
  ASSERT_EQ(found.size(), 1u) << run.out;
  const nlohmann::json& f = found[0];
  EXPECT_EQ(f["severity"], "warning");
  EXPECT_EQ(f["model"], "planar_arm");
  // 800 samples, the last floor(0.3 · 800) = 240 held out, the first 560 fitted.
  const std::vector<Sample> samples = ReadPlanarArmCsv(kDir + "planar_arm.csv");
  const double file_rms = HeldOutRmsWithFittedFriction(kFileArm, samples, 560);
  EXPECT_NEAR(f["evidence"]["file_torque_rms_n_m"].get<double>(), file_rms, 1e-6 * file_rms);
  EXPECT_EQ(f["evidence"]["held_out_samples_count"].get<double>(), 240);
  // The consistent fit leaves the recording's noise, σ = 0.01 N·m (make_identify_csv.py).
  const double fit_rms = f["evidence"]["consistent_fit_torque_rms_n_m"].get<double>();
  EXPECT_NEAR(fit_rms, 0.01, 0.0015);
  EXPECT_NEAR(f["evidence"]["ratio"].get<double>(), file_rms / fit_rms, 1e-6 * file_rms / fit_rms);
  EXPECT_GT(file_rms, 2 * fit_rms);
  EXPECT_LE(f["headline"].get<std::string>().size(), 110u) << f["headline"];
  EXPECT_NE(f["help"].get<std::string>().find("massprops identify ROBOT LOG --write OUT"),
            std::string::npos);
  // --fail-on warning makes it fail the run.
  EXPECT_EQ(Run("check -q '" + kDir + "planar_arm.urdf' --fail-on warning --data '" + kDir +
                "planar_arm.csv'")
                .code,
            1);
  // And the rule can be switched off like any other.
  const auto off = Run("check -q '" + kDir + "planar_arm.urdf' --fail-on warning --data '" + kDir +
                       "planar_arm.csv' --disable inertia-contradicts-data");
  EXPECT_EQ(off.code, 0) << off.out;
}

TEST_F(CheckDataCliTest, AnUnreadableLogIsAnErrorNamingItAndNothingIsChecked) {
  const std::string missing = (dir_ / "no-such-log.csv").string();
  const auto run = Run("check '" + kDir + "planar_arm.urdf' --data '" + missing + "'");
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find(missing), std::string::npos) << run.err;
  EXPECT_TRUE(run.out.empty()) << run.out;
  const fs::path bad = dir_ / "bad.csv";
  std::ofstream(bad) << "time,shoulder.q\n0,1\n";  // no torque column
  const auto bad_run = Run("check '" + kDir + "planar_arm.urdf' --data '" + bad.string() + "'");
  EXPECT_EQ(bad_run.code, 2);
  EXPECT_NE(bad_run.err.find("bad.csv"), std::string::npos) << bad_run.err;
}

}  // namespace

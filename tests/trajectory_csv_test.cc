// Recorded trajectories from CSV (massprops/io/trajectory_csv.h): columns read as written,
// velocities and accelerations derived from positions against the analytic derivatives of a
// sinusoid (d/dt A·sin ωt = Aω·cos ωt, d²/dt² = −Aω²·sin ωt), the filter's use on noisy
// positions, and each bad input a clear error with its line.
#include "massprops/io/trajectory_csv.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>

namespace massprops {
namespace {

std::string Messages(const TrajectoryReadResult& r) {
  std::string all;
  for (const ReadError& e : r.errors) all += e.ToString() + "\n";
  return all;
}

// n rows of two joints, a and b, with every column; row k: time k/100, values from k.
std::string FullCsv(int rows) {
  std::ostringstream csv;
  csv << "time,a.q,a.dq,a.ddq,a.tau,b.q,b.dq,b.ddq,b.tau,comment\n";
  for (int k = 0; k < rows; ++k) {
    csv << k * 0.01 << "," << k << "," << 2 * k << "," << 3 * k << "," << 4 * k << "," << -k << ","
        << -2 * k << "," << -3 * k << "," << -4 * k << ",x\n";
  }
  return csv.str();
}

TEST(TrajectoryCsvTest, ReadsEveryColumnAsWritten) {
  const TrajectoryReadResult r = ReadTrajectoryCsv("# recorded\n" + FullCsv(12), "log.csv");
  ASSERT_TRUE(r.ok()) << Messages(r);
  const JointTrajectory& t = *r.trajectory;
  EXPECT_EQ(t.joints, (std::vector<std::string>{"a", "b"}));
  ASSERT_EQ(t.q.rows(), 12);
  EXPECT_DOUBLE_EQ(t.time(11), 0.11);
  EXPECT_EQ(t.q(5, 0), 5);
  EXPECT_EQ(t.dq(5, 0), 10);
  EXPECT_EQ(t.ddq(5, 1), -15);
  EXPECT_EQ(t.tau(11, 1), -44);
  EXPECT_TRUE(t.notes.empty());
}

// q = A·sin(ωt) at 200 Hz for 10 s, f = 0.5 Hz, cutoff 10 Hz: the filter's gain at f is
// 1/(1 + (f/fc)⁴) = 1 − 6e-6, and central differences err by (ωh)²/6 = 1.6e-4 of the amplitude
// (hand-derived Taylor bound), so 1e-3 of Aω (and 2e-3 of Aω²) away from the ends.
TEST(TrajectoryCsvTest, DerivesVelocityAndAccelerationOfASinusoid) {
  const double A = 0.8, w = 2 * M_PI * 0.5, rate = 200;
  std::ostringstream csv;
  csv.precision(17);
  csv << "time,j.q,j.tau\n";
  for (int k = 0; k < 2000; ++k) csv << k / rate << "," << A * std::sin(w * k / rate) << ",0\n";
  const TrajectoryReadResult r = ReadTrajectoryCsv(csv.str(), "sine.csv");
  ASSERT_TRUE(r.ok()) << Messages(r);
  const JointTrajectory& t = *r.trajectory;
  ASSERT_EQ(t.notes.size(), 1u);
  EXPECT_NE(t.notes[0].find("joint 'j': dq and ddq derived from q"), std::string::npos);
  double worst_dq = 0, worst_ddq = 0;
  for (int k = 100; k < 1900; ++k) {
    const double time = t.time(k);
    worst_dq = std::max(worst_dq, std::abs(t.dq(k, 0) - A * w * std::cos(w * time)));
    worst_ddq = std::max(worst_ddq, std::abs(t.ddq(k, 0) + A * w * w * std::sin(w * time)));
  }
  EXPECT_LT(worst_dq, 1e-3 * A * w);
  EXPECT_LT(worst_ddq, 2e-3 * A * w * w);
}

// The same sinusoid stamped irregularly, as a robot's log stamped on arrival is (the Panda log of
// Gaz et al. 2019 varies from 0.7 to 8.8 ms around 1 ms): intervals of 5 ms with every third one
// 3 ms and every seventh 9 ms (median 5 ms; all under a quarter of the 10 Hz filter's period,
// 25 ms). The recording is resampled at 5 ms, said in a note, and the derivatives hold the bounds
// above: linear interpolation over h = 9 ms errs by at most h²/8 = 1.0e-5 s² times the second
// derivative (hand-derived bound of the interpolation error): 1.0e-5·Aω² for q, far under them.
// The velocity column, read as written, is interpolated too: Aω·cos ωt to 1.0e-5·Aω³.
TEST(TrajectoryCsvTest, ResamplesAnIrregularlyStampedRecordingBeforeDeriving) {
  const double A = 0.8, w = 2 * M_PI * 0.5;
  std::ostringstream csv;
  csv.precision(17);
  csv << "time,j.q,j.dq,j.tau\n";
  double time = 0;
  for (int k = 0; time < 10; ++k) {
    csv << time << "," << A * std::sin(w * time) << "," << A * w * std::cos(w * time) << ",0\n";
    time += k % 7 == 6 ? 0.009 : k % 3 == 2 ? 0.003 : 0.005;
  }
  const TrajectoryReadResult r = ReadTrajectoryCsv(csv.str(), "stamped.csv");
  ASSERT_TRUE(r.ok()) << Messages(r);
  const JointTrajectory& t = *r.trajectory;
  ASSERT_EQ(t.notes.size(), 2u);
  EXPECT_NE(t.notes[0].find("interpolated linearly onto"), std::string::npos) << t.notes[0];
  EXPECT_NE(t.notes[1].find("joint 'j': ddq derived from dq"), std::string::npos) << t.notes[1];
  for (Eigen::Index k = 1; k < t.time.size(); ++k) {
    ASSERT_NEAR(t.time(k) - t.time(k - 1), 0.005, 1e-12);
  }
  double worst_q = 0, worst_dq = 0, worst_ddq = 0;
  for (Eigen::Index k = 100; k + 100 < t.time.size(); ++k) {
    const double s = t.time(k);
    worst_q = std::max(worst_q, std::abs(t.q(k, 0) - A * std::sin(w * s)));
    worst_dq = std::max(worst_dq, std::abs(t.dq(k, 0) - A * w * std::cos(w * s)));
    worst_ddq = std::max(worst_ddq, std::abs(t.ddq(k, 0) + A * w * w * std::sin(w * s)));
  }
  EXPECT_LT(worst_q, 1.1e-5 * A * w * w);
  EXPECT_LT(worst_dq, 1.1e-5 * A * w * w * w);
  EXPECT_LT(worst_ddq, 2e-3 * A * w * w);
}

// With encoder-like noise (σ = 1e-3 rad) on the positions, raw central differences amplify it
// to about σ/(h·√2) = 0.14 rad/s at 200 Hz (worst sample over 0.2); the filtered velocity's
// worst error is at least 4 times smaller (measured: 0.032 rad/s).
TEST(TrajectoryCsvTest, TheLowPassFilterKeepsNoiseOutOfTheDerivatives) {
  const double A = 0.8, w = 2 * M_PI * 0.5, rate = 200, sigma = 1e-3;
  std::mt19937_64 rng(41);
  std::normal_distribution<double> noise(0, sigma);
  std::ostringstream csv;
  csv.precision(17);
  csv << "time,j.q,j.tau\n";
  Eigen::VectorXd q(2000);
  for (int k = 0; k < 2000; ++k) {
    q(k) = A * std::sin(w * k / rate) + noise(rng);
    csv << k / rate << "," << q(k) << ",0\n";
  }
  const TrajectoryReadResult r = ReadTrajectoryCsv(csv.str(), "noisy.csv");
  ASSERT_TRUE(r.ok()) << Messages(r);
  double filtered = 0, raw = 0;
  for (int k = 100; k < 1900; ++k) {
    const double truth = A * w * std::cos(w * k / rate);
    filtered = std::max(filtered, std::abs(r.trajectory->dq(k, 0) - truth));
    raw = std::max(raw, std::abs((q(k + 1) - q(k - 1)) * rate / 2 - truth));
  }
  EXPECT_LT(filtered, raw / 4);
  EXPECT_GT(raw, 0.2);
}

TEST(TrajectoryCsvTest, EachBadInputIsAnErrorWithItsLine) {
  const auto error_of = [](const std::string& text, int min_samples = 3) {
    TrajectoryCsvOptions options;
    options.min_samples = min_samples;
    const TrajectoryReadResult r = ReadTrajectoryCsv(text, "bad.csv", options);
    EXPECT_FALSE(r.ok());
    EXPECT_FALSE(r.trajectory.has_value());
    return Messages(r);
  };
  EXPECT_NE(error_of("a.q,a.tau\n1,2\n").find("no 'time' column"), std::string::npos);
  EXPECT_NE(error_of("time,a.q,a.dq\n0,1,2\n").find("joint 'a' has no 'a.tau' column"),
            std::string::npos);
  EXPECT_NE(error_of("time,a.tau\n0,1\n").find("joint 'a' has no 'a.q' column"), std::string::npos);
  EXPECT_NE(error_of("time,a.q,a.tau\n0,1,2\n0.1,nan,2\n0.2,1,2\n")
                .find("bad.csv:3: 'a.q' is 'nan', not a finite number"),
            std::string::npos);
  EXPECT_NE(error_of("time,a.q,a.tau\n0,1,2\n0.1,1,2\n0.1,1,2\n")
                .find("bad.csv:4: time 0.1 is not after the previous sample's"),
            std::string::npos);
  EXPECT_NE(error_of("time,a.q,a.tau\n0,1,2\n0.1,1\n0.2,1,2\n")
                .find("bad.csv:3: 2 fields where the header has 3"),
            std::string::npos);
  EXPECT_NE(error_of("time,a.q,a.tau\n0,1,2\n", 10).find("1 samples; at least 10 are needed"),
            std::string::npos);
  // A gap: 0.2 s where the median is 0.1 s, more than a quarter of the 10 Hz filter's period.
  EXPECT_NE(error_of("time,a.q,a.tau\n0,1,2\n0.1,1,2\n0.3,1,2\n0.4,1,2\n")
                .find("more than a quarter of the filter's period (0.025"),
            std::string::npos);
  EXPECT_NE(error_of("").find("no header row"), std::string::npos);
}

TEST(TrajectoryCsvTest, ACutoffAboveHalfTheSamplingRateIsAnError) {
  TrajectoryCsvOptions options;
  options.cutoff_hz = 60;  // sampled at 100 Hz
  const TrajectoryReadResult r = ReadTrajectoryCsv(
      "time,a.q,a.dq,a.tau\n0,0,0,0\n0.01,1,0,0\n0.02,2,0,0\n0.03,3,0,0\n0.04,4,0,0\n0.05,5,0,0\n"
      "0.06,6,0,0\n0.07,7,0,0\n0.08,8,0,0\n0.09,9,0,0\n",
      "fast.csv", options);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(Messages(r).find("cutoff 60"), std::string::npos) << Messages(r);
}

// testdata/identify/plotjuggler_joint_states.csv has the columns PlotJuggler's CSV export writes
// for a sensor_msgs/JointState topic /joint_states (its ROS parsers name each joint's series
// `<topic>/<joint>/position`, `/velocity`, `/effort`; the export's time column is `__time`), with
// values set by hand: row k at 1764660000 + k/100 s, shoulder q = 0.1·k, dq = 10, effort 1.5·k;
// elbow q = 0.02·k, dq = 2, effort −0.5·k; and the header stamp column, which is not a joint.
TEST(TrajectoryCsvTest, ReadsPlotJugglersJointStateColumns) {
  const TrajectoryReadResult r = ReadTrajectoryCsvFile(std::string(MASSPROPS_TESTDATA_DIR) +
                                                       "/identify/plotjuggler_joint_states.csv");
  ASSERT_TRUE(r.ok()) << Messages(r);
  const JointTrajectory& t = *r.trajectory;
  EXPECT_EQ(t.joints, (std::vector<std::string>{"elbow", "shoulder"}));  // column order
  ASSERT_EQ(t.q.rows(), 12);
  EXPECT_NEAR(t.time(11) - t.time(0), 0.11, 1e-6);
  EXPECT_DOUBLE_EQ(t.q(7, 1), 0.7);
  EXPECT_DOUBLE_EQ(t.dq(7, 1), 10);
  EXPECT_DOUBLE_EQ(t.tau(7, 1), 10.5);
  EXPECT_DOUBLE_EQ(t.q(7, 0), 0.14);
  EXPECT_DOUBLE_EQ(t.tau(7, 0), -3.5);
  // No accelerations in a JointState: derived from the velocities (constant, so 0).
  ASSERT_EQ(t.notes.size(), 2u);
  EXPECT_NE(t.notes[0].find("ddq derived from dq"), std::string::npos);
  EXPECT_NEAR(t.ddq(5, 1), 0, 1e-9);
  // Without the effort columns, the joint is named.
  const TrajectoryReadResult bad =
      ReadTrajectoryCsv("__time,/joint_states/elbow/position\n0,1\n", "pj.csv");
  EXPECT_NE(Messages(bad).find("joint 'elbow' has no 'elbow.tau' column"), std::string::npos)
      << Messages(bad);
}

TEST(TrajectoryCsvTest, AMissingFileIsAnError) {
  const TrajectoryReadResult r = ReadTrajectoryCsvFile("/nonexistent/massprops/log.csv");
  EXPECT_FALSE(r.ok());
  EXPECT_FALSE(r.trajectory.has_value());
}

}  // namespace
}  // namespace massprops

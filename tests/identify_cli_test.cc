// End-to-end tests of `massprops identify ROBOT DATA` (docs/identify.md): the planar two-link arm
// of testdata/identify/planar_arm.urdf (the file's values) and a recording of a different true arm,
// testdata/identify/planar_arm.csv, whose torques tools/make_identify_csv.py computes from the
// closed-form equations of Spong, Hutchinson and Vidyasagar ("Robot Modeling and Control", 2006,
// §7.4), not from massprops' dynamics. Expected values come from the script's TRUE arm:
// m2 = 1.0 kg, lc2 = 0.24 m, I2 = 0.012 kg·m², so the forearm's first moment m2·lc2 = 0.24 kg·m and
// its inertia about the elbow axis I2 + m2·lc2² = 0.0696 kg·m², both determined by the data
// (Khalil and Dombre 2002, §12.4: MX2 and ZZ2 are base parameters of the planar arm).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "massprops/io/model_reader.h"
#include "massprops/io/trajectory_csv.h"
#include "rosbag_writer.h"
#include "tool_runner.h"

namespace {

namespace fs = std::filesystem;

const std::string kDir = std::string(MASSPROPS_TESTDATA_DIR) + "/identify/";

using massprops::test_support::ReadWholeFile;
using ToolRun = massprops::test_support::SplitToolRun;

class IdentifyCliTest : public ::testing::Test {
 public:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "massprops-identify-XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
    fs::copy_file(kDir + "planar_arm.urdf", dir_ / "planar_arm.urdf");
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  ToolRun Run(const std::string& args) { return massprops::test_support::RunToolSplit(args, dir_); }
  const fs::path& dir() const { return dir_; }

  std::string Robot() const { return (dir_ / "planar_arm.urdf").string(); }
  std::string Csv(const std::string& text) {
    const fs::path path = dir_ / "data.csv";
    std::ofstream(path) << text;
    return path.string();
  }

  fs::path dir_;
};

TEST_F(IdentifyCliTest, JsonReportsIdentifiabilityAndTheHeldOutError) {
  const ToolRun run =
      Run("identify --format json --validate 0.25 '" + Robot() + "' '" + kDir + "planar_arm.csv'");
  ASSERT_EQ(run.code, 0) << run.err;
  const nlohmann::json doc = nlohmann::json::parse(run.out);
  // 2 × 10 inertial + 2 × 3 friction columns; the planar arm has 6 inertial base parameters
  // (Khalil and Dombre §12.4) and each joint's viscous, Coulomb and offset columns are
  // independent: 12.
  EXPECT_EQ(doc["identifiability"]["parameters"], 26);
  EXPECT_EQ(doc["identifiability"]["rank"], 12);
  EXPECT_TRUE(doc["identifiability"]["unexcited_links"].empty());
  EXPECT_EQ(doc["training_samples"], 600);
  EXPECT_EQ(doc["validation_samples"], 200);
  ASSERT_EQ(doc["joints"].size(), 2u);
  for (const auto& joint : doc["joints"]) {
    // The noise of the recording is 0.01 N·m (tools/make_identify_csv.py).
    EXPECT_LT(joint["rms_identified"].get<double>(), 0.012) << joint.dump();
    EXPECT_GT(joint["rms_file"].get<double>(), 0.05) << joint.dump();
    EXPECT_LE(joint["rms_identified"].get<double>(),
              joint["rms_least_squares"].get<double>() * 1.02 + 1e-4)
        << joint.dump();
  }
  for (const auto& link : doc["links"]) {
    EXPECT_TRUE(link["identified_consistent"]) << link.dump();
    // The standard errors of the consistent estimate (identify_test checks their values against
    // the spread over noise seeds): present, one per center-of-mass coordinate, not negative.
    EXPECT_GE(link["identified"]["mass_standard_error"].get<double>(), 0) << link.dump();
    ASSERT_EQ(link["identified"]["com_standard_error"].size(), 3u) << link.dump();
    // The forearm's x (along the link) is determined to well under a millimetre with σ 0.01 N·m.
    if (link["link"] == "fore") {
      const double se_x = link["identified"]["com_standard_error"][0];
      EXPECT_GT(se_x, 0) << link.dump();
      EXPECT_LT(se_x, 1e-3) << link.dump();
    }
  }
}

TEST_F(IdentifyCliTest, TextSaysIdentifiabilityFirstThenJointsThenLinks) {
  const ToolRun run = Run("identify '" + Robot() + "' '" + kDir + "planar_arm.csv'");
  ASSERT_EQ(run.code, 0) << run.err;
  const std::size_t id = run.out.find("identifiability: the data determine 12 combinations");
  const std::size_t joints = run.out.find("torque RMS on the held-out samples");
  const std::size_t links = run.out.find("link 'fore':");
  ASSERT_NE(id, std::string::npos) << run.out;
  ASSERT_NE(joints, std::string::npos) << run.out;
  ASSERT_NE(links, std::string::npos) << run.out;
  EXPECT_LT(id, joints);
  EXPECT_LT(joints, links);
  EXPECT_NE(run.out.find(" kg\n", run.out.find("mass 1.2 -> ", links)), std::string::npos);
  EXPECT_NE(run.out.find(" ± ", run.out.find("mass 1.2 -> ", links)), std::string::npos) << run.out;
}

// planar_arm_boxes.urdf: the same arm with a box per link. Each link's estimate is bounded by
// its box's ellipsoid, reported per link with the ratio tr(Q⁻¹(Σ + m·d·dᵀ))/m, recomputed here
// from the reported parameters and the hand ellipsoid of each box (semi-axes √3/2 times its
// sides, identify_ellipsoid_test): at most 1, within Khachiyan's 2% of the tool's own ratio.
// --no-geometry and the file without geometry impose nothing.
TEST_F(IdentifyCliTest, BoxesBoundEachLinkAndTheReportSaysSo) {
  fs::copy_file(kDir + "planar_arm_boxes.urdf", dir_ / "boxes.urdf");
  const std::string boxes = (dir_ / "boxes.urdf").string();
  const ToolRun run = Run("identify --format json '" + boxes + "' '" + kDir + "planar_arm.csv'");
  ASSERT_EQ(run.code, 0) << run.err;
  const nlohmann::json doc = nlohmann::json::parse(run.out);
  EXPECT_EQ(doc["geometry_bound_links"], 2);
  int outside = 0;
  for (const auto& link : doc["links"]) {
    ASSERT_TRUE(link["geometry_bound"]) << link.dump();
    EXPECT_TRUE(link["identified_consistent"]) << link.dump();
    const bool upper = link["link"] == "upper";
    const Eigen::Vector3d x0(upper ? 0.25 : 0.225, 0, 0);
    const Eigen::Vector3d semi =
        std::sqrt(3.0) / 2 *
        (upper ? Eigen::Vector3d(0.5, 0.12, 0.12) : Eigen::Vector3d(0.45, 0.1, 0.1));
    // From the reported parameters [m, h, Ixx, Ixy, Iyy, Ixz, Iyz, Izz] about the origin:
    // S = ½·tr(I)·1 − I = ∫p·pᵀ dm, and ∫(p − x0)(p − x0)ᵀ dm = S − h·x0ᵀ − x0·hᵀ + m·x0·x0ᵀ.
    const auto& pi = link["identified"]["parameters"];
    const double m = pi[0];
    const Eigen::Vector3d h(pi[1].get<double>(), pi[2].get<double>(), pi[3].get<double>());
    Eigen::Matrix3d I;
    I << pi[4], pi[5], pi[7], pi[5], pi[6], pi[8], pi[7], pi[8], pi[9];
    const Eigen::Matrix3d S = 0.5 * I.trace() * Eigen::Matrix3d::Identity() - I;
    const Eigen::Matrix3d about =
        S - h * x0.transpose() - x0 * h.transpose() + m * x0 * x0.transpose();
    const double ratio = (semi.cwiseAbs2().cwiseInverse().asDiagonal() * about).trace() / m;
    const double reported = link["ellipsoid_ratio"]["identified"];
    EXPECT_LE(reported, 1) << link.dump();
    EXPECT_NEAR(ratio, reported, 0.02 * reported) << link.dump();
    if (!link["least_squares_within_geometry"].get<bool>()) ++outside;
    EXPECT_EQ(link["least_squares_within_geometry"].get<bool>(),
              link["ellipsoid_ratio"]["least_squares"].get<double>() <= 1 + 1e-9)
        << link.dump();
  }
  EXPECT_EQ(doc["least_squares_outside_geometry_links"], outside);
  const ToolRun text = Run("identify '" + boxes + "' '" + kDir + "planar_arm.csv'");
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("geometry bound (a density inside the ellipsoid bounding the link's "
                          "geometry): imposed on 2 of 2 links"),
            std::string::npos)
      << text.out;
  EXPECT_NE(
      text.out.find("inside the ellipsoid bounding its geometry", text.out.find("link 'fore'")),
      std::string::npos)
      << text.out;
  for (const std::string& args : {"--no-geometry '" + boxes + "'", "'" + Robot() + "'"}) {
    const ToolRun off = Run("identify --format json " + args + " '" + kDir + "planar_arm.csv'");
    ASSERT_EQ(off.code, 0) << off.err;
    const nlohmann::json none = nlohmann::json::parse(off.out);
    EXPECT_EQ(none["geometry_bound_links"], 0) << args;
    for (const auto& link : none["links"]) {
      EXPECT_FALSE(link["geometry_bound"]) << args;
      EXPECT_TRUE(link["ellipsoid_ratio"].is_null()) << args;
    }
  }
  const ToolRun text_off =
      Run("identify --no-geometry '" + boxes + "' '" + kDir + "planar_arm.csv'");
  EXPECT_NE(text_off.out.find("not imposed (--no-geometry)"), std::string::npos) << text_off.out;
}

TEST_F(IdentifyCliTest, WriteChangesOnlyInertialNumbersToTheTrueArmsOnes) {
  const std::string out = (dir_ / "identified.urdf").string();
  const ToolRun run =
      Run("identify '" + Robot() + "' '" + kDir + "planar_arm.csv' --write '" + out + "'");
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(ReadWholeFile(Robot()),
            ReadWholeFile(kDir + "planar_arm.urdf"));  // the input is untouched
  const massprops::ReadResult read = massprops::ReadModelFile(out);
  ASSERT_TRUE(read.ok() && read.models.size() == 1);
  const massprops::Model& model = read.models[0];
  const massprops::Inertial& fore = *model.links[model.FindLink("fore")].inertial;
  const double cx = fore.X_BBi.p_AB.x();
  EXPECT_NEAR(fore.mass * cx, 0.24, 0.24 * 0.02);  // m2·lc2 of the true arm
  // ZZ2 = I2 + m2·lc2² (about the elbow axis, y), with the written central iyy.
  EXPECT_NEAR(fore.iyy + fore.mass * (cx * cx + fore.X_BBi.p_AB.z() * fore.X_BBi.p_AB.z()), 0.0696,
              0.0696 * 0.02);
  // Only lines inside <inertial> changed: the others are byte for byte the same.
  std::istringstream before(ReadWholeFile(kDir + "planar_arm.urdf")), after(ReadWholeFile(out));
  std::string a, b;
  bool inside = false;
  while (std::getline(before, a) && std::getline(after, b)) {
    if (a.find("<inertial>") != std::string::npos) inside = true;
    if (!inside) {
      EXPECT_EQ(a, b);
    }
    if (a.find("</inertial>") != std::string::npos) inside = false;
  }
}

TEST_F(IdentifyCliTest, JointsMissingOnEitherSideAreErrorsThatNameThem) {
  const std::string csv =
      Csv("time,shoulder.q,shoulder.tau,wrist.q,wrist.tau\n"
          "0,0,0,0,0\n0.01,0,0,0,0\n0.02,0,0,0,0\n0.03,0,0,0,0\n0.04,0,0,0,0\n"
          "0.05,0,0,0,0\n0.06,0,0,0,0\n0.07,0,0,0,0\n0.08,0,0,0,0\n0.09,0,0,0,0\n0.10,0,0,0,0\n");
  const ToolRun run = Run("identify '" + Robot() + "' '" + csv + "'");
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("joint 'elbow' of the model has no columns in the data"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("joint 'wrist' in the data is not a moving joint of the model"),
            std::string::npos)
      << run.err;
  EXPECT_TRUE(run.out.empty());
}

TEST_F(IdentifyCliTest, AMissingColumnIsAnErrorAndNothingIsWritten) {
  const std::string csv = Csv("time,shoulder.q,elbow.q,elbow.tau\n0,0,0,0\n");
  const std::string out = (dir_ / "never.urdf").string();
  const ToolRun run = Run("identify '" + Robot() + "' '" + csv + "' --write '" + out + "'");
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("shoulder"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out));
}

// planar_arm.csv's samples as a rosbag2 file: one sensor_msgs/msg/JointState per row (position,
// velocity, effort; the recording's accelerations are not in a JointState, so the reader derives
// them from the velocities), stamped with the row's time, the joints in reversed order on every
// other message; with a /tf topic beside it.
std::string PlanarArmBag(const fs::path& path) {
  const massprops::TrajectoryReadResult csv =
      massprops::ReadTrajectoryCsvFile(kDir + "planar_arm.csv");
  EXPECT_TRUE(csv.ok());
  const massprops::JointTrajectory& t = *csv.trajectory;
  std::vector<massprops::test_support::TestBagMessage> messages;
  for (Eigen::Index k = 0; k < t.q.rows(); ++k) {
    massprops::test_support::TestJointState m;
    const std::int64_t ns = std::llround(t.time(k) * 1e9);
    m.sec = static_cast<std::int32_t>(100 + ns / 1000000000);
    m.nanosec = static_cast<std::uint32_t>(ns % 1000000000);
    for (Eigen::Index j = 0; j < 2; ++j) {
      const Eigen::Index at = k % 2 == 0 ? j : 1 - j;
      m.name.push_back(t.joints[static_cast<std::size_t>(at)]);
      m.position.push_back(t.q(k, at));
      m.velocity.push_back(t.dq(k, at));
      m.effort.push_back(t.tau(k, at));
    }
    messages.push_back({"/joint_states", 100000000000 + ns, EncodeJointState(m)});
    messages.push_back({"/tf", 100000000000 + ns, {0, 1, 0, 0}});
  }
  EXPECT_EQ(massprops::test_support::WriteTestBag(path.string(),
                                                  {{"/tf", "tf2_msgs/msg/TFMessage"},
                                                   {"/joint_states", "sensor_msgs/msg/JointState"}},
                                                  messages),
            "");
  return path.string();
}

TEST_F(IdentifyCliTest, ReadsARosbagFileAndABagFolder) {
  fs::create_directory(dir_ / "bag");
  std::ofstream(dir_ / "bag" / "metadata.yaml") << "rosbag2_bagfile_information:\n  version: 5\n";
  const std::string db3 = PlanarArmBag(dir_ / "bag" / "bag_0.db3");
  for (const std::string& data : {db3, (dir_ / "bag").string()}) {
    const ToolRun run = Run("identify --format json '" + Robot() + "' '" + data + "'");
    ASSERT_EQ(run.code, 0) << run.err;
    EXPECT_NE(run.err.find("ddq derived from dq"), std::string::npos) << run.err;
    const nlohmann::json doc = nlohmann::json::parse(run.out);
    EXPECT_EQ(doc["identifiability"]["rank"], 12);  // as from the CSV (Khalil and Dombre §12.4)
    EXPECT_EQ(doc["training_samples"], 560);        // 800 messages, 0.3 held out
    for (const auto& joint : doc["joints"]) {
      // The recording's noise is 0.01 N·m; accelerations derived (10 Hz low-pass of a motion
      // below 2 Hz) add little: 1.5 times the noise bounds it, the file's values are 5 times off.
      EXPECT_LT(joint["rms_identified"].get<double>(), 0.015) << joint.dump();
      EXPECT_GT(joint["rms_file"].get<double>(), 0.05) << joint.dump();
    }
  }
}

TEST_F(IdentifyCliTest, ABagWithoutJointStatesIsAnErrorAndNothingIsWritten) {
  const std::string db3 = (dir_ / "tf_only.db3").string();
  ASSERT_EQ(massprops::test_support::WriteTestBag(db3, {{"/tf", "tf2_msgs/msg/TFMessage"}},
                                                  {{"/tf", 1, {0, 1, 0, 0}}}),
            "");
  const std::string out = (dir_ / "never.urdf").string();
  const ToolRun run = Run("identify '" + Robot() + "' '" + db3 + "' --write '" + out + "'");
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find(db3 + ": the bag has no topic of type sensor_msgs/msg/JointState"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(run.out.empty());
}

// The page of --html: Chart.js embedded, and its data block the held-out torques, whose RMS of
// measured minus identified (computed here) is the report's.
TEST_F(IdentifyCliTest, HtmlPlotsTheHeldOutTorquesTheReportMeasures) {
  const std::string page = (dir_ / "identify.html").string();
  const ToolRun run = Run("identify --format json '" + Robot() + "' '" + kDir +
                          "planar_arm.csv' --html '" + page + "'");
  ASSERT_EQ(run.code, 0) << run.err;
  const nlohmann::json report = nlohmann::json::parse(run.out);
  const std::string html = ReadWholeFile(page);
  EXPECT_NE(html.find("Chart.js v3.9"), std::string::npos);
  const std::string open = "<script id=\"identify-data\" type=\"application/json\">";
  const std::size_t from = html.find(open);
  ASSERT_NE(from, std::string::npos);
  const std::size_t to = html.find("</script>", from);
  const nlohmann::json data =
      nlohmann::json::parse(html.substr(from + open.size(), to - from - open.size()));
  EXPECT_EQ(data["first_sample"], 560);  // 800 samples, the last 30% held out
  ASSERT_EQ(data["joints"].size(), 2u);
  for (std::size_t j = 0; j < 2; ++j) {
    const nlohmann::json& joint = data["joints"][j];
    ASSERT_EQ(joint["measured"].size(), 240u);
    double sum = 0;
    for (std::size_t k = 0; k < 240; ++k) {
      const double e = joint["measured"][k].get<double>() - joint["identified"][k].get<double>();
      sum += e * e;
    }
    const double rms = std::sqrt(sum / 240);
    EXPECT_NEAR(rms, report["joints"][j]["rms_identified"].get<double>(), 1e-9 * rms);
  }
}

// The lines of `before` and `after` that differ (their count must match): identify --write may
// change only numbers inside <inertial> elements, so every other line must be byte for byte the
// same (checked line by line, independently of the writer's own diff).
std::vector<std::string> ChangedLines(const std::string& before, const std::string& after) {
  std::istringstream a(before), b(after);
  std::string x, y;
  std::vector<std::string> changed;
  while (std::getline(a, x)) {
    if (!std::getline(b, y)) return {"line count differs"};
    if (x != y) changed.push_back(x);
  }
  if (std::getline(b, y)) return {"line count differs"};
  return changed;
}

// The central rotational inertia, in the body frame, of the written <inertial> (R I R^T) and of
// the report's parameters [m, m·c, I about the body origin] by the parallel-axis theorem
// I_cm = I_o − m (|c|² 1 − c cᵀ) (e.g. Featherstone 2008, eq. 2.63).
Eigen::Matrix3d WrittenCentral(const massprops::Inertial& a) {
  Eigen::Matrix3d I;
  I << a.ixx, a.ixy, a.ixz, a.ixy, a.iyy, a.iyz, a.ixz, a.iyz, a.izz;
  return a.X_BBi.R_AB * I * a.X_BBi.R_AB.transpose();
}
Eigen::Matrix3d ReportedCentral(const nlohmann::json& pi) {
  const double m = pi[0];
  const Eigen::Vector3d c = Eigen::Vector3d(pi[1], pi[2], pi[3]) / m;
  Eigen::Matrix3d I_o;
  I_o << pi[4], pi[5], pi[7], pi[5], pi[6], pi[8], pi[7], pi[8], pi[9];
  return I_o - m * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
}

// Writes the identified values into a copy of the twin `file` and checks them against the JSON
// report: identify writes at least 6 significant digits (RoundedInertial), so mass, center of
// mass and tensor agree to 1e-5 of their scale; returns the written text.
std::string WriteTwinAndCompare(IdentifyCliTest* t, const std::string& file) {
  const fs::path in = t->dir() / file, out = t->dir() / ("identified-" + file);
  fs::copy_file(kDir + file, in);
  const ToolRun run = t->Run("identify --format json '" + in.string() + "' '" + kDir +
                             "planar_arm.csv' --write '" + out.string() + "'");
  EXPECT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.err.find("identified values of 2 link(s) written"), std::string::npos) << run.err;
  EXPECT_EQ(ReadWholeFile(in.string()), ReadWholeFile(kDir + file));  // the input is untouched
  const nlohmann::json doc = nlohmann::json::parse(run.out);
  const massprops::ReadResult read = massprops::ReadModelFile(out.string());
  EXPECT_TRUE(read.ok() && read.models.size() == 1);
  if (!read.ok() || read.models.size() != 1) return "";
  const massprops::Model& model = read.models[0];
  for (const nlohmann::json& link : doc["links"]) {
    const int i = model.FindLink(link["link"].get<std::string>());
    EXPECT_GE(i, 0) << link.dump();
    if (i < 0 || !model.links[i].inertial) continue;
    const massprops::Inertial& a = *model.links[i].inertial;
    const nlohmann::json& id = link["identified"];
    const double m = id["mass"];
    EXPECT_NEAR(a.mass, m, 1e-5 * m) << file;
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(a.X_BBi.p_AB[k], id["com"][k].get<double>(), 1e-5 * 0.5) << file << " " << k;
    }
    const Eigen::Matrix3d written = WrittenCentral(a), reported = ReportedCentral(id["parameters"]);
    EXPECT_LT((written - reported).cwiseAbs().maxCoeff(), 1e-5 * reported.trace())
        << file << "\n"
        << written << "\n"
        << reported;
  }
  return ReadWholeFile(out.string());
}

TEST_F(IdentifyCliTest, WritesTheSdfTwinOnlyInItsInertials) {
  const std::string written = WriteTwinAndCompare(this, "planar_arm.sdf");
  // Only <pose>, <mass> and tensor elements of the two <inertial> blocks change.
  for (const std::string& line : ChangedLines(ReadWholeFile(kDir + "planar_arm.sdf"), written)) {
    const bool inertial_number = line.find("<pose>0.2") != std::string::npos ||
                                 line.find("<mass>") != std::string::npos ||
                                 line.find("<i") != std::string::npos;
    EXPECT_TRUE(inertial_number) << line;
  }
}

TEST_F(IdentifyCliTest, WritesTheMjcfTwinKeepingFullinertiaAndQuatDiaginertia) {
  const std::string written = WriteTwinAndCompare(this, "planar_arm.xml");
  const std::vector<std::string> changed =
      ChangedLines(ReadWholeFile(kDir + "planar_arm.xml"), written);
  ASSERT_EQ(changed.size(), 2u) << written;  // the two <inertial> lines, nothing else
  for (const std::string& line : changed) EXPECT_NE(line.find("<inertial"), std::string::npos);
  // The upper arm's tensor stays fullinertia (body axes, MuJoCo's order ixx iyy izz ixy ixz iyz);
  // the forearm's, written with an orientation, stays quat + diaginertia (principal axes).
  std::istringstream lines(written);
  std::string line, upper, fore;
  while (std::getline(lines, line)) {
    if (line.find("<inertial") == std::string::npos) continue;
    (upper.empty() ? upper : fore) = line;
  }
  EXPECT_NE(upper.find("fullinertia=\""), std::string::npos) << upper;
  EXPECT_EQ(upper.find("diaginertia"), std::string::npos) << upper;
  EXPECT_NE(fore.find("quat=\""), std::string::npos) << fore;
  EXPECT_NE(fore.find("diaginertia=\""), std::string::npos) << fore;
  EXPECT_EQ(fore.find("fullinertia"), std::string::npos) << fore;
}

}  // namespace

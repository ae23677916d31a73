// Tests of the URDF reader (include/massprops/urdf_reader.h) on small fixtures written for them
// (testdata/urdf/) and on inline texts. Expected line numbers are those of the fixtures as written
// (hand-counted); expected numbers are the ones written in the fixtures; rotations are worked out
// by hand from the URDF convention (rpy = fixed-axis roll about x, then pitch about y, then yaw
// about z, i.e. R = Rz(yaw)·Ry(pitch)·Rx(roll); URDF XML specification, <origin> element).

#include "massprops/urdf_reader.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <urdf_model/utils.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace massprops {
namespace {

const std::string kDir = std::string(MASSPROPS_TESTDATA_DIR) + "/urdf/";

ReadResult Read(const std::string& xml) { return ReadUrdfString(xml, "mem.urdf"); }

// The first error, or a failure when there is none.
ReadError FirstError(const ReadResult& result) {
  if (result.errors.empty()) {
    ADD_FAILURE() << "expected an error";
    return {};
  }
  EXPECT_TRUE(result.models.empty()) << "a file with errors yields no model";
  return result.errors.front();
}

std::string AllErrors(const ReadResult& result) {
  std::string text;
  for (const ReadError& e : result.errors) text += e.ToString() + "\n";
  return text;
}

// A one-link robot whose <inertial> is `inertial` (placed on line 3).
std::string OneLink(const std::string& inertial) {
  return "<robot name=\"r\">\n  <link name=\"arm\">\n" + inertial + "\n  </link>\n</robot>\n";
}

Eigen::Matrix3d Rz90() {  // hand-derived: x -> y, y -> -x
  Eigen::Matrix3d R;
  R << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  return R;
}

class FeaturesFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    result_ = ReadUrdfFile(kDir + "features.urdf");
    ASSERT_TRUE(result_.ok()) << AllErrors(result_);
    ASSERT_EQ(result_.models.size(), 1u);
    model_ = &result_.models[0];
  }
  const Link& L(const std::string& name) {
    const int i = model_->FindLink(name);
    if (i < 0) throw std::runtime_error("no link " + name);
    return model_->links[i];
  }
  ReadResult result_;
  const Model* model_ = nullptr;
};

TEST_F(FeaturesFixture, ReadsRobotLinksAndJointsInFileOrder) {
  EXPECT_EQ(model_->name, "features");
  EXPECT_EQ(model_->format, Model::Format::kUrdf);
  EXPECT_EQ(model_->file, kDir + "features.urdf");
  EXPECT_EQ(model_->location.line, 3);
  ASSERT_EQ(model_->links.size(), 4u);
  EXPECT_EQ(model_->links[0].name, "base");
  EXPECT_EQ(model_->links[1].name, "arm");
  EXPECT_EQ(model_->links[2].name, "tool");
  EXPECT_EQ(model_->links[3].name, "wheel");
  ASSERT_EQ(model_->joints.size(), 3u);
  EXPECT_EQ(model_->joints[0].name, "shoulder");
  EXPECT_EQ(model_->joints[1].name, "wrist");
  EXPECT_EQ(model_->joints[2].name, "spin");
  EXPECT_EQ(model_->root_link, "base");
  EXPECT_TRUE(result_.warnings.empty());
}

TEST_F(FeaturesFixture, KeepsInertialNumbersExactlyAsWritten) {
  const Link& base = L("base");
  ASSERT_TRUE(base.inertial.has_value());
  const Inertial& i = *base.inertial;
  EXPECT_EQ(i.mass, 2.5);
  EXPECT_EQ(i.ixx, 0.1);
  EXPECT_EQ(i.ixy, -0.01);
  EXPECT_EQ(i.ixz, 0.02);
  EXPECT_EQ(i.iyy, 0.2);
  EXPECT_EQ(i.iyz, -0.03);
  EXPECT_EQ(i.izz, 0.3);
  EXPECT_EQ(i.X_BBi.p_AB, Eigen::Vector3d(0.1, -0.2, 0.3));
  EXPECT_TRUE(i.X_BBi.R_AB.isApprox(Rz90(), 1e-15));
  // Exponent forms and an explicit plus sign, as written on lines 23-24.
  const Inertial& a = *L("arm").inertial;
  EXPECT_EQ(a.mass, 1e-3);
  EXPECT_EQ(a.ixx, 1e-6);
  EXPECT_EQ(a.iyy, 2e-6);
  EXPECT_EQ(a.izz, 3e-6);
  EXPECT_TRUE(a.X_BBi.IsIdentity()) << "a missing <origin> is the identity";
}

TEST_F(FeaturesFixture, RecordsTheLineOfEveryElement) {
  const Link& base = L("base");
  EXPECT_EQ(base.location.line, 5);
  EXPECT_EQ(base.location.file, kDir + "features.urdf");
  EXPECT_EQ(base.inertial->location.line, 7);
  EXPECT_EQ(base.inertial->pose_location.line, 8);
  EXPECT_EQ(base.inertial->mass_location.line, 9);
  EXPECT_EQ(base.inertial->inertia_location.line, 10);
  EXPECT_EQ(base.geometries.at(0).location.line, 12);
  EXPECT_EQ(base.geometries.at(1).location.line, 16);
  const Link& arm = L("arm");
  EXPECT_EQ(arm.location.line, 21);
  EXPECT_EQ(arm.inertial->location.line, 22);
  EXPECT_EQ(arm.inertial->pose_location.line, 0) << "no <origin>: line 0";
  EXPECT_EQ(arm.inertial->mass_location.line, 23);
  EXPECT_EQ(arm.inertial->inertia_location.line, 24);
  EXPECT_EQ(L("tool").location.line, 38);
  EXPECT_EQ(L("wheel").location.line, 54);
  EXPECT_EQ(model_->joints[0].location.line, 39);
  EXPECT_EQ(model_->joints[1].location.line, 46);
  EXPECT_EQ(model_->joints[2].location.line, 50);
  EXPECT_EQ(model_->joints[0].location.column, 0);
}

TEST_F(FeaturesFixture, MissingInertialIsAbsentNotZero) {
  EXPECT_FALSE(L("tool").inertial.has_value());
  EXPECT_FALSE(L("wheel").inertial.has_value());
}

TEST_F(FeaturesFixture, ReadsEveryGeometryTypeWithItsPose) {
  const Link& base = L("base");
  ASSERT_EQ(base.geometries.size(), 2u);
  const Geometry& box = base.geometries[0];
  EXPECT_EQ(box.type, Geometry::Type::kBox);
  EXPECT_TRUE(box.is_collision);
  EXPECT_EQ(box.size, Eigen::Vector3d(0.4, 0.3, 0.1));
  EXPECT_EQ(box.X_BG.p_AB, Eigen::Vector3d(0, 0, 0.05));
  EXPECT_TRUE(box.X_BG.R_AB.isIdentity(0)) << "origin without rpy: no rotation";
  const Geometry& cylinder = base.geometries[1];
  EXPECT_EQ(cylinder.type, Geometry::Type::kCylinder);
  EXPECT_FALSE(cylinder.is_collision);
  EXPECT_EQ(cylinder.radius, 0.05);
  EXPECT_EQ(cylinder.length, 0.2);

  const Link& arm = L("arm");
  ASSERT_EQ(arm.geometries.size(), 3u);
  const Geometry& mesh = arm.geometries[0];
  EXPECT_EQ(mesh.type, Geometry::Type::kMesh);
  EXPECT_FALSE(mesh.is_collision);
  EXPECT_EQ(mesh.uri, "package://features/arm.stl");
  EXPECT_EQ(mesh.scale, Eigen::Vector3d(0.001, 0.001, 0.001));
  Eigen::Matrix3d Rx90;  // hand-derived: y -> z, z -> -y
  Rx90 << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  EXPECT_TRUE(mesh.X_BG.R_AB.isApprox(Rx90, 1e-15));
  EXPECT_EQ(arm.geometries[1].type, Geometry::Type::kSphere);
  EXPECT_EQ(arm.geometries[1].radius, 0.02);
  EXPECT_EQ(arm.geometries[1].location.line, 30);
  EXPECT_EQ(arm.geometries[2].type, Geometry::Type::kCapsule);
  EXPECT_EQ(arm.geometries[2].radius, 0.01);
  EXPECT_EQ(arm.geometries[2].length, 0.1);
  EXPECT_EQ(arm.geometries[2].location.line, 34);
}

TEST_F(FeaturesFixture, ReadsJointsWithOriginsAxesAndDefaults) {
  const Joint& shoulder = model_->joints[0];
  EXPECT_EQ(shoulder.type, Joint::Type::kRevolute);
  EXPECT_EQ(shoulder.type_name, "revolute");
  EXPECT_EQ(shoulder.parent, "base");
  EXPECT_EQ(shoulder.child, "arm");
  EXPECT_EQ(shoulder.X_PC.p_AB, Eigen::Vector3d(0, 0, 0.5));
  // rpy = (0.1, 0.2, 0.3): fixed axes x, y, z = Rz(0.3)·Ry(0.2)·Rx(0.1), built here from
  // angle-axis.
  const Eigen::Matrix3d expected = (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  EXPECT_TRUE(shoulder.X_PC.R_AB.isApprox(expected, 1e-14));
  EXPECT_EQ(shoulder.axis, Eigen::Vector3d(0, 0, 1)) << "axis (0 0 2) normalized";
  const Joint& wrist = model_->joints[1];
  EXPECT_EQ(wrist.type, Joint::Type::kFixed);
  EXPECT_TRUE(wrist.X_PC.IsIdentity()) << "missing <origin> = identity";
  const Joint& spin = model_->joints[2];
  EXPECT_EQ(spin.type, Joint::Type::kContinuous);
  EXPECT_EQ(spin.axis, Eigen::Vector3d(1, 0, 0)) << "URDF default axis";
  EXPECT_EQ(model_->FindParentJoint("arm"), 0);
  EXPECT_EQ(model_->FindParentJoint("base"), -1);
  EXPECT_EQ(model_->FindLink("nope"), -1);
}

TEST_F(FeaturesFixture, IgnoreCommentsAnywhereInsideALinkAreCollected) {
  EXPECT_EQ(L("base").ignored_rules,
            (std::vector<std::string>{"inertia-not-physical", "mass-zero"}));
  EXPECT_EQ(L("arm").ignored_rules, (std::vector<std::string>{"all"}))
      << "the comment on line 32 is nested in a <collision>";
  EXPECT_TRUE(L("tool").ignored_rules.empty());
}

TEST(UrdfReaderTest, ReadsFromTextWithTheGivenFileName) {
  const ReadResult result = ReadUrdfString(OneLink(""), "<stdin>");
  ASSERT_TRUE(result.ok()) << AllErrors(result);
  EXPECT_EQ(result.models.at(0).links.at(0).location.file, "<stdin>");
  EXPECT_EQ(result.models.at(0).links.at(0).location.line, 2);
  EXPECT_EQ(result.models.at(0).root_link, "arm");
}

TEST(UrdfReaderTest, RollPitchYawMatchesTheFixedAxisConvention) {
  // Each angle alone, then all three: compared with products of elementary rotations.
  const double r = 0.7, p = -0.4, y = 2.1;
  const ReadResult result =
      Read("<robot name=\"r\"><link name=\"a\"><visual><origin rpy=\"" + std::to_string(r) + " " +
           std::to_string(p) + " " + std::to_string(y) +
           "\"/><geometry><sphere radius=\"1\"/></geometry></visual>"
           "</link></robot>");
  ASSERT_TRUE(result.ok()) << AllErrors(result);
  const double rr = std::stod(std::to_string(r)), pp = std::stod(std::to_string(p)),
               yy = std::stod(std::to_string(y));
  const Eigen::Matrix3d expected = (Eigen::AngleAxisd(yy, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(pp, Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(rr, Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  EXPECT_TRUE(result.models[0].links[0].geometries[0].X_BG.R_AB.isApprox(expected, 1e-14));
}

// ---------------------------------------------------------------- numbers

TEST(UrdfNumberTest, AcceptsExactlyWhatUrdfdomAccepts) {
  // The oracle is urdfdom's own urdf::strToDouble (urdf_model/utils.h): same verdict, same bits.
  const char* texts[] = {"1",
                         " 1",
                         "\t2.5",
                         "1 ",
                         "1\t",
                         "+1",
                         "-0",
                         ".5",
                         "5.",
                         "1.e5",
                         "1e5",
                         "1E+5",
                         "1e-5",
                         "00012",
                         "-.5e-3",
                         "1e400",
                         "-1e400",
                         "1e-310",
                         "1e-400",
                         "-1e-400",
                         "2e-324",
                         "4.9e-324",
                         "1.7976931348623157e308",
                         "1.7976931348623159e308",
                         "nan",
                         "NaN",
                         "inf",
                         "-inf",
                         "Infinity",
                         "0x10",
                         "1.0abc",
                         "1,5",
                         "abc",
                         "",
                         " ",
                         "1e",
                         "1e+",
                         "e5",
                         "--1",
                         "+-1",
                         ".",
                         "+.",
                         "1..2",
                         "1e5.5",
                         "0.1000000000000000055511151231257827",
                         "123456789012345678901234567890",
                         "1e-320",
                         "0e999999999999"};
  for (const char* text : texts) {
    bool urdfdom_ok = true;
    double urdfdom_value = 0;
    try {
      urdfdom_value = urdf::strToDouble(text);
    } catch (const std::runtime_error&) {
      urdfdom_ok = false;
    }
    double value = 12345;
    const UrdfNumberStatus status = ParseUrdfNumber(text, &value);
    EXPECT_EQ(status == UrdfNumberStatus::kOk, urdfdom_ok) << "text: [" << text << "]";
    if (urdfdom_ok && status == UrdfNumberStatus::kOk) {
      EXPECT_EQ(std::signbit(value), std::signbit(urdfdom_value)) << text;
      EXPECT_EQ(value, urdfdom_value) << text;
    }
  }
}

TEST(UrdfNumberTest, ClassifiesWhyATextIsRejected) {
  double v = 0;
  EXPECT_EQ(ParseUrdfNumber("nan", &v), UrdfNumberStatus::kNotFinite);
  EXPECT_EQ(ParseUrdfNumber("-Inf", &v), UrdfNumberStatus::kNotFinite);
  EXPECT_EQ(ParseUrdfNumber("1e400", &v), UrdfNumberStatus::kOutOfRange);
  EXPECT_EQ(ParseUrdfNumber("1,5", &v), UrdfNumberStatus::kNotANumber);
  EXPECT_EQ(ParseUrdfNumber("abc", &v), UrdfNumberStatus::kNotANumber);
  EXPECT_EQ(ParseUrdfNumber("1.0abc", &v), UrdfNumberStatus::kNotANumber);
  ASSERT_EQ(ParseUrdfNumber("-1e-400", &v), UrdfNumberStatus::kOk);
  EXPECT_EQ(v, 0.0);
  EXPECT_TRUE(std::signbit(v)) << "underflow keeps the sign, as strtod does";
}

TEST(UrdfReaderTest, NumbersInTheFixtureAreRejectedWithElementLineAndQuotedText) {
  const ReadResult result = ReadUrdfFile(kDir + "bad_numbers.urdf");
  ASSERT_EQ(result.errors.size(), 3u) << AllErrors(result);
  EXPECT_TRUE(result.models.empty());
  EXPECT_EQ(result.errors[0].location.line, 4);
  EXPECT_EQ(result.errors[0].element, "<mass> of link 'comma'");
  EXPECT_NE(result.errors[0].message.find("\"1,5\" is not a number"), std::string::npos);
  EXPECT_EQ(result.errors[1].location.line, 11);
  EXPECT_EQ(result.errors[1].element, "<inertia> of link 'nan'");
  EXPECT_NE(result.errors[1].message.find("'ixx' = \"nan\" is not a finite number"),
            std::string::npos);
  EXPECT_EQ(result.errors[2].location.line, 16);
  EXPECT_EQ(result.errors[2].element, "<origin> of <inertial> of link 'overflow'");
  EXPECT_NE(result.errors[2].message.find("\"1e400\" is out of the range"), std::string::npos);
  EXPECT_EQ(result.errors[2].ToString(),
            kDir + "bad_numbers.urdf:16: <origin> of <inertial> of link 'overflow': " +
                result.errors[2].message);
}

TEST(UrdfReaderTest, TextAfterANumberIsRejected) {
  const ReadError e = FirstError(Read(OneLink(
      "<inertial><mass value=\"1.0abc\"/>"
      "<inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial>")));
  EXPECT_EQ(e.location.line, 3);
  EXPECT_NE(e.message.find("\"1.0abc\" is not a number"), std::string::npos) << e.message;
}

TEST(UrdfReaderTest, VectorsNeedExactlyThreeSpaceSeparatedNumbers) {
  const ReadError two = FirstError(Read(OneLink(
      "<inertial><origin xyz=\"1 2\"/><mass value=\"1\"/>"
      "<inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial>")));
  EXPECT_NE(two.message.find("has 2 numbers, 3 expected"), std::string::npos) << two.message;
  // urdfdom splits on spaces only, so a tab inside a vector is an error there too.
  const ReadError tab = FirstError(Read(OneLink(
      "<inertial><origin xyz=\"1\t2 3\"/><mass value=\"1\"/>"
      "<inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial>")));
  EXPECT_NE(tab.message.find("not tabs"), std::string::npos) << tab.message;
  const ReadResult spaces = Read(
      OneLink("<inertial><origin xyz=\"  1  2 3 \"/><mass value=\"1\"/>"
              "<inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial>"));
  ASSERT_TRUE(spaces.ok()) << AllErrors(spaces);
  EXPECT_EQ(spaces.models[0].links[0].inertial->X_BBi.p_AB, Eigen::Vector3d(1, 2, 3));
}

// ---------------------------------------------------------------- missing pieces

TEST(UrdfReaderTest, InertialWithoutMassOrInertiaIsAnErrorAsInUrdfdom) {
  // urdfdom 3 (link.cpp parseInertial) fails on a missing <mass> and on a missing <inertia>.
  const ReadError no_mass = FirstError(Read(
      OneLink("<inertial><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/>"
              "</inertial>")));
  EXPECT_EQ(no_mass.location.line, 3);
  EXPECT_EQ(no_mass.element, "<inertial> of link 'arm'");
  EXPECT_NE(no_mass.message.find("<mass>"), std::string::npos);
  const ReadError no_inertia =
      FirstError(Read(OneLink("<inertial><mass value=\"1\"/></inertial>")));
  EXPECT_NE(no_inertia.message.find("<inertia>"), std::string::npos);
  const ReadError no_value =
      FirstError(Read(OneLink("<inertial><mass/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" "
                              "iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial>")));
  EXPECT_EQ(no_value.element, "<mass> of link 'arm'");
  EXPECT_NE(no_value.message.find("missing required attribute 'value'"), std::string::npos);
  const ReadError no_iyz = FirstError(Read(OneLink(
      "<inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" izz=\"1\"/>"
      "</inertial>")));
  EXPECT_NE(no_iyz.message.find("'iyz'"), std::string::npos);
}

TEST(UrdfReaderTest, MissingNamesAndTypesAreErrors) {
  EXPECT_NE(FirstError(Read("<robot><link name=\"a\"/></robot>")).message.find("'name'"),
            std::string::npos);
  EXPECT_EQ(FirstError(Read("<robot name=\"r\">\n<link/></robot>")).location.line, 2);
  const ReadError no_type =
      FirstError(Read("<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/>\n<joint name=\"j\">"
                      "<parent link=\"a\"/><child link=\"b\"/></joint></robot>"));
  EXPECT_EQ(no_type.location.line, 2);
  EXPECT_NE(no_type.message.find("'type'"), std::string::npos);
  EXPECT_NE(FirstError(Read("<robot name=\"r\"></robot>")).message.find("no <link>"),
            std::string::npos);
}

TEST(UrdfReaderTest, UnknownJointAndGeometryTypesAreErrors) {
  const ReadError spherical = FirstError(
      Read("<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/><joint name=\"j\" "
           "type=\"spherical\"><parent link=\"a\"/><child link=\"b\"/></joint></robot>"));
  EXPECT_NE(spherical.message.find("\"spherical\""), std::string::npos);
  const ReadError cone = FirstError(
      Read("<robot name=\"r\"><link name=\"a\"><collision><geometry>\n<cone radius=\"1\"/>"
           "</geometry></collision></link></robot>"));
  EXPECT_EQ(cone.location.line, 2);
  EXPECT_EQ(cone.element, "<cone> of <collision> #1 of link 'a'");
  const ReadError empty = FirstError(
      Read("<robot name=\"r\"><link name=\"a\"><visual><geometry/></visual></link></robot>"));
  EXPECT_NE(empty.message.find("no shape"), std::string::npos);
}

TEST(UrdfReaderTest, RevoluteAndPrismaticJointsNeedLimitsAsInUrdfdom) {
  const ReadError e = FirstError(
      Read("<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/><joint name=\"j\" "
           "type=\"prismatic\"><parent link=\"a\"/><child link=\"b\"/></joint></robot>"));
  EXPECT_NE(e.message.find("<limit>"), std::string::npos);
  const ReadError bad_limit = FirstError(
      Read("<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/><joint name=\"j\" "
           "type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/><limit lower=\"-1.57.\" "
           "effort=\"1\" velocity=\"1\"/></joint></robot>"));
  EXPECT_NE(bad_limit.message.find("\"-1.57.\""), std::string::npos);
}

TEST(UrdfReaderTest, OnlyUrdfVersionOneIsAccepted) {
  EXPECT_TRUE(Read("<robot name=\"r\" version=\"1.0\"><link name=\"a\"/></robot>").ok());
  EXPECT_NE(FirstError(Read("<robot name=\"r\" version=\"2.0\"><link name=\"a\"/></robot>"))
                .message.find("version"),
            std::string::npos);
}

// ---------------------------------------------------------------- tree errors

TEST(UrdfReaderTest, DuplicateLinkAndJointNamesAreErrors) {
  const ReadError link =
      FirstError(Read("<robot name=\"r\">\n<link name=\"a\"/>\n"
                      "<link name=\"a\"/></robot>"));
  EXPECT_EQ(link.location.line, 3);
  EXPECT_NE(link.message.find("already defined at line 2"), std::string::npos);
  const ReadError joint = FirstError(
      Read("<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/>\n"
           "<joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>\n"
           "<joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>"
           "</robot>"));
  EXPECT_EQ(joint.location.line, 3);
  EXPECT_EQ(joint.element, "<joint> 'j'");
}

TEST(UrdfReaderTest, JointsNamingMissingLinksAreErrors) {
  const ReadError e =
      FirstError(Read("<robot name=\"r\"><link name=\"a\"/>\n<joint name=\"j\" type=\"fixed\">"
                      "<parent link=\"a\"/><child link=\"ghost\"/></joint></robot>"));
  EXPECT_EQ(e.location.line, 2);
  EXPECT_NE(e.message.find("child link 'ghost' is not defined"), std::string::npos);
  const ReadError no_parent =
      FirstError(Read("<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/><joint name=\"j\" "
                      "type=\"fixed\"><child link=\"b\"/></joint></robot>"));
  EXPECT_NE(no_parent.message.find("<parent link=...>"), std::string::npos);
}

TEST(UrdfReaderTest, SeveralRootsAreAnErrorListingThem) {
  const ReadError e =
      FirstError(Read("<robot name=\"r\">\n<link name=\"a\"/>\n"
                      "<link name=\"b\"/>\n</robot>"));
  EXPECT_EQ(e.location.line, 3) << "points at the second root";
  EXPECT_NE(e.message.find("2 root links"), std::string::npos);
  EXPECT_NE(e.message.find("'a' (line 2), 'b' (line 3)"), std::string::npos) << e.message;
}

TEST(UrdfReaderTest, KinematicLoopsAreErrorsEvenBesideARoot) {
  // loop.urdf: root -> a, and b <-> c (urdfdom 3 accepts this file: its root search only looks
  // for parentless links).
  const ReadError e = FirstError(ReadUrdfFile(kDir + "loop.urdf"));
  EXPECT_NE(e.message.find("kinematic loop"), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("'b' -> 'c' -> 'b'"), std::string::npos) << e.message;
  EXPECT_EQ(e.location.line, 8);
  // Everything a loop: no root at all.
  const ReadError all = FirstError(
      Read("<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/>"
           "<joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>"
           "<joint name=\"k\" type=\"fixed\"><parent link=\"b\"/><child link=\"a\"/></joint>"
           "</robot>"));
  EXPECT_NE(all.message.find("kinematic loop"), std::string::npos);
  const ReadError self =
      FirstError(Read("<robot name=\"r\"><link name=\"a\"/><joint name=\"j\" type=\"fixed\">"
                      "<parent link=\"a\"/><child link=\"a\"/></joint></robot>"));
  EXPECT_NE(self.message.find("to itself"), std::string::npos);
}

TEST(UrdfReaderTest, ALinkWithTwoParentJointsIsAnError) {
  const ReadError e = FirstError(
      Read("<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/><link name=\"c\"/>\n"
           "<joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"c\"/></joint>\n"
           "<joint name=\"k\" type=\"fixed\"><parent link=\"b\"/><child link=\"c\"/></joint>"
           "</robot>"));
  EXPECT_EQ(e.location.line, 3);
  EXPECT_NE(e.message.find("already the child of joint 'j' (line 2)"), std::string::npos);
}

// ---------------------------------------------------------------- bad files

TEST(UrdfReaderTest, MalformedXmlIsReportedWithTheLineOfTheUnclosedElement) {
  const ReadError e = FirstError(ReadUrdfFile(kDir + "malformed.urdf"));
  EXPECT_EQ(e.location.line, 4) << "the <inertial> opened on line 4 is never closed";
  EXPECT_EQ(e.element, "XML");
  EXPECT_NE(e.message.find("inertial"), std::string::npos) << e.message;
}

TEST(UrdfReaderTest, EmptyAndBlankFilesAreErrors) {
  EXPECT_NE(FirstError(Read("")).message.find("empty"), std::string::npos);
  EXPECT_NE(FirstError(Read(" \n\t\n")).message.find("empty"), std::string::npos);
}

TEST(UrdfReaderTest, ADocumentThatIsNotUrdfIsAnError) {
  const ReadError e = FirstError(Read("<?xml version=\"1.0\"?>\n<sdf version=\"1.9\"/>"));
  EXPECT_EQ(e.location.line, 2);
  EXPECT_NE(e.message.find("<sdf>"), std::string::npos);
}

TEST(UrdfReaderTest, BinaryGarbageNeverCrashesAndAlwaysErrs) {
  std::string with_nul = OneLink("");
  with_nul.insert(with_nul.find("</robot>"), std::string("\n\0\x01", 3));
  const ReadError nul = FirstError(Read(with_nul));
  EXPECT_NE(nul.message.find("NUL byte"), std::string::npos);
  // OneLink puts </robot> on line 5; the inserted line break moves the NUL to line 6.
  EXPECT_EQ(nul.location.line, 6);
  std::mt19937 random(12345);
  for (int trial = 0; trial < 300; ++trial) {
    std::string bytes(1 + random() % 2000, '\0');
    for (char& c : bytes) c = static_cast<char>(random() % 256);
    if (trial % 3 == 0) bytes = "<robot name=\"r\"><link name=\"" + bytes;  // garbage mid-file
    const ReadResult result = Read(bytes);
    EXPECT_FALSE(result.ok()) << "trial " << trial;
    EXPECT_TRUE(result.models.empty());
  }
}

TEST(UrdfReaderTest, ADirectoryOrAMissingFileIsAnError) {
  const ReadError dir = FirstError(ReadUrdfFile(kDir));
  EXPECT_NE(dir.message.find("directory"), std::string::npos);
  const ReadError missing = FirstError(ReadUrdfFile(kDir + "no_such_file.urdf"));
  EXPECT_EQ(missing.location.file, kDir + "no_such_file.urdf");
  EXPECT_NE(missing.message.find("cannot open"), std::string::npos);
}

long PeakRssKiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

TEST(UrdfReaderTest, AFileAboveTheLimitIsRefusedWithoutReadingIt) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "massprops_urdf_too_large.urdf";
  {
    std::ofstream out(path, std::ios::binary);
    out << "<robot name=\"big\">";
  }
  std::filesystem::resize_file(path, kMaxUrdfFileBytes + 1);  // sparse: costs no disk
  const long before = PeakRssKiB();
  const ReadError e = FirstError(ReadUrdfFile(path.string()));
  EXPECT_NE(e.message.find("larger than the limit"), std::string::npos) << e.message;
  EXPECT_LT(PeakRssKiB() - before, 16 * 1024) << "KiB: the file was not read into memory";
  std::filesystem::remove(path);
}

TEST(UrdfReaderTest, AHundredMegabyteFileIsReadWithBoundedMemory) {
  // A chain of links whose <inertial>s carry long comments, 100 MB in all.
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "massprops_urdf_100mb.urdf";
  const std::string padding(1000, 'x');
  int links = 0;
  std::uintmax_t size = 0;
  {
    std::ofstream out(path, std::ios::binary);
    out << "<robot name=\"big\">\n";
    while (out.tellp() < 100'000'000) {
      out << "<link name=\"l" << links << "\"><inertial><mass value=\"1\"/><inertia ixx=\"1\" "
          << "ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/><!-- " << padding
          << " --></inertial></link>\n";
      if (links > 0) {
        out << "<joint name=\"j" << links << "\" type=\"fixed\"><parent link=\"l" << links - 1
            << "\"/><child link=\"l" << links << "\"/></joint>\n";
      }
      ++links;
    }
    out << "</robot>\n";
    size = static_cast<std::uintmax_t>(out.tellp());
  }
  const long before = PeakRssKiB();
  const ReadResult result = ReadUrdfFile(path.string());
  const long grown_kib = PeakRssKiB() - before;
  std::filesystem::remove(path);
  ASSERT_TRUE(result.ok()) << AllErrors(result);
  EXPECT_EQ(result.models.at(0).links.size(), static_cast<std::size_t>(links));
  // Line 1 <robot>, line 2 l0, then l_k on line 2k+1 and j_k on line 2k+2.
  EXPECT_EQ(result.models[0].links.back().location.line, 2 * links - 1);
#if !defined(__SANITIZE_ADDRESS__)
  // The documented bound: about 4 to 6 times the file size at peak.
  EXPECT_LT(static_cast<double>(grown_kib) * 1024, 6.0 * static_cast<double>(size))
      << "peak grew by " << grown_kib / 1024 << " MiB for a " << size / (1 << 20) << " MiB file";
#else
  (void)grown_kib;
  (void)size;
#endif
}

}  // namespace
}  // namespace massprops

// Tests of the SDF reader on the fixtures of testdata/sdf/ and on inline bad input.
// Expected poses are hand-derived below (Rz(90°) maps (x, y, z) to (-y, x, z)); the same fixtures
// are also compared with libsdformat 12 in sdf_reader_sdformat_test.cc.

#include "massprops/sdf_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "massprops/model.h"

namespace massprops {
namespace {

const std::string kDir = std::string(MASSPROPS_TESTDATA_DIR) + "/sdf";

SdfReadOptions FixtureOptions() {
  SdfReadOptions options;
  options.model_paths = {kDir + "/models"};
  options.use_environment = false;
  return options;
}

Eigen::Matrix3d Rz90() {
  Eigen::Matrix3d R;
  R << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  return R;
}

void ExpectPose(const Pose& X, const Eigen::Vector3d& p, const Eigen::Matrix3d& R) {
  EXPECT_LT((X.p_AB - p).norm(), 1e-12) << X.p_AB.transpose() << " expected " << p.transpose();
  EXPECT_LT((X.R_AB - R).cwiseAbs().maxCoeff(), 1e-12) << X.R_AB << "\nexpected\n" << R;
}

const Link& LinkNamed(const Model& m, const std::string& name) {
  const int i = m.FindLink(name);
  EXPECT_GE(i, 0) << name;
  return m.links.at(static_cast<size_t>(i));
}

const Joint& JointNamed(const Model& m, const std::string& name) {
  for (const Joint& j : m.joints) {
    if (j.name == name) return j;
  }
  ADD_FAILURE() << "no joint " << name;
  return m.joints.at(0);
}

// ---------------------------------------------------------------- frames (SDF 1.8)

TEST(SdfReaderTest, RelativeToChainsFramesAndNestedModelsResolveToHandDerivedPoses) {
  std::vector<SdfModelFrames> frames;
  const ReadResult r = ReadSdfFile(kDir + "/frames_1_8.sdf", FixtureOptions(), &frames);
  ASSERT_TRUE(r.ok()) << r.errors.front().ToString();
  ASSERT_EQ(r.models.size(), 1u);
  const Model& m = r.models[0];
  EXPECT_EQ(m.name, "arm");
  EXPECT_EQ(m.format, Model::Format::kSdf);
  ASSERT_EQ(m.links.size(), 4u);
  EXPECT_EQ(m.links[3].name, "hand::palm");  // scoped name of a nested model's link
  ASSERT_EQ(frames.size(), 1u);
  ASSERT_EQ(frames[0].X_MB.size(), 4u);
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  // Hand-derived: base at the model origin.
  ExpectPose(frames[0].X_MB[0], {0, 0, 0}, I);
  // upper = F * (0 2 0): F = (1 0 0, yaw 90°) so p = (1,0,0) + Rz90*(0,2,0) = (-1,0,0), R = Rz90.
  ExpectPose(frames[0].X_MB[1], {-1, 0, 0}, Rz90());
  // tool = shoulder * (0 0 1); shoulder = upper * (0 0 0.25): p = (-1,0,1.25), R = Rz90.
  ExpectPose(frames[0].X_MB[2], {-1, 0, 1.25}, Rz90());
  // hand = tool * (0 0 0.5); palm = hand * (0.1 0 0): p = (-1,0,1.75) + Rz90*(0.1,0,0).
  ExpectPose(frames[0].X_MB[3], {-1, 0.1, 1.75}, Rz90());
  // The model pose (10 0 0) is the model frame in the world.
  ExpectPose(frames[0].X_WM, {10, 0, 0}, I);
  EXPECT_EQ(m.root_link, "base");
}

TEST(SdfReaderTest, JointPosesAreChildInParentFromTheResolvedLinkPoses) {
  const ReadResult r = ReadSdfFile(kDir + "/frames_1_8.sdf", FixtureOptions());
  ASSERT_TRUE(r.ok());
  const Model& m = r.models[0];
  ASSERT_EQ(m.joints.size(), 4u);
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const Joint& shoulder = JointNamed(m, "shoulder");
  EXPECT_EQ(shoulder.type, Joint::Type::kRevolute);
  EXPECT_EQ(shoulder.type_name, "revolute");
  EXPECT_EQ(shoulder.parent, "base");
  EXPECT_EQ(shoulder.child, "upper");
  ExpectPose(shoulder.X_PC, {-1, 0, 0}, Rz90());  // base is the identity: X_PC = X_M,upper
  // Axis (1 0 0) expressed in __model__, re-expressed in upper: Rz90^T*(1,0,0) = (0,-1,0).
  EXPECT_LT((shoulder.axis - Eigen::Vector3d(0, -1, 0)).norm(), 1e-12) << shoulder.axis;
  EXPECT_EQ(shoulder.location.line, 34);
  const Joint& wrist = JointNamed(m, "wrist");
  EXPECT_EQ(wrist.type, Joint::Type::kFixed);
  // upper (-1,0,0) to tool (-1,0,1.25), same rotation: X_PC = (0,0,1.25), identity.
  ExpectPose(wrist.X_PC, {0, 0, 1.25}, I);
  EXPECT_LT((wrist.axis - Eigen::Vector3d(0, 0, 1)).norm(), 1e-12);  // default <xyz> 0 0 1
  const Joint& mount = JointNamed(m, "mount");
  EXPECT_EQ(mount.child, "hand::palm");
  // Rz90^T * (palm - tool) = Rz90^T * (0, 0.1, 0.5) = (0.1, 0, 0.5).
  ExpectPose(mount.X_PC, {0.1, 0, 0.5}, I);
  const Joint& to_world = JointNamed(m, "to_world");
  EXPECT_EQ(to_world.parent, "world");
  ExpectPose(to_world.X_PC, {10, 0, 0}, I);  // model pose in the world composed with base (I)
}

TEST(SdfReaderTest, InertialsGeometriesLinesAndIgnoreCommentsAreRead) {
  const ReadResult r = ReadSdfFile(kDir + "/frames_1_8.sdf", FixtureOptions());
  ASSERT_TRUE(r.ok());
  const Model& m = r.models[0];
  EXPECT_FALSE(LinkNamed(m, "base").inertial.has_value());  // no <inertial>: absent, not zeros
  const Link& upper = LinkNamed(m, "upper");
  EXPECT_EQ(upper.location.line, 12);
  EXPECT_EQ(upper.location.file, kDir + "/frames_1_8.sdf");
  ASSERT_TRUE(upper.inertial.has_value());
  const Inertial& in = *upper.inertial;
  EXPECT_EQ(in.mass, 2.5);
  EXPECT_EQ(in.ixx, 0.1);
  EXPECT_EQ(in.iyy, 0.2);
  EXPECT_EQ(in.izz, 0.3);
  EXPECT_EQ(in.ixy, 0.0);  // SDF default for products (sdf/1.8/inertial.sdf)
  EXPECT_EQ(in.location.line, 15);
  EXPECT_EQ(in.mass_location.line, 17);
  ExpectPose(in.X_BBi, {0, 0, 0.5}, Eigen::Matrix3d::Identity());
  EXPECT_EQ(upper.ignored_rules, (std::vector<std::string>{"inertia-triangle", "mass-zero"}));
  ASSERT_EQ(upper.geometries.size(), 2u);
  const Geometry& box = upper.geometries[0];
  EXPECT_TRUE(box.is_collision);
  EXPECT_EQ(box.type, Geometry::Type::kBox);
  EXPECT_EQ(box.size, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(box.location.line, 25);
  ExpectPose(box.X_BG, {0, 0, 1}, Eigen::Matrix3d::Identity());
  const Geometry& cyl = upper.geometries[1];
  EXPECT_FALSE(cyl.is_collision);
  EXPECT_EQ(cyl.type, Geometry::Type::kCylinder);
  EXPECT_EQ(cyl.radius, 0.1);
  EXPECT_EQ(cyl.length, 0.4);
  // Visual pose relative_to base (the model origin), in upper: X_UM = (Rz90^T, -Rz90^T*(-1,0,0))
  // = (Rz(-90°), (0,-1,0)).
  ExpectPose(cyl.X_BG, {0, -1, 0}, Rz90().transpose());
  const Link& palm = LinkNamed(m, "hand::palm");
  ASSERT_EQ(palm.geometries.size(), 2u);
  EXPECT_EQ(palm.geometries[0].type, Geometry::Type::kSphere);
  EXPECT_EQ(palm.geometries[0].radius, 0.05);
  EXPECT_EQ(palm.geometries[1].type, Geometry::Type::kMesh);
  EXPECT_EQ(palm.geometries[1].uri, "model://hand/palm.stl");
  EXPECT_EQ(palm.geometries[1].scale, Eigen::Vector3d(0.001, 0.001, 0.001));
}

// ---------------------------------------------------------------- worlds, placement_frame

TEST(SdfReaderTest, EachModelOfAWorldIsItsOwnModelAndPlacementFrameMovesTheModel) {
  std::vector<SdfModelFrames> frames;
  const ReadResult r = ReadSdfFile(kDir + "/placement_world_1_8.sdf", FixtureOptions(), &frames);
  ASSERT_TRUE(r.ok()) << r.errors.front().ToString();
  ASSERT_EQ(r.models.size(), 2u);
  EXPECT_EQ(r.models[0].name, "a");
  EXPECT_EQ(r.models[1].name, "b");
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  // Hand-derived: p = l * (0 0 -0.25) = (0,0,0.25) in a; the pose (0 0 1) places p, so
  // X_Wa = (0,0,1) * X_ap^-1 = (0,0,0.75).
  ExpectPose(frames[0].X_WM, {0, 0, 0.75}, I);
  ExpectPose(frames[0].X_MB[0], {0, 0, 0.5}, I);
  // b is (1 0 0) relative to a: (1,0,0.75); its joint to the world carries that pose.
  ExpectPose(frames[1].X_WM, {1, 0, 0.75}, I);
  ExpectPose(r.models[1].joints.at(0).X_PC, {1, 0, 0.75}, I);
}

// ---------------------------------------------------------------- axis semantics by version

struct AxisCase {
  const char* file;
  Eigen::Vector3d j, k, n;
};

TEST(SdfReaderTest, JointAxisFollowsTheFrameRulesOfEachSdfVersion) {
  // Link b is yawed 90° in the model; <xyz>1 0 0</xyz> in the model frame is (0,-1,0) in b,
  // in the joint frame (= b) it is (1,0,0).
  // 1.4: libsdformat's 1.4->1.5 converter adds use_parent_model_frame=true to joints of top-level
  //      models only (sdf/1.5/1_4.convert), so j and k are in the model frame, inner::n is not.
  // 1.5, 1.6: <use_parent_model_frame> defaults to false (sdf/1.5/joint.sdf, sdf/1.6/joint.sdf).
  const Eigen::Vector3d x(1, 0, 0), my(0, -1, 0);
  for (const AxisCase& c : {AxisCase{"axis_1.4.sdf", my, my, x}, AxisCase{"axis_1.5.sdf", x, my, x},
                            AxisCase{"axis_1.6.sdf", x, my, x}}) {
    SCOPED_TRACE(c.file);
    const ReadResult r = ReadSdfFile(kDir + "/" + c.file, FixtureOptions());
    ASSERT_TRUE(r.ok()) << r.errors.front().ToString();
    const Model& m = r.models.at(0);
    EXPECT_LT((JointNamed(m, "j").axis - c.j).norm(), 1e-12) << JointNamed(m, "j").axis;
    EXPECT_LT((JointNamed(m, "k").axis - c.k).norm(), 1e-12) << JointNamed(m, "k").axis;
    EXPECT_LT((JointNamed(m, "inner::n").axis - c.n).norm(), 1e-12);
    EXPECT_EQ(JointNamed(m, "inner::n").type, Joint::Type::kPrismatic);
  }
}

// ---------------------------------------------------------------- includes

TEST(SdfReaderTest, IncludesResolveThroughModelPathsWithNameAndPoseOverrides) {
  std::vector<SdfModelFrames> frames;
  const ReadResult r = ReadSdfFile(kDir + "/include_world.sdf", FixtureOptions(), &frames);
  ASSERT_TRUE(r.ok()) << r.errors.front().ToString();
  ASSERT_EQ(r.models.size(), 4u);
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  // model.config lists 1.5, 1.7 and 1.6 files: the 1.7 one (box.sdf, link "body") is chosen.
  EXPECT_EQ(r.models[0].name, "box1");
  ASSERT_EQ(r.models[0].links.size(), 1u);
  EXPECT_EQ(r.models[0].links[0].name, "body");
  EXPECT_EQ(r.models[0].links[0].inertial->mass, 3.0);
  EXPECT_EQ(r.models[0].links[0].location.file, kDir + "/models/massprops_box/box.sdf");
  EXPECT_EQ(r.models[0].links[0].location.line, 5);
  ExpectPose(frames[0].X_WM, {1, 2, 3}, I);  // <pose> override
  EXPECT_EQ(r.models[1].name, "box");        // no <name>: the model's own name and pose
  ExpectPose(frames[1].X_WM, {0, 0, 1}, I);
  EXPECT_EQ(r.models[2].name, "box3");  // path relative to the including file
  const Model& cart = r.models[3];
  ASSERT_EQ(cart.links.size(), 2u);
  EXPECT_EQ(cart.links[1].name, "cargo::body");
  ExpectPose(cart.joints.at(0).X_PC, {0, 0, 2}, I);
  // The missing include is a warning naming it, with its line; the rest is read.
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].element.find("massprops_no_such_model"), std::string::npos);
  EXPECT_EQ(r.warnings[0].location.line, 31);
}

TEST(SdfReaderTest, ARecursiveIncludeIsAnErrorNotAnInfiniteLoop) {
  const ReadResult r = ReadSdfString(
      "<sdf version='1.7'><model name='m'><include><uri>model://massprops_loop</uri></include>"
      "</model></sdf>",
      "loop.sdf", FixtureOptions());
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errors[0].message.find("recursive include"), std::string::npos)
      << r.errors[0].ToString();
  EXPECT_EQ(r.errors[0].location.file, kDir + "/models/massprops_loop/model.sdf");
  EXPECT_EQ(r.errors[0].location.line, 5);
  EXPECT_TRUE(r.models.empty());
}

// ---------------------------------------------------------------- SDF 1.9 pose forms

TEST(SdfReaderTest, DegreesAndQuaternionPosesOfSdf19GiveTheSameRotation) {
  const ReadResult r = ReadSdfString(
      "<sdf version='1.9'><model name='m'>\n"
      "<link name='a'><pose degrees='true'>1 2 3 0 0 90</pose></link>\n"
      "<link name='b'><pose rotation_format='quat_xyzw'>1 2 3 0 0 0.7071067811865476 "
      "0.7071067811865476</pose></link>\n"
      "<link name='c'><inertial><pose>0 0 0 0 0 1.5707963267948966</pose></inertial></link>\n"
      "</model></sdf>",
      "poses.sdf", FixtureOptions(), nullptr);
  ASSERT_TRUE(r.ok()) << r.errors.front().ToString();
  std::vector<SdfModelFrames> frames;
  ReadSdfString(
      "<sdf version='1.9'><model name='m'>\n"
      "<link name='a'><pose degrees='true'>1 2 3 0 0 90</pose></link>\n"
      "<link name='b'><pose rotation_format='quat_xyzw'>1 2 3 0 0 0.7071067811865476 "
      "0.7071067811865476</pose></link>\n"
      "</model></sdf>",
      "poses.sdf", FixtureOptions(), &frames);
  // Hand-derived: yaw 90° = quaternion (0, 0, sin 45°, cos 45°).
  ExpectPose(frames.at(0).X_MB.at(0), {1, 2, 3}, Rz90());
  ExpectPose(frames.at(0).X_MB.at(1), {1, 2, 3}, Rz90());
  const Inertial& in = *r.models[0].links[2].inertial;
  ExpectPose(in.X_BBi, {0, 0, 0}, Rz90());
  EXPECT_EQ(in.mass, 1.0);  // SDF defaults: mass 1, ixx = iyy = izz = 1 (sdf/1.9/inertial.sdf)
  EXPECT_EQ(in.ixx, 1.0);
  EXPECT_EQ(in.izz, 1.0);
  EXPECT_EQ(in.iyz, 0.0);
}

TEST(SdfReaderTest, AutoInertialOfSdf111IsRecordedAsAbsentWithAWarning) {
  const ReadResult r = ReadSdfString(
      "<sdf version='1.11'><model name='m'>\n<link name='a'>\n<inertial auto='true'/></link>\n"
      "<link name='b'><inertial><mass>2</mass></inertial></link></model></sdf>",
      "auto.sdf", FixtureOptions());
  ASSERT_TRUE(r.ok());
  EXPECT_FALSE(r.models[0].links[0].inertial.has_value());
  ASSERT_TRUE(r.models[0].links[1].inertial.has_value());
  EXPECT_EQ(r.models[0].links[1].inertial->mass, 2.0);
  EXPECT_EQ(r.models[0].links[1].inertial->ixx, 1.0);  // <inertia> absent: SDF default ixx = 1
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].location.line, 3);
  EXPECT_NE(r.warnings[0].message.find("auto"), std::string::npos);
}

// SDF spec (model.sdf): <static> "If set to true, the model is immovable"; an <include>'s own
// <static> overrides the included model's.
TEST(SdfReaderTest, StaticModelsAndStaticIncludesAreMarkedStatic) {
  const ReadResult r = ReadSdfString(
      "<sdf version='1.7'><world name='w'>\n"
      "<model name='wall'><static>true</static><link name='l'/></model>\n"
      "<model name='cart'><static>false</static><link name='l'/></model>\n"
      "<model name='plain'><link name='l'/></model>\n"
      "<include><uri>model://massprops_box</uri><name>fixed_box</name><static>1</static>"
      "</include>\n"
      "</world></sdf>",
      "static.sdf", FixtureOptions());
  ASSERT_TRUE(r.ok()) << r.errors.front().ToString();
  ASSERT_EQ(r.models.size(), 4u);
  EXPECT_TRUE(r.models[0].is_static);
  EXPECT_FALSE(r.models[1].is_static);
  EXPECT_FALSE(r.models[2].is_static);
  EXPECT_EQ(r.models[3].name, "fixed_box");
  EXPECT_TRUE(r.models[3].is_static);
}

// ---------------------------------------------------------------- bad input

ReadResult ReadOne(const std::string& xml) { return ReadSdfString(xml, "bad.sdf", {}); }

void ExpectError(const ReadResult& r, const std::string& text, int line) {
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(r.models.empty());
  EXPECT_NE(r.errors[0].message.find(text), std::string::npos) << r.errors[0].ToString();
  EXPECT_EQ(r.errors[0].location.line, line) << r.errors[0].ToString();
  EXPECT_EQ(r.errors[0].location.file, "bad.sdf");
}

std::string MassFile(const std::string& mass) {
  return "<sdf version='1.7'>\n<model name='m'>\n<link name='l'>\n<inertial>\n<mass>" + mass +
         "</mass>\n</inertial>\n</link>\n</model>\n</sdf>\n";
}

TEST(SdfReaderTest, NonNumericNonFiniteAndOverflowingNumbersAreErrorsQuotingTheText) {
  ExpectError(ReadOne(MassFile("1,5")), "'1,5' is not a number", 5);
  ExpectError(ReadOne(MassFile("abc")), "'abc' is not a number", 5);
  ExpectError(ReadOne(MassFile("nan")), "'nan' is not a finite number", 5);
  ExpectError(ReadOne(MassFile("-inf")), "'-inf' is not a finite number", 5);
  ExpectError(ReadOne(MassFile("1e400")), "'1e400' is out of the range of double", 5);
  ExpectError(ReadOne(MassFile("1 2")), "expected 1 numbers", 5);
  EXPECT_EQ(ReadOne(MassFile("1,5")).errors[0].element, "<mass> of link 'l'");
  // A pose of 5 numbers.
  ExpectError(ReadOne("<sdf version='1.7'><model name='m'>\n<link name='l'><pose>1 2 3 4 5</pose>"
                      "</link></model></sdf>"),
              "expected 6 numbers", 2);
}

TEST(SdfReaderTest, MalformedEmptyAndGarbageInputAreErrorsNotCrashes) {
  // The <link> opened on line 3 is never closed: tinyxml2 reports the element left open.
  ExpectError(ReadOne("<sdf version='1.7'>\n<model name='m'>\n<link name='a'>\n</model></sdf>"),
              "malformed XML", 3);
  ExpectError(ReadOne(""), "empty", 0);
  ExpectError(ReadOne("  \n "), "empty", 0);
  ExpectError(ReadOne("<robot name='r'/>"), "root element must be <sdf>", 1);
  ExpectError(ReadOne("<sdf version='one'><model name='m'/></sdf>"), "version attribute", 1);
  std::mt19937 rng(42);
  for (int trial = 0; trial < 20; ++trial) {
    std::string garbage(4096, '\0');
    for (char& c : garbage) c = static_cast<char>(rng() & 0xff);
    const ReadResult r = ReadOne(garbage);
    EXPECT_FALSE(r.ok());
  }
  const ReadResult missing = ReadSdfFile(kDir + "/no_such_file.sdf");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.errors[0].message.find("cannot read"), std::string::npos);
}

TEST(SdfReaderTest, MissingAttributesMissingLinksDuplicatesAndCyclesAreErrors) {
  ExpectError(ReadOne("<sdf version='1.7'><model name='m'>\n<link/></model></sdf>"),
              "needs a name attribute", 2);
  ExpectError(ReadOne("<sdf version='1.7'><model name='m'><link name='a'/>\n<joint name='j'>"
                      "<parent>a</parent><child>a</child></joint></model></sdf>"),
              "needs a type attribute", 2);
  ExpectError(ReadOne("<sdf version='1.7'><model name='m'><link name='a'/>\n"
                      "<joint name='j' type='fixed'><parent>a</parent><child>ghost</child>"
                      "</joint></model></sdf>"),
              "'ghost'", 2);
  ExpectError(ReadOne("<sdf version='1.7'><model name='m'><link name='a'/>\n"
                      "<joint name='j' type='fixed'><parent>ghost</parent><child>a</child>"
                      "</joint></model></sdf>"),
              "the parent 'ghost' is not a link", 2);
  ExpectError(ReadOne("<sdf version='1.6'><model name='m'><link name='a'/>\n<link name='a'/>"
                      "</model></sdf>"),
              "already used", 2);
  ExpectError(ReadOne("<sdf version='1.7'><model name='m'><link name='a'/>\n"
                      "<frame name='F1'><pose relative_to='F2'/></frame>\n"
                      "<frame name='F2'><pose relative_to='F1'/></frame></model></sdf>"),
              "cycle", 2);
  ExpectError(ReadOne("<sdf version='1.7'><model name='m'>\n<link name='a'>"
                      "<pose relative_to='nowhere'/></link></model></sdf>"),
              "'nowhere'", 2);
}

TEST(SdfReaderTest, FilesOverTheSizeLimitAreRefusedWithoutReadingThem) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "massprops_sdf_reader_test_huge.sdf";
  { std::ofstream(path.string()) << "<sdf version='1.7'/>"; }
  std::filesystem::resize_file(path, kMaxSdfFileBytes + 1);  // sparse: no disk space used
  const ReadResult r = ReadSdfFile(path.string());
  std::filesystem::remove(path);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errors[0].message.find("limit"), std::string::npos) << r.errors[0].ToString();
}

}  // namespace
}  // namespace massprops

// Tests of the SDF reader on the fixtures of testdata/sdf/ and on inline bad input.
// Expected poses are hand-derived below (Rz(90°) maps (x, y, z) to (-y, x, z)); the same fixtures
// are also compared with libsdformat 12 in sdf_reader_sdformat_test.cc.

#include "massprops/io/sdf_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "massprops/model/model.h"
#include "shared_data.h"

namespace massprops {
namespace {

const std::string kDir = std::string(MASSPROPS_TESTDATA_DIR) + "/sdf";
constexpr double kPi = 3.14159265358979323846;

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
  // The missing include is an include-unresolved finding naming it, with its line; the rest is
  // read.
  EXPECT_TRUE(r.warnings.empty());
  ASSERT_EQ(r.findings.size(), 1u);
  EXPECT_EQ(r.findings[0].rule, "include-unresolved");
  EXPECT_NE(r.findings[0].message.find("massprops_no_such_model"), std::string::npos);
  EXPECT_EQ(r.findings[0].location.line, 31);
}

// Hand-derived from the fixture: the include's <pose> 1 0 0 replaces the arm's own <pose> 0 0 7,
// so the merged frame is at (1, 0, 0) in robot's frame; upper at (1, 0, 0.5); the frame tip at
// (1, 0, 1) turned 90° about z; hand (box.sdf, its own pose replaced by the include's
// relative_to tip 0.25 0 0) at tip + Rz90·(0.25, 0, 0) = (1, 0.25, 1), turned like tip; its link
// body at the hand model's frame.
TEST(SdfReaderTest, MergedIncludesPutTheirLinksJointsAndNestedIncludesIntoTheEnclosingModel) {
  std::vector<SdfModelFrames> frames;
  const ReadResult r = ReadSdfFile(kDir + "/merge_include.sdf", FixtureOptions(), &frames);
  ASSERT_TRUE(r.ok()) << r.errors.front().ToString();
  ASSERT_EQ(r.models.size(), 1u);
  const Model& m = r.models[0];
  ASSERT_EQ(m.links.size(), 3u);
  EXPECT_EQ(m.links[0].name, "base");
  EXPECT_EQ(m.links[1].name, "upper");
  EXPECT_EQ(m.links[2].name, "hand::body");
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  ExpectPose(frames[0].X_MB[1], {1, 0, 0.5}, I);
  ExpectPose(frames[0].X_MB[2], {1, 0.25, 1}, Rz90());
  // Elements of included files carry those files' paths and lines.
  EXPECT_EQ(m.links[1].location.file, kDir + "/models/massprops_arm/model.sdf");
  EXPECT_EQ(m.links[1].location.line, 8);
  EXPECT_EQ(m.links[1].inertial->location.file, kDir + "/models/massprops_arm/model.sdf");
  EXPECT_EQ(m.links[1].inertial->mass_location.line, 11);
  EXPECT_EQ(m.links[2].location.file, kDir + "/models/massprops_box/box.sdf");
  EXPECT_EQ(m.links[2].inertial->mass_location.line, 7);
  // The joints: mount (base -> upper, in robot's file) and wrist (upper -> hand::body, scoped).
  ASSERT_EQ(m.joints.size(), 2u);
  EXPECT_EQ(JointNamed(m, "mount").child, "upper");
  EXPECT_EQ(JointNamed(m, "wrist").parent, "upper");
  EXPECT_EQ(JointNamed(m, "wrist").child, "hand::body");
  EXPECT_EQ(JointNamed(m, "wrist").location.file, kDir + "/models/massprops_arm/model.sdf");
  ExpectPose(JointNamed(m, "wrist").X_PC, {0, 0.25, 0.5}, Rz90());
}

// SDF 1.10 world joints (sdf/1.10/world.sdf: <joint> in <world>, parent and child scoped names or
// "world"). Hand-derived: the arm at z = 1, the gripper at z = 3; weld gives palm in hand's frame
// at (0, 0, 2); anchor fixes the arm's canonical link (hand) to the world at (0, 0, 1).
TEST(SdfReaderTest, WorldJointsJoinTheirModelsIntoOneModelWithScopedNames) {
  std::vector<SdfModelFrames> frames;
  const ReadResult r = ReadSdfFile(kDir + "/world_joint.sdf", FixtureOptions(), &frames);
  ASSERT_TRUE(r.ok()) << r.errors.front().ToString();
  ASSERT_EQ(r.models.size(), 1u);
  const Model& m = r.models[0];
  EXPECT_EQ(m.name, "arm+gripper");
  ASSERT_EQ(m.links.size(), 2u);
  EXPECT_EQ(m.links[0].name, "arm::hand");
  EXPECT_EQ(m.links[1].name, "gripper::palm");
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  ExpectPose(frames[0].X_MB[1], {0, 0, 3}, I);  // the model frame is the world's
  ASSERT_EQ(m.joints.size(), 2u);
  const Joint& weld = JointNamed(m, "weld");
  EXPECT_EQ(weld.parent, "arm::hand");
  EXPECT_EQ(weld.child, "gripper::palm");
  EXPECT_EQ(weld.type, Joint::Type::kFixed);
  ExpectPose(weld.X_PC, {0, 0, 2}, I);
  const Joint& anchor = JointNamed(m, "anchor");
  EXPECT_EQ(anchor.parent, "world");
  EXPECT_EQ(anchor.child, "arm::hand");
  ExpectPose(anchor.X_PC, {0, 0, 1}, I);
  EXPECT_EQ(anchor.location.line, 19);
  // Before SDF 1.10 such a joint is not read, with a warning.
  const ReadResult old = ReadSdfString(
      "<sdf version='1.9'><world name='w'><model name='a'><link name='l'/></model>\n"
      "<joint name='j' type='fixed'><parent>world</parent><child>a</child></joint>"
      "</world></sdf>",
      "old.sdf", FixtureOptions());
  ASSERT_TRUE(old.ok());
  EXPECT_TRUE(old.models.at(0).joints.empty());
  ASSERT_EQ(old.warnings.size(), 1u);
  EXPECT_EQ(old.warnings[0].location.line, 2);
}

// SDFormat reserves the link name "world" (libsdformat 12: "The supplied link name [world] is
// reserved.", e.g. bullet3's wsg50_one_motor_gripper_new_free_base.sdf). massprops reads such a
// link like any other but says so, at the link's line, since a <parent>world</parent> then means
// this link instead of the world frame.
TEST(SdfReaderTest, ALinkNamedWorldIsAWarningAtItsLine) {
  const ReadResult r = ReadSdfString(
      "<sdf version='1.6'><model name='m'>\n"
      "<link name='world'/>\n"
      "<link name='base'/>\n"
      "<joint name='j' type='fixed'><parent>world</parent><child>base</child></joint>"
      "</model></sdf>",
      "world_link.sdf", FixtureOptions());
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].location.line, 2);
  EXPECT_NE(r.warnings[0].message.find("reserved"), std::string::npos);
  // A link with another name says nothing.
  const ReadResult plain =
      ReadSdfString("<sdf version='1.6'><model name='m'><link name='base'/></model></sdf>",
                    "plain.sdf", FixtureOptions());
  EXPECT_TRUE(plain.warnings.empty());
}

TEST(SdfReaderTest, AnUnresolvedIncludeCostsOnlyWhatItNamesAndSaysHowToPointMasspropsAtIt) {
  const ReadResult r = ReadSdfFile(kDir + "/unresolved_include.sdf", FixtureOptions());
  ASSERT_TRUE(r.ok()) << r.errors.front().ToString();
  ASSERT_EQ(r.models.size(), 1u);
  const Model& m = r.models[0];
  EXPECT_EQ(m.links.size(), 2u);   // base and arm
  ASSERT_EQ(m.joints.size(), 1u);  // shoulder; grip names the missing model
  EXPECT_EQ(m.joints[0].name, "shoulder");
  ASSERT_EQ(r.findings.size(), 2u);
  EXPECT_EQ(r.findings[0].rule, "include-unresolved");
  EXPECT_EQ(r.findings[0].model, "robot");
  EXPECT_EQ(r.findings[0].location.file, kDir + "/unresolved_include.sdf");
  EXPECT_EQ(r.findings[0].location.line, 12);
  for (const char* text :
       {"massprops_no_such_gripper", "--model-path", "SDF_PATH", "GZ_SIM_RESOURCE_PATH",
        "IGN_GAZEBO_RESOURCE_PATH", "models/massprops_no_such_gripper"}) {
    EXPECT_NE(r.findings[0].message.find(text), std::string::npos) << text;
  }
  EXPECT_EQ(r.findings[1].rule, "include-unresolved");
  EXPECT_EQ(r.findings[1].location.line, 16);
  EXPECT_NE(r.findings[1].message.find("gripper::palm"), std::string::npos);
  // A Fuel URL is named as remote.
  const ReadResult fuel = ReadSdfString(
      "<sdf version='1.7'><world name='w'>\n<include><uri>https://fuel.gazebosim.org/1.0/o/"
      "models/m</uri></include></world></sdf>",
      "fuel.sdf", FixtureOptions());
  ASSERT_TRUE(fuel.ok());
  ASSERT_EQ(fuel.findings.size(), 1u);
  EXPECT_EQ(fuel.findings[0].location.line, 2);
  EXPECT_NE(fuel.findings[0].message.find("remote"), std::string::npos);
}

// Models that include the next one twice: 2^depth links. The limits stop the read with an error
// naming the outermost include (hostile-input issue #15 runs the 17-file version).
TEST(SdfReaderTest, IncludeDepthAndExpandedSizeAreBoundedWithAnErrorNamingTheInclude) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "massprops_sdf_reader_test_bomb";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const int kFiles = 12;
  for (int k = 0; k < kFiles; ++k) {
    std::ofstream out((dir / ("m" + std::to_string(k) + ".sdf")).string());
    out << "<sdf version='1.7'><model name='m" << k << "'><link name='l'/>";
    if (k + 1 < kFiles) {
      for (const char* name : {"a", "b"}) {
        out << "<include><uri>m" << k + 1 << ".sdf</uri><name>" << name << "</name></include>";
      }
    }
    out << "</model></sdf>";
  }
  const std::string top = (dir / "m0.sdf").string();
  SdfReadOptions options = FixtureOptions();
  // Unbounded here: 2^12 - 1 = 4095 links.
  options.max_included_elements = 1000000;
  const ReadResult all = ReadSdfFile(top, options);
  ASSERT_TRUE(all.ok()) << all.errors.front().ToString();
  EXPECT_EQ(all.models.at(0).links.size(), 4095u);
  options.max_included_elements = 1000;
  const ReadResult big = ReadSdfFile(top, options);
  ASSERT_FALSE(big.ok());
  EXPECT_TRUE(big.models.empty());
  EXPECT_EQ(big.errors.size(), 1u);
  EXPECT_EQ(big.errors[0].location.file, top);
  EXPECT_NE(big.errors[0].message.find("more than 1000 elements"), std::string::npos)
      << big.errors[0].ToString();
  EXPECT_NE(big.errors[0].element.find("m1.sdf"), std::string::npos) << big.errors[0].element;
  options.max_included_elements = 1000000;
  options.max_include_depth = 5;
  const ReadResult deep = ReadSdfFile(top, options);
  ASSERT_FALSE(deep.ok());
  EXPECT_NE(deep.errors[0].message.find("deeper than 5 files"), std::string::npos)
      << deep.errors[0].ToString();
  EXPECT_NE(deep.errors[0].message.find("m1.sdf"), std::string::npos);
  std::filesystem::remove_all(dir);
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

// ---------------------------------------------------------------- SDF 1.11 auto inertials

void ExpectAuto(const Model& m, const std::string& link, double mass, const Eigen::Vector3d& com,
                const Eigen::Vector3d& moments, const Eigen::Vector3d& products,
                double tol = 1e-12) {
  SCOPED_TRACE(link);
  const Link& l = LinkNamed(m, link);
  ASSERT_TRUE(l.inertial.has_value());
  const Inertial& in = *l.inertial;
  const double scale = std::max(1.0, moments.norm());
  EXPECT_NEAR(in.mass, mass, tol * mass);
  EXPECT_LT((in.X_BBi.p_AB - com).norm(), tol * std::max(1.0, com.norm())) << in.X_BBi.p_AB;
  EXPECT_TRUE(in.X_BBi.R_AB.isIdentity(0));
  EXPECT_NEAR(in.ixx, moments.x(), tol * scale);
  EXPECT_NEAR(in.iyy, moments.y(), tol * scale);
  EXPECT_NEAR(in.izz, moments.z(), tol * scale);
  EXPECT_NEAR(in.ixy, products.x(), tol * scale);
  EXPECT_NEAR(in.ixz, products.y(), tol * scale);
  EXPECT_NEAR(in.iyz, products.z(), tol * scale);
}

// Expected values: the solid-body formulas of the SDFormat 1.11 auto-inertia proposal and of
// gz-math (box m/12·(b²+c²); cylinder m·r²/2 about its axis, m·(3r²+L²)/12 across; sphere
// 2/5·m·r²; ellipsoid m/5·(b²+c²); capsule: the cylinder plus two hemispheres, each 2/5·r²·m_h
// about the axis and m_h·(2/5·r² + L²/4 + 3Lr/8) across, its center of mass 3r/8 from its flat
// face), densities by libsdformat 14's precedence (collision, else <inertial><density>, else
// 1000 kg/m³), and a <mass> beside auto="true" scaling the sum (Link::ResolveAutoInertials).
TEST(SdfReaderTest, AutoInertialsAreComputedFromEachCollisionShapeAsSdformat14Does) {
  const ReadResult r = ReadSdfFile(kDir + "/auto_inertia.sdf", FixtureOptions());
  ASSERT_TRUE(r.ok()) << r.errors.front().ToString();
  const Model& m = r.models.at(0);
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  // Box 2 × 1 × 0.5 m, density 10 (collision): 10 kg at the collision pose (0, 0, 1); the visual
  // (ten times larger) plays no part.
  ExpectAuto(m, "box", 10, {0, 0, 1},
             {10.0 / 12 * (1 + 0.25), 10.0 / 12 * (4 + 0.25), 10.0 / 12 * (4 + 1)}, zero);
  // Cylinder r 0.5, L 2, default density 1000: m = 1000·π·0.25·2 = 500π; rolled 90° about x, so
  // its axis is y: iyy = m·r²/2, ixx = izz = m·(3r² + L²)/12.
  const double mc = 500 * kPi;
  ExpectAuto(m, "cylinder", mc, zero, {mc * 4.75 / 12, mc * 0.125, mc * 4.75 / 12}, zero);
  // Sphere r 0.1 with the link's <inertial><density> 2000: m = 2000·4/3·π·0.001 = 8π/3.
  const double ms = 8 * kPi / 3;
  ExpectAuto(m, "sphere", ms, zero, {0.4 * ms * 0.01, 0.4 * ms * 0.01, 0.4 * ms * 0.01}, zero);
  // Capsule r 0.5, L 1, density 1: cylinder part π/4 kg, caps π/6 kg; izz = π/4·r²/2 +
  // π/6·2/5·r² = 23π/480; ixx = π/4·(3r² + L²)/12 + π/6·(2/5·r² + L²/4 + 3Lr/8) = 121π/960.
  ExpectAuto(m, "capsule", 5 * kPi / 12, zero, {121 * kPi / 960, 121 * kPi / 960, 23 * kPi / 480},
             zero);
  // Ellipsoid radii 1, 2, 3 at density 3/(4π) (to 15 digits): volume 4/3·π·6 = 8π, mass 6;
  // (b² + c²)/5·6 = 15.6, (a² + c²)/5·6 = 12, (a² + b²)/5·6 = 6.
  ExpectAuto(m, "ellipsoid", 6, zero, {15.6, 12, 6}, zero);
  // Mesh: the closed box 0.1 × 0.2 × 0.3 m of testdata/mesh/box_ascii.stl (corner at the
  // origin), default density: 6 kg, center (0.05, 0.1, 0.15), box formulas. Assimp holds the
  // vertices as 32-bit floats (mesh_loader.h: up to 6e-8 relative), hence 1e-6 here.
  ExpectAuto(m, "mesh", 6, {0.05, 0.1, 0.15},
             {6.0 / 12 * (0.04 + 0.09), 6.0 / 12 * (0.01 + 0.09), 6.0 / 12 * (0.01 + 0.04)}, zero,
             1e-6);
  // Two 1 m cubes of density 1 (their own <density> wins over the link's 7) at x = ±1: 2 kg,
  // about the center ixx = 2·1/6, iyy = izz = 2·(1/6 + 1²); <mass> 4 doubles them.
  ExpectAuto(m, "two_cubes", 4, zero, {2 * 2.0 / 6, 2 * (2.0 / 6 + 2), 2 * (2.0 / 6 + 2)}, zero);
  // One inertial-auto note per computed link, at its <inertial> line, naming the collisions.
  int notes = 0;
  for (const ReadFinding& f : r.findings) {
    if (f.rule != "inertial-auto") continue;
    ++notes;
    EXPECT_EQ(f.location.line, LinkNamed(m, f.link).inertial->location.line);
    EXPECT_NE(f.message.find("collision"), std::string::npos);
  }
  EXPECT_EQ(notes, 7);
  // No collision to compute from: inertial-unreadable (libsdformat 14 refuses the file).
  const Link& none = LinkNamed(m, "no_collision");
  EXPECT_FALSE(none.inertial.has_value());
  EXPECT_TRUE(none.inertial_unreadable);
  EXPECT_EQ(r.findings.back().rule, "inertial-unreadable");
  EXPECT_EQ(r.findings.back().link, "no_collision");
  EXPECT_EQ(r.findings.back().location.line, 70);
}

// The corpus file named by issue 14: four 1 m cubes of density 6 (given on the collision or on
// the inertial) -> each link 6 kg, diag(6/12·2, ...) = diag(1, 1, 1) kg·m² about its center.
TEST(SdfReaderTest, InertialStatsAutoOfTheCorpusGivesFourSixKilogramCubes) {
  const std::string path =
      std::string(MASSPROPS_CORPUS_DIR) + "/sdformat/test/sdf/inertial_stats_auto.sdf";
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus/sdformat/test/sdf/inertial_stats_auto.sdf");
  const ReadResult r = ReadSdfFile(path, FixtureOptions());
  ASSERT_TRUE(r.ok()) << r.errors.front().ToString();
  ASSERT_EQ(r.models.at(0).links.size(), 4u);
  for (const Link& l : r.models[0].links) {
    ExpectAuto(r.models[0], l.name, 6, Eigen::Vector3d::Zero(), {1, 1, 1}, Eigen::Vector3d::Zero());
  }
}

TEST(SdfReaderTest, AutoInOlderSdfVersionsIsNotReadAsAuto) {
  // The attribute exists from SDF 1.11 (sdf/1.11/inertial.sdf); libsdformat ignores unknown
  // attributes of older versions, so the SDF defaults apply (mass 1, diag(1, 1, 1)).
  const ReadResult r = ReadSdfString(
      "<sdf version='1.10'><model name='m'>\n<link name='a'>\n<inertial auto='true'/>"
      "<collision name='c'><geometry><box><size>1 1 1</size></box></geometry></collision>"
      "</link></model></sdf>",
      "auto.sdf", FixtureOptions());
  ASSERT_TRUE(r.ok());
  ASSERT_TRUE(r.models[0].links[0].inertial.has_value());
  EXPECT_EQ(r.models[0].links[0].inertial->mass, 1.0);
  EXPECT_TRUE(r.findings.empty());
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

void ExpectUnreadable(const ReadResult& r, const std::string& text, int line) {
  SCOPED_TRACE(text);
  ASSERT_TRUE(r.ok()) << r.errors.front().ToString();
  ASSERT_EQ(r.models.size(), 1u);
  const Link& l = r.models[0].links.at(0);
  EXPECT_TRUE(l.inertial_unreadable);
  EXPECT_FALSE(l.inertial.has_value());
  ASSERT_EQ(r.findings.size(), 1u);
  EXPECT_EQ(r.findings[0].rule, "inertial-unreadable");
  EXPECT_EQ(r.findings[0].link, "l");
  EXPECT_EQ(r.findings[0].location.file, "bad.sdf");
  EXPECT_EQ(r.findings[0].location.line, line);
  EXPECT_NE(r.findings[0].message.find(text), std::string::npos) << r.findings[0].message;
}

// A bad number of an <inertial> costs its link (inertial-unreadable, quoting the text); any other
// bad number is a read error. 1e-400 and subnormals (1e-310) are out of the range libsdformat 12
// accepts (its std::stod throws std::out_of_range for them: checked with libsdformat 12.7).
TEST(SdfReaderTest, NonNumericNonFiniteAndOutOfRangeNumbersQuoteTheText) {
  ExpectUnreadable(ReadOne(MassFile("1,5")), "'1,5' is not a number", 5);
  ExpectUnreadable(ReadOne(MassFile("abc")), "'abc' is not a number", 5);
  ExpectUnreadable(ReadOne(MassFile("nan")), "'nan' is not a finite number", 5);
  ExpectUnreadable(ReadOne(MassFile("-inf")), "'-inf' is not a finite number", 5);
  ExpectUnreadable(ReadOne(MassFile("1e400")), "'1e400' is out of the range of double", 5);
  ExpectUnreadable(ReadOne(MassFile("1e-400")), "'1e-400' is out of the range of double", 5);
  ExpectUnreadable(ReadOne(MassFile("1e-310")), "'1e-310' is out of the range of double", 5);
  ExpectUnreadable(ReadOne(MassFile("1 2")), "expected 1 numbers", 5);
  EXPECT_NE(ReadOne(MassFile("1,5")).findings[0].message.find("<mass> of link 'l'"),
            std::string::npos);
  // The smallest normal double and zero written with a huge exponent are read.
  EXPECT_EQ(ReadOne(MassFile("2.2250738585072014e-308")).models[0].links[0].inertial->mass,
            2.2250738585072014e-308);
  EXPECT_EQ(ReadOne(MassFile("0e-999")).models[0].links[0].inertial->mass, 0.0);
  // A bad inertial <pose> costs the link too.
  ExpectUnreadable(ReadOne("<sdf version='1.7'><model name='m'><link name='l'><inertial>\n"
                           "<pose>0 0 x 0 0 0</pose></inertial></link></model></sdf>"),
                   "'x' is not a number", 2);
  // The fixture: link a has <iyy>1e-400</iyy> (line 11), link b is read.
  const ReadResult fixture = ReadSdfFile(kDir + "/bad_number.sdf", FixtureOptions());
  ASSERT_TRUE(fixture.ok());
  EXPECT_TRUE(fixture.models.at(0).links.at(0).inertial_unreadable);
  ASSERT_EQ(fixture.findings.size(), 1u);
  EXPECT_EQ(fixture.findings[0].location.line, 11);
  EXPECT_NE(fixture.findings[0].message.find("'1e-400'"), std::string::npos);
  ASSERT_TRUE(fixture.models[0].links.at(1).inertial.has_value());
  EXPECT_EQ(fixture.models[0].links[1].inertial->mass, 3.0);
  // Numbers outside <inertial> stay read errors (a collision box size).
  ExpectError(ReadOne("<sdf version='1.7'><model name='m'><link name='l'><collision name='c'>\n"
                      "<geometry><box><size>1 1 1e-400</size></box></geometry></collision></link>"
                      "</model></sdf>"),
              "out of the range", 2);
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

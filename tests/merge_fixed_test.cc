// Tests of include/massprops/output/merge_fixed.h on testdata/report/welded.urdf (hand-derived
// values of its composites are in tests/mass_report_test.cc; repeated here where used).
#include "massprops/output/merge_fixed.h"

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <sstream>
#include <string>

#include "massprops/analysis/welded_groups.h"
#include "massprops/io/model_reader.h"

namespace massprops {
namespace {

const double kPi = 3.14159265358979323846;

std::string FixturePath(const std::string& name) {
  return std::string(MASSPROPS_TESTDATA_DIR) + "/report/" + name;
}

std::string ReadText(const std::string& path) {
  std::string text;
  EXPECT_FALSE(ReadInputFile(path, kMaxModelFileBytes, &text).has_value());
  return text;
}

Model ReadMerged(const std::string& fixture) {
  const MergeFixedResult merged = MergeFixedJoints(ReadText(FixturePath(fixture)), fixture);
  EXPECT_TRUE(merged.errors.empty()) << merged.errors.front().ToString();
  const ReadResult read = ReadModelString(merged.text, "merged.urdf");
  EXPECT_TRUE(read.ok()) << (read.errors.empty() ? "" : read.errors.front().ToString()) << "\n"
                         << merged.text;
  return read.models.empty() ? Model() : read.models.front();
}

void ExpectNear(const Eigen::MatrixXd& actual, const Eigen::MatrixXd& expected, double tol) {
  const double scale = std::max(expected.cwiseAbs().maxCoeff(), 1e-300);
  EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), tol * scale) << "actual\n"
                                                                    << actual << "\nexpected\n"
                                                                    << expected;
}

TEST(MergeFixedTest, EveryWeldedGroupBecomesOneLinkAndMovingJointsAreReparented) {
  const Model model = ReadMerged("welded.urdf");
  ASSERT_EQ(model.links.size(), 2u);
  EXPECT_EQ(model.links[0].name, "base");
  EXPECT_EQ(model.links[1].name, "arm");
  ASSERT_EQ(model.joints.size(), 1u);
  const Joint& shoulder = model.joints[0];
  EXPECT_EQ(shoulder.name, "shoulder");
  EXPECT_EQ(shoulder.parent, "base");
  // Hand-derived: the shoulder sat at (0,0,2) of the cylinder, whose frame is at base (1,0,0)
  // turned +90° about y (z → x): the joint frame is at base (3,0,0), turned the same way.
  ExpectNear(shoulder.X_PC.p_AB, Eigen::Vector3d(3, 0, 0), 1e-15);
  ExpectNear(shoulder.X_PC.R_AB,
             Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitY()).toRotationMatrix(), 1e-15);
  EXPECT_EQ(shoulder.axis, Eigen::Vector3d(0, 0, 1));
}

TEST(MergeFixedTest, RootLinkCarriesTheHandComputedCompositeInertial) {
  const Model model = ReadMerged("welded.urdf");
  ASSERT_TRUE(model.links[0].inertial.has_value());
  const Inertial& inertial = *model.links[0].inertial;
  // Group base (see tests/mass_report_test.cc): m = 12, C = (1/3, 1/3, 1/6), and about C the
  // diagonal 1.275 + 30/36 + 180/648 + 20/9, ...; written with 17 digits, read back exactly.
  EXPECT_EQ(inertial.mass, 12);
  ExpectNear(inertial.X_BBi.p_AB, Eigen::Vector3d(1.0 / 3, 1.0 / 3, 1.0 / 6), 1e-15);
  EXPECT_TRUE(inertial.X_BBi.R_AB.isIdentity(0));
  EXPECT_NEAR(inertial.ixx, 0.625 + 0.25 + 0.4 + 30.0 / 36 + 180.0 / 648 + 20.0 / 9, 1e-14);
  EXPECT_NEAR(inertial.iyy, 2.125 + 19.0 / 24 + 0.4 + 30.0 / 36 + 3636.0 / 648 + 8.0 / 9, 1e-14);
  EXPECT_NEAR(inertial.izz, 2.5 + 19.0 / 24 + 0.4 + 48.0 / 36 + 3744.0 / 648 + 20.0 / 9, 1e-14);
  EXPECT_NEAR(inertial.ixy, -24.0 / 36 + 720.0 / 648 + 8.0 / 9, 1e-14);
  EXPECT_NEAR(inertial.ixz, -12.0 / 36 + 360.0 / 648 + 4.0 / 9, 1e-14);
  EXPECT_NEAR(inertial.iyz, -12.0 / 36 - 72.0 / 648 - 8.0 / 9, 1e-14);
}

TEST(MergeFixedTest, WholeModelCompositeIsUnchangedByMerging) {
  const ReadResult original = ReadModelFile(FixturePath("welded.urdf"));
  ASSERT_TRUE(original.ok());
  const CompositeInertia before = CalcModelCompositeInertia(original.models[0]).inertia;
  const CompositeInertia after = CalcModelCompositeInertia(ReadMerged("welded.urdf")).inertia;
  EXPECT_NEAR(after.mass, before.mass, 1e-15 * before.mass);
  ExpectNear(after.p_RoScm_R, before.p_RoScm_R, 1e-14);
  ExpectNear(after.I_SScm_R, before.I_SScm_R, 1e-13);
}

TEST(MergeFixedTest, VisualsAndCollisionsMoveIntoTheRootWithComposedOrigins) {
  const Model model = ReadMerged("welded.urdf");
  // base kept its box visual + collision and received the cylinder's visual + collision and the
  // sphere's collision; arm received arm_box's collision: 6 geometries, as before.
  ASSERT_EQ(model.links[0].geometries.size(), 5u);
  ASSERT_EQ(model.links[1].geometries.size(), 1u);
  // The cylinder geometry: origin (0,0,1) of a frame at (1,0,0) turned +90° about y → (2,0,0).
  const Geometry& cylinder = model.links[0].geometries[2];
  EXPECT_EQ(cylinder.type, Geometry::Type::kCylinder);
  ExpectNear(cylinder.X_BG.p_AB, Eigen::Vector3d(2, 0, 0), 1e-15);
  ExpectNear(cylinder.X_BG.R_AB,
             Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitY()).toRotationMatrix(), 1e-15);
  // arm_box: at (1,0,0) of arm, turned 30° about z.
  const Geometry& box = model.links[1].geometries[0];
  ExpectNear(box.X_BG.p_AB, Eigen::Vector3d(1, 0, 0), 1e-15);
  ExpectNear(box.X_BG.R_AB, Eigen::AngleAxisd(kPi / 6, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
             1e-15);
}

TEST(MergeFixedTest, AModelWithoutFixedJointsKeepsItsLinksAndInertials) {
  const MergeFixedResult merged =
      MergeFixedJoints(ReadText(FixturePath("far_tiny.urdf")), "far_tiny.urdf");
  ASSERT_TRUE(merged.errors.empty());
  EXPECT_EQ(merged.merged_links, 0);
  EXPECT_EQ(merged.groups_merged, 0);
  const ReadResult read = ReadModelString(merged.text, "x.urdf");
  ASSERT_TRUE(read.ok());
  ASSERT_EQ(read.models[0].links.size(), 2u);
  EXPECT_EQ(read.models[0].links[1].inertial->X_BBi.p_AB, Eigen::Vector3d(1000, 0, 0));
  EXPECT_EQ(read.models[0].links[1].inertial->ixx, 1e-11);
}

// SDF: testdata/merge_sdf/*.sdf, with hand-computed expectations (libsdformat's view of the
// same files is compared in tests/merge_fixed_sdf_sdformat_test.cc).
MergeFixedResult MergeSdfFixture(const std::string& name, Target target = Target::kGeneric) {
  const std::string path = std::string(MASSPROPS_TESTDATA_DIR) + "/merge_sdf/" + name;
  return MergeFixedJoints(ReadText(path), name, target);
}

// The element <TAG name="NAME"> anywhere below `e` (depth first), or null.
const tinyxml2::XMLElement* FindNamed(const tinyxml2::XMLElement* e, const std::string& tag,
                                      const std::string& name) {
  for (const tinyxml2::XMLElement* c = e->FirstChildElement(); c != nullptr;
       c = c->NextSiblingElement()) {
    if (tag == c->Name() && c->Attribute("name") != nullptr && name == c->Attribute("name")) {
      return c;
    }
    if (const tinyxml2::XMLElement* found = FindNamed(c, tag, name)) return found;
  }
  return nullptr;
}

std::string PoseText(const tinyxml2::XMLElement* e) {
  const tinyxml2::XMLElement* pose = e == nullptr ? nullptr : e->FirstChildElement("pose");
  return pose == nullptr || pose->GetText() == nullptr ? "" : pose->GetText();
}

TEST(MergeFixedTest, SdfTwoWeldedBoxesBecomeOneLinkWithTheHandComputedComposite) {
  const MergeFixedResult merged = MergeSdfFixture("two_boxes.sdf");
  ASSERT_TRUE(merged.errors.empty()) << merged.errors.front().ToString();
  EXPECT_EQ(merged.merged_links, 1);
  EXPECT_EQ(merged.groups_merged, 1);
  const ReadResult read = ReadModelString(merged.text, "merged.sdf");
  ASSERT_TRUE(read.ok()) << merged.text;
  const Model& model = read.models.front();
  ASSERT_EQ(model.links.size(), 3u);  // a, c, d: b is merged into a
  EXPECT_EQ(model.FindLink("b"), -1);
  const Inertial& in = *model.links[model.FindLink("a")].inertial;
  // By hand: two 2 kg bodies with unit central inertia at x = 0 and x = 2: m = 4, center of mass
  // x = 1; about it each adds 2·(|d|²·1 − d·dᵀ) with d = (±1, 0, 0) = diag(0, 2, 2), so
  // I = 2·diag(1, 1, 1) + 2·diag(0, 2, 2) = diag(2, 6, 6).
  EXPECT_EQ(in.mass, 4);
  EXPECT_EQ(in.X_BBi.p_AB, Eigen::Vector3d(1, 0, 0));
  EXPECT_TRUE(in.X_BBi.R_AB.isIdentity(0));
  EXPECT_EQ(Eigen::Vector3d(in.ixx, in.iyy, in.izz), Eigen::Vector3d(2, 6, 6));
  EXPECT_EQ(Eigen::Vector3d(in.ixy, in.ixz, in.iyz), Eigen::Vector3d::Zero());
  // The revolute joint left b: now from a, its frame where it was (at c, in the model frame).
  const Joint& hinge = model.joints[model.FindParentJoint("c")];
  EXPECT_EQ(hinge.parent, "a");
  EXPECT_EQ(hinge.X_PC.p_AB, Eigen::Vector3d(2, 0, 2));
  ASSERT_EQ(model.FindParentJoint("b"), -1);

  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(merged.text.c_str()), tinyxml2::XML_SUCCESS);
  const tinyxml2::XMLElement* a = FindNamed(doc.RootElement(), "link", "a");
  ASSERT_NE(a, nullptr);
  // b's visual "v" (pose 0 0 1 in b, b at 2 0 0) clashes with a's "v": renamed, pose composed;
  // its collision had no pose: now b's pose in a.
  EXPECT_NE(FindNamed(a, "visual", "v"), nullptr);
  EXPECT_EQ(PoseText(FindNamed(a, "visual", "b__v")), "2 0 1 0 0 0");
  EXPECT_EQ(PoseText(FindNamed(a, "collision", "c")), "2 0 0 0 0 0");
  // The frame attached to b: attached to a, its pose (0 0 0.5 in b) composed.
  const tinyxml2::XMLElement* tip = FindNamed(doc.RootElement(), "frame", "tip");
  ASSERT_NE(tip, nullptr);
  EXPECT_STREQ(tip->Attribute("attached_to"), "a");
  EXPECT_EQ(PoseText(tip), "2 0 0.5 0 0 0");
  // d's pose relative_to b (0 1 0): relative to a (2 1 0); the axis expressed in b: in a.
  const tinyxml2::XMLElement* d = FindNamed(doc.RootElement(), "link", "d");
  ASSERT_NE(d, nullptr);
  EXPECT_STREQ(d->FirstChildElement("pose")->Attribute("relative_to"), "a");
  EXPECT_EQ(PoseText(d), "2 1 0 0 0 0");
  EXPECT_EQ(model.links[model.FindLink("d")].inertial->mass, 1);
  const tinyxml2::XMLElement* xyz = FindNamed(doc.RootElement(), "joint", "slider")
                                        ->FirstChildElement("axis")
                                        ->FirstChildElement("xyz");
  EXPECT_STREQ(xyz->Attribute("expressed_in"), "a");
  EXPECT_STREQ(xyz->GetText(), "1 0 0");
  // Comments are kept; the fixed joint is gone, but a frame names it: it becomes a frame where the
  // joint frame was (the joint had no pose: at its child b, 2 0 0 in a), attached to a.
  EXPECT_NE(merged.text.find("b sits 2 m along x"), std::string::npos);
  EXPECT_EQ(FindNamed(doc.RootElement(), "joint", "weld"), nullptr);
  const tinyxml2::XMLElement* weld = FindNamed(doc.RootElement(), "frame", "weld");
  ASSERT_NE(weld, nullptr);
  EXPECT_STREQ(weld->Attribute("attached_to"), "a");
  EXPECT_EQ(PoseText(weld), "2 0 0 0 0 0");
  EXPECT_STREQ(FindNamed(doc.RootElement(), "frame", "at_weld")->Attribute("attached_to"), "weld");
}

TEST(MergeFixedTest, SdfRotatedMemberAndAJointWhoseChildIsMerged) {
  const MergeFixedResult merged = MergeSdfFixture("rotated.sdf");
  ASSERT_TRUE(merged.errors.empty()) << merged.errors.front().ToString();
  const ReadResult read = ReadModelString(merged.text, "merged.sdf");
  ASSERT_TRUE(read.ok()) << merged.text;
  const Model& model = read.models.front();
  ASSERT_EQ(model.links.size(), 2u);
  const Inertial& in = *model.links[model.FindLink("a")].inertial;
  // By hand: b (1 kg) at (1, 0, 0) turned +90° about z, its center of mass 0.5 along its x:
  // (1, 0.5, 0) in a, its inertia Rz·diag(1, 2, 3)·Rzᵀ = diag(2, 1, 3); a (1 kg) at the origin
  // with diag(1, 1, 1). m = 2, c = (0.5, 0.25, 0); d = ±(0.5, 0.25, 0), |d|² = 0.3125, each
  // |d|²·1 − d·dᵀ = [[0.0625, −0.125, 0], [−0.125, 0.25, 0], [0, 0, 0.3125]]; the sum:
  // [[3.125, −0.25, 0], [−0.25, 2.5, 0], [0, 0, 4.625]].
  EXPECT_EQ(in.mass, 2);
  ExpectNear(in.X_BBi.p_AB, Eigen::Vector3d(0.5, 0.25, 0), 1e-15);
  Eigen::Matrix3d I;
  I << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  Eigen::Matrix3d expected;
  expected << 3.125, -0.25, 0, -0.25, 2.5, 0, 0, 0, 4.625;
  ExpectNear(I, expected, 1e-15);
  // The ball joint whose child was b (pose 0 0 0.1 in b): child a, pose composed, so its frame
  // stays at (1, 0, 0.1) turned +90° about z.
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(merged.text.c_str()), tinyxml2::XML_SUCCESS);
  const tinyxml2::XMLElement* loop = FindNamed(doc.RootElement(), "joint", "loop");
  ASSERT_NE(loop, nullptr);
  EXPECT_STREQ(loop->FirstChildElement("child")->GetText(), "a");
  std::istringstream pose(PoseText(loop));
  Eigen::Matrix<double, 6, 1> v;
  for (int k = 0; k < 6; ++k) pose >> v(k);
  ExpectNear(v, (Eigen::Matrix<double, 6, 1>() << 1, 0, 0.1, 0, 0, kPi / 2).finished(), 1e-15);
  // The sensor (0 0.5 0 in b) moved into a: (1, 0, 0) + Rz·(0, 0.5, 0) = (0.5, 0, 0).
  std::istringstream sensor(PoseText(FindNamed(doc.RootElement(), "sensor", "imu")));
  for (int k = 0; k < 6; ++k) sensor >> v(k);
  ExpectNear(v, (Eigen::Matrix<double, 6, 1>() << 0.5, 0, 0, 0, 0, kPi / 2).finished(), 1e-15);
}

TEST(MergeFixedTest, SdfGroupInsideANestedModelIsMergedThere) {
  const MergeFixedResult merged = MergeSdfFixture("nested.sdf");
  ASSERT_TRUE(merged.errors.empty()) << merged.errors.front().ToString();
  EXPECT_EQ(merged.merged_links, 1);
  const ReadResult read = ReadModelString(merged.text, "merged.sdf");
  ASSERT_TRUE(read.ok()) << merged.text;
  const Model& model = read.models.front();
  ASSERT_EQ(model.links.size(), 2u);  // base, inner::x
  const Inertial& in = *model.links[model.FindLink("inner::x")].inertial;
  // By hand: two 1 kg links with SDF's default inertia diag(1, 1, 1), 1 m apart along x: m = 2,
  // center of mass x = 0.5; each adds 1·(0.25·1 − d·dᵀ) = diag(0, 0.25, 0.25) about it, so
  // I = diag(2, 2.5, 2.5).
  EXPECT_EQ(in.mass, 2);
  EXPECT_EQ(in.X_BBi.p_AB, Eigen::Vector3d(0.5, 0, 0));
  EXPECT_EQ(Eigen::Vector3d(in.ixx, in.iyy, in.izz), Eigen::Vector3d(2, 2.5, 2.5));
  // The outer joint naming the nested root is kept; y's visual is in x at y's place.
  EXPECT_EQ(model.joints.size(), 1u);
  EXPECT_EQ(model.joints[0].child, "inner::x");
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(merged.text.c_str()), tinyxml2::XML_SUCCESS);
  EXPECT_EQ(PoseText(FindNamed(FindNamed(doc.RootElement(), "link", "x"), "visual", "v")),
            "1 0 0 0 0 0");
}

TEST(MergeFixedTest, SdfOneSixPoseFrameAttributeIsRewrittenToTheRoot) {
  const MergeFixedResult merged = MergeSdfFixture("old_frame.sdf");
  ASSERT_TRUE(merged.errors.empty()) << merged.errors.front().ToString();
  const ReadResult read = ReadModelString(merged.text, "merged.sdf");
  ASSERT_TRUE(read.ok()) << merged.text;
  const Model& model = read.models.front();
  ASSERT_EQ(model.links.size(), 2u);
  // By hand: 1 kg at the origin and 3 kg at z = 1, both with SDF's default inertia diag(1, 1, 1):
  // m = 4, center of mass z = 0.75; about it 1·0.75² + 3·0.25² = 0.75 is added to ixx and iyy.
  const Inertial& in = *model.links[model.FindLink("a")].inertial;
  EXPECT_EQ(in.mass, 4);
  EXPECT_EQ(in.X_BBi.p_AB, Eigen::Vector3d(0, 0, 0.75));
  EXPECT_EQ(Eigen::Vector3d(in.ixx, in.iyy, in.izz), Eigen::Vector3d(2.75, 2.75, 2));
  // c's pose, 1 0 0 in b's frame, is now 1 0 1 in a's, with the same attribute.
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(merged.text.c_str()), tinyxml2::XML_SUCCESS);
  const tinyxml2::XMLElement* c = FindNamed(doc.RootElement(), "link", "c");
  EXPECT_STREQ(c->FirstChildElement("pose")->Attribute("frame"), "a");
  EXPECT_EQ(c->FirstChildElement("pose")->Attribute("relative_to"), nullptr);
  EXPECT_EQ(PoseText(c), "1 0 1 0 0 0");
  const Joint& hinge = model.joints[model.FindParentJoint("c")];
  EXPECT_EQ(hinge.parent, "a");
  EXPECT_EQ(hinge.X_PC.p_AB, Eigen::Vector3d(1, 0, 1));
}

TEST(MergeFixedTest, SdfWeldAcrossModelScopesIsANotSupportedErrorAtItsLine) {
  const MergeFixedResult merged = MergeSdfFixture("cross_scope.sdf");
  ASSERT_FALSE(merged.errors.empty());
  EXPECT_TRUE(merged.text.empty());
  EXPECT_EQ(merged.errors[0].location.file, "cross_scope.sdf");
  EXPECT_EQ(merged.errors[0].location.line, 8);  // <link name="x"> of the nested model
  EXPECT_EQ(merged.errors[0].element, "<link> 'inner::x'");
  EXPECT_NE(merged.errors[0].message.find("does not support"), std::string::npos);
}

// tinyxml2 accepts text after the root element but re-prints it as a file it refuses (found by
// tools/fuzz.sh sdf): merge-fixed then writes nothing and says why, never a broken file.
TEST(MergeFixedTest, AMergedTextThatWouldNotReadBackIsAnError) {
  const std::string path = std::string(MASSPROPS_TESTDATA_DIR) +
                           "/fuzz/regressions/sdf/merge_text_after_the_root_element.sdf";
  ASSERT_TRUE(ReadModelString(ReadText(path), "in.sdf").ok());  // The input itself reads.
  const MergeFixedResult merged = MergeFixedJoints(ReadText(path), "in.sdf");
  ASSERT_EQ(merged.errors.size(), 1u);
  EXPECT_TRUE(merged.text.empty());
  EXPECT_NE(merged.errors[0].message.find("cannot write this file: the merged model does not "
                                          "read back with 2 links (the merged text, line 64"),
            std::string::npos)
      << merged.errors[0].message;
}

TEST(MergeFixedTest, SdfGazeboTargetWritesTheFileUnchangedAndSaysWhy) {
  const std::string path = std::string(MASSPROPS_TESTDATA_DIR) + "/merge_sdf/two_boxes.sdf";
  const MergeFixedResult merged = MergeSdfFixture("two_boxes.sdf", Target::kGazebo);
  ASSERT_TRUE(merged.errors.empty());
  EXPECT_EQ(merged.text, ReadText(path));
  EXPECT_EQ(merged.merged_links, 0);
  ASSERT_EQ(merged.notes.size(), 1u);
  EXPECT_NE(merged.notes[0].find("does not lump"), std::string::npos);
}

TEST(MergeFixedTest, RollPitchYawRoundTripsThroughTheUrdfConvention) {
  // URDF: R = Rz(yaw)·Ry(pitch)·Rx(roll) (ROS REP 103 / urdfdom's Rotation::setFromRPY).
  const Eigen::Vector3d rpy(0.3, -0.2, 2.5);
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(rpy(2), Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(rpy(1), Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(rpy(0), Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  ExpectNear(RotationToRollPitchYaw(R), rpy, 1e-15);
  // Gimbal lock (pitch 90°): the rotation, not the angles, must come back.
  const Eigen::Matrix3d locked = (Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()) *
                                  Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitY()) *
                                  Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()))
                                     .toRotationMatrix();
  const Eigen::Vector3d a = RotationToRollPitchYaw(locked);
  const Eigen::Matrix3d back = (Eigen::AngleAxisd(a(2), Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(a(1), Eigen::Vector3d::UnitY()) *
                                Eigen::AngleAxisd(a(0), Eigen::Vector3d::UnitX()))
                                   .toRotationMatrix();
  ExpectNear(back, locked, 1e-12);
}

// A chain world -> base -> a -> b, every joint fixed, with <preserveFixedJoint> on base->a.
// Masses 1, 2 and 3 kg at the link origins, each with inertia diag(0.1, 0.1, 0.1) kg·m²; a is
// 1 m along x from base, b 1 m along x from a.
std::string GazeboChain() {
  auto link = [](const std::string& name, double mass) {
    return "<link name=\"" + name + "\"><inertial><mass value=\"" + std::to_string(mass) +
           "\"/><inertia ixx=\"0.1\" iyy=\"0.1\" izz=\"0.1\" ixy=\"0\" ixz=\"0\" "
           "iyz=\"0\"/></inertial></link>";
  };
  auto joint = [](const std::string& name, const std::string& parent, const std::string& child,
                  const std::string& xyz) {
    return "<joint name=\"" + name + "\" type=\"fixed\"><parent link=\"" + parent +
           "\"/><child link=\"" + child + "\"/><origin xyz=\"" + xyz + "\"/></joint>";
  };
  return "<robot name=\"chain\"><link name=\"world\"/>" + link("base", 1) + link("a", 2) +
         link("b", 3) + joint("to_world", "world", "base", "0 0 1") +
         joint("keep", "base", "a", "1 0 0") + joint("weld", "a", "b", "1 0 0") +
         "<gazebo reference=\"keep\"><preserveFixedJoint>true</preserveFixedJoint></gazebo>"
         "</robot>";
}

// --target gazebo merges as libsdformat lumps (gazebosim/sdformat parser_urdf.cc and its
// documentation of <preserveFixedJoint>): the preserved joint and the joint from the root link
// named "world" stay; only b is lumped into a. The generic merge folds everything into world.
TEST(MergeFixedTest, GazeboTargetKeepsPreservedJointsAndTheWorld) {
  const std::string text = GazeboChain();
  const MergeFixedResult gazebo = MergeFixedJoints(text, "chain.urdf", Target::kGazebo);
  ASSERT_TRUE(gazebo.errors.empty()) << gazebo.errors.front().ToString();
  EXPECT_EQ(gazebo.merged_links, 1);
  const ReadResult read = ReadModelString(gazebo.text, "merged.urdf");
  ASSERT_EQ(read.models.size(), 1u) << gazebo.text;
  const Model& model = read.models.front();
  ASSERT_EQ(model.links.size(), 3u) << gazebo.text;  // world, base, a
  EXPECT_EQ(model.FindLink("b"), -1);
  ASSERT_GE(model.FindLink("a"), 0);
  const Inertial& a = *model.links[model.FindLink("a")].inertial;
  // Hand-derived: m = 2 + 3 = 5 kg; c = (2·0 + 3·1)/5 = 0.6 m along x; about c, Ixx = 0.1 + 0.1,
  // Iyy = Izz = 0.2 + 2·0.6² + 3·0.4² = 0.2 + 0.72 + 0.48 = 1.4 kg·m².
  EXPECT_DOUBLE_EQ(a.mass, 5);
  ExpectNear(a.X_BBi.p_AB, Eigen::Vector3d(0.6, 0, 0), 1e-15);
  EXPECT_NEAR(a.ixx, 0.2, 1e-15);
  EXPECT_NEAR(a.iyy, 1.4, 1e-14);
  EXPECT_NEAR(a.izz, 1.4, 1e-14);
  EXPECT_EQ(MergeFixedJoints(text, "chain.urdf").merged_links, 3);  // generic: all into world
}

// A massless member's inertia still counts (libsdformat adds it): 1 kg root with diag(0.1), a
// massless member with diag(0.01) at the same origin gives diag(0.11), hand-added.
TEST(MergeFixedTest, AMasslessMembersInertiaIsAdded) {
  const std::string text =
      "<robot name=\"r\"><link name=\"base\"><inertial><mass value=\"1\"/><inertia ixx=\"0.1\" "
      "iyy=\"0.1\" izz=\"0.1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link><link "
      "name=\"foot\"><inertial><mass value=\"0\"/><inertia ixx=\"0.01\" iyy=\"0.01\" "
      "izz=\"0.01\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link><joint name=\"w\" "
      "type=\"fixed\"><parent link=\"base\"/><child link=\"foot\"/></joint></robot>";
  const MergeFixedResult merged = MergeFixedJoints(text, "r.urdf");
  const ReadResult read = ReadModelString(merged.text, "merged.urdf");
  ASSERT_EQ(read.models.size(), 1u) << merged.text;
  const Inertial& base = *read.models.front().links.front().inertial;
  EXPECT_DOUBLE_EQ(base.mass, 1);
  EXPECT_NEAR(base.ixx, 0.11, 1e-15);
  EXPECT_NEAR(base.izz, 0.11, 1e-15);
}

TEST(MergeFixedTest, MujocoAndDrakeTargetsAreNotSupported) {
  for (Target target : {Target::kMujoco, Target::kDrake}) {
    const MergeFixedResult merged = MergeFixedJoints(GazeboChain(), "chain.urdf", target);
    ASSERT_EQ(merged.errors.size(), 1u);
    EXPECT_NE(merged.errors.front().message.find("is not supported"), std::string::npos);
    EXPECT_EQ(merged.text, "");
  }
}

}  // namespace
}  // namespace massprops

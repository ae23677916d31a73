// Target profiles (include/massprops/analysis/target_profile.h) on small hand-made URDFs whose
// outcome is worked out by hand from MuJoCo 2.2.2's compiler rules (user_objects.cc
// mjCBody::Compile: exact A + B >= C; user_model.cc: fusestatic and mjMINVAL = 1e-15 on moving
// bodies). The same rules are checked against libmujoco itself on the corpus in
// target_profile_mujoco_test.cc.
#include "massprops/analysis/target_profile.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "massprops/analysis/config.h"
#include "massprops/analysis/repair.h"
#include "massprops/io/model_reader.h"
#include "tool_runner.h"

namespace massprops {
namespace {

// A URDF: a fixed root 'base' (mass 1), then the links and joints given.
std::string Robot(const std::string& body, const std::string& mujoco = "") {
  return "<robot name=\"r\">" + mujoco +
         "<link name=\"base\"><inertial><mass value=\"1\"/>"
         "<inertia ixx=\"0.01\" iyy=\"0.01\" izz=\"0.01\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/>"
         "</inertial></link>" +
         body + "</robot>";
}

std::string Link(const std::string& name, const std::string& inertial) {
  return "<link name=\"" + name + "\">" + inertial + "</link>";
}

std::string Inertial(double mass, double ixx, double iyy, double izz,
                     const std::string& xyz = "0 0 0") {
  char buffer[512];
  std::snprintf(buffer, sizeof(buffer),
                "<inertial><origin xyz=\"%s\"/><mass value=\"%.17g\"/><inertia ixx=\"%.17g\" "
                "iyy=\"%.17g\" izz=\"%.17g\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial>",
                xyz.c_str(), mass, ixx, iyy, izz);
  return buffer;
}

std::string Joint(const std::string& name, const std::string& type, const std::string& parent,
                  const std::string& child) {
  return "<joint name=\"" + name + "\" type=\"" + type + "\"><parent link=\"" + parent +
         "\"/><child link=\"" + child +
         "\"/><axis xyz=\"0 0 1\"/><limit effort=\"1\" velocity=\"1\" lower=\"-1\" "
         "upper=\"1\"/></joint>";
}

MujocoPrediction Predict(const std::string& urdf) {
  const ReadResult read = ReadModelString(urdf, "test.urdf");
  EXPECT_EQ(read.models.size(), 1u);
  if (read.models.empty()) return {};
  return PredictMujoco(read.models.front(), ReadMujocoCompilerOptions(urdf));
}

TEST(TargetProfileTest, ParsesTargetNames) {
  EXPECT_EQ(ParseTarget("mujoco"), Target::kMujoco);
  EXPECT_EQ(ParseTarget("drake"), Target::kDrake);
  EXPECT_EQ(ParseTarget("gazebo"), Target::kGazebo);
  EXPECT_EQ(ParseTarget("generic"), Target::kGeneric);
  EXPECT_FALSE(ParseTarget("bullet"));
  for (Target t : {Target::kGeneric, Target::kMujoco, Target::kDrake, Target::kGazebo}) {
    EXPECT_EQ(ParseTarget(ToString(t)), t);
  }
}

TEST(TargetProfileTest, TargetRulesAreRegistered) {
  for (const RuleInfo& rule : TargetRules()) {
    bool found = false;
    for (const RuleInfo& info : AllRules()) found |= info.id == rule.id;
    EXPECT_TRUE(found) << rule.id;
  }
}

TEST(TargetProfileTest, ConfigurationFileNamesTheTarget) {
  EXPECT_EQ(ParseConfig("target = \"mujoco\"\n", "c.toml").target, Target::kMujoco);
  EXPECT_FALSE(ParseConfig("tolerance = 1e-6\n", "c.toml").target);
  EXPECT_THROW(ParseConfig("target = \"bullet\"\n", "c.toml"), ConfigError);
}

// A thin rod, diag(0.1, 0.1, 0), is a valid body (a principal moment of 0), but a moving body
// needs every principal moment >= 1e-15 in MuJoCo.
TEST(MujocoProfileTest, MovingThinRodIsRefusedBelowMinVal) {
  const MujocoPrediction p =
      Predict(Robot(Link("rod", Inertial(1, 0.1, 0.1, 0)) + Joint("j", "revolute", "base", "rod")));
  ASSERT_EQ(p.errors.size(), 1u);
  EXPECT_EQ(p.errors[0].rule, "mujoco-rejects-below-minval");
  EXPECT_EQ(p.errors[0].body, "rod");
  EXPECT_EQ(p.errors[0].message, "mass and inertia of moving bodies must be larger than mjMINVAL");
  // The same rod welded to the fixed base is fused into it (fusestatic): nothing moves.
  EXPECT_TRUE(
      Predict(Robot(Link("rod", Inertial(1, 0.1, 0.1, 0)) + Joint("j", "fixed", "base", "rod")))
          .accepted());
}

// A thin disk written with 7 digits: 0.0833333 + 0.0833333 = 0.1666666 < 0.1666667. The
// relative violation 1e-7 / 0.3333333 = 3e-7 is within massprops' tolerance 1e-6 (valid), but
// MuJoCo's test is exact — even on the fixed root, which it compiles before fusing.
TEST(MujocoProfileTest, RoundedThinDiskIsRefusedByTheExactTriangleTest) {
  const std::string disk = "<robot name=\"r\">" +
                           Link("base", Inertial(1, 0.0833333, 0.0833333, 0.1666667)) + "</robot>";
  const MujocoPrediction p = Predict(disk);
  ASSERT_EQ(p.errors.size(), 1u);
  EXPECT_EQ(p.errors[0].rule, "mujoco-rejects-inertia-triangle");
  EXPECT_EQ(p.errors[0].body, "base");
  // balanceinertia accepts it.
  const std::string balanced =
      "<robot name=\"r\"><mujoco><compiler balanceinertia=\"true\"/></mujoco>" +
      Link("base", Inertial(1, 0.0833333, 0.0833333, 0.1666667)) + "</robot>";
  EXPECT_TRUE(Predict(balanced).accepted());
  // The check tool: an error with --target mujoco, nothing at error level without it.
  const ReadResult read = ReadModelString(disk, "disk.urdf");
  CheckOptions options;
  ApplyTargetProfile(Target::kMujoco, &options);
  std::vector<Finding> findings = CheckModel(read.models.front(), options);
  AddTargetFindings(read.models.front(), Target::kMujoco, options, {}, &findings);
  std::vector<Finding> errors;
  for (const Finding& f : findings) {
    if (f.severity == Severity::kError) errors.push_back(f);
  }
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].rule, "mujoco-rejects-inertia-triangle");
  EXPECT_NE(errors[0].message.find("Physics disagrees"), std::string::npos);
  EXPECT_NE(errors[0].message.find("balanceinertia"), std::string::npos);
  for (const Finding& f : CheckModel(read.models.front())) EXPECT_NE(f.severity, Severity::kError);
}

// A two-axis joint through a massless intermediate link: physics is fine (mass lies outboard),
// MuJoCo is not; boundmass/boundinertia accept it.
TEST(MujocoProfileTest, MasslessIntermediateLinkIsRefusedUnlessBounded) {
  const std::string body = Link("yaw", "") + Link("pitch", Inertial(1, 0.01, 0.01, 0.01)) +
                           Joint("j1", "revolute", "base", "yaw") +
                           Joint("j2", "revolute", "yaw", "pitch");
  const MujocoPrediction p = Predict(Robot(body));
  ASSERT_EQ(p.errors.size(), 1u);
  EXPECT_EQ(p.errors[0].body, "yaw");
  EXPECT_EQ(p.errors[0].mass, 0);
  EXPECT_TRUE(
      Predict(Robot(body, "<mujoco><compiler boundmass=\"1e-6\" boundinertia=\"1e-9\"/></mujoco>"))
          .accepted());
}

// A static child with mass is fused into its massless moving parent: the fused body has the
// child's mass (1) and inertia, and MuJoCo accepts it.
TEST(MujocoProfileTest, FusedStaticChildGivesTheMovingBodyItsMass) {
  const std::string body = Link("arm", "") + Link("motor", Inertial(1, 0.01, 0.01, 0.01)) +
                           Joint("j1", "revolute", "base", "arm") +
                           Joint("weld", "fixed", "arm", "motor");
  const MujocoPrediction p = Predict(Robot(body));
  EXPECT_TRUE(p.accepted());
  ASSERT_EQ(p.bodies.size(), 1u);  // base is fused into the world, motor into arm
  EXPECT_EQ(p.bodies[0].name, "arm");
  EXPECT_EQ(p.bodies[0].mass, 1);
  EXPECT_NEAR(p.bodies[0].inertia[0], 0.01, 1e-15);
  // Without fusestatic the static child still saves its parent (user_model.cc: "does it have
  // static children with mass and inertia").
  EXPECT_TRUE(Predict(Robot(body, "<mujoco><compiler fusestatic=\"false\"/></mujoco>")).accepted());
}

// A point mass (inertia 0) welded 0.1 m from a massless moving parent: the fused inertia about the
// fused center of mass is 0, below mjEPS = 1e-14; MuJoCo names no body in that message.
TEST(MujocoProfileTest, FusingAPointMassGivesAnInertiaMujocoRefuses) {
  const std::string body = Link("arm", "") + Link("tip", Inertial(1, 0, 0, 0)) +
                           Joint("j1", "revolute", "base", "arm") +
                           "<joint name=\"weld\" type=\"fixed\"><parent link=\"arm\"/><child "
                           "link=\"tip\"/><origin xyz=\"0.1 0 0\"/></joint>";
  const MujocoPrediction p = Predict(Robot(body));
  ASSERT_FALSE(p.accepted());
  EXPECT_EQ(p.errors[0].rule, "mujoco-rejects-fused-inertia");
  EXPECT_EQ(p.errors[0].body, "");
  EXPECT_EQ(p.errors[0].message,
            "error 'inertia must have positive eigenvalues' in fusing static body inertias");
}

// A link without <inertial> takes its mass from its collision geoms (inertiafromgeom="auto"):
// a 0.1 m box of density 1000 has mass 1 and moments 1·(0.05² + 0.05²)/3 = 1/600.
TEST(MujocoProfileTest, LinkWithoutInertialGetsMassFromItsCollisionBox) {
  const std::string body =
      "<link name=\"box\"><collision><geometry><box size=\"0.1 0.1 0.1\"/></geometry></collision>"
      "</link>" +
      Joint("j1", "revolute", "base", "box");
  const MujocoPrediction p = Predict(Robot(body));
  EXPECT_TRUE(p.accepted());
  ASSERT_EQ(p.bodies.size(), 1u);
  EXPECT_NEAR(p.bodies[0].mass, 1, 1e-12);
  EXPECT_NEAR(p.bodies[0].inertia[0], 1.0 / 600, 1e-15);
}

// A link without <inertial> whose two collision boxes are 1e-7 m cubes: MuJoCo's density 1000 gives
// each 1000 · (1e-7)³ = 1e-18 kg, 2e-18 kg in all, below mjMINVAL = 1e-15: mjCBody::GeomFrame
// cannot place the center of mass of several geoms.
TEST(MujocoProfileTest, TinyCollisionGeomsGiveTooLittleMassForTheirCenter) {
  auto speck = [](const std::string& z) {
    return "<collision><origin xyz=\"0 0 " + z +
           "\"/><geometry><box size=\"1e-7 1e-7 1e-7\"/></geometry></collision>";
  };
  const MujocoPrediction p = Predict(Robot("<link name=\"specks\">" + speck("0") + speck("1") +
                                           "</link>" + Joint("j", "revolute", "base", "specks")));
  ASSERT_FALSE(p.errors.empty());
  EXPECT_EQ(p.errors[0].rule, "mujoco-rejects-geom-inertia");
  EXPECT_EQ(p.errors[0].body, "specks");
  EXPECT_EQ(p.errors[0].message, "body mass is too small, cannot compute center of mass");
  EXPECT_NEAR(p.errors[0].mass, 2e-18, 1e-30);
}

// boundmass lifts a mass to at least its value (mju_max): with boundmass="-2" a mass of -1 stays
// -1, and MuJoCo refuses it; with the default 0 it becomes 0 (and then is below mjMINVAL).
TEST(MujocoProfileTest, NegativeMassThatBoundmassDoesNotLiftIsRefused) {
  const std::string body =
      Link("arm", Inertial(-1, 0.01, 0.01, 0.01)) + Joint("j", "revolute", "base", "arm");
  const MujocoPrediction p = Predict(Robot(body, "<mujoco><compiler boundmass=\"-2\"/></mujoco>"));
  ASSERT_FALSE(p.errors.empty());
  EXPECT_EQ(p.errors[0].rule, "mujoco-rejects-negative");
  EXPECT_EQ(p.errors[0].message, "mass and inertia cannot be negative");
  const MujocoPrediction lifted = Predict(Robot(body));
  ASSERT_FALSE(lifted.errors.empty());
  EXPECT_EQ(lifted.errors[0].rule, "mujoco-rejects-below-minval");
}

// A moving link without <inertial> whose collision is a mesh: MuJoCo computes its mass from the
// mesh's volume, which the prediction does not read; `check --target mujoco` says so.
TEST(MujocoProfileTest, InertiaFromAMeshIsSaidToBeUnpredicted) {
  const std::string path = ::testing::TempDir() + "/massprops_target_mesh.urdf";
  {
    std::ofstream out(path);
    out << Robot(
               "<link name=\"shell\"><collision><geometry><mesh filename=\"shell.stl\"/>"
               "</geometry></collision></link>" +
               Joint("j", "revolute", "base", "shell"))
        << "\n";
  }
  const test_support::ToolRun run =
      test_support::RunTool("check --target mujoco --no-geometry '" + path + "'");
  EXPECT_NE(run.output.find("MuJoCo's decision cannot be fully predicted: link 'shell' takes its "
                            "inertia from mesh geometry"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("[mujoco-not-predicted]"), std::string::npos) << run.output;
  std::remove(path.c_str());
}

// fix --target mujoco: the repaired model is accepted (triangle: nearest valid inertia; below
// mjMINVAL: a negligible mass and moment floor).
TEST(MujocoProfileTest, RepairsMakeMujocoAcceptTheModel) {
  for (const std::string& urdf :
       {std::string("<robot name=\"r\">") +
            Link("base", Inertial(1, 0.0833333, 0.0833333, 0.1666667)) + "</robot>",
        Robot(Link("rod", Inertial(1, 0.1, 0.1, 0)) + Joint("j", "revolute", "base", "rod")),
        Robot(Link("yaw", "") + Link("pitch", Inertial(1, 0.01, 0.01, 0.01)) +
              Joint("j1", "revolute", "base", "yaw") + Joint("j2", "revolute", "yaw", "pitch"))}) {
    SCOPED_TRACE(urdf);
    const ReadResult read = ReadModelString(urdf, "t.urdf");
    ASSERT_EQ(read.models.size(), 1u);
    const Model& model = read.models.front();
    ASSERT_FALSE(PredictMujoco(model).accepted());
    const std::vector<Repair> repairs = PlanTargetRepairs(model, Target::kMujoco, {}, {});
    ASSERT_FALSE(repairs.empty());
    EXPECT_TRUE(PredictMujoco(ApplyRepairs(model, repairs)).accepted());
    for (const Repair& r : repairs) {
      // Negligible next to the model: a changed inertial moves by less than 1e-5 relative; an
      // inserted one weighs 1e-6 of the model (2 kg here).
      if (r.inserts_inertial) {
        EXPECT_NEAR(r.after.mass, 2e-6, 1e-18) << DescribeRepair(r);
      } else {
        EXPECT_LT(r.relative_change, 1e-5) << DescribeRepair(r);
      }
    }
  }
}

TEST(MujocoProfileTest, CheckCommandTakesTheTarget) {
  const std::string path = ::testing::TempDir() + "/massprops_target_disk.urdf";
  {
    std::ofstream out(path);
    out << "<robot name=\"r\">" << Link("base", Inertial(1, 0.0833333, 0.0833333, 0.1666667))
        << "</robot>\n";
  }
  const test_support::ToolRun plain = test_support::RunTool("check '" + path + "'");
  EXPECT_EQ(plain.exit_code, 0) << plain.output;
  const test_support::ToolRun mujoco =
      test_support::RunTool("check --target mujoco '" + path + "'");
  EXPECT_EQ(mujoco.exit_code, 1) << mujoco.output;
  EXPECT_NE(mujoco.output.find("[mujoco-rejects-inertia-triangle]"), std::string::npos);
  const test_support::ToolRun bad = test_support::RunTool("check --target bullet '" + path + "'");
  EXPECT_EQ(bad.exit_code, 2);
  // fix --target mujoco writes a file MuJoCo's rules accept.
  const test_support::ToolRun fixed = test_support::RunTool("fix --target mujoco '" + path + "'");
  EXPECT_EQ(fixed.exit_code, 0);
  const ReadResult reread = ReadModelString(fixed.output, "fixed.urdf");
  ASSERT_EQ(reread.models.size(), 1u) << fixed.output;
  EXPECT_TRUE(PredictMujoco(reread.models.front()).accepted()) << fixed.output;
  std::remove(path.c_str());
}

// `target = "mujoco"` in .massprops.toml applies to files below it; --target generic overrides it.
TEST(MujocoProfileTest, ConfigurationFileSetsTheTarget) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(::testing::TempDir()) / "massprops_target_config";
  fs::create_directories(dir);
  {
    std::ofstream out(dir / "disk.urdf");
    out << "<robot name=\"r\">" << Link("base", Inertial(1, 0.0833333, 0.0833333, 0.1666667))
        << "</robot>\n";
    std::ofstream config(dir / ".massprops.toml");
    config << "target = \"mujoco\"\n";
  }
  const std::string file = "'" + (dir / "disk.urdf").string() + "'";
  EXPECT_EQ(test_support::RunTool("check " + file).exit_code, 1);
  EXPECT_EQ(test_support::RunTool("check --target generic " + file).exit_code, 0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace massprops

namespace massprops {
namespace {

std::vector<Finding> TargetFindings(const std::string& urdf, Target target) {
  const ReadResult read = ReadModelString(urdf, "t.urdf");
  EXPECT_EQ(read.models.size(), 1u);
  if (read.models.empty()) return {};
  CheckOptions options;
  ApplyTargetProfile(target, &options);
  std::vector<Finding> findings = CheckModel(read.models.front(), options);
  AddTargetFindings(read.models.front(), target, options, ReadMujocoCompilerOptions(urdf),
                    &findings, urdf);
  return findings;
}

int Count(const std::vector<Finding>& findings, const std::string& rule) {
  int n = 0;
  for (const Finding& f : findings) n += f.rule == rule ? 1 : 0;
  return n;
}

// Drake accepts a massless body when mass lies outboard of it (the yaw link of a two-axis joint),
// and refuses one with nothing outboard (a massless tip).
TEST(DrakeProfileTest, MasslessBodyIsAcceptedOnlyWithMassOutboard) {
  const std::string two_axis =
      Robot(Link("yaw", "") + Link("pitch", Inertial(1, 0.01, 0.01, 0.01)) +
            Joint("j1", "revolute", "base", "yaw") + Joint("j2", "revolute", "yaw", "pitch"));
  EXPECT_EQ(Count(TargetFindings(two_axis, Target::kDrake), "drake-rejects-massless-body"), 0);
  const std::string tip = Robot(Link("tip", "") + Joint("j1", "revolute", "base", "tip"));
  const std::vector<Finding> findings = TargetFindings(tip, Target::kDrake);
  EXPECT_EQ(Count(findings, "drake-rejects-massless-body"), 1);
  EXPECT_EQ(Count(findings, "massless-moving-body"), 0);  // the Drake rule decides
}

// A point mass on the axis of a revolute joint has no moment about it: singular for Drake. The
// same mass 0.1 m off the axis has m·d² = 0.01 kg·m² about it: fine.
TEST(DrakeProfileTest, NoMomentAboutTheRevoluteAxisIsRefused) {
  const std::string on_axis =
      Robot(Link("p", Inertial(1, 0, 0, 0)) + Joint("j1", "revolute", "base", "p"));
  EXPECT_EQ(Count(TargetFindings(on_axis, Target::kDrake), "drake-rejects-massless-body"), 1);
  const std::string off_axis =
      Robot(Link("p", Inertial(1, 0, 0, 0, "0.1 0 0")) + Joint("j1", "revolute", "base", "p"));
  EXPECT_EQ(Count(TargetFindings(off_axis, Target::kDrake), "drake-rejects-massless-body"), 0);
}

// Drake's tolerance is 16·eps·max(1, tr/2) (absolute below 1 kg·m²): 1 + 1 < 2 + 1e-15 is
// within it (1e-15 < 3.55e-15), 1 + 1 < 2.001 is not.
TEST(DrakeProfileTest, ValidityUsesDrakesTolerance) {
  EXPECT_EQ(Count(TargetFindings(Robot(Link("a", Inertial(1, 0.1, 0.1, 0.2 + 1e-15)) +
                                       Joint("j", "revolute", "base", "a")),
                                 Target::kDrake),
                  "drake-rejects-invalid-inertia"),
            0);
  EXPECT_EQ(Count(TargetFindings(Robot(Link("a", Inertial(1, 0.1, 0.1, 0.201)) +
                                       Joint("j", "revolute", "base", "a")),
                                 Target::kDrake),
                  "drake-rejects-invalid-inertia"),
            1);
}

// Gazebo lumps links across fixed joints unless the joint is preserved; an invalid member of a
// valid lumped body is a warning, not an error.
TEST(GazeboProfileTest, LumpsFixedJointsUnlessPreserved) {
  // The member's moments (0.1, 0.1, 0.3) break the triangle inequality; lumped 1 m from a 10 kg
  // base, the composite about its center of mass is valid (by the parallel-axis term
  // m_b·m_a/(m_b+m_a)·1² = 10/11 kg·m² on two axes).
  const std::string body = Link("member", Inertial(1, 0.1, 0.1, 0.3)) +
                           "<joint name=\"weld\" type=\"fixed\"><parent link=\"base\"/><child "
                           "link=\"member\"/><origin xyz=\"1 0 0\"/></joint>";
  const std::string heavy =
      "<robot name=\"r\"><link name=\"base\"><inertial><mass value=\"10\"/><inertia ixx=\"1\" "
      "iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link>" +
      body + "</robot>";
  const std::vector<Finding> lumped = TargetFindings(heavy, Target::kGazebo);
  EXPECT_EQ(Count(lumped, "gazebo-lumps-fixed-joint"), 1);
  int member_findings = 0;
  for (const Finding& f : lumped) {
    if (f.rule == "inertia-not-physical" && f.link == "member") {
      ++member_findings;
      EXPECT_EQ(f.severity, Severity::kWarning) << f.message;
    }
  }
  EXPECT_EQ(member_findings, 1);
  const std::string preserved =
      heavy.substr(0, heavy.size() - 8) +
      "<gazebo reference=\"weld\"><preserveFixedJoint>true</preserveFixedJoint></gazebo></robot>";
  const ReadResult read = ReadModelString(preserved, "t.urdf");
  ASSERT_EQ(read.models.size(), 1u);
  EXPECT_EQ(GazeboBodies(read.models.front(), preserved).size(), 2u);
  EXPECT_EQ(GazeboBodies(read.models.front(), heavy).size(), 1u);
  EXPECT_EQ(Count(TargetFindings(preserved, Target::kGazebo), "gazebo-lumps-fixed-joint"), 0);
}

}  // namespace
}  // namespace massprops

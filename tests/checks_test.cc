#include "massprops/analysis/checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "corpus_manifest.h"
#include "massprops/analysis/target_profile.h"
#include "massprops/io/sdf_reader.h"
#include "massprops/io/urdf_reader.h"

namespace massprops {
namespace {

const std::string kCheckDir = std::string(MASSPROPS_TESTDATA_DIR) + "/check/";

Model ReadFixture(const std::string& name) {
  const ReadResult result = ReadUrdfFile(kCheckDir + name + ".urdf");
  EXPECT_TRUE(result.ok()) << name << ": "
                           << (result.errors.empty() ? "" : result.errors[0].ToString());
  EXPECT_EQ(result.models.size(), 1u);
  return result.models.empty() ? Model() : result.models[0];
}

std::vector<const Finding*> Select(const std::vector<Finding>& findings, const std::string& rule) {
  std::vector<const Finding*> out;
  for (const Finding& f : findings) {
    if (f.rule == rule) out.push_back(&f);
  }
  return out;
}

std::string Dump(const std::vector<Finding>& findings) {
  std::string text;
  for (const Finding& f : findings) text += "  [" + f.rule + "] " + f.message + "\n";
  return text;
}

// Every rule has a fixture testdata/check/<rule>.urdf that triggers it and
// testdata/check/<rule>-ok.urdf that barely does not (numbers explained in docs/rules.md).
class RuleFixtureTest : public ::testing::TestWithParam<std::string> {};

TEST_P(RuleFixtureTest, TriggersOnItsFixtureAndNotOnTheBarelyValidOne) {
  const std::string rule = GetParam();
  const std::vector<Finding> bad = CheckModel(ReadFixture(rule));
  EXPECT_EQ(Select(bad, rule).size(), 1u) << Dump(bad);
  const std::vector<Finding> ok = CheckModel(ReadFixture(rule + "-ok"));
  EXPECT_TRUE(Select(ok, rule).empty()) << Dump(ok);
}

INSTANTIATE_TEST_SUITE_P(EveryRuleWithAFixture, RuleFixtureTest,
                         ::testing::Values("mass-not-positive", "inertia-not-physical",
                                           "massless-moving-body", "zero-inertia-about-joint-axis",
                                           "inertial-missing", "products-sign-suspect",
                                           "units-suspect", "inertia-about-origin-suspect",
                                           "inertia-exceeds-geometry", "com-outside-geometry",
                                           "inertia-near-boundary"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(ChecksTest, EveryRuleIsListedOnceWithItsSeverity) {
  std::set<std::string> ids;
  for (const RuleInfo& r : AllRules()) EXPECT_TRUE(ids.insert(r.id).second) << r.id;
  // 12 rules of CheckModel + 4 rules whose findings the readers make (ReadResult::findings,
  // inertial-auto from the SDF reader) + 9 target-profile rules (target_profile.h, reported only
  // with --target) + 2 geometry rules (geometry_checks.h), off unless --geometry.
  EXPECT_EQ(ids.size(), 18u + TargetRules().size());
  EXPECT_EQ(TargetRules().size(), 9u);
  EXPECT_FALSE(AllRules().back().enabled_by_default);
  EXPECT_EQ(AllRules().front().default_severity, Severity::kError);
  EXPECT_EQ(ToString(Severity::kNote), std::string("note"));
  EXPECT_EQ(ParseSeverity("warning"), Severity::kWarning);
  EXPECT_FALSE(ParseSeverity("fatal").has_value());
}

// SDF spec (model.sdf): a static model "is immovable", so a wall with collision geometry and no
// <inertial>, or a massless moving link inside it, is what the file should say: nothing is
// reported. The same model without <static> gets inertial-missing for its links.
TEST(ChecksTest, StaticSdfModelsNeedNoMassProperties) {
  const std::string body =
      "<link name='base'><collision name='c'><geometry><box><size>1 1 1</size></box></geometry>"
      "</collision></link>\n"
      "<link name='door'><inertial><mass>0</mass></inertial><collision name='c'><geometry><box>"
      "<size>1 1 0.1</size></box></geometry></collision></link>\n"
      "<joint name='hinge' type='revolute'><parent>base</parent><child>door</child>"
      "<axis><xyz>0 0 1</xyz></axis></joint>\n";
  const ReadResult fixed = ReadSdfString(
      "<sdf version='1.7'><model name='wall'><static>true</static>\n" + body + "</model></sdf>",
      "static.sdf");
  ASSERT_TRUE(fixed.ok()) << fixed.errors.front().ToString();
  EXPECT_TRUE(CheckModel(fixed.models[0]).empty()) << Dump(CheckModel(fixed.models[0]));
  const ReadResult moving = ReadSdfString(
      "<sdf version='1.7'><model name='wall'>\n" + body + "</model></sdf>", "moving.sdf");
  ASSERT_TRUE(moving.ok()) << moving.errors.front().ToString();
  const std::vector<Finding> findings = CheckModel(moving.models[0]);
  EXPECT_EQ(Select(findings, "inertial-missing").size(), 1u) << Dump(findings);
  EXPECT_EQ(Select(findings, "massless-moving-body").size(), 1u) << Dump(findings);
}

// A clean arm: valid inertias, a massless tool0, a zero-mass flange with an inertial of zeros and
// a base_footprint frame, all welded: nothing at all is reported.
TEST(ChecksTest, ACleanModelWithMasslessWeldedFramesGetsNoFinding) {
  const std::vector<Finding> findings = CheckModel(ReadFixture("clean"));
  EXPECT_TRUE(findings.empty()) << Dump(findings);
}

// Principal moments 0.1, 0.2, 0.5 (diagonal as written): 0.1 + 0.2 < 0.5 by 0.2, trace 0.8,
// so 25% of the trace (hand-derived).
TEST(ChecksTest, InertiaNotPhysicalQuotesThePrincipalMomentsAndTheViolatedInequality) {
  const std::vector<Finding> findings = CheckModel(ReadFixture("inertia-not-physical"));
  const auto selected = Select(findings, "inertia-not-physical");
  ASSERT_EQ(selected.size(), 1u);
  const Finding& f = *selected[0];
  EXPECT_EQ(f.severity, Severity::kError);
  EXPECT_EQ(f.link, "arm");
  EXPECT_NE(f.message.find("principal moments 0.1, 0.2, 0.5: 0.1 + 0.2 < 0.5 (by 0.2 = 25% of "
                           "the trace)"),
            std::string::npos)
      << f.message;
  EXPECT_EQ(f.location.line, 17);  // the <inertia> element of the fixture
  bool found = false;
  for (const auto& [name, value] : f.values) {
    if (name == "relative_violation") {
      found = true;
      EXPECT_NEAR(value, 0.25, 1e-12);
    }
  }
  EXPECT_TRUE(found);
}

// Products +0.0045 on diagonal 0.01: eigenvalues 0.01 + 2·0.0045 = 0.019 and 0.01 − 0.0045 =
// 0.0055 (twice): invalid; negated: 0.001, 0.0145, 0.0145 (valid). Hand-derived from the
// eigenvalues of a·1 + q·(ones − 1): a + 2q, a − q, a − q.
TEST(ChecksTest, ProductsSignSuspectComesWithTheInvalidInertiaItExplains) {
  const std::vector<Finding> findings = CheckModel(ReadFixture("products-sign-suspect"));
  ASSERT_EQ(Select(findings, "inertia-not-physical").size(), 1u);
  const auto selected = Select(findings, "products-sign-suspect");
  ASSERT_EQ(selected.size(), 1u);
  EXPECT_NE(selected[0]->message.find("principal moments are 0.001, 0.0145, 0.0145"),
            std::string::npos)
      << selected[0]->message;
}

// Mass 2000 (grams) with the inertia of a 2 kg, 0.4 m × r 0.05 m cylinder: k = sqrt(0.0583334 /
// 4000) = 0.0038188 m against the half-diagonal sqrt(0.05² + 0.05² + 0.2²) = 0.212132 m.
TEST(ChecksTest, UnitsSuspectNamesTheUnitMistakeThatFits) {
  const auto findings = CheckModel(ReadFixture("units-suspect"));
  const auto selected = Select(findings, "units-suspect");
  ASSERT_EQ(selected.size(), 1u);
  EXPECT_NE(selected[0]->message.find("grams"), std::string::npos) << selected[0]->message;
  EXPECT_NE(selected[0]->message.find("0.00381882 m"), std::string::npos) << selected[0]->message;
  EXPECT_NE(selected[0]->message.find("0.212132 m"), std::string::npos) << selected[0]->message;
}

TEST(ChecksTest, OverridesChangeTheSeverityOrDisableARule) {
  const Model model = ReadFixture("inertia-not-physical");
  CheckOptions options;
  options.overrides["inertia-not-physical"] = Severity::kWarning;
  auto findings = CheckModel(model, options);
  ASSERT_EQ(Select(findings, "inertia-not-physical").size(), 1u);
  EXPECT_EQ(Select(findings, "inertia-not-physical")[0]->severity, Severity::kWarning);
  options.overrides["inertia-not-physical"] = std::nullopt;
  findings = CheckModel(model, options);
  EXPECT_TRUE(Select(findings, "inertia-not-physical").empty());
}

// The same invalid inertia as inertia-not-physical.urdf, with
// <!-- massprops: ignore inertia-not-physical --> inside the link.
TEST(ChecksTest, AnIgnoreCommentInsideTheLinkSuppressesTheRuleForThatLink) {
  const std::vector<Finding> findings = CheckModel(ReadFixture("ignore-comment"));
  EXPECT_TRUE(Select(findings, "inertia-not-physical").empty()) << Dump(findings);
  Model model = ReadFixture("inertia-not-physical");
  model.links[1].ignored_rules = {"all"};
  EXPECT_TRUE(CheckModel(model).empty());
}

// The tolerance decides: the near-boundary fixture violates the triangle inequality by 5e-7 with
// trace 0.6 (8.3e-7 of the trace): valid at 1e-6, invalid at 1e-7.
TEST(ChecksTest, TheToleranceOptionMovesTheValidityBoundary) {
  const Model model = ReadFixture("inertia-near-boundary");
  CheckOptions options;
  EXPECT_TRUE(Select(CheckModel(model, options), "inertia-not-physical").empty());
  options.tolerance = 1e-7;
  EXPECT_EQ(Select(CheckModel(model, options), "inertia-not-physical").size(), 1u);
  EXPECT_TRUE(Select(CheckModel(model, options), "inertia-near-boundary").empty());
}

Model TwoLinkModel() {
  Model model;
  model.name = "m";
  model.root_link = "base";
  Link base;
  base.name = "base";
  Inertial in;
  in.mass = 1;
  in.ixx = in.iyy = in.izz = 0.01;
  base.inertial = in;
  Link arm = base;
  arm.name = "arm";
  model.links = {base, arm};
  Joint joint;
  joint.name = "j";
  joint.type = Joint::Type::kRevolute;
  joint.type_name = "revolute";
  joint.parent = "base";
  joint.child = "arm";
  model.joints = {joint};
  return model;
}

TEST(ChecksTest, InertiaNotFiniteIsReportedForNaNAndInfinity) {
  Model model = TwoLinkModel();
  model.links[1].inertial->ixy = std::numeric_limits<double>::quiet_NaN();
  auto findings = CheckModel(model);
  EXPECT_EQ(Select(findings, "inertia-not-finite").size(), 1u) << Dump(findings);
  EXPECT_TRUE(Select(findings, "inertia-not-physical").empty());
  model = TwoLinkModel();
  model.links[1].inertial->izz = std::numeric_limits<double>::infinity();
  findings = CheckModel(model);
  EXPECT_EQ(Select(findings, "inertia-not-finite").size(), 1u) << Dump(findings);
  EXPECT_TRUE(Select(CheckModel(TwoLinkModel()), "inertia-not-finite").empty());
}

// Without geometry, k = sqrt(tr/(2m)) > 10 m is flagged: tr = 3·100, m = 1 → k = 12.2 m;
// tr = 3·66, m = 1 → k = 9.95 m is not.
TEST(ChecksTest, UnitsSuspectWithoutGeometryFlagsARadiusOfGyrationBeyondTenMetres) {
  Model model = TwoLinkModel();
  model.links[1].inertial->ixx = model.links[1].inertial->iyy = model.links[1].inertial->izz = 100;
  EXPECT_EQ(Select(CheckModel(model), "units-suspect").size(), 1u);
  model.links[1].inertial->ixx = model.links[1].inertial->iyy = model.links[1].inertial->izz = 66;
  EXPECT_TRUE(Select(CheckModel(model), "units-suspect").empty());
}

// Two links each with the invalid moments (0, 0, 1) welded with parallel axes and the same com:
// the composite (0, 0, 2) is invalid too: one finding per link plus one for the group.
// The thin rod (1, 1, 0) welded to a massive valid body: the link is still reported (as written
// it is valid: a rod is on the boundary), and nothing else.
TEST(ChecksTest, AWeldedGroupIsJudgedAsOneRigidBodyToo) {
  Model model = TwoLinkModel();
  Link extra = model.links[1];
  extra.name = "extra";
  extra.inertial->ixx = extra.inertial->iyy = 0;
  extra.inertial->izz = 1;
  model.links[1].inertial->ixx = model.links[1].inertial->iyy = 0;
  model.links[1].inertial->izz = 1;
  model.links.push_back(extra);
  Joint weld;
  weld.name = "w";
  weld.type = Joint::Type::kFixed;
  weld.type_name = "fixed";
  weld.parent = "arm";
  weld.child = "extra";
  model.joints.push_back(weld);
  const auto findings = CheckModel(model);
  const auto selected = Select(findings, "inertia-not-physical");
  ASSERT_EQ(selected.size(), 3u) << Dump(findings);
  int group_findings = 0;
  for (const Finding* f : selected) {
    for (const auto& value : f->values) group_findings += value.first == "group_links" ? 1 : 0;
  }
  EXPECT_EQ(group_findings, 1);
}

// A moving body that is a point mass on its joint axis has zero moment about it.
TEST(ChecksTest, ZeroInertiaAboutJointAxisUsesTheCompositeAboutTheJointOrigin) {
  Model model = TwoLinkModel();
  model.joints[0].axis = Eigen::Vector3d(0, 0, 1);
  model.links[1].inertial->ixx = model.links[1].inertial->iyy = model.links[1].inertial->izz = 0;
  model.links[1].inertial->X_BBi.p_AB = Eigen::Vector3d(0, 0, 0.3);
  EXPECT_EQ(Select(CheckModel(model), "zero-inertia-about-joint-axis").size(), 1u);
  // Offset 0.1 m from the axis: moment m·0.1² = 0.01 > 0.
  model.links[1].inertial->X_BBi.p_AB = Eigen::Vector3d(0.1, 0, 0.3);
  EXPECT_TRUE(Select(CheckModel(model), "zero-inertia-about-joint-axis").empty());
}

// Geometry bounds: a box 0.2 × 0.4 × 0.6 turned 90° about z at (1, 0, 0) spans x in
// [0.8, 1.2], y in [-0.1, 0.1], z in [-0.3, 0.3] (hand-derived); a mesh hides the extent.
TEST(ChecksTest, GeometryBoundsFollowTheGeometryPoseAndSkipMeshes) {
  Link link;
  Geometry box;
  box.type = Geometry::Type::kBox;
  box.size = Eigen::Vector3d(0.2, 0.4, 0.6);
  box.X_BG.p_AB = Eigen::Vector3d(1, 0, 0);
  box.X_BG.R_AB = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  link.geometries.push_back(box);
  const auto bounds = CalcLinkGeometryBounds(link);
  ASSERT_TRUE(bounds.has_value());
  EXPECT_TRUE(bounds->box_B.min().isApprox(Eigen::Vector3d(0.8, -0.1, -0.3)));
  EXPECT_TRUE(bounds->box_B.max().isApprox(Eigen::Vector3d(1.2, 0.1, 0.3)));
  Geometry mesh;
  mesh.type = Geometry::Type::kMesh;
  link.geometries.push_back(mesh);
  EXPECT_FALSE(CalcLinkGeometryBounds(link).has_value());
}

// The MANIFEST's invalid_links notes (../shared/corpus/MANIFEST.tsv, computed with urdfdom and
// a 1e-6·trace tolerance) name exactly the links that massprops reports inertia-not-physical
// for, per link (group findings are left out).
TEST(ChecksTest, CorpusInvalidLinksMatchTheManifest) {
  if (!std::ifstream(test_support::CorpusDir() + "/MANIFEST.tsv")) GTEST_SKIP() << "no corpus";
  int files = 0;
  for (const test_support::ManifestRow& row : test_support::ReadCorpusManifest("urdf")) {
    const std::string& notes = row.notes;
    std::set<std::string> expected;
    const auto pos = notes.find("invalid_links=");
    if (pos != std::string::npos) {
      const std::string list = notes.substr(pos + 14, notes.find(';', pos) - pos - 14);
      std::stringstream items(list);
      std::string item;
      while (std::getline(items, item, '|')) {
        item.erase(0, item.find_first_not_of(' '));
        expected.insert(item.substr(0, item.find('(')));
      }
    }
    const ReadResult result = ReadUrdfFile(test_support::CorpusDir() + "/" + row.file);
    if (result.models.empty()) continue;  // read errors are the readers' tests
    // The notes come from urdfdom's model: a file urdfdom refuses has none.
    bool loadable = true;
    for (const ReadFinding& f : result.findings)
      loadable = loadable && f.rule != "urdf-not-loadable";
    if (!loadable) continue;
    ++files;
    std::set<std::string> flagged;
    for (const Finding& f : CheckModel(result.models[0])) {
      if (f.rule != "inertia-not-physical") continue;
      bool group = false;
      for (const auto& value : f.values) group = group || value.first == "group_links";
      if (!group) flagged.insert(f.link);
    }
    EXPECT_EQ(flagged, expected) << row.file;
  }
  EXPECT_GT(files, 100);
}

}  // namespace
}  // namespace massprops

// ReaderFindings turns a reader's findings into Findings with the rule's severity, honouring the
// overrides and a link's ignore comment (hand-built ReadResult; severities from AllRules()).
TEST(ChecksTest, ReaderFindingsTakeTheirRulesSeverityAndHonourOverridesAndIgnores) {
  massprops::ReadResult read;
  massprops::Model model;
  model.name = "m";
  massprops::Link quiet;
  quiet.name = "quiet";
  quiet.ignored_rules = {"inertial-unreadable"};
  massprops::Link loud;
  loud.name = "loud";
  model.links = {quiet, loud};
  read.models.push_back(model);
  for (const char* link : {"quiet", "loud"}) {
    massprops::ReadFinding rf;
    rf.rule = "inertial-unreadable";
    rf.model = "m";
    rf.link = link;
    rf.location.line = 7;
    rf.message = "mass value=\"abc\"";
    read.findings.push_back(rf);
  }
  std::vector<massprops::Finding> findings = massprops::ReaderFindings(read);
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].link, "loud");
  EXPECT_EQ(findings[0].severity, massprops::Severity::kError);
  EXPECT_EQ(findings[0].location.line, 7);

  massprops::CheckOptions options;
  options.overrides["inertial-unreadable"] = massprops::Severity::kWarning;
  findings = massprops::ReaderFindings(read, options);
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].severity, massprops::Severity::kWarning);
  options.overrides["inertial-unreadable"] = std::nullopt;
  EXPECT_TRUE(massprops::ReaderFindings(read, options).empty());
}

// A link whose <inertial> could not be read makes its welded group's mass unknown: no
// massless-moving-body (which its absent inertial would otherwise suggest).
TEST(ChecksTest, AGroupWithAnUnreadableInertialIsNotJudged) {
  massprops::Model model;
  model.name = "m";
  massprops::Link base;
  base.name = "base";
  base.inertial = massprops::Inertial{};
  base.inertial->mass = 1;
  base.inertial->ixx = base.inertial->iyy = base.inertial->izz = 0.1;
  massprops::Link arm;
  arm.name = "arm";
  arm.inertial_unreadable = true;
  model.links = {base, arm};
  massprops::Joint joint;
  joint.name = "shoulder";
  joint.type = massprops::Joint::Type::kRevolute;
  joint.type_name = "revolute";
  joint.parent = "base";
  joint.child = "arm";
  model.joints = {joint};
  model.root_link = "base";
  for (const massprops::Finding& f : massprops::CheckModel(model)) {
    EXPECT_NE(f.link, "arm") << f.rule << ": " << f.message;
  }
  arm.inertial_unreadable = false;  // the same arm, simply massless: reported
  model.links[1] = arm;
  bool massless = false;
  for (const massprops::Finding& f : massprops::CheckModel(model)) {
    massless = massless || f.rule == "massless-moving-body";
  }
  EXPECT_TRUE(massless);
}

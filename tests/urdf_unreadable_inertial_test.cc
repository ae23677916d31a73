// A link whose <inertial> could not be read wholly (inertial-unreadable): the Model keeps what the
// loader of record loads of it (Link::loaded_inertial, its unknown numbers marked), and the mass
// report carries those numbers and says which are unknown, for the link and for every composite
// holding it (issue 25). What urdfdom loads is taken from urdf::parseURDF itself (a second
// reading of the same text); composites are hand-derived below.
#include <console_bridge/console.h>
#include <gtest/gtest.h>
#include <urdf_parser/urdf_parser.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "massprops/analysis/mass_report.h"
#include "massprops/analysis/welded_groups.h"
#include "massprops/io/urdf_reader.h"

namespace massprops {
namespace {

const std::string kFixture = std::string(MASSPROPS_TESTDATA_DIR) + "/urdf/inertia_unreadable.urdf";

std::string FileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// urdfdom's own model of the text, its console messages dropped.
urdf::ModelInterfaceSharedPtr Urdfdom(const std::string& xml) {
  const console_bridge::LogLevel level = console_bridge::getLogLevel();
  console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_NONE);
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(xml);
  console_bridge::setLogLevel(level);
  return model;
}

// The link `arm` (index 1) of a two-link robot with the given <inertial>.
std::string ArmWith(const std::string& inertial, const std::string& joint_type = "fixed") {
  return "<robot name=\"r\">\n<link name=\"base\"/>\n<link name=\"arm\">\n" + inertial +
         "\n</link>\n<joint name=\"j\" type=\"" + joint_type +
         "\">\n<parent link=\"base\"/><child link=\"arm\"/>\n</joint>\n</robot>\n";
}

// The loaded inertial of `arm` equals urdfdom's numbers for it, bit for bit.
void ExpectUrdfdomsNumbers(const std::string& xml, const Inertial& loaded) {
  const urdf::ModelInterfaceSharedPtr urdf = Urdfdom(xml);
  ASSERT_TRUE(urdf);
  const urdf::InertialSharedPtr i = urdf->getLink("arm")->inertial;
  ASSERT_TRUE(i);
  EXPECT_EQ(loaded.mass, i->mass);
  EXPECT_EQ(loaded.X_BBi.p_AB,
            Eigen::Vector3d(i->origin.position.x, i->origin.position.y, i->origin.position.z));
  EXPECT_EQ(loaded.ixx, i->ixx);
  EXPECT_EQ(loaded.ixy, i->ixy);
  EXPECT_EQ(loaded.ixz, i->ixz);
  EXPECT_EQ(loaded.iyy, i->iyy);
  EXPECT_EQ(loaded.iyz, i->iyz);
  EXPECT_EQ(loaded.izz, i->izz);
}

TEST(UrdfUnreadableInertialTest, AnInertiaUrdfdomCannotReadKeepsTheMassAndComUrdfdomLoads) {
  const std::string xml = FileText(kFixture);
  const ReadResult result = ReadUrdfString(xml, "inertia_unreadable.urdf");
  ASSERT_TRUE(result.ok());
  const Link& pad = result.models.at(0).links.at(1);
  ASSERT_EQ(pad.name, "pad");
  EXPECT_TRUE(pad.inertial_unreadable);
  EXPECT_FALSE(pad.inertial.has_value());  // the checks judge nothing of it
  ASSERT_TRUE(pad.loaded_inertial.has_value());
  // As written: mass 0.0075 kg at (0.02, 0, 0); urdfdom keeps both and zeroes all six moments.
  EXPECT_EQ(pad.loaded_inertial->mass, 0.0075);
  EXPECT_EQ(pad.loaded_inertial->X_BBi.p_AB, Eigen::Vector3d(0.02, 0, 0));
  EXPECT_EQ(pad.loaded_inertial->unknown, kInertialMoments);
  EXPECT_EQ(UnknownInertialNumbers(pad), kInertialMoments);
  EXPECT_EQ(UnknownInertialNumbers(result.models[0].links[0]), 0u);
  const urdf::ModelInterfaceSharedPtr urdf = Urdfdom(xml);
  ASSERT_TRUE(urdf);
  const urdf::Inertial& i = *urdf->getLink("pad")->inertial;
  EXPECT_EQ(pad.loaded_inertial->mass, i.mass);
  EXPECT_EQ(pad.loaded_inertial->ixx, i.ixx);
  EXPECT_EQ(pad.loaded_inertial->ixz, i.ixz);
  // The finding says what urdfdom loads.
  ASSERT_EQ(result.findings.size(), 1u);
  EXPECT_EQ(result.findings[0].rule, "inertial-unreadable");
  EXPECT_NE(result.findings[0].message.find("mass and center of mass as written but an inertia "
                                            "of zero"),
            std::string::npos)
      << result.findings[0].message;
  // LinkMassProperties gives what the loader loads: the mass, not 0.
  EXPECT_EQ(LinkMassProperties(pad).mass, 0.0075);
}

TEST(UrdfUnreadableInertialTest, WhatUrdfdomLoadsOfAPartlyReadInertialIsKeptWithItsUnknownsMarked) {
  const char* kInertia =
      "<inertia ixx=\"1\" ixy=\"0.1\" ixz=\"0.2\" iyy=\"2\" iyz=\"0.3\" izz=\"3\"/>";
  struct Case {
    std::string inertial;
    unsigned unknown;
  };
  const Case cases[] = {
      // <mass> unreadable: urdfdom keeps the origin; mass and inertia are zero.
      {"<inertial><origin xyz=\"0.1 0.2 0.3\"/><mass value=\"2\n\"/>" + std::string(kInertia) +
           "</inertial>",
       kInertialMass | kInertialMoments},
      // <origin> unreadable: urdfdom keeps nothing.
      {"<inertial><origin xyz=\"0.1 0.2\"/><mass value=\"2\"/>" + std::string(kInertia) +
           "</inertial>",
       kInertialAll},
      // The last inertia number unreadable: all six are zero, mass and origin kept.
      {"<inertial><origin xyz=\"0.1 0.2 0.3\"/><mass value=\"2\"/><inertia ixx=\"1\" ixy=\"0.1\" "
       "ixz=\"0.2\" iyy=\"2\" iyz=\"0.3\" izz=\"3x\"/></inertial>",
       kInertialMoments},
  };
  for (const Case& c : cases) {
    const std::string xml = ArmWith(c.inertial);
    const ReadResult result = ReadUrdfString(xml, "mem.urdf");
    const Link& arm = result.models.at(0).links.at(1);
    ASSERT_TRUE(arm.loaded_inertial.has_value()) << c.inertial;
    EXPECT_EQ(arm.loaded_inertial->unknown, c.unknown) << c.inertial;
    ExpectUrdfdomsNumbers(xml, *arm.loaded_inertial);
  }
}

TEST(UrdfUnreadableInertialTest, TheLenientReadingKeepsEveryNumberItCanReadAndMarksTheOthers) {
  // urdfdom refuses the file (joint type "spherical"); the lenient reading cannot read the mass
  // nor ixy, and reads everything else as written.
  const std::string xml = ArmWith(
      "<inertial><origin xyz=\"1 2 3\"/><mass value=\"abc\"/><inertia ixx=\"1\" ixy=\"1,5\" "
      "ixz=\"0\" iyy=\"2\" iyz=\"0\" izz=\"3\"/></inertial>",
      "spherical");
  const ReadResult result = ReadUrdfString(xml, "mem.urdf");
  const Link& arm = result.models.at(0).links.at(1);
  EXPECT_TRUE(arm.inertial_unreadable);
  ASSERT_TRUE(arm.loaded_inertial.has_value());
  EXPECT_EQ(arm.loaded_inertial->unknown, kInertialMass | kInertialIxy);
  EXPECT_EQ(arm.loaded_inertial->X_BBi.p_AB, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(arm.loaded_inertial->ixx, 1);
  EXPECT_EQ(arm.loaded_inertial->iyy, 2);
  EXPECT_EQ(arm.loaded_inertial->izz, 3);
  int unreadable = 0;
  for (const ReadFinding& f : result.findings) {
    if (f.rule != "inertial-unreadable") continue;
    ++unreadable;
    EXPECT_NE(f.message.find("<mass value=\"abc\">, <inertia ixy=\"1,5\">"), std::string::npos)
        << f.message;
  }
  EXPECT_EQ(unreadable, 1);
}

TEST(UrdfUnreadableInertialTest, TheReportCarriesTheLoadedNumbersAndSaysWhichAreUnknown) {
  const ReadResult result = ReadUrdfFile(kFixture);
  ASSERT_TRUE(result.ok());
  ModelMassReport report;
  std::string error;
  ASSERT_TRUE(ComputeMassReport(result.models.at(0), MassReportOptions(), &report, &error))
      << error;
  ASSERT_EQ(report.links.size(), 2u);
  const BodyMassProperties& finger = report.links[0].properties;
  const BodyMassProperties& pad = report.links[1].properties;
  EXPECT_EQ(finger.unknown, 0u);
  EXPECT_EQ(pad.unknown, kUnknownInertia);
  EXPECT_EQ(pad.mass, 0.0075);
  EXPECT_EQ(pad.com, Eigen::Vector3d(0.02, 0, 0));
  // The welded group: hand-derived. Mass 0.1 + 0.0075 = 0.1075 kg; the pad's center of mass is
  // at (0, 0, 0.02) + (0.02, 0, 0) in the finger's frame, so the composite's is
  // (0.0075·0.02, 0, 0.1·0.01 + 0.0075·0.02) / 0.1075 = (0.00015, 0, 0.00115) / 0.1075.
  ASSERT_EQ(report.welded_groups.size(), 1u);
  const GroupMassReport& group = report.welded_groups[0];
  EXPECT_EQ(group.properties.unknown, kUnknownInertia);
  EXPECT_EQ(group.incomplete_links, std::vector<std::string>{"pad"});
  EXPECT_NEAR(group.properties.mass, 0.1075, 1e-16);
  EXPECT_NEAR(group.properties.com.x(), 0.00015 / 0.1075, 1e-17);
  EXPECT_NEAR(group.properties.com.y(), 0, 1e-17);
  EXPECT_NEAR(group.properties.com.z(), 0.00115 / 0.1075, 1e-17);
  ASSERT_TRUE(report.total.has_value());
  EXPECT_EQ(report.total->unknown, kUnknownInertia);
  EXPECT_EQ(report.total_incomplete_links, std::vector<std::string>{"pad"});
  EXPECT_NEAR(report.total->mass, 0.1075, 1e-16);
  // The same with --only and --frame (the table computes on demand there).
  MassReportOptions only;
  only.only = {"pad"};
  only.frame = "pad";
  ASSERT_TRUE(ComputeMassReport(result.models[0], only, &report, &error)) << error;
  ASSERT_EQ(report.links.size(), 1u);
  EXPECT_EQ(report.links[0].properties.unknown, kUnknownInertia);
  EXPECT_EQ(report.welded_groups.at(0).properties.unknown, kUnknownInertia);
  EXPECT_EQ(report.welded_groups[0].incomplete_links, std::vector<std::string>{"pad"});
}

TEST(UrdfUnreadableInertialTest, WhatOfACompositeIsUnknownFollowsWhatOfItsPartsIs) {
  // A part's unknown mass leaves everything of the composite unknown; its unknown position the
  // center of mass and the inertia; any unknown number the inertia.
  EXPECT_EQ(BodyUnknownOf(0), 0u);
  EXPECT_EQ(BodyUnknownOf(kInertialMass), kUnknownMass | kUnknownCom | kUnknownInertia);
  EXPECT_EQ(BodyUnknownOf(kInertialPosition), kUnknownCom | kUnknownInertia);
  EXPECT_EQ(BodyUnknownOf(kInertialOrientation), kUnknownInertia);
  EXPECT_EQ(BodyUnknownOf(kInertialIxz), kUnknownInertia);
}

}  // namespace
}  // namespace massprops

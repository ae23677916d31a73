// The xacro trace (massprops/io/xacro_trace.h) on the packages of ../shared/xacro/: every row of
// provenance.tsv (30 numbers whose source lines were checked by hand, see that folder's
// README.md) is traced to its file, line and `how`; plus small packages written here whose
// answers are worked out by hand in the comments.
#include "massprops/io/xacro_trace.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "shared_data.h"

namespace massprops {
namespace {

namespace fs = std::filesystem;

const fs::path kXacroDir = MASSPROPS_XACRO_DIR;

std::string ReadText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> SplitTabs(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string field; std::getline(in, field, '\t');) out.push_back(field);
  return out;
}

XacroTrace TracePackage(const std::string& package) {
  XacroTraceOptions options;
  options.source_roots = {(kXacroDir / package).string()};
  options.exclude_files = {(kXacroDir / package / "expanded.urdf").string()};
  return TraceXacro(ReadText(kXacroDir / package / "expanded.urdf"), "expanded.urdf", options);
}

TEST(XacroTraceTest, EveryRowOfProvenanceIsTracedToItsFileLineAndHow) {
  MASSPROPS_SKIP_WITHOUT_SHARED("xacro/provenance.tsv");
  std::ifstream in(kXacroDir / "provenance.tsv");
  std::string line;
  std::getline(in, line);  // header
  std::map<std::string, XacroTrace> traces;
  int rows = 0;
  while (std::getline(in, line)) {
    const std::vector<std::string> f = SplitTabs(line);
    ASSERT_EQ(f.size(), 8u) << line;
    const std::string &package = f[0], &link = f[1], &element = f[2], &attribute = f[3],
                      &value = f[4], &file = f[5], &how = f[7];
    const int source_line = std::stoi(f[6]);
    if (!traces.count(package)) traces[package] = TracePackage(package);
    // provenance.tsv's paths are relative to <package>/src/, or to <package>/ for src_deps/.
    const fs::path want_file =
        kXacroDir / package / (file.rfind("src_deps/", 0) == 0 ? file : "src/" + file);
    const TracedNumber* found = nullptr;
    for (const TracedNumber& n : traces[package].numbers) {
      const std::string attr = element == "mass" ? "value" : attribute;
      if (n.link == link && n.element == element && n.attribute == attr) found = &n;
    }
    ASSERT_NE(found, nullptr) << line;
    EXPECT_EQ(found->expanded_value, value) << line;
    ASSERT_EQ(found->places.size(), 1u) << line;
    const SourcePlace& place = found->places.front();
    EXPECT_TRUE(fs::equivalent(place.file, want_file)) << line << "\n  traced to " << place.file;
    EXPECT_EQ(place.line, source_line) << line;
    EXPECT_EQ(place.how, how) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 30);  // README.md: 10 rows each for franka_fr3, pmb2 and turtlebot4
}

TEST(XacroTraceTest, EveryInertialNumberOfEveryPackageIsReadAndAnsweredInTheVocabulary) {
  MASSPROPS_SKIP_WITHOUT_SHARED("xacro/provenance.tsv");
  // The counts of mass value, origin xyz/rpy and inertia attributes inside each <inertial> of
  // each expanded.urdf, counted with a regular expression in Python (docs/xacro.md's table).
  const std::map<std::string, std::size_t> counts = {{"franka_fr3", 99},
                                                     {"kinova_j2n6s300", 105},
                                                     {"kortex_gen3_robotiq_2f_85", 153},
                                                     {"panther", 45},
                                                     {"pmb2", 188},
                                                     {"turtlebot4", 319},
                                                     {"xarm7", 72}};
  const std::set<std::string> how = {"literal", "yaml", "parameter", "computed"};
  for (const auto& [package, count] : counts) {
    const XacroTrace trace = TracePackage(package);
    EXPECT_TRUE(trace.errors.empty()) << package;
    EXPECT_EQ(trace.numbers.size(), count) << package;
    for (const TracedNumber& n : trace.numbers) {
      for (const SourcePlace& p : n.places) {
        EXPECT_TRUE(how.count(p.how)) << package << " " << n.link << " " << p.how;
        EXPECT_GT(p.line, 0) << package << " " << n.link;
        EXPECT_TRUE(fs::exists(p.file)) << p.file;
      }
    }
  }
}

TEST(XacroTraceTest, ComputedValuesNameTheirInputs) {
  MASSPROPS_SKIP_WITHOUT_SHARED("xacro/turtlebot4");
  // rplidar.urdf.xacro:34 calls inertial_cuboid with mass="0.17", y = 10 cm, z = 6 cm:
  // ixx = m (y² + z²) / 12 = 0.17 · 0.0136 / 12 (common_properties.urdf.xacro line 9).
  const XacroTrace trace = TracePackage("turtlebot4");
  for (const TracedNumber& n : trace.numbers) {
    if (n.link != "rplidar_link" || n.attribute != "ixx") continue;
    ASSERT_EQ(n.places.size(), 1u);
    EXPECT_EQ(n.places[0].how, "computed");
    EXPECT_EQ(n.places[0].inputs, (std::vector<std::string>{"mass=0.17", "y=0.1", "z=0.06"}));
    return;
  }
  FAIL() << "rplidar_link ixx not found";
}

// A package written here: a literal shared by two links, one used by one link, and a YAML value.
class SmallPackage : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("massprops_xacro_trace_" + std::to_string(::getpid()));
    fs::create_directories(dir_ / "config");
    std::ofstream(dir_ / "robot.urdf.xacro") << R"(<?xml version="1.0"?>
<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:property name="props" value="${xacro.load_yaml('config/m.yaml')}"/>
  <xacro:macro name="leg" params="side m">
    <link name="${side}_leg">
      <inertial>
        <mass value="${m}"/>
        <inertia ixx="0.25" ixy="0" ixz="0" iyy="0.25" iyz="0" izz="${m*0.5}"/>
      </inertial>
    </link>
  </xacro:macro>
  <xacro:leg side="left" m="2.0"/>
  <xacro:leg side="right" m="3.0"/>
  <link name="body">
    <inertial>
      <mass value="${props['body']['mass']}"/>
      <inertia ixx="0.125" ixy="0" ixz="0" iyy="0.125" iyz="0" izz="0.125"/>
    </inertial>
  </link>
</robot>
)";
    std::ofstream(dir_ / "config" / "m.yaml") << "body:\n  mass: 7.50\nother:\n  mass: 1.0\n";
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(SmallPackage, TracesLiteralsParametersComputedAndYaml) {
  // The expansion ROS's xacro makes of the file above (written by hand: ${m} of the call's
  // "3.0" prints as 3.0, ${m*0.5} as 1.5, the YAML 7.50 as 7.5).
  const std::string expanded = R"(<?xml version="1.0"?>
<robot name="r">
  <link name="left_leg">
    <inertial>
      <mass value="2.0"/>
      <inertia ixx="0.25" ixy="0" ixz="0" iyy="0.25" iyz="0" izz="1.0"/>
    </inertial>
  </link>
  <link name="right_leg">
    <inertial>
      <mass value="3.0"/>
      <inertia ixx="0.25" ixy="0" ixz="0" iyy="0.25" iyz="0" izz="1.5"/>
    </inertial>
  </link>
  <link name="body">
    <inertial>
      <mass value="7.5"/>
      <inertia ixx="0.125" ixy="0" ixz="0" iyy="0.125" iyz="0" izz="0.125"/>
    </inertial>
  </link>
</robot>
)";
  XacroTraceOptions options;
  options.source_roots = {dir_.string()};
  const XacroTrace trace = TraceXacro(expanded, "x.urdf", options);
  auto find = [&](const std::string& link, const std::string& attribute) -> const TracedNumber& {
    for (const TracedNumber& n : trace.numbers) {
      if (n.link == link && n.attribute == attribute) return n;
    }
    static TracedNumber none;
    return none;
  };
  const std::string xacro_file = (dir_ / "robot.urdf.xacro").string();
  // right_leg's mass is the call's m="3.0" (line 13), a parameter.
  const TracedNumber& mass = find("right_leg", "value");
  ASSERT_EQ(mass.places.size(), 1u);
  EXPECT_EQ(mass.places[0].how, "parameter");
  EXPECT_EQ(mass.places[0].line, 13);
  EXPECT_EQ(mass.places[0].text, "3.0");
  // izz = m·0.5 is computed at the same call; its input is m = 3.
  const TracedNumber& izz = find("right_leg", "izz");
  ASSERT_EQ(izz.places.size(), 1u);
  EXPECT_EQ(izz.places[0].how, "computed");
  EXPECT_EQ(izz.places[0].line, 13);
  EXPECT_EQ(izz.places[0].inputs, std::vector<std::string>{"m=3"});
  // ixx="0.25" is one literal at line 8, written for both legs.
  const TracedNumber& ixx = find("left_leg", "ixx");
  ASSERT_EQ(ixx.places.size(), 1u);
  EXPECT_EQ(ixx.places[0].how, "literal");
  EXPECT_EQ(ixx.places[0].line, 8);
  EXPECT_EQ(ixx.places[0].file, xacro_file);
  // The body's mass: a YAML value (line 2 of m.yaml, key body.mass); "other: mass: 1.0" is not it.
  const TracedNumber& body = find("body", "value");
  ASSERT_EQ(body.places.size(), 1u);
  EXPECT_EQ(body.places[0].how, "yaml");
  EXPECT_EQ(body.places[0].line, 2);
  EXPECT_EQ(body.places[0].text, "7.50");
  EXPECT_TRUE(body.places[0].editable);
}

TEST(XacroTraceTest, PropertiesThatDoubleAtEachStepEndInTimeUntraced) {
  // p_k = p_(k-1) + p_(k-1): evaluating p40 naively takes 2^40 look-ups. The trace gives up after
  // its budget and leaves the mass untraced (it would be 2^40 = 1099511627776).
  const fs::path dir =
      fs::temp_directory_path() / ("massprops_xacro_doubling_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::string xacro =
      "<robot name=\"r\" xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n"
      "<xacro:property name=\"p0\" value=\"1\"/>\n";
  for (int k = 1; k <= 40; ++k) {
    xacro += "<xacro:property name=\"p" + std::to_string(k) + "\" value=\"${p" +
             std::to_string(k - 1) + "+p" + std::to_string(k - 1) + "}\"/>\n";
  }
  xacro += "<link name=\"a\"><inertial><mass value=\"${p40}\"/></inertial></link></robot>\n";
  std::ofstream(dir / "r.urdf.xacro") << xacro;
  XacroTraceOptions options;
  options.source_roots = {dir.string()};
  const XacroTrace trace = TraceXacro(
      "<robot name=\"r\"><link name=\"a\"><inertial><mass value=\"1099511627776.0\"/>"
      "</inertial></link></robot>",
      "x.urdf", options);
  fs::remove_all(dir);
  ASSERT_EQ(trace.numbers.size(), 1u);
  EXPECT_TRUE(trace.numbers[0].places.empty());
}

TEST(XacroTraceTest, AnExpansionThatIsNotXmlGivesOneErrorAndNoNumbers) {
  const XacroTrace trace = TraceXacro("<robot", "bad.urdf", {});
  EXPECT_TRUE(trace.numbers.empty());
  ASSERT_EQ(trace.errors.size(), 1u);
  EXPECT_EQ(trace.errors[0].location.file, "bad.urdf");
}

}  // namespace
}  // namespace massprops

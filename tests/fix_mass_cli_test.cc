// End-to-end tests of the mass repairs of `massprops fix` (--total-mass, --mass, --density
// LINK=RHO, --material; docs/fix.md): the file written, check on it, a second run, the effect
// printed against `massprops report`, and the command-line errors.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <utility>

#include "tool_runner.h"

namespace {

namespace fs = std::filesystem;

const std::string kMassDir = std::string(MASSPROPS_TESTDATA_DIR) + "/mass/";

std::string ReadFile(const fs::path& path) { return massprops::test_support::ReadWholeFile(path); }

using ToolRun = massprops::test_support::SplitToolRun;

class FixMassCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "massprops-fixmass-XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
    // The fixtures reference ../mesh/box_ascii.stl: keep that layout in the scratch folder.
    fs::create_directories(dir_ / "mass");
    fs::create_directories(dir_ / "mesh");
    fs::copy_file(std::string(MASSPROPS_TESTDATA_DIR) + "/mesh/box_ascii.stl",
                  dir_ / "mesh" / "box_ascii.stl");
    for (const char* name : {"arm.urdf", "cad_default.urdf"}) {
      fs::copy_file(kMassDir + name, dir_ / "mass" / name);
    }
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  ToolRun Run(const std::string& args) { return massprops::test_support::RunToolSplit(args, dir_); }

  std::string Path(const std::string& name) const { return (dir_ / "mass" / name).string(); }

  // The (rule, link) of every warning and error `check` finds in `file`.
  std::set<std::pair<std::string, std::string>> Findings(const std::string& file) {
    const ToolRun run = Run("check --format json '" + file + "'");
    EXPECT_LE(run.code, 1) << run.err;
    std::set<std::pair<std::string, std::string>> found;
    const nlohmann::json doc = nlohmann::json::parse(run.out);
    for (const auto& f : doc.at("files").at(0).at("findings")) {
      if (f.at("severity") == "note") continue;
      EXPECT_NE(f.at("severity"), "error") << f.dump();
      found.insert({f.at("rule").get<std::string>(), f.at("link").get<std::string>()});
    }
    return found;
  }

  // Runs `fix OPTIONS -o OUT FILE`, then checks OUT (no error, no warning FILE lacked) and that
  // the same command on OUT changes nothing; returns OUT's text.
  std::string FixTwice(const std::string& options, const std::string& file) {
    const std::string out = (dir_ / "mass" / "fixed.urdf").string();
    const ToolRun first = Run("fix " + options + " -o '" + out + "' '" + file + "'");
    EXPECT_EQ(first.code, 0) << first.err;
    const std::string fixed = ReadFile(out);
    EXPECT_NE(fixed, ReadFile(file));
    const auto before = Findings(file);
    for (const auto& finding : Findings(out)) {
      EXPECT_TRUE(before.count(finding))
          << "new finding " << finding.first << " on '" << finding.second << "'";
    }
    const std::string again = (dir_ / "mass" / "again.urdf").string();
    const ToolRun second = Run("fix " + options + " -o '" + again + "' '" + out + "'");
    EXPECT_EQ(second.code, 0) << second.err;
    EXPECT_EQ(ReadFile(again), fixed);
    EXPECT_NE(second.err.find("no change needed"), std::string::npos) << second.err;
    return fixed;
  }

  fs::path dir_;
};

TEST_F(FixMassCliTest, TotalMassWritesEveryLinkScaledAndASecondRunChangesNothing) {
  // 1 + 2 + 3 = 6 kg to 12 kg: k = 2, every number of every inertial doubled (hand-derived).
  const std::string fixed = FixTwice("--total-mass 12", Path("arm.urdf"));
  EXPECT_NE(fixed.find(R"(<mass value="2"/>)"), std::string::npos);
  EXPECT_NE(fixed.find(R"(ixx="0.02" ixy="0.002" ixz="-0.004" iyy="0.04" iyz="0.006" izz="0.05")"),
            std::string::npos)
      << fixed;
  EXPECT_NE(fixed.find(R"(<origin xyz="0.01 0.02 0.03" rpy="0 0 0"/>)"), std::string::npos);
  EXPECT_NE(fixed.find(R"(<mass value="6"/>)"), std::string::npos);
}

TEST_F(FixMassCliTest, MassWithTotalMassAndTheEffectEqualsTheReportOfTheWrittenFile) {
  const std::string out = Path("out.urdf");
  // tool 3 -> 6 kg (x 2), base and upper share 10.5 - 6 = 4.5 kg of their 3 kg: x 1.5.
  const ToolRun run = Run("fix --format json --mass tool=6 --total-mass 10.5 -o '" + out + "' '" +
                          Path("arm.urdf") + "'");
  ASSERT_EQ(run.code, 0) << run.err;
  const nlohmann::json fix = nlohmann::json::parse(run.out);
  EXPECT_EQ(fix.at("changed"), true);
  ASSERT_EQ(fix.at("repairs").size(), 3u);
  const nlohmann::json& effect = fix.at("effects").at(0);
  EXPECT_EQ(effect.at("total").at("before").at("mass"), 6.0);
  EXPECT_EQ(effect.at("total").at("after").at("mass"), 10.5);
  // Welded groups with a changed link: base, and upper + tool.
  ASSERT_EQ(effect.at("groups").size(), 2u);
  EXPECT_EQ(effect.at("groups").at(1).at("root_link"), "upper");
  EXPECT_EQ(effect.at("groups").at(1).at("after").at("mass"), 3.0 + 6.0);
  // The composite printed equals `massprops report` on the written file, number for number.
  const ToolRun report = Run("report --format json '" + out + "'");
  ASSERT_EQ(report.code, 0) << report.err;
  const nlohmann::json total = nlohmann::json::parse(report.out).at("models").at(0).at("total");
  for (const char* key : {"mass", "com", "principal_moments", "inertia_about_com", "frame"}) {
    EXPECT_EQ(effect.at("total").at("after").at(key), total.at(key)) << key;
  }
  const nlohmann::json groups =
      nlohmann::json::parse(report.out).at("models").at(0).at("welded_groups");
  EXPECT_EQ(effect.at("groups").at(1).at("after").at("principal_moments"),
            groups.at(1).at("principal_moments"));
}

TEST_F(FixMassCliTest, MaterialFromTheClosedMeshIsCleanAndStable) {
  // upper: the 0.006 m³ box of aluminium 6061 (2700 kg/m³): 16.2 kg (STL floats: 9th digit).
  const std::string fixed = FixTwice("--material upper=aluminium-6061", Path("arm.urdf"));
  EXPECT_NE(fixed.find(R"(<mass value="16.2000)"), std::string::npos) << fixed;
  // The text effect goes to standard error (standard output carries the file).
  const ToolRun run = Run("fix --dry-run --material upper=aluminium-6061 " + Path("arm.urdf"));
  EXPECT_EQ(run.code, 0);
  EXPECT_NE(run.out.find("[--material → from-closed-mesh]"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("effect on model 'arm'"), std::string::npos) << run.out;
}

TEST_F(FixMassCliTest, CadDefaultDensityIsGoneAfterTheMaterialsAreSet) {
  const std::string file = Path("cad_default.urdf");
  EXPECT_TRUE(Findings(file).count({"cad-default-density", ""}));
  const std::string out = Path("pla.urdf");
  const ToolRun run = Run("fix --material a=pla --material b=pla -o '" + out + "' '" + file + "'");
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_TRUE(Findings(out).empty());
  // --density LINK=RHO is the same as a material of that density.
  const std::string out2 = Path("pla2.urdf");
  ASSERT_EQ(Run("fix --density a=1240 --density b=1240 -o '" + out2 + "' '" + file + "'").code, 0);
  EXPECT_EQ(ReadFile(out2), ReadFile(out));
}

TEST_F(FixMassCliTest, BareFixAndABareDensityChangeNothingHere) {
  // The contract of a bare fix: no mass repair runs unless named.
  for (const char* options : {"", "--density 2000"}) {
    const ToolRun run = Run(std::string("fix --dry-run ") + options + " " + Path("arm.urdf"));
    EXPECT_EQ(run.code, 0) << options << run.err;
    EXPECT_NE(run.out.find("no change needed"), std::string::npos) << options << run.out;
  }
}

TEST_F(FixMassCliTest, AMassThatDrawsAWarningIsWrittenAndSaidSo) {
  // 6 kg to 0.006 kg: upper gets 0.002 kg on its 0.006 m³ mesh, 0.33 kg/m³ (below 100).
  const ToolRun run =
      Run("fix --total-mass 0.006 -o '" + Path("light.urdf") + "' '" + Path("arm.urdf") + "'");
  EXPECT_EQ(run.code, 0) << run.err;
  // Said as `check` says it: `file:line: warning: HEADLINE [rule]`, and why it is new. The
  // headline is density-implausible's (0.002 kg / 0.006 m³ = 0.333 kg/m³).
  EXPECT_NE(run.err.find(":17: warning: link 'upper': density 0.333 kg/m³ over its closed mesh, "
                         "lighter than foam (placeholder mass?) [density-implausible] (after the "
                         "repairs asked for)\n"),
            std::string::npos)
      << run.err;
}

TEST_F(FixMassCliTest, WrongOptionsExitTwoWithTheReason) {
  const std::string file = Path("arm.urdf");
  struct Case {
    const char* options;
    const char* message;
  } cases[] = {
      {"--density upper=abc", "--density LINK=KG_PER_M3"},
      {"--density 1000 --density 2000", "given once"},
      {"--material upper=wood", "aluminium-6061, steel, pla, abs, petg, nylon, carbon-fibre"},
      {"--mass upper=-1", "--mass LINK=KG"},
      {"--mass elbow=1", "has no link 'elbow'"},
      {"--total-mass 0", "--total-mass must be a positive number"},
      {"--total-mass 4 --mass tool=5", "already weigh 5 kg"},
      {"--density base=1000", "has no closed mesh"},
      {"--material upper=pla --no-geometry", "cannot be combined with --no-geometry"},
      {"--format json --total-mass 12", "--format json prints on standard output"},
  };
  for (const Case& c : cases) {
    const ToolRun run = Run(std::string("fix --dry-run ") + c.options + " " + file);
    if (std::string(c.options).rfind("--format", 0) == 0) {
      const ToolRun plain = Run(std::string("fix ") + c.options + " " + file);
      EXPECT_EQ(plain.code, 2) << c.options;
      EXPECT_NE(plain.err.find(c.message), std::string::npos) << plain.err;
      continue;
    }
    EXPECT_EQ(run.code, 2) << c.options;
    EXPECT_NE(run.err.find(c.message), std::string::npos) << c.options << ": " << run.err;
  }
}

}  // namespace

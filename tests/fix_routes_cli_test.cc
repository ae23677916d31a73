// `massprops fix` at a glance (docs/fix.md, "What fix says"): every refused repair and every
// error it leaves is said in `check`'s form (a headline of at most 110 characters, lines of at
// most 100 under it) with the repairs that would work and the numbers they would write; --dry-run
// shows what each available repair writes. The fixtures of testdata/fix/routes/ work their
// numbers out by hand in their comments; the numbers asserted here are those, at the 3
// significant digits fix prints.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const std::string kTool = MASSPROPS_TOOL_PATH;
const fs::path kRoutes = fs::path(MASSPROPS_TESTDATA_DIR) / "fix" / "routes";
const fs::path kExample = fs::path(MASSPROPS_TESTDATA_DIR) / ".." / "examples";

std::string ReadFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct ToolRun {
  int code = -1;
  std::string out;
  std::string err;
};

class FixRoutesCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "massprops-routes-XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Copies `fixture` into the scratch folder and runs the tool there with `args` before its
  // name (so that the messages name it by its short name).
  ToolRun Run(const fs::path& fixture, const std::string& args) {
    fs::copy_file(fixture, dir_ / fixture.filename(), fs::copy_options::overwrite_existing);
    const std::string command = "cd '" + dir_.string() + "' && '" + kTool + "' " + args + " " +
                                fixture.filename().string() + " >out.txt 2>err.txt";
    const int status = std::system(command.c_str());
    ToolRun run;
    run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = ReadFile(dir_ / "out.txt");
    run.err = ReadFile(dir_ / "err.txt");
    return run;
  }

  fs::path dir_;
};

// The characters of UTF-8 text (a '·', '²' or '→' is one character of two or three bytes).
std::size_t Chars(const std::string& s) {
  std::size_t n = 0;
  for (char c : s) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return n;
}

// Every line under a message (starting with a space) at most 100 characters, none cut with "…".
void ExpectLinesAtAGlance(const std::string& text) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] == ' ') {
      EXPECT_LE(Chars(line), 100u) << line;
    }
    EXPECT_EQ(line.find("…"), std::string::npos) << line;
  }
}

TEST_F(FixRoutesCliTest, ARefusedProjectionNamesFromGeometryWithTheBoxsNumbers) {
  const ToolRun run = Run(kRoutes / "refused_projection.urdf", "fix");
  EXPECT_EQ(run.code, 1) << run.err;
  EXPECT_EQ(run.out, ReadFile(kRoutes / "refused_projection.urdf"));  // nothing changed
  EXPECT_NE(
      run.err.find("refused_projection.urdf:10: error: link 'base': not repaired: its nearest "
                   "valid inertia does not fit its box either [inertia-not-physical]\n"),
      std::string::npos)
      << run.err;
  // The projection by hand (the fixture's comment): 0.336667, 0.336667, 0.673333.
  EXPECT_NE(run.err.find("  = evidence: principal moments 0.01, 0.01, 1 kg·m², the nearest valid "
                         "ones 0.337, 0.337, 0.673\n"),
            std::string::npos)
      << run.err;
  // The box as a uniform solid of 2 kg: 0.00833333, 0.0166667, 0.0216667 (ascending).
  EXPECT_NE(run.err.find("  = help: massprops fix --from-geometry=base refused_projection.urdf\n"
                         "    a guess (a uniform solid): its geometry's own inertia at its mass\n"
                         "    writes mass 2 kg, COM (0, 0, 0) m, principal moments 0.00833, "
                         "0.0167, 0.0217 kg·m²\n"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("then massprops check refused_projection.urdf"), std::string::npos);
  ExpectLinesAtAGlance(run.err);
  // The route named works: it writes the box's inertia and leaves no error.
  const ToolRun routed = Run(kRoutes / "refused_projection.urdf", "fix --from-geometry=base");
  EXPECT_EQ(routed.code, 0) << routed.err;
  EXPECT_NE(routed.out.find("ixx=\"0.0216667\""), std::string::npos) << routed.out;
  EXPECT_NE(routed.out.find("izz=\"0.00833333\""), std::string::npos) << routed.out;
}

TEST_F(FixRoutesCliTest, ARefusedRepairWithoutGeometryNamesTheMassAndCadRoutes) {
  const ToolRun run = Run(kRoutes / "no_geometry_units.urdf", "fix --apply units-suspect");
  EXPECT_EQ(run.code, 0) << run.err;  // a warning: fix leaves no error
  // Radius of gyration sqrt(6e9 / 2) = 54772 m, 54800 m at 3 digits.
  EXPECT_NE(run.err.find("no_geometry_units.urdf:7: warning: link 'a': not repaired: it has no "
                         "geometry to tell which unit factor fits [units-suspect]\n"
                         "  = evidence: radius of gyration 54800 m on a 1 kg body\n"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("  = help: massprops fix --mass a=KG no_geometry_units.urdf\n"
                         "    physics (a scale or datasheet): the part's weighed mass, its inertia "
                         "scaled\n"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("  = help: write its inertial from CAD or a datasheet, then massprops "
                         "check no_geometry_units.urdf\n    physics (the real part)"),
            std::string::npos)
      << run.err;
  EXPECT_EQ(run.err.find("--from-geometry"), std::string::npos) << run.err;  // no geometry
  ExpectLinesAtAGlance(run.err);
}

TEST_F(FixRoutesCliTest, AMasslessMovingLinkGetsTheRepairsThatGiveItAMass) {
  const ToolRun run = Run(kRoutes / "massless_moving.urdf", "fix");
  EXPECT_EQ(run.code, 1) << run.err;
  const std::size_t error = run.err.find("[massless-moving-body] (no repair)\n");
  ASSERT_NE(error, std::string::npos) << run.err;
  // 0.1 x 0.1 x 0.02 m of water: 0.2 kg, moments 0.000173333, 0.000173333, 0.000333333.
  const std::string writes =
      "    writes mass 0.2 kg, COM (0, 0, 0) m, principal moments 0.000173, 0.000173, "
      "0.000333 kg·m²\n";
  EXPECT_NE(run.err.find("  = help: massprops fix --apply massless-moving-body "
                         "massless_moving.urdf\n    a guess (a uniform solid): its geometry's "
                         "mass at 1000 kg/m³ (--density RHO)\n" +
                             writes,
                         error),
            std::string::npos)
      << run.err;
  EXPECT_NE(
      run.err.find("  = help: massprops fix --from-geometry=arm massless_moving.urdf\n", error),
      std::string::npos)
      << run.err;
  ExpectLinesAtAGlance(run.err);
  // --dry-run shows the same numbers as what each repair writes, old → new.
  const ToolRun dry = Run(kRoutes / "massless_moving.urdf", "fix --dry-run");
  ExpectLinesAtAGlance(dry.out);
  ExpectLinesAtAGlance(dry.err);
}

TEST_F(FixRoutesCliTest, DryRunShowsWhatEachRepairOfTheExampleWrites) {
  // The README's example (its comment): forearm, 0.8 kg, ixx typed 0.0046 for 0.00427333, breaks
  // the triangle inequality by 0.0046 − (0.000213333 + 0.00427333) = 0.000113337. The projection
  // moves its moments by a third of that along (1, 1, −1): 0.000251112, 0.00431111, 0.00456222.
  // Its box 0.04 × 0.04 × 0.25 m as a solid of 0.8 kg gives back the intended moments
  // 0.8·(0.04² + 0.25²)/12 = 0.00427333 (twice) and 0.8·(0.04² + 0.04²)/12 = 0.000213333.
  const ToolRun run = Run(kExample / "two_link_arm.urdf", "fix --dry-run");
  EXPECT_EQ(run.code, 0) << run.err;  // what is left is a warning and a note
  EXPECT_NE(run.out.find("  = choices for link 'forearm' (old → new):\n"
                         "    massprops fix two_link_arm.urdf (this run: project)\n"
                         "      physics (the nearest valid inertia)\n"
                         "      mass 0.8 kg (kept)\n"
                         "      COM (0, 0, 0.125) m (kept)\n"
                         "      principal moments 0.000213, 0.00427, 0.0046 → 0.000251, 0.00431, "
                         "0.00456 kg·m²\n"
                         "    massprops fix --from-geometry=forearm two_link_arm.urdf\n"
                         "      a guess (a uniform solid)\n"
                         "      mass 0.8 kg (kept)\n"
                         "      COM (0, 0, 0.125) m (kept)\n"
                         "      principal moments 0.000213, 0.00427, 0.0046 → 0.000213, 0.00427, "
                         "0.00427 kg·m²\n"),
            std::string::npos)
      << run.out;
  ExpectLinesAtAGlance(run.out);
  ExpectLinesAtAGlance(run.err);
}

}  // namespace

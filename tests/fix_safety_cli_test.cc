// End-to-end tests of how `massprops fix` and `massprops merge-fixed` write (src/tool/safe_write.h,
// docs/fix.md "How files are written"), of exit codes on write errors, and of `fix` on SDF
// included models. Each test runs the built tool (MASSPROPS_TOOL_PATH) in a fresh folder.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

const std::string kTool = MASSPROPS_TOOL_PATH;

std::string ReadFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void WriteFile(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

struct ToolRun {
  int code = -1;
  std::string out;
  std::string err;
};

// A link whose inertia breaks the triangle inequality (ixx + iyy = 2 < izz = 3): `fix` rewrites
// its inertia (the only error of the file), every other byte stays.
const std::string kBadUrdf =
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\r\n"
    "<!-- Gelenk \xC3\xBC\x62\x65r alles: a comment with non-ASCII text -->\r\n"
    "<robot name=\"r\">\r\n"
    "  <link name=\"arm\">\r\n"
    "    <inertial>\r\n"
    "      <mass value=\"2\"/>\r\n"
    "      <inertia izz=\"3\" ixx=\"1\" iyy=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/>\r\n"
    "    </inertial>\r\n"
    "  </link>\r\n"
    "</robot>\r\n";

class FixSafetyTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "massprops-safety-XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
    out_ = fs::temp_directory_path() / (dir_.filename().string() + ".out");
    err_ = fs::temp_directory_path() / (dir_.filename().string() + ".err");
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
    fs::remove(out_, ec);
    fs::remove(err_, ec);
  }

  // Runs `sh -c 'PREFIX massprops ARGS'` in the test folder; stdout/stderr captured unless
  // ARGS redirects them itself.
  ToolRun Tool(const std::string& args, const std::string& prefix = "") {
    const std::string command = "cd '" + dir_.string() + "' && { " + prefix + " '" + kTool + "' " +
                                args + "; } >'" + out_.string() + "' 2>'" + err_.string() + "'";
    const int status = std::system(command.c_str());
    ToolRun run;
    run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = ReadFile(out_);
    run.err = ReadFile(err_);
    return run;
  }

  std::set<std::string> Listing() const {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) {
      names.insert(entry.path().filename().string());
    }
    return names;
  }

  fs::path dir_, out_, err_;
};

// Every run of digits, signs, points and exponents replaced by "#": what must stay identical.
std::string WithoutNumbers(const std::string& text) {
  static const std::regex kNumber("[-+]?[0-9][0-9.eE+-]*");
  return std::regex_replace(text, kNumber, "#");
}

TEST_F(FixSafetyTest, BytesOutsideTheEditedNumbersAreIdenticalAndASecondFixChangesNothing) {
  WriteFile(dir_ / "r.urdf", kBadUrdf);
  const ToolRun first = Tool("fix r.urdf --in-place");
  EXPECT_EQ(first.code, 0) << first.err;
  const std::string fixed = ReadFile(dir_ / "r.urdf");
  EXPECT_NE(fixed, kBadUrdf);
  // CRLF, the XML declaration, the non-ASCII comment and attribute order (izz first) are kept.
  EXPECT_EQ(WithoutNumbers(fixed), WithoutNumbers(kBadUrdf));
  EXPECT_NE(fixed.find("<inertia izz=\""), std::string::npos);
  const ToolRun second = Tool("fix r.urdf --in-place");
  EXPECT_EQ(second.code, 0) << second.err;
  EXPECT_EQ(ReadFile(dir_ / "r.urdf"), fixed);
  EXPECT_NE(second.err.find("no change needed"), std::string::npos) << second.err;
  EXPECT_EQ(Tool("check r.urdf").code, 0);
  // Atomic replacement leaves no temporary file behind.
  EXPECT_EQ(Listing(), std::set<std::string>{"r.urdf"});
}

TEST_F(FixSafetyTest, TheFileModeIsKept) {
  WriteFile(dir_ / "r.urdf", kBadUrdf);
  fs::permissions(dir_ / "r.urdf", fs::perms(0640));
  ASSERT_EQ(Tool("fix r.urdf --in-place").code, 0);
  EXPECT_EQ(fs::status(dir_ / "r.urdf").permissions() & fs::perms::mask, fs::perms(0640));
}

TEST_F(FixSafetyTest, ANewOutputFileHonoursTheUmask) {
  WriteFile(dir_ / "r.urdf", kBadUrdf);
  ASSERT_EQ(Tool("fix r.urdf -o a.urdf", "umask 022 &&").code, 0);
  EXPECT_EQ(fs::status(dir_ / "a.urdf").permissions() & fs::perms::mask, fs::perms(0644));
  ASSERT_EQ(Tool("fix r.urdf -o b.urdf", "umask 027 &&").code, 0);
  EXPECT_EQ(fs::status(dir_ / "b.urdf").permissions() & fs::perms::mask, fs::perms(0640));
}

TEST_F(FixSafetyTest, ASymlinksTargetIsRewrittenAndTheLinkStaysALink) {
  WriteFile(dir_ / "real.urdf", kBadUrdf);
  fs::create_symlink("real.urdf", dir_ / "link.urdf");
  ASSERT_EQ(Tool("fix link.urdf --in-place").code, 0);
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.urdf"));
  EXPECT_NE(ReadFile(dir_ / "real.urdf"), kBadUrdf);
  // -o through a link to another file: the same.
  WriteFile(dir_ / "target.urdf", "old");
  fs::create_symlink("target.urdf", dir_ / "out.urdf");
  WriteFile(dir_ / "again.urdf", kBadUrdf);
  ASSERT_EQ(Tool("fix again.urdf -o out.urdf").code, 0);
  EXPECT_TRUE(fs::is_symlink(dir_ / "out.urdf"));
  EXPECT_EQ(ReadFile(dir_ / "target.urdf"), ReadFile(dir_ / "real.urdf"));
}

TEST_F(FixSafetyTest, AFifoOutputIsWrittenThroughNotReplaced) {
  WriteFile(dir_ / "r.urdf", kBadUrdf);
  ASSERT_EQ(mkfifo((dir_ / "pipe").c_str(), 0600), 0);
  // A reader drains the FIFO while fix writes into it.
  const ToolRun run =
      Tool("fix r.urdf -o pipe & timeout 20 cat pipe > drained; wait $!", "timeout 20");
  EXPECT_EQ(run.code, 0) << run.err;
  struct stat st {};
  ASSERT_EQ(lstat((dir_ / "pipe").c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  EXPECT_NE(ReadFile(dir_ / "drained").find("<robot name=\"r\">"), std::string::npos);
}

TEST_F(FixSafetyTest, ACharacterDeviceOutputStaysADevice) {
  WriteFile(dir_ / "r.urdf", kBadUrdf);
  const ToolRun run = Tool("fix r.urdf -o /dev/null");
  EXPECT_EQ(run.code, 0) << run.err;
  struct stat st {};
  ASSERT_EQ(lstat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
}

TEST_F(FixSafetyTest, AReadOnlyFileIsRefusedAndLeftAlone) {
  WriteFile(dir_ / "r.urdf", kBadUrdf);
  fs::permissions(dir_ / "r.urdf", fs::perms(0444));
  const ToolRun run = Tool("fix r.urdf --in-place");
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("r.urdf is read-only (mode 0444)"), std::string::npos) << run.err;
  EXPECT_EQ(ReadFile(dir_ / "r.urdf"), kBadUrdf);
  EXPECT_EQ(Listing(), std::set<std::string>{"r.urdf"});
  // -o onto a read-only file: the same.
  WriteFile(dir_ / "ro.urdf", "keep");
  fs::permissions(dir_ / "ro.urdf", fs::perms(0444));
  fs::permissions(dir_ / "r.urdf", fs::perms(0644));
  EXPECT_EQ(Tool("fix r.urdf -o ro.urdf").code, 2);
  EXPECT_EQ(ReadFile(dir_ / "ro.urdf"), "keep");
}

TEST_F(FixSafetyTest, AReadOnlyFolderIsAClearErrorAndNothingChanges) {
  if (geteuid() == 0) GTEST_SKIP() << "root can create files in a read-only folder";
  fs::create_directory(dir_ / "ro");
  WriteFile(dir_ / "ro" / "r.urdf", kBadUrdf);
  fs::permissions(dir_ / "ro", fs::perms(0555));
  const ToolRun run = Tool("fix ro/r.urdf --in-place");
  fs::permissions(dir_ / "ro", fs::perms(0755));
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("cannot create a temporary file in ro"), std::string::npos) << run.err;
  EXPECT_EQ(ReadFile(dir_ / "ro" / "r.urdf"), kBadUrdf);
}

TEST_F(FixSafetyTest, AHardLinkedFileIsReplacedUnderItsNameAndTheToolSaysSo) {
  WriteFile(dir_ / "r.urdf", kBadUrdf);
  fs::create_hard_link(dir_ / "r.urdf", dir_ / "other.urdf");
  const ToolRun run = Tool("fix r.urdf --in-place");
  EXPECT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.err.find("has 2 hard links"), std::string::npos) << run.err;
  EXPECT_NE(ReadFile(dir_ / "r.urdf"), kBadUrdf);
  EXPECT_EQ(ReadFile(dir_ / "other.urdf"), kBadUrdf);
}

TEST_F(FixSafetyTest, TwoConcurrentFixesLeaveAValidFile) {
  WriteFile(dir_ / "r.urdf", kBadUrdf);
  const ToolRun run =
      Tool("fix r.urdf --in-place & '" + kTool + "' fix r.urdf --in-place; wait $!");
  EXPECT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(Tool("check r.urdf").code, 0);
  EXPECT_EQ(WithoutNumbers(ReadFile(dir_ / "r.urdf")), WithoutNumbers(kBadUrdf));
  EXPECT_EQ(Listing(), std::set<std::string>{"r.urdf"});
}

TEST_F(FixSafetyTest, MergeFixedNeverFollowsAPlantedTemporaryName) {
  // The old fixed temporary name OUT.massprops-tmp, planted as a link to a victim file.
  WriteFile(dir_ / "r.urdf",
            "<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/>"
            "<joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>"
            "</robot>\n");
  WriteFile(dir_ / "victim", "precious");
  fs::create_symlink("victim", dir_ / "out.urdf.massprops-tmp");
  const ToolRun run = Tool("merge-fixed r.urdf -o out.urdf");
  EXPECT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(ReadFile(dir_ / "victim"), "precious");
  EXPECT_NE(ReadFile(dir_ / "out.urdf").find("<link name=\"a\""), std::string::npos);
  EXPECT_EQ(ReadFile(dir_ / "out.urdf").find("<link name=\"b\""), std::string::npos);
}

TEST_F(FixSafetyTest, WritingToAFullOrClosedStandardOutputIsExitTwo) {
  WriteFile(dir_ / "r.urdf", kBadUrdf);
  for (const std::string command : {"fix r.urdf", "check r.urdf", "report r.urdf"}) {
    std::ofstream(out_).close();
    const std::string full = "cd '" + dir_.string() + "' && '" + kTool + "' " + command +
                             " >/dev/full 2>'" + err_.string() + "'";
    int status = std::system(full.c_str());
    EXPECT_EQ(WEXITSTATUS(status), 2) << command;
    EXPECT_NE(ReadFile(err_).find("cannot write to standard output"), std::string::npos)
        << command << ": " << ReadFile(err_);
    const std::string closed = "cd '" + dir_.string() + "' && '" + kTool + "' " + command +
                               " >&- 2>'" + err_.string() + "'";
    status = std::system(closed.c_str());
    EXPECT_EQ(WEXITSTATUS(status), 2) << command;
    EXPECT_NE(ReadFile(err_).find("cannot write to standard output"), std::string::npos)
        << command << ": " << ReadFile(err_);
  }
}

TEST_F(FixSafetyTest, ANegativeOrNanToleranceIsRefused) {
  WriteFile(dir_ / "r.urdf", kBadUrdf);
  for (const std::string value : {"-1", "nan", "inf"}) {
    const ToolRun run = Tool("fix r.urdf --in-place --tolerance " + value);
    EXPECT_EQ(run.code, 2) << value;
    EXPECT_NE(run.err.find("--tolerance must be a finite number at least 0"), std::string::npos)
        << run.err;
    EXPECT_EQ(ReadFile(dir_ / "r.urdf"), kBadUrdf);
  }
}

TEST_F(FixSafetyTest, ACommentedOutLinkOnTheSameLineIsLeftAlone) {
  const std::string text =
      "<robot name=\"r\">\n"
      "  <!-- <link name=\"arm\"><inertial><mass value=\"2\"/><inertia ixx=\"1\" iyy=\"1\" "
      "izz=\"3\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link> --> <link name=\"arm\">"
      "<inertial><mass value=\"2\"/><inertia ixx=\"1\" iyy=\"1\" izz=\"3\" ixy=\"0\" ixz=\"0\" "
      "iyz=\"0\"/></inertial></link>\n"
      "</robot>\n";
  WriteFile(dir_ / "r.urdf", text);
  const ToolRun run = Tool("fix r.urdf --in-place");
  EXPECT_EQ(run.code, 0) << run.err;
  const std::string fixed = ReadFile(dir_ / "r.urdf");
  const std::size_t comment_end = text.find("-->");
  EXPECT_EQ(fixed.substr(0, comment_end), text.substr(0, comment_end));  // the comment as it was
  EXPECT_NE(fixed, text);
  EXPECT_EQ(Tool("check r.urdf").code, 0);
}

// An SDF world whose top-level model has a link "body" on the same line as an <include> of a
// model (in its own file) whose link "body" has an impossible inertia.
void WriteIncludeFixture(const fs::path& dir) {
  fs::create_directories(dir / "box");
  WriteFile(dir / "box" / "model.sdf",
            "<?xml version=\"1.0\"?>\n"
            "<sdf version=\"1.9\">\n"
            "  <model name=\"box\">\n"
            "    <link name=\"body\">\n"
            "      <inertial>\n"
            "        <mass>2</mass>\n"
            "        <inertia><ixx>1</ixx><iyy>1</iyy><izz>3</izz></inertia>\n"
            "      </inertial>\n"
            "    </link>\n"
            "  </model>\n"
            "</sdf>\n");
  WriteFile(dir / "top.sdf",
            "<?xml version=\"1.0\"?>\n"
            "<sdf version=\"1.9\">\n"
            "  <model name=\"cart\">\n"
            "    <link name=\"body\"><inertial><mass>1</mass><inertia><ixx>0.1</ixx><iyy>0.1"
            "</iyy><izz>0.1</izz></inertia></inertial></link>\n"
            "    <include><uri>box/model.sdf</uri><name>cargo</name></include>\n"
            "    <joint name=\"j\" type=\"fixed\"><parent>body</parent><child>cargo::body</child>"
            "</joint>\n"
            "  </model>\n"
            "</sdf>\n");
}

TEST_F(FixSafetyTest, AnIncludedModelsLinkIsNamedNotPatchedInTheTopLevelFile) {
  WriteIncludeFixture(dir_);
  const std::string top = ReadFile(dir_ / "top.sdf");
  const std::string box = ReadFile(dir_ / "box" / "model.sdf");
  const ToolRun run = Tool("fix top.sdf --in-place");
  EXPECT_EQ(run.code, 1) << run.err;  // the error stays: it is in another file
  EXPECT_EQ(ReadFile(dir_ / "top.sdf"), top);
  EXPECT_EQ(ReadFile(dir_ / "box" / "model.sdf"), box);
  EXPECT_NE(run.err.find("box/model.sdf:4: link 'cargo::body'"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--include-files"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("0 link(s) repaired"), std::string::npos) << run.err;
}

TEST_F(FixSafetyTest, IncludeFilesRepairsTheIncludedModelInItsOwnFile) {
  WriteIncludeFixture(dir_);
  const std::string top = ReadFile(dir_ / "top.sdf");
  const std::string box = ReadFile(dir_ / "box" / "model.sdf");
  const ToolRun run = Tool("fix top.sdf --in-place --include-files");
  EXPECT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(ReadFile(dir_ / "top.sdf"), top);
  const std::string fixed_box = ReadFile(dir_ / "box" / "model.sdf");
  EXPECT_NE(fixed_box, box);
  EXPECT_EQ(WithoutNumbers(fixed_box), WithoutNumbers(box));
  EXPECT_EQ(Tool("check top.sdf").code, 0);
  // Idempotent: the second run changes nothing anywhere.
  EXPECT_EQ(Tool("fix top.sdf --in-place --include-files").code, 0);
  EXPECT_EQ(ReadFile(dir_ / "box" / "model.sdf"), fixed_box);
  EXPECT_EQ(ReadFile(dir_ / "top.sdf"), top);
}

TEST_F(FixSafetyTest, ReportAndFixSayWhatTheReaderSkipped) {
  WriteFile(dir_ / "w.sdf",
            "<sdf version=\"1.9\"><model name=\"m\">\n"
            "<link name=\"a\"><inertial><mass>1</mass><inertia><ixx>1</ixx><iyy>1</iyy><izz>1"
            "</izz></inertia></inertial></link>\n"
            "<include><uri>model://massprops_no_such_model</uri></include>\n"
            "</model></sdf>\n");
  const ToolRun report = Tool("report w.sdf --model-path .", "SDF_PATH= GZ_SIM_RESOURCE_PATH=");
  EXPECT_NE(report.err.find("w.sdf:3:"), std::string::npos) << report.err;
  // The reader's warning or finding (read-warning, or include-unresolved once the reader makes
  // it a finding), printed as `check` prints it.
  EXPECT_NE(report.err.find("model://massprops_no_such_model"), std::string::npos) << report.err;
  const ToolRun fix = Tool("fix w.sdf", "SDF_PATH= GZ_SIM_RESOURCE_PATH=");
  EXPECT_NE(fix.err.find("w.sdf:3:"), std::string::npos) << fix.err;
  EXPECT_NE(fix.err.find("model://massprops_no_such_model"), std::string::npos) << fix.err;
}

}  // namespace

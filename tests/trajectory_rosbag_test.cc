// Recorded trajectories from ROS 2 bags (massprops/io/trajectory_rosbag.h): sensor_msgs/msg/
// JointState read from CDR bytes worked out by hand, bags written with SQLite's own C API in
// rosbag2's two tables (tests/rosbag_writer.h) read back value for value, joints in another order
// per message, a bag folder of two files, velocities derived where the messages have none
// (against the analytic derivative of a sinusoid, as trajectory_csv_test), and each bad input a
// clear error naming the file and the problem.
#include "massprops/io/trajectory_rosbag.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "io/joint_state_cdr.h"
#include "io/sqlite_library.h"
#include "rosbag_writer.h"

namespace massprops {
namespace {

// The reader declares SQLite's C API itself (src/io/sqlite_library.h: no sqlite3.h needed to build
// it); each declaration must be sqlite3.h's.
using io_internal::SqliteApi;
static_assert(std::is_same_v<decltype(&sqlite3_open_v2), decltype(SqliteApi::open_v2)>);
static_assert(std::is_same_v<decltype(&sqlite3_close), decltype(SqliteApi::close)>);
static_assert(std::is_same_v<decltype(&sqlite3_errmsg), decltype(SqliteApi::errmsg)>);
static_assert(std::is_same_v<decltype(&sqlite3_prepare_v2), decltype(SqliteApi::prepare_v2)>);
static_assert(std::is_same_v<decltype(&sqlite3_step), decltype(SqliteApi::step)>);
static_assert(std::is_same_v<decltype(&sqlite3_finalize), decltype(SqliteApi::finalize)>);
static_assert(std::is_same_v<decltype(&sqlite3_column_int64), decltype(SqliteApi::column_int64)>);
static_assert(std::is_same_v<decltype(&sqlite3_column_text), decltype(SqliteApi::column_text)>);
static_assert(std::is_same_v<decltype(&sqlite3_column_blob), decltype(SqliteApi::column_blob)>);
static_assert(std::is_same_v<decltype(&sqlite3_column_bytes), decltype(SqliteApi::column_bytes)>);
static_assert(std::is_same_v<decltype(&sqlite3_bind_int64), decltype(SqliteApi::bind_int64)>);
static_assert(io_internal::kSqliteOk == SQLITE_OK && io_internal::kSqliteRow == SQLITE_ROW &&
              io_internal::kSqliteDone == SQLITE_DONE &&
              io_internal::kSqliteOpenReadOnly == SQLITE_OPEN_READONLY);

namespace fs = std::filesystem;
using test_support::EncodeJointState;
using test_support::TestBagMessage;
using test_support::TestJointState;
using test_support::WriteTestBag;

constexpr const char* kJointState = "sensor_msgs/msg/JointState";

std::string Messages(const TrajectoryReadResult& r) {
  std::string all;
  for (const ReadError& e : r.errors) all += e.ToString() + "\n";
  return all;
}

// The message {stamp 1.5 s, frame_id "b", names j1 j2, position 0.5 −1, no velocity, effort
// 2 0.25} as little-endian CDR, byte by byte by hand (offsets counted after the 4-byte header,
// to which every alignment is relative): sec at 0, nanosec 500 000 000 = 0x1DCD6500 at 4,
// frame_id length 2 at 8 and "b\0" at 12, 2 bytes of padding, the name count at 16, "j1\0" (length
// 3) at 20, 1 byte of padding, "j2\0" at 28, 1 byte of padding, the position count at 36 and its
// doubles at 40 (8-aligned: 44 from the buffer's start, so an alignment counted from the start
// would misread them), 0.5 = 0x3FE0000000000000, −1 = 0xBFF0000000000000, the empty velocity's
// count at 56 (no padding after it), the effort count at 60, 2 = 0x4000000000000000 and
// 0.25 = 0x3FD0000000000000 at 64 and 72.
const std::vector<std::uint8_t> kHandMessage = {
    0x00, 0x01, 0x00, 0x00,                           // CDR_LE, options
    0x01, 0x00, 0x00, 0x00, 0x00, 0x65, 0xCD, 0x1D,   // stamp
    0x02, 0x00, 0x00, 0x00, 'b',  0x00, 0x00, 0x00,   // frame_id, padding
    0x02, 0x00, 0x00, 0x00,                           // 2 names
    0x03, 0x00, 0x00, 0x00, 'j',  '1',  0x00, 0x00,   // "j1", padding
    0x03, 0x00, 0x00, 0x00, 'j',  '2',  0x00, 0x00,   // "j2", padding
    0x02, 0x00, 0x00, 0x00,                           // 2 positions
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xE0, 0x3F,   // 0.5
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF0, 0xBF,   // -1
    0x00, 0x00, 0x00, 0x00,                           // no velocity
    0x02, 0x00, 0x00, 0x00,                           // 2 efforts
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x40,   // 2
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xD0, 0x3F};  // 0.25

TestJointState HandMessage() {
  TestJointState m;
  m.sec = 1;
  m.nanosec = 500000000;
  m.frame_id = "b";
  m.name = {"j1", "j2"};
  m.position = {0.5, -1};
  m.effort = {2, 0.25};
  return m;
}

TEST(JointStateCdrTest, ReadsTheHandWorkedMessage) {
  std::string error;
  const auto m = io_internal::ParseJointStateCdr(kHandMessage.data(), kHandMessage.size(), &error);
  ASSERT_TRUE(m) << error;
  EXPECT_EQ(m->stamp_sec, 1);
  EXPECT_EQ(m->stamp_nanosec, 500000000u);
  EXPECT_EQ(m->frame_id, "b");
  EXPECT_EQ(m->name, (std::vector<std::string>{"j1", "j2"}));
  EXPECT_EQ(m->position, (std::vector<double>{0.5, -1}));
  EXPECT_TRUE(m->velocity.empty());
  EXPECT_EQ(m->effort, (std::vector<double>{2, 0.25}));
  // The tests' encoder writes the same bytes, so the bags below hold what this test proves.
  EXPECT_EQ(EncodeJointState(HandMessage()), kHandMessage);
}

TEST(JointStateCdrTest, ReadsBigEndian) {
  // The same message big-endian: its header 0x00 0x00, every primitive's bytes reversed.
  const std::vector<std::uint8_t> big = EncodeJointState(HandMessage(), false);
  ASSERT_EQ(big.size(), kHandMessage.size());
  EXPECT_EQ(big[1], 0x00);
  EXPECT_EQ(big[4 + 3], 0x01);  // sec = 1, most significant byte first
  std::string error;
  const auto m = io_internal::ParseJointStateCdr(big.data(), big.size(), &error);
  ASSERT_TRUE(m) << error;
  EXPECT_EQ(m->stamp_nanosec, 500000000u);
  EXPECT_EQ(m->position, (std::vector<double>{0.5, -1}));
  EXPECT_EQ(m->effort, (std::vector<double>{2, 0.25}));
}

TEST(JointStateCdrTest, EveryTruncationIsAnErrorNotARead) {
  for (std::size_t size = 0; size < kHandMessage.size(); ++size) {
    std::string error;
    EXPECT_FALSE(io_internal::ParseJointStateCdr(kHandMessage.data(), size, &error)) << size;
    EXPECT_NE(error.find("truncated"), std::string::npos) << size << ": " << error;
  }
  // A name count of 2^32 − 1 in a short message: refused before anything is reserved.
  std::vector<std::uint8_t> huge = kHandMessage;
  huge[20] = huge[21] = huge[22] = huge[23] = 0xFF;
  std::string error;
  EXPECT_FALSE(io_internal::ParseJointStateCdr(huge.data(), huge.size(), &error));
  EXPECT_NE(error.find("'name'"), std::string::npos) << error;
  // Another encapsulation (PL_CDR_LE, 0x00 0x03) is named, not misread.
  std::vector<std::uint8_t> pl = kHandMessage;
  pl[1] = 3;
  EXPECT_FALSE(io_internal::ParseJointStateCdr(pl.data(), pl.size(), &error));
  EXPECT_NE(error.find("not plain CDR"), std::string::npos) << error;
}

// Hostile bytes: 20 000 seeded mutations of the hand-worked message (bytes overwritten, counts
// and lengths among them, and cuts) either parse to a message whose arrays fit in the bytes given
// or are refused with a reason; never a read past the end (the sanitizer tree runs this under
// ASan) or a throw.
TEST(JointStateCdrTest, MutatedMessagesParseOrAreRefusedNeverOverrun) {
  std::mt19937 rng(51);
  int parsed = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    std::vector<std::uint8_t> bytes = kHandMessage;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits; ++e) bytes[rng() % bytes.size()] = static_cast<std::uint8_t>(rng());
    if (rng() % 3 == 0) bytes.resize(rng() % bytes.size());
    std::string error;
    const auto m = io_internal::ParseJointStateCdr(bytes.data(), bytes.size(), &error);
    if (!m) {
      EXPECT_FALSE(error.empty()) << trial;
      continue;
    }
    ++parsed;
    std::size_t payload = m->frame_id.size();
    for (const std::string& n : m->name) payload += 4 + n.size();
    payload += 8 * (m->position.size() + m->velocity.size() + m->effort.size());
    EXPECT_LE(payload, bytes.size()) << trial;
  }
  EXPECT_GT(parsed, 0);  // some mutations (of a value, not of a count) still parse
}

class RosbagTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "massprops-rosbag-XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  // Message k of a 100 Hz recording of joints a and b: q_a = 0.8·sin(πk/100) (0.5 Hz),
  // q_b = k/1000, velocities their analytic derivatives, effort a = k, b = −k; stamp 10 s + k/100
  // (in nanoseconds exactly); the names reversed on odd k.
  static TestJointState Sample(int k, bool velocity = true) {
    const double t = k / 100.0, w = M_PI;
    TestJointState m;
    const std::int64_t ns = 10000000000 + std::int64_t{k} * 10000000;
    m.sec = static_cast<std::int32_t>(ns / 1000000000);
    m.nanosec = static_cast<std::uint32_t>(ns % 1000000000);
    m.name = {"a", "b"};
    m.position = {0.8 * std::sin(w * t), k / 1000.0};
    if (velocity) m.velocity = {0.8 * w * std::cos(w * t), 0.1};
    m.effort = {double(k), -double(k)};
    if (k % 2 == 1) {
      std::swap(m.name[0], m.name[1]);
      std::swap(m.position[0], m.position[1]);
      if (velocity) std::swap(m.velocity[0], m.velocity[1]);
      std::swap(m.effort[0], m.effort[1]);
    }
    return m;
  }
  static std::vector<TestBagMessage> Recording(int n, bool velocity = true) {
    std::vector<TestBagMessage> out;
    for (int k = 0; k < n; ++k) {
      // Receive times 3 ms after the stamps; another topic's message between.
      out.push_back({"/joint_states", 10003000000 + std::int64_t{k} * 10000000,
                     EncodeJointState(Sample(k, velocity))});
      out.push_back({"/tf", 10004000000 + std::int64_t{k} * 10000000, {0, 1, 0, 0, 7}});
    }
    return out;
  }
  std::string Bag(const std::vector<TestBagMessage>& messages, const std::string& name = "b.db3",
                  bool with_joint_states = true) {
    const std::string path = (dir_ / name).string();
    std::vector<std::pair<std::string, std::string>> topics = {{"/tf", "tf2_msgs/msg/TFMessage"}};
    if (with_joint_states) topics.emplace_back("/joint_states", kJointState);
    const std::string error = WriteTestBag(path, topics, messages);
    EXPECT_EQ(error, "");
    return path;
  }
  // The only error's message, which must name `path`.
  static std::string OnlyError(const TrajectoryReadResult& r, const std::string& path) {
    EXPECT_FALSE(r.ok());
    EXPECT_FALSE(r.trajectory);
    if (r.errors.empty()) return "";
    EXPECT_EQ(r.errors[0].location.file, path);
    return r.errors[0].message;
  }

  fs::path dir_;
};

TEST_F(RosbagTest, ReadsEveryValueAsWritten) {
  const std::string path = Bag(Recording(40));
  ASSERT_TRUE(IsRosbagPath(path));
  const TrajectoryReadResult r = ReadTrajectoryRosbag(path);
  ASSERT_TRUE(r.ok()) << Messages(r);
  const JointTrajectory& t = *r.trajectory;
  EXPECT_EQ(t.joints, (std::vector<std::string>{"a", "b"}));
  ASSERT_EQ(t.q.rows(), 40);
  for (int k = 0; k < 40; ++k) {
    const TestJointState m = Sample(k);
    const int a = k % 2;  // where joint a is in message k
    // Time from the first stamp: k/100 s, from integer nanoseconds (exact to round-off).
    EXPECT_NEAR(t.time(k), k / 100.0, 1e-15) << k;
    EXPECT_EQ(t.q(k, 0), m.position[a]);
    EXPECT_EQ(t.q(k, 1), m.position[1 - a]);
    EXPECT_EQ(t.dq(k, 0), m.velocity[a]);
    EXPECT_EQ(t.tau(k, 0), k);
    EXPECT_EQ(t.tau(k, 1), -k);
  }
  // ddq derived from the recorded dq (the only note per joint): d/dt of 0.8π·cos(πt) is
  // −0.8π²·sin(πt); 1e-3 of 0.8π² away from the ends (the filter's 10 Hz against 0.5 Hz and the
  // central differences' (ωh)²/6, as trajectory_csv_test bounds them).
  ASSERT_EQ(t.notes.size(), 2u);
  EXPECT_NE(t.notes[0].find("ddq derived from dq"), std::string::npos) << t.notes[0];
  for (int k = 10; k < 30; ++k)
    EXPECT_NEAR(t.ddq(k, 0), -0.8 * M_PI * M_PI * std::sin(M_PI * k / 100.0), 8e-3) << k;
}

TEST_F(RosbagTest, ZeroStampsTakeTheBagTimestamp) {
  std::vector<TestBagMessage> messages = Recording(12);
  for (TestBagMessage& m : messages) {
    if (m.topic != "/joint_states") continue;
    for (int i = 4; i < 12; ++i) m.data[static_cast<std::size_t>(i)] = 0;  // sec = nanosec = 0
  }
  const TrajectoryReadResult r = ReadTrajectoryRosbag(Bag(messages));
  ASSERT_TRUE(r.ok()) << Messages(r);
  EXPECT_NEAR(r.trajectory->time(11), 0.11, 1e-15);  // receive times, 10 ms apart
}

TEST_F(RosbagTest, ReadsABagFolderOfTwoFiles) {
  const std::vector<TestBagMessage> all = Recording(30);
  fs::create_directory(dir_ / "bag");
  std::ofstream(dir_ / "bag" / "metadata.yaml") << "rosbag2_bagfile_information:\n  version: 5\n";
  Bag({all.begin(), all.begin() + 20}, "bag/bag_0.db3");
  Bag({all.begin() + 20, all.end()}, "bag/bag_1.db3");
  const std::string folder = (dir_ / "bag").string();
  ASSERT_TRUE(IsRosbagPath(folder));
  const TrajectoryReadResult r = ReadTrajectoryRosbag(folder);
  ASSERT_TRUE(r.ok()) << Messages(r);
  ASSERT_EQ(r.trajectory->q.rows(), 30);  // 10 JointState messages in the first file, 20 after
  EXPECT_EQ(r.trajectory->tau(29, 1), -29);
}

TEST_F(RosbagTest, DerivesVelocitiesWhenTheMessagesHaveNone) {
  const TrajectoryReadResult r = ReadTrajectoryRosbag(Bag(Recording(200, false)));
  ASSERT_TRUE(r.ok()) << Messages(r);
  const JointTrajectory& t = *r.trajectory;
  EXPECT_NE(t.notes[0].find("dq and ddq derived from q"), std::string::npos) << t.notes[0];
  for (int k = 20; k < 180; ++k) {
    EXPECT_NEAR(t.dq(k, 0), 0.8 * M_PI * std::cos(M_PI * k / 100.0), 2.5e-3) << k;
    EXPECT_NEAR(t.dq(k, 1), 0.1, 1e-9) << k;  // a ramp passes the filter unchanged
  }
}

// Several JointState topics: /joint_states is read; without it the choice is an error naming them.
TEST_F(RosbagTest, PicksJointStatesAmongSeveralAndRefusesToGuess) {
  std::vector<TestBagMessage> messages = Recording(12);
  for (int k = 0; k < 12; ++k) {
    TestJointState other = Sample(k);
    other.effort = {7, 7};
    messages.push_back(
        {"/arm/joint_states", 20000000000 + std::int64_t{k}, EncodeJointState(other)});
  }
  const std::string both = (dir_ / "both.db3").string();
  ASSERT_EQ(WriteTestBag(both, {{"/arm/joint_states", kJointState}, {"/joint_states", kJointState}},
                         messages),
            "");
  const TrajectoryReadResult r = ReadTrajectoryRosbag(both);
  ASSERT_TRUE(r.ok()) << Messages(r);
  EXPECT_EQ(r.trajectory->tau(11, 0), 11);  // /joint_states' effort, not /arm/joint_states' 7
  for (TestBagMessage& m : messages)
    if (m.topic == "/joint_states") m.topic = "/leg/joint_states";
  const std::string neither = (dir_ / "neither.db3").string();
  ASSERT_EQ(WriteTestBag(neither,
                         {{"/arm/joint_states", kJointState}, {"/leg/joint_states", kJointState}},
                         messages),
            "");
  const std::string e = OnlyError(ReadTrajectoryRosbag(neither), neither);
  EXPECT_NE(e.find("several sensor_msgs/msg/JointState topics ('/arm/joint_states', "
                   "'/leg/joint_states') and none is /joint_states"),
            std::string::npos)
      << e;
}

TEST_F(RosbagTest, BadInputsAreErrorsNamingTheFileAndTheProblem) {
  // No JointState topic.
  std::string path = Bag(Recording(12), "no_joint_states.db3", false);
  EXPECT_NE(OnlyError(ReadTrajectoryRosbag(path), path)
                .find("no topic of type " + std::string(kJointState)),
            std::string::npos);
  // A message cut short: message 5 of the topic.
  std::vector<TestBagMessage> m = Recording(12);
  m[8].data.resize(50);
  path = Bag(m, "truncated.db3");
  std::string e = OnlyError(ReadTrajectoryRosbag(path), path);
  EXPECT_NE(e.find("message 5 of /joint_states: truncated"), std::string::npos) << e;
  // A joint missing from message 3 (index 4 of the list).
  m = Recording(12);
  TestJointState s = Sample(2);
  s.name.pop_back(), s.position.pop_back(), s.velocity.pop_back(), s.effort.pop_back();
  m[4].data = EncodeJointState(s);
  path = Bag(m, "missing.db3");
  e = OnlyError(ReadTrajectoryRosbag(path), path);
  EXPECT_NE(e.find("message 3 of /joint_states: joint 'b' is missing"), std::string::npos) << e;
  // NaN.
  m = Recording(12);
  s = Sample(6);
  s.effort[0] = std::numeric_limits<double>::quiet_NaN();
  m[12].data = EncodeJointState(s);
  path = Bag(m, "nan.db3");
  e = OnlyError(ReadTrajectoryRosbag(path), path);
  EXPECT_NE(e.find("joint 'a' effort is not a finite number"), std::string::npos) << e;
  // Time going back: message 4's stamp before message 3's.
  m = Recording(12);
  s = Sample(3);
  s.sec = 9;
  m[6].data = EncodeJointState(s);
  path = Bag(m, "back.db3");
  e = OnlyError(ReadTrajectoryRosbag(path), path);
  EXPECT_NE(e.find("message 4 of /joint_states: time 9030000000 ns is not after"),
            std::string::npos)
      << e;
  // Efforts missing: the joint is named.
  m = Recording(12);
  s = Sample(0);
  s.effort.clear();
  m[0].data = EncodeJointState(s);
  path = Bag(m, "no_effort.db3");
  e = OnlyError(ReadTrajectoryRosbag(path), path);
  EXPECT_NE(e.find("joint 'a' has no effort"), std::string::npos) << e;
  // Too few messages.
  path = Bag(Recording(5), "short.db3");
  EXPECT_NE(OnlyError(ReadTrajectoryRosbag(path), path).find("5 JointState messages"),
            std::string::npos);
  // Not a database; a folder without metadata.yaml.
  path = (dir_ / "text.db3").string();
  std::ofstream(path) << "time,a.q\n";
  EXPECT_NE(OnlyError(ReadTrajectoryRosbag(path), path).find("not a rosbag2 SQLite file"),
            std::string::npos);
  fs::create_directory(dir_ / "empty");
  path = (dir_ / "empty").string();
  EXPECT_NE(OnlyError(ReadTrajectoryRosbag(path), path).find("no metadata.yaml"),
            std::string::npos);
}

}  // namespace
}  // namespace massprops

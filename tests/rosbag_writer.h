#pragma once
// A test's own rosbag2 writer: sensor_msgs/msg/JointState messages serialized as CDR by a small
// encoder written from the OMG CDR rules (each primitive aligned to its size counted from the end
// of the 4-byte encapsulation header; strings as a uint32 length including the NUL, then the
// bytes; sequences as a uint32 count, then the elements), stored with SQLite's own C API in the
// two tables of rosbag2's SQLite storage (rosbag2_storage_default_plugins, sqlite3 plugin):
// topics(id, name, type, serialization_format, offered_qos_profiles) and
// messages(id, topic_id, timestamp, data). It shares no code with the reader under test
// (src/io/trajectory_rosbag.cc, src/io/joint_state_cdr.cc); rosbag_test checks its bytes against
// a message worked out by hand.

#include <sqlite3.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace massprops::test_support {

/// A JointState message to write.
struct TestJointState {
  std::int32_t sec = 0;
  std::uint32_t nanosec = 0;
  std::string frame_id;
  std::vector<std::string> name;
  std::vector<double> position, velocity, effort;
};

class TestCdrWriter {
 public:
  explicit TestCdrWriter(bool little_endian) : little_(little_endian) {
    bytes_ = {0, static_cast<std::uint8_t>(little_endian ? 1 : 0), 0, 0};
  }
  void U32(std::uint32_t v) { Put(&v, 4); }
  void I32(std::int32_t v) { Put(&v, 4); }
  void F64(double v) { Put(&v, 8); }
  void Str(const std::string& s) {
    U32(static_cast<std::uint32_t>(s.size() + 1));
    bytes_.insert(bytes_.end(), s.begin(), s.end());
    bytes_.push_back(0);
  }
  void Doubles(const std::vector<double>& v) {
    U32(static_cast<std::uint32_t>(v.size()));
    for (double x : v) F64(x);
  }
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

 private:
  // v's n bytes (host little-endian, as x86-64 and arm64 are), after padding to n from byte 4.
  void Put(const void* v, std::size_t n) {
    while ((bytes_.size() - 4) % n != 0) bytes_.push_back(0);
    std::uint8_t raw[8];
    std::memcpy(raw, v, n);
    for (std::size_t i = 0; i < n; ++i) bytes_.push_back(raw[little_ ? i : n - 1 - i]);
  }
  bool little_;
  std::vector<std::uint8_t> bytes_;
};

inline std::vector<std::uint8_t> EncodeJointState(const TestJointState& m,
                                                  bool little_endian = true) {
  TestCdrWriter w(little_endian);
  w.I32(m.sec);
  w.U32(m.nanosec);
  w.Str(m.frame_id);
  w.U32(static_cast<std::uint32_t>(m.name.size()));
  for (const std::string& n : m.name) w.Str(n);
  w.Doubles(m.position);
  w.Doubles(m.velocity);
  w.Doubles(m.effort);
  return w.bytes();
}

/// A message of a rosbag2 SQLite file: its topic's name, the receive timestamp, the bytes.
struct TestBagMessage {
  std::string topic;
  std::int64_t timestamp_ns = 0;
  std::vector<std::uint8_t> data;
};

/// Writes `path` (replacing it) with the topics given as (name, type) and the messages; returns
/// "" or SQLite's error.
inline std::string WriteTestBag(const std::string& path,
                                const std::vector<std::pair<std::string, std::string>>& topics,
                                const std::vector<TestBagMessage>& messages) {
  std::remove(path.c_str());
  sqlite3* db = nullptr;
  if (sqlite3_open(path.c_str(), &db) != SQLITE_OK) return "cannot open " + path;
  std::string error;
  auto exec = [&](const std::string& sql) {
    char* message = nullptr;
    if (sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &message) != SQLITE_OK && error.empty())
      error = message != nullptr ? message : sql;
    sqlite3_free(message);
  };
  exec(
      "CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, "
      "serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL)");
  exec(
      "CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, "
      "timestamp INTEGER NOT NULL, data BLOB NOT NULL)");
  for (std::size_t i = 0; i < topics.size(); ++i) {
    exec("INSERT INTO topics VALUES(" + std::to_string(i + 1) + ", '" + topics[i].first + "', '" +
         topics[i].second + "', 'cdr', '')");
  }
  exec("BEGIN");
  sqlite3_stmt* insert = nullptr;
  sqlite3_prepare_v2(db, "INSERT INTO messages(topic_id, timestamp, data) VALUES(?, ?, ?)", -1,
                     &insert, nullptr);
  for (const TestBagMessage& m : messages) {
    std::int64_t topic_id = 0;
    for (std::size_t i = 0; i < topics.size(); ++i)
      if (topics[i].first == m.topic) topic_id = static_cast<std::int64_t>(i + 1);
    sqlite3_bind_int64(insert, 1, topic_id);
    sqlite3_bind_int64(insert, 2, m.timestamp_ns);
    sqlite3_bind_blob(insert, 3, m.data.data(), static_cast<int>(m.data.size()), SQLITE_TRANSIENT);
    if (sqlite3_step(insert) != SQLITE_DONE && error.empty()) error = sqlite3_errmsg(db);
    sqlite3_reset(insert);
  }
  sqlite3_finalize(insert);
  exec("COMMIT");
  sqlite3_close(db);
  return error;
}

}  // namespace massprops::test_support

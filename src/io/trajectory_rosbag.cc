#include "massprops/io/trajectory_rosbag.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/joint_state_cdr.h"
#include "io/sqlite_library.h"
#include "io/trajectory_derive.h"

namespace massprops {

namespace {

constexpr const char* kJointStateType = "sensor_msgs/msg/JointState";
constexpr std::size_t kMaxBagErrors = 20;

// An open SQLite database and a statement on it, closed and finalized when they go.
class BagDatabase {
 public:
  BagDatabase(const io_internal::SqliteApi* api, const std::string& file) : api_(api) {
    if (api_->open_v2(file.c_str(), &db_, io_internal::kSqliteOpenReadOnly, nullptr) !=
        io_internal::kSqliteOk)
      error_ = db_ != nullptr ? api_->errmsg(db_) : "cannot be opened";
  }
  ~BagDatabase() {
    if (statement_ != nullptr) api_->finalize(statement_);
    if (db_ != nullptr) api_->close(db_);
  }
  BagDatabase(const BagDatabase&) = delete;
  BagDatabase& operator=(const BagDatabase&) = delete;

  const std::string& error() const { return error_; }
  // Prepares `sql` (finalizing the statement before); false with error() on failure.
  bool Prepare(const char* sql) {
    if (statement_ != nullptr) api_->finalize(statement_);
    statement_ = nullptr;
    if (api_->prepare_v2(db_, sql, -1, &statement_, nullptr) == io_internal::kSqliteOk) return true;
    error_ = std::string("not a rosbag2 SQLite file (") + api_->errmsg(db_) + ")";
    return false;
  }
  // The next row: true while there is one; a failure sets error().
  bool Step() {
    const int rc = api_->step(statement_);
    if (rc == io_internal::kSqliteRow) return true;
    if (rc != io_internal::kSqliteDone) error_ = api_->errmsg(db_);
    return false;
  }
  void Bind(int index, std::int64_t value) { api_->bind_int64(statement_, index, value); }
  std::int64_t Int(int column) { return api_->column_int64(statement_, column); }
  std::string Text(int column) {
    const unsigned char* text = api_->column_text(statement_, column);
    return text != nullptr ? reinterpret_cast<const char*>(text) : "";
  }
  const std::uint8_t* Blob(int column, std::size_t* size) {
    const void* blob = api_->column_blob(statement_, column);
    *size = static_cast<std::size_t>(std::max(0, api_->column_bytes(statement_, column)));
    return static_cast<const std::uint8_t*>(blob);
  }

 private:
  const io_internal::SqliteApi* api_;
  sqlite3* db_ = nullptr;
  sqlite3_stmt* statement_ = nullptr;
  std::string error_;
};

// One message, its arrays in the trajectory's joint order.
struct BagSample {
  std::int64_t time_ns = 0;
  std::vector<double> q, dq, tau;
};

class RosbagReader {
 public:
  RosbagReader(const io_internal::SqliteApi* api, const TrajectoryCsvOptions& options)
      : api_(api), options_(options) {}

  TrajectoryReadResult Read(const std::string& path) {
    std::vector<std::string> files;
    if (!BagFiles(path, &files)) return std::move(result_);
    for (const std::string& file : files) {
      if (!ReadFile(file)) return std::move(result_);
    }
    if (samples_.empty()) {
      Error(path, "the bag has no topic of type " + std::string(kJointStateType) +
                      " (or no message on it)");
      return std::move(result_);
    }
    if (static_cast<int>(samples_.size()) < options_.min_samples) {
      Error(path, std::to_string(samples_.size()) + " JointState messages; at least " +
                      std::to_string(options_.min_samples) + " are needed");
      return std::move(result_);
    }
    Assemble(path);
    return std::move(result_);
  }

 private:
  void Error(const std::string& file, const std::string& message) {
    if (result_.errors.size() < kMaxBagErrors)
      result_.errors.push_back(MakeReadError(file, 0, "", message));
  }

  // The .db3 files of the bag, in name order.
  bool BagFiles(const std::string& path, std::vector<std::string>* files) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::is_directory(path, ec)) {
      if (!fs::is_regular_file(path, ec)) {
        Error(path, "no such file or folder");
        return false;
      }
      files->push_back(path);
      return true;
    }
    if (!fs::exists(fs::path(path) / "metadata.yaml", ec)) {
      Error(path, "not a rosbag2 folder: it has no metadata.yaml");
      return false;
    }
    for (const fs::directory_entry& entry : fs::directory_iterator(path, ec))
      if (entry.path().extension() == ".db3") files->push_back(entry.path().string());
    std::sort(files->begin(), files->end());
    if (files->empty())
      Error(path, "the bag folder has no .db3 file (only SQLite storage is read)");
    return !files->empty();
  }

  // The id of the JointState topic of this file, or -1 (none; an error when ambiguous).
  std::int64_t JointStateTopic(const std::string& file, BagDatabase* db, bool* failed) {
    if (!db->Prepare("SELECT id, name, type FROM topics")) return *failed = true, -1;
    std::map<std::string, std::int64_t> topics;
    while (db->Step())
      if (db->Text(2) == kJointStateType) topics[db->Text(1)] = db->Int(0);
    if (!db->error().empty()) return *failed = true, -1;
    if (topics.empty()) return -1;
    if (topic_.empty()) {
      if (topics.size() > 1 && topics.count("/joint_states") == 0) {
        std::string names;
        for (const auto& [name, id] : topics) names += (names.empty() ? "'" : ", '") + name + "'";
        Error(file, "several " + std::string(kJointStateType) + " topics (" + names +
                        ") and none is /joint_states: which one to read is not clear");
        return *failed = true, -1;
      }
      topic_ = topics.size() == 1 ? topics.begin()->first : "/joint_states";
    }
    const auto it = topics.find(topic_);
    return it != topics.end() ? it->second : -1;
  }

  bool ReadFile(const std::string& file) {
    BagDatabase db(api_, file);
    bool failed = !db.error().empty();
    const std::int64_t topic = failed ? -1 : JointStateTopic(file, &db, &failed);
    if (!failed && topic >= 0) {
      failed = !db.Prepare(
          "SELECT timestamp, data FROM messages WHERE topic_id = ? ORDER BY timestamp, id");
      if (!failed) db.Bind(1, topic);
      while (!failed && db.Step()) {
        std::size_t size = 0;
        const std::uint8_t* data = db.Blob(1, &size);
        AddMessage(file, db.Int(0), data, size);
        if (result_.errors.size() >= kMaxBagErrors) break;
      }
      failed = failed || !db.error().empty();
    }
    if (failed && result_.errors.empty()) Error(file, db.error());
    return result_.errors.empty();
  }

  void AddMessage(const std::string& file, std::int64_t bag_ns, const std::uint8_t* data,
                  std::size_t size) {
    const std::string where = "message " + std::to_string(++messages_) + " of " + topic_;
    std::string why;
    const std::optional<io_internal::JointStateMessage> m =
        io_internal::ParseJointStateCdr(data, size, &why);
    if (!m) return Error(file, where + ": " + why);
    if (m->name.empty()) return Error(file, where + ": it names no joint");
    if (joints_.empty()) joints_ = m->name;
    BagSample s;
    const std::int64_t stamp = std::int64_t{m->stamp_sec} * 1000000000 + m->stamp_nanosec;
    s.time_ns = stamp != 0 ? stamp : bag_ns;
    if (!samples_.empty() && s.time_ns <= samples_.back().time_ns) {
      Error(file, where + ": time " + std::to_string(s.time_ns) +
                      " ns is not after the previous message's (" +
                      std::to_string(samples_.back().time_ns) + " ns)");
    }
    for (const auto* array : {&m->position, &m->velocity, &m->effort}) {
      if (!array->empty() && array->size() != m->name.size()) {
        return Error(file, where + ": " + std::to_string(m->name.size()) +
                               " names but an array of " + std::to_string(array->size()) +
                               " values");
      }
    }
    if (m->velocity.empty()) all_have_velocity_ = false;
    for (const std::string& joint : joints_) {
      const auto at = std::find(m->name.begin(), m->name.end(), joint);
      if (at == m->name.end()) return Error(file, where + ": joint '" + joint + "' is missing");
      const std::size_t i = static_cast<std::size_t>(at - m->name.begin());
      if (m->position.empty() || m->effort.empty()) {
        return Error(file, where + ": joint '" + joint + "' has no " +
                               (m->position.empty() ? "position" : "effort") +
                               " (identification needs the measured torques)");
      }
      const double v = m->velocity.empty() ? 0.0 : m->velocity[i];
      for (const auto& [what, value] : {std::pair<const char*, double>{"position", m->position[i]},
                                        {"velocity", v},
                                        {"effort", m->effort[i]}}) {
        if (!std::isfinite(value))
          return Error(file, where + ": joint '" + joint + "' " + what + " is not a finite number");
      }
      s.q.push_back(m->position[i]);
      s.dq.push_back(v);
      s.tau.push_back(m->effort[i]);
    }
    if (m->name.size() != joints_.size()) {
      return Error(file, where + ": " + std::to_string(m->name.size()) +
                             " joints where the first message has " +
                             std::to_string(joints_.size()));
    }
    samples_.push_back(std::move(s));
  }

  void Assemble(const std::string& path) {
    const Eigen::Index N = static_cast<Eigen::Index>(samples_.size());
    const Eigen::Index n = static_cast<Eigen::Index>(joints_.size());
    JointTrajectory t;
    t.joints = joints_;
    t.time.resize(N);
    t.q.resize(N, n);
    t.dq.resize(N, n);
    t.ddq.setZero(N, n);
    t.tau.resize(N, n);
    for (Eigen::Index k = 0; k < N; ++k) {
      const BagSample& s = samples_[static_cast<std::size_t>(k)];
      t.time(k) = static_cast<double>(s.time_ns - samples_.front().time_ns) * 1e-9;
      for (Eigen::Index j = 0; j < n; ++j) {
        const std::size_t jj = static_cast<std::size_t>(j);
        t.q(k, j) = s.q[jj];
        t.dq(k, j) = s.dq[jj];
        t.tau(k, j) = s.tau[jj];
      }
    }
    const std::vector<io_internal::RecordedDerivatives> recorded(
        joints_.size(), io_internal::RecordedDerivatives{all_have_velocity_, false});
    const std::string error = io_internal::DeriveMissingDerivatives(recorded, options_, &t);
    if (!error.empty()) return Error(path, error);
    result_.trajectory = std::move(t);
  }

  const io_internal::SqliteApi* api_;
  TrajectoryCsvOptions options_;
  TrajectoryReadResult result_;
  std::string topic_;
  std::vector<std::string> joints_;
  std::vector<BagSample> samples_;
  bool all_have_velocity_ = true;
  int messages_ = 0;
};

}  // namespace

bool IsRosbagPath(const std::string& path) {
  std::error_code ec;
  return std::filesystem::is_directory(path, ec) ||
         (path.size() >= 4 && path.compare(path.size() - 4, 4, ".db3") == 0);
}

TrajectoryReadResult ReadTrajectoryRosbag(const std::string& path,
                                          const TrajectoryCsvOptions& options) {
  std::string error;
  const io_internal::SqliteApi* api = io_internal::LoadSqlite(&error);
  if (api == nullptr) {
    TrajectoryReadResult result;
    result.errors.push_back(MakeReadError(path, 0, "", error));
    return result;
  }
  return RosbagReader(api, options).Read(path);
}

}  // namespace massprops

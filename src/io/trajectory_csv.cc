#include "massprops/io/trajectory_csv.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "io/trajectory_derive.h"
#include "massprops/io/model_reader.h"

namespace massprops {

namespace {

constexpr const char* kKinds[] = {"q", "dq", "ddq", "tau"};
constexpr std::size_t kMaxTrajectoryBytes = std::size_t{1} << 31;

std::string Trim(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

std::vector<std::string> SplitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) fields.push_back(Trim(field));
  if (!line.empty() && line.back() == ',') fields.push_back("");
  return fields;
}

// The data rows: each a line number and its fields.
struct Table {
  std::vector<std::string> header;
  int header_line = 0;
  std::vector<std::pair<int, std::vector<std::string>>> rows;
};

Table SplitTable(const std::string& text) {
  Table table;
  std::stringstream stream(text);
  std::string line;
  for (int number = 1; std::getline(stream, line); ++number) {
    const std::string trimmed = Trim(line);
    if (trimmed.empty() || trimmed[0] == '#') continue;
    if (table.header.empty()) {
      table.header = SplitFields(trimmed);
      table.header_line = number;
    } else {
      table.rows.emplace_back(number, SplitFields(trimmed));
    }
  }
  return table;
}

// Column index of each (joint, kind); -1 where absent. Joints in the order of their first column.
struct Columns {
  int time = -1;
  std::vector<std::string> joints;
  std::map<std::string, std::array<int, 4>> of;
};

// A PlotJuggler series name of a sensor_msgs/JointState topic, `<topic>/<J>/position` (also
// `velocity`, `effort`): its joint and kind ("q", "dq", "tau"), or false. PlotJuggler's ROS parsers
// (plotjuggler_plugins/ParserROS, JointStateMsgParser) name each joint's series so, and its CSV
// export writes them as columns after `__time`.
bool PlotJugglerColumn(const std::string& name, std::string* joint, std::string* kind) {
  if (name.empty() || name[0] != '/') return false;
  const std::size_t last = name.rfind('/');
  const std::size_t before = last == 0 ? std::string::npos : name.rfind('/', last - 1);
  if (before == std::string::npos || before == 0 || before + 1 == last) return false;
  const std::string field = name.substr(last + 1);
  if (field == "position")
    *kind = "q";
  else if (field == "velocity")
    *kind = "dq";
  else if (field == "effort")
    *kind = "tau";
  else
    return false;
  *joint = name.substr(before + 1, last - before - 1);
  return true;
}

Columns FindColumns(const std::vector<std::string>& header) {
  Columns c;
  int plotjuggler_time = -1;
  for (std::size_t i = 0; i < header.size(); ++i) {
    const std::string& name = header[i];
    if (name == "time") c.time = static_cast<int>(i);
    if (name == "__time") plotjuggler_time = static_cast<int>(i);
    std::string joint, kind;
    if (!PlotJugglerColumn(name, &joint, &kind)) {
      const std::size_t dot = name.rfind('.');
      if (dot == std::string::npos || dot == 0) continue;
      joint = name.substr(0, dot);
      kind = name.substr(dot + 1);
    }
    for (int k = 0; k < 4; ++k) {
      if (kind != kKinds[k]) continue;
      if (c.of.count(joint) == 0) {
        c.joints.push_back(joint);
        c.of[joint] = {-1, -1, -1, -1};
      }
      c.of[joint][static_cast<std::size_t>(k)] = static_cast<int>(i);
    }
  }
  if (c.time < 0) c.time = plotjuggler_time;
  return c;
}

class CsvReader {
 public:
  CsvReader(std::string file, const TrajectoryCsvOptions& options)
      : file_(std::move(file)), options_(options) {}

  TrajectoryReadResult Read(const std::string& text) {
    const Table table = SplitTable(text);
    if (table.header.empty()) return Fail(0, "the file has no header row");
    const Columns columns = FindColumns(table.header);
    if (columns.time < 0)
      return Fail(table.header_line, "no 'time' column (nor PlotJuggler's '__time') in the header");
    if (columns.joints.empty()) return Fail(table.header_line, "no joint columns ('J.q', 'J.tau')");
    for (const std::string& joint : columns.joints) {
      const auto& of = columns.of.at(joint);
      for (std::size_t kind : {0, 3}) {
        if (of[kind] < 0) {
          Error(table.header_line,
                "joint '" + joint + "' has no '" + joint + "." + kKinds[kind] + "' column");
        }
      }
    }
    if (!result_.errors.empty()) return std::move(result_);
    if (static_cast<int>(table.rows.size()) < options_.min_samples) {
      return Fail(0, std::to_string(table.rows.size()) + " samples; at least " +
                         std::to_string(options_.min_samples) + " are needed");
    }
    JointTrajectory t = Fill(table, columns);
    if (!result_.errors.empty()) return std::move(result_);
    std::vector<io_internal::RecordedDerivatives> recorded;
    for (const std::string& joint : t.joints)
      recorded.push_back({columns.of.at(joint)[1] >= 0, columns.of.at(joint)[2] >= 0});
    const std::string error = io_internal::DeriveMissingDerivatives(recorded, options_, &t);
    if (!error.empty()) return Fail(0, error);
    result_.trajectory = std::move(t);
    return std::move(result_);
  }

 private:
  TrajectoryReadResult Fail(int line, const std::string& message) {
    Error(line, message);
    return std::move(result_);
  }
  void Error(int line, const std::string& message) {
    if (result_.errors.size() < 20)
      result_.errors.push_back(MakeReadError(file_, line, "", message));
  }

  // The numbers of every row; errors for wrong field counts, non-numbers and time going back.
  JointTrajectory Fill(const Table& table, const Columns& columns) {
    const Eigen::Index N = static_cast<Eigen::Index>(table.rows.size());
    const Eigen::Index n = static_cast<Eigen::Index>(columns.joints.size());
    JointTrajectory t;
    t.joints = columns.joints;
    t.time.resize(N);
    t.q.setZero(N, n);
    t.dq.setZero(N, n);
    t.ddq.setZero(N, n);
    t.tau.setZero(N, n);
    Eigen::MatrixXd* kinds[] = {&t.q, &t.dq, &t.ddq, &t.tau};
    for (Eigen::Index k = 0; k < N; ++k) {
      const auto& [line, fields] = table.rows[static_cast<std::size_t>(k)];
      if (fields.size() != table.header.size()) {
        Error(line, std::to_string(fields.size()) + " fields where the header has " +
                        std::to_string(table.header.size()));
        continue;
      }
      t.time(k) = Number(line, table.header, fields, columns.time);
      if (k > 0 && !(t.time(k) > t.time(k - 1)))
        Error(line, "time " + fields[static_cast<std::size_t>(columns.time)] +
                        " is not after the previous sample's");
      for (Eigen::Index j = 0; j < n; ++j) {
        const auto& of = columns.of.at(columns.joints[static_cast<std::size_t>(j)]);
        for (std::size_t kind = 0; kind < 4; ++kind)
          if (of[kind] >= 0) (*kinds[kind])(k, j) = Number(line, table.header, fields, of[kind]);
      }
    }
    return t;
  }

  double Number(int line, const std::vector<std::string>& header,
                const std::vector<std::string>& fields, int column) {
    const std::string& text = fields[static_cast<std::size_t>(column)];
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value) || errno != 0) {
      Error(line, "'" + header[static_cast<std::size_t>(column)] + "' is '" + text +
                      "', not a finite number");
      return 0;
    }
    return value;
  }

  std::string file_;
  TrajectoryCsvOptions options_;
  TrajectoryReadResult result_;
};

}  // namespace

TrajectoryReadResult ReadTrajectoryCsv(const std::string& text, const std::string& file_name,
                                       const TrajectoryCsvOptions& options) {
  return CsvReader(file_name, options).Read(text);
}

TrajectoryReadResult ReadTrajectoryCsvFile(const std::string& path,
                                           const TrajectoryCsvOptions& options) {
  std::string text;
  if (std::optional<ReadError> error = ReadInputFile(path, kMaxTrajectoryBytes, &text)) {
    TrajectoryReadResult result;
    result.errors.push_back(*error);
    return result;
  }
  return ReadTrajectoryCsv(text, path, options);
}

}  // namespace massprops

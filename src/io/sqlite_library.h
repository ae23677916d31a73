#pragma once
// SQLite 3 for the rosbag2 reader (massprops/io/trajectory_rosbag.h), loaded with dlopen the first
// time a bag is read, as the mesh libraries are (mesh/mesh_backend.h): a process that reads no bag
// (every `massprops check`) never maps libsqlite3, and the library and tool link no more than
// before. The functions are SQLite's own C API (sqlite3.h, Debian's libsqlite3-dev), called
// through pointers of their declared types.

#include <sqlite3.h>

#include <string>

namespace massprops::io_internal {

/// The SQLite functions the bag reader calls.
struct SqliteApi {
  decltype(&sqlite3_open_v2) open_v2;
  decltype(&sqlite3_close) close;
  decltype(&sqlite3_errmsg) errmsg;
  decltype(&sqlite3_prepare_v2) prepare_v2;
  decltype(&sqlite3_step) step;
  decltype(&sqlite3_finalize) finalize;
  decltype(&sqlite3_column_int64) column_int64;
  decltype(&sqlite3_column_text) column_text;
  decltype(&sqlite3_column_blob) column_blob;
  decltype(&sqlite3_column_bytes) column_bytes;
  decltype(&sqlite3_bind_int64) bind_int64;
};

/// libsqlite3.so.0's functions, loaded on the first call (thread-safe; the library stays loaded);
/// nullptr with *error naming the library and dlerror's reason when it cannot be loaded or lacks
/// one of them.
const SqliteApi* LoadSqlite(std::string* error);

}  // namespace massprops::io_internal

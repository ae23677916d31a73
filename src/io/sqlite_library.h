#pragma once
// SQLite 3 for the rosbag2 reader (massprops/io/trajectory_rosbag.h), loaded with dlopen the first
// time a bag is read, as the mesh libraries are (mesh/mesh_backend.h): a process that reads no bag
// (every `massprops check`) never maps libsqlite3, and neither the build nor the library and tool
// need SQLite (only a machine that reads bags: libsqlite3.so.0, Debian's libsqlite3-0). The
// functions are SQLite's own C API, whose signatures and result codes are declared here as
// sqlite3.h declares them (a stable ABI, https://sqlite.org/c3ref/);
// tests/trajectory_rosbag_test.cc checks each type against sqlite3.h at compile time.

#include <string>

extern "C" {
struct sqlite3;       // an open database (sqlite3.h: typedef struct sqlite3 sqlite3)
struct sqlite3_stmt;  // a prepared statement
}

namespace massprops::io_internal {

/// SQLite's result codes and open flag that the reader uses (sqlite3.h's values).
constexpr int kSqliteOk = 0;            // SQLITE_OK
constexpr int kSqliteRow = 100;         // SQLITE_ROW
constexpr int kSqliteDone = 101;        // SQLITE_DONE
constexpr int kSqliteOpenReadOnly = 1;  // SQLITE_OPEN_READONLY

/// The SQLite functions the bag reader calls, with sqlite3.h's signatures.
struct SqliteApi {
  int (*open_v2)(const char* filename, sqlite3** db, int flags, const char* vfs);
  int (*close)(sqlite3* db);
  const char* (*errmsg)(sqlite3* db);
  int (*prepare_v2)(sqlite3* db, const char* sql, int bytes, sqlite3_stmt** statement,
                    const char** tail);
  int (*step)(sqlite3_stmt* statement);
  int (*finalize)(sqlite3_stmt* statement);
  long long (*column_int64)(sqlite3_stmt* statement, int column);  // sqlite3_int64
  const unsigned char* (*column_text)(sqlite3_stmt* statement, int column);
  const void* (*column_blob)(sqlite3_stmt* statement, int column);
  int (*column_bytes)(sqlite3_stmt* statement, int column);
  int (*bind_int64)(sqlite3_stmt* statement, int index, long long value);
};

/// libsqlite3.so.0's functions, loaded on the first call (thread-safe; the library stays loaded);
/// nullptr with *error naming the library and dlerror's reason when it cannot be loaded or lacks
/// one of them.
const SqliteApi* LoadSqlite(std::string* error);

}  // namespace massprops::io_internal

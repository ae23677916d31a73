#include "io/sqlite_library.h"

#include <dlfcn.h>

#include <mutex>

namespace massprops::io_internal {

namespace {

constexpr const char* kSqliteSoname = "libsqlite3.so.0";

struct SqliteLoad {
  SqliteApi api{};
  bool loaded = false;
  std::string error;
};

template <typename F>
bool SqliteSymbol(void* handle, const char* name, F* function, std::string* error) {
  void* symbol = dlsym(handle, name);
  if (symbol == nullptr) {
    *error = std::string(kSqliteSoname) + " has no function " + name;
    return false;
  }
  *function = reinterpret_cast<F>(symbol);
  return true;
}

SqliteLoad LoadSqliteOnce() {
  SqliteLoad load;
  void* handle = dlopen(kSqliteSoname, RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    load.error = "SQLite (" + std::string(kSqliteSoname) + ", Debian's libsqlite3-0) cannot be " +
                 "loaded to read the bag: " + (why != nullptr ? why : "dlopen failed");
    return load;
  }
  SqliteApi& a = load.api;
  std::string& e = load.error;
  load.loaded = SqliteSymbol(handle, "sqlite3_open_v2", &a.open_v2, &e) &&
                SqliteSymbol(handle, "sqlite3_close", &a.close, &e) &&
                SqliteSymbol(handle, "sqlite3_errmsg", &a.errmsg, &e) &&
                SqliteSymbol(handle, "sqlite3_prepare_v2", &a.prepare_v2, &e) &&
                SqliteSymbol(handle, "sqlite3_step", &a.step, &e) &&
                SqliteSymbol(handle, "sqlite3_finalize", &a.finalize, &e) &&
                SqliteSymbol(handle, "sqlite3_column_int64", &a.column_int64, &e) &&
                SqliteSymbol(handle, "sqlite3_column_text", &a.column_text, &e) &&
                SqliteSymbol(handle, "sqlite3_column_blob", &a.column_blob, &e) &&
                SqliteSymbol(handle, "sqlite3_column_bytes", &a.column_bytes, &e) &&
                SqliteSymbol(handle, "sqlite3_bind_int64", &a.bind_int64, &e);
  return load;  // The handle stays open for the life of the process.
}

}  // namespace

const SqliteApi* LoadSqlite(std::string* error) {
  static std::once_flag once;
  static SqliteLoad load;
  std::call_once(once, [] { load = LoadSqliteOnce(); });
  if (!load.loaded) {
    *error = load.error;
    return nullptr;
  }
  return &load.api;
}

}  // namespace massprops::io_internal

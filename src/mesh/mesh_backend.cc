// Loads libmassprops_meshlibs.so on first use (see mesh_backend.h).
#include "mesh/mesh_backend.h"

#include <mutex>
#include <string>

#ifndef MASSPROPS_MESH_BACKEND_STATIC
#include <dlfcn.h>
#include <link.h>
#include <unistd.h>

#include <vector>
#endif

namespace massprops::internal {

#ifdef MASSPROPS_MESH_BACKEND_STATIC

const MeshBackend* GetMeshBackend(std::string* /*error*/) { return massprops_mesh_backend_v2(); }

#else

namespace {

constexpr const char* kBackendFile = "libmassprops_meshlibs.so";
constexpr const char* kPrivateFolder = "massprops/";  // below the lib folder, when installed

#ifndef MASSPROPS_BIN_TO_LIB
#define MASSPROPS_BIN_TO_LIB "../lib"
#endif

std::string FolderOf(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

// Where to look for the module, best first: beside the shared object that holds this function
// (libmassprops.so in the build tree) and in the private folder massprops/ below it (installed:
// <prefix>/<lib>/massprops/, where Debian's policy puts a module that only massprops loads); when
// this code is linked into the executable instead (the `massprops` tool), beside the executable
// (the build tree) and in its prefix's <lib>/massprops/ (installed); then the loader's search path
// (LD_LIBRARY_PATH, the cache).
std::vector<std::string> Candidates() {
  std::vector<std::string> candidates;
  Dl_info info{};
  link_map* map = nullptr;
  if (dladdr1(reinterpret_cast<void*>(&GetMeshBackend), &info, reinterpret_cast<void**>(&map),
              RTLD_DL_LINKMAP) != 0) {
    if (map != nullptr && map->l_name != nullptr && map->l_name[0] != '\0') {
      candidates.push_back(FolderOf(map->l_name) + kBackendFile);
      candidates.push_back(FolderOf(map->l_name) + kPrivateFolder + kBackendFile);
    } else {  // The main program: glibc gives it no name in its link map.
      std::string exe(4096, '\0');
      const ssize_t length = readlink("/proc/self/exe", exe.data(), exe.size());
      if (length > 0 && static_cast<std::size_t>(length) < exe.size()) {
        exe.resize(static_cast<std::size_t>(length));
        const std::string folder = FolderOf(exe);
        if (!folder.empty()) {
          candidates.push_back(folder + kBackendFile);
          candidates.push_back(folder + MASSPROPS_BIN_TO_LIB + "/" + kPrivateFolder + kBackendFile);
        }
      }
    }
  }
  candidates.emplace_back(kBackendFile);
  return candidates;
}

struct Loaded {
  void* handle = nullptr;
  std::string error;
};

Loaded LoadModule() {
  Loaded loaded;
  std::string tried;
  for (const std::string& candidate : Candidates()) {
    loaded.handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (loaded.handle != nullptr) break;
    const char* why = dlerror();
    tried += (tried.empty() ? "" : "; ") + std::string(why != nullptr ? why : candidate);
  }
  if (loaded.handle == nullptr) {
    loaded.error = "the mesh libraries (" + std::string(kBackendFile) +
                   ", assimp and qhull) cannot be loaded: " + tried;
  }
  return loaded;  // The handle stays open for the life of the process.
}

// The module, loaded on the first call (thread-safe).
const Loaded& Module() {
  static std::once_flag once;
  static Loaded module;
  std::call_once(once, [] { module = LoadModule(); });
  return module;
}

}  // namespace

void* ModuleSymbol(const char* name, std::string* error) {
  const Loaded& module = Module();
  if (module.handle == nullptr) {
    if (error != nullptr) *error = module.error;
    return nullptr;
  }
  void* symbol = dlsym(module.handle, name);
  if (symbol == nullptr && error != nullptr) {
    *error = std::string(kBackendFile) + " has no entry " + name;
  }
  return symbol;
}

const MeshBackend* GetMeshBackend(std::string* error) {
  return ModuleEntry<MeshBackend>("massprops_mesh_backend_v2", error);
}

#endif

}  // namespace massprops::internal

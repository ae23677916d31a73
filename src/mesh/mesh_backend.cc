// Loads libmassprops_meshlibs.so on first use (see mesh_backend.h).
#include "mesh/mesh_backend.h"

#include <mutex>
#include <string>

#ifndef MASSPROPS_MESH_BACKEND_STATIC
#include <dlfcn.h>
#endif

namespace massprops::internal {

#ifdef MASSPROPS_MESH_BACKEND_STATIC

const MeshBackend* GetMeshBackend(std::string* /*error*/) { return massprops_mesh_backend_v1(); }

#else

namespace {

constexpr const char* kBackendFile = "libmassprops_meshlibs.so";

// The folder of the shared object that holds this function (libmassprops.so), with a trailing
// '/'; empty when it cannot be told.
std::string ThisLibraryFolder() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&GetMeshBackend), &info) == 0 || info.dli_fname == nullptr) {
    return {};
  }
  const std::string path = info.dli_fname;
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

struct Loaded {
  const MeshBackend* backend = nullptr;
  std::string error;
};

Loaded Load() {
  Loaded loaded;
  // Beside libmassprops.so first (the build tree, an install prefix), then the loader's search
  // path (LD_LIBRARY_PATH, the cache).
  std::string tried;
  void* handle = nullptr;
  for (const std::string& candidate :
       {ThisLibraryFolder() + kBackendFile, std::string(kBackendFile)}) {
    handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle != nullptr) break;
    const char* why = dlerror();
    tried += (tried.empty() ? "" : "; ") + std::string(why != nullptr ? why : candidate);
  }
  if (handle == nullptr) {
    loaded.error = "the mesh libraries (" + std::string(kBackendFile) +
                   ", assimp and qhull) cannot be loaded: " + tried;
    return loaded;
  }
  using Entry = const MeshBackend* (*)();
  const auto entry = reinterpret_cast<Entry>(dlsym(handle, "massprops_mesh_backend_v1"));
  if (entry == nullptr) {
    loaded.error = std::string(kBackendFile) + " has no entry massprops_mesh_backend_v1";
    return loaded;
  }
  loaded.backend = entry();
  return loaded;  // The handle stays open for the life of the process.
}

}  // namespace

const MeshBackend* GetMeshBackend(std::string* error) {
  static std::once_flag once;
  static Loaded loaded;
  std::call_once(once, [] { loaded = Load(); });
  if (loaded.backend == nullptr && error != nullptr) *error = loaded.error;
  return loaded.backend;
}

#endif

}  // namespace massprops::internal

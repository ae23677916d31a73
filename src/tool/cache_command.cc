// `massprops cache clean` and `massprops cache dir`: the cache of mesh numbers kept between runs
// (docs/meshes.md#cache).
#include <iostream>
#include <string>

#include "commands.h"
#include "massprops/mesh/mesh_loader.h"

namespace massprops::cli {

void AddCacheCommands(CLI::App& app, std::function<int()>* run) {
  CLI::App* cache = app.add_subcommand(
      "cache",
      "The cache of mesh numbers (boxes, hull points, mass properties) that `check` keeps between "
      "runs in $XDG_CACHE_HOME/massprops/meshes (default ~/.cache/massprops/meshes)");
  cache->require_subcommand(1);
  CLI::App* clean = cache->add_subcommand("clean", "Remove every entry of the cache");
  clean->callback([run] {
    *run = [] {
      const std::string folder = DefaultMeshCacheFolder();
      if (folder.empty()) {
        std::cerr << "massprops: no cache folder: neither XDG_CACHE_HOME nor HOME is set\n";
        return 2;
      }
      std::string error;
      const long removed = CleanMeshCache(folder, &error);
      if (removed < 0) {
        std::cerr << "massprops: " << error << "\n";
        return 2;
      }
      std::cout << "removed " << removed << " file" << (removed == 1 ? "" : "s") << " from "
                << folder << "\n";
      return 0;
    };
  });
  CLI::App* dir = cache->add_subcommand("dir", "Print the cache's folder");
  dir->callback([run] {
    *run = [] {
      const std::string folder = DefaultMeshCacheFolder();
      if (folder.empty()) {
        std::cerr << "massprops: no cache folder: neither XDG_CACHE_HOME nor HOME is set\n";
        return 2;
      }
      std::cout << folder << "\n";
      return 0;
    };
  });
}

}  // namespace massprops::cli

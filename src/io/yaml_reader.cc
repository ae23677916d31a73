// The YAML reader of io/yaml_scalars.h: an entry of the on-demand module libmassprops_meshlibs.so,
// looked up through the mesh part's loader of that module (mesh/mesh_backend.h); linked in
// directly in static builds.
#include "io/yaml_scalars.h"
#include "mesh/mesh_backend.h"

namespace massprops::internal {

#ifdef MASSPROPS_MESH_BACKEND_STATIC
const YamlReader* GetYamlReader(std::string* /*error*/) { return massprops_yaml_reader_v1(); }
#else
const YamlReader* GetYamlReader(std::string* error) {
  return ModuleEntry<YamlReader>("massprops_yaml_reader_v1", error);
}
#endif

}  // namespace massprops::internal

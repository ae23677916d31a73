#pragma once
// Private to the library: the scalars of a YAML text with their places, for the xacro trace
// (src/io/xacro_source.cc). yaml-cpp reads them; it lives in the optional module
// libmassprops_meshlibs.so with the mesh libraries (src/mesh/mesh_backend.h), so that a process
// that reads no .yaml file neither maps nor relocates libyaml-cpp at start-up
// (docs/benchmarks.md, section 3). Static builds link it into the library.

#include <cstddef>
#include <string>
#include <vector>

namespace massprops::internal {

/// One scalar of a YAML text, and every key path that reaches it (aliases reach one scalar by
/// several paths), in the order a depth-first walk of the document first meets it.
struct YamlScalarFound {
  std::size_t offset = 0;  ///< Byte offset of the scalar's text in the YAML text.
  int line = 0;            ///< 1-based.
  std::string text;
  std::vector<std::vector<std::string>> paths;
};

/// What the module does for the YAML reading. Version 1; a changed layout gets a new entry name.
struct YamlReader {
  /// Every scalar of `text`, walking at most `max_visits` nodes and 64 levels (aliases make a
  /// graph). Returns false and sets *error (yaml-cpp's message) when the text is not YAML (*out
  /// then holds what was walked before the error); never throws.
  bool (*read_scalars)(const std::string& text, int max_visits, std::vector<YamlScalarFound>* out,
                       std::string* error);
};

/// The YAML reader, loaded with the module on the first call (thread-safe). Returns null and sets
/// *error (if not null) when the module cannot be loaded.
const YamlReader* GetYamlReader(std::string* error);

}  // namespace massprops::internal

/// The entry point of the YAML reader in libmassprops_meshlibs.so (C linkage: found with dlsym).
extern "C" const massprops::internal::YamlReader* massprops_yaml_reader_v1();
